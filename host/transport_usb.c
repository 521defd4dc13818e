/*
 * transport_usb.c - the USB transport (docs/board-usb.md): libusb-1.0 behind
 * the ef_transport_ops table of transport.h.
 *
 * Discovery opens every device with the board VID:PID (default 1209:0001)
 * and asks IDENTIFY (a vendor control request to the device, so it works
 * without claiming the interface): only a device that answers with magic
 * "EFB1" and protocol 1 is ours.  Selection: serial, BUS:DEV or #INDEX,
 * comma-separated, all of which must match; every error repeats them.
 *
 * Data moves with asynchronous bulk transfers, several in flight each way
 * (blocking transfers leave the bus idle between them): OUT transfers are
 * filled by write() and submitted when full, when the bus would otherwise go
 * idle, or before waiting for the board (read, flush); IN transfers are kept
 * submitted while there is room to store what they bring, and read() drains
 * that store.  Every transfer has a timeout.  An IN timeout only means the
 * board had nothing to say; any other failure is sticky: the link reports it
 * on every later call, and the protocol layer above decides to resume.
 */
#include "transport.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <libusb.h>

#include "host_link.h"
#include "usb_ids.h"

/* The control requests carry the engine's bytes unchanged (docs/board-usb.md 3). */
_Static_assert(EF_USB_IDENTIFY_LEN == EF_PROTO_IDENTIFY_LEN, "IDENTIFY's wLength is the engine's identify size");
_Static_assert(EF_USB_STATUS_LEN == EF_PROTO_STATUS_LEN, "STATUS's wLength is the engine's status size");
_Static_assert(EF_USB_PROTOCOL == EF_PROTO_PROTOCOL, "one protocol version");

/* Defaults: 8 x 64 KiB each way is 512 KiB in flight, 9.8 ms of USB 2.0
 * High-Speed's 53.248 MB/s: enough to keep the bus busy through a host
 * scheduling hiccup of a few ms, small enough for any board's FIFO. */
#define USB_XFER_DEFAULT (64u * 1024u)
#define USB_XFER_MIN 512u /* one High-Speed packet */
#define USB_XFER_MAX (16u * 1024u * 1024u)
#define USB_INFLIGHT_DEFAULT 8u
#define USB_INFLIGHT_MIN 1u /* 1 is allowed for measuring; default >= 4 */
#define USB_INFLIGHT_MAX 256u
#define USB_TIMEOUT_DEFAULT 2000   /* ms, every bulk transfer */
#define USB_CTRL_TIMEOUT 1000      /* ms, every control transfer */
#define USB_IDENTIFY_RETRY_MS 1500 /* re-enumeration after plug-in */

typedef struct usb_xfer {
    struct libusb_transfer *t;
    struct ef_link *link;
    int busy; /* submitted, callback not yet run */
} usb_xfer;

struct ef_link {
    libusb_context *ctx;
    libusb_device_handle *h;
    int claimed;
    unsigned xfer_size, nx;
    int timeout_ms;
    char where[16]; /* "BUS:DEV" */
    char serial[20];

    usb_xfer *out;         /* nx OUT transfers */
    unsigned out_fill_idx; /* transfer being filled, or nx if none */
    size_t out_fill;       /* bytes in it */
    unsigned out_busy;

    usb_xfer *in; /* nx IN transfers */
    unsigned in_busy;
    uint8_t *ring; /* bytes received, not yet read */
    size_t ring_cap, ring_head, ring_len;

    int error; /* sticky EF_HOST_E*, 0 if none */
    char err[320];
};

/* ---- helpers ---------------------------------------------------------- */

static int64_t now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

static void sleep_ms(int ms)
{
    struct timespec ts = { ms / 1000, (long)(ms % 1000) * 1000000L };
    nanosleep(&ts, NULL);
}

/* libusb's codes to ours, at the boundary (transport.h). */
static int usb_err(int e)
{
    switch (e) {
    case LIBUSB_SUCCESS: return EF_HOST_OK;
    case LIBUSB_ERROR_NO_DEVICE: return EF_HOST_ENODEV;
    case LIBUSB_ERROR_TIMEOUT: return EF_HOST_ETIMEDOUT;
    case LIBUSB_ERROR_ACCESS: return EF_HOST_EACCESS;
    case LIBUSB_ERROR_BUSY: return EF_HOST_EBUSY;
    case LIBUSB_ERROR_NO_MEM: return EF_HOST_ENOMEM;
    case LIBUSB_ERROR_NOT_FOUND: return EF_HOST_ENOTFOUND;
    case LIBUSB_ERROR_NOT_SUPPORTED: return EF_HOST_EUNSUPPORTED;
    default: return EF_HOST_EIO;
    }
}

static int xfer_status_err(enum libusb_transfer_status s)
{
    switch (s) {
    case LIBUSB_TRANSFER_COMPLETED: return EF_HOST_OK;
    case LIBUSB_TRANSFER_TIMED_OUT: return EF_HOST_ETIMEDOUT;
    case LIBUSB_TRANSFER_NO_DEVICE: return EF_HOST_ENODEV;
    default: return EF_HOST_EIO; /* STALL, OVERFLOW, ERROR, CANCELLED */
    }
}

static const char *xfer_status_name(enum libusb_transfer_status s)
{
    switch (s) {
    case LIBUSB_TRANSFER_COMPLETED: return "completed";
    case LIBUSB_TRANSFER_TIMED_OUT: return "timed out";
    case LIBUSB_TRANSFER_NO_DEVICE: return "no device";
    case LIBUSB_TRANSFER_STALL: return "endpoint stalled";
    case LIBUSB_TRANSFER_OVERFLOW: return "overflow";
    case LIBUSB_TRANSFER_CANCELLED: return "cancelled";
    default: return "error";
    }
}

/* The message for LIBUSB_ERROR_ACCESS: the top complaint about USB tools, so
 * it names the shipped rule and the commands that make udev apply it. */
static void access_msg(char *err, size_t errlen, const char *where, const char *sel)
{
    snprintf(err, errlen,
             "device %s%s%s: install the udev rule shipped as "
             "host/60-edgeflag.rules (`make install` puts a copy in PREFIX/lib/udev/rules.d) as "
             "/etc/udev/rules.d/60-edgeflag.rules, then as root run "
             "`udevadm control --reload && udevadm trigger` (docs/board-usb.md section 8)",
             where, sel && *sel ? " --device " : "", sel && *sel ? sel : "");
}

/* Once broken, always broken: the first failure is the one the user sees. */
static int link_fail(struct ef_link *l, int e, const char *what)
{
    if (l->error)
        return l->error;
    l->error = e;
    if (e == EF_HOST_ENODEV)
        snprintf(l->err, sizeof l->err,
                 "usb %s (serial %s): the board went away during %s (unplugged or reset); "
                 "plug it in and run again with --resume",
                 l->where, l->serial, what);
    else if (e == EF_HOST_ETIMEDOUT)
        snprintf(l->err, sizeof l->err, "usb %s (serial %s): %s timed out after %d ms", l->where, l->serial, what,
                 l->timeout_ms);
    else
        snprintf(l->err, sizeof l->err, "usb %s (serial %s): %s failed: %s", l->where, l->serial, what,
                 ef_host_strerror(e));
    return e;
}

/* ---- discovery -------------------------------------------------------- */

/* IDENTIFY, retried briefly: right after plug-in a board may still be
 * re-enumerating (firmware loading, soft core coming out of reset) and stall
 * or time out the first request.  Access and no-device are final. */
static int usb_identify_raw(libusb_device_handle *h, uint8_t out[EF_USB_IDENTIFY_LEN], int retry_ms)
{
    int64_t end = now_ms() + retry_ms;
    int delay = 20;
    for (;;) {
        int n = libusb_control_transfer(h, EF_USB_RT_IN, EF_USB_REQ_IDENTIFY, 0, 0, out, EF_USB_IDENTIFY_LEN,
                                        USB_CTRL_TIMEOUT);
        if (n == EF_USB_IDENTIFY_LEN)
            return 0;
        if (n >= 0)
            return EF_HOST_EPROTO; /* short answer: not our board */
        if (n == LIBUSB_ERROR_NO_DEVICE || n == LIBUSB_ERROR_ACCESS || now_ms() >= end)
            return usb_err(n);
        sleep_ms(delay);
        if (delay < 200)
            delay *= 2;
    }
}

/* Is this our board?  0, or EF_HOST_EPROTO with the reason in why. */
static int usb_check_identify(const uint8_t raw[EF_USB_IDENTIFY_LEN], ef_host_ident *id, char *why, size_t whylen)
{
    if (ef_host_ident_parse(raw, id) == 0)
        return 0;
    if (memcmp(raw, EF_USB_MAGIC, 4) != 0)
        snprintf(why, whylen, "not an edgeflag board (identify magic %02x %02x %02x %02x, expected \"EFB1\")", raw[0],
                 raw[1], raw[2], raw[3]);
    else
        snprintf(why, whylen, "edgeflag board speaking protocol version %u; this host speaks version %u", id->protocol,
                 EF_USB_PROTOCOL);
    return EF_HOST_EPROTO;
}

typedef struct usb_cand {
    libusb_device *dev;
    uint8_t bus, addr;
    uint16_t vid, pid;
    int status; /* 0 ours, else why not */
    char serial[20];
    char desc[144]; /* room for "#N " in ef_found.desc */
} usb_cand;

/* Opens and identifies one candidate; fills status, serial, desc.
 * Keeps the handle in *hout when asked and the device is ours. */
static void cand_probe(usb_cand *c, libusb_device_handle **hout)
{
    libusb_device_handle *h = NULL;
    uint8_t id[EF_USB_IDENTIFY_LEN];
    int r = libusb_open(c->dev, &h);
    strcpy(c->serial, "?");
    if (r != 0) {
        c->status = usb_err(r);
        if (c->status == EF_HOST_EACCESS)
            snprintf(c->desc, sizeof c->desc,
                     "%04x:%04x permission denied (udev rule host/60-edgeflag.rules "
                     "not installed? see docs/board-usb.md section 8)",
                     c->vid, c->pid);
        else
            snprintf(c->desc, sizeof c->desc, "%04x:%04x cannot open: %s", c->vid, c->pid, libusb_error_name(r));
        return;
    }
    r = usb_identify_raw(h, id, USB_IDENTIFY_RETRY_MS);
    if (r != 0) {
        c->status = r;
        snprintf(c->desc, sizeof c->desc, "%04x:%04x identify failed: %s", c->vid, c->pid,
                 r == EF_HOST_EPROTO ? "short answer (not an edgeflag board)" : ef_host_strerror(r));
        libusb_close(h);
        return;
    }
    char why[120], d[200];
    ef_host_ident ident;
    c->status = usb_check_identify(id, &ident, why, sizeof why);
    if (c->status != 0) {
        snprintf(c->desc, sizeof c->desc, "%04x:%04x %s", c->vid, c->pid, why);
        libusb_close(h);
        return;
    }
    snprintf(c->serial, sizeof c->serial, "%s", ident.serial[0] ? ident.serial : "-");
    ef_host_ident_describe(&ident, d, sizeof d);
    snprintf(c->desc, sizeof c->desc, "%04x:%04x %.*s", c->vid, c->pid, (int)(sizeof c->desc - 11), d);
    if (hout)
        *hout = h;
    else
        libusb_close(h);
}

/* All devices with the VID:PID, identified, in (bus, address) order so that
 * #INDEX is stable between `list` and `stream`. */
static int cand_scan(libusb_context *ctx, const ef_host_opts *o, usb_cand **out)
{
    libusb_device **devs;
    ssize_t n = libusb_get_device_list(ctx, &devs);
    if (n < 0)
        return usb_err((int)n);
    uint16_t vid = o && o->vid ? o->vid : EF_USB_VID, pid = o && o->pid ? o->pid : EF_USB_PID;
    usb_cand *c = calloc((size_t)n + 1, sizeof *c);
    if (!c) {
        libusb_free_device_list(devs, 1);
        return EF_HOST_ENOMEM;
    }
    int k = 0;
    for (ssize_t i = 0; i < n; i++) {
        struct libusb_device_descriptor d;
        if (libusb_get_device_descriptor(devs[i], &d) != 0 || d.idVendor != vid || d.idProduct != pid)
            continue;
        c[k].dev = libusb_ref_device(devs[i]);
        c[k].bus = libusb_get_bus_number(devs[i]);
        c[k].addr = libusb_get_device_address(devs[i]);
        c[k].vid = d.idVendor;
        c[k].pid = d.idProduct;
        k++;
    }
    libusb_free_device_list(devs, 1);
    for (int i = 1; i < k; i++) /* insertion sort: a handful */
        for (int j = i; j > 0 && (c[j - 1].bus > c[j].bus || (c[j - 1].bus == c[j].bus && c[j - 1].addr > c[j].addr));
             j--) {
            usb_cand t = c[j];
            c[j] = c[j - 1];
            c[j - 1] = t;
        }
    *out = c;
    return k;
}

static void cand_free(usb_cand *c, int n)
{
    for (int i = 0; i < n; i++)
        libusb_unref_device(c[i].dev);
    free(c);
}

static int usb_init(libusb_context **ctx)
{
    int r = libusb_init(ctx);
    return r == 0 ? 0 : usb_err(r);
}

static int usb_probe(const ef_host_opts *o, ef_found *found, int max)
{
    libusb_context *ctx;
    int r = usb_init(&ctx);
    if (r)
        return r;
    usb_cand *c;
    int n = cand_scan(ctx, o, &c);
    if (n < 0) {
        libusb_exit(ctx);
        return n;
    }
    int idx = 0;
    for (int i = 0; i < n; i++) {
        cand_probe(&c[i], NULL);
        if (i < max) {
            ef_found *f = &found[i];
            memset(f, 0, sizeof *f);
            snprintf(f->transport, sizeof f->transport, "usb");
            snprintf(f->where, sizeof f->where, "%u:%u", c[i].bus, c[i].addr);
            f->ok = c[i].status == 0;
            f->err = c[i].status;
            if (f->ok)
                snprintf(f->desc, sizeof f->desc, "#%d %s", idx, c[i].desc);
            else
                snprintf(f->desc, sizeof f->desc, "%s", c[i].desc);
        }
        if (c[i].status == 0)
            idx++;
    }
    cand_free(c, n);
    libusb_exit(ctx);
    return n;
}

/* ---- selection -------------------------------------------------------- */

typedef struct usb_sel {
    const char *serial; /* NULL: any */
    size_t serial_len;
    int bus, addr; /* -1: any */
    int index;     /* -1: any */
} usb_sel;

static int all_digits(const char *s, size_t n)
{
    if (n == 0 || n > 3)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (s[i] < '0' || s[i] > '9')
            return 0;
    return 1;
}

static int parse_num(const char *s, size_t n)
{
    int v = 0;
    for (size_t i = 0; i < n; i++)
        v = v * 10 + (s[i] - '0');
    return v;
}

/* "SERIAL", "BUS:DEV", "#INDEX", "serial=S", comma-separated (docs/board-usb.md 7). */
static int parse_sel(const char *spec, usb_sel *s, char *err, size_t errlen)
{
    s->serial = NULL;
    s->serial_len = 0;
    s->bus = s->addr = s->index = -1;
    if (!spec || !*spec)
        return 0;
    const char *p = spec;
    for (;;) {
        const char *e = strchr(p, ',');
        size_t n = e ? (size_t)(e - p) : strlen(p);
        const char *colon = memchr(p, ':', n);
        if (n > 7 && memcmp(p, "serial=", 7) == 0) {
            s->serial = p + 7;
            s->serial_len = n - 7;
        } else if (n > 1 && p[0] == '#' && all_digits(p + 1, n - 1)) {
            s->index = parse_num(p + 1, n - 1);
        } else if (colon && all_digits(p, (size_t)(colon - p)) && all_digits(colon + 1, n - (size_t)(colon - p) - 1)) {
            s->bus = parse_num(p, (size_t)(colon - p));
            s->addr = parse_num(colon + 1, n - (size_t)(colon - p) - 1);
            if (s->bus > 255 || s->addr > 255)
                goto bad;
        } else if (n > 0 && n <= 16 && !colon) {
            s->serial = p;
            s->serial_len = n;
        } else {
            goto bad;
        }
        if (!e)
            return 0;
        p = e + 1;
    }
bad:
    snprintf(err, errlen,
             "--device '%s': expected SERIAL (up to 16 characters), BUS:DEV (decimal, "
             "as `edgeflag-host list` prints), #INDEX, or several of them separated by commas",
             spec);
    return EF_HOST_EINVAL;
}

static int sel_match(const usb_sel *s, const usb_cand *c, int idx)
{
    if (s->serial && (strlen(c->serial) != s->serial_len || memcmp(c->serial, s->serial, s->serial_len) != 0))
        return 0;
    if (s->bus >= 0 && (s->bus != c->bus || s->addr != c->addr))
        return 0;
    if (s->index >= 0 && s->index != idx)
        return 0;
    return 1;
}

/* ---- transfers -------------------------------------------------------- */

static void in_submit_more(struct ef_link *l);

static void LIBUSB_CALL out_cb(struct libusb_transfer *t)
{
    usb_xfer *x = t->user_data;
    struct ef_link *l = x->link;
    x->busy = 0;
    l->out_busy--;
    if (t->status != LIBUSB_TRANSFER_COMPLETED || t->actual_length != t->length) {
        /* A short OUT transfer cannot be resumed here: bytes after it are
         * already queued behind it.  The protocol layer resends from the
         * last acknowledged frame. */
        char what[64];
        snprintf(what, sizeof what, "bulk OUT transfer (%s, %d of %d bytes)", xfer_status_name(t->status),
                 t->actual_length, t->length);
        int e = xfer_status_err(t->status);
        link_fail(l, e ? e : EF_HOST_EIO, what);
    }
}

static void LIBUSB_CALL in_cb(struct libusb_transfer *t)
{
    usb_xfer *x = t->user_data;
    struct ef_link *l = x->link;
    x->busy = 0;
    l->in_busy--;
    /* A timed-out IN transfer may still carry data; take it either way. */
    if (t->actual_length > 0 && (t->status == LIBUSB_TRANSFER_COMPLETED || t->status == LIBUSB_TRANSFER_TIMED_OUT ||
                                 t->status == LIBUSB_TRANSFER_CANCELLED)) {
        size_t n = (size_t)t->actual_length, tail = (l->ring_head + l->ring_len) % l->ring_cap;
        size_t first = n < l->ring_cap - tail ? n : l->ring_cap - tail;
        memcpy(l->ring + tail, t->buffer, first);
        memcpy(l->ring, t->buffer + first, n - first);
        l->ring_len += n;
    }
    if (t->status == LIBUSB_TRANSFER_COMPLETED || t->status == LIBUSB_TRANSFER_TIMED_OUT) {
        in_submit_more(l);
    } else if (t->status != LIBUSB_TRANSFER_CANCELLED) {
        char what[64];
        snprintf(what, sizeof what, "bulk IN transfer (%s)", xfer_status_name(t->status));
        link_fail(l, xfer_status_err(t->status) ? xfer_status_err(t->status) : EF_HOST_EIO, what);
    }
}

/* Keeps IN transfers submitted while the ring can hold what all of them may
 * bring: the board is throttled by USB NAKs, never by lost data. */
static void in_submit_more(struct ef_link *l)
{
    if (l->error)
        return;
    for (unsigned i = 0; i < l->nx; i++) {
        if (l->in[i].busy)
            continue;
        if (l->ring_len + (size_t)(l->in_busy + 1) * l->xfer_size > l->ring_cap)
            return;
        int r = libusb_submit_transfer(l->in[i].t);
        if (r != 0) {
            link_fail(l, usb_err(r), "submitting a bulk IN transfer");
            return;
        }
        l->in[i].busy = 1;
        l->in_busy++;
    }
}

/* One round of the event loop: up to ms milliseconds. */
static int pump(struct ef_link *l, int ms)
{
    struct timeval tv = { ms / 1000, (ms % 1000) * 1000 };
    int r = libusb_handle_events_timeout_completed(l->ctx, &tv, NULL);
    if (r != 0 && r != LIBUSB_ERROR_INTERRUPTED)
        return link_fail(l, usb_err(r), "handling USB events");
    return l->error;
}

static int out_submit_fill(struct ef_link *l)
{
    if (l->out_fill_idx >= l->nx || l->out_fill == 0)
        return 0;
    usb_xfer *x = &l->out[l->out_fill_idx];
    x->t->length = (int)l->out_fill;
    int r = libusb_submit_transfer(x->t);
    if (r != 0)
        return link_fail(l, usb_err(r), "submitting a bulk OUT transfer");
    x->busy = 1;
    l->out_busy++;
    l->out_fill_idx = l->nx;
    l->out_fill = 0;
    return 0;
}

static int out_take(struct ef_link *l)
{
    for (unsigned i = 0; i < l->nx; i++)
        if (!l->out[i].busy) {
            l->out_fill_idx = i;
            l->out_fill = 0;
            return 1;
        }
    return 0;
}

static int remaining(int64_t end)
{
    int64_t r = end - now_ms();
    return r < 0 ? 0 : (int)(r > 100 ? 100 : r);
}

static int usb_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    if (l->error)
        return l->error;
    int64_t end = now_ms() + (timeout_ms > 0 ? timeout_ms : l->timeout_ms);
    while (len > 0) {
        if (l->out_fill_idx >= l->nx) {
            while (!out_take(l)) {
                if (now_ms() >= end)
                    return link_fail(l, EF_HOST_ETIMEDOUT, "waiting for a free bulk OUT transfer");
                if (pump(l, remaining(end)))
                    return l->error;
            }
        }
        size_t room = l->xfer_size - l->out_fill, n = len < room ? len : room;
        memcpy(l->out[l->out_fill_idx].t->buffer + l->out_fill, buf, n);
        l->out_fill += n;
        buf += n;
        len -= n;
        if (l->out_fill == l->xfer_size && out_submit_fill(l))
            return l->error;
    }
    /* Nothing on the wire: send the partial transfer now rather than wait for
     * more bytes that may only come after the board answers. */
    if (l->out_busy == 0 && out_submit_fill(l))
        return l->error;
    /* Let completions run without blocking. */
    return pump(l, 0);
}

static int usb_flush(ef_link *l, int timeout_ms)
{
    if (l->error)
        return l->error;
    if (out_submit_fill(l))
        return l->error;
    int64_t end = now_ms() + (timeout_ms > 0 ? timeout_ms : l->timeout_ms);
    while (l->out_busy > 0) {
        if (now_ms() >= end)
            return link_fail(l, EF_HOST_ETIMEDOUT, "flushing bulk OUT transfers");
        if (pump(l, remaining(end)))
            return l->error;
    }
    return 0;
}

static int usb_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    *got = 0;
    if (l->error && l->ring_len == 0)
        return l->error;
    if (!l->error && out_submit_fill(l)) /* the board may need these bytes to answer */
        return l->error;
    int64_t end = now_ms() + (timeout_ms > 0 ? timeout_ms : 0);
    while (l->ring_len == 0) {
        if (l->error)
            return l->error;
        in_submit_more(l);
        if (now_ms() >= end) {
            if (pump(l, 0) || l->ring_len)
                break;
            return EF_HOST_ETIMEDOUT;
        }
        if (pump(l, remaining(end)) && l->ring_len == 0)
            return l->error;
    }
    size_t n = cap < l->ring_len ? cap : l->ring_len;
    size_t first = n < l->ring_cap - l->ring_head ? n : l->ring_cap - l->ring_head;
    memcpy(buf, l->ring + l->ring_head, first);
    memcpy(buf + first, l->ring, n - first);
    l->ring_head = (l->ring_head + n) % l->ring_cap;
    l->ring_len -= n;
    *got = n;
    in_submit_more(l);
    return 0;
}

/* ---- control requests ------------------------------------------------- */

static int usb_ctrl_in(ef_link *l, uint8_t req, uint8_t *out, uint16_t len, const char *what)
{
    if (l->error)
        return l->error;
    int n = libusb_control_transfer(l->h, EF_USB_RT_IN, req, 0, 0, out, len, USB_CTRL_TIMEOUT);
    if (n == len)
        return 0;
    if (n >= 0) {
        snprintf(l->err, sizeof l->err, "usb %s (serial %s): %s returned %d of %u bytes", l->where, l->serial, what, n,
                 len);
        return EF_HOST_EPROTO;
    }
    if (n == LIBUSB_ERROR_NO_DEVICE)
        return link_fail(l, EF_HOST_ENODEV, what);
    /* A stall or timeout of a control request leaves the bulk stream intact:
     * report it, do not poison the link. */
    snprintf(l->err, sizeof l->err, "usb %s (serial %s): %s failed: %s", l->where, l->serial, what,
             libusb_error_name(n));
    return usb_err(n);
}

static int usb_identify(ef_link *l, uint8_t out[48])
{
    return usb_ctrl_in(l, EF_USB_REQ_IDENTIFY, out, EF_USB_IDENTIFY_LEN, "identify");
}

static int usb_status(ef_link *l, uint8_t out[40])
{
    return usb_ctrl_in(l, EF_USB_REQ_STATUS, out, EF_USB_STATUS_LEN, "status");
}

static int usb_reset(ef_link *l)
{
    if (l->error)
        return l->error;
    int n = libusb_control_transfer(l->h, EF_USB_RT_OUT, EF_USB_REQ_RESET, 0, 0, NULL, 0, USB_CTRL_TIMEOUT);
    if (n == 0) {
        /* Bytes the board queued before the reset are stale. */
        l->ring_len = 0;
        return 0;
    }
    if (n == LIBUSB_ERROR_NO_DEVICE)
        return link_fail(l, EF_HOST_ENODEV, "reset");
    snprintf(l->err, sizeof l->err, "usb %s (serial %s): reset failed: %s", l->where, l->serial, libusb_error_name(n));
    return usb_err(n);
}

/* ---- open / close ----------------------------------------------------- */

static void usb_close(ef_link *l)
{
    if (!l)
        return;
    /* Cancel what is in flight and wait for every callback (bounded): a
     * transfer freed while the kernel still owns it would be a use after
     * free, and an unreaped URB would leak in the kernel. */
    for (unsigned i = 0; l->out && i < l->nx; i++)
        if (l->out[i].busy)
            libusb_cancel_transfer(l->out[i].t);
    for (unsigned i = 0; l->in && i < l->nx; i++)
        if (l->in[i].busy)
            libusb_cancel_transfer(l->in[i].t);
    int64_t end = now_ms() + 2000;
    while ((l->out_busy || l->in_busy) && now_ms() < end) {
        struct timeval tv = { 0, 50000 };
        libusb_handle_events_timeout_completed(l->ctx, &tv, NULL);
    }
    int leaked = l->out_busy || l->in_busy;
    for (unsigned i = 0; l->out && i < l->nx; i++)
        if (!l->out[i].busy)
            libusb_free_transfer(l->out[i].t);
    for (unsigned i = 0; l->in && i < l->nx; i++)
        if (!l->in[i].busy)
            libusb_free_transfer(l->in[i].t);
    if (l->claimed)
        libusb_release_interface(l->h, EF_USB_INTERFACE);
    if (l->h)
        libusb_close(l->h);
    if (l->ctx && !leaked)
        libusb_exit(l->ctx);
    free(l->out);
    free(l->in);
    free(l->ring);
    free(l);
}

static int alloc_xfers(struct ef_link *l, usb_xfer **arr, unsigned char ep, libusb_transfer_cb_fn cb)
{
    *arr = calloc(l->nx, sizeof **arr);
    if (!*arr)
        return EF_HOST_ENOMEM;
    for (unsigned i = 0; i < l->nx; i++) {
        usb_xfer *x = &(*arr)[i];
        x->link = l;
        x->t = libusb_alloc_transfer(0);
        uint8_t *b = x->t ? malloc(l->xfer_size) : NULL;
        if (!b) {
            if (x->t)
                libusb_free_transfer(x->t);
            x->t = NULL;
            return EF_HOST_ENOMEM;
        }
        /* libusb frees the buffer with the transfer. */
        libusb_fill_bulk_transfer(x->t, l->h, ep, b, (int)l->xfer_size, cb, x, (unsigned)l->timeout_ms);
        x->t->flags = LIBUSB_TRANSFER_FREE_BUFFER;
    }
    return 0;
}

static int usb_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    *out = NULL;
    const char *spec = o && o->device ? o->device : "";
    char sel_echo[96];
    snprintf(sel_echo, sizeof sel_echo, "%s%s%s", *spec ? " --device '" : "", spec, *spec ? "'" : "");
    usb_sel sel;
    int r = parse_sel(spec, &sel, err, errlen);
    if (r)
        return r;
    unsigned xs = o && o->transfer_size ? o->transfer_size : USB_XFER_DEFAULT;
    unsigned nx = o && o->in_flight ? o->in_flight : USB_INFLIGHT_DEFAULT;
    if (xs < USB_XFER_MIN || xs > USB_XFER_MAX || xs % USB_XFER_MIN != 0) {
        snprintf(err, errlen, "transfer size %u: must be a multiple of 512 between %u and %u bytes", xs, USB_XFER_MIN,
                 USB_XFER_MAX);
        return EF_HOST_EINVAL;
    }
    if (nx < USB_INFLIGHT_MIN || nx > USB_INFLIGHT_MAX) {
        snprintf(err, errlen, "transfers in flight %u: must be between %u and %u", nx, USB_INFLIGHT_MIN,
                 USB_INFLIGHT_MAX);
        return EF_HOST_EINVAL;
    }

    struct ef_link *l = calloc(1, sizeof *l);
    if (!l)
        return EF_HOST_ENOMEM;
    l->xfer_size = xs;
    l->nx = nx;
    l->timeout_ms = o && o->timeout_ms > 0 ? o->timeout_ms : USB_TIMEOUT_DEFAULT;
    l->out_fill_idx = nx;
    if ((r = usb_init(&l->ctx)) != 0) {
        snprintf(err, errlen, "cannot initialise libusb: %s", ef_host_strerror(r));
        free(l);
        return r;
    }

    usb_cand *c;
    int n = cand_scan(l->ctx, o, &c);
    if (n < 0) {
        snprintf(err, errlen, "cannot list USB devices%s: %s", sel_echo, ef_host_strerror(n));
        usb_close(l);
        return n;
    }
    /* Identify every candidate: a selector may name a serial, and #INDEX
     * counts only boards that answer. */
    int idx = 0, match = -1, nmatch = 0, denied = -1, foreign = -1;
    char seen[200] = "";
    size_t sk = 0;
    for (int i = 0; i < n; i++) {
        libusb_device_handle *h = NULL;
        cand_probe(&c[i], &h);
        if (c[i].status == EF_HOST_EACCESS && denied < 0 &&
            (sel.bus < 0 || (sel.bus == c[i].bus && sel.addr == c[i].addr)))
            denied = i;
        if (c[i].status == EF_HOST_EPROTO && foreign < 0 &&
            (sel.bus < 0 || (sel.bus == c[i].bus && sel.addr == c[i].addr)))
            foreign = i;
        if (c[i].status != 0)
            continue;
        if (sk < sizeof seen)
            sk += (size_t)snprintf(seen + sk, sizeof seen - sk, "%s%u:%u serial %s", sk ? ", " : "", c[i].bus,
                                   c[i].addr, c[i].serial);
        if (sel_match(&sel, &c[i], idx)) {
            if (nmatch++ == 0) {
                match = i;
                l->h = h;
                h = NULL;
            }
        }
        idx++;
        if (h)
            libusb_close(h);
    }
    uint16_t vid = o && o->vid ? o->vid : EF_USB_VID, pid = o && o->pid ? o->pid : EF_USB_PID;
    if (nmatch != 1) {
        if (nmatch == 0 && denied >= 0) {
            char where[16];
            snprintf(where, sizeof where, "%u:%u", c[denied].bus, c[denied].addr);
            access_msg(err, errlen, where, spec);
            r = EF_HOST_EACCESS;
        } else if (nmatch == 0 && foreign >= 0 && idx == 0) {
            /* The device is there but is not (this version of) our board:
             * say what it answered rather than "not found". */
            snprintf(err, errlen, "device %u:%u%s: %s", c[foreign].bus, c[foreign].addr, sel_echo, c[foreign].desc);
            r = EF_HOST_EPROTO;
        } else if (nmatch == 0) {
            snprintf(err, errlen, "no edgeflag board matches%s (VID:PID %04x:%04x; %s%s)", sel_echo, vid, pid,
                     idx ? "boards found: "
                     : n ? "no device answered identify"
                         : "no such device",
                     seen);
            r = EF_HOST_ENOTFOUND;
        } else {
            snprintf(err, errlen, "%d boards match%s (%s); choose one with --device SERIAL or BUS:DEV", nmatch,
                     sel_echo, seen);
            r = EF_HOST_EAMBIGUOUS;
        }
        cand_free(c, n);
        usb_close(l);
        return r;
    }
    snprintf(l->where, sizeof l->where, "%u:%u", c[match].bus, c[match].addr);
    snprintf(l->serial, sizeof l->serial, "%s", c[match].serial);
    cand_free(c, n);

    r = libusb_claim_interface(l->h, EF_USB_INTERFACE);
    if (r != 0) {
        int e = usb_err(r);
        if (e == EF_HOST_EACCESS)
            access_msg(err, errlen, l->where, spec);
        else if (e == EF_HOST_EBUSY)
            snprintf(err, errlen,
                     "device %s (serial %s)%s: interface %d is claimed by another program (close it, "
                     "or check `lsof /dev/bus/usb/*/*`)",
                     l->where, l->serial, sel_echo, EF_USB_INTERFACE);
        else
            snprintf(err, errlen, "device %s (serial %s)%s: cannot claim interface %d: %s", l->where, l->serial,
                     sel_echo, EF_USB_INTERFACE, libusb_error_name(r));
        usb_close(l);
        return e;
    }
    l->claimed = 1;
    l->ring_cap = (size_t)(nx + 1) * xs;
    l->ring = malloc(l->ring_cap);
    if (!l->ring || alloc_xfers(l, &l->out, EF_USB_EP_OUT, out_cb) || alloc_xfers(l, &l->in, EF_USB_EP_IN, in_cb)) {
        snprintf(err, errlen, "device %s: out of memory for %u transfers of %u bytes", l->where, nx, xs);
        usb_close(l);
        return EF_HOST_ENOMEM;
    }
    in_submit_more(l);
    if (l->error) {
        snprintf(err, errlen, "%s", l->err);
        r = l->error;
        usb_close(l);
        return r;
    }
    *out = l;
    return 0;
}

static const char *usb_version(void)
{
    static char v[48];
    const struct libusb_version *lv = libusb_get_version();
    snprintf(v, sizeof v, "libusb %u.%u.%u", lv->major, lv->minor, lv->micro);
    return v;
}

static const char *usb_detail(ef_link *l) { return l ? l->err : ""; }

const ef_transport_ops ef_transport_usb = {
    .name = "usb",
    .probe = usb_probe,
    .open = usb_open,
    .identify = usb_identify,
    .status = usb_status,
    .reset = usb_reset,
    .write = usb_write,
    .flush = usb_flush,
    .read = usb_read,
    .close = usb_close,
    .version = usb_version,
    .detail = usb_detail,
};
