/*
 * plotter_crowd.h - a speed device of the plotter (included by plotter.c for
 * ef_plot_nonzero): crowded rows plotted without the per-sample winding
 * overflow test (spec 6.4), and redone with it when a cell may have needed
 * it.  These run once per crowded row; the per-edge count (crowd_add) is in
 * plotter.h.
 */
#ifndef EF_PLOTTER_CROWD_H
#define EF_PLOTTER_CROWD_H

/* The most edges that may plot into one cell of the crowded row just
 * plotted; leaves ctx->crowd zero. */
static int32_t crowd_most(ef_ctx *ctx)
{
    int32_t run = 0, most = 0;
    for (int32_t k = ctx->crowd_lo; k <= ctx->crowd_hi; k++) {
        run += ctx->crowd[k];
        ctx->crowd[k] = 0;
        most = run > most ? run : most;
    }
    return most;
}

/* Undoes a crowded row's plot: the AET and its edges' DDA state as they
 * were (new edges restart from their setup), and the cells and occupancy
 * bits it marked, all within [xmin, xmax] (spec 7.1; none if xmax < 0),
 * zero again. */
static void crowd_undo(ef_ctx *ctx, uint32_t naet, int32_t xmin, int32_t xmax)
{
    for (uint32_t k = 0; k < naet; k++) {
        const ef_aet_saved sv = ctx->aet_saved[k];
        ctx->aet[k] = sv.idx;
        ctx->edges[sv.idx].x = sv.x;
        ctx->edges[sv.idx].e = sv.e;
    }
    ctx->naet = naet;
    if (xmax < 0)
        return;
    const size_t words = (size_t)ctx->samples / 8;
    memset(&ctx->nz_cells[(size_t)xmin * words], 0, (size_t)(xmax - xmin + 1) * words * sizeof *ctx->nz_cells);
    memset(&ctx->occ[xmin >> 6], 0, (size_t)((xmax >> 6) - (xmin >> 6) + 1) * sizeof *ctx->occ);
}

/* Before a row plotted with the overflow count (sample by sample, in AET
 * order): the AET's MASK edges become STEEP ones (new edges start as such on
 * those rows, MASK_ROWS). */
static void mask_demote_aet(ef_ctx *ctx)
{
    for (uint32_t k = 0; k < ctx->naet; k++) {
        ef_edge *E = &ctx->edges[ctx->aet[k]];
        if (E->mode == EF_PLOT_MASK)
            ef_mask_demote(E, ctx->h);
    }
}

#endif
