/*
 * scene.c - benchmark scenes in double precision and the frame transform.
 *
 * Files are read by the model's own reader (ef_scene_load_file), fitted to a
 * canvas at load time, so every vertex is an exact Q16.8 device coordinate;
 * the benchmark converts each to the double v / 256.0 (exact).  Per frame,
 * the transform of bench/README.md ("Same frames") is applied once and its snapped
 * doubles are handed to every renderer.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "ef_scene.h"

#define B_PI 3.14159265358979323846 /* M_PI, which strict C11 does not declare */

static void base_name(char *dst, size_t n, const char *path)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    snprintf(dst, n, "%s", b);
    char *dot = strrchr(dst, '.');
    if (dot)
        *dot = '\0';
}

void bscene_free(bscene *s)
{
    free(s->shapes);
    free(s->start);
    free(s->pts);
    memset(s, 0, sizeof *s);
}

static void finish(bscene *s)
{
    s->max_shape_points = s->max_shape_contours = 0;
    s->has_evenodd = 0;
    for (uint32_t i = 0; i < s->nshapes; i++) {
        const bshape *sh = &s->shapes[i];
        uint32_t n = s->start[sh->first + sh->ncontours] - s->start[sh->first];
        if (n > s->max_shape_points)
            s->max_shape_points = n;
        if (sh->ncontours > s->max_shape_contours)
            s->max_shape_contours = sh->ncontours;
        if (sh->rule == B_EVENODD)
            s->has_evenodd = 1;
    }
}

void bscene_set_rule(bscene *s, int rule)
{
    if (rule < 0)
        return;
    for (uint32_t i = 0; i < s->nshapes; i++)
        s->shapes[i].rule = rule;
    finish(s);
}

int bscene_load(bscene *s, const char *path, int fit_w, int fit_h, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    ef_load_opts o;
    memset(&o, 0, sizeof o);
    o.fit_width = fit_w;
    o.fit_height = fit_h;
    ef_scene es;
    ef_error e;
    if (ef_scene_load_file(path, &o, &es, &e) != EF_OK) {
        ef_error_format(&e, err, errlen);
        return -1;
    }
    base_name(s->name, sizeof s->name, path);
    s->w = es.width;
    s->h = es.height;
    s->nshapes = es.nshapes;
    s->ncontours = es.ncontours;
    s->npoints = es.npoints;
    s->shapes = calloc(es.nshapes ? es.nshapes : 1, sizeof *s->shapes);
    s->start = calloc((size_t)es.ncontours + 1, sizeof *s->start);
    s->pts = calloc(es.npoints ? es.npoints : 1, sizeof *s->pts);
    if (!s->shapes || !s->start || !s->pts) {
        snprintf(err, errlen, "%s: out of memory", path);
        ef_scene_destroy(&es);
        bscene_free(s);
        return -1;
    }
    for (uint32_t i = 0; i < es.nshapes; i++) {
        const ef_shape *a = &es.shapes[i];
        bshape *b = &s->shapes[i];
        b->rule = a->rule == EF_RULE_EVENODD ? B_EVENODD : B_NONZERO;
        b->r = a->color.r;
        b->g = a->color.g;
        b->b = a->color.b;
        b->a = a->color.a;
        b->first = a->first_contour;
        b->ncontours = a->ncontours;
    }
    if (es.ncontours)
        memcpy(s->start, es.start, ((size_t)es.ncontours + 1) * sizeof *s->start);
    for (uint32_t i = 0; i < es.npoints; i++) {
        s->pts[i].x = es.points[i].x / 256.0; /* exact: |v| < 2^23 */
        s->pts[i].y = es.points[i].y / 256.0;
    }
    ef_scene_destroy(&es);
    finish(s);
    return 0;
}

void bscene_finish(bscene *s) { finish(s); }

int bscene_add_background(bscene *s)
{
    bshape *shapes = malloc(((size_t)s->nshapes + 1) * sizeof *shapes);
    uint32_t *start = malloc(((size_t)s->ncontours + 2) * sizeof *start);
    bpoint *pts = malloc(((size_t)s->npoints + 4) * sizeof *pts);
    if (!shapes || !start || !pts) {
        free(shapes);
        free(start);
        free(pts);
        return -1;
    }
    /* Three times the scene's canvas each way: the frame transform turns it by
     * at most 20 degrees (200 frames) and moves it by 10 px, so the canvas
     * stays covered in every frame. */
    const double w = s->w, h = s->h;
    const bpoint quad[4] = { { -w, -h }, { 2 * w, -h }, { 2 * w, 2 * h }, { -w, 2 * h } };
    shapes[0] = (bshape){ .rule = B_NONZERO, .r = 255, .g = 255, .b = 255, .a = 255, .first = 0, .ncontours = 1 };
    for (uint32_t i = 0; i < s->nshapes; i++) {
        shapes[i + 1] = s->shapes[i];
        shapes[i + 1].first++;
    }
    start[0] = 0;
    for (uint32_t c = 0; c <= s->ncontours; c++)
        start[c + 1] = s->start[c] + 4;
    memcpy(pts, quad, sizeof quad);
    if (s->npoints)
        memcpy(pts + 4, s->pts, (size_t)s->npoints * sizeof *pts);
    free(s->shapes);
    free(s->start);
    free(s->pts);
    s->shapes = shapes;
    s->start = start;
    s->pts = pts;
    s->nshapes++;
    s->ncontours++;
    s->npoints += 4;
    size_t n = strlen(s->name);
    snprintf(s->name + n, sizeof s->name - n, "_white");
    finish(s);
    return 0;
}

static inline double snap256(double v) { return round(v * 256.0) / 256.0; }

void bscene_frame(const bscene *s, int W, int H, int k, bpoint *out)
{
    const double sc = fmin(W / s->w, H / s->h);
    const double th = k * 0.1 * B_PI / 180.0; /* SPEC: pi = M_PI */
    const double c = cos(th), sn = sin(th);
    const double cx0 = s->w / 2, cy0 = s->h / 2;
    const double cx1 = W / 2.0 + k * 0.05, cy1 = H / 2.0 + k * 0.03;
    for (uint32_t i = 0; i < s->npoints; i++) {
        double u = (s->pts[i].x - cx0) * sc, v = (s->pts[i].y - cy0) * sc;
        out[i].x = snap256(cx1 + (u * c - v * sn));
        out[i].y = snap256(cy1 + (u * sn + v * c));
    }
}
