/*
 * vec_bin.c - vectors.bin (docs/vectors.md section 4): a 104-byte
 * little-endian header with the parameters, per-interface counts and two
 * CRC-32s, then every transaction of the recorded interfaces as a framed
 * record in global cycle order.  The header's record CRC must be known
 * before the records are written and the output is a stream (it is hashed
 * as it goes), so the records are produced twice: once to compute the CRC,
 * once to write them.  The merge is cheap next to the writing.
 */
#include "ef_vec.h"

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

static void put64(uint8_t *p, uint64_t v)
{
    for (int i = 0; i < 8; i++)
        p[i] = (uint8_t)(v >> (8 * i));
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

void ef_vec_bin_write(ef_vec_out *o, const ef_vec_info *info, const ef_vec_collect *c)
{
    uint8_t h[EF_VEC_BIN_HEADER], r[EF_VEC_BIN_RECORD_MAX];
    uint32_t crc = 0;
    ef_vec_merge m;
    ef_txn t;

    ef_vec_merge_init(&m, c, info->mask);
    while (ef_vec_merge_next(&m, &t))
        crc = ef_vec_crc32(crc, r, ef_vec_bin_record(&t, r));
    ef_vec_bin_header(h, info, c, crc);
    ef_vec_out_write(o, h, sizeof h);
    ef_vec_merge_init(&m, c, info->mask);
    while (ef_vec_merge_next(&m, &t))
        ef_vec_out_write(o, r, ef_vec_bin_record(&t, r));
}
