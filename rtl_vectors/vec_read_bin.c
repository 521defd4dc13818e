/*
 * vec_read_bin.c - reader of the binary vector stream of docs/vectors.md
 * section 4: a 104-byte little-endian header (magic, version, header size,
 * parameters, interface mask, per-interface counts, two CRC-32s) and framed
 * records { interface, payload length, cycle[8], payload[L] }.
 *
 * Read record by record from the source, so the stream is never held whole.
 * Every framing field is checked where it is read and reported as
 * "record N (byte offset O)"; what can only be known at the end - the counts
 * and the records' CRC - is checked there (counts first: a stream cut at a
 * record boundary is better described by "the header counts 120 pix
 * records, the stream holds 119" than by a CRC).
 */
#include "vec_read_internal.h"

#include <inttypes.h>
#include <string.h>

static uint64_t le(const uint8_t *p, unsigned n)
{
    uint64_t v = 0;
    for (unsigned i = n; i > 0; i--)
        v = (v << 8) | p[i - 1];
    return v;
}

/* Eight little-endian bytes, in one expression (one load where it can be). */
static uint64_t le64(const uint8_t *p)
{
    return (uint64_t)p[0] | (uint64_t)p[1] << 8 | (uint64_t)p[2] << 16 | (uint64_t)p[3] << 24 | (uint64_t)p[4] << 32 |
           (uint64_t)p[5] << 40 | (uint64_t)p[6] << 48 | (uint64_t)p[7] << 56;
}

static ef_status bad_magic(const uint8_t *hd, size_t got, const char *name, ef_vec_read_error *err)
{
    /* The magic is built to show how a transfer damaged it (as PNG's is). */
    if (got >= 4 && (hd[0] == 0x89 || hd[0] == 0x09) && memcmp(hd + 1, "EFV", 3) == 0)
        return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 0,
                             "bad magic: the stream was damaged by a text-mode or 7-bit transfer "
                             "(expected 89 45 46 56 0d 0a 1a 0a)");
    return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 0,
                         "bad magic: not an edgeflag binary vector stream (expected 89 45 46 56 0d 0a 1a 0a)");
}

static ef_status read_header(ef_vr_src *s, const char *name, ef_vec_dump *out, uint64_t counts[EF_IF_COUNT],
                             uint32_t *data_crc, ef_vec_read_error *err)
{
    uint8_t hd[EF_VEC_BIN_HEADER_SIZE];
    size_t got = ef_vr_read(s, hd, sizeof hd);
    const size_t m = got < 8 ? got : 8;

    if (s->ioerr)
        return EF_ERR_IO; /* ef_vec_read_path reports it */
    if (got == 0)
        return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 0,
                             "empty file: truncated header, 0 of %u bytes", EF_VEC_BIN_HEADER_SIZE);
    if (memcmp(hd, ef_vec_bin_magic, m) != 0)
        return bad_magic(hd, got, name, err);
    if (got >= 10 && le(hd + 8, 2) != EF_VEC_BIN_VERSION)
        return ef_vr_err_bin(err, EF_ERR_UNSUPPORTED, name, EF_VEC_AT_HEADER, 0, 8,
                             "format version %" PRIu64 " is not supported (this edgeflag reads version %u)",
                             le(hd + 8, 2), EF_VEC_BIN_VERSION);
    if (got >= 12 && le(hd + 10, 2) != EF_VEC_BIN_HEADER_SIZE)
        return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 10,
                             "header size %" PRIu64 ", version 1 has %u", le(hd + 10, 2), EF_VEC_BIN_HEADER_SIZE);
    if (got < sizeof hd)
        return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, got, "truncated header: %zu of %u bytes",
                             got, EF_VEC_BIN_HEADER_SIZE);
    uint32_t hcrc = ef_vec_read_crc32(0, hd, 100);
    if (hcrc != le(hd + 100, 4))
        return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 100,
                             "header CRC mismatch: computed 0x%08" PRIx32 ", stored 0x%08" PRIx64
                             " (the header is damaged)",
                             hcrc, le(hd + 100, 4));
    /* The CRC holds, so a bad field below was written so, not damaged. */
    const unsigned samples = hd[12], rule = hd[13];
    if (!ef_samples_valid((int)samples))
        return ef_vr_err_bin(err, EF_ERR_RANGE, name, EF_VEC_AT_HEADER, 0, 12,
                             "samples %u: " EF_SAMPLES_TEXT " expected", samples);
    if (rule > 2)
        return ef_vr_err_bin(err, EF_ERR_RANGE, name, EF_VEC_AT_HEADER, 0, 13,
                             "rule %u: 0 (nonzero), 1 (evenodd) or 2 (each shape's own) expected", rule);
    if (le(hd + 14, 2) != 0 || le(hd + 36, 4) != 0)
        return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, le(hd + 14, 2) ? 14 : 36,
                             "reserved header bytes are not 0");
    for (unsigned k = 0; k < 2; k++) {
        uint64_t v = le(hd + 16 + 4 * k, 4);
        if (v < 1 || v > EF_MAX_CANVAS)
            return ef_vr_err_bin(err, EF_ERR_RANGE, name, EF_VEC_AT_HEADER, 0, 16 + 4 * k,
                                 "%s %" PRIu64 ": 1..%d expected", k ? "height" : "width", v, EF_MAX_CANVAS);
    }
    const uint64_t mask = le(hd + 32, 4);
    if (mask & ~(uint64_t)EF_IF_ALL)
        return ef_vr_err_bin(err, EF_ERR_RANGE, name, EF_VEC_AT_HEADER, 0, 32,
                             "interface mask 0x%08" PRIx64 " names interfaces past %d", mask, EF_IF_COUNT - 1);
    for (int i = 0; i < EF_IF_COUNT; i++) {
        counts[i] = le(hd + 40 + 8 * (unsigned)i, 8);
        if (!(mask >> i & 1u) && counts[i])
            return ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 40 + 8 * (uint64_t)i,
                                 "count %" PRIu64 " for interface %s, which the mask says is not recorded", counts[i],
                                 ef_iface_get(i)->name);
        if (mask >> i & 1u)
            ef_vr_dump_add_iface(out, i);
    }
    out->samples = (int)samples;
    out->rule = (int)rule;
    out->width = (int32_t)le(hd + 16, 4);
    out->height = (int32_t)le(hd + 20, 4);
    out->seed = le(hd + 24, 8);
    *data_crc = (uint32_t)le(hd + 96, 4);
    return EF_OK;
}

/* One record at offset off (record number rec).  1 and the record, 0 at a
 * clean end of the stream, or -1 with err set. */
static int read_record(ef_vr_src *s, const char *name, ef_vec_dump *out, uint64_t rec, uint64_t off,
                       ef_vec_read_error *err)
{
    uint8_t buf[10 + 32];
    const uint8_t *pre = buf, *pl = buf + 10;
    size_t n, m;
    /* A record whole in the current chunk (all but a few per chunk) is read
     * where it is; the rest are copied together across the chunk boundary. */
    const int direct = s->n - s->pos >= sizeof buf;
    if (direct) {
        pre = s->p + s->pos;
        pl = pre + 10;
        n = 10;
    } else if ((n = ef_vr_read(s, buf, 10)) == 0) {
        return 0;
    }
    const unsigned iface = pre[0];
    const ef_iface_desc *d = ef_iface_get((int)iface);
    if (!d || !(out->mask >> iface & 1u)) {
        if (!d)
            ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_RECORD, rec, off, "unknown interface number %u (0..%d)",
                          iface, EF_IF_COUNT - 1);
        else
            ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_RECORD, rec, off,
                          "interface %u (%s) is not in the header's interface mask 0x%02" PRIx32, iface, d->name,
                          out->mask);
        return -1;
    }
    const unsigned want = (d->width + 7u) / 8u;
    if (n >= 2 && pre[1] != want) {
        ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_RECORD, rec, off,
                      "payload length %u, interface %s has %u bytes", pre[1], d->name, want);
        return -1;
    }
    if (direct) {
        s->pos += 10u + want;
        m = want;
    } else {
        m = n == 10 ? ef_vr_read(s, buf + 10, want) : 0;
    }
    if (n < 10 || m < want) {
        ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_RECORD, rec, off, "truncated record: %zu of %u bytes", n + m,
                      10u + want);
        return -1;
    }
    const uint64_t cycle = le64(pre + 2);
    if (cycle >> EF_CYCLE_BITS) {
        ef_vr_err_bin(err, EF_ERR_RANGE, name, EF_VEC_AT_RECORD, rec, off, "cycle %" PRIu64 " does not fit %u bits",
                      cycle, EF_CYCLE_BITS);
        return -1;
    }
    uint64_t w[EF_TXN_WORDS] = { 0 };
    unsigned b = 0;
    for (; b + 8 <= want; b += 8)
        w[b / 8] = le64(pl + b);
    for (; b < want; b++)
        w[b / 8] |= (uint64_t)pl[b] << (8 * (b % 8));
    const unsigned top = d->width % 64u;
    if (top && (w[d->width / 64u] >> top)) {
        ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_RECORD, rec, off,
                      "payload bits above bit %u are set (interface %s has %u bits)", d->width - 1u, d->name,
                      (unsigned)d->width);
        return -1;
    }
    if (ef_vr_append(out, (int)iface, cycle, w, rec, off, 1)) {
        ef_vr_err_file(err, EF_ERR_NOMEM, name, "out of memory");
        return -1;
    }
    return 1;
}

ef_status ef_vr_bin(ef_vr_src *s, const char *name, ef_vec_dump *out, ef_vec_read_error *err)
{
    uint64_t counts[EF_IF_COUNT];
    uint32_t stored_crc = 0, crc;
    uint64_t rec = 0;
    int r;

    ef_vr_dump_init(out, EF_VEC_FMT_BIN);
    ef_status st = read_header(s, name, out, counts, &stored_crc, err);
    if (st != EF_OK)
        goto fail;
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (out->mask >> i & 1u)
            ef_vr_reserve(out, i, counts[i], s->size, 10u + (ef_iface_get(i)->width + 7u) / 8u, 1);
    ef_vr_crc_start(s); /* the records' CRC: every byte after the header */
    for (;;) {
        const uint64_t off = ef_vr_tell(s);
        r = read_record(s, name, out, rec + 1, off, err);
        if (r <= 0) {
            if (r < 0) {
                st = err->status;
                goto fail;
            }
            break;
        }
        rec++;
    }
    if (s->ioerr) {
        st = EF_ERR_IO;
        goto fail;
    }
    crc = ef_vr_crc_end(s);
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (counts[i] != out->seq[i].n) {
            st = ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_END, rec, ef_vr_tell(s),
                               "the header counts %" PRIu64 " %s records, the stream holds %zu", counts[i],
                               ef_iface_get(i)->name, out->seq[i].n);
            goto fail;
        }
    if (crc != stored_crc) {
        st = ef_vr_err_bin(err, EF_ERR_SYNTAX, name, EF_VEC_AT_HEADER, 0, 96,
                           "records CRC mismatch: computed 0x%08" PRIx32 ", stored 0x%08" PRIx32
                           " (the records are damaged)",
                           crc, stored_crc);
        goto fail;
    }
    return EF_OK;
fail:
    ef_vec_dump_destroy(out);
    return st;
}
