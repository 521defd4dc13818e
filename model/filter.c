/*
 * filter.c - the section 3.5 options (docs/spec.md section 10): per-channel
 * sample offsets and the 2x2-pixel tent filter, computed from the filled
 * scanline masks with one saved mask line per channel (section 3.6's
 * scanline approach kept: no frame-sized buffer).
 *
 * How: a channel's samples sit at the spec's positions shifted by
 * (sx, sy) = (delta_c - t, -t), t = 1/2 px for the tent and 0 for the box.
 * Shifting every sample by (sx, sy) is, exactly and with the same tie rule,
 * shifting the geometry by (-sx, -sy), which is a Q16.8 integer: so each
 * channel runs the unchanged blocks (edge setup, plotter, fillers) on its own
 * context, over the polygon translated by (-sx, -sy), on a (W+e) x (H+e) mask
 * canvas (e = 1 for the tent: its base reaches half a pixel past every side).
 * The channels step through the rows together; after mask row q is filled,
 * output row q (box) or q - 1 (tent, from the saved line q - 1 and line q)
 * is weighted with per-byte tables (the paper's "table lookups") and
 * composited.
 */
#include <stdlib.h>
#include <string.h>

#include "filter_internal.h"

void ef_filt_free(struct ef_filt *f)
{
    if (!f)
        return;
    for (int c = 0; c < 3; c++) {
        ef_ctx_destroy(f->ch[c]);
        free(f->line[c][0]);
        free(f->line[c][1]);
        free(f->iv[c][0]);
        free(f->iv[c][1]);
    }
    free(f->tab);
    free(f->sum);
    free(f->merge);
    free(f->pts);
    free(f);
}

ef_status ef_ctx_set_filter(ef_ctx *ctx, ef_filter filter, ef_subpixel subpixel)
{
    if (!ctx || (filter != EF_FILTER_BOX && filter != EF_FILTER_TENT) ||
        (subpixel != EF_SUBPIXEL_NONE && subpixel != EF_SUBPIXEL_RGB && subpixel != EF_SUBPIXEL_BGR))
        return EF_ERR_ARG;
    ef_filt_free(ctx->filt);
    ctx->filt = NULL;
    if (filter == EF_FILTER_BOX && subpixel == EF_SUBPIXEL_NONE)
        return EF_OK; /* the default: ef_fill's own path */
    struct ef_filt *f = calloc(1, sizeof *f);
    if (!f)
        return EF_ERR_NOMEM;
    f->filter = filter;
    f->subpixel = subpixel;
    f->nch = subpixel == EF_SUBPIXEL_NONE ? 1 : 3;
    f->e = filter == EF_FILTER_TENT;
    const int32_t wm = ctx->width + f->e, hm = ctx->height + f->e;
    const int32_t t = f->e ? EF_DEV_ONE / 2 : 0;
    f->ty = t;
    for (int c = 0; c < 3; c++)
        f->pos_of_colour[c] = f->nch == 1 ? 0 : subpixel == EF_SUBPIXEL_RGB ? c : 2 - c;
    ef_status st = EF_OK;
    for (int p = 0; p < f->nch && st == EF_OK; p++) {
        const int32_t delta = f->nch == 1 ? 0 : (p - 1) * EF_SUBPIXEL_SHIFT;
        f->tx[p] = t - delta; /* samples move by delta - t: geometry by t - delta */
        st = ef_ctx_create(&f->ch[p], wm, hm, ctx->samples);
        f->line[p][0] = calloc((size_t)wm, sizeof(uint32_t));
        f->line[p][1] = calloc((size_t)wm, sizeof(uint32_t));
        f->iv[p][0] = malloc((size_t)wm * 2 * sizeof(int32_t));
        f->iv[p][1] = malloc((size_t)wm * 2 * sizeof(int32_t));
        if (st == EF_OK && (!f->line[p][0] || !f->line[p][1] || !f->iv[p][0] || !f->iv[p][1]))
            st = EF_ERR_NOMEM;
        f->lo[p][0] = f->lo[p][1] = INT32_MAX;
        f->hi[p][0] = f->hi[p][1] = -1;
    }
    f->sum = calloc((size_t)ctx->width * 3, sizeof(uint32_t));
    f->merge = malloc((size_t)(wm + 1) * 12 * sizeof(int32_t));
    if (st == EF_OK && (!f->sum || !f->merge))
        st = EF_ERR_NOMEM;
    if (st == EF_OK && f->e) {
        /* Tent weights (spec 10.2): sample s (column k_s) of the base's pixel
         * (a, b) weighs X_a(k_s) * Y_b(s), X_0(k) = 2k+1, X_1(k) = 2N-2k-1,
         * Y the same in s; tables by byte of the mask. */
        const int n = ctx->samples, groups = n / 8;
        const uint8_t *k = ef_pattern(n);
        f->tab = calloc((size_t)4 * (size_t)groups * 256, sizeof(uint32_t));
        if (!f->tab)
            st = EF_ERR_NOMEM;
        for (int ab = 0; st == EF_OK && ab < 4; ab++)
            for (int g = 0; g < groups; g++)
                for (int v = 0; v < 256; v++) {
                    uint32_t w = 0;
                    for (int bit = 0; bit < 8; bit++) {
                        if (!(v >> bit & 1))
                            continue;
                        const int s = 8 * g + bit;
                        const uint32_t wx = (ab >> 1) ? (uint32_t)(2 * n - 2 * k[s] - 1) : (uint32_t)(2 * k[s] + 1);
                        const uint32_t wy = (ab & 1) ? (uint32_t)(2 * n - 2 * s - 1) : (uint32_t)(2 * s + 1);
                        w += wx * wy;
                    }
                    f->tab[((size_t)ab * (size_t)groups + (size_t)g) * 256 + (size_t)v] = w;
                }
    }
    if (st != EF_OK) {
        ef_filt_free(f);
        return st;
    }
    ctx->filt = f;
    return EF_OK;
}

void ef_ctx_get_filter(const ef_ctx *ctx, ef_filter *filter, ef_subpixel *subpixel)
{
    *filter = ctx->filt ? (ef_filter)ctx->filt->filter : EF_FILTER_BOX;
    *subpixel = ctx->filt ? (ef_subpixel)ctx->filt->subpixel : EF_SUBPIXEL_NONE;
}

uint32_t ef_filter_denominator(const ef_ctx *ctx)
{
    const uint32_t n = (uint32_t)ctx->samples;
    return ctx->filt && ctx->filt->e ? 4u * n * n * n : n;
}

/* ------------------------------------------------------------ the rows */

typedef struct line_sink {
    uint32_t *m;
    int32_t *lo, *hi;
    int32_t *iv;
    uint32_t *niv;
} line_sink;

static void to_line(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    (void)y;
    line_sink *ls = user;
    for (int32_t i = 0; i < len; i++)
        ls->m[x + i] = mask;
    if (x < *ls->lo)
        *ls->lo = x;
    if (x + len - 1 > *ls->hi)
        *ls->hi = x + len - 1;
    ls->iv[2 * *ls->niv] = x;
    ls->iv[2 * *ls->niv + 1] = x + len - 1;
    ++*ls->niv;
}

/* One mask row of a channel context: rasterize.c's loop body. */
static void mask_row(ef_ctx *sc, int32_t row, int evenodd, line_sink *ls)
{
    uint32_t nnew;
    const int32_t head = ef_et_take(sc, row, &nnew);
    if (sc->naet == 0 && head < 0)
        return;
    int32_t xmin = INT32_MAX, xmax = -1;
    sc->naet_row = sc->naet + nnew;
    if (evenodd)
        ef_plot_evenodd(sc, row, head, &xmin, &xmax);
    else
        ef_plot_nonzero(sc, row, head, &xmin, &xmax);
    if (xmax < 0)
        return;
    if (evenodd)
        ef_fill_evenodd(sc, row, xmin, xmax, to_line, ls, NULL);
    else
        ef_fill_nonzero(sc, row, xmin, xmax, to_line, ls, NULL);
}

static inline uint32_t tent_of(const uint32_t *tab, int groups, int ab, uint32_t m)
{
    const uint32_t *t = tab + (size_t)ab * (size_t)groups * 256;
    uint32_t w = 0;
    for (int g = 0; g < groups; g++, m >>= 8)
        w += t[(size_t)g * 256 + (m & 0xFFu)];
    return w;
}

/* Receives each output row: sums[x*3 + colour] for x in [x0, x1]. */
typedef void (*row_fn)(void *user, int32_t y, int32_t x0, int32_t x1, const uint32_t *sums);

static void clear_line(struct ef_filt *f, int p, int which)
{
    if (f->hi[p][which] >= 0)
        memset(f->line[p][which] + f->lo[p][which], 0,
               (size_t)(f->hi[p][which] - f->lo[p][which] + 1) * sizeof(uint32_t));
    f->lo[p][which] = INT32_MAX;
    f->hi[p][which] = -1;
    f->niv[p][which] = 0;
}

static int cmp_iv(const void *a, const void *b)
{
    const int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Weights output row y from the channels' lines: box from the current line,
 * tent from the saved (upper) and current (lower) ones. */
static void out_row(ef_ctx *ctx, int32_t y, row_fn fn, void *user)
{
    struct ef_filt *f = ctx->filt;
    const int32_t w = ctx->width;
    const int cur = f->cur, up = cur ^ 1;
    /* The columns to weigh: every span of the lines read, widened by e to the
     * left (the tent's pixel x reads columns x and x+1), merged.  Columns
     * outside them have all masks zero: sum 0, nothing to composite. */
    uint32_t n = 0;
    for (int p = 0; p < f->nch; p++)
        for (int l = 0; l <= f->e; l++) {
            const int which = l ? up : cur;
            for (uint32_t k = 0; k < f->niv[p][which]; k++) {
                f->merge[2 * n] = f->iv[p][which][2 * k] - f->e;
                f->merge[2 * n + 1] = f->iv[p][which][2 * k + 1];
                n++;
            }
        }
    if (!n)
        return;
    qsort(f->merge, n, 2 * sizeof(int32_t), cmp_iv);
    const int groups = ctx->samples / 8;
    const uint32_t full = ctx->samples == 32 ? UINT32_MAX : (UINT32_C(1) << ctx->samples) - 1u;
    const uint32_t den = ef_filter_denominator(ctx);
    uint32_t k = 0;
    while (k < n) {
        int32_t lo = f->merge[2 * k], hi = f->merge[2 * k + 1];
        for (k++; k < n && f->merge[2 * k] <= hi + 1; k++)
            hi = f->merge[2 * k + 1] > hi ? f->merge[2 * k + 1] : hi;
        lo = lo < 0 ? 0 : lo;
        hi = hi > w - 1 ? w - 1 : hi;
        if (lo > hi)
            continue;
        uint32_t psum[3] = { 0, 0, 0 };
        for (int32_t x = lo; x <= hi; x++) {
            for (int p = 0; p < f->nch; p++) {
                if (f->e) {
                    const uint32_t *u = f->line[p][up], *d = f->line[p][cur];
                    const uint32_t u0 = u[x], u1 = u[x + 1], d0 = d[x], d1 = d[x + 1];
                    if ((u0 & u1 & d0 & d1) == full)
                        psum[p] = den; /* interior: the whole base covered */
                    else if (!(u0 | u1 | d0 | d1))
                        psum[p] = 0;
                    else
                        psum[p] = tent_of(f->tab, groups, 0, u0) + tent_of(f->tab, groups, 2, u1) +
                                  tent_of(f->tab, groups, 1, d0) + tent_of(f->tab, groups, 3, d1);
                } else {
                    psum[p] = ef_popcount32(f->line[p][cur][x]);
                }
            }
            for (int c = 0; c < 3; c++)
                f->sum[(size_t)x * 3 + (size_t)c] = psum[f->pos_of_colour[c]];
        }
        fn(user, y, lo, hi, f->sum);
    }
}

/* Runs the shape through every channel, row by row, handing each output row
 * to fn. */
static ef_status filter_rows(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, row_fn fn, void *user)
{
    struct ef_filt *f = ctx->filt;
    if (!poly || (rule != EF_RULE_NONZERO && rule != EF_RULE_EVENODD))
        return EF_ERR_ARG;
    const uint32_t npts = poly->ncontours ? poly->start[poly->ncontours] : 0;
    if ((size_t)npts > f->pts_cap) {
        ef_point *np = realloc(f->pts, (size_t)npts * sizeof *np);
        if (!np)
            return EF_ERR_NOMEM;
        f->pts = np;
        f->pts_cap = npts;
    }
    int32_t rmin[3], rmax[3], qmin = INT32_MAX, qmax = -1;
    ef_status st = EF_OK;
    int p = 0;
    for (; p < f->nch; p++) {
        /* The translated copy: vertices are checked by edge setup as usual,
         * so one that the shift takes past +-2^23 is EF_ERR_ARG. */
        for (uint32_t i = 0; i < npts; i++)
            f->pts[i] = (ef_point){ poly->pts[i].x + f->tx[p], poly->pts[i].y + f->ty };
        ef_polygon tp = { f->pts, poly->start, poly->ncontours };
        ef_ctx *sc = f->ch[p];
        ef_et_reset(sc);
        const ef_diag before = sc->diag;
        st = ef_edges_setup(sc, &tp, &rmin[p], &rmax[p]);
        if (p == 0) { /* the shape's edges, counted once (spec 10.5) */
            ctx->diag.edges_in += sc->diag.edges_in - before.edges_in;
            ctx->diag.edges_dropped += sc->diag.edges_dropped - before.edges_dropped;
        }
        if (st != EF_OK)
            break;
        if (rmin[p] <= rmax[p]) {
            qmin = rmin[p] < qmin ? rmin[p] : qmin;
            qmax = rmax[p] > qmax ? rmax[p] : qmax;
        }
    }
    if (st != EF_OK) {
        for (int c = 0; c < p; c++) /* leave the edge tables empty */
            for (int32_t r = rmin[c]; r <= rmax[c]; r++) {
                uint32_t n;
                (void)ef_et_take(f->ch[c], r, &n);
            }
        return st;
    }
    if (qmax < 0)
        return EF_OK;
    const int32_t hm = ctx->height + f->e;
    const int32_t qend = qmax + f->e < hm - 1 ? qmax + f->e : hm - 1;
    const int evenodd = rule == EF_RULE_EVENODD;
    for (int c = 0; c < f->nch; c++) { /* the line above the first row is empty */
        clear_line(f, c, 0);
        clear_line(f, c, 1);
    }
    for (int32_t q = qmin; q <= qend; q++) {
        for (int c = 0; c < f->nch; c++) {
            const uint64_t ov = f->ch[c]->diag.winding_overflows;
            clear_line(f, c, f->cur);
            line_sink ls = { f->line[c][f->cur], &f->lo[c][f->cur], &f->hi[c][f->cur], f->iv[c][f->cur],
                             &f->niv[c][f->cur] };
            mask_row(f->ch[c], q, evenodd, &ls); /* empty slot and AET outside its rows: nothing */
            ctx->diag.winding_overflows += f->ch[c]->diag.winding_overflows - ov;
        }
        if (!f->e)
            out_row(ctx, q, fn, user);
        else if (q >= 1)
            out_row(ctx, q - 1, fn, user);
        f->cur ^= 1;
    }
    return EF_OK;
}

/* ------------------------------------------------------------- outputs */

typedef struct cov_user {
    ef_cov_fn fn;
    void *user;
} cov_user;

static void row_to_cov(void *user, int32_t y, int32_t x0, int32_t x1, const uint32_t *sums)
{
    cov_user *cu = user;
    for (int32_t x = x0; x <= x1; x++) {
        const uint32_t *s = sums + (size_t)x * 3;
        if (s[0] | s[1] | s[2])
            cu->fn(cu->user, y, x, s);
    }
}

ef_status ef_filter_coverage(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_cov_fn fn, void *user)
{
    if (!ctx || !ctx->filt || !fn)
        return EF_ERR_ARG;
    cov_user cu = { fn, user };
    return filter_rows(ctx, poly, rule, row_to_cov, &cu);
}

typedef struct blend_user {
    ef_image *img;
    uint8_t premul[4], a;
    uint32_t den;
    uint64_t p4; /* premul in 4 lanes (internal.h's compositing helpers) */
} blend_user;

/* Spec 10.4: each colour channel blends with its own coverage, alpha with
 * the centre (green) channel's. */
static void row_to_image(void *user, int32_t y, int32_t x0, int32_t x1, const uint32_t *sums)
{
    blend_user *b = user;
    uint8_t *d = b->img->px + (size_t)y * b->img->stride + (size_t)x0 * 4;
    for (int32_t x = x0; x <= x1; x++, d += 4) {
        const uint32_t *s = sums + (size_t)x * 3;
        if (!(s[0] | s[1] | s[2]))
            continue;
        if (b->a == 255 && (s[0] & s[1] & s[2]) == b->den && (s[0] | s[1] | s[2]) == b->den) {
            memcpy(d, b->premul, 4); /* d' = P exactly: mul(d, 255) = d */
            continue;
        }
        uint8_t cov[4];
        for (int c = 0; c < 3; c++)
            cov[c] = (uint8_t)((255u * s[c] + b->den / 2u) / b->den);
        cov[3] = cov[1];
        if (cov[0] == cov[1] && cov[1] == cov[2]) {
            /* one coverage for all four channels: spec 8 in four lanes, as ef_blend_span_n */
            const uint64_t dd = ef_spread4(ef_load32(d));
            const uint32_t v =
                ef_pack4((dd + ef_mul255x4(b->p4, cov[0]) - ef_mul255x4(dd, ef_mul255(b->a, cov[0]))) & EF_LANE8X4);
            memcpy(d, &v, 4);
            continue;
        }
        for (int ch = 0; ch < 4; ch++) {
            const uint32_t sv = ef_mul255(b->premul[ch], cov[ch]), sa = ef_mul255(b->a, cov[ch]);
            d[ch] = (uint8_t)(d[ch] + sv - ef_mul255(d[ch], sa));
        }
    }
}

ef_status ef_filter_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color)
{
    blend_user b = { img,
                     { ef_mul255(color.r, color.a), ef_mul255(color.g, color.a), ef_mul255(color.b, color.a), color.a },
                     color.a,
                     ef_filter_denominator(ctx),
                     0 };
    b.p4 = ef_spread4(ef_load32(b.premul));
    return filter_rows(ctx, poly, rule, row_to_image, &b);
}
