/*
 * plotter.c - the edge plotter (docs/spec.md section 6.1): for every active
 * edge and every sample row of the current pixel row, one flag into the
 * scanline buffer at pixel floor((x + off[s]) / 256), clamped to [0, W], then
 * one exact DDA step.  This is the hardware's one-edge-row-per-cycle loop.
 *
 * The even-odd buffer takes an XOR of the sample's bit; the non-zero buffer
 * adds the edge direction to the sample's 7-bit lane of a packed word.
 *
 * EF_MUTATION (test builds only) injects known bugs so the oracle test can
 * prove that it catches them: 1 = one wrong n-rooks offset, 2 = an off-by-one
 * in the x rounding (crossings up to 1/256 px left of a sample are missed).
 */
#include "internal.h"

#ifndef EF_MUTATION
#define EF_MUTATION 0
#endif

static inline int32_t plot_cell(const ef_ctx *ctx, int32_t x, int s)
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
static inline void dda_step(int32_t *x, int32_t *e, const ef_edge *E)
{
    *x += E->qs;
    *e += E->rs;
    if (*e >= E->dy) {
        *e -= E->dy;
        *x += 1;
    }
}

void ef_plot_evenodd(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax)
{
    const int32_t base = row * ctx->samples;
    const int32_t end = base + ctx->samples - 1;
    uint32_t *cells = ctx->eo_cells;
    int32_t lo = *xmin, hi = *xmax;
    for (uint32_t k = 0; k < ctx->naet; k++) {
        ef_edge *E = &ctx->edges[ctx->aet[k]];
        int32_t x = E->x, e = E->e, r = E->r;
        int32_t last = E->r1 < end ? E->r1 : end;
        for (; r <= last; r++) {
            int s = r - base;
            int32_t q = plot_cell(ctx, x, s);
            cells[q] ^= UINT32_C(1) << s;
            if (q < lo)
                lo = q;
            if (q > hi)
                hi = q;
            dda_step(&x, &e, E);
        }
        E->x = x;
        E->e = e;
        E->r = r;
    }
    *xmin = lo;
    *xmax = hi;
}

void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t *xmin, int32_t *xmax)
{
    const int32_t base = row * ctx->samples;
    const int32_t end = base + ctx->samples - 1;
    const int words = ctx->samples / 8;
    uint64_t *cells = ctx->nz_cells;
    int32_t lo = *xmin, hi = *xmax;
    uint64_t overflows = 0;
    for (uint32_t k = 0; k < ctx->naet; k++) {
        ef_edge *E = &ctx->edges[ctx->aet[k]];
        int32_t x = E->x, e = E->e, r = E->r;
        int32_t last = E->r1 < end ? E->r1 : end;
        /* +1 or -1 modulo 128 in one lane (spec 6.3). */
        const uint64_t d = E->dir > 0 ? 0x01u : 0x7Fu;
        const uint64_t edge_limit = E->dir > 0 ? 0x3Fu : 0x40u;  /* 63 + 1 or -64 - 1 overflows */
        for (; r <= last; r++) {
            int s = r - base;
            int32_t q = plot_cell(ctx, x, s);
            uint64_t *w = &cells[(size_t)q * (size_t)words + (size_t)(s >> 3)];
            unsigned sh = 8u * (unsigned)(s & 7);
            overflows += ((*w >> sh) & 0x7Fu) == edge_limit;
            *w = (*w + (d << sh)) & EF_LANES7;
            if (q < lo)
                lo = q;
            if (q > hi)
                hi = q;
            dda_step(&x, &e, E);
        }
        E->x = x;
        E->e = e;
        E->r = r;
    }
    ctx->diag.winding_overflows += overflows;
    *xmin = lo;
    *xmax = hi;
}
