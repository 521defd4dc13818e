/*
 * ef_frame.c - frame layout of the board protocol (ef_frame.h).  The parser
 * trusts nothing: a frame is accepted only with the magic, a zero reserved
 * field, a length within EF_PROTO_PAYLOAD_MAX and a matching CRC; anything
 * else is "not a frame here" and the caller skips to the next magic.
 */
#include "ef_frame.h"

#include <string.h>
#include <zlib.h>

/* zlib's crc32 (the same CRC as vectors.bin's): about twice the speed of
 * rtl_vectors' slicing-by-8 here, and the frame CRC is the host's main cost
 * per byte (docs/board.md section 8).  The vector tools keep their own, as
 * the 32-bit and cross builds of the portability matrix cannot have zlib;
 * the host and the board engine are built natively only. */
uint32_t ef_frame_crc32(uint32_t crc, const void *data, size_t n)
{
    while (n > 0) { /* zlib takes uInt lengths */
        const uInt k = n > 0x40000000u ? 0x40000000u : (uInt)n;
        crc = (uint32_t)crc32(crc, data, k);
        data = (const uint8_t *)data + k;
        n -= k;
    }
    return crc;
}

uint32_t ef_frame_crc32_combine(uint32_t crc_a, uint32_t crc_b, uint64_t len_b)
{
    return (uint32_t)crc32_combine(crc_a, crc_b, (z_off_t)len_b);
}

/* The frame's CRC from the header's and the payload's: the payload is read
 * once, and its own CRC (which results and inputs are chained with) comes
 * for free. */
static size_t seal(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, uint32_t len, uint32_t *payload_crc)
{
    memcpy(out, EF_PROTO_MAGIC, 4);
    out[4] = type;
    out[5] = flags;
    out[6] = out[7] = 0;
    ef_put32(out + 8, seq);
    ef_put32(out + 12, len);
    const uint32_t cp = ef_frame_crc32(0, out + EF_PROTO_HEADER, len);
    ef_put32(out + EF_PROTO_HEADER + len, ef_frame_crc32_combine(ef_frame_crc32(0, out, EF_PROTO_HEADER), cp, len));
    if (payload_crc)
        *payload_crc = cp;
    return EF_PROTO_HEADER + (size_t)len + EF_PROTO_TRAILER;
}

size_t ef_frame_seal(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, uint32_t len)
{
    return seal(out, type, flags, seq, len, NULL);
}

size_t ef_frame_put_crc(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, const void *payload, uint32_t len,
                        uint32_t *payload_crc)
{
    if (len)
        memmove(out + EF_PROTO_HEADER, payload, len);
    return seal(out, type, flags, seq, len, payload_crc);
}

size_t ef_frame_put(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, const void *payload, uint32_t len)
{
    return ef_frame_put_crc(out, type, flags, seq, payload, len, NULL);
}

int ef_frame_parse_part(const uint8_t *buf, size_t n, ef_frame *f, size_t *used, ef_frame_part *part)
{
    static const uint8_t magic[4] = { 'E', 'F', 'B', '1' };
    const size_t m = n < 4 ? n : 4;
    if (memcmp(buf, magic, m) != 0)
        return EF_FRAME_BAD;
    if (n < EF_PROTO_HEADER)
        return EF_FRAME_MORE;
    const uint32_t len = ef_get32(buf + 12);
    if (buf[6] != 0 || buf[7] != 0 || len > EF_PROTO_PAYLOAD_MAX)
        return EF_FRAME_BAD;
    const size_t total = EF_PROTO_HEADER + (size_t)len + EF_PROTO_TRAILER;
    ef_frame_part whole = { 0, 0 }; /* (ef_frame_parse: the payload read once, when all there) */
    if (!part) {
        if (n < total)
            return EF_FRAME_MORE;
        part = &whole;
    }
    const size_t have = n - EF_PROTO_HEADER < len ? n - EF_PROTO_HEADER : len; /* payload bytes here */
    if (have > part->done) {
        part->crc = ef_frame_crc32(part->crc, buf + EF_PROTO_HEADER + part->done, have - part->done);
        part->done = (uint32_t)have;
    }
    if (n < total)
        return EF_FRAME_MORE;
    const uint32_t ch = ef_frame_crc32(0, buf, EF_PROTO_HEADER);
    const uint32_t cp = part->crc;
    if (ef_frame_crc32_combine(ch, cp, len) != ef_get32(buf + EF_PROTO_HEADER + len))
        return EF_FRAME_BAD;
    f->payload_crc = cp;
    f->type = buf[4];
    f->flags = buf[5];
    f->seq = ef_get32(buf + 8);
    f->len = len;
    f->payload = buf + EF_PROTO_HEADER;
    *used = total;
    return EF_FRAME_OK;
}

int ef_frame_parse(const uint8_t *buf, size_t n, ef_frame *f, size_t *used)
{
    return ef_frame_parse_part(buf, n, f, used, NULL);
}

size_t ef_frame_resync(const uint8_t *buf, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        const uint8_t *p = memchr(buf + i, 'E', n - i);
        if (!p)
            return n;
        i = (size_t)(p - buf);
        const size_t m = n - i < 4 ? n - i : 4;
        if (memcmp(p, EF_PROTO_MAGIC, m) == 0)
            return i;
    }
    return n;
}
