/*
 * r_stb.c - stb_truetype's rasterizer (Debian's libstb-dev header, version 2
 * rasterizer: signed-area accumulation in float) as a benchmark renderer.
 * stbtt_Rasterize draws one shape into an 8-bit bitmap of the shape's
 * bounding box (clipped to the canvas), which is then composited row by row
 * (docs/spec.md section 8).  The vertex type is redefined to float: the
 * default `short` would round every vertex to a whole pixel (float holds a
 * multiple of 1/256 px exactly below 65536 px).  stb only knows the non-zero
 * rule, so scenes with an even-odd shape are reported unsupported.  stb
 * allocates its edge and point lists on every call: that is its API.  Its
 * assertions are compiled out (see below).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wstrict-prototypes"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#endif
#define stbtt_vertex_type float
typedef struct {
    float x, y, cx, cy, cx1, cy1;
    unsigned char type, padding;
} bench_stbtt_vertex;
#define stbtt_vertex bench_stbtt_vertex
#define STBTT_STATIC
/* Release behaviour: one of stb's internal asserts fires on the 46,000-point
 * shape of lorem_ipsum_compound (float rounding); with assertions off, as in
 * any NDEBUG build, it draws on. */
#define STBTT_assert(x) ((void)0)
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb/stb_truetype.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

typedef struct stb_state {
    bcanvas cv;
    bench_stbtt_vertex *v;
    uint32_t cap_v;
    uint8_t *bm;
    size_t cap_bm;
} stb_state;

static void *stb_create(int w, int h)
{
    stb_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->cap_bm = (size_t)w * (size_t)h;
    st->bm = malloc(st->cap_bm);
    if (!st->bm || bcanvas_init(&st->cv, w, h)) {
        free(st->bm);
        free(st);
        return NULL;
    }
    return st;
}

static void stb_clear(void *p)
{
    stb_state *st = p;
    memset(st->cv.px, 0, st->cv.stride * (size_t)st->cv.h);
}

static void stb_render(void *p, const bscene *s, const bpoint *pts)
{
    stb_state *st = p;
    if (s->max_shape_points > st->cap_v) {
        /* Grows once, in the untimed warm-up frame. */
        free(st->v);
        st->v = calloc(s->max_shape_points, sizeof *st->v);
        st->cap_v = st->v ? s->max_shape_points : 0;
        if (!st->v)
            return;
    }
    const int W = st->cv.w, H = st->cv.h;
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape *sh = &s->shapes[i];
        uint32_t a = s->start[sh->first], b = s->start[sh->first + sh->ncontours];
        if (a == b)
            continue;
        double x0 = pts[a].x, x1 = x0, y0 = pts[a].y, y1 = y0;
        for (uint32_t k = a; k < b; k++) {
            x0 = fmin(x0, pts[k].x);
            x1 = fmax(x1, pts[k].x);
            y0 = fmin(y0, pts[k].y);
            y1 = fmax(y1, pts[k].y);
        }
        int bx0 = (int)fmax(0, floor(x0)), by0 = (int)fmax(0, floor(y0));
        int bx1 = (int)fmin(W, ceil(x1)), by1 = (int)fmin(H, ceil(y1));
        if (bx0 >= bx1 || by0 >= by1)
            continue;
        int bw = bx1 - bx0, bh = by1 - by0;
        for (uint32_t c = sh->first; c < sh->first + sh->ncontours; c++)
            for (uint32_t k = s->start[c]; k < s->start[c + 1]; k++) {
                bench_stbtt_vertex *v = &st->v[k - a];
                v->type = k == s->start[c] ? STBTT_vmove : STBTT_vline;
                v->x = (float)pts[k].x;
                v->y = (float)pts[k].y;
            }
        stbtt__bitmap r;
        r.w = bw;
        r.h = bh;
        r.stride = bw;
        r.pixels = st->bm;
        /* stb maps y to y * scale + shift - y_off.  It clamps edges above the
         * bitmap only when y_off != 0 (else it asserts), so shift by one and
         * take y_off = by0 + 1: the same pixels, y_off never 0. */
        stbtt_Rasterize(&r, 0.35f, st->v, (int)(b - a), 1.0f, 1.0f, 0.0f, 1.0f, bx0, by0 + 1, 0, NULL);
        for (int y = 0; y < bh; y++)
            bblend_hspan(&st->cv, sh, bx0, by0 + y, bw, st->bm + (size_t)y * (size_t)bw);
    }
}

static void stb_read(void *p, uint8_t *rgba)
{
    stb_state *st = p;
    memcpy(rgba, st->cv.px, st->cv.stride * (size_t)st->cv.h);
}

static void stb_destroy(void *p)
{
    stb_state *st = p;
    if (!st)
        return;
    bcanvas_free(&st->cv);
    free(st->v);
    free(st->bm);
    free(st);
}

static const char *stb_unsupported(const bscene *s)
{
    return s->has_evenodd ? "stb_truetype rasterizes the non-zero rule only" : NULL;
}

const brenderer br_stb = { "stb", stb_unsupported, stb_create, stb_clear, stb_render, stb_read, stb_destroy };
