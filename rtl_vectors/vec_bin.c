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

void ef_vec_bin_header_counts(uint8_t h[EF_VEC_BIN_HEADER], const ef_vec_info *info, const uint64_t counts[EF_IF_COUNT],
                              uint32_t records_crc)
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

/* Where the next record of each interface comes from. */
typedef struct heads {
    const uint64_t *at[EF_IF_COUNT];
    unsigned nw[EF_IF_COUNT], len[EF_IF_COUNT];
} heads;

static void heads_init(heads *h, const ef_vec_collect *c)
{
    for (int i = 0; i < EF_IF_COUNT; i++) {
        h->at[i] = c->list[i].rec;
        h->nw[i] = c->list[i].nw;
        h->len[i] = (ef_iface_get(i)->width + 7u) / 8u;
    }
}

/* The merge of the interfaces' lists into stream order (cycle, ties: the
 * lower interface first), taken a piece at a time so that the records it
 * compares are still in the cache when the first pass builds them. */
typedef struct merge {
    const uint64_t *head[EF_IF_COUNT];
    size_t left[EF_IF_COUNT];
    unsigned stride[EF_IF_COUNT];
} merge;

static void merge_init(merge *m, const ef_vec_collect *c, uint32_t mask)
{
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_vec_list *l = &c->list[i];
        m->head[i] = l->rec;
        m->left[i] = (mask >> i & 1u) ? l->count : 0;
        m->stride[i] = 1u + l->nw;
    }
}

/* The interfaces of the next n records into ord (there are at least n). */
static void merge_next(merge *m, uint8_t *ord, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        int best = -1;
        uint64_t cyc = 0;
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (m->left[i] && (best < 0 || m->head[i][0] < cyc)) {
                best = i;
                cyc = m->head[i][0];
            }
        ord[k] = (uint8_t)best;
        m->head[best] += m->stride[best];
        m->left[best]--;
    }
}

/* Records ord[0..n) into dst, which has room for 10 + 8 * EF_TXN_WORDS
 * bytes past the last record's start (the payload is stored as whole words;
 * the bytes past ceil(P/8) are overwritten by the next record).  Returns the
 * bytes of the n records. */
static size_t build(heads *h, const uint8_t *ord, size_t n, uint8_t *dst)
{
    uint8_t *r = dst;
    for (size_t k = 0; k < n; k++) {
        const unsigned i = ord[k];
        const uint64_t *w = h->at[i];
        r[0] = (uint8_t)i;
        r[1] = (uint8_t)h->len[i];
        put64(r + 2, w[0]);
        for (unsigned j = 0; j < h->nw[i]; j++) /* little-endian words (a plain store on such hosts) */
            put64(r + 10 + 8 * j, w[1 + j]);
        r += 10u + h->len[i];
        h->at[i] = w + 1 + h->nw[i];
    }
    return (size_t)(r - dst);
}

/* The records go out in pieces of at most this many, so that every piece
 * fits the sink's room (EF_VEC_OUT_ROOM) and stays in the cache for the
 * CRC or the hash that follows. */
#define PIECE ((EF_VEC_OUT_ROOM - (10u + 8u * EF_TXN_WORDS)) / (10u + 8u * EF_TXN_WORDS))

/* The header's CRC covers the records and the header comes first, and the
 * stream is hashed as it goes: so the records are built twice, a piece at
 * a time, once for their CRC (right after the merge has put the piece in
 * order) and once into the sink, instead of once into a block of the whole
 * stream's size (15 MB for the tiger at 640x480, every page of it a fault
 * and read back from memory by the CRC and the hash). */
int ef_vec_bin_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c)
{
    uint8_t h[EF_VEC_BIN_HEADER];
    uint8_t piece[EF_VEC_OUT_ROOM];
    size_t n = 0;
    uint32_t crc = 0;
    uint8_t *ord;
    merge mg;
    heads hd;

    for (int i = 0; i < EF_IF_COUNT; i++)
        if (info->mask >> i & 1u)
            n += ef_vec_collect_count(c, i);
    if ((ord = malloc(n ? n : 1)) == NULL)
        return -1;
    merge_init(&mg, c, info->mask);
    heads_init(&hd, c);
    for (size_t k = 0; k < n; k += PIECE) {
        const size_t m = n - k < PIECE ? n - k : PIECE;
        merge_next(&mg, ord + k, m);
        crc = ef_vec_crc32(crc, piece, build(&hd, ord + k, m, piece));
    }
    ef_vec_bin_header(h, info, c, crc);
    ef_vec_out_write(o, h, sizeof h);
    heads_init(&hd, c);
    for (size_t k = 0; k < n; k += PIECE) {
        const size_t m = n - k < PIECE ? n - k : PIECE;
        ef_vec_out_advance(o, build(&hd, ord + k, m, ef_vec_out_room(o, EF_VEC_OUT_ROOM)));
    }
    free(ord);
    return 0;
}
