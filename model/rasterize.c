/*
 * rasterize.c - the scanline loop (docs/spec.md section 6): for each pixel row
 * that holds edges, take the row's edge-table slot, plot the active edges'
 * and the new edges' sample rows into the one-scanline buffer (the plotter
 * activates the new edges and retires the finished ones in the same pass),
 * and fill between the row's tracked extents (edge tracking, spec 7.1).
 */
#include "internal.h"

ef_status ef_rasterize_to(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_span_fn span, void *user,
                          const ef_blend *blend)
{
    if (!ctx || !poly || (!span && !blend) || (rule != EF_RULE_NONZERO && rule != EF_RULE_EVENODD))
        return EF_ERR_ARG;
    int32_t row_min, row_max;
    ef_et_reset(ctx);
    ef_status st = ef_edges_setup(ctx, poly, &row_min, &row_max);
    if (st != EF_OK)
        return st;

    const int evenodd = rule == EF_RULE_EVENODD;
    for (int32_t row = row_min; row <= row_max; row++) {
        uint32_t nnew;
        int32_t head = ef_et_take(ctx, row, &nnew);
        if (ctx->naet == 0 && head < 0)
            continue;
        int32_t xmin = INT32_MAX, xmax = -1;
        ctx->naet_row = ctx->naet + nnew; /* the AET of spec 6 for this row */
        if (evenodd)
            ef_plot_evenodd(ctx, row, head, &xmin, &xmax);
        else
            ef_plot_nonzero(ctx, row, head, &xmin, &xmax);
        if (xmax < 0)
            continue;
        if (evenodd)
            ef_fill_evenodd(ctx, row, xmin, xmax, span, user, blend);
        else
            ef_fill_nonzero(ctx, row, xmin, xmax, span, user, blend);
    }
    return EF_OK;
}

ef_status ef_rasterize(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_span_fn span, void *user)
{
    if (!span)
        return EF_ERR_ARG;
    return ef_rasterize_to(ctx, poly, rule, span, user, NULL);
}
