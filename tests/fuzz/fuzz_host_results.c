/*
 * fuzz_host_results.c - libFuzzer target for edgeflag-host's receiving side
 * (host/host_link.c): frame parsing, ACK/NAK handling, RESULT records, DONE
 * and ERROR, the resume bookkeeping and the writing of vectors.actual.bin.
 * A transport made by the harness plays the board: identify and status say
 * "edgeflag board", everything the host sends is accepted, and what the host
 * reads is the fuzzer's input.
 *
 * The first byte picks how the rest arrives:
 *   even  raw bytes in chunks whose sizes the following bytes choose;
 *   odd   frames made by the harness from [type][flags][seq][len][payload]
 *         groups and sealed with the right CRC (past the CRC, into the
 *         protocol and the record checks);
 * and with its bit 1 the run is a digest run of 4-transaction windows
 * (docs/board.md 4.5: digest records, the windows fetched, the rebuilt
 * results).
 * The host runs against a small real vectors.bin (a triangle, every
 * interface), made once with the library at start-up, with a 1 ms timeout.
 * Properties (each aborts, so libFuzzer keeps the input):
 *  - the exit code is one the protocol can produce (0, 4, 5, 6);
 *  - exit 0 leaves a vectors.actual.bin that the vector reader accepts,
 *    with the records' counts; any other code leaves none.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ef_frame.h"
#include "ef_trace.h"
#include "ef_vec.h"
#include "ef_vec_read.h"
#include "fuzz_common.h"
#include "host_link.h"

static char dir[256], vec_path[300], res_dir[300], actual[400];
static const uint8_t *in;
static size_t in_len, in_pos;
static int sealed;
static uint8_t *sealbuf;

static void cleanup(void)
{
    static const char *const names[] = { "vectors.actual.bin", ".resume", ".resume.tmp", ".results.part", ".digests" };
    char p[512];
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        snprintf(p, sizeof p, "%s/%s", res_dir, names[i]);
        unlink(p);
    }
    rmdir(res_dir);
    unlink(vec_path);
    rmdir(dir);
}

static void make_vectors(void)
{
    snprintf(dir, sizeof dir, "%s/edgeflag-fuzz-host.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    FUZZ_CHECK(mkdtemp(dir), "mkdtemp");
    atexit(cleanup);
    snprintf(vec_path, sizeof vec_path, "%s/vectors.bin", dir);
    snprintf(res_dir, sizeof res_dir, "%s/results", dir);
    snprintf(actual, sizeof actual, "%s/vectors.actual.bin", res_dir);
    ef_ctx *ctx;
    ef_image img;
    ef_vec_collect c;
    FUZZ_CHECK(ef_ctx_create(&ctx, 8, 6, 8) == EF_OK && ef_image_create(&img, 8, 6) == EF_OK, "model");
    ef_vec_collect_create(&c, EF_IF_ALL);
    const ef_point pts[3] = { { 256, 128 }, { 1900, 700 }, { 600, 1500 } };
    const uint32_t start[2] = { 0, 3 };
    const ef_polygon poly = { pts, start, 1 };
    ef_vec_info info = { "fuzz", 8, 6, 8, -1, 0, 0, EF_IF_ALL, 0 };
    FUZZ_CHECK(ef_trace_enable(ctx, EF_IF_ALL, ef_vec_collect_sink, &c) == EF_OK &&
                   ef_trace_frame_begin(ctx) == EF_OK &&
                   ef_fill(ctx, &img, &poly, EF_RULE_NONZERO, (ef_rgba8){ 200, 100, 50, 255 }) == EF_OK &&
                   ef_trace_frame_end(ctx, &info.cycles) == EF_OK,
               "trace");
    FILE *f = fopen(vec_path, "wb");
    FUZZ_CHECK(f, "cannot write %s", vec_path);
    ef_vec_out o;
    ef_vec_out_init(&o, f, 0);
    ef_vec_bin_write(&o, &info, &c);
    FUZZ_CHECK(ef_vec_out_finish(&o, NULL) == 0 && fclose(f) == 0, "write vectors");
    ef_vec_collect_destroy(&c);
    ef_image_destroy(&img);
    ef_ctx_destroy(ctx);
}

static int f_identify(ef_link *l, uint8_t out[48])
{
    (void)l;
    memset(out, 0, 48);
    memcpy(out, "EFB1", 4);
    out[4] = 1, out[6] = 4;
    ef_put32(out + 8, 8); /* digest runs */
    ef_put32(out + 12, 0x7f);
    ef_put32(out + 16, 1u << 3 | 1u << 4 | 1u << 5);
    ef_put32(out + 20, 64), ef_put32(out + 24, 64), ef_put32(out + 28, 4096);
    return 0;
}
static int f_status(ef_link *l, uint8_t out[40])
{
    (void)l;
    memset(out, 0, 40);
    memcpy(out, "EFB1", 4);
    return 0;
}
static int f_reset(ef_link *l)
{
    (void)l;
    return 0;
}
static int f_write(ef_link *l, const uint8_t *b, size_t n, int t)
{
    (void)l, (void)b, (void)n, (void)t;
    return 0;
}
static int f_flush(ef_link *l, int t)
{
    (void)l, (void)t;
    return 0;
}
static void f_close(ef_link *l) { (void)l; }
static int f_probe(const ef_host_opts *o, ef_found *f, int m)
{
    (void)o, (void)f, (void)m;
    return 0;
}
static const char *f_version(void) { return "fuzz"; }

static int f_read(ef_link *l, uint8_t *buf, size_t cap, size_t *got, int t)
{
    (void)l, (void)t;
    *got = 0;
    if (in_pos >= in_len)
        return EF_HOST_ETIMEDOUT;
    if (!sealed) {
        size_t k = 1 + in[in_pos++] % 97u;
        if (k > in_len - in_pos)
            k = in_len - in_pos;
        if (k > cap)
            k = cap;
        memcpy(buf, in + in_pos, k);
        in_pos += k;
        *got = k;
        return 0;
    }
    if (in_len - in_pos < 4) {
        in_pos = in_len;
        return EF_HOST_ETIMEDOUT;
    }
    const uint8_t type = in[in_pos], flags = in[in_pos + 1], seq = in[in_pos + 2];
    size_t len = in[in_pos + 3];
    in_pos += 4;
    if (len > in_len - in_pos)
        len = in_len - in_pos;
    const size_t n = ef_frame_put(sealbuf, type, flags, seq, in + in_pos, (uint32_t)len);
    in_pos += len;
    if (n > cap)
        return EF_HOST_ETIMEDOUT;
    memcpy(buf, sealbuf, n);
    *got = n;
    return 0;
}

static const ef_transport_ops FUZZ_OPS = { "fuzz",  f_probe, NULL,   f_identify, f_status,  f_reset,
                                           f_write, f_flush, f_read, f_close,    f_version, NULL };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!dir[0]) {
        make_vectors();
        sealbuf = malloc(EF_PROTO_FRAME_MAX);
        FUZZ_CHECK(sealbuf, "out of memory");
    }
    if (size == 0)
        return 0;
    sealed = data[0] & 1;
    in = data + 1, in_len = size - 1, in_pos = 0;
    unlink(actual);
    const uint32_t digest = data[0] & 2 ? 4 : 0;
    ef_host_stream_opts so = { vec_path, res_dir, EF_IF_ALL & ~1u, 0, 3, 1, 0, 1, digest, 0, 2 };
    ef_host_stream_report rep;
    const int code = ef_host_stream(&FUZZ_OPS, NULL, &so, &rep);
    FUZZ_CHECK(code == 0 || code == 4 || code == 5 || code == 6, "exit code %d", code);
    if (code == 0) {
        ef_vec_dump d;
        ef_vec_read_error err;
        memset(&d, 0, sizeof d);
        FUZZ_CHECK(ef_vec_read_path(actual, NULL, -1, -1, &d, &err) == EF_OK, "results unreadable: %s", err.msg);
        uint64_t n = 0;
        for (int i = 0; i < EF_IF_COUNT; i++)
            n += d.seq[i].n;
        /* (a digest run's file is rebuilt: the reader checked its counts against its records) */
        FUZZ_CHECK(digest || n == rep.records, "results hold %llu records, %llu received", (unsigned long long)n,
                   (unsigned long long)rep.records);
        ef_vec_dump_destroy(&d);
    } else {
        FUZZ_CHECK(access(actual, F_OK) != 0, "exit %d left a vectors.actual.bin", code);
    }
    return 0;
}
