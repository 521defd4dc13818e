/*
 * fill_evenodd.c - the even-odd filler (docs/spec.md section 7.2).
 *
 * XOR-accumulates the flag cells left to right: the running value is the
 * coverage mask, one bit per sample.  Mask tracking: a zero cell leaves the
 * mask unchanged, so runs between non-zero cells become one span each (a
 * solid span when the mask is full); every cell is cleared as it is read.
 * The occupancy map (one bit per cell, set by the plotter) lets the scan jump
 * from marked cell to marked cell a 64-bit word at a time; unmarked cells are
 * zero and change nothing, so the spans are exactly those of a cell-by-cell
 * scan from xmin to xmax.
 */
#include "internal.h"

void ef_fill_evenodd(ef_ctx *ctx, int32_t y, int32_t xmin, int32_t xmax, ef_span_fn span, void *user)
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
                continue;                  /* flags that cancelled: mask unchanged */
            cells[p] = 0;                  /* clear-on-read */
            if (acc && p > start)
                span(user, y, start, (p < W ? p : W) - start, acc);
            acc ^= v;
            start = p;
        } while (bits);
    }
    /* After xmax the accumulator is zero for closed polygons (spec 7.2). */
    if (acc && start < W) {
        int32_t end = xmax + 1 < W ? xmax + 1 : W;
        span(user, y, start, end - start, acc);
    }
}
