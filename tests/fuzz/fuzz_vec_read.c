/*
 * fuzz_vec_read.c - libFuzzer target for the readers `edgeflag check` uses
 * (rtl_vectors/ef_vec_read.h): hex dumps, binary streams, manifests.
 *
 * The first byte picks the reader and its expectations, the rest is the file:
 *   0  hex, interface from the header, else from a hint (the second byte)
 *   1  hex that must hold one interface (the second byte)
 *   2  binary stream as is
 *   3  binary stream with magic, version, header size and both CRCs made
 *      right by the harness, so the fuzzer spends its time past them
 *      (docs/fuzzing.md: a CRC is no reason to skip an input)
 *   4  manifest.json
 * Properties (each aborts, so libFuzzer keeps the input):
 *  - the same bytes read twice give the same status and the same dump or
 *    the same error; read from a stream in the fuzz build's tiny chunks
 *    (every token and record straddles a chunk boundary) they give it again;
 *  - a failure leaves the dump empty and names its file and place
 *    (line:col >= 1, a record >= 1, an offset within the input);
 *  - a success holds only what the format allows: cycles below 2^48, no
 *    payload bit above the interface's width, lines and records in order;
 *  - a hex dump written back with the vector writer (ef_vec_hex_word) reads
 *    back to the same transactions; the two CRC-32 implementations (reader's
 *    and writer's) agree on every input;
 *  - a manifest's file names are plain names (no '/', no "..").
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ef_vec.h"
#include "ef_vec_read.h"
#include "fuzz_common.h"

static const char *const NAME = "fuzz.vec";

static void check_error(ef_status st, const ef_vec_read_error *e, const ef_vec_dump *d, size_t len)
{
    FUZZ_CHECK(st != EF_OK && e->status == st, "error status %d, returned %d", (int)e->status, (int)st);
    FUZZ_CHECK(e->msg[0] != '\0', "error without a message");
    FUZZ_CHECK(strcmp(e->file, NAME) == 0, "error names '%s'", e->file);
    if (e->at == EF_VEC_AT_LINE)
        FUZZ_CHECK(e->line >= 1 && e->col >= 1, "error at %" PRIu64 ":%" PRIu64, e->line, e->col);
    if (e->at == EF_VEC_AT_RECORD)
        FUZZ_CHECK(e->record >= 1, "error at record 0");
    if (e->at == EF_VEC_AT_HEADER || e->at == EF_VEC_AT_RECORD || e->at == EF_VEC_AT_END)
        FUZZ_CHECK(e->offset <= len, "error at offset %" PRIu64 " of %zu bytes", e->offset, len);
    if (e->at == EF_VEC_AT_FILE)
        FUZZ_CHECK(st == EF_ERR_NOMEM || st == EF_ERR_IO, "a whole-file error for a bad input: %s", e->msg);
    FUZZ_CHECK(d->mask == 0, "a failed read left interfaces");
    for (int i = 0; i < EF_IF_COUNT; i++)
        FUZZ_CHECK(d->seq[i].n == 0 && !d->seq[i].cycle && !d->seq[i].pay && !d->seq[i].loc && !d->seq[i].off,
                   "a failed read left transactions");
    char buf[1024];
    ef_vec_read_error_format(e, buf, sizeof buf);
    FUZZ_CHECK(strncmp(buf, NAME, strlen(NAME)) == 0, "formatted error does not start with the file name");
}

static void check_dump(const ef_vec_dump *d, size_t len)
{
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_vec_seq *q = &d->seq[i];
        if (!(d->mask >> i & 1u)) {
            FUZZ_CHECK(q->n == 0, "transactions of an interface not in the mask");
            continue;
        }
        const ef_iface_desc *desc = ef_iface_get(i);
        FUZZ_CHECK(q->nw == (desc->width + 63u) / 64u, "word count %u for %s", q->nw, desc->name);
        for (size_t k = 0; k < q->n; k++) {
            FUZZ_CHECK(q->cycle[k] >> EF_CYCLE_BITS == 0, "cycle past 48 bits");
            const uint64_t top = q->pay[k * q->nw + q->nw - 1];
            const unsigned used = desc->width - 64u * (q->nw - 1);
            FUZZ_CHECK(used == 64 || top >> used == 0, "payload bits above the width of %s", desc->name);
            if (k)
                FUZZ_CHECK(q->loc[k] > q->loc[k - 1] || (d->format == EF_VEC_FMT_HEX && q->loc[k] == q->loc[k - 1]),
                           "places out of order");
            if (d->format == EF_VEC_FMT_BIN)
                FUZZ_CHECK(q->off && q->off[k] + 10 < len, "record offset past the input");
            else
                FUZZ_CHECK(!q->off && q->loc[k] >= 1 && q->loc[k] <= len, "line %" PRIu64 " of %zu bytes", q->loc[k],
                           len);
        }
    }
}

static int same_dump(const ef_vec_dump *a, const ef_vec_dump *b)
{
    if (a->format != b->format || a->mask != b->mask || a->width != b->width || a->height != b->height ||
        a->samples != b->samples || a->rule != b->rule || a->seed != b->seed || a->has_header != b->has_header)
        return 0;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_vec_seq *p = &a->seq[i], *q = &b->seq[i];
        if (p->n != q->n || p->nw != q->nw)
            return 0;
        if (p->n &&
            (memcmp(p->cycle, q->cycle, p->n * 8) || memcmp(p->pay, q->pay, p->n * p->nw * 8) ||
             memcmp(p->loc, q->loc, p->n * 8) || (!p->off != !q->off) || (p->off && memcmp(p->off, q->off, p->n * 8))))
            return 0;
    }
    return 1;
}

typedef struct result {
    ef_status st;
    ef_vec_dump d;
    ef_vec_read_error e;
} result;

static void read_mem(int mode, const uint8_t *p, size_t n, int arg, result *r)
{
    memset(&r->e, 0, sizeof r->e);
    if (mode == 0)
        r->st = ef_vec_read_hex(NAME, p, n, -1, arg % (EF_IF_COUNT + 1) - 1, &r->d, &r->e);
    else if (mode == 1)
        r->st = ef_vec_read_hex(NAME, p, n, arg % EF_IF_COUNT, -1, &r->d, &r->e);
    else
        r->st = ef_vec_read_bin(NAME, p, n, &r->d, &r->e);
}

static void read_stream(int mode, uint8_t *p, size_t n, int arg, result *r)
{
    memset(&r->e, 0, sizeof r->e);
    FILE *f = n ? fmemopen((void *)p, n, "rb") : NULL;
    if (!f) {
        read_mem(mode, p, n, arg, r); /* glibc refuses a 0-byte fmemopen */
        return;
    }
    if (mode == 0)
        r->st = ef_vec_read_fp(f, NAME, 0, -1, arg % (EF_IF_COUNT + 1) - 1, &r->d, &r->e);
    else if (mode == 1)
        r->st = ef_vec_read_fp(f, NAME, 0, arg % EF_IF_COUNT, -1, &r->d, &r->e);
    else
        r->st = ef_vec_read_fp(f, NAME, 1, -1, -1, &r->d, &r->e);
    fclose(f);
}

static void compare_results(const result *a, const result *b, const char *what)
{
    FUZZ_CHECK(a->st == b->st, "%s: status %d then %d", what, (int)a->st, (int)b->st);
    if (a->st != EF_OK) {
        char x[1024], y[1024];
        ef_vec_read_error_format(&a->e, x, sizeof x);
        ef_vec_read_error_format(&b->e, y, sizeof y);
        FUZZ_CHECK(strcmp(x, y) == 0, "%s: '%s' then '%s'", what, x, y);
    } else {
        FUZZ_CHECK(same_dump(&a->d, &b->d), "%s: two different dumps", what);
    }
}

/* A successful hex dump, written back word by word with the writer. */
static void hex_round_trip(const ef_vec_dump *d)
{
    int iface = -1;
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (d->mask >> i & 1u)
            iface = i;
    FUZZ_CHECK(iface >= 0 && d->mask == 1u << iface, "a hex dump of mask 0x%x", d->mask);
    const ef_vec_seq *q = &d->seq[iface];
    fuzz_buf b = { 0 };
    char word[EF_VEC_HEX_MAX_DIGITS + 2];
    fuzz_buf_put(&b, "// round trip\n", 14);
    for (size_t k = 0; k < q->n; k++) {
        ef_txn t;
        ef_vec_dump_txn(d, iface, k, &t);
        unsigned n = ef_vec_hex_word(&t, word);
        word[n] = '\n';
        fuzz_buf_put(&b, word, n + 1);
    }
    ef_vec_dump back;
    ef_vec_read_error e;
    ef_status st = ef_vec_read_hex(NAME, (const uint8_t *)b.p, b.n, iface, -1, &back, &e);
    FUZZ_CHECK(st == EF_OK, "the writer's words do not read back: %s", e.msg);
    FUZZ_CHECK(back.seq[iface].n == q->n, "round trip: %zu words, %zu read", q->n, back.seq[iface].n);
    if (q->n)
        FUZZ_CHECK(!memcmp(back.seq[iface].cycle, q->cycle, q->n * 8) &&
                       !memcmp(back.seq[iface].pay, q->pay, q->n * q->nw * 8),
                   "round trip changed a transaction");
    ef_vec_dump_destroy(&back);
    free(b.p);
}

static void put_le(uint8_t *p, unsigned n, uint64_t v)
{
    for (unsigned i = 0; i < n; i++)
        p[i] = (uint8_t)(v >> (8 * i) & 0xffu);
}

static void fuzz_manifest(const uint8_t *p, size_t n)
{
    ef_vec_manifest m, m2;
    ef_vec_read_error e, e2;
    ef_status st = ef_vec_read_manifest(NAME, p, n, &m, &e);
    ef_status st2 = ef_vec_read_manifest(NAME, p, n, &m2, &e2);
    FUZZ_CHECK(st == st2, "manifest: status %d then %d", (int)st, (int)st2);
    if (st != EF_OK) {
        FUZZ_CHECK(m.nfiles == 0 && !m.files, "a failed manifest left files");
        FUZZ_CHECK(e.msg[0] && (e.at != EF_VEC_AT_LINE || (e.line >= 1 && e.col >= 1)), "manifest error unplaced");
        FUZZ_CHECK(e.line == e2.line && e.col == e2.col && !strcmp(e.msg, e2.msg), "manifest error differs");
        return;
    }
    FUZZ_CHECK(m.nfiles == m2.nfiles && m.nfiles <= n / 2, "%zu files in %zu bytes", m.nfiles, n);
    for (size_t k = 0; k < m.nfiles; k++) {
        const char *nm = m.files[k].name;
        FUZZ_CHECK(nm && nm[0] && !strchr(nm, '/') && !strstr(nm, ".."), "file name '%s' accepted", nm ? nm : "");
        FUZZ_CHECK(!strcmp(nm, m2.files[k].name), "manifest differs");
    }
    FUZZ_CHECK(m.width >= 0 && m.width <= EF_MAX_CANVAS && m.height >= 0 && m.height <= EF_MAX_CANVAS, "size");
    ef_vec_manifest_destroy(&m);
    ef_vec_manifest_destroy(&m2);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2 || size > (1u << 20))
        return 0;
    const int mode = data[0] % 5, arg = data[1];
    size_t n = size - 2;
    uint8_t *p = malloc(n ? n : 1);
    FUZZ_CHECK(p != NULL, "out of memory in the harness");
    memcpy(p, data + 2, n);
    FUZZ_CHECK(ef_vec_read_crc32(0, p, n) == ef_vec_crc32(0, p, n), "the two CRC-32s disagree");
    if (mode == 4) {
        fuzz_manifest(p, n);
        free(p);
        return 0;
    }
    if (mode == 3 && n >= EF_VEC_BIN_HEADER_SIZE) {
        memcpy(p, ef_vec_bin_magic, 8);
        put_le(p + 8, 2, EF_VEC_BIN_VERSION);
        put_le(p + 10, 2, EF_VEC_BIN_HEADER_SIZE);
        put_le(p + 96, 4, ef_vec_read_crc32(0, p + EF_VEC_BIN_HEADER_SIZE, n - EF_VEC_BIN_HEADER_SIZE));
        put_le(p + 100, 4, ef_vec_read_crc32(0, p, 100));
    }
    result r1, r2, r3;
    read_mem(mode, p, n, arg, &r1);
    read_mem(mode, p, n, arg, &r2);
    read_stream(mode, p, n, arg, &r3);
    compare_results(&r1, &r2, "twice");
    compare_results(&r1, &r3, "memory and stream");
    if (r1.st != EF_OK) {
        check_error(r1.st, &r1.e, &r1.d, n);
    } else {
        check_dump(&r1.d, n);
        if (mode <= 1)
            hex_round_trip(&r1.d);
    }
    ef_vec_dump_destroy(&r1.d);
    ef_vec_dump_destroy(&r2.d);
    ef_vec_dump_destroy(&r3.d);
    free(p);
    return 0;
}
