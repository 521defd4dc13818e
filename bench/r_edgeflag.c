/*
 * r_edgeflag.c - edgeflag (this project's model) as a benchmark renderer, at
 * 8, 16 and 32 samples per pixel.  The fill rule is the shape's (the scene
 * carries the rule of the case being measured).
 *
 * Fairness: the peers take the frame's double vertices and convert them to
 * their own fixed point inside their timed calls (AGG and Cairo to 24.8,
 * FreeType to 26.6), so edgeflag does the same: the double -> Q16.8 int32
 * conversion of every vertex is inside the timed render call.  It is exact:
 * the frame transform snaps every vertex to a multiple of 1/256 px, so
 * v * 256 is an integer-valued double below 2^23 in magnitude and the cast
 * does not round.  Compositing is ef_fill's own (docs/spec.md section 8).
 */
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "edgeflag.h"
#include "ef_filter.h"

typedef struct ef_state {
    ef_ctx *ctx;
    ef_image img;
    ef_point *buf; /* the frame's vertices in Q16.8 */
    uint32_t cap;
    int samples;
} ef_state;

static void *ef_create_n(int w, int h, int n)
{
    ef_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->samples = n;
    if (ef_ctx_create(&st->ctx, w, h, n) != EF_OK || ef_image_create(&st->img, w, h) != EF_OK) {
        ef_ctx_destroy(st->ctx);
        free(st);
        return NULL;
    }
    return st;
}
static void *ef_create8(int w, int h) { return ef_create_n(w, h, 8); }
static void *ef_create16(int w, int h) { return ef_create_n(w, h, 16); }
static void *ef_create32(int w, int h) { return ef_create_n(w, h, 32); }

static void ef_clear(void *p)
{
    ef_state *st = p;
    memset(st->img.px, 0, st->img.stride * (size_t)st->img.height);
}

static void ef_render(void *p, const bscene *s, const bpoint *pts)
{
    ef_state *st = p;
    if (s->npoints > st->cap) {
        /* Grows once, in the untimed warm-up frame. */
        free(st->buf);
        st->buf = malloc((size_t)s->npoints * sizeof *st->buf);
        st->cap = st->buf ? s->npoints : 0;
        if (!st->buf)
            return;
    }
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape *sh = &s->shapes[i];
        uint32_t a = s->start[sh->first], b = s->start[sh->first + sh->ncontours];
        for (uint32_t k = a; k < b; k++) {
            st->buf[k].x = (int32_t)(pts[k].x * 256.0);
            st->buf[k].y = (int32_t)(pts[k].y * 256.0);
        }
        ef_polygon poly = { st->buf, s->start + sh->first, sh->ncontours };
        ef_rgba8 col = { sh->r, sh->g, sh->b, sh->a };
        ef_fill(st->ctx, &st->img, &poly, sh->rule == B_EVENODD ? EF_RULE_EVENODD : EF_RULE_NONZERO, col);
    }
}

static void ef_read(void *p, uint8_t *rgba)
{
    ef_state *st = p;
    for (int y = 0; y < st->img.height; y++)
        memcpy(rgba + (size_t)y * st->img.width * 4, st->img.px + (size_t)y * st->img.stride,
               (size_t)st->img.width * 4);
}

static void ef_destroy(void *p)
{
    ef_state *st = p;
    if (!st)
        return;
    ef_ctx_destroy(st->ctx);
    ef_image_destroy(&st->img);
    free(st->buf);
    free(st);
}

static const char *ef_unsupported(const bscene *s)
{
    (void)s;
    return NULL;
}

/* docs/spec.md section 10: the tent filter and the RGB-stripe offsets, for
 * their cost against the box (same N) and their quality against the dense
 * filtered truth (truth_filter.c). */
static void *ef_create_filtered(int w, int h, int n, ef_filter f, ef_subpixel sp)
{
    ef_state *st = ef_create_n(w, h, n);
    if (st && ef_ctx_set_filter(st->ctx, f, sp) != EF_OK) {
        ef_destroy(st);
        return NULL;
    }
    return st;
}
static void *ef_create8t(int w, int h) { return ef_create_filtered(w, h, 8, EF_FILTER_TENT, EF_SUBPIXEL_NONE); }
static void *ef_create16t(int w, int h) { return ef_create_filtered(w, h, 16, EF_FILTER_TENT, EF_SUBPIXEL_NONE); }
static void *ef_create32t(int w, int h) { return ef_create_filtered(w, h, 32, EF_FILTER_TENT, EF_SUBPIXEL_NONE); }
static void *ef_create16rgb(int w, int h) { return ef_create_filtered(w, h, 16, EF_FILTER_BOX, EF_SUBPIXEL_RGB); }
static void *ef_create16trgb(int w, int h) { return ef_create_filtered(w, h, 16, EF_FILTER_TENT, EF_SUBPIXEL_RGB); }

const brenderer br_ef8 = { "ef8", ef_unsupported, ef_create8, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef16 = { "ef16", ef_unsupported, ef_create16, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef32 = { "ef32", ef_unsupported, ef_create32, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef8t = { "ef8t", ef_unsupported, ef_create8t, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef16t = { "ef16t", ef_unsupported, ef_create16t, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef32t = { "ef32t", ef_unsupported, ef_create32t, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef16rgb = { "ef16rgb", ef_unsupported, ef_create16rgb, ef_clear, ef_render, ef_read, ef_destroy };
const brenderer br_ef16trgb = { "ef16trgb", ef_unsupported, ef_create16trgb, ef_clear, ef_render, ef_read, ef_destroy };

/* ---- bit-exactness check (efbench hash): FNV-1a 64 of the image ef_fill
 * composites, of the span stream ef_rasterize reports, and the diagnostics.
 * Two builds of the model agree bit for bit when these agree. ---- */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * UINT64_C(0x100000001b3);
    return h;
}

static void span_hash(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    uint64_t *h = user;
    int32_t v[4] = { y, x, len, (int32_t)mask };
    *h = fnv(*h, v, sizeof v);
}

int bench_ef_hash(int samples, int w, int h, const bscene *s, const bpoint *pts, uint64_t *img_hash, uint64_t *spans,
                  uint64_t diag[3])
{
    ef_state *st = ef_create_n(w, h, samples);
    ef_ctx *ctx2;
    if (!st || ef_ctx_create(&ctx2, w, h, samples) != EF_OK)
        return -1;
    ef_clear(st);
    ef_render(st, s, pts);
    *img_hash = fnv(UINT64_C(0xcbf29ce484222325), st->img.px, st->img.stride * (size_t)h);
    *spans = UINT64_C(0xcbf29ce484222325);
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape *sh = &s->shapes[i];
        ef_polygon poly = { st->buf, s->start + sh->first, sh->ncontours };
        ef_rasterize(ctx2, &poly, sh->rule == B_EVENODD ? EF_RULE_EVENODD : EF_RULE_NONZERO, span_hash, spans);
    }
    ef_diag d1, d2;
    ef_ctx_diag(st->ctx, &d1);
    ef_ctx_diag(ctx2, &d2);
    diag[0] = d1.edges_in;
    diag[1] = d1.edges_dropped;
    diag[2] = d1.winding_overflows;
    int same = d1.edges_in == d2.edges_in && d1.edges_dropped == d2.edges_dropped &&
               d1.winding_overflows == d2.winding_overflows;
    ef_ctx_destroy(ctx2);
    ef_destroy(st);
    return same ? 0 : 1;
}
