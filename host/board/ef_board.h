/*
 * ef_board.h - the board's side of the edgeflag board protocol (docs/board.md):
 * the engine that board firmware or a soft core runs.  Bytes from the host
 * (USB bulk OUT, or the GPIO bus's host-to-board bytes) go in through
 * ef_board_rx(); bytes for the host (acks, results, done, errors: USB bulk IN
 * or the GPIO bus's board-to-host bytes) come out of ef_board_tx().  The three
 * control requests (identify, status, reset) are plain calls; a transport maps
 * them onto USB control transfers or onto its own bus cycles.
 *
 * The engine never blocks, never prints and holds no globals: the simulated
 * board, the emulated USB device and the emulated GPIO bus each own one.  The
 * DUT behind it is pluggable (ef_board_dut); the default is the C model's
 * timing model (dut_model.c).
 */
#ifndef EF_BOARD_H
#define EF_BOARD_H

#include <stddef.h>
#include <stdint.h>

#define EF_BOARD_PROTOCOL 1        /* protocol version in identify */
#define EF_BOARD_MAGIC "EFB1"      /* first 4 bytes of every frame */
#define EF_BOARD_HEADER 16         /* frame header bytes */
#define EF_BOARD_TRAILER 4         /* CRC-32 after the payload */
#define EF_BOARD_PAYLOAD_MAX 65536 /* largest payload a board must take */
#define EF_BOARD_FRAME_MAX (EF_BOARD_HEADER + EF_BOARD_PAYLOAD_MAX + EF_BOARD_TRAILER)
#define EF_BOARD_IDENTIFY_LEN 48
#define EF_BOARD_STATUS_LEN 40
#define EF_BOARD_CMD_BYTES 13 /* one 100-bit cmd word, little-endian */

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

typedef struct ef_board ef_board;

/* Bit of a sample count in samples_mask: 8 -> 3, 16 -> 4, 32 -> 5, other -> 31 (never set). */
static inline unsigned ef_board_samples_bit(unsigned n) { return n == 8 ? 3u : n == 16 ? 4u : n == 32 ? 5u : 31u; }

/* START payload (docs/board.md section 3.2), EF_BOARD_START_LEN bytes:
 * iface_mask u32, samples u32, mode u32, source_kib u32, cmd_count u64. */
#define EF_BOARD_START_LEN 24
enum {
    EF_MODE_DUT = 0,      /* commands to the DUT, its transactions back */
    EF_MODE_SINK = 1,     /* link test: DATA accepted and dropped */
    EF_MODE_LOOPBACK = 2, /* link test: each DATA payload comes back as a RESULT payload */
    EF_MODE_SOURCE = 3    /* link test: source_kib KiB of RESULT payload, no DATA needed */
};
/* ACKR flags */
enum { EF_ACKR_RESEND = 1 };
/* DONE payload, EF_BOARD_DONE_LEN bytes: records u64, result_bytes u64,
 * cmds u64, input_crc u32, results_crc u32. */
#define EF_BOARD_DONE_LEN 32
/* Board states in status. */
enum { EF_BS_IDLE = 0, EF_BS_RUNNING = 1, EF_BS_DONE = 2, EF_BS_ERROR = 3 };

/* What the board reports in identify (docs/board.md section 3). */
typedef struct ef_board_info {
    char serial[17];       /* NUL-terminated, at most 16 characters */
    uint32_t capabilities; /* EF_BOARD_CAP_* */
    uint32_t samples_mask; /* bit k: 2^k samples supported (bits 3, 4, 5: 8, 16, 32) */
    uint32_t width_max, height_max, edges_max;
    uint32_t window;     /* frames the host may have unacknowledged */
    uint32_t iface_mask; /* interfaces the board can return */
} ef_board_info;

enum { EF_BOARD_CAP_RESULTS = 1, EF_BOARD_CAP_RESUME = 2, EF_BOARD_CAP_INTERNAL = 4 };

/* The DUT behind the engine.  push() takes one cmd word (13 bytes); results
 * are handed back through emit(), one vectors.bin record at a time, in cycle
 * order.  finish() is called at END.  Return 0 or a negative error. */
typedef struct ef_board_dut {
    void *self;
    int (*start)(void *self, ef_board *b, uint32_t iface_mask, int samples);
    int (*push)(void *self, const uint8_t cmd[EF_BOARD_CMD_BYTES]);
    int (*finish)(void *self);
    void (*stop)(void *self); /* ends the run (reset, or after DONE/ERROR is acknowledged) */
    void (*destroy)(void *self);
} ef_board_dut;

ef_board *ef_board_new(const ef_board_info *info, ef_board_dut dut);
void ef_board_free(ef_board *b);

/* Host -> board bytes, any split.  Returns 0, or a negative error when the
 * board can take no more (its receive buffer is full: the host exceeded the
 * window).  Never fails on bad frames: those are answered with NAK. */
int ef_board_rx(ef_board *b, const uint8_t *buf, size_t len);
/* Board -> host bytes: copies up to cap pending bytes, returns the count. */
size_t ef_board_tx(ef_board *b, uint8_t *buf, size_t cap);
size_t ef_board_tx_pending(const ef_board *b);

/* Control requests (also answered in the byte stream: docs/board.md 5.5). */
void ef_board_identify(const ef_board *b, uint8_t out[EF_BOARD_IDENTIFY_LEN]);
void ef_board_status(const ef_board *b, uint8_t out[EF_BOARD_STATUS_LEN]);
void ef_board_reset(ef_board *b);
/* A byte-stream link's connection ended (docs/board.md 5.5): drops a frame
 * only partly received and the bytes not yet sent, keeps the run. */
void ef_board_link_lost(ef_board *b);

/* Called by the DUT for every output record (vectors.bin layout). */
int ef_board_emit(ef_board *b, const uint8_t *record, size_t len);
/* Called by the DUT when it fails: the run stops with an ERROR frame. */
void ef_board_fail(ef_board *b, uint32_t code, const char *why);

/* The C model's timing model as the DUT (dut_model.c). */
ef_board_dut ef_board_dut_model(void);

/* Counters for tests and the simulated board's --sim-state. */
typedef struct ef_board_stats {
    uint64_t frames_ok, frames_bad, frames_dup, frames_gap, naks, cmds, records;
    uint32_t input_crc; /* CRC-32 of every accepted DATA payload, in order */
    uint32_t rx_seq, res_next, res_acked;
    int state;
} ef_board_stats;
void ef_board_get_stats(const ef_board *b, ef_board_stats *s);

#endif /* EF_BOARD_H */
