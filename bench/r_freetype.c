/*
 * r_freetype.c - FreeType's smooth (gray) rasterizer from Debian's
 * libfreetype as a benchmark renderer: per shape an FT_Outline in 26.6 fixed
 * point (the doubles rounded to 1/64 px inside the timed call: its API's
 * precision), FT_OUTLINE_EVEN_ODD_FILL for even-odd, and
 * FT_Outline_Render with FT_RASTER_FLAG_AA | DIRECT | CLIP: spans go
 * straight to a callback that composites them (docs/spec.md section 8).
 * FT_Outline counts points and contours in a `short`: shapes with more than
 * 32767 of either cannot be drawn (reported as unsupported).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "bench.h"

typedef struct ft_state {
    FT_Library lib;
    bcanvas cv;
    FT_Vector *pts;
    char *tags;
    short *ends;
    uint32_t cap_pts, cap_ends;
    const bshape *cur;
} ft_state;

static void *ft_create(int w, int h)
{
    ft_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    if (FT_Init_FreeType(&st->lib) || bcanvas_init(&st->cv, w, h)) {
        free(st);
        return NULL;
    }
    return st;
}

static void ft_clear(void *p)
{
    ft_state *st = p;
    memset(st->cv.px, 0, st->cv.stride * (size_t)st->cv.h);
}

static void spans_cb(int y, int count, const FT_Span *spans, void *user)
{
    ft_state *st = user;
    for (int i = 0; i < count; i++)
        bblend_hline(&st->cv, st->cur, spans[i].x, y, spans[i].len, spans[i].coverage);
}

static void ft_render(void *p, const bscene *s, const bpoint *pts)
{
    ft_state *st = p;
    if (s->max_shape_points > st->cap_pts || s->max_shape_contours > st->cap_ends) {
        /* Grows once, in the untimed warm-up frame. */
        free(st->pts);
        free(st->tags);
        free(st->ends);
        st->cap_pts = s->max_shape_points;
        st->cap_ends = s->max_shape_contours;
        st->pts = malloc((st->cap_pts + 1) * sizeof *st->pts);
        st->tags = malloc(st->cap_pts + 1);
        st->ends = malloc((st->cap_ends + 1) * sizeof *st->ends);
        if (!st->pts || !st->tags || !st->ends) {
            st->cap_pts = st->cap_ends = 0;
            return;
        }
        memset(st->tags, FT_CURVE_TAG_ON, st->cap_pts + 1);
    }
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape *sh = &s->shapes[i];
        uint32_t a = s->start[sh->first], b = s->start[sh->first + sh->ncontours];
        if (a == b)
            continue;
        for (uint32_t k = a; k < b; k++) {
            st->pts[k - a].x = lround(pts[k].x * 64.0);
            st->pts[k - a].y = lround(pts[k].y * 64.0);
        }
        for (uint32_t c = 0; c < sh->ncontours; c++)
            st->ends[c] = (short)(s->start[sh->first + c + 1] - 1 - a);
        FT_Outline o;
        o.n_points = (short)(b - a);
        o.n_contours = (short)sh->ncontours;
        o.points = st->pts;
        o.tags = st->tags;
        o.contours = st->ends;
        o.flags = sh->rule == B_EVENODD ? FT_OUTLINE_EVEN_ODD_FILL : FT_OUTLINE_NONE;
        st->cur = sh;
        FT_Raster_Params rp;
        memset(&rp, 0, sizeof rp);
        rp.source = &o;
        rp.flags = FT_RASTER_FLAG_AA | FT_RASTER_FLAG_DIRECT | FT_RASTER_FLAG_CLIP;
        rp.gray_spans = spans_cb;
        rp.user = st;
        rp.clip_box.xMin = 0;
        rp.clip_box.yMin = 0;
        rp.clip_box.xMax = st->cv.w;
        rp.clip_box.yMax = st->cv.h;
        FT_Outline_Render(st->lib, &o, &rp);
    }
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
    FT_Done_FreeType(st->lib);
    bcanvas_free(&st->cv);
    free(st->pts);
    free(st->tags);
    free(st->ends);
    free(st);
}

static const char *ft_unsupported(const bscene *s)
{
    if (s->max_shape_points > 32767 || s->max_shape_contours > 32767)
        return "a shape has more than 32767 points or contours (FT_Outline counts in a short)";
    return NULL;
}

const brenderer br_freetype = { "freetype", ft_unsupported, ft_create, ft_clear, ft_render, ft_read, ft_destroy };
