/*
 * trace.h - the timing model's state and its two halves (not installed):
 *   trace.c         enable, frames, commands, DEC and SETUP (cmd, edge, et_wr)
 *   trace_raster.c  the rows: ETM/AET/PLOT, SLB/FILL, COV (et_rd, plot,
 *                   span, pix), cycle by cycle as docs/microarch.md section 4
 *
 * When tracing is on, ef_fill runs this plain, cycle-stamped implementation of
 * the pipeline instead of the optimised blocks.  It uses the same edge setup,
 * edge table, DDA start, offsets, buffers and compositing arithmetic, so it
 * renders the same image and diagnostics (tests/unit/test_trace.c checks it on
 * every shared SVG: a second implementation of the plotter and fillers, in
 * the hardware's order, agreeing bit for bit with the fast one).
 */
#ifndef EF_TRACE_INTERNAL_H
#define EF_TRACE_INTERNAL_H

#include "ef_trace.h"
#include "internal.h"

typedef struct ef_trace {
    uint32_t mask; /* interfaces to report */
    ef_txn_fn sink;
    void *user;
    int in_frame;
    uint64_t cmd_next;                           /* earliest cycle of the next command */
    uint64_t end;                                /* one past the last transfer so far */
    uint16_t lsb[EF_IF_COUNT][EF_IF_MAX_FIELDS]; /* field positions */
    ef_schedule schedule;                        /* docs/microarch.md section 4 or 6 */
    uint8_t plotted[EF_MAX_CANVAS + 1];          /* overlap: the row's plotted cells (section 6) */
} ef_trace;

/* Reports one transfer of `iface` at `cycle` with field values v[] (in the
 * interface's field order; each cut to its width). */
void ef_trace_emit(ef_trace *tr, int iface, uint64_t cycle, const uint64_t *v);

/* trace.c: one command at the next command cycle (returns its cycle); whether
 * record E is the one edge setup made of edge a -> z. */
uint64_t ef_trace_command(ef_trace *tr, uint64_t op, uint64_t a, uint64_t b, uint64_t c, uint64_t d);
int ef_trace_record_of(const ef_edge *E, ef_point a, ef_point z);

/* trace_filter.c: the spec 10 options in the timing model (docs/microarch.md
 * section 5): ef_fill with the trace and the options on, and FRAME's c field. */
#define EF_L_FILT 4 /* weigh sweep visit -> pix: line read, adder tree, alpha, blend */
ef_status ef_trace_filter_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color);
uint64_t ef_trace_filter_bits(const ef_ctx *ctx);

/* trace.c: ef_fill with the trace on. */
ef_status ef_trace_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color);

/* trace_raster.c: rasterizes and composites the shape whose edges are set up
 * (rows row_min..row_max), starting at cycle t0; returns the cycle at which
 * the shape has drained (T_free).  `premul` is the premultiplied colour. */
uint64_t ef_trace_rows(ef_ctx *ctx, ef_image *img, ef_rule rule, const uint8_t premul[4], uint8_t alpha,
                       int32_t row_min, int32_t row_max, uint64_t t0);

#endif /* EF_TRACE_INTERNAL_H */
