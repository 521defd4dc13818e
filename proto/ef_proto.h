/*
 * ef_proto.h - the board protocol's wire constants (docs/board.md): the frame
 * header, the frame types, the START, DONE, identify and status layouts and
 * their fields.  The layer below both ends: the board engine (board/) and
 * edgeflag-host (host/) include it; it includes nothing of either.
 */
#ifndef EF_PROTO_H
#define EF_PROTO_H

#include <stdint.h>

#define EF_PROTO_PROTOCOL 1        /* protocol version in identify */
#define EF_PROTO_MAGIC "EFB1"      /* first 4 bytes of every frame */
#define EF_PROTO_HEADER 16         /* frame header bytes */
#define EF_PROTO_TRAILER 4         /* CRC-32 after the payload */
#define EF_PROTO_PAYLOAD_MAX 65536 /* largest payload a board must take */
#define EF_PROTO_FRAME_MAX (EF_PROTO_HEADER + EF_PROTO_PAYLOAD_MAX + EF_PROTO_TRAILER)
#define EF_PROTO_IDENTIFY_LEN 48
#define EF_PROTO_STATUS_LEN 40
#define EF_PROTO_CMD_BYTES 13 /* one 100-bit cmd word, little-endian */

/* Frame types (docs/board.md section 2). */
enum {
    EF_FT_DATA = 0x01,   /* host -> board: cmd words */
    EF_FT_END = 0x02,    /* host -> board: end of the command stream */
    EF_FT_ACKR = 0x03,   /* host -> board: results received up to seq (cumulative) */
    EF_FT_START = 0x04,  /* host -> board: new run (interfaces to return) */
    EF_FT_ACK = 0x81,    /* board -> host: frames accepted up to seq, credits */
    EF_FT_NAK = 0x82,    /* board -> host: bad frame, resend from seq */
    EF_FT_RESULT = 0x83, /* board -> host: vectors.bin records */
    EF_FT_DONE = 0x84,   /* board -> host: the run is complete */
    EF_FT_ERROR = 0x85,  /* board -> host: the DUT or the board failed */
    /* Control frames of a byte-stream link (docs/board.md 5.5): requests from
     * the host, seq = a tag the reply (type | EF_FT_REPLY) echoes. */
    EF_FT_IDENTIFY = 0x10,
    EF_FT_STATUS = 0x11,
    EF_FT_RESET = 0x12,
    EF_FT_REPLY = 0x80
};

/* Bit of a sample count in samples_mask: 8 -> 3, 16 -> 4, 32 -> 5, other -> 31 (never set). */
static inline unsigned ef_proto_samples_bit(unsigned n) { return n == 8 ? 3u : n == 16 ? 4u : n == 32 ? 5u : 31u; }

/* START payload (docs/board.md section 3.2), EF_PROTO_START_LEN bytes:
 * iface_mask u32, samples u32, mode u32, source_kib u32, cmd_count u64. */
#define EF_PROTO_START_LEN 24
enum {
    EF_MODE_DUT = 0,      /* commands to the DUT, its transactions back */
    EF_MODE_SINK = 1,     /* link test: DATA accepted and dropped */
    EF_MODE_LOOPBACK = 2, /* link test: each DATA payload comes back as a RESULT payload */
    EF_MODE_SOURCE = 3    /* link test: source_kib KiB of RESULT payload, no DATA needed */
};
/* START flags (the frame header's flags field; docs/board.md 4.5): a digest
 * run returns a CRC-32 per window of N transactions of each interface, a
 * select run the full records of chosen windows only. */
enum { EF_START_DIGEST = 1, EF_START_SELECT = 2 };
/* DIGEST: the START payload, then the window N (u32, >= 1).  SELECT: then N,
 * a count K (u32, <= EF_PROTO_SELECT_MAX) and K u32 (interface << 24 | window
 * index), strictly ascending. */
#define EF_PROTO_START_DIGEST_LEN 28
#define EF_PROTO_SELECT_MAX 1024
/* A digest record in a digest run's RESULT payload: interface u8, 0xFF (no
 * vectors.bin record has that length), window index u32, transactions in the
 * window u32, CRC-32 of the window's vectors.bin records u32. */
#define EF_PROTO_DIGEST_LEN 14
#define EF_PROTO_DIGEST_MARK 0xFF
#define EF_PROTO_IFACES 8 /* interface numbers are below this (bit i of a mask) */
/* ACKR flags */
enum { EF_ACKR_RESEND = 1 };
/* DONE payload, EF_PROTO_DONE_LEN bytes: records u64, result_bytes u64,
 * cmds u64, input_crc u32, results_crc u32. */
#define EF_PROTO_DONE_LEN 32
/* Board states in status. */
enum { EF_BS_IDLE = 0, EF_BS_RUNNING = 1, EF_BS_DONE = 2, EF_BS_ERROR = 3 };

/* What the board reports in identify (docs/board.md section 3). */
typedef struct ef_proto_info {
    char serial[17];       /* NUL-terminated, at most 16 characters */
    uint32_t capabilities; /* EF_PROTO_CAP_* */
    uint32_t samples_mask; /* bit k: 2^k samples supported (bits 3, 4, 5: 8, 16, 32) */
    uint32_t width_max, height_max, edges_max;
    uint32_t window;     /* frames the host may have unacknowledged */
    uint32_t iface_mask; /* interfaces the board can return */
} ef_proto_info;

/* Capabilities.  Bits 16-23 are the largest DATA payload the board takes, in
 * KiB (1-63; 0: 64 KiB, EF_PROTO_PAYLOAD_MAX): a board with little RAM says
 * so (capabilities |= EF_PROTO_CAP_DATA(4)).  The engine sets DIGEST itself. */
enum { EF_PROTO_CAP_RESULTS = 1, EF_PROTO_CAP_RESUME = 2, EF_PROTO_CAP_INTERNAL = 4, EF_PROTO_CAP_DIGEST = 8 };
#define EF_PROTO_CAP_DATA(kib) ((uint32_t)(kib) << 16)
#define EF_PROTO_CAP_DATA_KIB(caps) ((caps) >> 16 & 0xffu)

#endif /* EF_PROTO_H */
