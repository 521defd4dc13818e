/*
 * plotter.c - the edge plotter (docs/spec.md section 6.1): for every active
 * edge and every sample row of the current pixel row, one flag into the
 * scanline buffer at pixel floor((x + off[s]) / 256), clamped to [0, W], then
 * one exact DDA step.  This is the hardware's one-edge-row-per-cycle loop.
 *
 * The even-odd buffer takes an XOR of the sample's bit; the non-zero buffer
 * adds the edge direction to the sample's 7-bit lane of a packed word.  Each
 * marked cell also sets its bit in the occupancy map, so the filler visits
 * only marked cells (mask tracking, word at a time); a range of cells that
 * contains every marked one bounds the row (edge tracking, see track()).
 *
 * Speed: the loops are specialised per sample count (N a compile-time
 * constant, so a full scanline of sample rows is a fixed-count loop the
 * compiler unrolls - the paper's 3.8 D), and the winding-overflow diagnostic
 * (spec 6.4) is only evaluated on rows with 64 or more active edges: with at
 * most 63 edges no counter can leave [-64, 63], so the count is the same.
 *
 * EF_MUTATION (test builds only) injects known bugs so the oracle test can
 * prove that it catches them: 1 = one wrong n-rooks offset, 2 = an off-by-one
 * in the x rounding (crossings up to 1/256 px left of a sample are missed).
 */
#include "internal.h"

#ifndef EF_MUTATION
#define EF_MUTATION 0
#endif

#if defined(__GNUC__)
#define EF_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define EF_ALWAYS_INLINE inline
#endif

static EF_ALWAYS_INLINE int32_t plot_cell(const ef_ctx *ctx, int32_t x, int s)
{
    int32_t off = ctx->off[s];
#if EF_MUTATION == 1
    if (s == 3)
        off += ctx->h;
#elif EF_MUTATION == 2
    off -= 1;
#endif
    int32_t q = ef_asr_i32(x + off, EF_DEV_FRAC_BITS);
    return ef_clamp_i32(q, 0, ctx->width);
}

/* One exact DDA step (spec 5 step 5 / 6.1). */
static EF_ALWAYS_INLINE void dda_step(int32_t *x, int32_t *e, const ef_edge *E)
{
    /* Branch-free carry: the error term's overflow is data-dependent and would
     * mispredict about half the time. */
    int32_t ee = *e + E->rs;
    int32_t carry = ee >= E->dy;
    *e = ee - (E->dy & -carry);
    *x += E->qs + carry;
}

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

static EF_ALWAYS_INLINE void mark_occ(uint64_t *occ, int32_t q)
{
    occ[q >> 6] |= UINT64_C(1) << (q & 63);
}

static EF_ALWAYS_INLINE void plot_evenodd(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax, const int NS)
{
    const int32_t base = row * NS;
    const int32_t end = base + NS - 1;
    uint32_t *cells = ctx->eo_cells;
    uint64_t *occ = ctx->occ;
    int32_t lo = *xmin, hi = *xmax;
    for (uint32_t k = 0; k < ctx->naet; k++) {
        ef_edge *E = &ctx->edges[ctx->aet[k]];
        int32_t x = E->x, e = E->e, xl = x;
        int s0 = E->r - base;
        int s1 = (E->r1 < end ? E->r1 : end) - base;
        for (int s = s0; s <= s1; s++) {
            int32_t q = plot_cell(ctx, x, s);
            cells[q] ^= UINT32_C(1) << s;
            mark_occ(occ, q);
            xl = x;
            dda_step(&x, &e, E);
        }
        track(ctx, E->x, xl, &lo, &hi);
        E->x = x;
        E->e = e;
        E->r = base + s1 + 1;
    }
    *xmin = lo;
    *xmax = hi;
}

static EF_ALWAYS_INLINE void plot_nonzero(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax, const int NS,
                                          const int check_overflow)
{
    const int32_t base = row * NS;
    const int32_t end = base + NS - 1;
    const int words = NS / 8;
    uint64_t *cells = ctx->nz_cells;
    uint64_t *occ = ctx->occ;
    int32_t lo = *xmin, hi = *xmax;
    uint64_t overflows = 0;
    for (uint32_t k = 0; k < ctx->naet; k++) {
        ef_edge *E = &ctx->edges[ctx->aet[k]];
        int32_t x = E->x, e = E->e, xl = x;
        int s0 = E->r - base;
        int s1 = (E->r1 < end ? E->r1 : end) - base;
        /* +1 or -1 modulo 128 in one lane (spec 6.3). */
        const uint64_t d = E->dir > 0 ? 0x01u : 0x7Fu;
        const uint64_t limit = E->dir > 0 ? 0x3Fu : 0x40u;   /* 63 + 1 or -64 - 1 overflows */
        for (int s = s0; s <= s1; s++) {
            int32_t q = plot_cell(ctx, x, s);
            uint64_t *w = &cells[(size_t)q * (size_t)words + (size_t)(s >> 3)];
            unsigned sh = 8u * (unsigned)(s & 7);
            if (check_overflow)
                overflows += ((*w >> sh) & 0x7Fu) == limit;
            *w = (*w + (d << sh)) & EF_LANES7;
            mark_occ(occ, q);
            xl = x;
            dda_step(&x, &e, E);
        }
        track(ctx, E->x, xl, &lo, &hi);
        E->x = x;
        E->e = e;
        E->r = base + s1 + 1;
    }
    ctx->diag.winding_overflows += overflows;
    *xmin = lo;
    *xmax = hi;
}

void ef_plot_evenodd(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax)
{
    switch (ctx->samples) {
    case 8: plot_evenodd(ctx, row, xmin, xmax, 8); break;
    case 16: plot_evenodd(ctx, row, xmin, xmax, 16); break;
    default: plot_evenodd(ctx, row, xmin, xmax, 32); break;
    }
}

void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax)
{
    const int check = ctx->naet >= 64;
    switch (ctx->samples * 2 + check) {
    case 16: plot_nonzero(ctx, row, xmin, xmax, 8, 0); break;
    case 17: plot_nonzero(ctx, row, xmin, xmax, 8, 1); break;
    case 32: plot_nonzero(ctx, row, xmin, xmax, 16, 0); break;
    case 33: plot_nonzero(ctx, row, xmin, xmax, 16, 1); break;
    case 64: plot_nonzero(ctx, row, xmin, xmax, 32, 0); break;
    default: plot_nonzero(ctx, row, xmin, xmax, 32, 1); break;
    }
}
