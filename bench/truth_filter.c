/*
 * truth_filter.c - the dense references for docs/spec.md section 10: the
 * same exact 64 x 64 point sampling per pixel as truth.c (samples at
 * X = 4g + 2, Y = 4r + 2 in 1/256 px, exact crossings, exact windings), but
 * weighted by the filter of the renderer under test and per channel:
 *   tent: weight (1 - |X - Xc|/256)(1 - |Y - Yc|/256) around the centre
 *         Xc = 256 i + 128 + delta_c, Yc = 256 j + 128 (a 2x2-pixel base),
 *   box:  weight 1 on [256 i + delta_c, 256 i + 256 + delta_c) x the row,
 * with delta = -85, 0, +85 for R, G, B (RGB stripes) or 0.  Samples run past
 * the canvas as far as a support reaches, as the model's mask canvas does.
 * Each channel's coverage is its weighted sum over the weight of a full
 * support, alpha = floor(255 cov + 1/2), composited by spec 10.4.  Every
 * covered run of a sample row adds to the pixels it meets in closed form
 * (sums of arithmetic sequences), in double precision: a reference, outside
 * the integer-only model.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define TSS 64
#define PAD 64 /* samples past each canvas side (half a pixel is 32; margin) */

typedef struct fedge {
    int64_t x0, y0, dx, dy;
    int64_t r0, r1;
    int dir;
} fedge;

typedef struct ft_state {
    bcanvas cv;
    int tent, nch;
    int32_t delta[3]; /* R, G, B */
    double full[3];   /* weight of a full support, per channel */
    double *acc;      /* W * H * 3 */
    fedge *e;
    size_t cap;
    int64_t *xs;
    int *xd;
} ft_state;

static int64_t fdiv(int64_t a, int64_t d) { return a / d - (a % d != 0 && a < 0); }
static int64_t cdiv(int64_t a, int64_t d) { return -fdiv(-a, d); }

/* Sum over integer g in [l, h] of (A + B g). */
static double lin_sum(int64_t l, int64_t h, double A, double B)
{
    if (h < l)
        return 0;
    const double n = (double)(h - l + 1);
    return n * A + B * (double)(l + h) * n / 2;
}

/* Weighted count of samples g in [ga, gb) for the support of pixel column i. */
static double xweight(const ft_state *st, int64_t ga, int64_t gb, int64_t i, int32_t delta)
{
    gb--;
    if (!st->tent) {
        const int64_t lo = cdiv(256 * i + delta - 2, 4), hi = cdiv(256 * i + 256 + delta - 2, 4) - 1;
        const int64_t l = ga > lo ? ga : lo, h = gb < hi ? gb : hi;
        return h >= l ? (double)(h - l + 1) : 0;
    }
    const int64_t Xc = 256 * i + 128 + delta;
    const int64_t l1 = fdiv(Xc - 258, 4) + 1, h1 = fdiv(Xc - 2, 4); /* Xc - 256 < X <= Xc */
    const int64_t l2 = h1 + 1, h2 = cdiv(Xc + 254, 4) - 1;          /* Xc < X < Xc + 256 */
    double s = 0;
    /* left: (256 - Xc + 4g + 2)/256; right: (256 + Xc - 4g - 2)/256 */
    s += lin_sum(ga > l1 ? ga : l1, gb < h1 ? gb : h1, (256.0 - (double)Xc + 2) / 256, 4.0 / 256);
    s += lin_sum(ga > l2 ? ga : l2, gb < h2 ? gb : h2, (256.0 + (double)Xc - 2) / 256, -4.0 / 256);
    return s;
}

static void *ft_create(int w, int h, int tent, int rgb)
{
    ft_state *st = calloc(1, sizeof *st);
    if (!st || bcanvas_init(&st->cv, w, h)) {
        free(st);
        return NULL;
    }
    st->tent = tent;
    st->nch = rgb ? 3 : 1;
    for (int c = 0; c < 3; c++)
        st->delta[c] = rgb ? (c - 1) * 85 : 0;
    for (int c = 0; c < 3; c++) /* a run over everything, for pixel column 8 (any works) */
        st->full[c] = xweight(st, -1000000, 1000000, 8, st->delta[c]) * (double)TSS;
    st->acc = calloc((size_t)w * (size_t)h * 3, sizeof *st->acc);
    if (!st->acc) {
        bcanvas_free(&st->cv);
        free(st);
        return NULL;
    }
    return st;
}
static void *ft_create_tent(int w, int h) { return ft_create(w, h, 1, 0); }
static void *ft_create_rgb(int w, int h) { return ft_create(w, h, 0, 1); }
static void *ft_create_trgb(int w, int h) { return ft_create(w, h, 1, 1); }

static void ft_clear(void *p)
{
    ft_state *st = p;
    memset(st->cv.px, 0, st->cv.stride * (size_t)st->cv.h);
}

static uint8_t mul255(unsigned a, unsigned b)
{
    unsigned t = a * b + 128;
    return (uint8_t)(((t >> 8) + t) >> 8);
}

static void ft_shape(ft_state *st, const bscene *s, const bpoint *pts, const bshape *sh)
{
    const int W = st->cv.w, H = st->cv.h;
    const uint32_t a = s->start[sh->first], b = s->start[sh->first + sh->ncontours];
    if (b - a > st->cap) {
        free(st->e);
        free(st->xs);
        free(st->xd);
        st->cap = b - a;
        st->e = malloc(st->cap * sizeof *st->e);
        st->xs = malloc(st->cap * sizeof *st->xs);
        st->xd = malloc(st->cap * sizeof *st->xd);
        if (!st->e || !st->xs || !st->xd) {
            st->cap = 0;
            return;
        }
    }
    const int64_t rmin = -PAD, rmax = (int64_t)H * TSS + PAD - 1;
    const int64_t gmin = -PAD, gmax = (int64_t)W * TSS + PAD;
    size_t ne = 0;
    int64_t ylo = INT64_MAX, yhi = INT64_MIN;
    for (uint32_t c = sh->first; c < sh->first + sh->ncontours; c++) {
        const uint32_t c0 = s->start[c], c1 = s->start[c + 1];
        for (uint32_t k = c0; k < c1; k++) {
            const bpoint *p = &pts[k], *q = &pts[k + 1 < c1 ? k + 1 : c0];
            int64_t xa = (int64_t)(p->x * 256.0), ya = (int64_t)(p->y * 256.0);
            int64_t xb = (int64_t)(q->x * 256.0), yb = (int64_t)(q->y * 256.0);
            if (ya == yb)
                continue;
            fedge *E = &st->e[ne];
            E->dir = ya < yb ? 1 : -1;
            if (ya > yb) {
                int64_t t = xa;
                xa = xb, xb = t;
                t = ya;
                ya = yb, yb = t;
            }
            E->r0 = cdiv(ya - 2, 4);
            E->r1 = cdiv(yb - 2, 4) - 1;
            E->r0 = E->r0 < rmin ? rmin : E->r0;
            E->r1 = E->r1 > rmax ? rmax : E->r1;
            if (E->r0 > E->r1)
                continue;
            E->x0 = xa, E->y0 = ya, E->dx = xb - xa, E->dy = yb - ya;
            ylo = E->r0 < ylo ? E->r0 : ylo;
            yhi = E->r1 > yhi ? E->r1 : yhi;
            ne++;
        }
    }
    if (!ne)
        return;
    int jlo = H, jhi = -1;
    for (int64_t r = ylo; r <= yhi; r++) {
        const int64_t Y = 4 * r + 2;
        size_t nx = 0;
        for (size_t k = 0; k < ne; k++) { /* every edge crossing the row, sorted */
            const fedge *E = &st->e[k];
            if (r < E->r0 || r > E->r1)
                continue;
            const int64_t n = E->x0 * E->dy + (Y - E->y0) * E->dx, g = cdiv(n - 2 * E->dy, 4 * E->dy);
            size_t i = nx++;
            while (i > 0 && st->xs[i - 1] > g) {
                st->xs[i] = st->xs[i - 1];
                st->xd[i] = st->xd[i - 1];
                i--;
            }
            st->xs[i] = g;
            st->xd[i] = E->dir;
        }
        /* output rows this sample row weighs into, with their y weights */
        int js[2], nj = 0;
        double wy[2];
        if (st->tent) {
            const int64_t j0 = fdiv(Y - 128, 256);
            for (int64_t j = j0; j <= j0 + 1; j++) {
                const double d = fabs((double)(Y - (256 * j + 128))) / 256;
                if (j >= 0 && j < H && d < 1) {
                    js[nj] = (int)j;
                    wy[nj++] = 1 - d;
                }
            }
        } else if (r >= 0 && r < (int64_t)H * TSS) {
            js[nj] = (int)(r / TSS);
            wy[nj++] = 1;
        }
        if (!nj)
            continue;
        int64_t wind = 0;
        for (size_t k = 0; k + 1 < nx; k++) {
            wind += st->xd[k];
            if (!(sh->rule == B_EVENODD ? (wind & 1) : wind != 0))
                continue;
            int64_t ga = st->xs[k] < gmin ? gmin : st->xs[k], gb = st->xs[k + 1] > gmax ? gmax : st->xs[k + 1];
            if (gb <= ga)
                continue;
            for (int c = 0; c < st->nch; c++) {
                const int32_t d = st->delta[c];
                int64_t i0 = fdiv(4 * ga + 2 - d - 384, 256), i1 = fdiv(4 * (gb - 1) + 2 - d + 256, 256);
                i0 = i0 < 0 ? 0 : i0;
                i1 = i1 > W - 1 ? W - 1 : i1;
                for (int64_t i = i0; i <= i1; i++) {
                    const double wx = xweight(st, ga, gb, i, d);
                    if (wx == 0)
                        continue;
                    for (int q = 0; q < nj; q++)
                        st->acc[((size_t)js[q] * (size_t)W + (size_t)i) * 3 + (size_t)c] += wx * wy[q];
                }
            }
            for (int q = 0; q < nj; q++) {
                jlo = js[q] < jlo ? js[q] : jlo;
                jhi = js[q] > jhi ? js[q] : jhi;
            }
        }
    }
    /* alpha per channel and spec 10.4 */
    const uint8_t P[4] = { mul255(sh->r, sh->a), mul255(sh->g, sh->a), mul255(sh->b, sh->a), sh->a };
    for (int j = jlo; j <= jhi; j++)
        for (int i = 0; i < W; i++) {
            double *A = &st->acc[((size_t)j * (size_t)W + (size_t)i) * 3];
            uint8_t cov[4];
            for (int c = 0; c < 3; c++) {
                const int cc = st->nch == 3 ? c : 0;
                const double v = A[cc] / st->full[cc];
                cov[c] = (uint8_t)floor(255 * (v > 1 ? 1 : v) + 0.5);
            }
            cov[3] = cov[1];
            A[0] = A[1] = A[2] = 0;
            if (!(cov[0] | cov[1] | cov[2]))
                continue;
            uint8_t *d = st->cv.px + (size_t)j * st->cv.stride + (size_t)i * 4;
            for (int ch = 0; ch < 4; ch++)
                d[ch] = (uint8_t)(d[ch] + mul255(P[ch], cov[ch]) - mul255(d[ch], mul255(sh->a, cov[ch])));
        }
}

static void ft_render(void *p, const bscene *s, const bpoint *pts)
{
    ft_state *st = p;
    for (uint32_t i = 0; i < s->nshapes; i++)
        ft_shape(st, s, pts, &s->shapes[i]);
}

static void ft_read(void *p, uint8_t *rgba)
{
    ft_state *st = p;
    memcpy(rgba, st->cv.px, st->cv.stride * (size_t)st->cv.h);
}

static void ft_destroy(void *p)
{
    ft_state *st = p;
    if (!st)
        return;
    bcanvas_free(&st->cv);
    free(st->acc);
    free(st->e);
    free(st->xs);
    free(st->xd);
    free(st);
}

static const char *ft_unsupported(const bscene *s)
{
    (void)s;
    return NULL;
}

const brenderer br_truth_tent = {
    "truth-tent", ft_unsupported, ft_create_tent, ft_clear, ft_render, ft_read, ft_destroy
};
const brenderer br_truth_rgb = { "truth-rgb", ft_unsupported, ft_create_rgb, ft_clear, ft_render, ft_read, ft_destroy };
const brenderer br_truth_trgb = {
    "truth-trgb", ft_unsupported, ft_create_trgb, ft_clear, ft_render, ft_read, ft_destroy
};

const brenderer *bench_truth_of(const brenderer *r)
{
    if (r == &br_ef8t || r == &br_ef16t || r == &br_ef32t)
        return &br_truth_tent;
    if (r == &br_ef16rgb)
        return &br_truth_rgb;
    if (r == &br_ef16trgb)
        return &br_truth_trgb;
    return &br_truth;
}
