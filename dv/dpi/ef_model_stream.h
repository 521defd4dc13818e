/*
 * ef_model_stream.h - the reference model as a stream, for testbenches that
 * run it in lockstep with an RTL (DPI-C, a C++ Verilator harness, cocotb):
 * commands go in one at a time as the `cmd` interface's 100-bit words
 * (docs/microarch.md 3.1, the payloads of cmd.stim.hex), and the expected
 * transactions of every interface come out one at a time, each with the cycle
 * stamp of the reference schedule (docs/microarch.md 4).  docs/dpi.md is the
 * contract; dv/dpi/ef_dpi.c wraps it for SystemVerilog's DPI-C.
 *
 * Why commands, not a scene: a testbench owns its stimulus (a file, a
 * generator, a sequence) and has only the words it sends the DUT.  The model
 * buffers a shape's commands and runs the traced model (ef_fill with
 * ef_trace_enable, model/ef_trace.h) at its SHAPE_END, so a shape's
 * transactions appear all at once when its SHAPE_END is fed: a pop before
 * that says EF_MS_EMPTY ("feed more commands"), never "no transaction".
 *
 * Every handle is independent (no global state, nothing lazily built), so a
 * simulation may hold several models, created and used from several threads
 * as long as one handle is used by one thread at a time.  Nothing here prints
 * or exits; every failure is a status and a message on the handle.
 */
#ifndef EF_MODEL_STREAM_H
#define EF_MODEL_STREAM_H

#include <stddef.h>
#include <stdint.h>

#include "edgeflag.h"
#include "ef_trace.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Status of every call.  Non-negative values are outcomes, negative ones
 * errors.  An error from ef_mstream_cmd is sticky: the handle refuses every
 * later command with EF_MS_ERR_STOPPED (its message stays the first error's),
 * while transactions queued before it can still be popped. */
typedef enum ef_mstream_status {
    EF_MS_OK = 0,
    EF_MS_EMPTY = 1,        /* nothing queued on the interface yet: feed more commands */
    EF_MS_END = 2,          /* the frame has ended and the interface has nothing more */
    EF_MS_MISMATCH = 3,     /* ef_mstream_expect: the actual transaction differs (see the message) */
    EF_MS_ERR_ARG = -1,     /* a NULL handle, a bad interface number or parameter */
    EF_MS_ERR_NOMEM = -2,   /* out of memory */
    EF_MS_ERR_OP = -3,      /* a command with an op code that is not in docs/microarch.md 3.1 */
    EF_MS_ERR_FIELD = -4,   /* a command field outside its range (a reserved field not 0, a rule not 0/1, ...) */
    EF_MS_ERR_ORDER = -5,   /* a command out of place (EDGE outside SHAPE..SHAPE_END, a FRAME inside a frame, ...) */
    EF_MS_ERR_LIMIT = -6,   /* over the hardware's parameters: a canvas over width_max x height_max, more than
                                 edges_max EDGE commands in one shape */
    EF_MS_ERR_CONTOUR = -7, /* a shape's edges do not chain into closed contours (the model takes polygons) */
    EF_MS_ERR_MODEL = -8,   /* the model refused the shape (its ef_status is in the message) */
    EF_MS_ERR_STOPPED = -9  /* an earlier command failed; the handle takes no more */
} ef_mstream_status;

/* A fixed English text for a status ("out of memory"), never NULL. */
const char *ef_mstream_strerror(int status);

/* The rule setting: each SHAPE command's own, or one for every shape (as
 * `edgeflag vectors --rule`; the model's cmd transactions then carry it). */
#define EF_MS_RULE_CMD (-1)

typedef struct ef_mstream_params {
    int samples;        /* 8, 16 or 32 (the RTL's NS) */
    int32_t width_max;  /* largest canvas a FRAME may set (the RTL's W_MAX), 1..16384 */
    int32_t height_max; /* (H_MAX), 1..16384 */
    uint32_t edges_max; /* most EDGE commands in one shape (E_MAX), 1..2^22 */
    int rule;           /* EF_MS_RULE_CMD, EF_RULE_NONZERO or EF_RULE_EVENODD */
    uint32_t ifaces;    /* interfaces to queue, bit i = ef_iface i (EF_IF_ALL); others are not kept */
} ef_mstream_params;

/* samples 8, 16384 x 16384, 2^22 edges, each shape's own rule, all interfaces. */
void ef_mstream_params_default(ef_mstream_params *p);

typedef struct ef_mstream ef_mstream;

/* Creates a model.  *out is NULL on failure (EF_MS_ERR_ARG for a parameter
 * outside its range, EF_MS_ERR_NOMEM). */
int ef_mstream_create(ef_mstream **out, const ef_mstream_params *p);
void ef_mstream_destroy(ef_mstream *m);

/* Feeds one command: the 100-bit payload of a cmd word, word[0] = bits 63..0,
 * word[1] = bits 99..64 (bits above 99 must be 0: EF_MS_ERR_FIELD).  The
 * order rules are docs/microarch.md 3.1's: FRAME, then per shape SHAPE,
 * EDGE..., SHAPE_END, then FRAME_END; a new FRAME may follow (its cycles
 * start again at 0).  EF_MS_OK, or an error (sticky, see above). */
int ef_mstream_cmd(ef_mstream *m, const uint64_t word[2]);
/* The same from the fields (op 4 bits; a..d 24-bit two's complement, given
 * as signed values or as their 24 bits). */
int ef_mstream_cmd_fields(ef_mstream *m, unsigned op, int32_t a, int32_t b, int32_t c, int32_t d);

/* The next expected transaction of interface iface (ef_iface): EF_MS_OK and
 * *out (cycle, payload, iface); EF_MS_EMPTY when none is queued but the frame
 * is still open (feed more commands), EF_MS_END when the frame has ended and
 * all of this interface's transactions were popped; EF_MS_ERR_ARG for an
 * interface outside params.ifaces.  Within one interface the cycles
 * strictly increase (one transfer per cycle); across interfaces no order is
 * promised.  Peek is the same without removing it. */
int ef_mstream_pop(ef_mstream *m, int iface, ef_txn *out);
int ef_mstream_peek(const ef_mstream *m, int iface, ef_txn *out);
/* Transactions of iface queued now (0 for an interface not queued). */
size_t ef_mstream_pending(const ef_mstream *m, int iface);

/* Scoreboard step: pops the next expected transaction of actual->iface and
 * compares it with actual (payload and cycle; cycle ignored when
 * check_cycle is 0).  EF_MS_OK when equal, EF_MS_MISMATCH when not, EF_MS_END
 * for an extra transaction, EF_MS_EMPTY when the model has none yet (nothing
 * popped: feed commands and call again).  For MISMATCH and END the message
 * (ef_mstream_message) names the interface, the cycle and every decoded
 * field, expected against actual, each differing actual field marked `*`. */
int ef_mstream_expect(ef_mstream *m, const ef_txn *actual, int check_cycle);
/* End of a run: EF_MS_OK when iface has nothing left queued, else
 * EF_MS_MISMATCH with a "missing transaction" message naming the first one. */
int ef_mstream_expect_done(ef_mstream *m, int iface);

/* The last error's or mismatch's text ("" if none); valid until the next call
 * on the handle.  Errors of ef_mstream_cmd name the command's number (from 1)
 * and op. */
const char *ef_mstream_message(const ef_mstream *m);

/* Commands fed so far (accepted ones). */
uint64_t ef_mstream_commands(const ef_mstream *m);
/* After FRAME_END: 1 and the frame's length in cycles (one past its last
 * transfer, as `cycles` in manifest.json); 0 while a frame is open or before
 * the first. */
int ef_mstream_frame_cycles(const ef_mstream *m, uint64_t *cycles);
/* The frame buffer as the model has blended it so far (premultiplied RGBA8,
 * all zero at FRAME), or NULL before the first FRAME. */
const ef_image *ef_mstream_frame(const ef_mstream *m);

/* "name=value ..." of t's fields, as edgeflag check prints them (signed
 * fields in decimal, unsigned ones of 32 bits or more in hex, the rest in
 * decimal), a `*` after each field that differs from other (may be NULL).
 * Returns the length it needed (snprintf's convention). */
int ef_mstream_format(const ef_txn *t, const ef_txn *other, char *buf, size_t size);

#ifdef __cplusplus
}
#endif

#endif /* EF_MODEL_STREAM_H */
