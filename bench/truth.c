/*
 * truth.c - the reference for the quality comparison: exact point sampling
 * on a dense 64 x 64 grid per pixel, in integers.
 *
 * The frame's vertices are multiples of 1/256 px, so they are taken as Q16.8
 * integers.  Sample (a, b) of pixel (i, j) sits at
 * (i + (2a+1)/128, j + (2b+1)/128) px, i.e. at X = 4g + 2, Y = 4r + 2 in
 * 1/256 px with g = 64i + a, r = 64j + b: also an integer.  A sample counts
 * an edge when the edge crosses its row (y0 <= Y < y1, half-open, as in
 * docs/spec.md 5.1) at x_c <= X; with x_c = (x0*dy + (Y-y0)*dx) / dy exactly,
 * the first sample that counts it is g = ceil((n - 2dy) / (4dy)), n the
 * numerator: no rounding anywhere.  The winding number is the exact sum of
 * directions (no counter width), the rule applied to it, the covered samples
 * counted per pixel and turned into alpha = floor(255 * count / 4096 + 1/2),
 * composited with docs/spec.md section 8 like the renderers under test.
 * Slow (it sweeps 64 sample rows per pixel row), for quality only.
 */
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define TSS 64 /* samples per pixel side */

typedef struct tedge {
    int64_t x0, y0, dx, dy; /* upper end point, dy > 0, Q16.8 */
    int32_t r0, r1;         /* first and last sample row (global, inclusive) */
    int dir;
} tedge;

typedef struct xing {
    int64_t g;
    int dir;
} xing;

typedef struct truth_state {
    bcanvas cv;
    tedge *e;
    size_t cap_e;
    int32_t *act; /* active edge indices */
    xing *xs;
    uint16_t *count; /* covered samples per pixel of the row */
    uint8_t *cov;
} truth_state;

static int64_t floordiv(int64_t a, int64_t d) /* d > 0 */
{
    int64_t q = a / d;
    return (a % d != 0 && a < 0) ? q - 1 : q;
}
static int64_t ceildiv(int64_t a, int64_t d) { return -floordiv(-a, d); }

static int cmp_r0(const void *a, const void *b)
{
    const tedge *x = a, *y = b;
    return (x->r0 > y->r0) - (x->r0 < y->r0);
}

static void *truth_create(int w, int h)
{
    truth_state *st = calloc(1, sizeof *st);
    if (!st || bcanvas_init(&st->cv, w, h)) {
        free(st);
        return NULL;
    }
    st->count = calloc((size_t)w, sizeof *st->count);
    st->cov = calloc((size_t)w, 1);
    return st;
}

static void truth_clear(void *p)
{
    truth_state *st = p;
    memset(st->cv.px, 0, st->cv.stride * (size_t)st->cv.h);
}

static void add_run(uint16_t *count, int64_t ga, int64_t gb) /* samples [ga, gb) */
{
    int64_t pa = ga / TSS, pb = (gb - 1) / TSS;
    if (pa == pb) {
        count[pa] += (uint16_t)(gb - ga);
        return;
    }
    count[pa] += (uint16_t)(TSS * (pa + 1) - ga);
    for (int64_t p = pa + 1; p < pb; p++)
        count[p] += TSS;
    count[pb] += (uint16_t)(gb - TSS * pb);
}

static void truth_shape(truth_state *st, const bscene *s, const bpoint *pts, const bshape *sh)
{
    const int W = st->cv.w, H = st->cv.h;
    const int64_t GW = (int64_t)W * TSS;
    uint32_t a = s->start[sh->first], b = s->start[sh->first + sh->ncontours];
    if (b - a > st->cap_e) {
        free(st->e);
        free(st->act);
        free(st->xs);
        st->cap_e = b - a;
        st->e = malloc(st->cap_e * sizeof *st->e);
        st->act = malloc(st->cap_e * sizeof *st->act);
        st->xs = malloc(st->cap_e * sizeof *st->xs);
        if (!st->e || !st->act || !st->xs) {
            st->cap_e = 0;
            return;
        }
    }
    size_t ne = 0;
    for (uint32_t c = sh->first; c < sh->first + sh->ncontours; c++) {
        uint32_t c0 = s->start[c], c1 = s->start[c + 1];
        for (uint32_t k = c0; k < c1; k++) {
            const bpoint *p = &pts[k], *q = &pts[k + 1 < c1 ? k + 1 : c0];
            int64_t xa = (int64_t)(p->x * 256.0), ya = (int64_t)(p->y * 256.0);
            int64_t xb = (int64_t)(q->x * 256.0), yb = (int64_t)(q->y * 256.0);
            if (ya == yb)
                continue;
            tedge *E = &st->e[ne];
            E->dir = ya < yb ? 1 : -1;
            if (ya > yb) {
                int64_t t = xa;
                xa = xb;
                xb = t;
                t = ya;
                ya = yb;
                yb = t;
            }
            /* Rows r with ya <= 4r + 2 < yb. */
            int64_t r0 = ceildiv(ya - 2, 4), r1 = ceildiv(yb - 2, 4) - 1;
            if (r0 < 0)
                r0 = 0;
            if (r1 > (int64_t)H * TSS - 1)
                r1 = (int64_t)H * TSS - 1;
            if (r0 > r1)
                continue;
            E->x0 = xa;
            E->y0 = ya;
            E->dx = xb - xa;
            E->dy = yb - ya;
            E->r0 = (int32_t)r0;
            E->r1 = (int32_t)r1;
            ne++;
        }
    }
    if (ne == 0)
        return;
    qsort(st->e, ne, sizeof *st->e, cmp_r0);
    size_t next = 0, nact = 0;
    for (int32_t j = st->e[0].r0 / TSS; j < H; j++) {
        if (nact == 0) {
            if (next == ne)
                break;
            if (st->e[next].r0 / TSS > j)
                j = st->e[next].r0 / TSS; /* skip rows without edges */
        }
        memset(st->count, 0, (size_t)W * sizeof *st->count);
        int64_t lo = GW, hi = 0;
        for (int32_t r = j * TSS; r < (j + 1) * TSS; r++) {
            while (next < ne && st->e[next].r0 == r)
                st->act[nact++] = (int32_t)next++;
            size_t w = 0, nx = 0;
            const int64_t Y = 4 * (int64_t)r + 2;
            for (size_t k = 0; k < nact; k++) {
                const tedge *E = &st->e[st->act[k]];
                if (E->r1 < r)
                    continue; /* finished */
                st->act[w++] = st->act[k];
                int64_t n = E->x0 * E->dy + (Y - E->y0) * E->dx;
                xing x = { ceildiv(n - 2 * E->dy, 4 * E->dy), E->dir };
                /* insertion sort: rows change slowly, so this is near O(n) */
                size_t i = nx++;
                while (i > 0 && st->xs[i - 1].g > x.g) {
                    st->xs[i] = st->xs[i - 1];
                    i--;
                }
                st->xs[i] = x;
            }
            nact = w;
            int64_t wind = 0;
            for (size_t k = 0; k + 1 < nx; k++) {
                wind += st->xs[k].dir;
                int in = sh->rule == B_EVENODD ? (int)(wind & 1) : wind != 0;
                if (!in)
                    continue;
                int64_t ga = st->xs[k].g, gb = st->xs[k + 1].g;
                if (ga < 0)
                    ga = 0;
                if (gb > GW)
                    gb = GW;
                if (gb <= ga)
                    continue;
                add_run(st->count, ga, gb);
                if (ga < lo)
                    lo = ga;
                if (gb > hi)
                    hi = gb;
            }
        }
        if (hi <= lo)
            continue;
        int px0 = (int)(lo / TSS), px1 = (int)((hi - 1) / TSS);
        for (int x = px0; x <= px1; x++)
            st->cov[x] = (uint8_t)((255u * st->count[x] + TSS * TSS / 2) / (TSS * TSS));
        bblend_hspan(&st->cv, sh, px0, j, px1 - px0 + 1, st->cov + px0);
    }
}

static void truth_render(void *p, const bscene *s, const bpoint *pts)
{
    truth_state *st = p;
    for (uint32_t i = 0; i < s->nshapes; i++)
        truth_shape(st, s, pts, &s->shapes[i]);
}

static void truth_read(void *p, uint8_t *rgba)
{
    truth_state *st = p;
    memcpy(rgba, st->cv.px, st->cv.stride * (size_t)st->cv.h);
}

static void truth_destroy(void *p)
{
    truth_state *st = p;
    if (!st)
        return;
    bcanvas_free(&st->cv);
    free(st->e);
    free(st->act);
    free(st->xs);
    free(st->count);
    free(st->cov);
    free(st);
}

static const char *truth_unsupported(const bscene *s)
{
    (void)s;
    return NULL;
}

const brenderer br_truth = { "truth",      truth_unsupported, truth_create, truth_clear,
                             truth_render, truth_read,        truth_destroy };
