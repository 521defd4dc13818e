/*
 * transport_sim.c - the simulated board (docs/board.md section 5.3): the
 * board engine and the C model as its DUT, in the host's own process, behind
 * the same operations as a real link, so that every byte goes through the
 * protocol exactly as it would over USB.
 *
 * --sim-state DIR makes the board outlive the host process, as a real board
 * does: every byte the board receives (and every reset) is logged to
 * DIR/board.log and replayed into a fresh engine when the next process opens
 * the board.  The engine and the DUT are deterministic, so the replayed board
 * is in the very state the previous process left it in.
 *
 * --sim-faults LIST plays a faulty link or board (section 6): KIND=N[,...]
 * with KIND drop, corrupt, unplug, reset or stall counting the host's frames
 * (1 = the first), drop-reply or corrupt-reply counting the board's;
 * not-ours=1 answers identify without the magic (another device), protocol=N
 * answers it with protocol version N.
 *
 * --sim-dut rtl puts the Verilated reference RTL behind the engine instead
 * of the model (board/dut_rtl.c, when built in: board/rtl_dut.mk);
 * identify then says the RTL's own limits and sample counts.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "atomic_file.h"
#include "dut_rtl.h"
#include "ef_board.h"
#include "ef_frame.h"
#include "transport.h"

enum { F_DROP, F_CORRUPT, F_UNPLUG, F_RESET, F_STALL, F_DROP_REPLY, F_CORRUPT_REPLY, F_NOT_OURS, F_PROTOCOL, F_KINDS };
static const char *const FAULT_NAME[F_KINDS] = { "drop",       "corrupt",       "unplug",   "reset",   "stall",
                                                 "drop-reply", "corrupt-reply", "not-ours", "protocol" };
#define MAX_FAULTS 32
#define LOG_RESET 0xffffffffu

typedef struct sim_link {
    ef_board *b;
    FILE *log;
    int gone, stalled;
    int reply_faults; /* drop-reply or corrupt-reply asked for: replies go frame by frame */
    struct {
        int kind;
        uint64_t at;
    } fault[MAX_FAULTS];
    int nfaults;
    uint64_t wframes, rframes;
    uint8_t *in; /* board output not yet split into frames */
    size_t in_len, in_cap;
    uint8_t *out; /* frames for the host, after reply faults */
    size_t out_len, out_pos, out_cap;
} sim_link;

static int sim_dut = EF_SIM_DUT_MODEL; /* set by main before any open */

void ef_transport_sim_select_dut(int which) { sim_dut = which; }

static void nap_ms(int ms)
{
    if (ms <= 0)
        return;
    struct timespec t = { ms / 1000, (long)(ms % 1000) * 1000000L };
    nanosleep(&t, NULL);
}

static int fault_at(const sim_link *s, int kind, uint64_t n)
{
    for (int i = 0; i < s->nfaults; i++)
        if (s->fault[i].kind == kind && s->fault[i].at == n)
            return 1;
    return 0;
}

static int parse_faults(sim_link *s, const char *text, char *err, size_t errlen)
{
    const char *p = text;
    while (p && *p) {
        const char *comma = strchr(p, ',');
        const size_t len = comma ? (size_t)(comma - p) : strlen(p);
        const char *eq = memchr(p, '=', len);
        int kind = -1;
        for (int k = 0; eq && k < F_KINDS; k++)
            if (strlen(FAULT_NAME[k]) == (size_t)(eq - p) && memcmp(p, FAULT_NAME[k], (size_t)(eq - p)) == 0)
                kind = k;
        char *end;
        const unsigned long long n = eq ? strtoull(eq + 1, &end, 10) : 0;
        if (kind < 0 || !eq || end != p + len || n == 0 || eq[1] == '-' || s->nfaults == MAX_FAULTS) {
            snprintf(err, errlen,
                     "--sim-faults: '%.*s' is not KIND=N (KIND: drop, corrupt, unplug, reset, stall, "
                     "drop-reply, corrupt-reply, not-ours, protocol; N >= 1; at most %d)",
                     (int)len, p, MAX_FAULTS);
            return EF_HOST_EINVAL;
        }
        s->fault[s->nfaults].kind = kind;
        if (kind == F_DROP_REPLY || kind == F_CORRUPT_REPLY)
            s->reply_faults = 1;
        s->fault[s->nfaults].at = n;
        s->nfaults++;
        p = comma ? comma + 1 : NULL;
    }
    return 0;
}

static int log_bytes(sim_link *s, const uint8_t *buf, uint32_t len)
{
    if (!s->log)
        return 0;
    uint8_t n[4];
    ef_put32(n, len);
    if (fwrite(n, 1, 4, s->log) != 4 || (len != LOG_RESET && fwrite(buf, 1, len, s->log) != len) || fflush(s->log) != 0)
        return EF_HOST_EIO;
    return 0;
}

/* Splits the board's output into frames and applies the reply faults. */
static int pull(sim_link *s)
{
    uint8_t tmp[65536];
    size_t n;
    while ((n = ef_board_tx(s->b, tmp, sizeof tmp)) > 0) {
        if (s->in_len + n > s->in_cap) {
            size_t cap = s->in_cap ? s->in_cap : 1 << 20;
            while (cap < s->in_len + n)
                cap *= 2;
            uint8_t *p = realloc(s->in, cap);
            if (!p)
                return EF_HOST_ENOMEM;
            s->in = p, s->in_cap = cap;
        }
        memcpy(s->in + s->in_len, tmp, n);
        s->in_len += n;
    }
    size_t pos = 0;
    while (s->in_len - pos >= EF_PROTO_HEADER) {
        const size_t size = EF_PROTO_HEADER + ef_get32(s->in + pos + 12) + EF_PROTO_TRAILER;
        if (s->in_len - pos < size)
            break;
        s->rframes++;
        if (!fault_at(s, F_DROP_REPLY, s->rframes)) {
            if (s->out_pos == s->out_len)
                s->out_pos = s->out_len = 0;
            if (s->out_len + size > s->out_cap) {
                size_t cap = s->out_cap ? s->out_cap : 1 << 20;
                while (cap < s->out_len + size)
                    cap *= 2;
                uint8_t *p = realloc(s->out, cap);
                if (!p)
                    return EF_HOST_ENOMEM;
                s->out = p, s->out_cap = cap;
            }
            memcpy(s->out + s->out_len, s->in + pos, size);
            if (fault_at(s, F_CORRUPT_REPLY, s->rframes))
                s->out[s->out_len + size / 2] ^= 0x5a;
            s->out_len += size;
        }
        pos += size;
    }
    memmove(s->in, s->in + pos, s->in_len - pos);
    s->in_len -= pos;
    return 0;
}

static int replay(sim_link *s, const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return errno == ENOENT ? 0 : EF_HOST_EIO;
    uint8_t *buf = malloc(EF_PROTO_FRAME_MAX + 16);
    uint8_t n[4], sink[65536];
    int r = buf ? 0 : EF_HOST_ENOMEM;
    while (!r && fread(n, 1, 4, f) == 4) {
        const uint32_t len = ef_get32(n);
        if (len == LOG_RESET) {
            ef_board_reset(s->b);
        } else if (len > EF_PROTO_FRAME_MAX + 16 || fread(buf, 1, len, f) != len) {
            r = EF_HOST_EIO; /* a log cut short by a crash: the tail is lost */
        } else {
            ef_board_rx(s->b, buf, len);
        }
        while (ef_board_tx(s->b, sink, sizeof sink) > 0) {
        }
    }
    free(buf);
    fclose(f);
    return r;
}

static int sim_open(ef_link **out, const ef_host_opts *o, char *err, size_t errlen)
{
    sim_link *s = calloc(1, sizeof *s);
    if (!s)
        return EF_HOST_ENOMEM;
    int r = o->sim_faults ? parse_faults(s, o->sim_faults, err, errlen) : 0;
    if (r) {
        free(s);
        return r;
    }
    ef_proto_info info = { "EFSIM0001",
                           EF_PROTO_CAP_RESULTS | EF_PROTO_CAP_RESUME | EF_PROTO_CAP_INTERNAL,
                           1u << 3 | 1u << 4 | 1u << 5,
                           16384,
                           16384,
                           1u << 22,
                           16,
                           (1u << 7) - 1 };
    ef_board_dut dut;
    if (sim_dut == EF_SIM_DUT_RTL) {
        if (!ef_board_dut_rtl_built()) {
            snprintf(err, errlen, "--sim-dut rtl: the RTL DUT is %s", ef_board_dut_rtl_describe());
            free(s);
            return EF_HOST_EUNSUPPORTED;
        }
        /* a board with the RTL says the RTL's parameters */
        snprintf(info.serial, sizeof info.serial, "EFSIMRTL1");
        ef_board_dut_rtl_limits(&info.width_max, &info.height_max, &info.edges_max, &info.samples_mask);
        dut = ef_board_dut_rtl();
    } else {
        dut = ef_board_dut_model();
    }
    s->b = dut.self ? ef_board_new(&info, dut) : NULL;
    if (!s->b) {
        if (dut.self)
            dut.destroy(dut.self);
        free(s);
        return EF_HOST_ENOMEM;
    }
    if (o->sim_state) {
        char path[4200];
        snprintf(path, sizeof path, "%s/board.log", o->sim_state);
        if (ef_util_make_dirs(o->sim_state) != 0 || (r = replay(s, path)) != 0 || !(s->log = fopen(path, "ab"))) {
            snprintf(err, errlen, "--sim-state: cannot use %s: %s", path, r ? ef_host_strerror(r) : strerror(errno));
            ef_board_free(s->b);
            free(s);
            return r ? r : EF_HOST_EIO;
        }
    }
    *out = (ef_link *)s;
    return 0;
}

static int sim_identify(ef_link *l, uint8_t out[48])
{
    sim_link *s = (sim_link *)l;
    if (s->gone)
        return EF_HOST_ENODEV;
    ef_board_identify(s->b, out);
    for (int i = 0; i < s->nfaults; i++) {
        if (s->fault[i].kind == F_NOT_OURS)
            memcpy(out, "USB\0", 4);
        if (s->fault[i].kind == F_PROTOCOL)
            out[4] = (uint8_t)s->fault[i].at, out[5] = (uint8_t)(s->fault[i].at >> 8);
    }
    return 0;
}

static int sim_status(ef_link *l, uint8_t out[40])
{
    sim_link *s = (sim_link *)l;
    if (s->gone)
        return EF_HOST_ENODEV;
    ef_board_status(s->b, out);
    return 0;
}

static int sim_reset(ef_link *l)
{
    sim_link *s = (sim_link *)l;
    if (s->gone)
        return EF_HOST_ENODEV;
    ef_board_reset(s->b);
    s->in_len = s->out_len = s->out_pos = 0;
    return log_bytes(s, NULL, LOG_RESET);
}

static int sim_write(ef_link *l, const uint8_t *buf, size_t len, int timeout_ms)
{
    sim_link *s = (sim_link *)l;
    (void)timeout_ms;
    if (s->gone)
        return EF_HOST_ENODEV;
    s->wframes++;
    if (fault_at(s, F_UNPLUG, s->wframes)) {
        s->gone = 1;
        return EF_HOST_ENODEV;
    }
    if (fault_at(s, F_STALL, s->wframes))
        s->stalled = 1;
    if (s->stalled || fault_at(s, F_DROP, s->wframes))
        return 0;
    if (fault_at(s, F_RESET, s->wframes)) {
        ef_board_reset(s->b);
        if (log_bytes(s, NULL, LOG_RESET) != 0)
            return EF_HOST_EIO;
    }
    const uint8_t *p = buf;
    uint8_t *copy = NULL;
    if (fault_at(s, F_CORRUPT, s->wframes)) {
        if (!(copy = malloc(len)))
            return EF_HOST_ENOMEM;
        memcpy(copy, buf, len);
        copy[len / 2] ^= 0xa5;
        p = copy;
    }
    int r = log_bytes(s, p, (uint32_t)len);
    if (!r && ef_board_rx(s->b, p, len) != 0)
        r = EF_HOST_ENOMEM;
    free(copy);
    return r;
}

static int sim_flush(ef_link *l, int timeout_ms)
{
    (void)timeout_ms;
    return ((sim_link *)l)->gone ? EF_HOST_ENODEV : 0;
}

static int sim_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms)
{
    sim_link *s = (sim_link *)l;
    *got = 0;
    if (s->gone)
        return EF_HOST_ENODEV;
    if (!s->stalled && s->reply_faults) {
        const int r = pull(s);
        if (r)
            return r;
    }
    size_t n = s->out_len - s->out_pos;
    if (n == 0 && !s->stalled && !s->reply_faults) {
        /* no reply to drop or damage: the board's bytes straight into the host's buffer */
        n = ef_board_tx(s->b, buf, cap);
        *got = n;
        if (n)
            return 0;
    }
    if (n == 0) {
        nap_ms(timeout_ms); /* nothing will come: a board would be silent this long */
        return EF_HOST_ETIMEDOUT;
    }
    if (n > cap)
        n = cap;
    memcpy(buf, s->out + s->out_pos, n);
    s->out_pos += n;
    *got = n;
    return 0;
}

static void sim_close(ef_link *l)
{
    sim_link *s = (sim_link *)l;
    if (!s)
        return;
    if (s->log)
        fclose(s->log);
    ef_board_free(s->b);
    free(s->in);
    free(s->out);
    free(s);
}

static int sim_probe(const ef_host_opts *o, ef_found *found, int max)
{
    (void)o, (void)found, (void)max;
    return 0; /* never found: the simulated board is only used when named */
}

static const char *sim_version(void)
{
    static char text[320];
    snprintf(text, sizeof text, "built in (the board engine and the C model in-process); --sim-dut rtl: %s",
             ef_board_dut_rtl_describe());
    return text;
}

const ef_transport_ops ef_transport_sim = { "sim",     sim_probe, sim_open, sim_identify, sim_status,  sim_reset,
                                            sim_write, sim_flush, sim_read, sim_close,    sim_version, NULL };
