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

#define EF_BOARD_PROTOCOL 1            /* protocol version in identify */
#define EF_BOARD_MAGIC "EFB1"          /* first 4 bytes of every frame */
#define EF_BOARD_HEADER 16             /* frame header bytes */
#define EF_BOARD_TRAILER 4             /* CRC-32 after the payload */
#define EF_BOARD_PAYLOAD_MAX 65536     /* largest payload a board must take */
#define EF_BOARD_FRAME_MAX (EF_BOARD_HEADER + EF_BOARD_PAYLOAD_MAX + EF_BOARD_TRAILER)
#define EF_BOARD_IDENTIFY_LEN 48
#define EF_BOARD_STATUS_LEN 40
#define EF_BOARD_CMD_BYTES 13          /* one 100-bit cmd word, little-endian */

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
    EF_FT_ERROR = 0x85   /* board -> host: the DUT or the board failed */
};

typedef struct ef_board ef_board;

/* What the board reports in identify (docs/board.md section 3). */
typedef struct ef_board_info {
    char serial[17];         /* NUL-terminated, at most 16 characters */
    uint32_t capabilities;   /* EF_BOARD_CAP_* */
    uint32_t samples_mask;   /* bit n: n samples supported (8, 16, 32) */
    uint32_t width_max, height_max, edges_max;
    uint32_t window;         /* frames the host may have unacknowledged */
    uint32_t iface_mask;     /* interfaces the board can return */
} ef_board_info;

enum { EF_BOARD_CAP_RESULTS = 1, EF_BOARD_CAP_RESUME = 2, EF_BOARD_CAP_INTERNAL = 4 };

/* The DUT behind the engine.  push() takes one cmd word (13 bytes); results
 * are handed back through emit(), one vectors.bin record at a time, in cycle
 * order.  finish() is called at END.  Return 0 or a negative error. */
typedef struct ef_board_dut {
    void *self;
    int (*start)(void *self, uint32_t iface_mask);
    int (*push)(void *self, const uint8_t cmd[EF_BOARD_CMD_BYTES]);
    int (*finish)(void *self);
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

/* Control requests. */
void ef_board_identify(const ef_board *b, uint8_t out[EF_BOARD_IDENTIFY_LEN]);
void ef_board_status(const ef_board *b, uint8_t out[EF_BOARD_STATUS_LEN]);
void ef_board_reset(ef_board *b);

/* Called by the DUT for every output record (vectors.bin layout). */
int ef_board_emit(ef_board *b, const uint8_t *record, size_t len);

#endif /* EF_BOARD_H */
