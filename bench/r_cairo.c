/*
 * r_cairo.c - Cairo (Debian's libcairo2, image backend, pixman compositing)
 * as a benchmark renderer: CAIRO_ANTIALIAS_DEFAULT ("cairo") and
 * CAIRO_ANTIALIAS_NONE ("cairo-noaa", the non-antialiased baseline).
 * One cairo_t reused for the run; per shape: new path, move_to/line_to/
 * close_path per contour, fill rule, source colour, cairo_fill.  Cairo
 * converts the doubles to its 24.8 fixed point inside the timed call.
 * Its compositing (pixman) rounds like docs/spec.md section 8 up to +-1.
 */
#include <stdlib.h>
#include <string.h>

#include <cairo.h>

#include "bench.h"

typedef struct cairo_state {
    cairo_surface_t *surf;
    cairo_t *cr;
    int w, h;
} cairo_state;

static void *cr_create_aa(int w, int h, cairo_antialias_t aa)
{
    cairo_state *st = calloc(1, sizeof *st);
    if (!st)
        return NULL;
    st->w = w;
    st->h = h;
    st->surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    st->cr = cairo_create(st->surf);
    cairo_set_antialias(st->cr, aa);
    cairo_set_operator(st->cr, CAIRO_OPERATOR_OVER);
    return st;
}
static void *cr_create(int w, int h) { return cr_create_aa(w, h, CAIRO_ANTIALIAS_DEFAULT); }
static void *cr_create_noaa(int w, int h) { return cr_create_aa(w, h, CAIRO_ANTIALIAS_NONE); }

static void cr_clear(void *p)
{
    cairo_state *st = p;
    cairo_surface_flush(st->surf);
    uint8_t *d = cairo_image_surface_get_data(st->surf);
    int stride = cairo_image_surface_get_stride(st->surf);
    for (int y = 0; y < st->h; y++)
        memset(d + (size_t)y * (size_t)stride, 0, (size_t)st->w * 4);
    cairo_surface_mark_dirty(st->surf);
}

static void cr_render(void *p, const bscene *s, const bpoint *pts)
{
    cairo_state *st = p;
    cairo_t *cr = st->cr;
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape *sh = &s->shapes[i];
        cairo_new_path(cr);
        for (uint32_t c = sh->first; c < sh->first + sh->ncontours; c++) {
            uint32_t a = s->start[c], b = s->start[c + 1];
            if (a == b)
                continue;
            cairo_move_to(cr, pts[a].x, pts[a].y);
            for (uint32_t k = a + 1; k < b; k++)
                cairo_line_to(cr, pts[k].x, pts[k].y);
            cairo_close_path(cr);
        }
        cairo_set_fill_rule(cr, sh->rule == B_EVENODD ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
        cairo_set_source_rgba(cr, sh->r / 255.0, sh->g / 255.0, sh->b / 255.0, sh->a / 255.0);
        cairo_fill(cr);
    }
    cairo_surface_flush(st->surf);
}

static void cr_read(void *p, uint8_t *rgba)
{
    cairo_state *st = p;
    cairo_surface_flush(st->surf);
    const uint8_t *d = cairo_image_surface_get_data(st->surf);
    int stride = cairo_image_surface_get_stride(st->surf);
    for (int y = 0; y < st->h; y++)
        for (int x = 0; x < st->w; x++) {
            uint32_t v;
            memcpy(&v, d + (size_t)y * (size_t)stride + (size_t)x * 4, 4); /* native-endian ARGB */
            uint8_t *o = rgba + ((size_t)y * (size_t)st->w + (size_t)x) * 4;
            o[0] = (uint8_t)(v >> 16);
            o[1] = (uint8_t)(v >> 8);
            o[2] = (uint8_t)v;
            o[3] = (uint8_t)(v >> 24);
        }
}

static void cr_destroy(void *p)
{
    cairo_state *st = p;
    if (!st)
        return;
    cairo_destroy(st->cr);
    cairo_surface_destroy(st->surf);
    free(st);
}

static const char *cr_unsupported(const bscene *s)
{
    (void)s;
    return NULL;
}

const brenderer br_cairo = { "cairo", cr_unsupported, cr_create, cr_clear, cr_render, cr_read, cr_destroy };
const brenderer br_cairo_noaa = {
    "cairo-noaa", cr_unsupported, cr_create_noaa, cr_clear, cr_render, cr_read, cr_destroy
};
