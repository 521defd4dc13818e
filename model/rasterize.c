/*
 * rasterize.c - the scanline loop (docs/spec.md section 6): for each pixel row
 * that holds edges, activate the row's edge-table slot, plot the active edges'
 * sample rows into the one-scanline buffer, retire finished edges, and fill
 * between the row's tracked extents (edge tracking, spec 7.1).
 */
#include "internal.h"

ef_status ef_rasterize(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_span_fn span, void *user)
{
    if (!ctx || !poly || !span || (rule != EF_RULE_NONZERO && rule != EF_RULE_EVENODD))
        return EF_ERR_ARG;
    int32_t row_min, row_max;
    ef_et_reset(ctx);
    ef_status st = ef_edges_setup(ctx, poly, &row_min, &row_max);
    if (st != EF_OK)
        return st;

    const int evenodd = rule == EF_RULE_EVENODD;
    for (int32_t row = row_min; row <= row_max; row++) {
        ef_et_activate(ctx, row);
        if (ctx->naet == 0)
            continue;
        int32_t xmin = INT32_MAX, xmax = -1;
        ctx->naet_row = ctx->naet;
        if (evenodd)
            ef_plot_evenodd(ctx, row, &xmin, &xmax);
        else
            ef_plot_nonzero(ctx, row, &xmin, &xmax);
        ef_aet_retire(ctx);
        if (xmax < 0)
            continue;
        if (evenodd)
            ef_fill_evenodd(ctx, row, xmin, xmax, span, user);
        else
            ef_fill_nonzero(ctx, row, xmin, xmax, span, user);
    }
    return EF_OK;
}
