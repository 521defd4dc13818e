/*
 * vec_mutate.c - edits a vectors.bin for tests/check/run.sh and for the
 * bad-input catalogue's binary files: the mutations a broken RTL or a
 * damaged transfer makes, with the stream's counts and CRCs made consistent
 * again where the test wants `check` to see a mismatch (exit 1) rather than
 * a malformed stream (exit 2).  Framing is walked from docs/vectors.md
 * section 4 (1-byte interface, 1-byte length, 8-byte cycle, payload).
 *
 *   vec_mutate IN OUT flip  IFACE K BIT  flip payload bit BIT of IFACE's K-th record (K from 1); fix the CRC
 *   vec_mutate IN OUT drop  IFACE K      remove that record; fix its count and both CRCs
 *   vec_mutate IN OUT delay IFACE K D    add D to its cycle; fix the CRC
 *   vec_mutate IN OUT count IFACE N      set IFACE's header count to N; fix the header CRC
 *   vec_mutate IN OUT byte  OFFSET V     set one byte; fix nothing
 *   vec_mutate IN OUT cut   LENGTH       keep the first LENGTH bytes; fix nothing
 *
 * flip, delay and drop print the record they touched:
 *   record R offset O cycle C payload HEX     (R from 1; HEX most significant byte first)
 * Exit 0, or 2 on a usage or file error.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ef_trace.h"
#include "ef_vec_read.h"

#define HDR 104u

static uint64_t le(const uint8_t *p, unsigned n)
{
    uint64_t v = 0;
    for (unsigned i = n; i > 0; i--)
        v = (v << 8) | p[i - 1];
    return v;
}

static void put_le(uint8_t *p, unsigned n, uint64_t v)
{
    for (unsigned i = 0; i < n; i++)
        p[i] = (uint8_t)(v >> (8 * i) & 0xffu);
}

static void fix_crcs(uint8_t *b, size_t n)
{
    put_le(b + 96, 4, ef_vec_read_crc32(0, b + HDR, n - HDR));
    put_le(b + 100, 4, ef_vec_read_crc32(0, b, 100));
}

static int die(const char *msg)
{
    fprintf(stderr, "vec_mutate: %s\n", msg);
    return 2;
}

/* Offset of interface iface's k-th record (k from 1) and its global number. */
static size_t find(const uint8_t *b, size_t n, int iface, uint64_t k, uint64_t *rec)
{
    uint64_t seen = 0;
    *rec = 0;
    for (size_t off = HDR; off + 10 <= n; off += 10u + b[off + 1]) {
        ++*rec;
        if (b[off] == iface && ++seen == k)
            return off + 10u + b[off + 1] <= n ? off : 0;
    }
    return 0;
}

static void print_record(const uint8_t *b, size_t off, uint64_t rec)
{
    printf("record %" PRIu64 " offset %zu cycle %" PRIu64 " payload ", rec, off, le(b + off + 2, 8));
    for (unsigned i = b[off + 1]; i > 0; i--)
        printf("%02x", b[off + 10 + i - 1]);
    printf("\n");
}

int main(int argc, char **argv)
{
    if (argc < 5)
        return die("usage: vec_mutate IN OUT flip|drop|delay|count|byte|cut ARGS (see the source)");
    FILE *f = fopen(argv[1], "rb");
    if (!f)
        return die("cannot open IN");
    size_t cap = 1 << 20, n = 0, got;
    uint8_t *b = malloc(cap);
    while (b && (got = fread(b + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) {
            uint8_t *nb = realloc(b, cap *= 2);
            if (!nb) {
                free(b);
                b = NULL;
            }
            b = nb;
        }
    }
    fclose(f);
    if (!b)
        return die("out of memory");
    const char *op = argv[3];
    int iface = ef_iface_find(argv[4]);
    uint64_t a1 = argc > 5 ? strtoull(argv[5], NULL, 10) : 0, a2 = argc > 6 ? strtoull(argv[6], NULL, 10) : 0;
    size_t off = 0;
    uint64_t rec = 0;

    if (strcmp(op, "byte") == 0 || strcmp(op, "cut") == 0) {
        uint64_t at = strtoull(argv[4], NULL, 10);
        if (strcmp(op, "cut") == 0)
            n = at < n ? (size_t)at : n;
        else if (at < n)
            b[at] = (uint8_t)(a1 & 0xffu);
    } else if (strcmp(op, "count") == 0) {
        if (iface < 0 || n < HDR)
            return die("bad interface or stream");
        put_le(b + 40 + 8 * (unsigned)iface, 8, a1);
        put_le(b + 100, 4, ef_vec_read_crc32(0, b, 100));
    } else {
        if (iface < 0 || n < HDR || (off = find(b, n, iface, a1, &rec)) == 0)
            return die("no such interface or record");
        if (strcmp(op, "flip") == 0) {
            if (a2 >= 8u * b[off + 1])
                return die("bit past the payload");
            b[off + 10 + a2 / 8] ^= (uint8_t)(1u << (a2 % 8));
            print_record(b, off, rec);
        } else if (strcmp(op, "delay") == 0) {
            put_le(b + off + 2, 8, le(b + off + 2, 8) + a2);
            print_record(b, off, rec);
        } else if (strcmp(op, "drop") == 0) {
            size_t len = 10u + b[off + 1];
            print_record(b, off, rec);
            memmove(b + off, b + off + len, n - off - len);
            n -= len;
            put_le(b + 40 + 8 * (unsigned)iface, 8, le(b + 40 + 8 * (unsigned)iface, 8) - 1);
        } else {
            return die("unknown operation");
        }
        fix_crcs(b, n);
    }
    f = fopen(argv[2], "wb");
    if (!f || fwrite(b, 1, n, f) != n || fclose(f) != 0)
        return die("cannot write OUT");
    free(b);
    return 0;
}
