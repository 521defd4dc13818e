/*
 * plotter.c - the edge plotter (docs/spec.md section 6): for every pixel
 * row, every active edge in AET order, and every sample row r of the pixel
 * row that the edge crosses (r0 <= r <= r1), one flag into the scanline
 * buffer, then one exact DDA step (spec 6.1):
 *
 *     s = r mod N;  q = clamp(floor((x + off[s]) / 256), 0, W)
 *     mark cell q for sample s      (even-odd: XOR, 6.2; non-zero: +-1, 6.3)
 *     x += qs;  e += rs;  if (e >= dY) { e -= dY; x += 1 }
 *
 * This is the hardware's one-edge-row-per-cycle loop, and plot_edge_row's
 * last branch is it, sample by sample.  Around it, for the filler (spec 7.1):
 * the occupancy map gets a bit for every cell that may have been marked, so
 * the filler visits only those (mask tracking, a word at a time), and a
 * range of cells that contains every marked one bounds the row (edge
 * tracking).  A row's new edges are activated (their DDA started,
 * ef_dda_start) as they are plotted, after the edges already active, and
 * edges past their last sample row leave the AET in the same pass: the AET
 * order of spec 6 is kept.  Non-zero rows may count winding overflows
 * (6.4), sample by sample.
 *
 * Speed devices, each with exactly the results of the loop above, sit
 * behind one switch, EF_PLOT_FAST (plotter.h; 0 = the plain loop for every
 * edge, and in mutant builds): plotter_fast.h (unrolled rows, no clamp where
 * it cannot act, ranges instead of bits), plotter_sse2.h (a whole row of a
 * nearly vertical edge at once), plotter_crowd.h (the overflow count only on
 * rows that can need it).  Their measurements: bench/results/PROFILE.md.
 */
#include "plotter.h"

/* ---------------------------------------------------- the spec's steps */

/* The plot offsets of this context (spec 6.1), with the test mutations. */
static EF_ALWAYS_INLINE void load_offsets(const ef_ctx *ctx, int32_t *off, const int NS)
{
    for (int s = 0; s < NS; s++)
        off[s] = ef_plot_mutate_offset(ctx->off[s], s, ctx->h);
}

/* One exact DDA step (spec 5 step 5 / 6.1).  Branch-free carry: the error
 * term's overflow is data-dependent and would mispredict about half the time.
 * With rsd = rs - dy and qs1 = qs + 1 (per edge): t = e + rs - dy, carry =
 * t >= 0; neg = -1 without a carry, 0 with one; e = t + (dy & neg) and
 * x += qs + carry = qs1 + neg, so the error term's chain is one add, and no
 * compare or select is needed.  |t| < 2^24. */
#define DDA_STEP() \
    do { \
        const int32_t t_ = e + rsd; \
        const int32_t neg_ = -(int32_t)((uint32_t)t_ >> 31); \
        e = t_ + (dy & neg_); \
        x += qs1 + neg_; \
    } while (0)

/* Sample s's even-odd bit is `bit` in the caller's loop: in the plain loop
 * a register doubled every sample (a shift by the variable s costs two
 * instructions); a constant 1 << s in the unrolled rows.  64 bits: no bit is
 * shifted out after sample 31. */
#define EO_BIT(s) ((void)(s), (uint32_t)bit)

/* Marks sample s of cell q (6.2 / 6.3) and its occupancy bit.  Non-zero:
 * the counter of sample s is a byte (ef_nz_lane_byte), to which d8 (0x01 or
 * 0xFF) is added modulo 256: its low 7 bits are the spec's lane modulo 128
 * and its top bit is the pad bit, which the filler masks off when it reads
 * the word (fill_nonzero.c).  One byte add replaces the word's load, add,
 * mask, store and the lane rotation, and consecutive samples of an edge touch
 * different bytes, so no store feeds the next load.  limit is the old 7-bit
 * value that overflows (63 for +1, 64 for -1; spec 6.4). */
#define PLOT_CELL_NOOCC(q, s) \
    do { \
        if (NZ) { \
            uint8_t *b_ = &nzb[(size_t)(q) * (size_t)NS + ef_nz_lane_byte((unsigned)(s))]; \
            if (check) \
                *overflows += (*b_ & 0x7Fu) == limit; \
            *b_ = (uint8_t)(*b_ + d8); \
        } else { \
            eo[q] ^= EO_BIT(s); \
        } \
    } while (0)

#define PLOT_CELL(q, s) \
    do { \
        PLOT_CELL_NOOCC(q, s); \
        occ[(q) >> 6] |= UINT64_C(1) << ((q)&63); \
    } while (0)

/* Edge tracking per edge and row rather than per sample: the filler only
 * needs a range that contains every marked cell. */
static EF_ALWAYS_INLINE void track(const ef_ctx *ctx, int32_t xa, int32_t xb, int32_t *lo, int32_t *hi)
{
    int32_t qa, qb;
    cells_of_x_range(ctx->width, xa, xb, &qa, &qb);
    *lo = qa < *lo ? qa : *lo;
    *hi = qb > *hi ? qb : *hi;
}

#if EF_PLOT_FAST
#include "plotter_fast.h"
#endif

/* ------------------------------------------------------------ one edge */

/* Plots sample rows s0..s1 (of this pixel row) of one edge, stepping its DDA
 * (*px, *pe) to the next pixel row, and widens the cell range [*lo, *hi]
 * that holds every cell it marks (edge tracking).  The last branch is the
 * spec's loop: every edge of the plain build (EF_PLOT_FAST 0) takes it, and
 * the CLAMP edges (an end point outside [1, 256W]) of the fast one; the
 * branches before it are plotter_fast.h's and plotter_sse2.h's. */
static EF_ALWAYS_INLINE void plot_edge_row(ef_ctx *ctx, const int32_t *off, int32_t *px, int32_t *pe, int32_t qs,
                                           int32_t rs, int32_t dx, int32_t dy, int s0, int s1, int32_t dir,
                                           int32_t mode, int32_t *lo, int32_t *hi, int32_t *lox, int32_t *hix,
                                           uint64_t *overflows, const int NS, const int NZ, const int check,
                                           const int first)
{
#if EF_MASK_ROWS
    if (MASK_ROWS(NS, check) && mode == EF_PLOT_MASK) {
        plot_mask_row(ctx, px, pe, dx, dy, qs, rs, dir, s0, s1, lo, hi, NS, NZ);
        return;
    }
#else
    (void)dx;
#endif
    uint32_t *eo = ctx->eo_cells;
    uint8_t *nzb = (uint8_t *)ctx->nz_cells;
    uint64_t *occ = ctx->occ;
    const uint8_t d8 = (uint8_t)dir; /* +1 or -1 modulo 256 */
    const unsigned limit = dir > 0 ? 0x3Fu : 0x40u;
    (void)d8;
    (void)limit;
    (void)overflows;
    int32_t x = *px, e = *pe;
    const int32_t xa = x;
    const int32_t rsd = rs - dy, qs1 = qs + 1;
#if EF_PLOT_FAST
    if (mode >= EF_PLOT_STEEP) { /* MASK edges too, on rows that count overflows */
        PLOT_STEEP_ROW();
    } else if (mode == EF_PLOT_INSIDE) {
        PLOT_INSIDE_ROW();
    } else
#else
    (void)mode;
    (void)lox;
    (void)hix;
    (void)first;
#endif
    {
        /* spec 6.1, one sample row at a time */
        const int32_t W = ctx->width;
        int32_t xl = x;
        uint64_t bit = UINT64_C(1) << s0;
        for (int s = s0; s <= s1; s++) {
            const int32_t q = ef_clamp_i32(ef_asr_i32(x + off[s], EF_DEV_FRAC_BITS), 0, W);
            PLOT_CELL(q, s);
            bit <<= 1;
            xl = x;
            DDA_STEP();
        }
        track(ctx, xa, xl, lo, hi);
    }
    *px = x;
    *pe = e;
}

/* ------------------------------------------------------------ one row */

/* Plots pixel row `row`.  check: count winding overflows (spec 6.4) per
 * sample.  crowd: instead, save the AET's state first (ctx->aet_saved) and
 * count per cell how many edges may plot there (ctx->crowd), so that
 * ef_plot_nonzero can tell whether the row needs the check at all
 * (plotter_crowd.h; only in EF_PLOT_FAST builds). */
static EF_ALWAYS_INLINE void plot_row(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax,
                                      const int NS, const int NZ, const int check, const int crowd)
{
    const int32_t base = row * NS;
    const int32_t end = base + NS - 1;
    ef_edge *edges = ctx->edges;
    int32_t *aet = ctx->aet;
    const uint32_t naet = ctx->naet;
    int32_t off[EF_SAMPLES_MAX];
    load_offsets(ctx, off, NS);
    int32_t lo = *xmin, hi = *xmax, lox = INT32_MAX, hix = -1;
    uint64_t overflows = 0;
    uint32_t kept = 0;
    int32_t *const crowd_d = ctx->crowd;
    ef_aet_saved *const saved = ctx->aet_saved;
    const int32_t W = ctx->width;
    int32_t crowd_lo = W + 1, crowd_hi = 0;
    /* Edges active from earlier rows: they start this row at its first
     * sample row. */
    for (uint32_t k = 0; k < naet; k++) {
        const int32_t idx = aet[k];
        ef_edge *E = &edges[idx];
        int32_t x = E->x, e = E->e;
        const int32_t r1 = E->r1;
        const int s1 = (r1 < end ? r1 : end) - base;
        if (crowd)
            saved[k] = (ef_aet_saved){ idx, x, e };
        plot_edge_row(ctx, off, &x, &e, E->qs, E->rs, E->dx, E->dy, 0, s1, E->dir, E->mode, &lo, &hi, &lox, &hix,
                      &overflows, NS, NZ, check, 0);
        if (crowd)
            crowd_add(crowd_d, W, E->x, x, &crowd_lo, &crowd_hi); /* x is monotonic: first plot to past the last */
        /* Still active below this row: stays, in AET order.  Branch-free:
         * whether an edge ends here is data, and would mispredict. */
        E->x = x;
        E->e = e;
        aet[kept] = idx;
        kept += r1 > end;
    }
    /* This row's new edges, in input order: their DDA starts here. */
    const int32_t h = ctx->h, c = ctx->c, w256 = ctx->width * EF_DEV_ONE;
    for (int32_t idx = head; idx >= 0;) {
        ef_edge *E = &edges[idx];
        ef_dda_start(E, h, c, w256, NS - 1, MASK_ROWS(NS, check));
        int32_t x = E->x, e = E->e;
        const int32_t r1 = E->r1;
        const int s1 = (r1 < end ? r1 : end) - base;
        plot_edge_row(ctx, off, &x, &e, E->qs, E->rs, E->dx, E->dy, E->r0 - base, s1, E->dir, E->mode, &lo, &hi, &lox,
                      &hix, &overflows, NS, NZ, check, 1);
        if (crowd)
            crowd_add(crowd_d, W, E->x, x, &crowd_lo, &crowd_hi);
        E->x = x;
        E->e = e;
        aet[kept] = idx;
        kept += r1 > end;
        idx = E->next;
    }
    ctx->naet = kept;
    if (crowd) {
        ctx->crowd_lo = crowd_lo;
        ctx->crowd_hi = crowd_hi;
    }
    if (NZ)
        ctx->diag.winding_overflows += overflows;
    if (hix >= 0) {
        /* STEEP and INSIDE edges: x in [0, 256W - 1], cells within
         * [x/256 - 6, x/256 + 7] of the x's tracked (clamped to [0, W]). */
        const int32_t a = (int32_t)((uint32_t)lox >> EF_DEV_FRAC_BITS) - 6;
        const int32_t b = (int32_t)((uint32_t)hix >> EF_DEV_FRAC_BITS) + 7;
        lo = a < lo ? (a < 0 ? 0 : a) : lo;
        hi = b > hi ? (b > ctx->width ? ctx->width : b) : hi;
    }
    *xmin = lo;
    *xmax = hi;
}

void ef_plot_evenodd(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax)
{
    switch (ctx->samples) {
    case 8: plot_row(ctx, row, head, xmin, xmax, 8, 0, 0, 0); break;
    case 16: plot_row(ctx, row, head, xmin, xmax, 16, 0, 0, 0); break;
    default: plot_row(ctx, row, head, xmin, xmax, 32, 0, 0, 0); break;
    }
}

#include "plotter_crowd.h"

#define PLOT_NZ(check, crowd) \
    do { \
        switch (ctx->samples) { \
        case 8: plot_row(ctx, row, head, xmin, xmax, 8, 1, check, 0); break; \
        case 16: plot_row(ctx, row, head, xmin, xmax, 16, 1, check, crowd); break; \
        default: plot_row(ctx, row, head, xmin, xmax, 32, 1, check, crowd); break; \
        } \
    } while (0)

/* The winding-overflow count (spec 6.4) needs a test per sample, but only
 * where a counter can leave [-64, 63]: it takes one plot per edge crossing
 * its sample row in its cell, so it needs 64 such edges.  Rows with fewer
 * active edges are plotted without the test.  At N = 16 and 32 a crowded
 * row (64 or more) is plotted without it too, counting per cell the edges
 * that may plot there (crowd_add); only if a cell has 64 is the plot undone
 * and redone with the test, so the count is the same (text set as one
 * compound path has rows of hundreds of edges and at most about ten in a
 * cell).  At N = 8 (few samples an edge-row) the count costs more than the
 * test it saves (PROFILE.md), and crowded rows take the test; so does the
 * plain build (EF_PLOT_FAST 0). */
void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax)
{
    if (ctx->naet_row < 64) {
        PLOT_NZ(0, 0);
        return;
    }
    if (ctx->samples == 8 || !EF_PLOT_FAST) {
        PLOT_NZ(1, 0);
        return;
    }
    const int32_t xmin0 = *xmin, xmax0 = *xmax;
    const uint32_t naet = ctx->naet;
    PLOT_NZ(0, 1);
    if (crowd_most(ctx) < 64)
        return;
    crowd_undo(ctx, naet, *xmin, *xmax);
    *xmin = xmin0;
    *xmax = xmax0;
    if (EF_MASK_ROWS)
        mask_demote_aet(ctx);
    PLOT_NZ(1, 0);
}
