/*
 * trace.c - the timing model's front end (docs/microarch.md section 4, items
 * 1-3 and 7): the command stream, DEC and SETUP.  A shape's commands go out
 * back to back; each EDGE gives its `seg` L_DEC cycles later and, if edge
 * setup keeps it, its `et_wr` L_SETUP cycles after that; SHAPE_END's tokens
 * follow the same path and start the rows (trace_raster.c).  The command after
 * a SHAPE_END waits until the shape has drained.
 */
#include <stdlib.h>

#include "trace.h"

ef_status ef_trace_enable(ef_ctx *ctx, uint32_t iface_mask, ef_txn_fn sink, void *user)
{
    if (!ctx || (iface_mask & ~EF_IF_ALL))
        return EF_ERR_ARG;
    if (!sink) {
        free(ctx->trace);
        ctx->trace = NULL;
        return EF_OK;
    }
    ef_trace *tr = ctx->trace ? ctx->trace : calloc(1, sizeof *tr);
    if (!tr)
        return EF_ERR_NOMEM;
    tr->mask = iface_mask;
    tr->sink = sink;
    tr->user = user;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        unsigned lsb = 0;
        for (int k = d->nfields - 1; k >= 0; k--) { /* the last field is the least significant */
            tr->lsb[i][k] = (uint16_t)lsb;
            lsb += d->field[k].width;
        }
    }
    ctx->trace = tr;
    return EF_OK;
}

ef_status ef_trace_set_schedule(ef_ctx *ctx, ef_schedule schedule)
{
    if (!ctx || !ctx->trace || (schedule != EF_SCHEDULE_REFERENCE && schedule != EF_SCHEDULE_OVERLAP))
        return EF_ERR_ARG;
    ctx->trace->schedule = schedule;
    return EF_OK;
}

void ef_trace_emit(ef_trace *tr, int iface, uint64_t cycle, const uint64_t *v)
{
    if (cycle + 1 > tr->end)
        tr->end = cycle + 1;
    if (!(tr->mask & (1u << iface)))
        return;
    const ef_iface_desc *d = ef_iface_get(iface);
    ef_txn t = { .cycle = cycle, .iface = (uint8_t)iface };
    for (unsigned k = 0; k < d->nfields; k++) {
        const unsigned w = d->field[k].width, p = tr->lsb[iface][k];
        const uint64_t x = v[k] & ((UINT64_C(1) << w) - 1); /* w <= 32 */
        /* the bits that stay in this word (x << 0 when aligned), then the rest */
        t.w[p >> 6] |= (x & (UINT64_MAX >> (p & 63))) << (p & 63);
        if ((p & 63) + w > 64)
            t.w[(p >> 6) + 1] |= x >> (64 - (p & 63));
    }
    tr->sink(tr->user, &t);
}

/* One command at the next command cycle. */
uint64_t ef_trace_command(ef_trace *tr, uint64_t op, uint64_t a, uint64_t b, uint64_t c, uint64_t d)
{
    const uint64_t t = tr->cmd_next, v[5] = { op, a, b, c, d };
    ef_trace_emit(tr, EF_IF_CMD, t, v);
    tr->cmd_next = t + 1;
    return t;
}

/* Two's complement bits of a signed value (the emitter cuts them to width). */
static inline uint64_t bits(int64_t v) { return (uint64_t)v; }

ef_status ef_trace_frame_begin(ef_ctx *ctx)
{
    if (!ctx || !ctx->trace)
        return EF_ERR_ARG;
    ef_trace *tr = ctx->trace;
    tr->cmd_next = 0;
    tr->end = 0;
    tr->in_frame = 1;
    /* c: the spec 10 options, {subpixel[1:0], filter[0]}; 0 (the default) without them */
    ef_trace_command(tr, EF_OP_FRAME, (uint64_t)ctx->width, (uint64_t)ctx->height, ef_trace_filter_bits(ctx), 0);
    return EF_OK;
}

ef_status ef_trace_frame_end(ef_ctx *ctx, uint64_t *cycles)
{
    if (!ctx || !ctx->trace || !ctx->trace->in_frame)
        return EF_ERR_ARG;
    ef_trace *tr = ctx->trace;
    ef_trace_command(tr, EF_OP_FRAME_END, 0, 0, 0, 0);
    tr->in_frame = 0;
    if (cycles)
        *cycles = tr->end;
    return EF_OK;
}

/* Edge k of contour [b, b+n) runs pts[b+k] -> pts[b+(k+1) mod n] (spec 5). */
static inline void contour_edge(const ef_polygon *poly, uint32_t b, uint32_t n, uint32_t k, ef_point *a, ef_point *z)
{
    *a = poly->pts[b + k];
    *z = poly->pts[b + (k + 1 == n ? 0 : k + 1)];
}

/* Whether record E is the one edge setup made of edge a -> z (spec 5 step 2
 * orders the end points by y).  Records are made in reverse input order, so
 * walking them from the last one pairs each with its input edge: an edge that
 * was dropped cannot equal the next kept one (dropping depends only on the
 * end points), so a match is never a coincidence. */
int ef_trace_record_of(const ef_edge *E, ef_point a, ef_point z)
{
    const int down = a.y < z.y;
    const ef_point p0 = down ? a : z, p1 = down ? z : a;
    return a.y != z.y && E->x0 == p0.x && E->y0 == p0.y && E->dx == p1.x - p0.x && E->dy == p1.y - p0.y &&
           E->dir == (down ? 1 : -1);
}

ef_status ef_trace_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color)
{
    ef_trace *tr = ctx->trace;
    if (!poly || (rule != EF_RULE_NONZERO && rule != EF_RULE_EVENODD))
        return EF_ERR_ARG;
    if (ctx->filt && tr->schedule != EF_SCHEDULE_REFERENCE)
        return EF_ERR_UNSUPPORTED; /* section 6 covers the box filter alone */
    if (ctx->filt)
        return ef_trace_filter_fill(ctx, img, poly, rule, color); /* spec 10 (trace_filter.c) */
    /* Edge setup first: a polygon it refuses sends no command at all. */
    int32_t row_min, row_max;
    ef_et_reset(ctx);
    ef_status st = ef_edges_setup(ctx, poly, &row_min, &row_max);
    if (st != EF_OK)
        return st;
    if (!tr->in_frame)
        ef_trace_frame_begin(ctx);

    ef_trace_command(tr, EF_OP_SHAPE, rule == EF_RULE_EVENODD,
                     (uint64_t)color.r << 16 | (uint64_t)color.g << 8 | color.b, color.a, 0);
    const int32_t h = ctx->h, c = ctx->c, w256 = ctx->width * EF_DEV_ONE;
    const unsigned log2n = ef_samples_log2(ctx->samples);
    int64_t rec = (int64_t)ctx->nedges - 1; /* next record, walking backwards = input order */
    for (uint32_t ci = 0; ci < poly->ncontours; ci++) {
        const uint32_t b = poly->start[ci], n = poly->start[ci + 1] - b;
        for (uint32_t k = 0; k < n; k++) {
            ef_point a, z;
            contour_edge(poly, b, n, k, &a, &z);
            const uint64_t t = ef_trace_command(tr, EF_OP_EDGE, bits(a.x), bits(a.y), bits(z.x), bits(z.y));
            const uint64_t ve[5] = { 0, bits(a.x), bits(a.y), bits(z.x), bits(z.y) };
            ef_trace_emit(tr, EF_IF_SEG, t + EF_L_DEC, ve);
            if (rec < 0 || !ef_trace_record_of(&ctx->edges[rec], a, z))
                continue;                  /* horizontal or outside: no record */
            ef_edge E = ctx->edges[rec--]; /* a copy: the plotter starts the DDA itself */
            ef_dda_start(&E, h, c, w256, ctx->samples - 1, 0);
            const uint64_t vw[10] = {
                0,          (uint64_t)E.r0 >> log2n, (uint64_t)E.r0, (uint64_t)E.r1, bits(E.x), (uint64_t)E.e,
                bits(E.qs), (uint64_t)E.rs,          (uint64_t)E.dy, E.dir < 0
            };
            ef_trace_emit(tr, EF_IF_ET_WR, t + EF_L_DEC + EF_L_SETUP, vw);
        }
    }
    const uint64_t t_end = ef_trace_command(tr, EF_OP_SHAPE_END, 0, 0, 0, 0);
    const uint64_t eos[10] = { 1 }; /* eos = 1, every other field 0 */
    ef_trace_emit(tr, EF_IF_SEG, t_end + EF_L_DEC, eos);
    ef_trace_emit(tr, EF_IF_ET_WR, t_end + EF_L_DEC + EF_L_SETUP, eos);
    const uint64_t t0 = t_end + EF_L_DEC + EF_L_SETUP + 1;

    const uint8_t premul[4] = { ef_mul255(color.r, color.a), ef_mul255(color.g, color.a), ef_mul255(color.b, color.a),
                                color.a };
    const uint64_t t_free = ef_trace_rows(ctx, img, rule, premul, color.a, row_min, row_max, t0);
    if (t_free > tr->cmd_next)
        tr->cmd_next = t_free;
    return EF_OK;
}
