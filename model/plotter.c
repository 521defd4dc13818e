/*
 * plotter.c - the edge plotter (docs/spec.md section 6.1): for every active
 * edge and every sample row of the current pixel row, one flag into the
 * scanline buffer at pixel floor((x + off[s]) / 256), clamped to [0, W], then
 * one exact DDA step.  This is the hardware's one-edge-row-per-cycle loop.
 *
 * The even-odd buffer takes an XOR of the sample's bit; the non-zero buffer
 * adds the edge direction to the sample's 7-bit lane of a packed word.  The
 * occupancy map gets a bit for every cell that may have been marked, so the
 * filler visits only those (mask tracking, word at a time); a range of cells
 * that contains every marked one bounds the row (edge tracking).  A row's
 * new edges are activated (their DDA started, ef_dda_start) as they are
 * plotted, after the edges already active, and edges past their last sample
 * row leave the AET in the same pass: the AET order of spec 6 is kept.
 *
 * Speed, with exactly the results of the plain loop (efbench hash, and the
 * oracle, check every bit):
 * - N is a compile-time constant per instance, and a full row of N sample
 *   rows is a fixed-count loop unrolled into N plots with constant bits
 *   (the paper's 3.8 D); an exact slope (rs = 0) steps without the carry;
 * - edges with both end points in [1, 256W] (EF_PLOT_INSIDE, EF_PLOT_STEEP)
 *   take x only in [0, 256W - 1], so the clamp of 6.1 cannot act and is
 *   skipped, and the shifts are of non-negative values;
 * - the occupancy bits of a full row of a STEEP edge (less than 6 px of
 *   movement per row) are set once for its cell range, and edge tracking of
 *   STEEP and INSIDE edges widens an x range once per edge and row, turned
 *   into cells with a margin at the end of the row: supersets of the marked
 *   cells, which change no span (unmarked cells are zero, spec 7.1);
 * - data-dependent choices (an edge's end, the DDA carry, the floor of a
 *   division) are computed without branches, which would mispredict;
 * - the winding-overflow diagnostic (spec 6.4) is only evaluated on rows
 *   with 64 or more active edges: with at most 63 edges no counter can leave
 *   [-64, 63], so the count is the same.
 *
 * EF_MUTATION (test builds only) injects known bugs so the oracle test can
 * prove that it catches them: 1 = one wrong n-rooks offset, 2 = an off-by-one
 * in the x rounding (crossings up to 1/256 px left of a sample are missed).
 * Mutated offsets may leave [1, 255], so mutant builds always clamp.
 */
#include "internal.h"

#ifndef EF_MUTATION
#define EF_MUTATION 0
#endif
#define EF_FAST_PATH (EF_MUTATION == 0)

#if defined(__GNUC__)
#define EF_ALWAYS_INLINE inline __attribute__((always_inline))
#define EF_UNROLL _Pragma("GCC unroll 32")
#else
#define EF_ALWAYS_INLINE inline
#define EF_UNROLL
#endif

/* The plot offsets of this context (spec 6.1), with the test mutations. */
static EF_ALWAYS_INLINE void load_offsets(const ef_ctx *ctx, int32_t *off, const int NS)
{
    for (int s = 0; s < NS; s++) {
        off[s] = ctx->off[s];
#if EF_MUTATION == 1
        if (s == 3)
            off[s] += ctx->h;
#elif EF_MUTATION == 2
        off[s] -= 1;
#endif
    }
}

/* One exact DDA step (spec 5 step 5 / 6.1).  Branch-free carry: the error
 * term's overflow is data-dependent and would mispredict about half the time. */
#define DDA_STEP()                                \
    do {                                          \
        const int32_t ee_ = e + rs, et_ = ee_ - dy; \
        const int32_t carry_ = et_ >= 0;          \
        e = carry_ ? et_ : ee_;                   \
        x += qs + carry_;                         \
    } while (0)

/* Edge tracking per edge and row rather than per sample: the DDA's x moves
 * monotonically from xa to xb over the row's samples and every offset lies in
 * [1, 255], so every plotted cell lies in [floor(min/256), floor(max/256) + 1]
 * (clamped).  The filler only needs a range that contains every marked cell. */
static EF_ALWAYS_INLINE void track(const ef_ctx *ctx, int32_t xa, int32_t xb, int32_t *lo, int32_t *hi)
{
    int32_t a = xa < xb ? xa : xb, b = xa < xb ? xb : xa;
    int32_t qa = ef_clamp_i32(ef_asr_i32(a, EF_DEV_FRAC_BITS), 0, ctx->width);
    int32_t qb = ef_clamp_i32(ef_asr_i32(b, EF_DEV_FRAC_BITS) + 1, 0, ctx->width);
    *lo = qa < *lo ? qa : *lo;
    *hi = qb > *hi ? qb : *hi;
}

/* Marks sample s of cell q (6.2 / 6.3) and its occupancy bit.  Non-zero:
 * dl is the lane increment (0x01 or 0x7F) already shifted to lane s & 7, and
 * limit the old lane value that overflows (63 + 1, -64 - 1).  For N = 8 a
 * cell is one word, so the word index (s >> 3) & (N/8 - 1) folds to 0. */
#define PLOT_CELL(q, s)                                                                           \
    do {                                                                                          \
        if (NZ) {                                                                                 \
            uint64_t *w_ = &nz[(size_t)(q) * (size_t)(NS / 8) + (size_t)(((s) >> 3) & (NS / 8 - 1))]; \
            const uint64_t old_ = *w_;                                                            \
            if (check)                                                                            \
                *overflows += ((old_ >> (8u * (unsigned)((s) & 7))) & 0x7Fu) == limit;            \
            *w_ = (old_ + dl) & EF_LANES7;                                                        \
            dl = dl << 8 | dl >> 56;       /* next sample: next lane, wrapping to lane 0 */       \
        } else {                                                                                  \
            eo[q] ^= UINT32_C(1) << (s);                                                          \
        }                                                                                         \
        occ[(q) >> 6] |= UINT64_C(1) << ((q) & 63);                                               \
    } while (0)

/* PLOT_CELL without the occupancy bit (the caller marks a range). */
#define PLOT_CELL_NOOCC(q, s)                                                                     \
    do {                                                                                          \
        if (NZ) {                                                                                 \
            uint64_t *w_ = &nz[(size_t)(q) * (size_t)(NS / 8) + (size_t)(((s) >> 3) & (NS / 8 - 1))]; \
            const uint64_t old_ = *w_;                                                            \
            if (check)                                                                            \
                *overflows += ((old_ >> (8u * (unsigned)((s) & 7))) & 0x7Fu) == limit;            \
            *w_ = (old_ + dl) & EF_LANES7;                                                        \
            dl = dl << 8 | dl >> 56;                                                              \
        } else {                                                                                  \
            eo[q] ^= UINT32_C(1) << (s);                                                          \
        }                                                                                         \
    } while (0)

/* Occupancy bits for the cells [a, b], a <= b, b - a < 64. */
static EF_ALWAYS_INLINE void mark_occ_range(uint64_t *occ, uint32_t a, uint32_t b)
{
    const uint32_t wa = a >> 6, wb = b >> 6;
    const uint64_t ma = ~UINT64_C(0) << (a & 63), mb = ~UINT64_C(0) >> (63 - (b & 63));
    if (wa == wb) {
        occ[wa] |= ma & mb;
    } else {
        occ[wa] |= ma;
        occ[wb] |= mb;
    }
}

/* Plots sample rows s0..s1 (of this pixel row) of one edge, stepping its DDA
 * (*px, *pe).  Edge tracking: a CLAMP edge widens the cell range [*lo, *hi]
 * exactly; the others widen the range [*lox, *hix] of x values, which the
 * caller turns into cells with a margin of 6 and 7: a STEEP edge's cells lie
 * within that margin of its first x (it moves less than 6 px over the row),
 * an INSIDE edge's within 1 of its first and last plotted x. */
/* Full rows of STEEP edges at N >= 16 (no overflow check): the row's
 * samples are sorted into cells in registers and each cell is written once,
 * instead of one read-modify-write per sample (consecutive samples of a steep
 * edge hit the same cell: a store-to-load chain).  x moves monotonically, so
 * every cell lies in [a, b], a = floor(min x / 256), b = floor(max x / 256)
 * + 1, b - a <= 7 (less than 6 px of movement).  A sample's distance d from
 * the cell the edge starts at (a when x increases, b when it decreases:
 * b - q = floor((256b + 255 - v) / 256) for v = x + off) has 3 bits, kept as
 * three bit planes with bit s for sample s; the cell at distance k gets the
 * samples whose planes spell k.  Non-zero: a word's 8 samples become its
 * lanes' increments at once (lanes cannot carry into each other). */
static EF_ALWAYS_INLINE uint64_t spread_lanes(uint64_t m8)
{
    /* bit i of m8 (i < 8) -> 0x01 in lane i */
    return ((((m8 * UINT64_C(0x0101010101010101)) & UINT64_C(0x8040201008040201)) + EF_LANES7) & EF_PADS) >> 7;
}

static EF_ALWAYS_INLINE void steep_flush(ef_ctx *ctx, uint64_t p0, uint64_t p1, uint64_t p2, int32_t xa, int32_t xl,
                                         int32_t dir, int32_t flip, const int NS, const int NZ)
{
    const int32_t mn = xa < xl ? xa : xl, mx = xa < xl ? xl : xa;
    const uint32_t a = (uint32_t)mn >> EF_DEV_FRAC_BITS, b = ((uint32_t)mx >> EF_DEV_FRAC_BITS) + 1u; /* <= W */
    mark_occ_range(ctx->occ, a, b);
    const int32_t c0 = (int32_t)(flip ? b : a);                  /* flip = -1: x decreases */
    const uint64_t dirb = (uint64_t)((uint32_t)dir & 0x7Fu);
    const uint32_t nc = b - a + 1u;                              /* 2 .. 8 */
    const uint64_t full = NS == 32 ? UINT64_C(0xFFFFFFFF) : UINT64_C(0xFFFF);
    uint32_t *eo = ctx->eo_cells;
    uint64_t *nz = ctx->nz_cells;
#define STEEP_CELL(k)                                                                                   \
    do {                                                                                                \
        const uint64_t m_ = ~((p0 ^ (uint64_t)-(int64_t)((k) & 1)) | (p1 ^ (uint64_t)-(int64_t)(((k) >> 1) & 1)) | \
                              (p2 ^ (uint64_t)-(int64_t)(((k) >> 2) & 1))) & full;                      \
        const int32_t q_ = c0 + (((int32_t)(k) ^ flip) - flip);                                         \
        if (NZ) {                                                                                       \
            uint64_t *w_ = &nz[(size_t)q_ * (size_t)(NS / 8)];                                          \
            for (int wi_ = 0; wi_ < NS / 8; wi_++)                                                      \
                w_[wi_] = (w_[wi_] + spread_lanes((m_ >> (8 * wi_)) & 0xFFu) * dirb) & EF_LANES7;         \
        } else {                                                                                        \
            eo[q_] ^= (uint32_t)m_;                                                                     \
        }                                                                                               \
    } while (0)
    STEEP_CELL(0u);
    STEEP_CELL(1u);
    for (uint32_t k = 2; k < nc; k++)
        STEEP_CELL(k);
#undef STEEP_CELL
}

static EF_ALWAYS_INLINE void plot_edge_row(ef_ctx *ctx, const int32_t *off, int32_t *px, int32_t *pe, int32_t qs,
                                           int32_t rs, int32_t dy, int s0, int s1, int32_t dir, int32_t mode,
                                           int32_t *lo, int32_t *hi, int32_t *lox, int32_t *hix,
                                           uint64_t *overflows, const int NS, const int NZ, const int check)
{
    uint32_t *eo = ctx->eo_cells;
    uint64_t *nz = ctx->nz_cells;
    uint64_t *occ = ctx->occ;
    /* +1 or -1 modulo 128 in one lane (spec 6.3), at sample s0's lane. */
    uint64_t dl = (uint64_t)((uint32_t)dir & 0x7Fu) << (8u * ((unsigned)s0 & 7u));
    const uint64_t limit = dir > 0 ? 0x3Fu : 0x40u;
    (void)dl;
    (void)limit;
    (void)overflows;
    int32_t x = *px, e = *pe;
    const int32_t xa = x;
    if (EF_FAST_PATH && mode == EF_PLOT_STEEP && NS >= 16 && !check && s0 == 0 && s1 == NS - 1) {
        *lox = xa < *lox ? xa : *lox;
        *hix = xa > *hix ? xa : *hix;
        /* y = 256 d + fraction: v - 256a, or 256b + 255 - v = ~v + 256(b + 1),
         * as (v ^ flip) + adj.  x decreases over the row iff qs < 0. */
        const int32_t flip = -(int32_t)(qs < 0);
        const int32_t qa = (int32_t)((uint32_t)xa >> EF_DEV_FRAC_BITS);
        const int32_t adj = flip ? (qa + 2) * EF_DEV_ONE : -qa * EF_DEV_ONE;
        int32_t xl = x;
        uint64_t p0 = 0, p1 = 0, p2 = 0;
        if (rs == 0) {
            EF_UNROLL
            for (int s = 0; s < NS; s++) {
                const uint64_t t = (uint64_t)(uint32_t)(((x + off[s]) ^ flip) + adj) << s;
                p0 |= t & (UINT64_C(1) << (s + 8));
                p1 |= t & (UINT64_C(1) << (s + 9));
                p2 |= t & (UINT64_C(1) << (s + 10));
                xl = x;
                x += qs;
            }
        } else {
            EF_UNROLL
            for (int s = 0; s < NS; s++) {
                const uint64_t t = (uint64_t)(uint32_t)(((x + off[s]) ^ flip) + adj) << s;
                p0 |= t & (UINT64_C(1) << (s + 8));
                p1 |= t & (UINT64_C(1) << (s + 9));
                p2 |= t & (UINT64_C(1) << (s + 10));
                xl = x;
                DDA_STEP();
            }
        }
        steep_flush(ctx, p0 >> 8, p1 >> 9, p2 >> 10, xa, xl, dir, flip, NS, NZ);
    } else if (EF_FAST_PATH && mode == EF_PLOT_STEEP) {
        /* x in [0, 256W - 1]: q = (x + off) >> 8 in [0, W], no clamp. */
        *lox = xa < *lox ? xa : *lox;
        *hix = xa > *hix ? xa : *hix;
        if (s0 == 0 && s1 == NS - 1) {
            /* A full row, unrolled; its cells lie in [xa/256, xl/256 + 1]
             * (x moves monotonically), marked in the occupancy map at once.
             * An exact slope (rs = 0: vertical edges, among others) steps
             * without the carry. */
            int32_t xl = x;
            if (rs == 0) {
                EF_UNROLL
                for (int s = 0; s < NS; s++) {
                    const uint32_t q = (uint32_t)(x + off[s]) >> EF_DEV_FRAC_BITS;
                    PLOT_CELL_NOOCC(q, s);
                    xl = x;
                    x += qs;
                }
            } else {
                EF_UNROLL
                for (int s = 0; s < NS; s++) {
                    const uint32_t q = (uint32_t)(x + off[s]) >> EF_DEV_FRAC_BITS;
                    PLOT_CELL_NOOCC(q, s);
                    xl = x;
                    DDA_STEP();
                }
            }
            const uint32_t a = (uint32_t)(xa < xl ? xa : xl) >> EF_DEV_FRAC_BITS;
            const uint32_t b = ((uint32_t)(xa < xl ? xl : xa) >> EF_DEV_FRAC_BITS) + 1;   /* <= W */
            mark_occ_range(occ, a, b);
        } else {
            /* A partial row: s0..s1 only.  For N >= 16 (more samples a row)
             * the occupancy range is marked once, as for a full row; for
             * N = 8 a bit per sample costs less (measured). */
            int32_t xl = x;
            for (int s = s0; s <= s1; s++) {
                const uint32_t q = (uint32_t)(x + off[s]) >> EF_DEV_FRAC_BITS;
                if (NS >= 16)
                    PLOT_CELL_NOOCC(q, s);
                else
                    PLOT_CELL(q, s);
                xl = x;
                DDA_STEP();
            }
            if (NS >= 16) {
                const uint32_t a = (uint32_t)(xa < xl ? xa : xl) >> EF_DEV_FRAC_BITS;
                const uint32_t b = ((uint32_t)(xa < xl ? xl : xa) >> EF_DEV_FRAC_BITS) + 1;   /* <= W */
                mark_occ_range(occ, a, b);
            }
        }
    } else if (EF_FAST_PATH && mode == EF_PLOT_INSIDE) {
        int32_t xl = x;
        for (int s = s0; s <= s1; s++) {
            const uint32_t q = (uint32_t)(x + off[s]) >> EF_DEV_FRAC_BITS;
            PLOT_CELL(q, s);
            xl = x;
            DDA_STEP();
        }
        /* the first and last plotted x, both in [0, 256W - 1] */
        const int32_t a = xa < xl ? xa : xl, b = xa < xl ? xl : xa;
        *lox = a < *lox ? a : *lox;
        *hix = b > *hix ? b : *hix;
    } else {
        const int32_t W = ctx->width;
        int32_t xl = x;
        for (int s = s0; s <= s1; s++) {
            const int32_t q = ef_clamp_i32(ef_asr_i32(x + off[s], EF_DEV_FRAC_BITS), 0, W);
            PLOT_CELL(q, s);
            xl = x;
            DDA_STEP();
        }
        track(ctx, xa, xl, lo, hi);
    }
    *px = x;
    *pe = e;
}

static EF_ALWAYS_INLINE void plot_row(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax,
                                      const int NS, const int NZ, const int check)
{
    const int32_t base = row * NS;
    const int32_t end = base + NS - 1;
    ef_edge *edges = ctx->edges;
    int32_t *aet = ctx->aet;
    const uint32_t naet = ctx->naet;
    int32_t off[32];
    load_offsets(ctx, off, NS);
    int32_t lo = *xmin, hi = *xmax, lox = INT32_MAX, hix = -1;
    uint64_t overflows = 0;
    uint32_t kept = 0;
    /* Edges active from earlier rows: they start this row at its first
     * sample row. */
    for (uint32_t k = 0; k < naet; k++) {
        const int32_t idx = aet[k];
        ef_edge *E = &edges[idx];
        int32_t x = E->x, e = E->e;
        const int32_t r1 = E->r1;
        const int s1 = (r1 < end ? r1 : end) - base;
        plot_edge_row(ctx, off, &x, &e, E->qs, E->rs, E->dy, 0, s1, E->dir, E->mode, &lo, &hi, &lox, &hix,
                      &overflows, NS, NZ, check);
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
        ef_dda_start(E, h, c, w256, NS - 1);
        int32_t x = E->x, e = E->e;
        const int32_t r1 = E->r1;
        const int s1 = (r1 < end ? r1 : end) - base;
        plot_edge_row(ctx, off, &x, &e, E->qs, E->rs, E->dy, E->r0 - base, s1, E->dir, E->mode, &lo, &hi, &lox,
                      &hix, &overflows, NS, NZ, check);
        E->x = x;
        E->e = e;
        aet[kept] = idx;
        kept += r1 > end;
        idx = E->next;
    }
    ctx->naet = kept;
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
    case 8: plot_row(ctx, row, head, xmin, xmax, 8, 0, 0); break;
    case 16: plot_row(ctx, row, head, xmin, xmax, 16, 0, 0); break;
    default: plot_row(ctx, row, head, xmin, xmax, 32, 0, 0); break;
    }
}

void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax)
{
    const int check = ctx->naet_row >= 64;
    switch (ctx->samples * 2 + check) {
    case 16: plot_row(ctx, row, head, xmin, xmax, 8, 1, 0); break;
    case 17: plot_row(ctx, row, head, xmin, xmax, 8, 1, 1); break;
    case 32: plot_row(ctx, row, head, xmin, xmax, 16, 1, 0); break;
    case 33: plot_row(ctx, row, head, xmin, xmax, 16, 1, 1); break;
    case 64: plot_row(ctx, row, head, xmin, xmax, 32, 1, 0); break;
    default: plot_row(ctx, row, head, xmin, xmax, 32, 1, 1); break;
    }
}
