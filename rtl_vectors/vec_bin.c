/*
 * vec_bin.c - vectors.bin (docs/vectors.md section 4): a 104-byte
 * little-endian header with the parameters, per-interface counts and two
 * CRC-32s, then every transaction of the recorded interfaces as a framed
 * record in global cycle order.  The header's record CRC must be known
 * before the records are written and the output is a stream (it is hashed
 * as it goes), so the records are built in memory first (their size is
 * known from the counts), their CRC taken, and then header and records
 * written in one piece.
 */
#include "ef_vec.h"

#include <stdlib.h>
#include <string.h>

static void put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void put32(uint8_t *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

/* Written out byte by byte: compilers merge the eight stores into one where
 * the host is little-endian (a loop would stay a loop at -O2). */
static void put64(uint8_t *p, uint64_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
    p[4] = (uint8_t)(v >> 32);
    p[5] = (uint8_t)(v >> 40);
    p[6] = (uint8_t)(v >> 48);
    p[7] = (uint8_t)(v >> 56);
}

size_t ef_vec_bin_record(const ef_txn *t, uint8_t r[EF_VEC_BIN_RECORD_MAX])
{
    const unsigned len = (ef_iface_get(t->iface)->width + 7u) / 8u;
    r[0] = t->iface;
    r[1] = (uint8_t)len;
    put64(r + 2, t->cycle);
    for (unsigned i = 0; i < len; i++)
        r[10 + i] = (uint8_t)(t->w[i / 8] >> (8 * (i % 8)));
    return 10u + len;
}

void ef_vec_bin_header(uint8_t h[EF_VEC_BIN_HEADER], const ef_vec_info *info, const ef_vec_collect *c,
                       uint32_t records_crc)
{
    uint64_t counts[EF_IF_COUNT];
    for (int i = 0; i < EF_IF_COUNT; i++)
        counts[i] = ef_vec_collect_count(c, i);
    ef_vec_bin_header_counts(h, info, counts, records_crc);
}

void ef_vec_bin_header_counts(uint8_t h[EF_VEC_BIN_HEADER], const ef_vec_info *info,
                              const uint64_t counts[EF_IF_COUNT], uint32_t records_crc)
{
    static const uint8_t magic[8] = { 0x89, 'E', 'F', 'V', '\r', '\n', 0x1a, '\n' };
    memset(h, 0, EF_VEC_BIN_HEADER);
    memcpy(h, magic, sizeof magic);
    put16(h + 8, EF_VEC_FORMAT);
    put16(h + 10, EF_VEC_BIN_HEADER);
    h[12] = (uint8_t)info->samples;
    h[13] = (uint8_t)(info->rule == EF_RULE_NONZERO ? 0 : info->rule == EF_RULE_EVENODD ? 1 : 2);
    put32(h + 16, (uint32_t)info->width);
    put32(h + 20, (uint32_t)info->height);
    put64(h + 24, info->seed);
    put32(h + 32, info->mask);
    for (int i = 0; i < EF_IF_COUNT; i++)
        put64(h + 40 + 8 * i, (info->mask >> i & 1u) ? counts[i] : 0);
    put32(h + 96, records_crc);
    put32(h + 100, ef_vec_crc32(0, h, 100));
}

/* The records of every interface in mask, merged into cycle order (ties:
 * the lower interface first), into r; returns the bytes written.  The
 * heads of the seven lists are compared directly instead of going through
 * ef_vec_merge one ef_txn at a time. */
static size_t records(const ef_vec_collect *c, uint32_t mask, uint8_t *r)
{
    const uint64_t *head[EF_IF_COUNT];
    size_t left[EF_IF_COUNT];
    unsigned stride[EF_IF_COUNT], len[EF_IF_COUNT];
    uint8_t *const r0 = r;

    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_vec_list *l = &c->list[i];
        head[i] = l->rec;
        left[i] = (mask >> i & 1u) ? l->count : 0;
        stride[i] = 1u + l->nw;
        len[i] = (ef_iface_get(i)->width + 7u) / 8u;
    }
    for (;;) {
        int best = -1;
        uint64_t cyc = 0;
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (left[i] && (best < 0 || head[i][0] < cyc)) {
                best = i;
                cyc = head[i][0];
            }
        if (best < 0)
            return (size_t)(r - r0);
        const uint64_t *w = head[best] + 1;
        uint8_t pay[8 * EF_TXN_WORDS];
        r[0] = (uint8_t)best;
        r[1] = (uint8_t)len[best];
        put64(r + 2, cyc);
        /* Whole words little-endian (a plain store on such hosts), then
         * the record's ceil(P/8) bytes of them. */
        for (unsigned k = 0; k < stride[best] - 1u; k++)
            put64(pay + 8 * k, w[k]);
        memcpy(r + 10, pay, len[best]);
        r += 10u + len[best];
        head[best] += stride[best];
        left[best]--;
    }
}

int ef_vec_bin_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c)
{
    uint8_t h[EF_VEC_BIN_HEADER];
    size_t size = 0;
    uint8_t *all;

    for (int i = 0; i < EF_IF_COUNT; i++)
        if (info->mask >> i & 1u)
            size += ef_vec_collect_count(c, i) * (10u + (ef_iface_get(i)->width + 7u) / 8u);
    if ((all = malloc(size ? size : 1)) == NULL)
        return -1;
    size = records(c, info->mask, all);
    ef_vec_bin_header(h, info, c, ef_vec_crc32(0, all, size));
    ef_vec_out_write(o, h, sizeof h);
    ef_vec_out_write(o, all, size);
    free(all);
    return 0;
}
