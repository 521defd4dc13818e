/*
 * transport_gpio.c - ef_transport_gpio: the board protocol's byte stream over
 * a parallel bus bit-banged on GPIO lines (docs/board-gpio.md).  The host is
 * the bus master: every byte either way costs one bus cycle of
 * setup writes, a clock-high write, hold steps and one read of the board's
 * lines.  Host-to-board and board-to-host bytes share a cycle whenever both
 * are pending, so a run's acks and results flow while its commands go out.
 *
 * Library calls go through gpio_lib.h (libgpiod v1, v2 or none); this file
 * knows the bus, not the library.
 */
#include "transport.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ef_board.h"
#include "ef_frame.h"
#include "gpio_bus.h"
#include "gpio_lib.h"
#include "transport_gpio.h"

/* The bus's signals (docs/board-gpio.md section 2).  Outputs first, in the
 * order of the output request (bit i of ef_gpiol_set), then inputs. */
/* clang-format off */
enum {
    SIG_D0 = 0, SIG_CLK = 8, SIG_VALID, SIG_TAKE, SIG_CTL,
    SIG_Q0 = 12, SIG_READY = 20, SIG_AVAIL, SIG_DONE, SIG_ERR,
    SIG_COUNT, SIG_OUTPUTS = 12, SIG_INPUTS = 12
};
static const char *const sig_name[SIG_COUNT] = {
    "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "clk", "valid", "take", "ctl",
    "q0", "q1", "q2", "q3", "q4", "q5", "q6", "q7", "ready", "avail", "done", "err"
};
/* clang-format on */
#define OUT_BIT(sig) ((uint32_t)1 << (sig))
#define IN_BIT(sig) ((uint32_t)1 << ((sig)-SIG_INPUTS))

#define DEFAULT_TIMEOUT_MS 1000
#define STEPS_MAX 1000
#define RING 65536 /* board bytes taken during writes, for read() */
#define NAME_MAX_LEN 48
#define CONSUMER "edgeflag-host"

struct ef_link {
    char err[256]; /* the last failure, in words */
    ef_gpiol *c;
    char chip[64];
    unsigned offset[SIG_COUNT];
    unsigned setup, hold;
    int timeout_ms;    /* control replies and err queries (--timeout) */
    uint32_t in;       /* the board's lines at the last sample */
    int ctl;           /* ctl at the last edge */
    int engine_failed; /* err is high for an engine failure: bytes still flow */
    uint8_t ring[RING];
    size_t ring_head, ring_len;
    uint64_t cycles, sent, taken;
};

/* ---- the line map (docs/board-gpio.md section 6) ---- */

typedef struct line_map {
    char token[SIG_COUNT][NAME_MAX_LEN]; /* an offset in digits, or a line name */
    unsigned setup, hold;
} line_map;

static int sig_lookup(const char *key, size_t n)
{
    for (int i = 0; i < SIG_COUNT; i++)
        if (strlen(sig_name[i]) == n && memcmp(sig_name[i], key, n) == 0)
            return i;
    return -1;
}

static int is_number(const char *s, size_t n, unsigned long *v)
{
    if (n == 0 || n > 9)
        return 0;
    unsigned long r = 0;
    for (size_t i = 0; i < n; i++) {
        if (s[i] < '0' || s[i] > '9')
            return 0;
        r = r * 10 + (unsigned long)(s[i] - '0');
    }
    *v = r;
    return 1;
}

static int set_token(line_map *m, int sig, const char *v, size_t n, const char *item, char *err, size_t errlen)
{
    if (n == 0 || n >= NAME_MAX_LEN || memchr(v, '=', n)) {
        snprintf(err, errlen, "--lines: '%s': a line is an offset or a name of at most %d characters", item,
                 NAME_MAX_LEN - 1);
        return EF_HOST_EINVAL;
    }
    memcpy(m->token[sig], v, n);
    m->token[sig][n] = '\0';
    return 0;
}

/* d=A-B (eight consecutive offsets, d0 first) or d=L0:L1:...:L7. */
static int set_byte_bus(line_map *m, int first, const char *v, size_t n, const char *item, char *err, size_t errlen)
{
    const char *dash = memchr(v, '-', n);
    unsigned long a, b;
    if (dash && is_number(v, (size_t)(dash - v), &a) && is_number(dash + 1, n - (size_t)(dash - v) - 1, &b)) {
        if (!(b == a + 7 || a == b + 7)) {
            snprintf(err, errlen, "--lines: '%s': a range must span exactly 8 lines", item);
            return EF_HOST_EINVAL;
        }
        for (int i = 0; i < 8; i++)
            snprintf(m->token[first + i], NAME_MAX_LEN, "%lu", b > a ? a + (unsigned long)i : a - (unsigned long)i);
        return 0;
    }
    const char *p = v, *end = v + n;
    for (int i = 0; i < 8; i++) {
        const char *colon = memchr(p, ':', (size_t)(end - p));
        const char *stop = colon ? colon : end;
        if ((i < 7 && !colon) || (i == 7 && colon)) {
            snprintf(err, errlen, "--lines: '%s': give 8 lines separated by ':' or a range A-B", item);
            return EF_HOST_EINVAL;
        }
        int rc = set_token(m, first + i, p, (size_t)(stop - p), item, err, errlen);
        if (rc)
            return rc;
        p = stop + 1;
    }
    return 0;
}

static int parse_lines(line_map *m, const char *spec, char *err, size_t errlen)
{
    for (int i = 0; i < SIG_COUNT; i++) /* the default map: offset = signal index */
        snprintf(m->token[i], NAME_MAX_LEN, "%d", i);
    m->setup = m->hold = 1;
    if (!spec)
        return 0;
    const char *p = spec;
    while (*p) {
        const char *comma = strchr(p, ',');
        size_t n = comma ? (size_t)(comma - p) : strlen(p);
        char item[128];
        snprintf(item, sizeof item, "%.*s", (int)(n < 100 ? n : 100), p);
        const char *eq = memchr(p, '=', n);
        if (!eq) {
            snprintf(err, errlen, "--lines: '%s': expected SIGNAL=LINE", item);
            return EF_HOST_EINVAL;
        }
        size_t kn = (size_t)(eq - p), vn = n - kn - 1;
        const char *v = eq + 1;
        unsigned long num;
        int sig, rc = 0;
        if ((kn == 5 && memcmp(p, "setup", 5) == 0) || (kn == 4 && memcmp(p, "hold", 4) == 0)) {
            if (!is_number(v, vn, &num) || num < 1 || num > STEPS_MAX) {
                snprintf(err, errlen, "--lines: '%s': steps must be 1 to %d", item, STEPS_MAX);
                return EF_HOST_EINVAL;
            }
            *(kn == 5 ? &m->setup : &m->hold) = (unsigned)num;
        } else if (kn == 1 && (*p == 'd' || *p == 'q')) {
            rc = set_byte_bus(m, *p == 'd' ? SIG_D0 : SIG_Q0, v, vn, item, err, errlen);
        } else if ((sig = sig_lookup(p, kn)) >= 0) {
            rc = set_token(m, sig, v, vn, item, err, errlen);
        } else {
            snprintf(err, errlen,
                     "--lines: '%s': unknown signal (d, q, d0..d7, q0..q7, clk, valid, take, ctl, "
                     "ready, avail, done, err, setup, hold)",
                     item);
            return EF_HOST_EINVAL;
        }
        if (rc)
            return rc;
        p += n + (comma ? 1 : 0);
        if (comma && !*p) {
            snprintf(err, errlen, "--lines: trailing ','");
            return EF_HOST_EINVAL;
        }
    }
    /* The same line twice is wrong on any chip: say so before opening one
     * (names and offsets that meet on the chip are caught by resolve_lines). */
    for (int a = 0; a < SIG_COUNT; a++)
        for (int b = a + 1; b < SIG_COUNT; b++)
            if (strcmp(m->token[a], m->token[b]) == 0) {
                snprintf(err, errlen, "--lines: line %s is mapped to both %s and %s", m->token[a], sig_name[a],
                         sig_name[b]);
                return EF_HOST_EINVAL;
            }
    return 0;
}

/* Turns the map's tokens into offsets on the open chip. */
static int resolve_lines(ef_link *l, const line_map *m, char *err, size_t errlen)
{
    char label[64];
    unsigned nlines;
    int rc = ef_gpiol_info(l->c, label, sizeof label, &nlines);
    if (rc) {
        snprintf(err, errlen, "%s: cannot read the chip's information: %s", l->chip, ef_host_strerror(rc));
        return rc;
    }
    char(*names)[NAME_MAX_LEN] = NULL; /* read once, only when a name is used */
    for (int s = 0; s < SIG_COUNT && rc == 0; s++) {
        unsigned long num;
        const char *t = m->token[s];
        if (is_number(t, strlen(t), &num)) {
            if (num >= nlines) {
                snprintf(err, errlen, "--lines: %s=%s: %s has %u lines (0 to %u)", sig_name[s], t, l->chip, nlines,
                         nlines - 1);
                rc = EF_HOST_EINVAL;
            }
            l->offset[s] = (unsigned)num;
            continue;
        }
        if (!names) {
            names = calloc(nlines ? nlines : 1, sizeof *names);
            if (!names)
                return EF_HOST_ENOMEM;
            char consumer[8];
            for (unsigned i = 0; i < nlines && rc == 0; i++)
                rc = ef_gpiol_line(l->c, i, names[i], sizeof names[i], consumer, sizeof consumer);
            if (rc) {
                snprintf(err, errlen, "%s: cannot read the line names: %s", l->chip, ef_host_strerror(rc));
                break;
            }
        }
        int found = -1, count = 0;
        for (unsigned i = 0; i < nlines; i++)
            if (strcmp(names[i], t) == 0)
                found = (int)i, count++;
        if (count != 1) {
            snprintf(err, errlen, "--lines: %s=%s: %s has %s line named '%s'", sig_name[s], t, l->chip,
                     count ? "more than one" : "no", t);
            rc = count ? EF_HOST_EAMBIGUOUS : EF_HOST_ENOTFOUND;
        }
        l->offset[s] = (unsigned)found;
    }
    free(names);
    for (int a = 0; a < SIG_COUNT && rc == 0; a++)
        for (int b = a + 1; b < SIG_COUNT; b++)
            if (l->offset[a] == l->offset[b]) {
                snprintf(err, errlen, "--lines: line %u of %s is mapped to both %s and %s", l->offset[a], l->chip,
                         sig_name[a], sig_name[b]);
                rc = EF_HOST_EINVAL;
                break;
            }
    return rc;
}

/* ---- chips ---- */

static int chip_filter(const struct dirent *e) { return strncmp(e->d_name, "gpiochip", 8) == 0; }

/* /dev/gpiochip* in numeric order; returns the count or a negative error. */
static int list_chips(char (*paths)[64], int max)
{
    DIR *d = opendir("/dev");
    if (!d)
        return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)))
        if (chip_filter(e)) {
            if (n < max)
                snprintf(paths[n], 64, "/dev/%.50s", e->d_name);
            n++;
        }
    closedir(d);
    int m = n < max ? n : max;
    for (int i = 1; i < m; i++) /* insertion sort by chip number */
        for (int j = i; j > 0 && atoi(paths[j - 1] + 13) > atoi(paths[j] + 13); j--) {
            char t[64];
            memcpy(t, paths[j], 64), memcpy(paths[j], paths[j - 1], 64), memcpy(paths[j - 1], t, 64);
        }
    return n;
}

/* --chip: a path, gpiochipN, N, or a chip label; absent: the only chip. */
static int resolve_chip(const char *chip, char *path, size_t pathlen, char *err, size_t errlen)
{
    char paths[64][64];
    unsigned long num;
    if (chip && strchr(chip, '/')) {
        snprintf(path, pathlen, "%s", chip);
        return 0;
    }
    if (chip && strncmp(chip, "gpiochip", 8) == 0) {
        snprintf(path, pathlen, "/dev/%s", chip);
        return 0;
    }
    if (chip && is_number(chip, strlen(chip), &num)) {
        snprintf(path, pathlen, "/dev/gpiochip%lu", num);
        return 0;
    }
    int n = list_chips(paths, 64);
    if (!chip) {
        if (n == 1) {
            snprintf(path, pathlen, "%.63s", paths[0]);
            return 0;
        }
        snprintf(err, errlen,
                 n ? "%d GPIO chips: choose one with --chip (edgeflag-host list shows them)"
                   : "no GPIO chip found (/dev/gpiochip*)",
                 n);
        return n ? EF_HOST_EAMBIGUOUS : EF_HOST_ENOTFOUND;
    }
    int hits = 0;
    for (int i = 0; i < n && i < 64; i++) {
        ef_gpiol *c;
        char label[64], e2[64];
        unsigned lines;
        if (ef_gpiol_open(&c, paths[i], e2, sizeof e2) != 0)
            continue;
        if (ef_gpiol_info(c, label, sizeof label, &lines) == 0 && strcmp(label, chip) == 0) {
            if (!hits++)
                snprintf(path, pathlen, "%.63s", paths[i]);
        }
        ef_gpiol_close(c);
    }
    if (hits == 1)
        return 0;
    snprintf(err, errlen,
             hits ? "--chip %s: several chips have this label; give the path"
                  : "--chip %s: no GPIO chip has this name or label",
             chip);
    return hits ? EF_HOST_EAMBIGUOUS : EF_HOST_ENOTFOUND;
}

/* ---- bus cycles (docs/board-gpio.md section 4) ---- */

static int fail_io(ef_link *l, int rc, const char *what)
{
    snprintf(l->err, sizeof l->err, "%s: %s failed: %s", l->chip, what, ef_host_strerror(rc));
    return rc == EF_HOST_ENOTFOUND ? EF_HOST_ENODEV : rc;
}

static int sample(ef_link *l)
{
    uint32_t v;
    int rc = ef_gpiol_get(l->c, &v);
    if (rc)
        return fail_io(l, rc, "reading the board's lines");
    l->in = v;
    return 0;
}

/* One cycle: setup writes with clk low, `hold` writes with clk high (the
 * first is the rising edge), then the read that ends the hold time. */
static int cycle(ef_link *l, uint8_t d, uint32_t ctrl)
{
    uint32_t v = d | ctrl;
    for (unsigned i = 0; i < l->setup; i++) {
        int rc = ef_gpiol_set(l->c, v);
        if (rc)
            return fail_io(l, rc, "driving the bus");
    }
    v |= OUT_BIT(SIG_CLK);
    for (unsigned i = 0; i < l->hold; i++) {
        int rc = ef_gpiol_set(l->c, v);
        if (rc)
            return fail_io(l, rc, "driving the bus");
    }
    l->ctl = (ctrl & OUT_BIT(SIG_CTL)) != 0;
    l->cycles++;
    return sample(l);
}

static uint8_t in_q(const ef_link *l) { return (uint8_t)(l->in >> (SIG_Q0 - SIG_INPUTS)); }

static int in_line(const ef_link *l, int sig) { return (l->in & IN_BIT(sig)) != 0; }

static int64_t now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

/* Waits for the board to raise sig; polls fast first, then backs off to 1 ms
 * so a stalled board does not cost a core.  A timeout is declared only on a
 * sample taken after the deadline: a host paused past it (a sleep that
 * overran, the scheduler) samples once more first, so a board that raised
 * the line meanwhile is not called stalled. */
static int wait_line(ef_link *l, int sig, int timeout_ms, int64_t *waited)
{
    int64_t t0 = now_ms();
    int late = 0; /* the last sample was taken after the deadline */
    for (unsigned spin = 0; !in_line(l, sig); spin++) {
        if (sig != SIG_ERR && in_line(l, SIG_ERR) && !l->ctl && !l->engine_failed)
            return EF_HOST_EIO; /* the caller asks why (err_line) */
        if (late) {
            *waited = now_ms() - t0;
            return EF_HOST_ETIMEDOUT;
        }
        if (now_ms() - t0 >= timeout_ms) {
            late = 1; /* one more sample, then the verdict */
            int rc = sample(l);
            if (rc)
                return rc;
            continue;
        }
        if (spin >= 64) {
            struct timespec ts = { 0, spin < 256 ? 100000 : 1000000 };
            nanosleep(&ts, NULL);
        }
        int rc = sample(l);
        if (rc)
            return rc;
    }
    return 0;
}

/* A control request (section 5): enter the control view with the code,
 * take len reply bytes, leave it with an idle edge. */
static int control(ef_link *l, uint8_t code, uint8_t *out, size_t len, int timeout_ms, const char *what)
{
    int rc = cycle(l, code, OUT_BIT(SIG_CTL) | OUT_BIT(SIG_VALID));
    for (size_t i = 0; rc == 0 && i < len; i++) {
        int64_t waited = 0;
        rc = wait_line(l, SIG_AVAIL, timeout_ms, &waited);
        if (rc == EF_HOST_ETIMEDOUT)
            snprintf(l->err, sizeof l->err,
                     "%s: no %s reply from the board after %d of %zu bytes in %lld ms "
                     "(is a board on these lines? docs/board-gpio.md)",
                     l->chip, what, (int)i, len, (long long)waited);
        if (rc)
            break;
        out[i] = in_q(l);
        rc = cycle(l, 0, OUT_BIT(SIG_CTL) | OUT_BIT(SIG_TAKE));
    }
    int rc2 = cycle(l, 0, 0); /* back to the stream view */
    return rc ? rc : rc2;
}

static const char *const cause_text[] = {
    "none", "overrun (the host clocked valid while ready was low)",
    "underrun (the host clocked take while avail was low)",
    "bad control cycle (unknown request code, or valid/take on an edge that changed ctl)",
    "the board's engine failed (an ERROR frame says why)"
};

/* err is high: ask the bus why (BUS_STATUS).  A bus fault stops the
 * transport with the cause and the byte counts; an engine failure does not,
 * because the engine's ERROR frame (which says why) is still to be read by
 * the protocol layer (docs/board-gpio.md section 4.3).  Returns 0 to go on. */
static int err_line(ef_link *l, const char *during)
{
    if (!in_line(l, SIG_ERR) || l->engine_failed)
        return 0;
    uint8_t st[EF_GB_BUS_STATUS_LEN];
    if (control(l, EF_GB_REQ_BUS_STATUS, st, sizeof st, l->timeout_ms, "bus status") != 0) {
        snprintf(l->err, sizeof l->err,
                 "%s: the board raised its error line during %s "
                 "(its bus status could not be read)",
                 l->chip, during);
        return EF_HOST_EIO;
    }
    if (st[0] == EF_GB_ERR_ENGINE) {
        l->engine_failed = 1;
        return 0;
    }
    snprintf(l->err, sizeof l->err,
             "%s: the board raised its error line during %s: %s; it accepted %lu bytes "
             "(host sent %llu) and sent %lu (host took %llu) since its reset; reset the board to clear it",
             l->chip, during, st[0] < sizeof cause_text / sizeof cause_text[0] ? cause_text[st[0]] : "unknown cause",
             (unsigned long)ef_get32(st + 4), (unsigned long long)l->sent, (unsigned long)ef_get32(st + 8),
             (unsigned long long)l->taken);
    return EF_HOST_EIO;
}

/* ---- the ops ---- */

static int gpio_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    line_map m;
    *out = NULL;
    if (!ef_gpiol_available()) {
        snprintf(err, errlen,
                 "the gpio transport is absent: edgeflag-host was built without libgpiod "
                 "(install libgpiod-dev and rebuild)");
        return EF_HOST_EUNSUPPORTED;
    }
    int rc = parse_lines(&m, o->lines, err, errlen);
    if (rc)
        return rc;
    ef_link *l = calloc(1, sizeof *l);
    if (!l)
        return EF_HOST_ENOMEM;
    l->setup = m.setup, l->hold = m.hold;
    l->timeout_ms = o->timeout_ms > 0 ? o->timeout_ms : DEFAULT_TIMEOUT_MS;
    rc = resolve_chip(o->chip, l->chip, sizeof l->chip, err, errlen);
    if (!rc)
        rc = ef_gpiol_open(&l->c, l->chip, err, errlen);
    if (!rc)
        rc = resolve_lines(l, &m, err, errlen);
    if (!rc) {
        /* A line another program just released can stay busy for a moment
         * while the kernel (or an emulator) notices: retry briefly. */
        int64_t t0 = now_ms();
        do {
            rc = ef_gpiol_request(l->c, l->offset, SIG_OUTPUTS, l->offset + SIG_OUTPUTS, SIG_INPUTS, CONSUMER, err,
                                  errlen);
            if (rc == EF_HOST_EBUSY) {
                struct timespec ts = { 0, 5000000 };
                nanosleep(&ts, NULL);
            }
        } while (rc == EF_HOST_EBUSY && now_ms() - t0 < 200);
        if (rc == EF_HOST_EBUSY) {
            for (int s = 0; s < SIG_COUNT; s++) {
                char name[NAME_MAX_LEN], consumer[64];
                if (ef_gpiol_line(l->c, l->offset[s], name, sizeof name, consumer, sizeof consumer) == 0 &&
                    consumer[0]) {
                    snprintf(err, errlen, "%s: line %u (%s) is in use by '%s'", l->chip, l->offset[s], sig_name[s],
                             consumer);
                    break;
                }
            }
        }
    }
    if (!rc)
        rc = sample(l);
    if (rc) {
        if (l->err[0] && err[0] == '\0')
            snprintf(err, errlen, "%s", l->err);
        ef_gpiol_close(l->c);
        free(l);
        return rc;
    }
    *out = l;
    return 0;
}

static void gpio_close(ef_link *l)
{
    if (!l)
        return;
    ef_gpiol_set(l->c, 0); /* leave every output low */
    ef_gpiol_close(l->c);
    free(l);
}

static int timeout_of(int t) { return t > 0 ? t : DEFAULT_TIMEOUT_MS; }

static int gpio_identify(ef_link *l, uint8_t out[48])
{
    return control(l, EF_GB_REQ_IDENTIFY, out, EF_PROTO_IDENTIFY_LEN, l->timeout_ms, "identify");
}

static int gpio_status(ef_link *l, uint8_t out[40])
{
    return control(l, EF_GB_REQ_STATUS, out, EF_PROTO_STATUS_LEN, l->timeout_ms, "status");
}

static int gpio_reset(ef_link *l)
{
    int rc = control(l, EF_GB_REQ_RESET, NULL, 0, l->timeout_ms, "reset");
    l->ring_head = l->ring_len = 0; /* bytes from before the reset are void */
    l->engine_failed = 0;
    l->sent = l->taken = 0; /* counted like the board's counters */
    return rc;
}

static void ring_push(ef_link *l, uint8_t b)
{
    l->ring[(l->ring_head + l->ring_len) % RING] = b;
    l->ring_len++;
}

static int gpio_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    int t = timeout_of(timeout_ms);
    for (size_t i = 0; i < len; i++) {
        int64_t waited = 0;
        int rc;
        /* err_line() returns 0 for an engine failure, and then ready is
         * waited for again: the bytes keep flowing. */
        do {
            if ((rc = err_line(l, "a write")) != 0)
                return rc;
            rc = wait_line(l, SIG_READY, t, &waited);
        } while (rc == EF_HOST_EIO && in_line(l, SIG_ERR));
        if (rc == EF_HOST_ETIMEDOUT) {
            snprintf(l->err, sizeof l->err,
                     "%s: the board held ready low for %lld ms after %llu bytes "
                     "(stalled; done is %s)",
                     l->chip, (long long)waited, (unsigned long long)l->sent, in_line(l, SIG_DONE) ? "high" : "low");
            return rc;
        }
        if (rc)
            return rc;
        /* Take a board byte in the same cycle when one is offered and there
         * is room: acks flow while commands go out. */
        int take = in_line(l, SIG_AVAIL) && l->ring_len < RING;
        uint8_t q = in_q(l);
        rc = cycle(l, buf[i], OUT_BIT(SIG_VALID) | (take ? OUT_BIT(SIG_TAKE) : 0));
        if (rc)
            return rc;
        l->sent++;
        if (take)
            ring_push(l, q), l->taken++;
    }
    return 0;
}

static int gpio_flush(ef_link *l, int timeout_ms)
{
    (void)timeout_ms; /* every write is on the wire when it returns */
    return err_line(l, "a flush");
}

static int gpio_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    size_t n = 0;
    while (n < cap && l->ring_len) {
        buf[n++] = l->ring[l->ring_head];
        l->ring_head = (l->ring_head + 1) % RING, l->ring_len--;
    }
    int t = timeout_of(timeout_ms);
    int64_t t0 = now_ms();
    for (;;) {
        while (n < cap && in_line(l, SIG_AVAIL)) {
            uint8_t q = in_q(l);
            int rc = cycle(l, 0, OUT_BIT(SIG_TAKE));
            if (rc) {
                *got = n;
                return rc;
            }
            buf[n++] = q, l->taken++;
        }
        if (n > 0 || cap == 0)
            break;
        int rc0 = err_line(l, "a read");
        if (rc0) {
            *got = 0;
            return rc0;
        }
        int64_t waited = 0;
        int left = t - (int)(now_ms() - t0);
        int rc = left > 0 ? wait_line(l, SIG_AVAIL, left, &waited) : EF_HOST_ETIMEDOUT;
        if (rc == EF_HOST_ETIMEDOUT) {
            snprintf(l->err, sizeof l->err, "%s: nothing from the board for %d ms (done is %s)", l->chip, t,
                     in_line(l, SIG_DONE) ? "high" : "low");
            *got = 0;
            return rc;
        }
        if (rc && !in_line(l, SIG_ERR)) {
            *got = 0;
            return rc;
        }
    }
    *got = n;
    return 0;
}

static int gpio_probe(const ef_host_opts *o, ef_found *found, int max)
{
    char paths[64][64];
    if (!ef_gpiol_available())
        return EF_HOST_EUNSUPPORTED;
    int n = list_chips(paths, 64);
    for (int i = 0; i < n && i < 64 && i < max; i++) {
        ef_found *f = &found[i];
        ef_gpiol *c;
        char label[64] = "", e2[160];
        unsigned lines = 0;
        memset(f, 0, sizeof *f);
        snprintf(f->transport, sizeof f->transport, "gpio");
        snprintf(f->where, sizeof f->where, "%.63s", paths[i]);
        if (ef_gpiol_open(&c, paths[i], e2, sizeof e2) != 0) {
            snprintf(f->desc, sizeof f->desc, "%s", e2);
            continue;
        }
        ef_gpiol_info(c, label, sizeof label, &lines);
        int len = snprintf(f->desc, sizeof f->desc, "[%s] %u lines", label, lines);
        /* Named lines follow while they fit: they are what --lines accepts. */
        for (unsigned k = 0; k < lines && len > 0 && (size_t)len < sizeof f->desc - 8; k++) {
            char name[NAME_MAX_LEN], consumer[64];
            if (ef_gpiol_line(c, k, name, sizeof name, consumer, sizeof consumer) == 0 && name[0]) {
                int w = snprintf(f->desc + len, sizeof f->desc - (size_t)len, "%s%u=%s", k ? " " : ": ", k, name);
                if (w < 0 || (size_t)(len + w) >= sizeof f->desc - 4) {
                    snprintf(f->desc + len, sizeof f->desc - (size_t)len, " ...");
                    break;
                }
                len += w;
            }
        }
        ef_gpiol_close(c);
        /* Driving lines of an unknown chip could harm what is wired to it:
         * only the chip named with --chip (and --lines) is asked to identify. */
        if (o && o->chip && o->lines) {
            char want[64], e3[160];
            if (resolve_chip(o->chip, want, sizeof want, e3, sizeof e3) == 0 && strcmp(want, paths[i]) == 0) {
                ef_link *l;
                uint8_t id[EF_PROTO_IDENTIFY_LEN];
                if (gpio_open(&l, o, e3, sizeof e3) == 0) {
                    f->ok = gpio_identify(l, id) == 0 && memcmp(id, EF_PROTO_MAGIC, 4) == 0;
                    gpio_close(l);
                }
            }
        }
    }
    return n;
}

static const char *gpio_version(void) { return ef_gpiol_version(); }

static const char *gpio_detail(ef_link *l) { return l ? l->err : ""; }

const ef_transport_ops ef_transport_gpio = {
    .name = "gpio",
    .probe = gpio_probe,
    .open = gpio_open,
    .identify = gpio_identify,
    .status = gpio_status,
    .reset = gpio_reset,
    .write = gpio_write,
    .flush = gpio_flush,
    .read = gpio_read,
    .close = gpio_close,
    .version = gpio_version,
    .detail = gpio_detail,
};

const char *ef_gpio_link_detail(const ef_link *l) { return l->err; }

unsigned long long ef_gpio_link_cycles(const ef_link *l) { return (unsigned long long)l->cycles; }
