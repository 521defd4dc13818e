/*
 * fill_evenodd.c - the even-odd filler (docs/spec.md section 7.2).
 *
 * XOR-accumulates the flag cells left to right: the running value is the
 * coverage mask, one bit per sample.  Mask tracking: a zero cell leaves the
 * mask unchanged, so runs between non-zero cells become one span each (a
 * solid span when the mask is full); every cell is cleared as it is read.
 * The occupancy map (one bit per cell, set by the plotter for every cell it
 * may have marked) lets the scan jump from candidate cell to candidate cell a
 * 64-bit word at a time; other cells are zero and change nothing, and so do
 * candidates that turn out zero, so the spans are exactly those of a
 * cell-by-cell scan from xmin to xmax.
 *
 * Spans go to the caller's callback, or (ef_fill) straight to the compositor,
 * inlined: the same loop is compiled twice, once per sink.
 */
#include "internal.h"

static EF_ALWAYS_INLINE void fill_evenodd(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span,
                                          void *user, const ef_blend *blend, const int direct)
{
    uint32_t *cells = ctx->eo_cells;
    uint64_t *occ = ctx->occ;
    const int32_t W = ctx->width;
    uint32_t acc = 0;
    int32_t start = xmin;
    for (int32_t wi = xmin >> 6; wi <= xmax >> 6; wi++) {
        uint64_t bits = occ[wi];
        if (!bits)
            continue;
        occ[wi] = 0;
        do {
            int32_t p = wi * 64 + (int32_t)ef_ctz64(bits);
            bits &= bits - 1;
            uint32_t v = cells[p];
            if (v == 0)
                continue; /* flags that cancelled: mask unchanged */
            cells[p] = 0; /* clear-on-read */
            if (acc && p > start) {
                int32_t len = (p < W ? p : W) - start;
                if (direct)
                    ef_blend_span(blend, y, start, len, acc);
                else
                    span(user, y, start, len, acc);
            }
            acc ^= v;
            start = p;
        } while (bits);
    }
    /* After xmax the accumulator is zero for closed polygons (spec 7.2). */
    if (acc && start < W) {
        int32_t end = xmax + 1 < W ? xmax + 1 : W;
        if (direct)
            ef_blend_span(blend, y, start, end - start, acc);
        else
            span(user, y, start, end - start, acc);
    }
}

void ef_fill_evenodd(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user,
                     const ef_blend *blend)
{
    if (blend)
        fill_evenodd(ctx, y, xmin, xmax, NULL, NULL, blend, 1);
    else
        fill_evenodd(ctx, y, xmin, xmax, span, user, NULL, 0);
}
