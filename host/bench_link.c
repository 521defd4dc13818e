/*
 * bench_link.c - link tests of `edgeflag-host bench` (docs/board.md 8).
 * They use the board's link-test modes (START mode SINK, SOURCE, LOOPBACK),
 * so the DUT's cost is not in the figures, and the same framing and CRC code
 * as a real run.  A lost or damaged frame fails the bench: it measures a
 * clean link, retransmission is tested elsewhere.
 */
#include "bench_link.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ef_board.h"
#include "ef_frame.h"

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

typedef struct run {
    const ef_transport_ops *ops;
    ef_link *l;
    int timeout;
    uint8_t *f, *r;
    size_t rlen;
    uint32_t window;
} run;

static int send_start(run *b, uint32_t mode, uint32_t kib)
{
    uint8_t p[EF_PROTO_START_LEN] = { 0 };
    ef_put32(p + 8, mode);
    ef_put32(p + 12, kib);
    return b->ops->write(b->l, b->f, ef_frame_put(b->f, EF_FT_START, 0, 0, p, sizeof p), b->timeout);
}

/* Sends frames 1..n (n-1 DATA of `chunk` bytes, then END) and takes
 * everything the board answers until END is acknowledged and, when
 * want_done, DONE arrived.  *got counts RESULT payload bytes. */
static int pump(run *b, uint32_t ndata, uint32_t chunk, int want_done, uint64_t *got)
{
    const uint32_t last = ndata + 1;
    uint32_t base = 1, next = 1, res_next = 0, unacked = 0;
    int done = !want_done;
    double idle = now_s();
    for (uint32_t i = 0; i < chunk; i++)
        b->f[EF_PROTO_HEADER + i] = (uint8_t)(i * 7u);
    while (base <= last || !done) {
        while (next <= last && next - base < b->window) {
            const uint8_t type = next == last ? EF_FT_END : EF_FT_DATA;
            int r = b->ops->write(b->l, b->f, ef_frame_seal(b->f, type, 0, next, type == EF_FT_END ? 0 : chunk),
                                  b->timeout);
            if (r < 0)
                return r;
            next++;
        }
        size_t n = 0;
        int r = b->ops->read(b->l, b->r + b->rlen, 4 * EF_PROTO_FRAME_MAX - b->rlen, &n,
                             next <= last && next - base < b->window ? 0 : 10);
        if (r < 0 && r != EF_HOST_ETIMEDOUT)
            return r;
        b->rlen += n;
        size_t pos = 0;
        while (pos < b->rlen) {
            ef_frame f;
            size_t used;
            const int k = ef_frame_parse(b->r + pos, b->rlen - pos, &f, &used);
            if (k == EF_FRAME_MORE)
                break;
            if (k == EF_FRAME_BAD)
                return EF_HOST_EIO;
            if (f.type == EF_FT_ACK && f.len >= 8) {
                if (ef_get32(f.payload) > base)
                    base = ef_get32(f.payload);
            } else if ((f.type == EF_FT_RESULT || f.type == EF_FT_DONE) && f.seq == res_next) {
                res_next++;
                if (f.type == EF_FT_DONE)
                    done = 1;
                else
                    *got += f.len;
                unacked++;
            } else {
                return EF_HOST_EIO; /* NAK, ERROR or out of order: not a clean link */
            }
            pos += used;
            idle = now_s();
        }
        memmove(b->r, b->r + pos, b->rlen - pos);
        b->rlen -= pos;
        if (unacked >= 4 || (unacked && (done || base > last))) {
            uint8_t p[4], a[EF_PROTO_HEADER + 4 + EF_PROTO_TRAILER];
            ef_put32(p, res_next);
            if ((r = b->ops->write(b->l, a, ef_frame_put(a, EF_FT_ACKR, 0, 0, p, 4), b->timeout)) < 0)
                return r;
            unacked = 0;
        }
        if ((now_s() - idle) * 1000 > b->timeout)
            return EF_HOST_ETIMEDOUT;
    }
    return b->ops->flush(b->l, b->timeout);
}

static int median_cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int ef_bench_link(const ef_transport_ops *ops, ef_link *l, uint64_t bytes, int timeout_ms, ef_bench_result out[4])
{
    run b = { ops, l, timeout_ms > 0 ? timeout_ms : 2000, malloc(EF_PROTO_FRAME_MAX), malloc(4 * EF_PROTO_FRAME_MAX),
              0,   16 };
    uint8_t id[EF_PROTO_IDENTIFY_LEN], st[EF_PROTO_STATUS_LEN];
    int r = 0;
    memset(out, 0, 4 * sizeof *out);
    out[0].name = "sink", out[1].name = "source", out[2].name = "loopback", out[3].name = "latency";
    if (!b.f || !b.r) {
        r = EF_HOST_ENOMEM;
        goto end;
    }
    if ((r = ops->identify(l, id)) < 0)
        goto end;
    b.window = (uint32_t)(id[6] | id[7] << 8);
    if (!b.window)
        b.window = 1;
    const uint32_t chunk = EF_PROTO_PAYLOAD_MAX;
    const uint32_t ndata = (uint32_t)((bytes + chunk - 1) / chunk);
    const int is_null = strcmp(ops->name, "null") == 0;

    for (int m = 0; m < 3; m++) {
        ef_bench_result *o = &out[m];
        if (is_null && m > 0) {
            snprintf(o->note, sizeof o->note, "the null link has no board to send results");
            continue;
        }
        uint64_t got = 0;
        if ((r = ops->reset(l)) < 0)
            goto end;
        b.rlen = 0;
        const double t0 = now_s();
        if (m == 0) {
            if ((r = send_start(&b, EF_MODE_SINK, 0)) < 0 || (r = pump(&b, ndata, chunk, !is_null, &got)) < 0)
                goto end;
            o->bytes = (uint64_t)ndata * chunk;
        } else if (m == 1) {
            const uint32_t kib = (uint32_t)(bytes / 1024);
            if ((r = send_start(&b, EF_MODE_SOURCE, kib)) < 0 || (r = pump(&b, 0, 0, 1, &got)) < 0)
                goto end;
            o->bytes = got;
        } else {
            if ((r = send_start(&b, EF_MODE_LOOPBACK, 0)) < 0 || (r = pump(&b, ndata, chunk, 1, &got)) < 0)
                goto end;
            o->bytes = got;
        }
        o->seconds = now_s() - t0;
        o->mb_s = o->seconds > 0 ? (double)o->bytes / o->seconds / 1e6 : 0;
        o->ran = 1;
    }
    { /* latency: the status request's round trip */
        enum { N = 200 };
        double t[N];
        for (int i = 0; i < N; i++) {
            const double t0 = now_s();
            if ((r = ops->status(l, st)) < 0)
                goto end;
            t[i] = (now_s() - t0) * 1e6;
        }
        qsort(t, N, sizeof *t, median_cmp);
        out[3].usec_min = t[0];
        out[3].usec_median = t[N / 2];
        out[3].ran = 1;
        snprintf(out[3].note, sizeof out[3].note, "status request round trip, %d times", N);
    }
    r = 0;
end:
    free(b.f);
    free(b.r);
    return r;
}
