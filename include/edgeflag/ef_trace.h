/*
 * ef_trace.h - the cycle-level transaction trace of the reference
 * microarchitecture (docs/microarch.md): every transfer at every interface
 * of the pipeline, stamped with the cycle at which the reference schedule
 * presents it.  `edgeflag vectors` turns the trace into test vectors and
 * `edgeflag check` compares an RTL's dumps against them.
 *
 * Tracing is off unless ef_trace_enable() was called; it never changes a
 * result (the traced ef_fill renders the same pixels and diagnostics as the
 * untraced one, tests/unit/test_trace.c), and when it is off the only cost is
 * one test per ef_fill call.  Only ef_fill is traced: the trace describes
 * the whole pipeline up to the blended pixel, so ef_rasterize (spans to a
 * callback) emits nothing.
 */
#ifndef EF_TRACE_H
#define EF_TRACE_H

#include <stdint.h>

#include "edgeflag.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The interfaces, in pipeline order (docs/microarch.md section 3). */
typedef enum ef_iface {
    EF_IF_CMD = 0, /* host -> DEC: commands */
    EF_IF_SEG,     /* DEC -> SETUP: polygon edges (`seg`; `edge` is a Verilog keyword) */
    EF_IF_ET_WR,   /* SETUP -> ETM: edge records */
    EF_IF_ET_RD,   /* ETM -> AET: activations */
    EF_IF_PLOT,    /* PLOT -> SLB: one sample of one edge */
    EF_IF_SPAN,    /* FILL -> COV: coverage spans */
    EF_IF_PIX,     /* COV -> memory: blended pixels */
    EF_IF_COUNT
} ef_iface;
#define EF_IF_ALL ((1u << EF_IF_COUNT) - 1u)

#define EF_IF_MAX_FIELDS 10
#define EF_TXN_WORDS 4   /* payload up to 256 bits */
#define EF_CYCLE_BITS 48 /* cycle stamps are < 2^48 */

/* Schedule latencies (docs/microarch.md sections 4 and 6): the one source of
 * each, shared by both schedules. */
#define EF_L_DEC 1    /* cmd -> seg */
#define EF_L_SETUP 33 /* seg -> et_wr: 2 + 30 divider stages + 1 */
#define EF_L_COV 3    /* span accepted (overlap: started) -> first pix */
#define EF_L_PLOT 2   /* a row's last et_rd cycle (or its start, without one) -> its first plot: PLOT's two registers */
#define EF_L_REC 1    /* a row with new edges: the AET's register of the last record, before the first plot */
#define EF_SPANQ 16   /* overlap schedule: spans COV's queue holds (section 6) */

/* The schedule the trace stamps: the reference one (docs/microarch.md
 * section 4, the default) or the overlapped one (section 6): the same
 * transactions in the same order per interface, at other cycles. */
typedef enum ef_schedule { EF_SCHEDULE_REFERENCE = 0, EF_SCHEDULE_OVERLAP = 1 } ef_schedule;

/* Commands (the `op` field of cmd). */
enum { EF_OP_FRAME = 1, EF_OP_SHAPE = 2, EF_OP_EDGE = 3, EF_OP_SHAPE_END = 4, EF_OP_FRAME_END = 5 };
/* "FRAME" .. "FRAME_END" (docs/microarch.md 3.1), NULL for another op. */
EF_API const char *ef_op_name(int op);

typedef struct ef_field_desc {
    const char *name;
    uint8_t width;     /* bits, 1..32 */
    uint8_t is_signed; /* two's complement */
} ef_field_desc;

typedef struct ef_iface_desc {
    const char *name;      /* "plot" */
    const char *from, *to; /* producing and consuming block */
    uint16_t width;        /* payload bits: the sum of the field widths */
    uint8_t nfields;
    ef_field_desc field[EF_IF_MAX_FIELDS]; /* most significant first */
} ef_iface_desc;

/* NULL when iface is out of range. */
EF_API const ef_iface_desc *ef_iface_get(int iface);
/* The interface called `name`, or -1.  The old name `edge` (of `seg`) is read
 * as an alias. */
EF_API int ef_iface_find(const char *name);

/* One transfer.  The payload is the concatenation of the fields, most
 * significant first, as one little number: bit 0 is bit 0 of w[0]. */
typedef struct ef_txn {
    uint64_t cycle;
    uint64_t w[EF_TXN_WORDS];
    uint8_t iface;
} ef_txn;
/* Field k of t (raw bits, zero-extended), and sign-extended when the field
 * is signed. */
EF_API uint64_t ef_txn_field(const ef_txn *t, unsigned k);
EF_API int64_t ef_txn_field_value(const ef_txn *t, unsigned k);
/* Stores the low width bits of v into field k. */
EF_API void ef_txn_set_field(ef_txn *t, unsigned k, uint64_t v);

/* Receives every transaction of the enabled interfaces.  Within one
 * interface transactions arrive in cycle order; across interfaces they do
 * not (a consumer that needs one global order merges them). */
typedef void (*ef_txn_fn)(void *user, const ef_txn *t);

/* Enables tracing of the interfaces in iface_mask (bit i = ef_iface i) to
 * sink, or disables it (sink NULL).  EF_ERR_ARG for a bad mask. */
EF_API ef_status ef_trace_enable(ef_ctx *ctx, uint32_t iface_mask, ef_txn_fn sink, void *user);
/* Chooses the schedule of the frames traced from now on (kept until changed).
 * EF_ERR_ARG with tracing off or for another value.  The overlap schedule
 * covers the box filter without subpixel offsets: a traced ef_fill with the
 * spec 10 options on under it returns EF_ERR_UNSUPPORTED. */
EF_API ef_status ef_trace_set_schedule(ef_ctx *ctx, ef_schedule schedule);
/* Starts a frame: the FRAME command at cycle 0 (the clock restarts). */
EF_API ef_status ef_trace_frame_begin(ef_ctx *ctx);
/* Ends it: the FRAME_END command; *cycles (if not NULL) receives the
 * frame's length, one past the last transfer's cycle. */
EF_API ef_status ef_trace_frame_end(ef_ctx *ctx, uint64_t *cycles);

#ifdef __cplusplus
}
#endif

#endif /* EF_TRACE_H */
