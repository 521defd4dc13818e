/*
 * test_input.c - the front end (model/input/): path grammar, curves and
 * arcs, transforms and viewports, colours and properties, error positions,
 * the .scene reader (peerbench SPEC.md section 1, rule by rule), hostile
 * input, and all shared SVG files.
 *
 * Doubles appear only to check error bounds against the exact geometry.
 * The SVG test data is $EF_SVG (default tests/data/svg, in the repository).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <math.h>

#include "ef_scene.h"

static const double EF_TEST_PI = 3.14159265358979323846;

/* ------------------------------------------------------------ helpers */

typedef struct notes {
    int count;
    char last[256];
} notes;

static void on_note(void *user, const char *file, uint32_t line, uint32_t col, const char *msg)
{
    notes *n = user;
    (void)file;
    n->count++;
    snprintf(n->last, sizeof n->last, "%u:%u:%s", (unsigned)line, (unsigned)col, msg);
}

static ef_status svg_opts(const char *text, int fw, int fh, notes *nt, ef_scene *s, ef_error *e)
{
    ef_load_opts o = { fw, fh, nt ? on_note : NULL, nt };
    return ef_scene_load_svg("t.svg", text, strlen(text), &o, s, e);
}

static ef_status svg(const char *text, ef_scene *s, ef_error *e) { return svg_opts(text, 0, 0, NULL, s, e); }

static ef_status txt_opts(const char *text, int fw, int fh, ef_scene *s, ef_error *e)
{
    ef_load_opts o = { fw, fh, NULL, NULL };
    return ef_scene_load_text("t.scene", text, strlen(text), &o, s, e);
}

static ef_status txt(const char *text, ef_scene *s, ef_error *e) { return txt_opts(text, 0, 0, s, e); }

/* A 100 x 100 canvas around one path. */
static ef_status path(const char *d, ef_scene *s, ef_error *e)
{
    char buf[4096];
    snprintf(buf, sizeof buf, "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><path d='%s'/></svg>",
             d);
    return svg(buf, s, e);
}

/* The scene must load; fails the test with the message otherwise. */
static void must(ef_status st, const ef_error *e)
{
    if (st != EF_OK) {
        char b[600];
        ef_error_format(e, b, sizeof b);
        fail_msg("unexpected error: %s", b);
    }
}

static double px(int32_t v) { return v / 256.0; }

/* The error must be `status` at line:col. */
static void expect_error(ef_status st, const ef_error *e, ef_status status, uint32_t line, uint32_t col,
                         const ef_scene *s)
{
    char b[600];
    ef_error_format(e, b, sizeof b);
    if (st != status || e->line != line || e->col != col)
        fail_msg("expected status %d at %u:%u, got %d: %s", status, (unsigned)line, (unsigned)col, st, b);
    assert_int_equal(s->nshapes, 0); /* no partial result */
    assert_int_equal(s->npoints, 0);
    assert_null(s->points);
}

/* Contour c of the scene as a point list. */
static uint32_t contour_len(const ef_scene *s, uint32_t c) { return s->start[c + 1] - s->start[c]; }
static ef_point pt(const ef_scene *s, uint32_t c, uint32_t i) { return s->points[s->start[c] + i]; }

static void assert_pt(const ef_scene *s, uint32_t c, uint32_t i, double x, double y)
{
    ef_point p = pt(s, c, i);
    if (fabs(px(p.x) - x) > 1e-9 || fabs(px(p.y) - y) > 1e-9)
        fail_msg("contour %u point %u: (%g, %g), expected (%g, %g)", (unsigned)c, (unsigned)i, px(p.x), px(p.y), x, y);
}

static bool same_points(const ef_scene *a, const ef_scene *b)
{
    if (a->npoints != b->npoints || a->ncontours != b->ncontours)
        return false;
    for (uint32_t i = 0; i < a->npoints; i++)
        if (a->points[i].x != b->points[i].x || a->points[i].y != b->points[i].y)
            return false;
    for (uint32_t c = 0; c <= a->ncontours; c++)
        if (a->start[c] != b->start[c])
            return false;
    return true;
}

static void assert_same_path(const char *d1, const char *d2)
{
    ef_scene a, b;
    ef_error e;
    must(path(d1, &a, &e), &e);
    must(path(d2, &b, &e), &e);
    if (!same_points(&a, &b))
        fail_msg("'%s' and '%s' differ (%u vs %u points)", d1, d2, a.npoints, b.npoints);
    ef_scene_destroy(&a);
    ef_scene_destroy(&b);
}

/* ------------------------------------------------------- path grammar */

static void test_path_lines(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    must(path("M 10 20 L 30.5 20 L 30.5 40.25 Z", &s, &e), &e);
    assert_int_equal(s.width, 100);
    assert_int_equal(s.nshapes, 1);
    assert_int_equal(s.ncontours, 1);
    assert_int_equal(contour_len(&s, 0), 3);
    assert_pt(&s, 0, 0, 10, 20);
    assert_pt(&s, 0, 1, 30.5, 20);
    assert_pt(&s, 0, 2, 30.5, 40.25);
    assert_int_equal(s.shapes[0].rule, EF_RULE_NONZERO);
    assert_int_equal(s.shapes[0].color.a, 255);
    assert_int_equal(s.shapes[0].color.r, 0);
    ef_polygon p = ef_scene_polygon(&s, 0);
    assert_int_equal(p.ncontours, 1);
    assert_int_equal(p.start[0], 0);
    assert_int_equal(p.start[1], 3);
    ef_scene_destroy(&s);
}

static void test_path_number_forms(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* "0.5.5" is 0.5 and .5; "1e1-2" is 10 and -2; signs separate numbers. */
    must(path("M0.5.5L1e1-2L-3-4.5", &s, &e), &e);
    assert_int_equal(contour_len(&s, 0), 3);
    assert_pt(&s, 0, 0, 0.5, 0.5);
    assert_pt(&s, 0, 1, 10, -2);
    assert_pt(&s, 0, 2, -3, -4.5);
    ef_scene_destroy(&s);
    /* Rounding to Q16.8 once: 0.001953125 = 1/512 is a tie, up; 1/3 rounds down. */
    must(path("M 0.001953125 0.3333333 L 5 0 L 0 5", &s, &e), &e);
    assert_int_equal(pt(&s, 0, 0).x, 1);
    assert_int_equal(pt(&s, 0, 0).y, 85);
    ef_scene_destroy(&s);
    must(path("M -0.001953125 -0.0019531 L 5 0 L 0 5", &s, &e), &e);
    assert_int_equal(pt(&s, 0, 0).x, 0); /* -0.5 ulp: ties toward +inf */
    assert_int_equal(pt(&s, 0, 0).y, 0);
    ef_scene_destroy(&s);
}

static void test_path_implicit(void **state)
{
    (void)state;
    /* Pairs after M are L; after m they are l. */
    assert_same_path("M 0 0 10 0 10 10", "M 0 0 L 10 0 L 10 10");
    assert_same_path("m 1 1 2 0 0 2", "M 1 1 l 2 0 l 0 2");
    assert_same_path("M1,1 2,1 2,2", "M1 1L2 1L2 2");
    assert_same_path("M 0 0 H 10 20 V 5 8", "M 0 0 L 10 0 L 20 0 L 20 5 L 20 8");
    assert_same_path("M 5 5 h 10 v 10 h -10 z", "M 5 5 L 15 5 L 15 15 L 5 15 Z");
    assert_same_path("M0 0 L 10 0 20 10 30 0", "M0 0 L 10 0 L 20 10 L 30 0");
    /* A leading m is absolute (the current point is the origin). */
    assert_same_path("m 5 5 l 10 0 l 0 10", "M 5 5 L 15 5 L 15 15");
}

static void test_path_subpath_after_close(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* resvg's M-L-Z-L-L: after z the next L starts a subpath at (10, 10). */
    must(path("M 10 10 L 10 20 L 20 10 z L 100 100 L 120 100", &s, &e), &e);
    assert_int_equal(s.ncontours, 2);
    assert_int_equal(contour_len(&s, 1), 3);
    assert_pt(&s, 1, 0, 10, 10);
    assert_pt(&s, 1, 1, 100, 100);
    assert_pt(&s, 1, 2, 120, 100);
    ef_scene_destroy(&s);
    /* Relative commands after z are relative to the subpath start. */
    must(path("M 10 10 l 10 0 l 0 10 z l 5 0 l 0 5", &s, &e), &e);
    assert_int_equal(s.ncontours, 2);
    assert_pt(&s, 1, 0, 10, 10);
    assert_pt(&s, 1, 1, 15, 10);
    assert_pt(&s, 1, 2, 15, 15);
    ef_scene_destroy(&s);
    /* m after z: relative to the start point too. */
    assert_same_path("M 10 10 l 10 0 l 0 10 z m 1 1 l 5 0 l 0 5", "M 10 10 L 20 10 L 20 20 Z M 11 11 L 16 11 L 16 16");
    /* Unclosed subpaths are closed implicitly; degenerate ones vanish. */
    must(path("M 0 0 L 10 0 M 20 20 L 30 20 L 30 30 M 50 50", &s, &e), &e);
    assert_int_equal(s.ncontours, 1);
    assert_pt(&s, 0, 0, 20, 20);
    ef_scene_destroy(&s);
    /* Repeated and closing points are not repeated in the contour. */
    must(path("M 0 0 L 0 0 L 10 0 L 10 0 L 10 10 L 0 0 Z", &s, &e), &e);
    assert_int_equal(contour_len(&s, 0), 3);
    ef_scene_destroy(&s);
}

static void test_path_grammar_errors(void **state)
{
    (void)state;
    static const struct {
        const char *d;
        ef_status st;
        uint32_t col; /* the value starts at column 75 in path()'s template */
    } cases[] = {
        { "L 1 2", EF_ERR_SYNTAX, 75 },                      /* must begin with a moveto */
        { "M 1 2 L 3", EF_ERR_SYNTAX, 84 },                  /* missing y */
        { "M,1 2", EF_ERR_SYNTAX, 76 },                      /* comma after a command letter */
        { "M 1 2,,3 4", EF_ERR_SYNTAX, 81 },                 /* double comma */
        { "M 1 2 3 4,", EF_ERR_SYNTAX, 85 },                 /* trailing comma */
        { "M 1 2, L 3 4", EF_ERR_SYNTAX, 82 },               /* comma before a command */
        { "M 0 0 L 1 0 1 1 Z 5 5", EF_ERR_SYNTAX, 93 },      /* numbers after Z */
        { "M 0 0 X 1 2", EF_ERR_SYNTAX, 81 },                /* unknown command */
        { "M 0 0 A 1 1 0 2 0 5 5", EF_ERR_SYNTAX, 89 },      /* arc flag must be 0 or 1 */
        { "M 0 0 L 3e9 0", EF_ERR_RANGE, 83 },               /* beyond Q31.32 */
        { "M 0 0 L 1 1 C", EF_ERR_SYNTAX, 87 },              /* command without arguments */
        { "M 0 0 L 40000 0 0 1", EF_ERR_RANGE, 81 },         /* device coordinate beyond 32768 px: the command */
        { "M 0 0 L 1 1 2 2 30000 40000", EF_ERR_RANGE, 91 }, /* ... or the repeated group */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ef_scene s;
        ef_error e;
        ef_status st = path(cases[i].d, &s, &e);
        if (st != cases[i].st || e.line != 1 || e.col != cases[i].col) {
            char b[600];
            ef_error_format(&e, b, sizeof b);
            fail_msg("'%s': expected %d at 1:%u, got %d: %s", cases[i].d, cases[i].st, (unsigned)cases[i].col, st, b);
        }
        assert_int_equal(s.npoints, 0);
    }
    ef_scene s;
    ef_error e;
    /* A relative coordinate whose sum leaves Q31.32: the repeated group's first number. */
    ef_status st = svg("<svg width='10' height='10'><path transform='scale(0.00001)' "
                       "d='M 0 0 l 2000000000 0 2000000000 0'/></svg>",
                       &s, &e);
    expect_error(st, &e, EF_ERR_RANGE, 1, 86, &s);
    /* Empty path data draws nothing and is no error. */
    must(path("  ", &s, &e), &e);
    assert_int_equal(s.nshapes, 0);
    ef_scene_destroy(&s);
}

/* -------------------------------------------------------- curves */

static void test_shorthand_reflection(void **state)
{
    (void)state;
    assert_same_path("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0", "M0 0 C 0 10 10 10 10 0 C 10 -10 20 -10 20 0");
    assert_same_path("m0 0 c 0 10 10 10 10 0 s 10 -10 10 0", "M0 0 C 0 10 10 10 10 0 C 10 -10 20 -10 20 0");
    /* S after S reflects the previous S's second control point. */
    assert_same_path("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0 S 30 10 30 0",
                     "M0 0 C 0 10 10 10 10 0 C 10 -10 20 -10 20 0 C 20 10 30 10 30 0");
    /* S without a preceding curve: the first control point is the current point. */
    assert_same_path("M0 0 L 5 5 S 10 10 20 0", "M0 0 L 5 5 C 5 5 10 10 20 0");
    assert_same_path("M0 0 Q 10 10 20 0 T 40 0", "M0 0 Q 10 10 20 0 Q 30 -10 40 0");
    assert_same_path("M0 0 Q 10 10 20 0 T 40 0 T 60 0", "M0 0 Q 10 10 20 0 Q 30 -10 40 0 Q 50 10 60 0");
    assert_same_path("m0 0 q 10 10 20 0 t 20 0", "M0 0 Q 10 10 20 0 Q 30 -10 40 0");
    /* T after a cubic does not reflect; S after a quadratic does not either. */
    assert_same_path("M0 0 C 0 10 10 10 10 0 T 20 5", "M0 0 C 0 10 10 10 10 0 Q 10 0 20 5");
    assert_same_path("M0 0 Q 10 10 20 0 S 30 10 40 0", "M0 0 Q 10 10 20 0 C 20 0 30 10 40 0");
    /* Implicit repeats of S keep reflecting. */
    assert_same_path("M0 0 C 0 10 10 10 10 0 S 20 -10 20 0 30 10 30 0",
                     "M0 0 C 0 10 10 10 10 0 S 20 -10 20 0 S 30 10 30 0");
}

/* Distance from (x, y) to the polyline of contour c (closed). */
static double dist_to_contour(const ef_scene *s, uint32_t c, double x, double y)
{
    double best = 1e300;
    uint32_t n = contour_len(s, c);
    for (uint32_t i = 0; i < n; i++) {
        ef_point a = pt(s, c, i), b = pt(s, c, (i + 1) % n);
        double ax = px(a.x), ay = px(a.y), bx = px(b.x), by = px(b.y);
        double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
        double t = l2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / l2 : 0;
        if (t < 0)
            t = 0;
        if (t > 1)
            t = 1;
        double d = hypot(ax + t * dx - x, ay + t * dy - y);
        if (d < best)
            best = d;
    }
    return best;
}

static void test_quadratic_flattening(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* L = |0 - 200 + 0| px = 200 px -> n^2 >= 200 * 16 / 4 = 800 -> n = 29:
     * the start, 28 inner points and the end point. */
    must(path("M 0 0 Q 50 100 100 0", &s, &e), &e);
    assert_int_equal(contour_len(&s, 0), 30);
    assert_pt(&s, 0, 29, 100, 0);
    /* Point i is B(i/29) rounded once to 1/256 px. */
    for (int i = 0; i <= 29; i++) {
        double t = i / 29.0, x = 100 * t, y = 200 * t * (1 - t);
        ef_point p = pt(&s, 0, (uint32_t)i);
        assert_true(fabs(px(p.x) - x) <= 1.0 / 512 + 1e-12);
        assert_true(fabs(px(p.y) - y) <= 1.0 / 512 + 1e-12);
    }
    ef_scene_destroy(&s);
    /* A straight quadratic (L = 0) is one segment. */
    must(path("M 0 0 Q 5 5 10 10 L 0 10", &s, &e), &e);
    assert_int_equal(contour_len(&s, 0), 3);
    ef_scene_destroy(&s);
}

static void test_cubic_flattening(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    must(path("M 10 80 C 40 10 65 10 95 80 Z", &s, &e), &e);
    /* Second differences: (10 - 80 + 65, 80 - 20 + 10) = (-5, 70) and (40 - 130 + 95, 10 - 20 + 80) = (5, 70):
     * L = 75 px; n^2 >= 3 * 75 * 4 = 900 -> n = 30. */
    assert_int_equal(contour_len(&s, 0), 31);
    assert_pt(&s, 0, 30, 95, 80);
    /* Every curve point is within 1/16 px (+ rounding) of the polyline. */
    for (int k = 0; k <= 1000; k++) {
        double t = k / 1000.0, u = 1 - t;
        double x = u * u * u * 10 + 3 * u * u * t * 40 + 3 * u * t * t * 65 + t * t * t * 95;
        double y = u * u * u * 80 + 3 * u * u * t * 10 + 3 * u * t * t * 10 + t * t * t * 80;
        assert_true(dist_to_contour(&s, 0, x, y) <= 1.0 / 16 + 1.0 / 256);
    }
    ef_scene_destroy(&s);
    /* A huge curve stops at 256 segments. */
    must(svg("<svg width='100' height='100'><path d='M -30000 0 C 30000 30000 -30000 30000 30000 0'/></svg>", &s, &e),
         &e);
    assert_int_equal(contour_len(&s, 0), 257);
    ef_scene_destroy(&s);
}

/* ----------------------------------------------------------- arcs */

static void bbox(const ef_scene *s, double b[4])
{
    b[0] = b[1] = 1e300;
    b[2] = b[3] = -1e300;
    for (uint32_t i = 0; i < s->npoints; i++) {
        double x = px(s->points[i].x), y = px(s->points[i].y);
        if (x < b[0])
            b[0] = x;
        if (y < b[1])
            b[1] = y;
        if (x > b[2])
            b[2] = x;
        if (y > b[3])
            b[3] = y;
    }
}

static void assert_on_circle(const ef_scene *s, double cx, double cy, double r, uint32_t from, uint32_t to)
{
    for (uint32_t i = from; i < to; i++) {
        double d = hypot(px(s->points[i].x) - cx, px(s->points[i].y) - cy);
        if (fabs(d - r) > 0.005)
            fail_msg("point %u at distance %g from (%g, %g), expected %g", (unsigned)i, d, cx, cy, r);
    }
}

static void test_arc_quarter(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* From (0, 10) to (10, 0), r = 10, small arc, positive sweep: centre (10, 10). */
    must(path("M 0 10 A 10 10 0 0 1 10 0 L 10 10", &s, &e), &e);
    uint32_t n = contour_len(&s, 0);
    assert_pt(&s, 0, 0, 0, 10);
    assert_pt(&s, 0, n - 2, 10, 0); /* end point exact */
    assert_pt(&s, 0, n - 1, 10, 10);
    assert_on_circle(&s, 10, 10, 10, 0, n - 1);
    /* sqrt(2 * 10) * pi / 2 = 7.02 -> 8 segments (the radius bound is sqrt 2 r here: 9). */
    assert_true(n - 2 >= 8 && n - 2 <= 12);
    /* Chord error bound: the arc's mid-angle points lie within 1/16 px. */
    for (int k = 0; k <= 100; k++) {
        double t = EF_TEST_PI + k * (EF_TEST_PI / 2) / 100;
        assert_true(dist_to_contour(&s, 0, 10 + 10 * cos(t), 10 + 10 * sin(t)) <= 1.0 / 16 + 1.0 / 256);
    }
    ef_scene_destroy(&s);
}

static void test_arc_flags(void **state)
{
    (void)state;
    static const struct {
        const char *d;
        double box[4]; /* expected bounding box (vertices: within the 1/16 px tolerance) */
    } cases[] = {
        /* small arc, positive sweep: centre (10, 10), bulges toward the origin */
        { "M 0 10 A 10 10 0 0 1 10 0", { 0, 0, 10, 10 } },
        /* small arc, negative sweep: centre (0, 0) */
        { "M 0 10 A 10 10 0 0 0 10 0", { 0, 0, 10, 10 } },
        /* large arc, positive sweep: centre (0, 0), through (-10, 0) and (0, -10) */
        { "M 0 10 A 10 10 0 1 1 10 0", { -10, -10, 10, 10 } },
        /* large arc, negative sweep: centre (10, 10), through (20, 10) and (10, 20) */
        { "M 0 10 A 10 10 0 1 0 10 0", { 0, 0, 20, 20 } },
    };
    double centres[4][2] = { { 10, 10 }, { 0, 0 }, { 0, 0 }, { 10, 10 } };
    for (int i = 0; i < 4; i++) {
        ef_scene s;
        ef_error e;
        must(path(cases[i].d, &s, &e), &e);
        double b[4];
        bbox(&s, b);
        for (int k = 0; k < 4; k++)
            if (fabs(b[k] - cases[i].box[k]) > 1.0 / 16 + 0.005)
                fail_msg("%s: bbox[%d] = %g, expected %g", cases[i].d, k, b[k], cases[i].box[k]);
        assert_on_circle(&s, centres[i][0], centres[i][1], 10, 0, s.npoints);
        ef_scene_destroy(&s);
    }
}

static void test_arc_special_cases(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    double b[4];
    /* Radii too small: scaled up (F.6.6) to a half circle of radius 5 about (5, 0). */
    must(path("M 0 0 A 1 1 0 0 1 10 0 Z", &s, &e), &e);
    assert_on_circle(&s, 5, 0, 5, 0, s.npoints);
    bbox(&s, b);
    assert_true(fabs(b[1] + 5) < 0.01 && fabs(b[3]) < 1e-9); /* positive sweep from 180 deg: above */
    ef_scene_destroy(&s);
    /* Negative radii lose their sign. */
    assert_same_path("M 0 10 A -10 -10 0 0 1 10 0", "M 0 10 A 10 10 0 0 1 10 0");
    /* A zero radius is a straight line. */
    assert_same_path("M 0 0 A 0 5 0 0 1 10 0 L 10 10", "M 0 0 L 10 0 L 10 10");
    /* Equal end points: the arc is omitted. */
    assert_same_path("M 5 5 A 3 3 0 0 1 5 5 L 10 5 L 10 10", "M 5 5 L 10 5 L 10 10");
    /* Rotation: rx = 10 along y after 90 degrees; the chord is 2 rx, so a half ellipse of half width 5,
     * clockwise on the screen (positive sweep) from the top: to the right. */
    must(path("M 50 0 A 10 5 90 0 1 50 20 Z", &s, &e), &e);
    bbox(&s, b);
    assert_true(fabs(b[0] - 50) < 1e-9 && fabs(b[2] - 55) < 1.0 / 16 + 0.005);
    ef_scene_destroy(&s);
    /* Relative arc end point; compact flags "01" followed by the end point. */
    assert_same_path("M 0 10 a10,10 0 0110-10", "M 0 10 A 10 10 0 0 1 10 0");
}

static void test_shapes(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    double b[4];
    must(svg("<svg width='100' height='100'>"
             "<rect x='10' y='20' width='30' height='40'/>"
             "<rect x='10' y='20' width='30' height='40' rx='5'/>"
             "<circle cx='50' cy='50' r='20'/>"
             "<ellipse cx='50' cy='50' rx='20' ry='10'/>"
             "<polygon points='0,0 10,0 10,10'/>"
             "<polyline points='0 0 10 0 10 10'/>"
             "<line x1='0' y1='0' x2='10' y2='10'/>"
             "<rect width='0' height='10'/><circle r='0'/>"
             "</svg>",
             &s, &e),
         &e);
    assert_int_equal(s.nshapes, 6); /* line and empty shapes draw nothing */
    assert_int_equal(s.shapes[0].ncontours, 1);
    assert_int_equal(contour_len(&s, 0), 4);
    assert_pt(&s, 0, 0, 10, 20);
    assert_pt(&s, 0, 2, 40, 60);
    /* Rounded rect: starts at (x + rx, y), corners are quarter arcs of radius 5. */
    assert_pt(&s, 1, 0, 15, 20);
    ef_point q = pt(&s, 1, 1);
    assert_true(px(q.x) == 35 && px(q.y) == 20);
    /* Circle: starts at (cx + r, cy), all on the circle. */
    assert_pt(&s, 2, 0, 70, 50);
    for (uint32_t i = s.start[2]; i < s.start[3]; i++)
        assert_true(fabs(hypot(px(s.points[i].x) - 50, px(s.points[i].y) - 50) - 20) < 0.005);
    ef_scene_destroy(&s);
    must(
        svg("<svg width='100' height='100'><rect x='10' y='10' width='20' height='10' rx='50' ry='50'/></svg>", &s, &e),
        &e);
    bbox(&s, b); /* rx, ry clamped to half the size: an ellipse filling the box */
    assert_true(fabs(b[0] - 10) < 1e-9 && fabs(b[1] - 10) < 1e-9 && fabs(b[2] - 30) < 1e-9 && fabs(b[3] - 20) < 1e-9);
    ef_scene_destroy(&s);
    ef_status st = svg("<svg width='100' height='100'><rect width='-1' height='10'/></svg>", &s, &e);
    expect_error(st, &e, EF_ERR_RANGE, 1, 31, &s);
}

/* ------------------------------------------------------ transforms */

static void test_transforms(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    must(svg("<svg width='100' height='100'>"
             "<g transform='translate(10,20)'><g transform='scale(2)'><path d='M1 1 L 2 1 L 2 2'/></g></g>"
             "<path transform='rotate(90)' d='M1 0 L 2 0 L 2 1'/>"
             "<path transform='rotate(90, 5, 5)' d='M5 0 L 6 0 L 6 1'/>"
             "<path transform='skewX(45)' d='M0 2 L 1 2 L 1 3'/>"
             "<path transform='matrix(1 0 0 1 3 4) translate(1) scale(1 2)' d='M0 1 L 1 1 L 1 2'/>"
             "<g transform='translate(50 50)'><use href='#u' x='1' y='2'/></g>"
             "<defs><path id='u' d='M0 0 L 1 0 L 1 1'/></defs>"
             "</svg>",
             &s, &e),
         &e);
    assert_int_equal(s.nshapes, 6);
    assert_pt(&s, 0, 0, 12, 22);
    assert_pt(&s, 0, 1, 14, 22);
    assert_pt(&s, 0, 2, 14, 24);
    assert_pt(&s, 1, 0, 0, 1); /* (x, y) -> (-y, x): sin/cos exact at 90 degrees */
    assert_pt(&s, 1, 1, 0, 2);
    assert_pt(&s, 1, 2, -1, 2);
    assert_pt(&s, 2, 0, 10, 5); /* about (5, 5): (5, 0) -> (10, 5) */
    ef_point p = pt(&s, 3, 0);  /* skewX(45): x + y tan 45, within rounding of tan */
    assert_true(fabs(px(p.x) - 2) <= 1.0 / 256 && px(p.y) == 2);
    assert_pt(&s, 4, 0, 4, 6);
    assert_pt(&s, 4, 2, 5, 8);
    assert_pt(&s, 5, 0, 51, 52); /* use: outer transform, then x/y */
    assert_pt(&s, 5, 1, 52, 52);
    ef_scene_destroy(&s);

    static const char *bad[] = { "scale(1,2,3)", "foo(1)", "translate(1", "rotate(1 2)", "skewX(90)", "translate(1,)" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char buf[256];
        snprintf(buf, sizeof buf, "<svg width='10' height='10'><path transform='%s' d='M0 0 L 1 0 L 1 1'/></svg>",
                 bad[i]);
        ef_status st = svg(buf, &s, &e);
        assert_true(st == EF_ERR_SYNTAX || st == EF_ERR_RANGE);
        assert_int_equal(e.line, 1);
        assert_true(e.col >= 46);
        assert_int_equal(s.nshapes, 0);
    }
}

static void test_viewbox_and_fit(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    const char *doc = "<svg viewBox='0 0 100 50'><path d='M0 0 L 100 0 L 100 50'/></svg>";
    must(svg(doc, &s, &e), &e);
    assert_int_equal(s.width, 100);
    assert_int_equal(s.height, 50);
    assert_pt(&s, 0, 2, 100, 50);
    ef_scene_destroy(&s);
    /* Fit into 200 x 200: scale 2, centred vertically. */
    must(svg_opts(doc, 200, 200, NULL, &s, &e), &e);
    assert_int_equal(s.width, 200);
    assert_int_equal(s.height, 200);
    assert_pt(&s, 0, 0, 0, 50);
    assert_pt(&s, 0, 2, 200, 150);
    ef_scene_destroy(&s);
    /* width/height with a viewBox: default xMidYMid meet. */
    must(svg("<svg width='300' height='100' viewBox='0 0 100 100'><path d='M0 0 L 100 0 L 100 100'/></svg>", &s, &e),
         &e);
    assert_int_equal(s.width, 300);
    assert_pt(&s, 0, 0, 100, 0);
    assert_pt(&s, 0, 2, 200, 100);
    ef_scene_destroy(&s);
    must(svg("<svg width='300' height='100' viewBox='0 0 100 100' preserveAspectRatio='xMaxYMin'>"
             "<path d='M0 0 L 100 0 L 100 100'/></svg>",
             &s, &e),
         &e);
    assert_pt(&s, 0, 0, 200, 0);
    ef_scene_destroy(&s);
    must(svg("<svg width='300' height='100' viewBox='0 0 100 100' preserveAspectRatio='none'>"
             "<path d='M0 0 L 100 0 L 100 100'/></svg>",
             &s, &e),
         &e);
    assert_pt(&s, 0, 1, 300, 0);
    assert_pt(&s, 0, 2, 300, 100);
    ef_scene_destroy(&s);
    must(svg("<svg width='300' height='100' viewBox='0 0 100 100' preserveAspectRatio='xMinYMid slice'>"
             "<path d='M0 0 L 100 0 L 100 100'/></svg>",
             &s, &e),
         &e);
    assert_pt(&s, 0, 0, 0, -100);
    assert_pt(&s, 0, 2, 300, 200);
    ef_scene_destroy(&s);
    /* Canvas sizes round up; units convert at 96 px per inch. */
    must(svg("<svg width='10.2' height='1in'/>", &s, &e), &e);
    assert_int_equal(s.width, 11);
    assert_int_equal(s.height, 96);
    ef_scene_destroy(&s);
    /* One size given: the other follows the viewBox's aspect ratio. */
    must(svg("<svg width='50' viewBox='0 0 100 40'/>", &s, &e), &e);
    assert_int_equal(s.height, 20);
    ef_scene_destroy(&s);
    ef_status st = svg("<svg width='20000' height='10'/>", &s, &e);
    expect_error(st, &e, EF_ERR_LIMIT, 1, 1, &s);
    st = svg("<svg viewBox='0 0 0 10'/>", &s, &e);
    expect_error(st, &e, EF_ERR_RANGE, 1, 15, &s);
    st = svg("<svg viewBox='0 0 10'/>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 1, 21, &s);
    /* Percentages of the viewport. */
    must(svg("<svg viewBox='0 0 200 100'><rect x='10%' y='10%' width='50%' height='50%'/></svg>", &s, &e), &e);
    assert_pt(&s, 0, 0, 20, 10);
    assert_pt(&s, 0, 2, 120, 60);
    ef_scene_destroy(&s);
}

/* -------------------------------------------------- colours, properties */

static ef_rgba8 color_of(const char *attrs)
{
    char buf[512];
    ef_scene s;
    ef_error e;
    snprintf(buf, sizeof buf, "<svg width='10' height='10'><path %s d='M0 0 L 1 0 L 1 1'/></svg>", attrs);
    must(svg(buf, &s, &e), &e);
    ef_rgba8 c = { 0, 0, 0, 0 };
    if (s.nshapes == 1)
        c = s.shapes[0].color;
    else
        assert_int_equal(s.nshapes, 0);
    ef_scene_destroy(&s);
    return c;
}

static void assert_color(const char *attrs, int r, int g, int b, int a)
{
    ef_rgba8 c = color_of(attrs);
    if (c.r != r || c.g != g || c.b != b || c.a != a)
        fail_msg("%s: (%d %d %d %d), expected (%d %d %d %d)", attrs, c.r, c.g, c.b, c.a, r, g, b, a);
}

static void test_colors(void **state)
{
    (void)state;
    assert_color("", 0, 0, 0, 255);
    assert_color("fill='#f80'", 255, 136, 0, 255);
    assert_color("fill='#12aBcD'", 0x12, 0xab, 0xcd, 255);
    assert_color("fill='rgb(255, 0, 10)'", 255, 0, 10, 255);
    assert_color("fill='rgb(100%,0%,50%)'", 255, 0, 128, 255);
    assert_color("fill='rgb(300 -5 127.5)'", 255, 0, 128, 255);
    assert_color("fill='rgba(10,20,30,0.5)'", 10, 20, 30, 128);
    assert_color("fill='Red'", 255, 0, 0, 255);
    assert_color("fill='lightgoldenrodyellow'", 250, 250, 210, 255);
    assert_color("fill='currentColor' color='#010203'", 1, 2, 3, 255);
    assert_color("fill='transparent'", 0, 0, 0, 0); /* not drawn */
    assert_color("fill='none'", 0, 0, 0, 0);
    assert_color("fill='red' fill-opacity='0.5'", 255, 0, 0, 128);
    assert_color("fill='red' fill-opacity='25%'", 255, 0, 0, 64);
    assert_color("fill='red' opacity='0.5' fill-opacity='0.5'", 255, 0, 0, 64);
    assert_color("fill='red' fill-opacity='7'", 255, 0, 0, 255); /* clamped */
    assert_color("style='fill: blue ; fill-opacity:.2'", 0, 0, 255, 51);
    assert_color("fill='red' style='fill:lime'", 0, 255, 0, 255); /* style wins */
    assert_color("fill='url(#nothing) #00f'", 0, 0, 255, 255);    /* fallback */
    assert_color("fill='url(#nothing)'", 0, 0, 0, 0);             /* no fallback: not drawn */

    ef_scene s;
    ef_error e;
    ef_status st = svg("<svg width='10' height='10'><path fill='bogus' d='M0 0 L 1 0 L 1 1'/></svg>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 1, 41, &s);
    st = svg("<svg width='10' height='10'>\n<path style='fill:#12' d='M0 0 L 1 0 L 1 1'/></svg>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 2, 19, &s);
}

static void test_inheritance(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    notes nt = { 0, "" };
    must(svg_opts("<svg width='10' height='10'>"
                  "<style>.c { fill: #00ff00 } path.d { fill-rule: evenodd } #e { fill: #0000ff }</style>"
                  "<g fill-rule='evenodd' fill='red' opacity='0.5'>"
                  "  <path d='M0 0 L 1 0 L 1 1'/>"                     /* 0: evenodd red, alpha .5 */
                  "  <path fill-rule='nonzero' d='M0 0 L 1 0 L 1 1'/>" /* 1: nonzero */
                  "  <g fill-rule='nonzero'><path fill-rule='inherit' d='M0 0 L 1 0 L 1 1'/></g>" /* 2: nonzero */
                  "  <g opacity='0.5'><path class='c' d='M0 0 L 1 0 L 1 1'/></g>"                 /* 3: green, .25 */
                  "  <path fill='none' stroke='black' d='M0 0 L 1 0 L 1 1'/>"                     /* skipped */
                  "  <path class='d' fill-rule='nonzero' d='M0 0 L 1 0 L 1 1'/>" /* 4: css over attribute */
                  "  <path id='e' class='c' d='M0 0 L 1 0 L 1 1'/>"              /* 5: id beats class */
                  "  <path visibility='hidden' d='M0 0 L 1 0 L 1 1'/>"
                  "  <path display='none' d='M0 0 L 1 0 L 1 1'/>"
                  "  <path stroke='blue' d='M0 0 L 1 0 L 1 1'/>" /* 6 */
                  "</g>"
                  "<g visibility='hidden'><path visibility='visible' d='M0 0 L 1 0 L 1 1'/></g>" /* 7 */
                  "<g display='none'><path d='M0 0 L 1 0 L 1 1'/></g>"
                  "</svg>",
                  0, 0, &nt, &s, &e),
         &e);
    assert_int_equal(s.nshapes, 8);
    assert_int_equal(s.shapes[0].rule, EF_RULE_EVENODD);
    assert_int_equal(s.shapes[0].color.r, 255);
    assert_int_equal(s.shapes[0].color.a, 128);
    assert_int_equal(s.shapes[1].rule, EF_RULE_NONZERO);
    assert_int_equal(s.shapes[2].rule, EF_RULE_NONZERO);
    assert_int_equal(s.shapes[3].color.g, 255);
    assert_int_equal(s.shapes[3].color.a, 64);
    assert_int_equal(s.shapes[4].rule, EF_RULE_EVENODD);
    assert_int_equal(s.shapes[5].color.b, 255);
    assert_int_equal(s.shapes[6].color.r, 255);
    assert_int_equal(s.shapes[7].color.a, 255);
    /* Two stroked elements, one note. */
    assert_int_equal(nt.count, 1);
    assert_int_equal(s.notes, 1);
    assert_non_null(strstr(nt.last, "stroke ignored"));
    ef_scene_destroy(&s);
}

static void test_gradient_and_notes(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    notes nt = { 0, "" };
    must(
        svg_opts(
            "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='10' height='10'>"
            "<defs><linearGradient id='g'><stop offset='0' stop-color='#000'/>"
            "<stop offset='1' style='stop-color:#fff;stop-opacity:0.5'/></linearGradient>"
            "<radialGradient id='h' xlink:href='#g'/></defs>"
            "<path fill='url(#g)' d='M0 0 L 1 0 L 1 1'/>"
            "<path fill='url(#h)' d='M0 0 L 1 0 L 1 1'/>"
            "<text>hi</text><image/><clipPath/><path clip-path='url(#x)' d='M0 0 L 1 0 L 1 1'/>"
            "</svg>",
            0, 0, &nt, &s, &e),
        &e);
    assert_int_equal(s.nshapes, 3);
    /* (0 + 255) / 2 rounded; opacity (1 + 0.5) / 2 = 0.75 -> 191. */
    assert_int_equal(s.shapes[0].color.r, 128);
    assert_int_equal(s.shapes[0].color.a, 191);
    assert_int_equal(s.shapes[1].color.r, 128); /* stops through href */
    assert_int_equal(nt.count, 4);              /* gradient, text, image, clip */
    ef_scene_destroy(&s);
}

/* ---------------------------------------------------- errors, hostile */

static void test_error_positions(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    char b[600];
    /* Path data on a later line: line and column inside the attribute. */
    ef_status st =
        svg("<svg width='10' height='10'>\n  <path fill='red'\n     d='M 1 1\n        L 2 x'/>\n</svg>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 4, 13, &s);
    ef_error_format(&e, b, sizeof b);
    assert_non_null(strstr(b, "t.svg:4:13: "));
    /* XML errors at expat's position. */
    st = svg("<svg width='10' height='10'>\n<path d='M0 0'>\n</svg>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 3, 3, &s);
    st = svg("<svg width='10' height='10'><path d='M0 0 L 1 0'/>\xff</svg>", &s, &e);
    assert_int_equal(st, EF_ERR_SYNTAX); /* bad UTF-8 */
    assert_int_equal(e.line, 1);
    /* Out-of-range device coordinates: the element. */
    st = svg("<svg width='10' height='10'>\n<g transform='scale(1000)'><rect width='100' height='1'/></g></svg>", &s,
             &e);
    expect_error(st, &e, EF_ERR_RANGE, 2, 28, &s);
    st = svg("<html/>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 1, 1, &s);
    st = svg("", &s, &e);
    assert_int_equal(st, EF_ERR_SYNTAX);
    ef_error_set(&e, EF_ERR_IO, "f", 0, 0, "x %d", 5);
    ef_error_format(&e, b, sizeof b);
    assert_string_equal(b, "f: x 5");
}

static void test_hostile(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* Billion laughs: rejected at the first entity declaration. */
    const char *laughs =
        "<?xml version='1.0'?>\n<!DOCTYPE svg [\n <!ENTITY a 'aaaaaaaaaa'>\n"
        " <!ENTITY b '&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;'>\n <!ENTITY c '&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;'>\n"
        " <!ENTITY d '&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;'>\n]>\n<svg width='10' height='10'><desc>&d;</desc></svg>";
    ef_status st = svg(laughs, &s, &e);
    assert_int_equal(st, EF_ERR_UNSUPPORTED);
    assert_int_equal(e.line, 3);
    assert_int_equal(s.nshapes, 0);
    /* External entity and parameter entities: same. */
    st = svg("<!DOCTYPE svg [<!ENTITY x SYSTEM 'file:///etc/passwd'>]><svg>&x;</svg>", &s, &e);
    assert_int_equal(st, EF_ERR_UNSUPPORTED);
    st = svg("<!DOCTYPE svg [<!ENTITY % p 'x'> %p;]><svg/>", &s, &e);
    assert_int_not_equal(st, EF_OK);
    /* Undefined entity behind an external DTD. */
    st = svg(
        "<!DOCTYPE svg PUBLIC '-//W3C//DTD SVG 1.0//EN' 'http://x/svg10.dtd'><svg width='1' height='1'>&nbsp;</svg>",
        &s, &e);
    assert_int_equal(st, EF_ERR_SYNTAX);
    /* A plain DOCTYPE and a BOM are fine. */
    must(svg("\xef\xbb\xbf<?xml version='1.0' encoding='utf-8'?>\n<!DOCTYPE svg PUBLIC '-//W3C//DTD SVG 1.0//EN' "
             "'http://www.w3.org/TR/2001/REC-SVG-20010904/DTD/svg10.dtd'>\n<svg width='1' height='1'/>",
             &s, &e),
         &e);
    ef_scene_destroy(&s);
    /* Deep nesting. */
    char *deep = malloc(300 * 7 + 64);
    assert_non_null(deep);
    strcpy(deep, "<svg>");
    for (int i = 0; i < 300; i++)
        strcat(deep, "<g>");
    for (int i = 0; i < 300; i++)
        strcat(deep, "</g>");
    strcat(deep, "</svg>");
    st = svg(deep, &s, &e);
    assert_int_equal(st, EF_ERR_LIMIT);
    free(deep);
    /* <use> cycles and amplification. */
    st = svg("<svg width='10' height='10'><g id='a'><use href='#a'/></g></svg>", &s, &e);
    expect_error(st, &e, EF_ERR_SYNTAX, 1, 39, &s);
    char *bomb = malloc(16384);
    assert_non_null(bomb);
    strcpy(bomb, "<svg width='10' height='10'><defs><g id='a0'/>");
    for (int i = 1; i < 8; i++) {
        char g[64];
        snprintf(g, sizeof g, "<g id='a%d'>", i);
        strcat(bomb, g);
        for (int k = 0; k < 10; k++) {
            snprintf(g, sizeof g, "<use href='#a%d'/>", i - 1);
            strcat(bomb, g);
        }
        strcat(bomb, "</g>");
    }
    strcat(bomb, "</defs><use href='#a7'/></svg>");
    st = svg(bomb, &s, &e);
    assert_int_equal(st, EF_ERR_LIMIT);
    free(bomb);
    /* A document over the size limit is refused before parsing. */
    st = ef_scene_load_svg("big.svg", "<svg/>", (size_t)65 << 20, NULL, &s, &e);
    assert_int_equal(st, EF_ERR_LIMIT);
    /* Fit options must come in pairs. */
    st = svg_opts("<svg/>", 10, 0, NULL, &s, &e);
    assert_int_equal(st, EF_ERR_ARG);
}

/* ------------------------------------------------------- .scene reader */

static void test_scene_basic(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    must(txt("# a square with a square hole, then a half-transparent triangle\n"
             "scene 100 100\n"
             "shape evenodd 0 0 128 255\n"
             "contour 10 10 90 10 90 90 10 90\n"
             "contour 30 30 70 30 70 70 30 70\n"
             "shape nonzero 255 0 0 128\n"
             "contour 50 5 95 95 5 95\n",
             &s, &e),
         &e);
    assert_int_equal(s.width, 100);
    assert_int_equal(s.nshapes, 2);
    assert_int_equal(s.ncontours, 3);
    assert_int_equal(s.npoints, 11);
    assert_int_equal(s.shapes[0].rule, EF_RULE_EVENODD);
    assert_int_equal(s.shapes[0].ncontours, 2);
    assert_int_equal(s.shapes[0].color.b, 128);
    assert_int_equal(s.shapes[1].color.a, 128);
    assert_pt(&s, 2, 0, 50, 5);
    ef_polygon p = ef_scene_polygon(&s, 1);
    assert_int_equal(p.ncontours, 1);
    assert_int_equal(p.start[0], 8);
    assert_int_equal(p.start[1], 11);
    ef_scene_destroy(&s);
}

static void test_scene_tokens(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* Comments anywhere, blank lines, tabs, CRLF, every number form of SPEC.md. */
    must(txt("\n  # comment\nscene\t10.2 7 # size\r\n\n\tshape  nonzero 1 2 3 4#c\n"
             "contour 12.375 -3 .5 1e-2 2.5E+1 0 +1 5.\n"
             "shape evenodd 0 0 0 0\n", /* a shape with no contour */
             &s, &e),
         &e);
    assert_int_equal(s.width, 11); /* rounded up */
    assert_int_equal(s.height, 7);
    assert_int_equal(s.nshapes, 2);
    assert_int_equal(s.shapes[1].ncontours, 0);
    assert_pt(&s, 0, 0, 12.375, -3);
    assert_pt(&s, 0, 1, 0.5, 0.01171875); /* 0.01 rounds to 3/256 */
    assert_pt(&s, 0, 2, 25, 0);
    assert_pt(&s, 0, 3, 1, 5);
    ef_scene_destroy(&s);
}

static void test_scene_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        ef_status st;
        uint32_t line, col;
    } cases[] = {
        { "", EF_ERR_SYNTAX, 1, 1 }, /* no scene */
        { "# only a comment\n", EF_ERR_SYNTAX, 1, 1 },
        { "shape nonzero 1 2 3 4\n", EF_ERR_SYNTAX, 1, 1 },    /* scene first */
        { "scene 10 10\nscene 10 10\n", EF_ERR_SYNTAX, 2, 1 }, /* once */
        { "scene 10\n", EF_ERR_SYNTAX, 1, 9 },
        { "scene 10 10 10\n", EF_ERR_SYNTAX, 1, 13 },
        { "scene 0 10\n", EF_ERR_RANGE, 1, 7 }, /* positive */
        { "scene -1 10\n", EF_ERR_RANGE, 1, 7 },
        { "scene 20000 10\n", EF_ERR_LIMIT, 1, 1 },
        { "scene 10 10\ncontour 0 0 1 0 1 1\n", EF_ERR_SYNTAX, 2, 1 }, /* contour before shape */
        { "scene 10 10\nshape winding 1 2 3 4\n", EF_ERR_SYNTAX, 2, 7 },
        { "scene 10 10\nshape EvenOdd 1 2 3 4\n", EF_ERR_SYNTAX, 2, 7 }, /* case-sensitive */
        { "scene 10 10\nshape nonzero 1 2 3\n", EF_ERR_SYNTAX, 2, 20 },
        { "scene 10 10\nshape nonzero 1 2 3 256\n", EF_ERR_SYNTAX, 2, 21 },
        { "scene 10 10\nshape nonzero 1 2 3 -1\n", EF_ERR_SYNTAX, 2, 21 },
        { "scene 10 10\nshape nonzero 1 2 3 4.0\n", EF_ERR_SYNTAX, 2, 21 },
        { "scene 10 10\nshape nonzero 1 2 3 4 5\n", EF_ERR_SYNTAX, 2, 23 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1\n", EF_ERR_SYNTAX, 3, 1 }, /* >= 3 points */
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2\n", EF_ERR_SYNTAX, 3, 18 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 inf\n", EF_ERR_SYNTAX, 3, 19 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 nan\n", EF_ERR_SYNTAX, 3, 19 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 0x10\n", EF_ERR_SYNTAX, 3, 19 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 1,5\n", EF_ERR_SYNTAX, 3, 19 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 6e\n", EF_ERR_SYNTAX, 3, 19 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 40000\n", EF_ERR_RANGE, 3, 19 },
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 1 2 3e9\n", EF_ERR_RANGE, 3, 19 },
        { "scene 10 10\nShape nonzero 1 2 3 4\n", EF_ERR_SYNTAX, 2, 1 }, /* unknown directive */
        { "scene 10 10\nshape nonzero 1 2 3 4\ncontour 0 0 1 0 1 1\vx\n", EF_ERR_SYNTAX, 3, 19 },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ef_scene s;
        ef_error e;
        ef_status st = txt(cases[i].text, &s, &e);
        if (st != cases[i].st || e.line != cases[i].line || e.col != cases[i].col) {
            char b[600];
            ef_error_format(&e, b, sizeof b);
            fail_msg("case %zu: expected %d at %u:%u, got %d: %s", i, cases[i].st, (unsigned)cases[i].line,
                     (unsigned)cases[i].col, st, b);
        }
        assert_int_equal(s.nshapes, 0);
        assert_null(s.points);
    }
}

static void test_scene_fit(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* 100 x 50 into 200 x 200: s = 2, X = 2x, Y = 100 + (y - 25) 2. */
    must(txt_opts("scene 100 50\nshape nonzero 0 0 0 255\ncontour 0 0 100 0 100 50 50.5 25\n", 200, 200, &s, &e), &e);
    assert_int_equal(s.width, 200);
    assert_int_equal(s.height, 200);
    assert_pt(&s, 0, 0, 0, 50);
    assert_pt(&s, 0, 1, 200, 50);
    assert_pt(&s, 0, 2, 200, 150);
    assert_pt(&s, 0, 3, 101, 100);
    ef_scene_destroy(&s);
    /* The scene's own size: the identity. */
    must(txt_opts("scene 64 32\nshape nonzero 0 0 0 255\ncontour 0.00390625 1 63.5 2 7 31.99609375\n", 64, 32, &s, &e),
         &e);
    assert_pt(&s, 0, 0, 0.00390625, 1);
    assert_pt(&s, 0, 2, 7, 31.99609375);
    ef_scene_destroy(&s);
}

/* --------------------------------------------------- builder, files */

static void test_scene_builder(void **state)
{
    (void)state;
    ef_scene s;
    ef_scene_create(&s, 8, 4);
    ef_point pts[3] = { { 0, 0 }, { 256, 0 }, { 256, 256 } };
    assert_int_equal(ef_scene_add_contour(&s, pts, 3), EF_ERR_ARG); /* no shape yet */
    ef_rgba8 c = { 1, 2, 3, 4 };
    assert_int_equal(ef_scene_begin_shape(&s, EF_RULE_EVENODD, c), EF_OK);
    ef_polygon p = ef_scene_polygon(&s, 0);
    assert_int_equal(p.ncontours, 0);
    assert_non_null(p.start);
    assert_int_equal(ef_scene_add_contour(&s, pts, 3), EF_OK);
    assert_int_equal(ef_scene_add_contour(&s, pts, 2), EF_OK); /* allowed, draws nothing */
    ef_point far = { EF_COORD_LIMIT, 0 };
    assert_int_equal(ef_scene_add_contour(&s, &far, 1), EF_ERR_RANGE);
    p = ef_scene_polygon(&s, 0);
    assert_int_equal(p.ncontours, 2);
    assert_int_equal(p.start[2], 5);
    assert_int_equal(s.npoints, 5);
    p = ef_scene_polygon(&s, 7);
    assert_null(p.pts);
    ef_scene_destroy(&s);
    assert_int_equal(s.nshapes, 0);
}

static const char *svg_dir(void)
{
    const char *d = getenv("EF_SVG");
    return d && *d ? d : "tests/data/svg";
}

/* Issue 3: limits the readers enforce with a position, and messages that
 * quote hostile input safely. */
static void test_robustness(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    /* A shape takes at most EF_MAX_EDGES_PER_SHAPE points (= edges), the
     * model's limit, whatever the contours: exactly the limit is fine. */
    ef_point *pts = calloc(EF_MAX_EDGES_PER_SHAPE, sizeof *pts);
    assert_non_null(pts);
    ef_rgba8 c = { 1, 2, 3, 255 };
    ef_scene_create(&s, 4, 4);
    assert_int_equal(ef_scene_begin_shape(&s, EF_RULE_NONZERO, c), EF_OK);
    assert_int_equal(ef_scene_add_contour(&s, pts, EF_MAX_EDGES_PER_SHAPE - 3), EF_OK);
    assert_int_equal(ef_scene_add_contour(&s, pts, 3), EF_OK);
    assert_int_equal(ef_scene_add_contour(&s, pts, 1), EF_ERR_LIMIT);
    assert_int_equal(ef_scene_begin_shape(&s, EF_RULE_NONZERO, c), EF_OK);
    assert_int_equal(ef_scene_add_contour(&s, pts, 3), EF_OK); /* the next shape starts afresh */
    ef_scene_destroy(&s);
    free(pts);

    /* Quoted input: control characters (NUL included), invalid UTF-8 and a
     * stray byte order mark are escaped, with the position unchanged. */
    static const char esc[] = "scene 10 10\nshape nonzero 1 2 3 255\n\x1b[31mcontour 1 1 5 1 5 5\n";
    assert_int_equal(txt(esc, &s, &e), EF_ERR_SYNTAX);
    assert_int_equal(e.line, 3);
    assert_int_equal(e.col, 1);
    assert_non_null(strstr(e.msg, "'\\x1B[31mcontour'"));
    assert_null(strchr(e.msg, 0x1b));
    static const char nul[] = "scene 10 10\nshape nonzero 1 2 3 255\ncontour 1 1 5\0001 5 5\n";
    assert_int_equal(ef_scene_load_text("nul.scene", nul, sizeof nul - 1, NULL, &s, &e), EF_ERR_SYNTAX);
    assert_int_equal(e.col, 13);
    assert_non_null(strstr(e.msg, "'5\\x001'"));
    assert_int_equal(txt("scene 10 10\n\xef\xbb\xbfshape nonzero 1 2 3 255\n", &s, &e), EF_ERR_SYNTAX);
    assert_non_null(strstr(e.msg, "'\\uFEFFshape'"));
    assert_int_equal(txt("scene 10 10\nshape nonzero 1 2 3 255\ncontour 1 1 \xff\xc0 5 5 1\n", &s, &e), EF_ERR_SYNTAX);
    assert_non_null(strstr(e.msg, "'\\xFF\\xC0'"));
    /* Valid UTF-8 is kept as it is. */
    assert_int_equal(txt("scene 10 10\nshape nonzero 1 2 3 255\ncontour 1 1 \xc2\xbd 5 5 1\n", &s, &e), EF_ERR_SYNTAX);
    assert_non_null(strstr(e.msg, "'\xc2\xbd'"));
    /* A BOM at the very start of either format is accepted. */
    must(txt("\xef\xbb\xbfscene 1 1\n", &s, &e), &e);
    ef_scene_destroy(&s);
}

static void test_load_file(void **state)
{
    (void)state;
    ef_scene s;
    ef_error e;
    char path[1024];
    assert_int_equal(ef_scene_load_file("nowhere/x.svg", NULL, &s, &e), EF_ERR_IO);
    assert_int_equal(ef_scene_load_file("x.png", NULL, &s, &e), EF_ERR_UNSUPPORTED);
    snprintf(path, sizeof path, "%s/lion.svg", svg_dir());
    must(ef_scene_load_file(path, NULL, &s, &e), &e);
    ef_scene_destroy(&s);
}

static void test_shared_svgs(void **state)
{
    (void)state;
    /* Exact contour counts (path structure, independent of flattening) and
     * point ranges; all vertices within the canvas (+ 1 px: the tiger's
     * outline overhangs its viewBox by 0.64 px). */
    static const struct {
        const char *file;
        uint32_t shapes, contours, min_pts, max_pts;
        int notes;
    } files[] = {
        { "antiloop2.svg", 18, 59, 2500, 4000, 1 },
        { "burning_car.svg", 271, 322, 25000, 40000, 0 },
        { "flag_tm.svg", 161, 481, 4500, 7000, 0 },
        { "human_head.svg", 168, 388, 9000, 14000, 0 },
        { "lion.svg", 12, 132, 1942, 1942, 0 },
        { "lorem_ipsum_compound.svg", 1, 1204, 30000, 45000, 0 },
        { "lorem_ipsum_separate.svg", 812, 1204, 30000, 45000, 0 },
        { "stress_pixi_bezier_loop.svg", 1, 1, 20, 80, 0 },
        { "stress_pixi_bowtie.svg", 1, 1, 4, 4, 0 },
        { "stress_pixi_figure8.svg", 1, 1, 100, 300, 0 },
        { "stress_pixi_fill_rule_evenodd_basic.svg", 1, 2, 8, 8, 0 },
        { "stress_pixi_fill_rule_multiple_holes.svg", 1, 4, 16, 16, 0 },
        { "stress_pixi_fill_rule_nested_holes.svg", 1, 3, 12, 12, 0 },
        { "stress_pixi_fill_rule_nonzero_basic.svg", 1, 2, 8, 8, 0 },
        { "stress_pixi_fill_rule_star_evenodd.svg", 1, 1, 10, 10, 0 },
        { "stress_pixi_fill_rule_star_nonzero.svg", 1, 1, 10, 10, 0 },
        { "stress_pixi_nonzero_opposite_winding.svg", 1, 2, 8, 8, 0 },
        { "stress_pixi_pentagram_default_rule.svg", 1, 1, 5, 5, 0 },
        { "stress_pixi_twisted_quad.svg", 1, 1, 4, 4, 0 },
        { "stress_resvg_fill_rule_evenodd.svg", 1, 1, 5, 5, 1 },
        { "stress_resvg_fill_rule_nonzero.svg", 1, 1, 5, 5, 1 },
        { "stress_resvg_subpath_after_close.svg", 1, 2, 6, 6, 1 },
        { "stress_vello_unclosed_subpaths.svg", 4, 4, 14, 14, 0 },
        { "tiger.svg", 130, 226, 14000, 24000, 1 },
    };
    int found = 0;
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
        char path[1024];
        ef_scene s;
        ef_error e;
        notes nt = { 0, "" };
        ef_load_opts o = { 0, 0, on_note, &nt };
        snprintf(path, sizeof path, "%s/%s", svg_dir(), files[i].file);
        ef_status st = ef_scene_load_file(path, &o, &s, &e);
        if (st == EF_ERR_IO)
            continue;
        found++;
        must(st, &e);
        if (s.nshapes != files[i].shapes || s.ncontours != files[i].contours || s.npoints < files[i].min_pts ||
            s.npoints > files[i].max_pts || nt.count != files[i].notes)
            fail_msg("%s: %u shapes, %u contours, %u points, %d notes", files[i].file, s.nshapes, s.ncontours,
                     s.npoints, nt.count);
        for (uint32_t k = 0; k < s.npoints; k++) {
            ef_point p = s.points[k];
            if (p.x < -256 || p.y < -256 || p.x > 256 * (s.width + 1) || p.y > 256 * (s.height + 1))
                fail_msg("%s: vertex (%g, %g) outside the %dx%d canvas", files[i].file, px(p.x), px(p.y), s.width,
                         s.height);
        }
        ef_scene_destroy(&s);
        /* The same file fitted into 640 x 480 stays inside too. */
        ef_load_opts fo = { 640, 480, NULL, NULL };
        must(ef_scene_load_file(path, &fo, &s, &e), &e);
        assert_int_equal(s.width, 640);
        for (uint32_t k = 0; k < s.npoints; k++) {
            ef_point p = s.points[k];
            assert_true(p.x >= -4 * 256 && p.y >= -4 * 256 && p.x <= 644 * 256 && p.y <= 484 * 256);
        }
        ef_scene_destroy(&s);
    }
    if (found != 24)
        print_message("SVG folder %s (EF_SVG): %d of the 24 files found\n", svg_dir(), found);
    assert_int_equal(found, 24);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_path_lines),
        cmocka_unit_test(test_path_number_forms),
        cmocka_unit_test(test_path_implicit),
        cmocka_unit_test(test_path_subpath_after_close),
        cmocka_unit_test(test_path_grammar_errors),
        cmocka_unit_test(test_shorthand_reflection),
        cmocka_unit_test(test_quadratic_flattening),
        cmocka_unit_test(test_cubic_flattening),
        cmocka_unit_test(test_arc_quarter),
        cmocka_unit_test(test_arc_flags),
        cmocka_unit_test(test_arc_special_cases),
        cmocka_unit_test(test_shapes),
        cmocka_unit_test(test_transforms),
        cmocka_unit_test(test_viewbox_and_fit),
        cmocka_unit_test(test_colors),
        cmocka_unit_test(test_inheritance),
        cmocka_unit_test(test_gradient_and_notes),
        cmocka_unit_test(test_error_positions),
        cmocka_unit_test(test_hostile),
        cmocka_unit_test(test_scene_basic),
        cmocka_unit_test(test_scene_tokens),
        cmocka_unit_test(test_scene_errors),
        cmocka_unit_test(test_scene_fit),
        cmocka_unit_test(test_scene_builder),
        cmocka_unit_test(test_robustness),
        cmocka_unit_test(test_load_file),
        cmocka_unit_test(test_shared_svgs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
