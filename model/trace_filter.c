/*
 * trace_filter.c - the timing model with the section 3.5 options on
 * (docs/spec.md section 10, docs/microarch.md section 5): one SETUP and one
 * DDA per edge for the centre channel's mask canvas; per mask row, one PLOT +
 * SLB + FILL pass per channel (the channel's cell is (x - delta_c + off) >> 8
 * from the same DDA state, replayed for each pass), FILL's spans written into
 * that channel's current mask line, then one weigh sweep over the output row
 * (tent: the saved and the current line; box with offsets: the current one),
 * one pixel a cycle, each visited pixel with coverage giving its `pix`
 * L_FILT cycles later.
 *
 * Written plainly and apart from filter.c on purpose: it shares edge setup,
 * the edge table and ef_dda_start, but computes the channels' cells from one
 * DDA with per-channel offsets (filter.c rasterizes translated copies) and
 * the tent sums sample by sample from spec 10.2's formula (filter.c uses
 * per-byte tables); tests/unit/test_trace_filter.c requires the same image.
 */
#include <stdlib.h>
#include <string.h>

#include "filter_internal.h"
#include "trace.h"

uint64_t ef_trace_filter_bits(const ef_ctx *ctx)
{
    return ctx->filt ? (uint64_t)ctx->filt->filter | (uint64_t)ctx->filt->subpixel << 1 : 0;
}

typedef struct fr {
    ef_ctx *ctx; /* the caller's context: canvas, diagnostics */
    ef_ctx *sc;  /* the centre channel's: edge records, AET, one SLB per pass reused */
    struct ef_filt *f;
    ef_trace *tr;
    ef_image *img;
    int nz, ns, nch, e;
    int32_t wm, w;    /* mask canvas width W+e, canvas width W */
    int32_t shift[3]; /* delta_c of the pass's channel (left, centre, right), Q16.8 */
    uint64_t t, lw_free, drained;
    uint32_t *line[3][2];
    int32_t lo[3][2], hi[3][2];
    int cur;
    uint8_t premul[4], alpha;
    int pending;
    uint64_t pend[5];
} fr;

static void transfer(fr *r, int iface, uint64_t cycle, const uint64_t *v)
{
    ef_trace_emit(r->tr, iface, cycle, v);
    if (cycle + 1 > r->drained)
        r->drained = cycle + 1;
}

static void plot_out(fr *r, int32_t row, int s, int32_t q, int32_t dir)
{
    if (r->pending)
        transfer(r, EF_IF_PLOT, r->t++, r->pend);
    const uint64_t v[5] = { 0, (uint64_t)row, (uint64_t)s, (uint64_t)q, dir < 0 };
    memcpy(r->pend, v, sizeof v);
    r->pending = 1;
}

static void plot_last(fr *r)
{
    r->pend[0] = 1;
    transfer(r, EF_IF_PLOT, r->t++, r->pend);
    r->pending = 0;
}

/* SLB read-modify-write (spec 6.2, 6.3) with the 6.4 diagnostic. */
static void mark(fr *r, int32_t q, int s, int32_t dir)
{
    ef_ctx *sc = r->sc;
    if (!r->nz) {
        sc->eo_cells[q] ^= UINT32_C(1) << s;
        return;
    }
    uint64_t *word = &sc->nz_cells[(size_t)q * (size_t)(r->ns / 8) + (size_t)(s / 8)];
    const unsigned lane = 8u * (unsigned)(s % 8);
    const int32_t v = ((int32_t)((*word >> lane) & 0x7Fu) ^ 0x40) - 0x40;
    if (v + dir < -64 || v + dir > 63)
        r->ctx->diag.winding_overflows++;
    *word = (*word & ~(UINT64_C(0x7F) << lane)) | (uint64_t)((uint32_t)(v + dir) & 0x7Fu) << lane;
}

/* One pass's plots of edge E (a copy of its DDA state at the row start). */
static void plot_edge(fr *r, ef_edge E, int32_t row, int s0, int s1, int32_t shift, int32_t *xmin, int32_t *xmax)
{
    for (int s = s0; s <= s1; s++) {
        const int32_t q = ef_clamp_i32(ef_asr_i32(E.x - shift + r->sc->off[s], EF_DEV_FRAC_BITS), 0, r->wm);
        mark(r, q, s, E.dir);
        *xmin = q < *xmin ? q : *xmin;
        *xmax = q > *xmax ? q : *xmax;
        plot_out(r, row, s, q, E.dir);
        E.e += E.rs;
        E.x += E.qs;
        if (E.e >= E.dy) {
            E.e -= E.dy;
            E.x += 1;
        }
    }
}

/* A span goes to the line writer (one mask a cycle) instead of COV. */
static uint64_t span_out(fr *r, int p, int32_t y, int32_t x, int32_t len, uint32_t mask, uint64_t closed)
{
    const uint64_t a = closed + 1 > r->lw_free ? closed + 1 : r->lw_free;
    const uint64_t vs[4] = { (uint64_t)y, (uint64_t)x, (uint64_t)len, mask };
    transfer(r, EF_IF_SPAN, a, vs);
    uint32_t *l = r->line[p][r->cur];
    for (int32_t i = 0; i < len; i++)
        l[x + i] = mask;
    r->lo[p][r->cur] = x < r->lo[p][r->cur] ? x : r->lo[p][r->cur];
    r->hi[p][r->cur] = x + len - 1 > r->hi[p][r->cur] ? x + len - 1 : r->hi[p][r->cur];
    r->lw_free = a + (uint64_t)len;
    return a;
}

/* FILL of one pass (spec 7.2, microarch 4 item 5), cells xmin..xmax and the flush step. */
static void scan(fr *r, int p, int32_t y, int32_t xmin, int32_t xmax)
{
    int64_t acc[32] = { 0 };
    uint32_t mask = 0;
    int32_t start = xmin;
    uint64_t t = r->t;
    for (int32_t x = xmin; x <= xmax; x++) {
        uint64_t next = t + 1;
        uint32_t m = 0;
        int marked;
        if (r->nz) {
            uint64_t *cell = &r->sc->nz_cells[(size_t)x * (size_t)(r->ns / 8)];
            marked = 0;
            for (int w = 0; w < r->ns / 8; w++)
                marked |= cell[w] != 0;
            if (marked) {
                for (int s = 0; s < r->ns; s++) {
                    const int64_t c = (int64_t)((cell[s / 8] >> (8 * (s % 8))) & 0x7Fu);
                    int64_t v = acc[s] + ((c ^ 0x40) - 0x40);
                    if (v < -64 || v > 63)
                        r->ctx->diag.winding_overflows++;
                    acc[s] = ((v + 64) & 0x7F) - 64;
                    m |= (uint32_t)(acc[s] != 0) << s;
                }
                for (int w = 0; w < r->ns / 8; w++)
                    cell[w] = 0;
            }
        } else {
            const uint32_t v = r->sc->eo_cells[x];
            r->sc->eo_cells[x] = 0;
            marked = v != 0;
            m = mask ^ v;
        }
        if (marked) {
            if (mask && x > start)
                next = span_out(r, p, y, start, x - start, mask, t);
            mask = m;
            start = x;
        }
        t = next;
    }
    uint64_t next = t + 1;
    if (mask && start < r->wm) {
        const int32_t end = xmax + 1 < r->wm ? xmax + 1 : r->wm;
        next = span_out(r, p, y, start, end - start, mask, t);
    }
    r->t = next;
}

/* Spec 10.2 for one channel's mask m of base pixel (a, b): the sum of
 * X_a(k_s) Y_b(s) over its covered samples. */
static uint32_t tent_sum(const fr *r, uint32_t m, int a, int b)
{
    const uint8_t *k = ef_pattern(r->ns);
    const uint32_t n2 = 2u * (uint32_t)r->ns;
    uint32_t sum = 0;
    for (int s = 0; s < r->ns; s++)
        if (m >> s & 1u) {
            const uint32_t x = 2u * k[s] + 1u, y = 2u * (uint32_t)s + 1u;
            sum += (a ? n2 - x : x) * (b ? n2 - y : y);
        }
    return sum;
}

/* The weigh sweep of output row y: columns lo..hi one a cycle (spec 10.2-10.4). */
static void weigh(fr *r, int32_t y)
{
    const int cur = r->cur, up = cur ^ 1;
    int32_t lo = INT32_MAX, hi = -1;
    for (int p = 0; p < r->nch; p++)
        for (int l = 0; l <= r->e; l++) {
            const int wh = l ? up : cur;
            if (r->hi[p][wh] < 0)
                continue;
            lo = r->lo[p][wh] - r->e < lo ? r->lo[p][wh] - r->e : lo;
            hi = r->hi[p][wh] > hi ? r->hi[p][wh] : hi;
        }
    lo = lo < 0 ? 0 : lo;
    hi = hi > r->w - 1 ? r->w - 1 : hi;
    uint64_t v = r->t > r->lw_free ? r->t : r->lw_free; /* after the line writer's last mask */
    const uint32_t n = (uint32_t)r->ns, den = r->e ? 4u * n * n * n : n;
    for (int32_t x = lo; x <= hi; x++, v++) {
        uint32_t sum[3];
        for (int p = 0; p < r->nch; p++) {
            if (r->e)
                sum[p] = tent_sum(r, r->line[p][up][x], 0, 0) + tent_sum(r, r->line[p][up][x + 1], 1, 0) +
                         tent_sum(r, r->line[p][cur][x], 0, 1) + tent_sum(r, r->line[p][cur][x + 1], 1, 1);
            else
                sum[p] = ef_popcount32(r->line[p][cur][x]);
        }
        uint32_t any = 0;
        for (int p = 0; p < r->nch; p++)
            any |= sum[p];
        if (!any)
            continue; /* no coverage in any channel: no pix */
        uint8_t cov[4];
        for (int c = 0; c < 3; c++)
            cov[c] = (uint8_t)((255u * sum[r->f->pos_of_colour[c]] + den / 2u) / den);
        cov[3] = cov[1];
        uint8_t *d = r->img->px + (size_t)y * r->img->stride + (size_t)x * 4;
        uint64_t rgba = 0;
        for (int ch = 0; ch < 4; ch++) {
            d[ch] =
                (uint8_t)(d[ch] + ef_mul255(r->premul[ch], cov[ch]) - ef_mul255(d[ch], ef_mul255(r->alpha, cov[ch])));
            rgba = rgba << 8 | d[ch];
        }
        const uint64_t vp[4] = { (uint64_t)y, (uint64_t)x, cov[3], rgba };
        transfer(r, EF_IF_PIX, v + EF_L_FILT, vp);
    }
    if (hi >= lo)
        r->t = v;
}

static void clear_line(fr *r, int p, int wh)
{
    if (r->hi[p][wh] >= 0)
        memset(r->line[p][wh] + r->lo[p][wh], 0, (size_t)(r->hi[p][wh] - r->lo[p][wh] + 1) * sizeof(uint32_t));
    r->lo[p][wh] = INT32_MAX;
    r->hi[p][wh] = -1;
}

static uint64_t bits(int64_t v) { return (uint64_t)v; }

ef_status ef_trace_filter_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color)
{
    ef_trace *tr = ctx->trace;
    struct ef_filt *f = ctx->filt;
    const int ce = ef_filt_centre(f);
    ef_ctx *sc = f->ch[ce];
    const uint32_t npts = poly->ncontours ? poly->start[poly->ncontours] : 0;
    /* Spec 10.1's limit for every channel: a vertex that any shift takes out of range. */
    for (int p = 0; p < f->nch; p++)
        for (uint32_t i = 0; i < npts; i++) {
            const int64_t x = (int64_t)poly->pts[i].x + f->tx[p], y = (int64_t)poly->pts[i].y + f->ty;
            if (x <= -EF_COORD_LIMIT || x >= EF_COORD_LIMIT || y <= -EF_COORD_LIMIT || y >= EF_COORD_LIMIT)
                return EF_ERR_ARG;
        }
    ef_point *tp = malloc(((size_t)npts + 1) * sizeof *tp);
    fr r = { .ctx = ctx,
             .sc = sc,
             .f = f,
             .tr = tr,
             .img = img,
             .nz = rule == EF_RULE_NONZERO,
             .ns = ctx->samples,
             .nch = f->nch,
             .e = f->e,
             .wm = ctx->width + f->e,
             .w = ctx->width,
             .alpha = color.a };
    int ok = tp != NULL;
    for (int p = 0; p < 3; p++)
        for (int l = 0; l < 2; l++) {
            r.line[p][l] = calloc((size_t)r.wm, sizeof(uint32_t));
            ok &= r.line[p][l] != NULL;
            r.lo[p][l] = INT32_MAX;
            r.hi[p][l] = -1;
        }
    ef_status st = ok ? EF_OK : EF_ERR_NOMEM;
    int32_t row_min = 0, row_max = -1;
    if (st == EF_OK) {
        for (uint32_t i = 0; i < npts; i++)
            tp[i] = (ef_point){ poly->pts[i].x + f->tx[ce], poly->pts[i].y + f->ty };
        const ef_polygon tpoly = { tp, poly->start, poly->ncontours };
        const ef_diag before = sc->diag;
        ef_et_reset(sc);
        st = ef_edges_setup(sc, &tpoly, &row_min, &row_max);
        ctx->diag.edges_in += sc->diag.edges_in - before.edges_in;
        ctx->diag.edges_dropped += sc->diag.edges_dropped - before.edges_dropped;
    }
    if (st == EF_OK) {
        if (!tr->in_frame)
            ef_trace_frame_begin(ctx);
        ef_trace_command(tr, EF_OP_SHAPE, rule == EF_RULE_EVENODD,
                         (uint64_t)color.r << 16 | (uint64_t)color.g << 8 | color.b, color.a, 0);
        /* DEC passes the input edge; SETUP moves it by the centre channel's
         * (tx, ty) and sets up the mask canvas's record (microarch 5). */
        const int32_t h = sc->h, c = sc->c, wm256 = r.wm * EF_DEV_ONE;
        const unsigned log2n = ef_samples_log2(r.ns);
        int64_t rec = (int64_t)sc->nedges - 1;
        for (uint32_t ci = 0; ci < poly->ncontours; ci++) {
            const uint32_t b = poly->start[ci], n = poly->start[ci + 1] - b;
            for (uint32_t k = 0; k < n; k++) {
                const ef_point a = poly->pts[b + k], z = poly->pts[b + (k + 1 == n ? 0 : k + 1)];
                const uint64_t t = ef_trace_command(tr, EF_OP_EDGE, bits(a.x), bits(a.y), bits(z.x), bits(z.y));
                const uint64_t ve[5] = { 0, bits(a.x), bits(a.y), bits(z.x), bits(z.y) };
                ef_trace_emit(tr, EF_IF_SEG, t + EF_L_DEC, ve);
                const ef_point ta = { a.x + f->tx[ce], a.y + f->ty }, tz = { z.x + f->tx[ce], z.y + f->ty };
                if (rec < 0 || !ef_trace_record_of(&sc->edges[rec], ta, tz))
                    continue;
                ef_edge E = sc->edges[rec--];
                ef_dda_start(&E, h, c, wm256, r.ns - 1, 0);
                const uint64_t vw[10] = {
                    0,          (uint64_t)E.r0 >> log2n, (uint64_t)E.r0, (uint64_t)E.r1, bits(E.x), (uint64_t)E.e,
                    bits(E.qs), (uint64_t)E.rs,          (uint64_t)E.dy, E.dir < 0
                };
                ef_trace_emit(tr, EF_IF_ET_WR, t + EF_L_DEC + EF_L_SETUP, vw);
            }
        }
        const uint64_t t_end = ef_trace_command(tr, EF_OP_SHAPE_END, 0, 0, 0, 0);
        const uint64_t eos[10] = { 1 };
        ef_trace_emit(tr, EF_IF_SEG, t_end + EF_L_DEC, eos);
        ef_trace_emit(tr, EF_IF_ET_WR, t_end + EF_L_DEC + EF_L_SETUP, eos);
        r.t = r.drained = t_end + EF_L_DEC + EF_L_SETUP + 1;
        for (int k = 0; k < 4; k++)
            r.premul[k] = k < 3 ? ef_mul255((&color.r)[k], color.a) : color.a;
        for (int p = 0; p < r.nch; p++)
            r.shift[p] = f->tx[ce] - f->tx[p]; /* delta_p: x_p = x - delta_p */

        const int32_t hm = ctx->height + r.e, qend = row_max + r.e < hm - 1 ? row_max + r.e : hm - 1;
        for (int32_t q = row_min; q <= qend && row_min <= row_max; q++) {
            for (int p = 0; p < r.nch; p++)
                clear_line(&r, p, r.cur);
            uint32_t nnew;
            const int32_t head = ef_et_take(sc, q, &nnew);
            if (sc->naet || head >= 0) {
                for (int32_t idx = head; idx >= 0; idx = sc->edges[idx].next) {
                    const uint64_t v[2] = { (uint64_t)q, (uint64_t)(sc->nedges - 1u - (uint32_t)idx) };
                    transfer(&r, EF_IF_ET_RD, r.t++, v);
                }
                for (int32_t idx = head; idx >= 0; idx = sc->edges[idx].next)
                    ef_dda_start(&sc->edges[idx], h, c, wm256, r.ns - 1, 0);
                const int32_t base = q * r.ns, end = base + r.ns - 1;
                for (int p = 0; p < r.nch; p++) { /* one pass per channel, left to right */
                    int32_t xmin = INT32_MAX, xmax = -1;
                    for (uint32_t k = 0; k < sc->naet; k++) {
                        const ef_edge *E = &sc->edges[sc->aet[k]];
                        plot_edge(&r, *E, q, 0, (E->r1 < end ? E->r1 : end) - base, r.shift[p], &xmin, &xmax);
                    }
                    for (int32_t idx = head; idx >= 0; idx = sc->edges[idx].next) {
                        const ef_edge *E = &sc->edges[idx];
                        plot_edge(&r, *E, q, E->r0 - base, (E->r1 < end ? E->r1 : end) - base, r.shift[p], &xmin,
                                  &xmax);
                    }
                    plot_last(&r);
                    scan(&r, p, q, xmin, xmax);
                }
                /* the DDA moves on once, after the last pass; finished edges leave */
                uint32_t kept = 0;
                for (uint32_t k = 0; k < sc->naet; k++) {
                    ef_edge *E = &sc->edges[sc->aet[k]];
                    for (int32_t rr = base; rr <= (E->r1 < end ? E->r1 : end); rr++) {
                        E->e += E->rs;
                        E->x += E->qs;
                        if (E->e >= E->dy) {
                            E->e -= E->dy;
                            E->x += 1;
                        }
                    }
                    if (E->r1 > end)
                        sc->aet[kept++] = sc->aet[k];
                }
                for (int32_t idx = head; idx >= 0; idx = sc->edges[idx].next) {
                    ef_edge *E = &sc->edges[idx];
                    for (int32_t rr = E->r0; rr <= (E->r1 < end ? E->r1 : end); rr++) {
                        E->e += E->rs;
                        E->x += E->qs;
                        if (E->e >= E->dy) {
                            E->e -= E->dy;
                            E->x += 1;
                        }
                    }
                    if (E->r1 > end)
                        sc->aet[kept++] = idx;
                }
                sc->naet = kept;
            }
            if (!r.e)
                weigh(&r, q);
            else if (q >= 1)
                weigh(&r, q - 1);
            r.cur ^= 1;
        }
        const uint64_t t_free = r.drained > r.t ? r.drained : r.t;
        if (t_free > tr->cmd_next)
            tr->cmd_next = t_free;
    }
    free(tp);
    for (int p = 0; p < 3; p++)
        for (int l = 0; l < 2; l++)
            free(r.line[p][l]);
    return st;
}
