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

#include "ef_proto.h"

typedef struct ef_board ef_board;

/* The DUT behind the engine.  push() takes one cmd word (13 bytes); results
 * are handed back through emit(), one vectors.bin record at a time, in cycle
 * order.  finish() is called at END.  Return 0 or a negative error; push()
 * and finish() may also return 1: busy (the command not taken, the DUT not
 * finished), and the engine calls them again later with the same command.
 * While ef_board_results_full() the DUT holds its records (back-pressure)
 * and says busy rather than wait: the engine never blocks. */
typedef struct ef_board_dut {
    void *self;
    int (*start)(void *self, ef_board *b, uint32_t iface_mask, int samples);
    int (*push)(void *self, const uint8_t cmd[EF_PROTO_CMD_BYTES]);
    int (*finish)(void *self);
    void (*stop)(void *self); /* ends the run (reset, or after DONE/ERROR is acknowledged) */
    void (*destroy)(void *self);
} ef_board_dut;

ef_board *ef_board_new(const ef_proto_info *info, ef_board_dut dut);
void ef_board_free(ef_board *b);

/* Host -> board bytes, any split.  Returns 0, or a negative error when the
 * board can take no more (its receive buffer is full: the host exceeded the
 * window).  Never fails on bad frames: those are answered with NAK. */
int ef_board_rx(ef_board *b, const uint8_t *buf, size_t len);
/* Board -> host bytes: copies up to cap pending bytes, returns the count. */
size_t ef_board_tx(ef_board *b, uint8_t *buf, size_t cap);
size_t ef_board_tx_pending(const ef_board *b);

/* Control requests (also answered in the byte stream: docs/board.md 5.5). */
void ef_board_identify(const ef_board *b, uint8_t out[EF_PROTO_IDENTIFY_LEN]);
void ef_board_status(const ef_board *b, uint8_t out[EF_PROTO_STATUS_LEN]);
void ef_board_reset(ef_board *b);
/* A byte-stream link's connection ended (docs/board.md 5.5): drops a frame
 * only partly received and the bytes not yet sent, keeps the run. */
void ef_board_link_lost(ef_board *b);
/* A serial line has been idle (no byte from the host) for longer than a frame
 * takes (docs/board-serial.md section 3): drops a frame only partly received,
 * whose rest will never come (a host killed mid-frame), so the next frame is
 * not taken for its payload.  Keeps everything else. */
void ef_board_rx_idle(ef_board *b);

/* Whether the run's result queue is full (docs/board.md 4.2: at most
 * EF_BOARD_RESULT_QUEUE result frames made and not acknowledged, default
 * 32): the engine gives the DUT no command then, and the DUT should hold its
 * records until it is not. */
int ef_board_results_full(const ef_board *b);
/* Sets that bound (result frames; 0: none).  For tests. */
void ef_board_set_result_queue(ef_board *b, uint32_t frames);

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
    uint32_t res_peak; /* the most result frames kept at once in this run */
    uint32_t held;     /* host frames received and waiting for the DUT */
} ef_board_stats;
void ef_board_get_stats(const ef_board *b, ef_board_stats *s);

#endif /* EF_BOARD_H */
