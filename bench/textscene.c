/*
 * textscene.c - the glyph-text scene: a paragraph of DejaVu Sans set at
 * 16 px on a 640x480 canvas, word-wrapped, one non-zero shape per glyph (as
 * text is drawn glyph by glyph).  Outlines come from FreeType unscaled and
 * unhinted (FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING); quadratic and cubic
 * segments are flattened here in double precision, with a tolerance of
 * 1/64 px at this size (1/32 px at 1280x960, the largest size benchmarked).
 * Advance widths only (no kerning): the point is the geometry, not typography.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include "bench.h"

#define TEXT_W 640
#define TEXT_H 480
#define TEXT_PX 16.0
#define TEXT_MARGIN 16.0
#define TEXT_LEADING 1.2
#define TEXT_TOL (1.0 / 64.0)

static const char *const kText =
    "The scanline edge-flag algorithm fills a polygon by marking, for every sample row that an edge "
    "crosses, one flag at the first sample right of the crossing, and then sweeping each scanline from "
    "left to right while a running mask toggles at every flag. With eight, sixteen or thirty-two samples "
    "per pixel in an n-rooks pattern, each pixel's coverage is the number of set bits of that mask. "
    "The even-odd rule needs one bit per sample; the non-zero rule keeps a small winding counter per "
    "sample, packed eight to a machine word with a pad bit each, so that a single addition updates "
    "eight counters at once. No edge sorting is needed, no area is computed, and only one scanline of "
    "flags is kept in memory, which makes the method attractive for hardware as well as for software. "
    "Quick brown foxes jump over lazy dogs; sphinx of black quartz, judge my vow! 0123456789 "
    "(parentheses), [brackets], {braces}, ampersands & at-signs @ and percent signs % 100.";

typedef struct builder {
    bscene *s;
    uint32_t cap_pts, cap_start, cap_shapes;
    double ox, oy, scale;   /* pen position (px) and font units -> px */
    double lx, ly;          /* last point, px */
    uint32_t contour_first; /* index of the current contour's first point */
    int in_contour;
    int oom;
} builder;

static void push_pt(builder *b, double x, double y)
{
    bscene *s = b->s;
    if (s->npoints == b->cap_pts) {
        uint32_t cap = b->cap_pts ? b->cap_pts * 2 : 4096;
        bpoint *p = realloc(s->pts, cap * sizeof *p);
        if (!p) {
            b->oom = 1;
            return;
        }
        s->pts = p;
        b->cap_pts = cap;
    }
    s->pts[s->npoints].x = x;
    s->pts[s->npoints].y = y;
    s->npoints++;
    b->lx = x;
    b->ly = y;
}

static void end_contour(builder *b)
{
    bscene *s = b->s;
    if (!b->in_contour)
        return;
    b->in_contour = 0;
    uint32_t n = s->npoints - b->contour_first;
    /* FreeType closes each contour with a segment back to its start: drop the
     * repeated point (contours are implicitly closed). */
    if (n > 1 && s->pts[s->npoints - 1].x == s->pts[b->contour_first].x &&
        s->pts[s->npoints - 1].y == s->pts[b->contour_first].y) {
        s->npoints--;
        n--;
    }
    if (n < 3) {
        s->npoints = b->contour_first;
        return;
    }
    if (s->ncontours + 2 > b->cap_start) {
        uint32_t cap = b->cap_start ? b->cap_start * 2 : 1024;
        uint32_t *p = realloc(s->start, cap * sizeof *p);
        if (!p) {
            b->oom = 1;
            return;
        }
        s->start = p;
        b->cap_start = cap;
    }
    s->start[s->ncontours] = b->contour_first;
    s->ncontours++;
    s->start[s->ncontours] = s->npoints;
    s->shapes[s->nshapes - 1].ncontours++;
}

static double px_x(const builder *b, const FT_Vector *v) { return b->ox + v->x * b->scale; }
static double px_y(const builder *b, const FT_Vector *v) { return b->oy - v->y * b->scale; }

static int cb_move(const FT_Vector *to, void *u)
{
    builder *b = u;
    end_contour(b);
    b->contour_first = b->s->npoints;
    b->in_contour = 1;
    push_pt(b, px_x(b, to), px_y(b, to));
    return b->oom;
}

static int cb_line(const FT_Vector *to, void *u)
{
    builder *b = u;
    push_pt(b, px_x(b, to), px_y(b, to));
    return b->oom;
}

static int cb_conic(const FT_Vector *c, const FT_Vector *to, void *u)
{
    builder *b = u;
    double x0 = b->lx, y0 = b->ly, x1 = px_x(b, c), y1 = px_y(b, c), x2 = px_x(b, to), y2 = px_y(b, to);
    /* Deviation of a quadratic from its chord is at most |p0 - 2p1 + p2| / 4;
     * with n pieces it drops by n^2. */
    double dd = hypot(x0 - 2 * x1 + x2, y0 - 2 * y1 + y2) / 4;
    int n = (int)ceil(sqrt(dd / TEXT_TOL));
    if (n < 1)
        n = 1;
    for (int i = 1; i <= n; i++) {
        double t = (double)i / n, m = 1 - t;
        push_pt(b, m * m * x0 + 2 * m * t * x1 + t * t * x2, m * m * y0 + 2 * m * t * y1 + t * t * y2);
    }
    return b->oom;
}

static int cb_cubic(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to, void *u)
{
    builder *b = u;
    double x0 = b->lx, y0 = b->ly, x1 = px_x(b, c1), y1 = px_y(b, c1);
    double x2 = px_x(b, c2), y2 = px_y(b, c2), x3 = px_x(b, to), y3 = px_y(b, to);
    double d1 = hypot(x0 - 2 * x1 + x2, y0 - 2 * y1 + y2), d2 = hypot(x1 - 2 * x2 + x3, y1 - 2 * y2 + y3);
    double dd = 0.75 * (d1 > d2 ? d1 : d2);
    int n = (int)ceil(sqrt(dd / TEXT_TOL));
    if (n < 1)
        n = 1;
    for (int i = 1; i <= n; i++) {
        double t = (double)i / n, m = 1 - t;
        double a = m * m * m, bb = 3 * m * m * t, cc = 3 * m * t * t, d = t * t * t;
        push_pt(b, a * x0 + bb * x1 + cc * x2 + d * x3, a * y0 + bb * y1 + cc * y2 + d * y3);
    }
    return b->oom;
}

int bscene_text(bscene *s, const char *font_path, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    FT_Library lib;
    FT_Face face;
    if (FT_Init_FreeType(&lib)) {
        snprintf(err, errlen, "FT_Init_FreeType failed");
        return -1;
    }
    if (FT_New_Face(lib, font_path, 0, &face)) {
        snprintf(err, errlen, "%s: cannot open the font (install fonts-dejavu-core)", font_path);
        FT_Done_FreeType(lib);
        return -1;
    }
    snprintf(s->name, sizeof s->name, "text_dejavu");
    s->w = TEXT_W;
    s->h = TEXT_H;
    size_t len = strlen(kText);
    s->shapes = calloc(len, sizeof *s->shapes);
    builder b;
    memset(&b, 0, sizeof b);
    b.s = s;
    b.scale = TEXT_PX / face->units_per_EM;
    const double line_h = TEXT_PX * TEXT_LEADING, right = TEXT_W - TEXT_MARGIN;
    double pen_x = TEXT_MARGIN, base = TEXT_MARGIN + TEXT_PX;
    FT_Outline_Funcs fn = { cb_move, cb_line, cb_conic, cb_cubic, 0, 0 };
    int rc = s->shapes ? 0 : -1;
    for (size_t i = 0; i < len && rc == 0; i++) {
        unsigned char ch = (unsigned char)kText[i];
        if (ch == ' ') {
            /* Wrap before a word that would not fit. */
            double w = 0;
            for (size_t j = i + 1; j < len && kText[j] != ' '; j++)
                if (!FT_Load_Char(face, (unsigned char)kText[j], FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING))
                    w += face->glyph->advance.x * b.scale;
            if (!FT_Load_Char(face, ' ', FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING))
                pen_x += face->glyph->advance.x * b.scale;
            if (pen_x + w > right) {
                pen_x = TEXT_MARGIN;
                base += line_h;
            }
            continue;
        }
        if (FT_Load_Char(face, ch, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) ||
            face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
            snprintf(err, errlen, "%s: no outline for '%c'", font_path, ch);
            rc = -1;
            break;
        }
        bshape *sh = &s->shapes[s->nshapes++];
        sh->rule = B_NONZERO; /* TrueType outlines are non-zero */
        sh->r = sh->g = sh->b = 0;
        sh->a = 255;
        sh->first = s->ncontours;
        b.ox = pen_x;
        b.oy = base;
        if (FT_Outline_Decompose(&face->glyph->outline, &fn, &b) || b.oom) {
            snprintf(err, errlen, "out of memory or bad outline");
            rc = -1;
            break;
        }
        end_contour(&b);
        pen_x += face->glyph->advance.x * b.scale;
    }
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    if (rc == 0 && (b.oom || !s->start)) {
        snprintf(err, errlen, "out of memory");
        rc = -1;
    }
    if (rc != 0) {
        bscene_free(s);
        return -1;
    }
    bscene_finish(s);
    return 0;
}
