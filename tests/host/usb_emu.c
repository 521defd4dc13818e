/*
 * usb_emu.c - an emulated edgeflag board on USB, for testing the unmodified
 * edgeflag-host binary with no hardware (docs/board-usb.md, tests/host/usb.sh).
 *
 * umockdev builds the device: sysfs attributes and USB descriptors of a
 * vendor-class board (VID:PID 1209:0001, interface 0, bulk OUT 0x01 and bulk
 * IN 0x81, 512-byte packets) and a device node whose ioctls come to this
 * program.  The ioctl handler plays the kernel's usbfs: it takes URBs
 * (submit, reap, discard), answers control transfers and capability queries,
 * and behind it runs the real board engine (board/ef_board.c) with the C
 * model as its DUT: bulk OUT bytes go into ef_board_rx(), ef_board_tx() fills
 * bulk IN URBs, and the vendor control requests call ef_board_identify(),
 * ef_board_status() and ef_board_reset().
 *
 * The commands to test run as child processes under umockdev's preload
 * library (LD_PRELOAD, with UMOCKDEV_DIR pointing at the testbed), as
 * libusb's own tests/umockdev.c does in-process, so the binary under test is
 * the one users run.  Commands run one after the other against the same
 * board; a board unplugged by a fault is plugged in again (at a new address,
 * as a real bus does) before the next command, keeping its state, which is
 * what `--resume` after an unplug needs.
 *
 *   usb_emu [options] --run 'SHELL COMMAND' [--run ...]
 *     --serial S        a board with this serial (repeat for several; default EMU0001)
 *     --bus N           the bus number (default 1; 0 is valid)
 *     --fault F[,F...]  faults, also read from $EF_USB_EMU_FAULT:
 *                       unplug-at=BYTES   the board vanishes once it has taken BYTES bulk OUT bytes
 *                       unplug-in=BYTES   ... once it has sent BYTES bulk IN bytes (results flowing)
 *                       stall-at=BYTES    ... stops answering (no OUT accepted, no IN data)
 *                       reset-at=BYTES    ... resets itself (power glitch, watchdog)
 *                       corrupt-out=BYTE  flips a bit of bulk OUT byte BYTE before the board sees it
 *                       corrupt-in=N      flips a bit in the payload of the N-th frame to the host (1-based)
 *                       drop-ack=N        the N-th ACK frame to the host is lost (1-based)
 *                       magic=XXXX        identify answers with this magic
 *                       protocol=N        identify answers with this protocol version
 *                       identify-stall=N  the first N identify requests stall (re-enumeration)
 *                       eacces            the device node is root-only and commands run as nobody
 *     --soc SOCKET      the board is the simulated SoC (board/sim/board_sim.cpp --usb SOCKET): each
 *                       URB goes to its USB core's host controller (board/sim/usb_link.cpp), which
 *                       carries it out as full-speed transactions on the gateware's UTMI side;
 *                       enumeration happens here, and libusb sees the gateware's descriptors.
 *                       Faults: unplug-at (the board takes exactly BYTES: the packets of the
 *                       crossing transfer before that point reach it), unplug-in, stall-at (the
 *                       board's CPU stops: the core NAKs), corrupt-out, eacces; the report's board
 *                       counters come from STATUS.
 *     --report FILE     what the board saw, as key=value lines (written at the end)
 *     --dut-log FILE    every command word the DUT received, raw, in order
 *   Exit status: the last command's; 70 when the emulation itself failed.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <linux/ioctl.h>
#include <linux/usbdevice_fs.h>
#include <umockdev.h>

#include "ef_board.h"
#include "ef_frame.h"
#include "usb_ids.h"
#include "usb_wire.h"

#define MAX_BOARDS 4
#define MAX_RUNS 8

typedef struct urb_rec {
    UMockdevIoctlData *urb; /* the client's struct usbdevfs_urb, resolved */
    UMockdevIoctlData *buf; /* its buffer, resolved under urb */
    int status, actual;
    uint32_t id; /* --soc: the transfer's id on the simulated board's socket */
    struct urb_rec *next;
} urb_rec;

typedef struct faults {
    long long unplug_at, unplug_in, stall_at, reset_at, corrupt_out;
    long corrupt_in, drop_ack, identify_stall, protocol;
    char magic[5];
    int eacces;
} faults;

typedef struct emu_board {
    struct emu *emu;
    int index;
    char serial[17];
    int bus, dev;
    char syspath[256];
    ef_board *b;
    ef_board_dut model; /* the real DUT, wrapped to log its input */
    UMockdevIoctlBase *handler;

    /* usbfs state of the current client */
    urb_rec *pend_in, *pend_out, *done; /* FIFOs (append at tail) */
    int gone, stalled, reset_done;

    /* board -> host: frames staged whole so faults can pick them */
    uint8_t *stage;
    size_t stage_len, stage_cap;
    uint8_t *deliver;
    size_t deliver_head, deliver_len, deliver_cap;
    long frames_to_host, acks_to_host;

    /* counters for the report */
    long long out_bytes, in_bytes, urbs, discards;
    long identifies, statuses, resets, ctrl_other, rx_refused, acks_dropped, frames_corrupted;

    /* --soc: the simulated board's USB core (board/sim/usb_link.cpp) */
    int soc_fd;
    uint8_t *srx;
    size_t srx_len, srx_cap;
    urb_rec *pend_soc; /* URBs the simulated board has (any endpoint), in submission order */
    uint32_t next_id;
    long long out_submitted; /* bulk OUT bytes handed to the board (the byte-position faults) */
    uint32_t sync_id;        /* a transfer this program waits for (enumeration, the report) */
    int sync_done, sync_status, sync_actual;
    uint8_t sync_data[512];
    char desc_hex[1024], manufacturer[64], product[64];
    int frozen;
} emu_board;

typedef struct emu {
    UMockdevTestbed *tb;
    pthread_mutex_t mu;
    faults f;
    emu_board boards[MAX_BOARDS];
    int nboards;
    FILE *dut_log;
    int verbose;
    const char *soc; /* --soc SOCKET: the board is the simulated SoC's USB core */
} emu;

static void die(const char *fmt, const char *arg)
{
    fprintf(stderr, "usb_emu: ");
    fprintf(stderr, fmt, arg);
    fputc('\n', stderr);
    exit(70);
}

/* ------------------------------------------------------------- the DUT */

/* The C model, with every command it receives also written to --dut-log:
 * the test compares that log between an interrupted-and-resumed run and an
 * uninterrupted one, byte for byte. */
typedef struct dut_wrap {
    ef_board_dut inner;
    emu *e;
} dut_wrap;

static int w_start(void *self, ef_board *b, uint32_t mask, int samples)
{
    dut_wrap *w = self;
    return w->inner.start(w->inner.self, b, mask, samples);
}

static int w_push(void *self, const uint8_t cmd[EF_PROTO_CMD_BYTES])
{
    dut_wrap *w = self;
    if (w->e->dut_log)
        fwrite(cmd, 1, EF_PROTO_CMD_BYTES, w->e->dut_log);
    return w->inner.push(w->inner.self, cmd);
}

static int w_finish(void *self)
{
    dut_wrap *w = self;
    return w->inner.finish(w->inner.self);
}

static void w_stop(void *self)
{
    dut_wrap *w = self;
    if (w->inner.stop)
        w->inner.stop(w->inner.self);
}

static void w_destroy(void *self)
{
    dut_wrap *w = self;
    if (w->inner.destroy)
        w->inner.destroy(w->inner.self);
    free(w);
}

static ef_board_dut dut_logged(emu *e)
{
    dut_wrap *w = calloc(1, sizeof *w);
    if (!w)
        die("%s", "out of memory");
    w->inner = ef_board_dut_model();
    w->e = e;
    return (ef_board_dut){ w, w_start, w_push, w_finish, w_stop, w_destroy };
}

/* ------------------------------------------------------------ URB lists */

static void urb_append(urb_rec **list, urb_rec *r)
{
    r->next = NULL;
    while (*list)
        list = &(*list)->next;
    *list = r;
}

static urb_rec *urb_pop(urb_rec **list)
{
    urb_rec *r = *list;
    if (r)
        *list = r->next;
    return r;
}

static void urb_free(urb_rec *r)
{
    g_object_unref(r->buf);
    g_object_unref(r->urb);
    free(r);
}

static void urb_drop_all(urb_rec **list)
{
    urb_rec *r;
    while ((r = urb_pop(list)))
        urb_free(r);
}

/* Every URB the client still has in flight completes with status (the
 * kernel does this on unplug: -ENODEV). */
static void urb_fail_all(emu_board *eb, int status)
{
    urb_rec *r;
    while ((r = urb_pop(&eb->pend_in))) {
        r->status = status, r->actual = 0;
        urb_append(&eb->done, r);
    }
    while ((r = urb_pop(&eb->pend_out))) {
        r->status = status, r->actual = 0;
        urb_append(&eb->done, r);
    }
}

/* ------------------------------------------------- board -> host frames */

static void grow(uint8_t **p, size_t *cap, size_t need)
{
    if (need <= *cap)
        return;
    size_t c = *cap ? *cap : 65536;
    while (c < need)
        c *= 2;
    uint8_t *n = realloc(*p, c);
    if (!n)
        die("%s", "out of memory");
    *p = n, *cap = c;
}

/* Moves what the engine has to say into the delivery queue, frame by frame,
 * applying drop-ack and corrupt-in on the way. */
static void pull_from_board(emu_board *eb)
{
    faults *f = &eb->emu->f;
    for (;;) {
        grow(&eb->stage, &eb->stage_cap, eb->stage_len + 65536);
        size_t n = ef_board_tx(eb->b, eb->stage + eb->stage_len, eb->stage_cap - eb->stage_len);
        if (n == 0)
            break;
        eb->stage_len += n;
    }
    size_t pos = 0;
    while (pos < eb->stage_len) {
        ef_frame fr;
        size_t used;
        int r = ef_frame_parse(eb->stage + pos, eb->stage_len - pos, &fr, &used);
        if (r == EF_FRAME_MORE)
            break;
        if (r == EF_FRAME_BAD) { /* the engine never sends these: pass the byte on */
            used = 1;
        } else {
            eb->frames_to_host++;
            if (fr.type == EF_FT_ACK && ++eb->acks_to_host == f->drop_ack) {
                eb->acks_dropped++;
                pos += used;
                continue;
            }
        }
        if (eb->deliver_head > 0 && eb->deliver_head == eb->deliver_len)
            eb->deliver_head = eb->deliver_len = 0;
        grow(&eb->deliver, &eb->deliver_cap, eb->deliver_len + used);
        memcpy(eb->deliver + eb->deliver_len, eb->stage + pos, used);
        if (r == EF_FRAME_OK && eb->frames_to_host == f->corrupt_in) {
            /* a bit of the payload (or of the CRC when there is none) */
            eb->deliver[eb->deliver_len + EF_PROTO_HEADER + (fr.len ? fr.len / 2 : 0)] ^= 0x10;
            eb->frames_corrupted++;
        }
        eb->deliver_len += used;
        pos += used;
    }
    memmove(eb->stage, eb->stage + pos, eb->stage_len - pos);
    eb->stage_len -= pos;
}

/* Fills pending IN URBs, in order, from the delivery queue.  A real board
 * ends every burst with a short packet (or a zero-length packet when the
 * burst is a multiple of 512 bytes), so an IN URB completes with what the
 * board had, never waiting to be full. */
static void unplug(emu_board *eb);
static void nap_ms(int ms);
static void soc_send(emu_board *eb, uint32_t op, uint32_t id, uint32_t a, uint32_t b, const uint8_t *d, uint32_t len);

static void serve_in(emu_board *eb)
{
    faults *f = &eb->emu->f;
    if (eb->gone || eb->stalled)
        return;
    pull_from_board(eb);
    while (eb->pend_in && eb->deliver_len > eb->deliver_head) {
        urb_rec *r = urb_pop(&eb->pend_in);
        struct usbdevfs_urb *u = (struct usbdevfs_urb *)r->urb->data;
        size_t n = eb->deliver_len - eb->deliver_head;
        if (n > (size_t)u->buffer_length)
            n = (size_t)u->buffer_length;
        if (f->unplug_in > 0 && eb->in_bytes + (long long)n > f->unplug_in) {
            /* this transfer never arrives: the board is gone while results flow */
            f->unplug_in = 0;
            urb_append(&eb->pend_in, r);
            unplug(eb);
            return;
        }
        memcpy(r->buf->data, eb->deliver + eb->deliver_head, n);
        eb->deliver_head += n;
        eb->in_bytes += (long long)n;
        r->status = 0, r->actual = (int)n;
        urb_append(&eb->done, r);
        if (eb->deliver_head == eb->deliver_len)
            pull_from_board(eb);
    }
}

/* ------------------------------------------------------------- faults */

static void unplug(emu_board *eb)
{
    /* The uevent first, then the device: libusb's hotplug thread sees the
     * remove while the node still exists, as with a real kernel. */
    eb->gone = 1;
    urb_fail_all(eb, -ENODEV);
    if (eb->emu->soc) {
        /* The simulated board drops them (their completions are ignored), except bulk OUT
         * transfers: those came before the unplug point, so their bytes reach the board, as the
         * C board takes them at once; the host sees them fail all the same. */
        urb_rec *r;
        while ((r = urb_pop(&eb->pend_soc))) {
            const struct usbdevfs_urb *u = (const struct usbdevfs_urb *)r->urb->data;
            if (!(u->type == USBDEVFS_URB_TYPE_BULK && u->endpoint == EF_USB_EP_OUT))
                soc_send(eb, USBW_CANCEL, r->id, 0, 0, NULL, 0);
            r->status = -ENODEV, r->actual = 0;
            urb_append(&eb->done, r);
        }
    }
    umockdev_testbed_uevent(eb->emu->tb, eb->syspath, "remove");
    umockdev_testbed_remove_device(eb->emu->tb, eb->syspath);
    if (eb->emu->verbose)
        fprintf(stderr, "usb_emu: board %s unplugged after %lld bytes\n", eb->serial, eb->out_bytes);
}

/* Bulk OUT bytes to the board, with the byte-position faults. */
static void board_take(emu_board *eb, uint8_t *p, size_t n, int *status)
{
    faults *f = &eb->emu->f;
    long long start = eb->out_bytes;
    *status = 0;
    if (f->corrupt_out >= start && f->corrupt_out < start + (long long)n)
        p[f->corrupt_out - start] ^= 0x01;
    if (f->unplug_at > 0 && start + (long long)n > f->unplug_at && !eb->reset_done) {
        /* this transfer never arrives */
        f->unplug_at = 0;
        *status = -ENODEV;
        unplug(eb);
        return;
    }
    if (ef_board_rx(eb->b, p, n) != 0)
        eb->rx_refused++; /* the host overran the window: a protocol violation */
    eb->out_bytes += (long long)n;
    if (f->reset_at > 0 && eb->out_bytes >= f->reset_at) {
        f->reset_at = 0;
        ef_board_reset(eb->b);
        eb->stage_len = 0;
        eb->deliver_head = eb->deliver_len = 0;
        eb->reset_done = 1;
    }
    if (f->stall_at > 0 && eb->out_bytes >= f->stall_at) {
        f->stall_at = 0; /* once: the next command finds it answering */
        eb->stalled = 1;
    }
}

/* ------------------------------------------------------- control requests */

static int put_string_desc(const char *s, uint8_t *out, int cap)
{
    int n = 2;
    for (; *s && n + 2 <= cap && n < 254; s++) {
        out[n++] = (uint8_t)*s;
        out[n++] = 0;
    }
    out[0] = (uint8_t)n;
    out[1] = 3;
    return n;
}

/* A control URB: 8-byte setup packet, then the data stage.  Returns the
 * data bytes for an IN request, or a negative errno (-EPIPE = stall). */
static int control(emu_board *eb, uint8_t *buf, int buflen)
{
    faults *f = &eb->emu->f;
    uint8_t rt = buf[0], req = buf[1];
    uint16_t wvalue = (uint16_t)(buf[2] | buf[3] << 8), wlen = (uint16_t)(buf[6] | buf[7] << 8);
    uint8_t *data = buf + 8;
    int cap = buflen - 8 < wlen ? buflen - 8 : wlen;
    uint8_t tmp[64];
    if (rt == EF_USB_RT_IN && req == EF_USB_REQ_IDENTIFY) {
        eb->identifies++;
        if (f->identify_stall > 0) {
            f->identify_stall--;
            return -EPIPE;
        }
        ef_board_identify(eb->b, tmp);
        if (f->magic[0])
            memcpy(tmp, f->magic, 4);
        if (f->protocol >= 0)
            tmp[4] = (uint8_t)f->protocol;
        int n = cap < EF_USB_IDENTIFY_LEN ? cap : EF_USB_IDENTIFY_LEN;
        memcpy(data, tmp, (size_t)n);
        return n;
    }
    if (rt == EF_USB_RT_IN && req == EF_USB_REQ_STATUS) {
        eb->statuses++;
        ef_board_status(eb->b, tmp);
        int n = cap < EF_USB_STATUS_LEN ? cap : EF_USB_STATUS_LEN;
        memcpy(data, tmp, (size_t)n);
        return n;
    }
    if (rt == EF_USB_RT_OUT && req == EF_USB_REQ_RESET && wlen == 0) {
        eb->resets++;
        ef_board_reset(eb->b);
        eb->stage_len = 0;
        eb->deliver_head = eb->deliver_len = 0;
        return 0;
    }
    eb->ctrl_other++;
    if (rt == 0x80 && req == 6 && (wvalue >> 8) == 3) { /* GET_DESCRIPTOR, string */
        int idx = wvalue & 0xff, n;
        if (idx == 0) {
            uint8_t lang[4] = { 4, 3, 0x09, 0x04 }; /* en-US */
            memcpy(tmp, lang, 4);
            n = 4;
        } else if (idx == 1) {
            n = put_string_desc("edgeflag", tmp, sizeof tmp);
        } else if (idx == 2) {
            n = put_string_desc("edgeflag board (emulated)", tmp, sizeof tmp);
        } else if (idx == 3) {
            n = put_string_desc(eb->serial, tmp, sizeof tmp);
        } else {
            return -EPIPE;
        }
        n = n < cap ? n : cap;
        memcpy(data, tmp, (size_t)n);
        return n;
    }
    return -EPIPE; /* unknown request: stall */
}

/* ----------------------------------- --soc: the simulated SoC's USB core */

/* The board is the Verilated SoC (board/sim/board_sim.cpp --usb SOCKET): each
 * URB becomes one transfer on the socket (board/sim/usb_wire.h), which the
 * simulated board's host controller (board/sim/usb_link.cpp) carries out as
 * full-speed transactions on the UTMI side of the SoC's USB core (LUNA's
 * device, board/soc/usb_core.py) and completes.  Enumeration (bus reset,
 * descriptors, SET_ADDRESS, SET_CONFIGURATION) is done here when the board is
 * plugged in, as the kernel would, and the sysfs descriptors umockdev shows
 * libusb are the ones the gateware returned. */

#define SOC_SYNC 0x80000000u /* ids of the transfers this program waits for */

static void soc_send(emu_board *eb, uint32_t op, uint32_t id, uint32_t a, uint32_t b, const uint8_t *d, uint32_t len)
{
    usbw_hdr h = { op, id, a, b, len };
    const uint8_t *parts[2] = { (const uint8_t *)&h, d };
    size_t lens[2] = { sizeof h, len };
    for (int k = 0; k < 2; k++)
        for (size_t off = 0; off < lens[k];) {
            ssize_t n = write(eb->soc_fd, parts[k] + off, lens[k] - off);
            if (n > 0)
                off += (size_t)n;
            else if (n < 0 && errno != EINTR && errno != EAGAIN)
                die("the simulated board's socket: %s", strerror(errno));
        }
}

static void soc_completed(emu_board *eb, const usbw_hdr *h, const uint8_t *d)
{
    if (h->id & SOC_SYNC) {
        if (h->id == eb->sync_id) {
            eb->sync_done = 1;
            eb->sync_status = (int32_t)h->a;
            eb->sync_actual = (int)h->b;
            memcpy(eb->sync_data, d, h->len < sizeof eb->sync_data ? h->len : sizeof eb->sync_data);
        }
        return;
    }
    urb_rec **pp = &eb->pend_soc;
    while (*pp && (*pp)->id != h->id)
        pp = &(*pp)->next;
    urb_rec *r = *pp;
    if (!r)
        return; /* failed already (unplugged) */
    *pp = r->next;
    struct usbdevfs_urb *u = (struct usbdevfs_urb *)r->urb->data;
    r->status = (int32_t)h->a;
    r->actual = (int)h->b;
    if (h->len) {
        size_t at = u->type == USBDEVFS_URB_TYPE_CONTROL ? 8 : 0;
        size_t n = h->len <= (size_t)u->buffer_length - at ? h->len : (size_t)u->buffer_length - at;
        memcpy((uint8_t *)r->buf->data + at, d, n);
    }
    if (u->type == USBDEVFS_URB_TYPE_BULK && u->endpoint == EF_USB_EP_IN) {
        faults *f = &eb->emu->f;
        if (f->unplug_in > 0 && eb->in_bytes + r->actual > f->unplug_in) {
            /* this transfer never arrives: the board is gone while results flow */
            f->unplug_in = 0;
            r->next = eb->pend_soc;
            eb->pend_soc = r;
            unplug(eb);
            return;
        }
        eb->in_bytes += r->actual;
    } else if (u->type == USBDEVFS_URB_TYPE_BULK) {
        eb->out_bytes += r->actual;
    }
    urb_append(&eb->done, r);
}

/* Reads what the simulated board sent; waits up to wait_ms for something. */
static void soc_pump(emu_board *eb, int wait_ms)
{
    struct pollfd pfd = { eb->soc_fd, POLLIN, 0 };
    if (poll(&pfd, 1, wait_ms) <= 0)
        return;
    for (;;) {
        grow(&eb->srx, &eb->srx_cap, eb->srx_len + 65536);
        ssize_t n = read(eb->soc_fd, eb->srx + eb->srx_len, eb->srx_cap - eb->srx_len);
        if (n > 0) {
            eb->srx_len += (size_t)n;
            continue;
        }
        if (n == 0)
            die("%s", "the simulated board closed its USB socket (did board_sim stop?)");
        if (errno == EAGAIN || errno == EWOULDBLOCK)
            break;
        if (errno != EINTR)
            die("the simulated board's socket: %s", strerror(errno));
    }
    size_t at = 0;
    while (eb->srx_len - at >= sizeof(usbw_hdr)) {
        usbw_hdr h;
        memcpy(&h, eb->srx + at, sizeof h);
        if (eb->srx_len - at - sizeof h < h.len)
            break;
        if (h.op == USBW_COMPLETE || h.op == USBW_BUS_RESET) {
            if (h.op == USBW_BUS_RESET)
                h.a = 0, h.b = 0;
            soc_completed(eb, &h, eb->srx + at + sizeof h);
        }
        at += sizeof h + h.len;
    }
    memmove(eb->srx, eb->srx + at, eb->srx_len - at);
    eb->srx_len -= at;
}

/* One transfer this program waits for: returns the bytes done, status in *st. */
static int soc_sync(emu_board *eb, uint32_t op, uint32_t a, uint32_t b, const uint8_t *d, uint32_t len, int *st)
{
    eb->sync_id = SOC_SYNC | ++eb->next_id;
    eb->sync_done = 0;
    soc_send(eb, op, eb->sync_id, a, b, d, len);
    for (int waited = 0; !eb->sync_done; waited += 100) {
        if (waited > 600000)
            die("%s", "the simulated board did not complete a transfer in 600 s");
        soc_pump(eb, 100);
    }
    *st = eb->sync_status;
    return eb->sync_actual;
}

static int soc_control(emu_board *eb, uint8_t rt, uint8_t req, uint16_t value, uint16_t index, uint16_t len, int *st)
{
    uint8_t setup[8] = { rt,
                         req,
                         (uint8_t)value,
                         (uint8_t)(value >> 8),
                         (uint8_t)index,
                         (uint8_t)(index >> 8),
                         (uint8_t)len,
                         (uint8_t)(len >> 8) };
    return soc_sync(eb, USBW_SUBMIT, USBW_CONTROL, len, setup, 8, st);
}

static void ascii_of(const uint8_t *desc, int n, char *out, size_t cap)
{
    size_t k = 0;
    for (int i = 2; i + 1 < n && k + 1 < cap; i += 2)
        out[k++] = desc[i] >= 0x20 && desc[i] < 0x7F && !desc[i + 1] ? (char)desc[i] : '?';
    out[k] = 0;
}

/* What the kernel does with a device that appears: a bus reset, the device
 * descriptor at address 0, SET_ADDRESS, the descriptors and strings, then
 * configuration 1 (a vendor-class interface has no driver to bind). */
static void soc_enumerate(emu_board *eb)
{
    int st, n;
    soc_sync(eb, USBW_BUS_RESET, 0, 0, NULL, 0, &st);
    n = soc_control(eb, 0x80, 6, 0x0100, 0, 64, &st);
    if (st || n < 8)
        die("%s", "the simulated board's USB core does not answer GET_DESCRIPTOR(device) at address 0");
    soc_control(eb, 0x00, 5, (uint16_t)eb->dev, 0, 0, &st);
    if (st)
        die("%s", "the simulated board's USB core refused SET_ADDRESS");
    char *h = eb->desc_hex;
    n = soc_control(eb, 0x80, 6, 0x0100, 0, 18, &st);
    if (st || n != 18)
        die("%s", "GET_DESCRIPTOR(device) at the new address failed");
    for (int i = 0; i < n; i++)
        h += sprintf(h, "%02x", eb->sync_data[i]);
    n = soc_control(eb, 0x80, 6, 0x0200, 0, 9, &st);
    if (st || n != 9)
        die("%s", "GET_DESCRIPTOR(configuration) failed");
    const uint16_t total = (uint16_t)(eb->sync_data[2] | eb->sync_data[3] << 8);
    n = soc_control(eb, 0x80, 6, 0x0200, 0, total, &st);
    if (st || n != total || total > 255)
        die("%s", "GET_DESCRIPTOR(configuration, whole) failed");
    for (int i = 0; i < n; i++)
        h += sprintf(h, "%02x", eb->sync_data[i]);
    char *strs[3] = { eb->manufacturer, eb->product, eb->serial };
    size_t caps[3] = { sizeof eb->manufacturer, sizeof eb->product, sizeof eb->serial };
    for (int i = 0; i < 3; i++) {
        n = soc_control(eb, 0x80, 6, (uint16_t)(0x0300 | (i + 1)), 0x0409, 255, &st);
        if (st || n < 2)
            die("%s", "GET_DESCRIPTOR(string) failed");
        ascii_of(eb->sync_data, n, strs[i], caps[i]);
    }
    soc_control(eb, 0x00, 9, 1, 0, 0, &st);
    if (st)
        die("%s", "SET_CONFIGURATION(1) failed");
    if (eb->emu->verbose)
        fprintf(stderr, "usb_emu: enumerated the simulated board at %d:%d: serial %s, descriptors %s\n", eb->bus,
                eb->dev, eb->serial, eb->desc_hex);
}

static void soc_connect(emu_board *eb, const char *path)
{
    struct sockaddr_un sa;
    memset(&sa, 0, sizeof sa);
    sa.sun_family = AF_UNIX;
    if (strlen(path) >= sizeof sa.sun_path)
        die("--soc %s: path too long", path);
    strcpy(sa.sun_path, path);
    for (int tries = 0;; tries++) {
        eb->soc_fd = socket(AF_UNIX, SOCK_STREAM, 0);
        if (eb->soc_fd < 0)
            die("socket: %s", strerror(errno));
        if (connect(eb->soc_fd, (struct sockaddr *)&sa, sizeof sa) == 0)
            break;
        close(eb->soc_fd);
        if (tries > 600)
            die("cannot connect to the simulated board's USB socket %s", path);
        nap_ms(100);
    }
    fcntl(eb->soc_fd, F_SETFL, fcntl(eb->soc_fd, F_GETFL) | O_NONBLOCK);
}

/* A URB for the simulated board. */
static void soc_submit(emu_board *eb, urb_rec *r)
{
    faults *f = &eb->emu->f;
    struct usbdevfs_urb *u = (struct usbdevfs_urb *)r->urb->data;
    uint8_t *d = r->buf->data;
    r->id = ++eb->next_id & ~SOC_SYNC;
    if (u->type == USBDEVFS_URB_TYPE_CONTROL) {
        const uint16_t wlen = (uint16_t)(d[6] | d[7] << 8);
        if (d[0] == EF_USB_RT_IN && d[1] == EF_USB_REQ_IDENTIFY)
            eb->identifies++;
        else if (d[0] == EF_USB_RT_IN && d[1] == EF_USB_REQ_STATUS)
            eb->statuses++;
        else if (d[0] == EF_USB_RT_OUT && d[1] == EF_USB_REQ_RESET)
            eb->resets++;
        else
            eb->ctrl_other++;
        const uint32_t out = (d[0] & 0x80) ? 0 : wlen;
        urb_append(&eb->pend_soc, r);
        soc_send(eb, USBW_SUBMIT, r->id, USBW_CONTROL, wlen, d, 8 + out);
        return;
    }
    if (u->endpoint == EF_USB_EP_OUT) {
        const long long start = eb->out_submitted, n = u->buffer_length;
        if (f->corrupt_out >= start && f->corrupt_out < start + n)
            d[f->corrupt_out - start] ^= 0x01;
        if (f->unplug_at > 0 && start + n > f->unplug_at) {
            /* The board takes exactly unplug_at bytes: the packets of this transfer before that
             * point reach it (a transfer of this program's, whose completion nobody awaits),
             * then it vanishes and the URB fails.  So a resumable run is left whatever way the
             * host cut its writes into transfers. */
            const long long k = f->unplug_at - start;
            f->unplug_at = 0;
            if (k > 0)
                soc_send(eb, USBW_SUBMIT, SOC_SYNC | ++eb->next_id, USBW_BULK | (uint32_t)EF_USB_EP_OUT << 8, 0, d,
                         (uint32_t)k);
            eb->out_submitted += k;
            r->status = -ENODEV, r->actual = 0;
            urb_append(&eb->done, r);
            unplug(eb);
            return;
        }
        eb->out_submitted += n;
        urb_append(&eb->pend_soc, r);
        soc_send(eb, USBW_SUBMIT, r->id, USBW_BULK | (uint32_t)EF_USB_EP_OUT << 8, 0, d, (uint32_t)n);
        if (f->stall_at > 0 && eb->out_submitted >= f->stall_at) {
            f->stall_at = 0; /* the board's CPU stops: the core NAKs; the next command finds it running */
            eb->frozen = 1;
            soc_send(eb, USBW_FREEZE, 0, 1, 0, NULL, 0);
        }
        return;
    }
    urb_append(&eb->pend_soc, r);
    soc_send(eb, USBW_SUBMIT, r->id, USBW_BULK | (uint32_t)EF_USB_EP_IN << 8, (uint32_t)u->buffer_length, NULL, 0);
}

/* The board's STATUS (docs/board-usb.md 3.2) for the report. */
static int soc_status(emu_board *eb, uint8_t out[EF_USB_STATUS_LEN])
{
    int st, n = soc_control(eb, EF_USB_RT_IN, EF_USB_REQ_STATUS, 0, 0, EF_USB_STATUS_LEN, &st);
    if (st || n != EF_USB_STATUS_LEN)
        return -1;
    memcpy(out, eb->sync_data, EF_USB_STATUS_LEN);
    return 0;
}

/* --------------------------------------------------------- usbfs ioctls */

static int find_addr(urb_rec **list, gulong addr, urb_rec **out)
{
    for (; *list; list = &(*list)->next)
        if ((*list)->urb->client_addr == addr) {
            *out = *list;
            *list = (*list)->next;
            return 1;
        }
    return 0;
}

static void nap_ms(int ms)
{
    struct timespec ts = { 0, (long)ms * 1000000L };
    nanosleep(&ts, NULL);
}

static gboolean on_ioctl(UMockdevIoctlBase *handler, UMockdevIoctlClient *client, gpointer user)
{
    emu_board *eb = user;
    emu *e = eb->emu;
    (void)handler;
    gulong request = umockdev_ioctl_client_get_request(client);
    UMockdevIoctlData *arg = umockdev_ioctl_client_get_arg(client);
    int nap = 0;
    gboolean handled = TRUE;

    pthread_mutex_lock(&e->mu);
    switch (request) {
    case USBDEVFS_GET_CAPABILITIES: {
        /* No size limit and scatter-gather: libusb then sends each transfer
         * as one URB instead of cutting it into 16 KiB pieces. */
        UMockdevIoctlData *d = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), NULL);
        *(guint32 *)d->data = USBDEVFS_CAP_BULK_SCATTER_GATHER | USBDEVFS_CAP_BULK_CONTINUATION |
                              USBDEVFS_CAP_NO_PACKET_SIZE_LIM | USBDEVFS_CAP_REAP_AFTER_DISCONNECT |
                              USBDEVFS_CAP_ZERO_PACKET;
        g_object_unref(d);
        umockdev_ioctl_client_complete(client, 0, 0);
        break;
    }
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_SETINTERFACE:
    case USBDEVFS_SETCONFIGURATION:
    case USBDEVFS_CLEAR_HALT:
    case USBDEVFS_RESETEP:
    case USBDEVFS_RESET:
        if (eb->gone)
            umockdev_ioctl_client_complete(client, -1, ENODEV);
        else
            umockdev_ioctl_client_complete(client, 0, 0);
        break;
    case USBDEVFS_GETDRIVER:
        umockdev_ioctl_client_complete(client, -1, ENODATA); /* no kernel driver bound */
        break;
    case USBDEVFS_SUBMITURB: {
        if (eb->gone) {
            umockdev_ioctl_client_complete(client, -1, ENODEV);
            break;
        }
        urb_rec *r = calloc(1, sizeof *r);
        if (!r)
            die("%s", "out of memory");
        r->urb = umockdev_ioctl_data_resolve(arg, 0, sizeof(struct usbdevfs_urb), NULL);
        struct usbdevfs_urb *u = (struct usbdevfs_urb *)r->urb->data;
        r->buf = umockdev_ioctl_data_resolve(r->urb, G_STRUCT_OFFSET(struct usbdevfs_urb, buffer),
                                             (gsize)u->buffer_length, NULL);
        eb->urbs++;
        if (e->soc &&
            ((u->type == USBDEVFS_URB_TYPE_CONTROL && u->buffer_length >= 8) ||
             (u->type == USBDEVFS_URB_TYPE_BULK && (u->endpoint == EF_USB_EP_OUT || u->endpoint == EF_USB_EP_IN)))) {
            soc_submit(eb, r);
        } else if (u->type == USBDEVFS_URB_TYPE_CONTROL && u->buffer_length >= 8) {
            int n = control(eb, r->buf->data, u->buffer_length);
            r->status = n < 0 ? n : 0;
            r->actual = n < 0 ? 0 : n;
            urb_append(&eb->done, r);
        } else if (u->type == USBDEVFS_URB_TYPE_BULK && u->endpoint == EF_USB_EP_OUT) {
            if (eb->stalled) {
                urb_append(&eb->pend_out, r);
            } else {
                int st;
                board_take(eb, r->buf->data, (size_t)u->buffer_length, &st);
                r->status = st;
                r->actual = st ? 0 : u->buffer_length;
                urb_append(&eb->done, r);
            }
        } else if (u->type == USBDEVFS_URB_TYPE_BULK && u->endpoint == EF_USB_EP_IN) {
            urb_append(&eb->pend_in, r);
        } else {
            urb_free(r);
            umockdev_ioctl_client_complete(client, -1, EINVAL);
            break;
        }
        umockdev_ioctl_client_complete(client, 0, 0);
        break;
    }
    case USBDEVFS_REAPURB:
    case USBDEVFS_REAPURBNDELAY: {
        if (e->soc)
            soc_pump(eb, 0);
        else
            serve_in(eb);
        urb_rec *r = urb_pop(&eb->done);
        if (!r) {
            /* The node is a plain file, so poll always says "ready" and
             * libusb asks again at once: a short nap keeps that spin cheap. */
            nap = 1;
            umockdev_ioctl_client_complete(client, -1, eb->gone ? ENODEV : EAGAIN);
            break;
        }
        struct usbdevfs_urb *u = (struct usbdevfs_urb *)r->urb->data;
        u->status = r->status;
        u->actual_length = r->actual;
        UMockdevIoctlData *slot = umockdev_ioctl_data_resolve(arg, 0, sizeof(gpointer), NULL);
        umockdev_ioctl_data_set_ptr(slot, 0, r->urb);
        umockdev_ioctl_client_complete(client, 0, 0);
        g_object_unref(slot);
        urb_free(r);
        break;
    }
    case USBDEVFS_DISCARDURB: {
        /* The argument is the URB's address in the client, not a pointer to
         * resolve.  A discarded URB must still be reaped (-ENOENT), or
         * libusb's cancel and timeout never finish. */
        gulong addr = *(gulong *)arg->data;
        urb_rec *r;
        if (e->soc) {
            /* the simulated board completes it with what it has (-ENOENT), reaped as usual */
            for (r = eb->pend_soc; r && r->urb->client_addr != addr; r = r->next)
                ;
            if (r) {
                soc_send(eb, USBW_CANCEL, r->id, 0, 0, NULL, 0);
                eb->discards++;
                umockdev_ioctl_client_complete(client, 0, 0);
            } else {
                umockdev_ioctl_client_complete(client, -1, EINVAL);
            }
        } else if (find_addr(&eb->pend_in, addr, &r) || find_addr(&eb->pend_out, addr, &r)) {
            r->status = -ENOENT, r->actual = 0;
            urb_append(&eb->done, r);
            eb->discards++;
            umockdev_ioctl_client_complete(client, 0, 0);
        } else {
            umockdev_ioctl_client_complete(client, -1, EINVAL);
        }
        break;
    }
    default:
        if (e->verbose)
            fprintf(stderr, "usb_emu: unhandled ioctl 0x%lx\n", request);
        handled = FALSE;
        break;
    }
    pthread_mutex_unlock(&e->mu);
    if (nap)
        nap_ms(1);
    return handled;
}

/* ------------------------------------------------------- the testbed */

static void plug(emu_board *eb)
{
    emu *e = eb->emu;
    char node[64], desc[4096];
    snprintf(node, sizeof node, "/dev/bus/usb/%03d/%03d", eb->bus, eb->dev);
    if (e->soc) {
        /* the device the gateware is: its descriptors and strings as it returned them */
        pthread_mutex_lock(&e->mu);
        soc_enumerate(eb);
        pthread_mutex_unlock(&e->mu);
        unsigned v[3];
        for (int k = 0; k < 3; k++) {
            unsigned lo, hi;
            sscanf(eb->desc_hex + 16 + 4 * k, "%2x%2x", &lo, &hi);
            v[k] = lo | hi << 8;
        }
        snprintf(desc, sizeof desc,
                 "P: /devices/usb%d/%d-%d\n"
                 "N: bus/usb/%03d/%03d\n"
                 "E: SUBSYSTEM=usb\n"
                 "E: DEVTYPE=usb_device\n"
                 "E: DRIVER=usb\n"
                 "E: PRODUCT=%x/%x/%x\n"
                 "E: BUSNUM=%03d\n"
                 "E: DEVNUM=%03d\n"
                 "E: DEVNAME=%s\n"
                 "A: busnum=%d\\n\n"
                 "A: devnum=%d\\n\n"
                 "A: bConfigurationValue=1\\n\n"
                 "A: bNumConfigurations=1\\n\n"
                 "A: speed=12\\n\n"
                 "A: idVendor=%04x\\n\n"
                 "A: idProduct=%04x\\n\n"
                 "A: manufacturer=%s\\n\n"
                 "A: product=%s\\n\n"
                 "A: serial=%s\\n\n"
                 "H: descriptors=%s\n",
                 eb->bus, eb->bus, eb->index + 1, eb->bus, eb->dev, v[0], v[1], v[2], eb->bus, eb->dev, node, eb->bus,
                 eb->dev, v[0], v[1], eb->manufacturer, eb->product, eb->serial, eb->desc_hex);
    } else {
        /* Device, configuration, interface (vendor class 0xff), bulk OUT 0x01 and
     * bulk IN 0x81 of 512 bytes: docs/board-usb.md section 2. */
        snprintf(desc, sizeof desc,
                 "P: /devices/usb%d/%d-%d\n"
                 "N: bus/usb/%03d/%03d\n"
                 "E: SUBSYSTEM=usb\n"
                 "E: DEVTYPE=usb_device\n"
                 "E: DRIVER=usb\n"
                 "E: PRODUCT=1209/1/100\n"
                 "E: BUSNUM=%03d\n"
                 "E: DEVNUM=%03d\n"
                 "E: DEVNAME=%s\n"
                 "A: busnum=%d\\n\n"
                 "A: devnum=%d\\n\n"
                 "A: bConfigurationValue=1\\n\n"
                 "A: bNumConfigurations=1\\n\n"
                 "A: speed=480\\n\n"
                 "A: idVendor=1209\\n\n"
                 "A: idProduct=0001\\n\n"
                 "A: manufacturer=edgeflag\\n\n"
                 "A: product=edgeflag board (emulated)\\n\n"
                 "A: serial=%s\\n\n"
                 "H: descriptors=120100020000004009120100000101020301"
                 "090220000101008032"
                 "0904000002ff000000"
                 "07050102000200"
                 "07058102000200\n",
                 eb->bus, eb->bus, eb->index + 1, eb->bus, eb->dev, eb->bus, eb->dev, node, eb->bus, eb->dev,
                 eb->serial);
    }
    if (eb->handler)
        g_object_unref(eb->handler);
    eb->handler = umockdev_ioctl_base_new();
    g_signal_connect(eb->handler, "handle-ioctl", G_CALLBACK(on_ioctl), eb);
    GError *err = NULL;
    /* The handler first, then the device with its node (umockdev issue 173). */
    if (!umockdev_testbed_attach_ioctl(e->tb, node, eb->handler, &err))
        die("attach_ioctl: %s", err ? err->message : "?");
    if (!umockdev_testbed_add_from_string(e->tb, desc, &err))
        die("add_from_string: %s", err ? err->message : "?");
    snprintf(eb->syspath, sizeof eb->syspath, "/sys/devices/usb%d/%d-%d", eb->bus, eb->bus, eb->index + 1);
    eb->gone = 0;
    eb->stalled = 0;
}

/* Before each command: a fresh usbfs client, the board's state kept. */
static void prepare_run(emu *e)
{
    for (int i = 0; i < e->nboards; i++) {
        emu_board *eb = &e->boards[i];
        pthread_mutex_lock(&e->mu);
        urb_drop_all(&eb->pend_in);
        urb_drop_all(&eb->pend_out);
        urb_drop_all(&eb->done);
        if (e->soc) {
            /* what the last client left at the simulated board ends with it, as the kernel
             * kills a closed file's URBs; a frozen board runs again */
            for (urb_rec *r = eb->pend_soc; r; r = r->next)
                soc_send(eb, USBW_CANCEL, r->id, 0, 0, NULL, 0);
            urb_drop_all(&eb->pend_soc);
            if (eb->frozen)
                soc_send(eb, USBW_FREEZE, 0, 0, 0, NULL, 0);
            eb->frozen = 0;
        }
        int replug = eb->gone;
        pthread_mutex_unlock(&e->mu);
        if (replug) {
            eb->dev++; /* a new address, as after a real replug */
            plug(eb);
        }
        eb->stalled = 0;
        if (e->soc) {
            /* The simulation runs some 400 times slower than the board: the host's fixed 1 s
             * control timeout is a few ms of board time, less than the firmware may still
             * spend on bytes it took before a freeze or an unplug (a frame's commands take it
             * tens of ms, and it answers control requests only between them).  So the next
             * command starts once the board is quiet: two STATUS answers in a row alike, as a
             * real board would be long before a user could type the command. */
            uint8_t st[EF_USB_STATUS_LEN], prev[EF_USB_STATUS_LEN];
            pthread_mutex_lock(&e->mu);
            int ok = soc_status(eb, prev) == 0;
            for (int k = 0; ok && k < 100; k++) {
                ok = soc_status(eb, st) == 0;
                if (!ok || !memcmp(st, prev, sizeof st))
                    break;
                memcpy(prev, st, sizeof st);
            }
            pthread_mutex_unlock(&e->mu);
        }
    }
}

static int run(emu *e, const char *cmd)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0)
        die("fork: %s", strerror(errno));
    if (pid == 0) {
        if (e->f.eacces) {
            /* An ordinary user with no udev rule: root would open anything. */
            struct passwd *pw = getpwnam("nobody");
            if (!pw || setgroups(0, NULL) || setgid(pw->pw_gid) || setuid(pw->pw_uid)) {
                perror("usb_emu: cannot become nobody");
                _exit(70);
            }
        }
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR)
            die("waitpid: %s", strerror(errno));
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

static void parse_faults(faults *f, const char *spec)
{
    char *s = strdup(spec), *save = NULL;
    for (char *t = strtok_r(s, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        char *v = strchr(t, '=');
        if (v)
            *v++ = 0;
        if (!strcmp(t, "eacces")) {
            f->eacces = 1;
            continue;
        }
        if (!v)
            die("fault '%s' needs =VALUE", t);
        if (!strcmp(t, "magic")) {
            if (strlen(v) != 4)
                die("magic=%s: 4 characters", v);
            memcpy(f->magic, v, 5);
            continue;
        }
        char *end;
        long long n = strtoll(v, &end, 10);
        if (*end || n < 0)
            die("fault value '%s' is not a number", v);
        if (!strcmp(t, "unplug-at"))
            f->unplug_at = n;
        else if (!strcmp(t, "unplug-in"))
            f->unplug_in = n;
        else if (!strcmp(t, "stall-at"))
            f->stall_at = n;
        else if (!strcmp(t, "reset-at"))
            f->reset_at = n;
        else if (!strcmp(t, "corrupt-out"))
            f->corrupt_out = n;
        else if (!strcmp(t, "corrupt-in"))
            f->corrupt_in = (long)n;
        else if (!strcmp(t, "drop-ack"))
            f->drop_ack = (long)n;
        else if (!strcmp(t, "identify-stall"))
            f->identify_stall = (long)n;
        else if (!strcmp(t, "protocol"))
            f->protocol = (long)n;
        else
            die("unknown fault '%s'", t);
    }
    free(s);
}

static void report(emu *e, const char *path, const int *rc, int nruns)
{
    FILE *o = fopen(path, "w");
    if (!o)
        die("cannot write %s", path);
    for (int i = 0; i < nruns; i++)
        fprintf(o, "run%d_exit=%d\n", i + 1, rc[i]);
    for (int i = 0; i < e->nboards; i++) {
        emu_board *eb = &e->boards[i];
        ef_board_stats s;
        memset(&s, 0, sizeof s);
        if (e->soc) {
            /* the simulated board's counters, from its STATUS (docs/board-usb.md 3.2) */
            uint8_t st[EF_USB_STATUS_LEN];
            if (eb->gone || soc_status(eb, st) != 0) {
                fprintf(o, "status_read=0\n");
            } else {
#define LE32(p) ((uint32_t)(p)[0] | (uint32_t)(p)[1] << 8 | (uint32_t)(p)[2] << 16 | (uint32_t)(p)[3] << 24)
                s.state = st[6], s.rx_seq = LE32(st + 8), s.res_next = LE32(st + 12), s.res_acked = LE32(st + 16);
                s.input_crc = LE32(st + 20);
                s.cmds = LE32(st + 24) | (uint64_t)LE32(st + 28) << 32;
                s.records = LE32(st + 32) | (uint64_t)LE32(st + 36) << 32;
#undef LE32
            }
        } else {
            ef_board_get_stats(eb->b, &s);
        }
        const char *p = e->nboards > 1 ? eb->serial : NULL;
#define KV(k, fmt, v) fprintf(o, "%s%s" k "=" fmt "\n", p ? p : "", p ? "." : "", v)
        fprintf(o, "%s%saddress=%d:%d\n", p ? p : "", p ? "." : "", eb->bus, eb->dev);
        if (e->soc) /* what the gateware enumerated with */
            fprintf(o, "usb_descriptors=%s\nusb_serial=%s\nusb_manufacturer=%s\nusb_product=%s\n", eb->desc_hex,
                    eb->serial, eb->manufacturer, eb->product);
        KV("out_bytes", "%lld", eb->out_bytes);
        KV("in_bytes", "%lld", eb->in_bytes);
        KV("urbs", "%lld", eb->urbs);
        KV("discards", "%lld", eb->discards);
        KV("identify", "%ld", eb->identifies);
        KV("status", "%ld", eb->statuses);
        KV("reset", "%ld", eb->resets);
        KV("ctrl_other", "%ld", eb->ctrl_other);
        KV("rx_refused", "%ld", eb->rx_refused);
        KV("acks_dropped", "%ld", eb->acks_dropped);
        KV("frames_corrupted", "%ld", eb->frames_corrupted);
        KV("frames_ok", "%llu", (unsigned long long)s.frames_ok);
        KV("frames_bad", "%llu", (unsigned long long)s.frames_bad);
        KV("frames_dup", "%llu", (unsigned long long)s.frames_dup);
        KV("frames_gap", "%llu", (unsigned long long)s.frames_gap);
        KV("naks", "%llu", (unsigned long long)s.naks);
        KV("cmds", "%llu", (unsigned long long)s.cmds);
        KV("records", "%llu", (unsigned long long)s.records);
        KV("input_crc", "%08x", (unsigned)s.input_crc);
        KV("rx_seq", "%u", (unsigned)s.rx_seq);
        KV("state", "%d", s.state);
#undef KV
    }
    fclose(o);
}

/* The emulator itself runs under the preload too: umockdev's uevent sender
 * looks the device up through libudev, which must see the testbed's /sys,
 * not the machine's.  The commands inherit it. */
static void ensure_preload(char **argv)
{
    const char *pre = getenv("LD_PRELOAD");
    if (pre && strstr(pre, "libumockdev-preload"))
        return;
    char lp[1024];
    snprintf(lp, sizeof lp, "libumockdev-preload.so.0%s%s", pre && *pre ? ":" : "", pre ? pre : "");
    setenv("LD_PRELOAD", lp, 1);
    execv("/proc/self/exe", argv);
    die("cannot re-execute under umockdev's preload: %s", strerror(errno));
}

int main(int argc, char **argv)
{
    static emu e;
    ensure_preload(argv);
    const char *runs[MAX_RUNS], *report_path = NULL, *dut_log = NULL;
    int nruns = 0, bus = 1;
    const char *serials[MAX_BOARDS];
    int nser = 0;
    e.f.protocol = -1;
    e.f.corrupt_out = -1;
    const char *env = getenv("EF_USB_EMU_FAULT");
    if (env && *env)
        parse_faults(&e.f, env);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "-v")) {
            e.verbose = 1;
            continue;
        }
        if (!v)
            die("%s needs a value (usage: see the header of tests/host/usb_emu.c)", a);
        i++;
        if (!strcmp(a, "--run") && nruns < MAX_RUNS)
            runs[nruns++] = v;
        else if (!strcmp(a, "--serial") && nser < MAX_BOARDS)
            serials[nser++] = v;
        else if (!strcmp(a, "--bus"))
            bus = atoi(v);
        else if (!strcmp(a, "--fault"))
            parse_faults(&e.f, v);
        else if (!strcmp(a, "--report"))
            report_path = v;
        else if (!strcmp(a, "--dut-log"))
            dut_log = v;
        else if (!strcmp(a, "--soc"))
            e.soc = v;
        else
            die("unknown option %s", a);
    }
    if (nruns == 0)
        die("%s", "nothing to run: give --run 'COMMAND'");
    if (e.soc) {
        faults *f = &e.f;
        if (nser > 0 || dut_log)
            die("%s", "--soc: one board, the simulated SoC (its serial is its own; its DUT is ef_raster)");
        if (f->reset_at || f->corrupt_in || f->drop_ack || f->magic[0] || f->protocol >= 0 || f->identify_stall)
            die("%s", "--soc: the faults are unplug-at, unplug-in, stall-at, corrupt-out and eacces (the others "
                      "change what the board itself does)");
        serials[nser++] = "";
    }
    if (nser == 0)
        serials[nser++] = "EMU0001";
    if (dut_log && !(e.dut_log = fopen(dut_log, "wb")))
        die("cannot write %s", dut_log);
    pthread_mutex_init(&e.mu, NULL);
    signal(SIGPIPE, SIG_IGN);

    e.tb = umockdev_testbed_new();
    if (!e.tb)
        die("%s", "umockdev_testbed_new failed");
    e.nboards = nser;
    for (int i = 0; i < nser; i++) {
        emu_board *eb = &e.boards[i];
        eb->emu = &e;
        eb->index = i;
        eb->bus = bus;
        eb->dev = 4 + i;
        snprintf(eb->serial, sizeof eb->serial, "%s", serials[i]);
        /* What the simulated board reports (transport_sim.c): the C model
         * can do every size, sample count and interface. */
        ef_proto_info info = { .capabilities = EF_PROTO_CAP_RESULTS | EF_PROTO_CAP_RESUME | EF_PROTO_CAP_INTERNAL,
                               .samples_mask = 1u << ef_proto_samples_bit(8) | 1u << ef_proto_samples_bit(16) |
                                               1u << ef_proto_samples_bit(32),
                               .width_max = 16384,
                               .height_max = 16384,
                               .edges_max = 1u << 22,
                               .window = 16,
                               .iface_mask = (1u << 7) - 1 };
        snprintf(info.serial, sizeof info.serial, "%s", serials[i]);
        if (e.soc) {
            soc_connect(eb, e.soc);
        } else {
            eb->b = ef_board_new(&info, dut_logged(&e));
            if (!eb->b)
                die("%s", "ef_board_new failed");
        }
        plug(eb);
    }
    if (e.f.eacces) {
        /* The testbed open to all (the user's libudev monitor binds its
         * emulated netlink socket in there), the node root-only, as
         * /dev/bus/usb nodes are without a udev rule. */
        char *root = umockdev_testbed_get_root_dir(e.tb), cmd[600];
        snprintf(cmd, sizeof cmd, "chmod -R a+rwX '%s' && chmod 0600 '%s'/dev/bus/usb/*/*", root, root);
        if (system(cmd) != 0)
            die("%s", "chmod of the testbed failed");
        g_free(root);
    }

    int rc[MAX_RUNS];
    for (int i = 0; i < nruns; i++) {
        if (i > 0)
            prepare_run(&e);
        rc[i] = run(&e, runs[i]);
    }
    if (report_path)
        report(&e, report_path, rc, nruns);
    if (e.dut_log)
        fclose(e.dut_log);
    pthread_mutex_lock(&e.mu);
    for (int i = 0; i < e.nboards; i++) {
        urb_drop_all(&e.boards[i].pend_in);
        urb_drop_all(&e.boards[i].pend_out);
        urb_drop_all(&e.boards[i].done);
        urb_drop_all(&e.boards[i].pend_soc);
    }
    pthread_mutex_unlock(&e.mu);
    g_object_unref(e.tb);
    for (int i = 0; i < e.nboards; i++) {
        if (e.boards[i].b)
            ef_board_free(e.boards[i].b);
        free(e.boards[i].srx);
        if (e.boards[i].soc_fd > 0)
            close(e.boards[i].soc_fd);
        free(e.boards[i].stage);
        free(e.boards[i].deliver);
    }
    return rc[nruns - 1];
}
