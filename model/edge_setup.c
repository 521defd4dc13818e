/*
 * edge_setup.c - edge setup block (docs/spec.md section 5).
 *
 * Turns each polygon edge into an exact DDA record: the sample rows it
 * crosses (half-open in y), clipped to the canvas rows, and the quotient /
 * remainder pair that steps its crossing from one sample row to the next
 * without any rounding error.  Horizontal edges and edges that cross no
 * sample row inside the clip rectangle are dropped here.
 */
#include <stdlib.h>

#include "internal.h"

static ef_status reserve_edges(ef_ctx *ctx, uint32_t need)
{
    if (need <= ctx->edges_cap)
        return EF_OK;
    if (need > EF_MAX_EDGES_PER_SHAPE)
        return EF_ERR_LIMIT;
    uint32_t cap = ctx->edges_cap ? ctx->edges_cap : 256;
    while (cap < need)
        cap = cap > EF_MAX_EDGES_PER_SHAPE / 2 ? EF_MAX_EDGES_PER_SHAPE : cap * 2;
    ef_edge *e = realloc(ctx->edges, (size_t)cap * sizeof *e);
    if (!e)
        return EF_ERR_NOMEM;
    ctx->edges = e;
    int32_t *a = realloc(ctx->aet, (size_t)cap * sizeof *a);
    if (!a)
        return EF_ERR_NOMEM;
    ctx->aet = a;
    ctx->edges_cap = cap;
    return EF_OK;
}

static int coord_ok(ef_point p)
{
    return p.x > -EF_COORD_LIMIT && p.x < EF_COORD_LIMIT && p.y > -EF_COORD_LIMIT && p.y < EF_COORD_LIMIT;
}

/* Spec 5 steps 2-6 for one edge a -> b (not horizontal). */
static void setup_edge(ef_ctx *ctx, ef_point a, ef_point b, int32_t *row_min, int32_t *row_max)
{
    const int64_t h = ctx->h, c = ctx->c;
    int32_t dir = a.y < b.y ? 1 : -1;
    ef_point p0 = dir > 0 ? a : b, p1 = dir > 0 ? b : a;

    int64_t r0 = ef_ceildiv_i64((int64_t)p0.y - c, h);
    int64_t r1 = ef_ceildiv_i64((int64_t)p1.y - c, h) - 1;
    if (r0 < 0)
        r0 = 0;                                        /* top clip: start inside */
    int64_t last_row = (int64_t)ctx->samples * ctx->height - 1;
    if (r1 > last_row)
        r1 = last_row;                                 /* bottom clip */
    if (r0 > r1) {
        ctx->diag.edges_dropped++;
        return;
    }

    int64_t dy = (int64_t)p1.y - p0.y;                 /* 1 .. 2^24 - 1 */
    int64_t dx = (int64_t)p1.x - p0.x;                 /* |dx| < 2^24 */
    int64_t yr0 = h * r0 + c;
    /* |A| < 2^23 * 2^24 + 2^24 * 2^24 < 2^49: exact in int64. */
    int64_t A = (int64_t)p0.x * dy + (yr0 - p0.y) * dx - 1;
    int64_t x, e, qs, rs;
    ef_divmod_floor_i64(A, dy, &x, &e);
    /* |h*dx| < 2^29 and dy < 2^24: the step fits 32-bit division, which is
     * several times cheaper than 64-bit on most cores.  Same floor rule. */
    int32_t step = (int32_t)(h * dx), dy32 = (int32_t)dy;
    int32_t q32 = step / dy32, r32 = step % dy32;
    if (r32 < 0) {
        q32 -= 1;
        r32 += dy32;
    }
    qs = q32;
    rs = r32;

    uint32_t i = ctx->nedges++;
    ef_edge *E = &ctx->edges[i];
    E->x = (int32_t)x;
    E->e = (int32_t)e;
    E->qs = (int32_t)qs;
    E->rs = (int32_t)rs;
    E->dy = (int32_t)dy;
    E->r = (int32_t)r0;
    E->r1 = (int32_t)r1;
    E->dir = dir;
    int32_t slot = (int32_t)(r0 / ctx->samples);       /* r0 >= 0 here */
    ef_et_insert(ctx, i, slot);
    if (slot < *row_min)
        *row_min = slot;
    int32_t last = (int32_t)(r1 / ctx->samples);
    if (last > *row_max)
        *row_max = last;
}

ef_status ef_edges_setup(ef_ctx *ctx, const ef_polygon *poly, int32_t *row_min, int32_t *row_max)
{
    *row_min = INT32_MAX;
    *row_max = -1;
    ctx->nedges = 0;
    uint64_t total = poly->ncontours ? (uint64_t)poly->start[poly->ncontours] - poly->start[0] : 0;
    if (total > EF_MAX_EDGES_PER_SHAPE)
        return EF_ERR_LIMIT;
    ef_status st = reserve_edges(ctx, (uint32_t)total);
    if (st != EF_OK)
        return st;
    /* Validate everything before touching the edge table, so an error leaves
     * no half-built state behind. */
    for (uint32_t k = poly->ncontours ? poly->start[0] : 0; k < (poly->ncontours ? poly->start[poly->ncontours] : 0); k++) {
        if (!coord_ok(poly->pts[k]))
            return EF_ERR_ARG;
    }
    for (uint32_t ci = 0; ci < poly->ncontours; ci++) {
        uint32_t b = poly->start[ci], n = poly->start[ci + 1] - b;
        const ef_point *pts = poly->pts + b;
        for (uint32_t k = 0; k < n; k++) {
            ef_point a = pts[k], bb = pts[k + 1 == n ? 0 : k + 1];
            ctx->diag.edges_in++;
            if (a.y == bb.y) {
                ctx->diag.edges_dropped++;             /* horizontal: crosses no row */
                continue;
            }
            setup_edge(ctx, a, bb, row_min, row_max);
        }
    }
    return EF_OK;
}
