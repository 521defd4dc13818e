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
    ef_aet_saved *sv = realloc(ctx->aet_saved, (size_t)cap * sizeof *sv);
    if (!sv)
        return EF_ERR_NOMEM;
    ctx->aet_saved = sv;
    ctx->edges_cap = cap;
    return EF_OK;
}

/* |x|, |y| < 2^23, as unsigned compares (wrapping is defined). */
static inline int coord_bad(ef_point p)
{
    const uint32_t lim = 2u * (EF_COORD_LIMIT - 1);
    return ((uint32_t)p.x + (EF_COORD_LIMIT - 1) > lim) | ((uint32_t)p.y + (EF_COORD_LIMIT - 1) > lim);
}

/* floor(v / 2^sh) for |v| < 2^24, 0 <= sh <= 5, without `>>` on a negative
 * value: biased by 2^25 (a multiple of 2^sh) into the unsigned range. */
static inline int32_t floor_shr(int32_t v, unsigned sh)
{
    return (int32_t)(((uint32_t)v + (UINT32_C(1) << 25)) >> sh) - (int32_t)((UINT32_C(1) << 25) >> sh);
}

/* Edge setup's state while it walks a polygon, in a local rather than in
 * ctx (where every store into an edge record may alias it), written back to
 * ctx once at the end. */
typedef struct setup_state {
    ef_edge *edges;
    ef_slot *slot;
    uint32_t nedges;
    uint32_t dropped;
    int32_t h, c;     /* 256/N and h/2 */
    unsigned sh;      /* h = 2^sh */
    int32_t last_row; /* last sample row, N*H - 1 */
    int32_t row_min, row_max;
} setup_state;

/* Spec 5 steps 2-4 and 6 for one edge a -> b (not horizontal).  h = 256/N is
 * a power of two (2^sh), so the ceilings of step 3 are shifts.  Step 5 (the
 * DDA's divisions) is ef_dda_start, run by the plotter at the edge's first
 * row. */
static inline void setup_edge(setup_state *st, ef_point a, ef_point b)
{
    const int32_t h = st->h, c = st->c;
    const unsigned sh = st->sh;
    const int down = a.y < b.y;
    const ef_point p0 = down ? a : b, p1 = down ? b : a;
    int32_t r0 = floor_shr(p0.y - c + h - 1, sh); /* ceil((Y0 - c) / h) */
    int32_t r1 = floor_shr(p1.y - c - 1, sh);     /* ceil((Y1 - c) / h) - 1 */
    if (r0 < 0)
        r0 = 0; /* top clip: start inside */
    if (r1 > st->last_row)
        r1 = st->last_row; /* bottom clip */
    if (r0 > r1) {
        st->dropped++;
        return;
    }
    const uint32_t i = st->nedges++;
    ef_edge *E = &st->edges[i];
    E->x0 = p0.x;
    E->y0 = p0.y;
    E->dx = p1.x - p0.x; /* |dx| < 2^24 */
    E->dy = p1.y - p0.y; /* 1 .. 2^24 - 1 */
    E->r0 = r0;
    E->r1 = r1;
    E->dir = down ? 1 : -1;
    /* Pixel rows of the first and last sample rows: N = 2^(8 - sh), r0 >= 0. */
    const int32_t slot = r0 >> (8 - sh), last = r1 >> (8 - sh);
    ef_et_insert(st->edges, st->slot, i, slot);
    st->row_min = slot < st->row_min ? slot : st->row_min;
    st->row_max = last > st->row_max ? last : st->row_max;
}

ef_status ef_edges_setup(ef_ctx *ctx, const ef_polygon *poly, int32_t *row_min, int32_t *row_max)
{
    *row_min = INT32_MAX;
    *row_max = -1;
    ctx->nedges = 0;
    uint64_t total = poly->ncontours ? (uint64_t)poly->start[poly->ncontours] - poly->start[0] : 0;
    if (total > EF_MAX_EDGES_PER_SHAPE)
        return EF_ERR_LIMIT;
    ef_status status = reserve_edges(ctx, (uint32_t)total);
    if (status != EF_OK)
        return status;
    /* Reverse input order: the edge table prepends, so its lists (and the
     * AET) read in input order (edge_table.c).  Every point is checked once
     * (as the start of its edge); a bad one undoes what was built, so an
     * error leaves no state behind (and no diagnostic counted: the counts
     * reach ctx->diag only on success). */
    setup_state st = {
        ctx->edges, ctx->slot, 0, 0, ctx->h, ctx->c, 8u - ef_samples_log2(ctx->samples), ctx->samples * ctx->height - 1,
        INT32_MAX,  -1
    };
    uint32_t edges_in = 0;
    int bad = 0;
    for (uint32_t ci = poly->ncontours; ci-- > 0 && !bad;) {
        uint32_t b = poly->start[ci], n = poly->start[ci + 1] - b;
        edges_in += n;
        if (n == 0)
            continue; /* pts may be NULL when every contour is empty */
        const ef_point *pts = poly->pts + b;
        ef_point bb = pts[0]; /* edge k runs pts[k] -> pts[k+1 mod n] */
        if (coord_bad(bb)) {
            bad = 1;
            break;
        }
        for (uint32_t k = n; k-- > 0;) {
            ef_point a = pts[k];
            if (coord_bad(a)) {
                bad = 1;
                break;
            }
            if (a.y == bb.y)
                st.dropped++; /* horizontal: crosses no row */
            else
                setup_edge(&st, a, bb);
            bb = a;
        }
    }
    if (bad) {
        for (int32_t j = st.row_min; j <= st.row_max; j++)
            ctx->slot[j] = (ef_slot){ -1, 0 };
        ctx->nedges = 0;
        return EF_ERR_ARG;
    }
    ctx->nedges = st.nedges;
    ctx->diag.edges_in += edges_in;
    ctx->diag.edges_dropped += st.dropped;
    *row_min = st.row_min;
    *row_max = st.row_max;
    return EF_OK;
}
