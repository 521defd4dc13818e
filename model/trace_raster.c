/*
 * trace_raster.c - the timing model's rows (docs/microarch.md sections 3.3,
 * 3.4 and 4, items 4-6): the sequencer's activations (et_rd), one plot per
 * cycle (plot), the cell-by-cell scan with its flush step (span) and COV's
 * one pixel per cycle (pix), each transfer stamped with its cycle.
 *
 * Written plainly, in the hardware's order, on purpose: it is a second
 * implementation of the plotter, fillers and compositing beside the optimised
 * ones (plotter.c, fill_*.c, ef_blend_span), and tests/unit/test_trace.c
 * requires the two to agree on every pixel and diagnostic.  Only edge setup,
 * the edge table and ef_dda_start are shared.
 *
 * The overlap schedule (section 6) differs in two places only, each marked
 * `overlap`: the scan visits the plotted cells alone, and COV takes spans
 * through a queue of EF_SPANQ entries.
 */
#include "trace.h"

typedef struct raster {
    ef_ctx *ctx;
    ef_trace *tr;
    ef_image *img;
    int nz, ns;
    int32_t w;
    uint64_t t;            /* the sequencer's cursor: its next free cycle */
    uint64_t cov_free;     /* COV accepts the next span from this cycle */
    uint64_t drained;      /* one past the shape's last transfer */
    const uint8_t *premul; /* colour P, premultiplied, bytes R G B A */
    uint8_t alpha;
    int pending; /* a plot waits for its `last` bit */
    uint64_t pend[5];
    int overlap;               /* the schedule of section 6 */
    uint8_t *plotted;          /* overlap: cells plotted in the row (SLB's bitmap) */
    uint64_t qstart[EF_SPANQ]; /* overlap: the cycles COV started the last EF_SPANQ spans */
    uint64_t nspan;            /* overlap: spans so far in the shape */
} raster;

static void transfer(raster *r, int iface, uint64_t cycle, const uint64_t *v)
{
    ef_trace_emit(r->tr, iface, cycle, v);
    if (cycle + 1 > r->drained)
        r->drained = cycle + 1;
}

/* ------------------------------------------------------------- plotting */

/* The previous plot goes out once it is known whether it ends the row. */
static void plot_out(raster *r, int32_t row, int s, int32_t q, int32_t dir)
{
    if (r->pending)
        transfer(r, EF_IF_PLOT, r->t++, r->pend);
    r->pend[0] = 0;
    r->pend[1] = (uint64_t)row;
    r->pend[2] = (uint64_t)s;
    r->pend[3] = (uint64_t)q;
    r->pend[4] = dir < 0;
    r->pending = 1;
}

static void plot_last(raster *r)
{
    r->pend[0] = 1;
    transfer(r, EF_IF_PLOT, r->t++, r->pend);
    r->pending = 0;
}

/* SLB's read-modify-write of sample s of cell q (spec 6.2, 6.3), with the
 * winding-overflow diagnostic of 6.4 (an add that leaves [-64, 63]). */
static void mark(raster *r, int32_t q, int s, int32_t dir)
{
    ef_ctx *ctx = r->ctx;
    if (!r->nz) {
        ctx->eo_cells[q] ^= UINT32_C(1) << s;
        return;
    }
    uint64_t *word = &ctx->nz_cells[(size_t)q * (size_t)(r->ns / 8) + (size_t)(s / 8)];
    const unsigned lane = 8u * (unsigned)(s % 8);
    const int32_t old = (int32_t)((*word >> lane) & 0x7Fu);
    const int32_t v = (old ^ 0x40) - 0x40; /* the lane as a signed 7-bit number */
    if (v + dir < -64 || v + dir > 63)
        ctx->diag.winding_overflows++;
    const uint64_t nv = (uint64_t)((uint32_t)(v + dir) & 0x7Fu);
    *word = (*word & ~(UINT64_C(0x7F) << lane)) | nv << lane;
}

/* Plots sample rows s0..s1 of pixel row `row` for edge E (spec 6.1), one
 * plot per cycle, and widens [*xmin, *xmax] to the cells it marked. */
static void plot_edge(raster *r, ef_edge *E, int32_t row, int s0, int s1, int32_t *xmin, int32_t *xmax)
{
    const ef_ctx *ctx = r->ctx;
    for (int s = s0; s <= s1; s++) {
        const int32_t q = ef_clamp_i32(ef_asr_i32(E->x + ctx->off[s], EF_DEV_FRAC_BITS), 0, r->w);
        mark(r, q, s, E->dir);
        if (r->overlap)
            r->plotted[q] = 1;
        if (q < *xmin)
            *xmin = q;
        if (q > *xmax)
            *xmax = q;
        plot_out(r, row, s, q, E->dir);
        E->e += E->rs; /* the exact DDA step */
        E->x += E->qs;
        if (E->e >= E->dy) {
            E->e -= E->dy;
            E->x += 1;
        }
    }
}

/* ---------------------------------------------------------- COV, pixels */

/* Offers the span closed by the scan step at cycle `closed`; returns the
 * cycle it transfers at (COV may still be busy with the previous span). */
static uint64_t span_out(raster *r, int32_t y, int32_t x, int32_t len, uint32_t mask, uint64_t closed)
{
    uint64_t a = closed + 1 > r->cov_free ? closed + 1 : r->cov_free, b = a;
    if (r->overlap) { /* section 6: into the queue in the cycle after span k - EF_SPANQ left it */
        const uint64_t *old = &r->qstart[r->nspan % EF_SPANQ];
        a = closed + 1;
        if (r->nspan >= EF_SPANQ && *old + 1 > a)
            a = *old + 1;
        b = a > r->cov_free ? a : r->cov_free; /* COV starts it */
        r->qstart[r->nspan++ % EF_SPANQ] = b;
    }
    const uint64_t vs[4] = { (uint64_t)y, (uint64_t)x, (uint64_t)len, mask };
    transfer(r, EF_IF_SPAN, a, vs);
    const uint8_t cov = ef_coverage_alpha(mask, r->ns); /* spec 7.3 */
    const uint8_t sa = ef_mul255(r->alpha, cov);
    uint8_t *d = r->img->px + (size_t)y * r->img->stride + (size_t)x * 4;
    for (int32_t i = 0; i < len; i++, d += 4) {
        uint64_t rgba = 0;
        for (int ch = 0; ch < 4; ch++) { /* spec 8: d' = d + s - mul(d, sa) mod 256 */
            const uint32_t s = ef_mul255(r->premul[ch], cov);
            d[ch] = (uint8_t)(d[ch] + s - ef_mul255(d[ch], sa));
            rgba = rgba << 8 | d[ch];
        }
        const uint64_t vp[4] = { (uint64_t)y, (uint64_t)(x + i), cov, rgba };
        transfer(r, EF_IF_PIX, b + EF_L_COV + (uint64_t)i, vp);
    }
    r->cov_free = b + (uint64_t)len;
    return a;
}

/* ---------------------------------------------------------- scan, spans */

/* One scan step of the non-zero filler at cell p: accumulates the cell's
 * winding lanes into acc (spec 7.2) and clears it; returns 1 if the cell
 * held anything (only then can the mask change). */
static int accumulate_nz(raster *r, int32_t p, int64_t *acc, uint32_t *mask)
{
    uint64_t *cell = &r->ctx->nz_cells[(size_t)p * (size_t)(r->ns / 8)];
    int any = 0;
    for (int w = 0; w < r->ns / 8; w++)
        any |= cell[w] != 0;
    if (!any)
        return 0;
    uint32_t m = 0;
    for (int s = 0; s < r->ns; s++) {
        const int64_t c = (int64_t)((cell[s / 8] >> (8 * (s % 8))) & 0x7Fu);
        int64_t v = acc[s] + ((c ^ 0x40) - 0x40); /* 7-bit signed add */
        if (v < -64 || v > 63)
            r->ctx->diag.winding_overflows++;
        v = ((v + 64) & 0x7F) - 64; /* wraps as the packed lanes do */
        acc[s] = v;
        m |= (uint32_t)(v != 0) << s;
    }
    for (int w = 0; w < r->ns / 8; w++)
        cell[w] = 0; /* clear-on-read */
    *mask = m;
    return 1;
}

/* FILL for row y: steps xmin..xmax and the flush step from the cursor. */
static void scan(raster *r, int32_t y, int32_t xmin, int32_t xmax)
{
    int64_t acc_nz[EF_SAMPLES_MAX] = { 0 };
    uint32_t mask = 0;
    int32_t start = xmin;
    uint64_t t = r->t;
    for (int32_t p = xmin; p <= xmax; p++) {
        if (r->overlap) { /* section 6: the scan visits the plotted cells alone */
            if (!r->plotted[p])
                continue;
            r->plotted[p] = 0;
        }
        uint64_t next = t + 1;
        uint32_t m = mask;
        int marked;
        if (r->nz) {
            marked = accumulate_nz(r, p, acc_nz, &m);
        } else {
            const uint32_t v = r->ctx->eo_cells[p];
            r->ctx->eo_cells[p] = 0;
            marked = v != 0;
            m = mask ^ v;
        }
        if (marked) {
            if (mask && p > start)
                next = span_out(r, y, start, p - start, mask, t); /* p <= W */
            mask = m;
            start = p;
        }
        t = next;
    }
    /* the flush step: after xmax every closed polygon's mask is zero */
    uint64_t next = t + 1;
    if (mask && start < r->w) {
        const int32_t end = xmax + 1 < r->w ? xmax + 1 : r->w;
        next = span_out(r, y, start, end - start, mask, t);
    }
    r->t = next;
}

/* -------------------------------------------------------------- the rows */

uint64_t ef_trace_rows(ef_ctx *ctx, ef_image *img, ef_rule rule, const uint8_t premul[4], uint8_t alpha,
                       int32_t row_min, int32_t row_max, uint64_t t0)
{
    const int overlap = ctx->trace->schedule == EF_SCHEDULE_OVERLAP;
    raster r = { .ctx = ctx,
                 .tr = ctx->trace,
                 .img = img,
                 .nz = rule == EF_RULE_NONZERO,
                 .ns = ctx->samples,
                 .w = ctx->width,
                 .t = t0,
                 .cov_free = 0,
                 .drained = t0,
                 .premul = premul,
                 .alpha = alpha,
                 .overlap = overlap,
                 .plotted = ctx->trace->plotted,
                 .nspan = 0 };
    const int32_t ns = ctx->samples, h = ctx->h, c = ctx->c, w256 = ctx->width * EF_DEV_ONE;
    for (int32_t row = row_min; row <= row_max; row++) {
        uint32_t nnew;
        const int32_t head = ef_et_take(ctx, row, &nnew);
        if (ctx->naet == 0 && head < 0)
            continue; /* costs no cycle */
        for (int32_t idx = head; idx >= 0; idx = ctx->edges[idx].next) {
            const uint64_t v[2] = { (uint64_t)row, (uint64_t)(ctx->nedges - 1u - (uint32_t)idx) };
            transfer(&r, EF_IF_ET_RD, r.t++, v);
        }
        /* the first plot at t + n + L_PLOT, or t + n + L_REC + L_PLOT with new edges (microarch 3.6):
         * the AET's record register, then PLOT's two registers */
        r.t += EF_L_PLOT + (head >= 0 ? EF_L_REC : 0);
        const int32_t base = row * ns, end = base + ns - 1;
        int32_t xmin = INT32_MAX, xmax = -1;
        uint32_t kept = 0;
        for (uint32_t k = 0; k < ctx->naet; k++) { /* active from earlier rows, AET order */
            const int32_t idx = ctx->aet[k];
            ef_edge *E = &ctx->edges[idx];
            plot_edge(&r, E, row, 0, (E->r1 < end ? E->r1 : end) - base, &xmin, &xmax);
            if (E->r1 > end)
                ctx->aet[kept++] = idx;
        }
        for (int32_t idx = head; idx >= 0; idx = ctx->edges[idx].next) { /* new, input order */
            ef_edge *E = &ctx->edges[idx];
            ef_dda_start(E, h, c, w256, ns - 1, 0);
            plot_edge(&r, E, row, E->r0 - base, (E->r1 < end ? E->r1 : end) - base, &xmin, &xmax);
            if (E->r1 > end)
                ctx->aet[kept++] = idx;
        }
        ctx->naet = kept;
        plot_last(&r);
        scan(&r, row, xmin, xmax);
    }
    return r.drained > r.t ? r.drained : r.t;
}
