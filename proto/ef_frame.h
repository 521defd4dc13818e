/*
 * ef_frame.h - one frame of the board protocol (docs/board.md section 2),
 * the same in both directions:
 *
 *   offset 0  "EFB1"             magic
 *          4  type (u8)          EF_FT_*
 *          5  flags (u8)         per type; 0 unless the type says otherwise
 *          6  reserved (u16)     0
 *          8  seq (u32)          sequence number (per direction)
 *         12  len (u32)          payload bytes, 0 .. EF_PROTO_PAYLOAD_MAX
 *         16  payload
 *   16 + len  crc (u32)          CRC-32 (IEEE, as vectors.bin) of bytes 0 .. 16+len-1
 *
 * All integers little-endian.  Used by the board engine and by edgeflag-host.
 */
#ifndef EF_FRAME_H
#define EF_FRAME_H

#include <stddef.h>
#include <stdint.h>

#include "ef_proto.h"

typedef struct ef_frame {
    uint8_t type, flags;
    uint32_t seq, len;
    const uint8_t *payload; /* points into the parsed buffer */
    uint32_t payload_crc;   /* CRC-32 of the payload alone, derived from the frame's */
} ef_frame;

enum {
    EF_FRAME_OK = 0,   /* *used = the frame's size */
    EF_FRAME_MORE = 1, /* a frame may start here: need more bytes */
    EF_FRAME_BAD = -1  /* not a frame here (magic, reserved, length or CRC): skip a byte */
};

/* Writes a frame into out (room for EF_PROTO_HEADER + len + EF_PROTO_TRAILER
 * bytes); returns its size.  payload may be NULL when len is 0. */
size_t ef_frame_put(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, const void *payload, uint32_t len);
/* Writes only the header and trailer around a payload already at
 * out + EF_PROTO_HEADER (no copy); returns the frame's size. */
size_t ef_frame_seal(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, uint32_t len);
/* The same, also giving the CRC-32 of the payload alone (one pass over it). */
size_t ef_frame_put_crc(uint8_t *out, uint8_t type, uint8_t flags, uint32_t seq, const void *payload, uint32_t len,
                        uint32_t *payload_crc);
/* Parses the frame at buf[0..n). */
int ef_frame_parse(const uint8_t *buf, size_t n, ef_frame *f, size_t *used);
/* A frame's payload CRC so far, for a frame that arrives in pieces: zeroed
 * (ef_frame_part p = { 0 }) for each new frame start, kept by the caller while
 * the bytes of buf[0..n) stay and only grow. */
typedef struct ef_frame_part {
    uint32_t crc, done; /* CRC-32 of the payload's first `done` bytes */
} ef_frame_part;
/* ef_frame_parse, but each call reads only the payload bytes the last call
 * with the same *part did not (a frame of n bytes costs O(n) however many
 * calls it takes): the same results.  part NULL: ef_frame_parse. */
int ef_frame_parse_part(const uint8_t *buf, size_t n, ef_frame *f, size_t *used, ef_frame_part *part);
/* Offset of the next possible frame start ("EFB1" or a prefix of it at the
 * end) in buf[1..n), or n. */
size_t ef_frame_resync(const uint8_t *buf, size_t n);

uint32_t ef_frame_crc32(uint32_t crc, const void *data, size_t n);
/* CRC-32 of A then B from crc(A), crc(B) and B's length (zlib's crc32_combine). */
uint32_t ef_frame_crc32_combine(uint32_t crc_a, uint32_t crc_b, uint64_t len_b);

static inline void ef_put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}
static inline uint32_t ef_get32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static inline void ef_put64(uint8_t *p, uint64_t v) { ef_put32(p, (uint32_t)v), ef_put32(p + 4, (uint32_t)(v >> 32)); }
static inline uint64_t ef_get64(const uint8_t *p) { return (uint64_t)ef_get32(p) | (uint64_t)ef_get32(p + 4) << 32; }

#endif /* EF_FRAME_H */
