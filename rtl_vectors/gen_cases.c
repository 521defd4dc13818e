/*
 * gen_cases.c - the directed corner cases of `edgeflag gen`, as a commented
 * table (after TestFloat's genCases tables): one row per case, with its
 * category, what it is known to produce, a small builder and the text that
 * becomes the comment at the top of its file.  docs/gen.md section 5 lists
 * the same table; `edgeflag gen --list` prints it.
 *
 * Units: every coordinate is Q16.8 (1/256 px), y grows downward.  PX(v) is v
 * pixels.  Builders flagged EF_GEN_F_GRID place vertices on the sample grid
 * of b->grid samples per pixel (docs/spec.md section 4):
 *   row(r)    = h r + c            y of global sample row r (h = 256/N, c = h/2)
 *   col(i, k) = 256 i + h k + c    x of sample column k of pixel column i
 *   sx(i, s)  = col(i, k_s)        x of sample s (sub-scanline s) of pixel column i
 * and are built once per grid (level 1: --samples, default 16; level 2: 8, 16
 * and 32).  Contours are written as listed: a rectangle (x0,y0)-(x1,y1) runs
 * clockwise on the screen, so its left edge goes up (dir = -1, spec 5).
 *
 * Rows must not be reordered or edited without bumping EF_GEN_VERSION: case
 * numbers and file contents follow from this table.
 */
#include "gen_internal.h"

#define PX(v) ((int32_t)(v)*EF_GEN_PX)
#define LIM EF_GEN_LIM

/* What each case is known to produce (checked by tests/unit/test_gen.c). */
#define X_ANY \
    { \
        EF_GEN_EXPECT_ANY, 0, 0, 0, -1 \
    }
#define X_EMPTY \
    { \
        EF_GEN_EXPECT_EMPTY, 0, 0, 0, 0 \
    }
#define X_FULL \
    { \
        EF_GEN_EXPECT_FULL, 0, 0, 0, -1 \
    }
#define X_PROBE(x, y, a, ov) \
    { \
        EF_GEN_EXPECT_PROBE, x, y, a, ov \
    }

#define RECT(b, x0, y0, x1, y1) ef_genb_rect(b, x0, y0, x1, y1)
/* The same rectangle counter-clockwise: left edge down (dir = +1). */
static void rect_ccw(ef_genb *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    ef_genb_pt(b, x0, y0);
    ef_genb_pt(b, x0, y1);
    ef_genb_pt(b, x1, y1);
    ef_genb_pt(b, x1, y0);
    ef_genb_end(b);
}

static void tri(ef_genb *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2, int32_t y2)
{
    ef_genb_pt(b, x0, y0);
    ef_genb_pt(b, x1, y1);
    ef_genb_pt(b, x2, y2);
    ef_genb_end(b);
}

static int32_t row(const ef_genb *b, int32_t r) { return ef_genb_row(b, r); }
static int32_t col(const ef_genb *b, int32_t i, int32_t k) { return ef_genb_col(b, i, k); }
static int32_t sx(const ef_genb *b, int32_t i, int s) { return ef_genb_sx(b, i, s); }
/* The sample point of sub-scanline s of pixel (i, j). */
static void spt(ef_genb *b, int32_t i, int32_t j, int s) { ef_genb_pt(b, sx(b, i, s), row(b, b->grid * j + s)); }

/* ================================================ sample rows and columns */

static void b_sample_points(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    spt(b, 1, 1, 0);
    spt(b, 6, 1, n - 1);
    spt(b, 6, 6, n / 2);
    spt(b, 1, 6, 1);
    ef_genb_end(b);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 128);
    spt(b, 0, 3, 2);
    spt(b, 7, 4, n - 3);
    spt(b, 3, 7, n / 4);
    ef_genb_end(b);
}

static void b_sample_rows(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 8, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    for (int i = 0; i < 8; i++) {
        int32_t top = n * (i % 4) / 4 + i, h = 1 + (i % 3) * (n / 8);
        RECT(b, PX(i) + 32, row(b, top), PX(i) + 224, row(b, top + h));
    }
}

static void b_sample_cols(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 4, n);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 0, 255);
    for (int s = 0; s < n; s++)
        RECT(b, sx(b, 1, s), PX(s), sx(b, 2, s), PX(s + 1));
}

static void b_sample_pm1(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 0, 255);
    for (int q = 0; q < 4; q++) {
        int32_t d = (q & 1) ? 1 : -1, e = (q & 2) ? 1 : -1;
        int32_t ox = 4 * (q & 1), oy = 4 * (q >> 1);
        RECT(b, sx(b, ox, 1) + d, row(b, n * oy + 1) + e, sx(b, ox + 3, n - 2) + d, row(b, n * (oy + 3) + n - 2) + e);
    }
}

static void b_sample_diag(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 0, 255, 255);
    spt(b, 1, 1, 0);
    spt(b, 6, 2, 3);
    spt(b, 3, 6, n / 2 + 1);
    ef_genb_end(b);
    /* a second triangle sharing the first one's sample-point vertices */
    spt(b, 1, 1, 0);
    spt(b, 3, 6, n / 2 + 1);
    spt(b, 0, 7, n - 1);
    ef_genb_end(b);
}

/* ================================================================ horizontal */

static void b_staircase(ef_genb *b, int arg)
{
    /* in half pixels: every edge horizontal or vertical */
    static const int32_t xy[] = {
        2, 2, 8, 2, 8, 7, 14, 7, 14, 12, 20, 12, 20, 17, 26, 17, 26, 22, 30, 22, 30, 30, 2, 30
    };
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 200, 100, 0, 255);
    for (int i = 0; i < 12; i++)
        ef_genb_pt(b, 128 * xy[2 * i], 128 * xy[2 * i + 1]);
    ef_genb_end(b);
}

static void b_horizontal_rows(ef_genb *b, int arg)
{
    int n = b->grid;
    int32_t y = row(b, 3 * n + 1);
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 200, 200, 255);
    /* every edge horizontal: all dropped by edge setup */
    ef_genb_pt(b, PX(1), y);
    ef_genb_pt(b, PX(3), y);
    ef_genb_pt(b, PX(6), y);
    ef_genb_pt(b, PX(2), y);
    ef_genb_end(b);
    /* top edge on a sample row (that row counts), apex below */
    tri(b, PX(1), row(b, n + 2), PX(7), row(b, n + 2), PX(4), row(b, 3 * n + 2));
    /* bottom edge on a sample row (that row does not count), apex above */
    tri(b, PX(4), row(b, 4 * n + 3), PX(7), row(b, 7 * n + 1), PX(1), row(b, 7 * n + 1));
}

/* ================================================================== vertical */

static void b_vertical_pixel(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, PX(1), PX(1), PX(3), PX(7));
    RECT(b, PX(4), PX(-2), PX(5), PX(10));
    RECT(b, PX(6), 0, PX(6) + 1, PX(8));
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 255);
    RECT(b, PX(8), 0, PX(12), PX(8));
    RECT(b, PX(9), PX(2), PX(11), PX(6));
    RECT(b, PX(13), PX(1), PX(15), PX(7));
}

static void b_vertical_subpixel(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 8, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    for (int k = 0; k < n; k++) {
        int32_t x = col(b, k % 8, k);
        RECT(b, x - 1, 0, x + 1, PX(2)); /* 2 units around sample column k */
        RECT(b, x, PX(2), x + 1, PX(4)); /* exactly [X, X + 1): that column only */
    }
}

static void b_vertical_long(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 64);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 255, 255);
    RECT(b, PX(2) + 128, -LIM, PX(5) + 64, LIM);
    RECT(b, PX(6), -LIM, PX(7), PX(32));
}

/* =============================================================== zero-length */

static void b_repeated_vertices(ef_genb *b, int arg)
{
    static const int32_t hex[] = { 4,  1,  4,  1,  12, 1,  12, 1,  12, 1, 15, 8, 15, 8,
                                   12, 15, 12, 15, 4,  15, 4,  15, 1,  8, 1,  8, 4,  1 };
    (void)arg;
    ef_genb_canvas(b, 24, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    for (int i = 0; i < 14; i++)
        ef_genb_pt(b, PX(hex[2 * i]), PX(hex[2 * i + 1]));
    ef_genb_end(b);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 255);
    for (int i = 0; i < 3; i++)
        ef_genb_pt(b, PX(17) + 77, PX(2) + 3);
    for (int i = 0; i < 3; i++)
        ef_genb_pt(b, PX(23), PX(9) + 200);
    for (int i = 0; i < 3; i++)
        ef_genb_pt(b, PX(18), PX(14) + 1);
    ef_genb_end(b);
}

static void b_zero_length_samples(ef_genb *b, int arg)
{
    int n = b->grid;
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 128, 0, 255);
    spt(b, 1, 1, 1);
    spt(b, 1, 1, 1);
    spt(b, 6, 1, 2);
    spt(b, 6, 1, 2);
    spt(b, 6, 1, 2);
    spt(b, 6, 6, n - 2);
    spt(b, 1, 6, n - 1);
    spt(b, 1, 6, n - 1);
    ef_genb_end(b);
    /* a contour of one sample point, three times */
    spt(b, 3, 3, 3);
    spt(b, 3, 3, 3);
    spt(b, 3, 3, 3);
    ef_genb_end(b);
}

/* ===================================================================== slope */

static void b_slope_45(ef_genb *b, int arg)
{
    int n = b->grid;
    int32_t cx = sx(b, 4, n / 2), cy = row(b, 4 * n + n / 2), r = PX(3);
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 128, 255, 255);
    ef_genb_pt(b, cx, cy - r);
    ef_genb_pt(b, cx + r, cy);
    ef_genb_pt(b, cx, cy + r);
    ef_genb_pt(b, cx - r, cy);
    ef_genb_end(b);
    /* a band at 45 degrees (dX = +h per sample row) from the first sample row down to the right */
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 255, 0, 128);
    ef_genb_pt(b, col(b, 0, 0), row(b, 0));
    ef_genb_pt(b, col(b, 0, 0) + 2 * b->h, row(b, 0));
    ef_genb_pt(b, col(b, 7, 0) + 2 * b->h, row(b, 0) + PX(7));
    ef_genb_pt(b, col(b, 7, 0), row(b, 0) + PX(7));
    ef_genb_end(b);
}

static void b_slope_unit(ef_genb *b, int arg)
{
    int n = b->grid;
    int32_t d = 32 * n; /* one unit per sample row over 32 pixel rows */
    (void)arg;
    ef_genb_canvas(b, 12, 32);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    ef_genb_pt(b, PX(1), 0);
    ef_genb_pt(b, PX(11), 0);
    ef_genb_pt(b, PX(11) - d, PX(32));
    ef_genb_pt(b, PX(1) + d, PX(32));
    ef_genb_end(b);
}

static void b_near_horizontal(ef_genb *b, int arg)
{
    /* y offsets inside the pixel: sample rows sit at 4, 12, ... (N = 32),
     * 8, 24, ... (N = 16), 16, 48, ... (N = 8) */
    static const int32_t t[8] = { 3, 4, 7, 8, 15, 16, 47, 48 };
    (void)arg;
    ef_genb_canvas(b, 16, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    for (int j = 0; j < 8; j++) {
        int32_t y = PX(j) + t[j];
        /* horizontal top, vertical right side, and an edge with dY = 1 unit */
        tri(b, 0, y, PX(16), y + 1, PX(16), y);
    }
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 128);
    for (int j = 0; j < 8; j++) {
        int32_t y = PX(j) + t[j];
        tri(b, PX(2), y - 1, PX(14), y + 1, PX(2), y + 1); /* dY = 2 units */
    }
}

static void b_near_vertical(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 512);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 0, 255);
    /* dX = -1 and +1 unit over 512 px */
    ef_genb_pt(b, PX(4) + 4, 0);
    ef_genb_pt(b, PX(7) + 4, 0);
    ef_genb_pt(b, PX(7) + 5, PX(512));
    ef_genb_pt(b, PX(4) + 3, PX(512));
    ef_genb_end(b);
    /* dX = +-3 units over 512 px, crossing sample columns */
    ef_genb_pt(b, PX(9) + 1, 0);
    ef_genb_pt(b, PX(12) + 125, 0);
    ef_genb_pt(b, PX(12) + 122, PX(512));
    ef_genb_pt(b, PX(9) + 4, PX(512));
    ef_genb_end(b);
}

static void b_long_exact(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 64, 2048);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 255, 128, 255);
    tri(b, -5120085, -8388480, 5120030, 8388416, 8064, PX(1024));
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 128, 128);
    tri(b, PX(-3001) - 77, PX(-17) + 3, PX(3067) + 201, PX(2100) - 9, PX(-1) + 1, PX(2090) + 131);
}

/* ================================================================ degenerate */

static void b_single_point(ef_genb *b, int arg)
{
    static const int32_t p[][2] = { { PX(2), PX(2) }, { PX(4) + 128, PX(4) + 128 }, { 0, 0 },
                                    { PX(8), PX(8) }, { PX(3) + 26, PX(5) + 201 },  { PX(6) + 16, PX(1) + 16 } };
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    for (int i = 0; i < 6; i++) {
        for (int r = 0; r < 3; r++)
            ef_genb_pt(b, p[i][0], p[i][1]);
        ef_genb_end(b);
    }
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 255, 0, 255);
    for (int r = 0; r < 5; r++)
        ef_genb_pt(b, PX(5) + 100, PX(5) + 100);
    ef_genb_end(b);
}

static void b_collinear(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    /* on y = (x + 1) / 2, out and back */
    ef_genb_pt(b, PX(1), PX(1));
    ef_genb_pt(b, PX(7), PX(4));
    ef_genb_pt(b, PX(3), PX(2));
    ef_genb_pt(b, PX(5), PX(3));
    ef_genb_end(b);
    /* vertical and horizontal */
    tri(b, PX(2) + 100, PX(1), PX(2) + 100, PX(7), PX(2) + 100, PX(3));
    tri(b, PX(1), PX(6) + 8, PX(7), PX(6) + 8, PX(4), PX(6) + 8);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 255);
    tri(b, PX(0), PX(0), PX(8), PX(8), PX(4), PX(4));
}

static void b_spike(ef_genb *b, int arg)
{
    static const int32_t xy[] = { 2, 2, 8, 2, 8, 5, 14, 11, 8, 5, 8, 8, 2, 8 };
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 0, 255);
    for (int i = 0; i < 7; i++)
        ef_genb_pt(b, PX(xy[2 * i]), PX(xy[2 * i + 1]));
    ef_genb_end(b);
}

static void b_touching(ef_genb *b, int arg)
{
    static const int32_t xy[] = { 1, 1, 5, 5, 9, 1, 9, 9, 5, 5, 1, 9 };
    (void)arg;
    ef_genb_canvas(b, 10, 10);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 255, 255);
    for (int i = 0; i < 6; i++)
        ef_genb_pt(b, PX(xy[2 * i]), PX(xy[2 * i + 1]));
    ef_genb_end(b);
}

static void b_tiny(ef_genb *b, int arg)
{
    int n = b->grid;
    int32_t y = row(b, n + 2), x = sx(b, 1, 2), h = b->h;
    (void)arg;
    ef_genb_canvas(b, 4, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    /* strictly between two sample rows: covers nothing */
    tri(b, x - 2, y + 1, x + 2, y + 1, x, y + h - 1);
    /* around exactly one sample point: sample 3 of pixel (2, 1) */
    tri(b, sx(b, 2, 3) - 2, row(b, n + 3) - 2, sx(b, 2, 3) + 2, row(b, n + 3) - 2, sx(b, 2, 3), row(b, n + 3) + 2);
    /* one unit square on a sample point: covers exactly that sample */
    RECT(b, sx(b, 1, n - 1), row(b, 2 * n + n - 1), sx(b, 1, n - 1) + 1, row(b, 2 * n + n - 1) + 1);
    /* one unit square just left of a sample point: covers nothing */
    RECT(b, sx(b, 2, 5) - 1, row(b, 2 * n + 5), sx(b, 2, 5), row(b, 2 * n + 5) + 1);
}

static void b_empty_shape(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 6, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 255, 0, 255);
    tri(b, PX(1), PX(1), PX(5), PX(2), PX(2), PX(3) + 128);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 0, 255, 255);
}

static void b_empty_scene(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 5, 3);
}

/* ================================================================ coincident */

static void b_shared_edges(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 128, 255, 128);
    RECT(b, PX(1), PX(1), PX(4), PX(4));
    RECT(b, PX(4), PX(1), PX(7), PX(4)); /* shares x = 4 */
    RECT(b, PX(1), PX(4), PX(4), PX(7)); /* shares y = 4 */
    tri(b, PX(9), PX(1), PX(15), PX(1), PX(15), PX(7));
    tri(b, PX(9), PX(1), PX(15), PX(7), PX(9), PX(7)); /* shares the diagonal */
    tri(b, PX(4) + 37, PX(4) + 11, PX(7), PX(4) + 200, PX(5) + 3, PX(7));
    tri(b, PX(4) + 37, PX(4) + 11, PX(5) + 3, PX(7), PX(4), PX(6) + 1); /* shares a sloped edge */
}

static void b_identical_evenodd(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 0, 0, 255);
    RECT(b, PX(1), PX(1), PX(4), PX(7));
    RECT(b, PX(1), PX(1), PX(4), PX(7));
    RECT(b, PX(4) + 77, PX(1) + 5, PX(7) + 3, PX(6) + 250);
    rect_ccw(b, PX(4) + 77, PX(1) + 5, PX(7) + 3, PX(6) + 250);
}

static void b_identical_nonzero(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, PX(1), PX(1), PX(7), PX(7));
    RECT(b, PX(1), PX(1), PX(7), PX(7));
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 0, 255, 128);
    for (int i = 0; i < 3; i++)
        tri(b, PX(2) + 33, PX(2) + 7, PX(6) + 200, PX(3) + 99, PX(3) + 1, PX(6) + 254);
}

static void b_overlap_collinear(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 12, 12);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 0, 0, 255);
    RECT(b, PX(2), PX(1), PX(6), PX(7));
    RECT(b, PX(2), PX(4), PX(6), PX(10)); /* x = 2 and x = 6 overlap for 4 <= y <= 7 */
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 0, 128);
    RECT(b, PX(7), PX(1), PX(11), PX(5));
    RECT(b, PX(8), PX(1), PX(10), PX(5)); /* y = 1 and y = 5 overlap for 8 <= x <= 10 */
    rect_ccw(b, PX(7), PX(8), PX(11), PX(11));
    RECT(b, PX(7), PX(9), PX(11), PX(11) + 128); /* x = 7 and 11 overlap in opposite directions */
}

static void b_t_junction(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 12, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 128, 0, 255, 255);
    RECT(b, PX(1), PX(1), PX(5), PX(7));
    RECT(b, PX(5), PX(3), PX(9), PX(5));                     /* its left edge lies inside the first's right edge */
    tri(b, PX(9), PX(1), PX(11), PX(4), PX(9), PX(7) + 128); /* its edge x = 9 contains the second's right edge */
}

/* ==================================================================== cancel */

static void b_reversed_pair(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, PX(1), PX(1), PX(7), PX(7));
    rect_ccw(b, PX(1), PX(1), PX(7), PX(7));
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 255);
    tri(b, PX(1) + 50, PX(2) + 3, PX(6) + 9, PX(4) + 100, PX(2) + 3, PX(7) + 1);
    tri(b, PX(2) + 3, PX(7) + 1, PX(6) + 9, PX(4) + 100, PX(1) + 50, PX(2) + 3);
}

static void b_self_cancel(ef_genb *b, int arg)
{
    static const int32_t xy[] = { 2, 2, 6, 2, 6, 6, 2, 6, 2, 2, 2, 6, 6, 6, 6, 2 };
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 0, 255);
    for (int i = 0; i < 8; i++)
        ef_genb_pt(b, PX(xy[2 * i]) + 11, PX(xy[2 * i + 1]) + 5);
    ef_genb_end(b);
}

static void b_hole(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 20, 10);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, PX(1), PX(1), PX(9), PX(9));
    rect_ccw(b, PX(3), PX(3), PX(7), PX(7)); /* opposite: a hole */
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 0, 255, 255);
    RECT(b, PX(11), PX(1), PX(19), PX(9));
    RECT(b, PX(13), PX(3), PX(17), PX(7)); /* same direction: winding 2, no hole */
}

static void b_figure8(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 0, 255);
    /* a bow tie: lobes of winding +1 and -1 */
    ef_genb_pt(b, PX(1), PX(1));
    ef_genb_pt(b, PX(7), PX(7));
    ef_genb_pt(b, PX(7), PX(1));
    ef_genb_pt(b, PX(1), PX(7));
    ef_genb_end(b);
    /* a bow tie overlapped by a square of winding +1: the -1 lobe cancels to 0 */
    ef_genb_pt(b, PX(9), PX(1));
    ef_genb_pt(b, PX(15), PX(7));
    ef_genb_pt(b, PX(15), PX(1));
    ef_genb_pt(b, PX(9), PX(7));
    ef_genb_end(b);
    rect_ccw(b, PX(9), PX(1), PX(15), PX(7));
}

static void b_star(ef_genb *b, int arg)
{
    /* a pentagram of radius 5 px: the inner pentagon has winding 2 */
    static const int32_t p[5][2] = { { 1536, 256 }, { 2288, 2572 }, { 319, 1141 }, { 2753, 1141 }, { 784, 2572 } };
    (void)arg;
    ef_genb_canvas(b, 24, 12);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 128, 0, 255);
    for (int i = 0; i < 5; i++)
        ef_genb_pt(b, p[i][0], p[i][1]);
    ef_genb_end(b);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 128, 255, 255);
    for (int i = 0; i < 5; i++)
        ef_genb_pt(b, p[i][0] + PX(12), p[i][1]);
    ef_genb_end(b);
}

static void b_rings(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    RECT(b, PX(1), PX(1), PX(15), PX(15));
    rect_ccw(b, PX(3), PX(3), PX(13), PX(13));
    RECT(b, PX(5), PX(5), PX(11), PX(11));
    rect_ccw(b, PX(7), PX(7), PX(9), PX(9));
}

/* ========================================================= winding overflow */

/* |arg| coincident squares [2, 6]^2: clockwise (left edge up) if arg > 0,
 * counter-clockwise if arg < 0. */
static void b_overflow(ef_genb *b, int arg)
{
    int n = arg < 0 ? -arg : arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    for (int i = 0; i < n; i++) {
        if (arg > 0)
            RECT(b, PX(2), PX(2), PX(6), PX(6));
        else
            rect_ccw(b, PX(2), PX(2), PX(6), PX(6));
    }
}

static void b_overflow_evenodd(ef_genb *b, int arg)
{
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 0, 0, 255);
    for (int i = 0; i < arg; i++)
        RECT(b, PX(2), PX(2), PX(6), PX(6));
}

static void b_overflow_nested(ef_genb *b, int arg)
{
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 0, 255);
    for (int i = 0; i < arg; i++)
        rect_ccw(b, 128 + 12 * i, 128 + 12 * i, PX(16) - 128 - 12 * i, PX(16) - 128 - 12 * i);
}

static void b_overflow_staggered(ef_genb *b, int arg)
{
    ef_genb_canvas(b, 16, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 0, 255, 255);
    for (int i = 0; i < arg; i++)
        rect_ccw(b, PX(2) + 8 * i, PX(2), PX(10) + 8 * i, PX(6));
}

/* ================================================================ limits */

static void b_limit_corners(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, -LIM, -LIM, LIM, LIM);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 200);
    /* its long edge runs from (-LIM + 16 px, LIM) to (LIM, -LIM + 16 px): x + y = 16 px */
    tri(b, -LIM + PX(16), LIM, LIM, -LIM + PX(16), LIM, LIM);
}

static void b_limit_long_edges(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 0, 160);
    tri(b, -LIM, PX(8), LIM, PX(8) + 1, LIM, LIM); /* dX = 2^24 - 2, dY = 1 */
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 255, 160);
    tri(b, PX(8), -LIM, PX(8) + 1, LIM, -LIM, LIM); /* dX = 1, dY = 2^24 - 2 */
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 0, 255, 160);
    tri(b, -LIM, -LIM, LIM, LIM - 1, -LIM + 1, LIM); /* both near 2^24 */
}

/* ================================================================ outside */

static void b_outside_sides(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, -LIM, PX(2), -1, PX(14));    /* left: flags clamp to cell 0 and cancel */
    RECT(b, PX(16), PX(2), LIM, PX(14)); /* right: from x = W on, all in the sink */
    RECT(b, PX(2), -LIM, PX(14), 0);     /* above */
    RECT(b, PX(2), PX(16), PX(14), LIM); /* below */
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 255, 0, 255);
    tri(b, -LIM, -LIM, -LIM + 5, -LIM, -LIM, -LIM + 5);
    tri(b, LIM, LIM, LIM - 5, LIM, LIM, LIM - 5);
    tri(b, -LIM, LIM, -PX(1), PX(8), -LIM, -LIM);
}

static void b_outside_partial(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, -LIM, PX(2), PX(10), PX(14));
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 0, 255, 128);
    ef_genb_pt(b, PX(6), PX(4));
    ef_genb_pt(b, LIM, PX(2));
    ef_genb_pt(b, LIM, PX(14));
    ef_genb_pt(b, PX(6), PX(12));
    ef_genb_end(b);
}

static void b_outside_crossing(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 16, 16);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 255, 0, 255);
    ef_genb_pt(b, -LIM, -LIM);
    ef_genb_pt(b, LIM, PX(4));
    ef_genb_pt(b, -LIM, PX(8));
    ef_genb_pt(b, LIM, PX(12));
    ef_genb_pt(b, -LIM, LIM);
    ef_genb_end(b);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 0, 255, 128);
    tri(b, PX(8), -LIM, LIM, LIM, -LIM, LIM);
}

/* ============================================================ clip borders */

static void b_canvas_rect(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 7, 5);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    RECT(b, 0, 0, PX(7), PX(5));
}

static void b_border_strips(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 0, 0, 255);
    RECT(b, 0, 0, PX(1), PX(8));
    RECT(b, PX(7), 0, PX(8), PX(8));
    RECT(b, 0, 0, PX(8), PX(1));
    RECT(b, 0, PX(7), PX(8), PX(8));
}

static void b_border_pm1(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    RECT(b, -1, -1, PX(8) + 1, PX(8) + 1);
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 128);
    RECT(b, 1, 1, PX(8) - 1, PX(8) - 1);
}

static void b_border_rows(ef_genb *b, int arg)
{
    int n = b->grid;
    int32_t first = row(b, 0), last = row(b, 4 * n - 1);
    (void)arg;
    ef_genb_canvas(b, 4, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    RECT(b, 64, first, PX(1), last);                 /* first row counts, last does not */
    RECT(b, PX(1) + 64, first + 1, PX(2), last + 1); /* first row missed, last counts */
    RECT(b, PX(2) + 64, first - 1, PX(3), last - 1); /* first row counts, last missed */
    RECT(b, PX(3) + 64, 0, PX(4), PX(4));            /* exactly the canvas' top and bottom */
}

static void b_right_sink(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 8, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 0, 255);
    RECT(b, PX(7) + 128, 0, PX(11), PX(1));  /* crosses x = W */
    RECT(b, PX(8), PX(1), PX(12), PX(2));    /* starts exactly at x = W: nothing */
    RECT(b, PX(8) - 1, PX(2), PX(8), PX(3)); /* the last unit before x = W */
    RECT(b, -PX(3), PX(3), 128, PX(4));      /* crosses x = 0 */
}

/* ========================================================== edges per row */

/* One zigzag contour of arg edges, every one crossing every sample row
 * between y = 0.5 and 7.5 px; spread evenly over the canvas width. */
static void b_zigzag(ef_genb *b, int arg)
{
    int32_t w = arg > 4096 ? 256 : 64;
    ef_genb_canvas(b, w, 8);
    ef_genb_shape(b, EF_RULE_EVENODD, 255, 255, 255, 255);
    for (int32_t i = 0; i < arg; i++)
        ef_genb_pt(b, (int32_t)((int64_t)i * PX(w) / arg) + 1, (i & 1) ? PX(7) + 128 : 128);
    ef_genb_end(b);
}

/* arg edges all crossing inside pixel column 1. */
static void b_same_cell(ef_genb *b, int arg)
{
    ef_genb_canvas(b, 4, 4);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 0, 255);
    for (int32_t i = 0; i < arg; i++)
        ef_genb_pt(b, PX(1) + (i * 37) % 256, (i & 1) ? PX(3) + 128 : 128);
    ef_genb_end(b);
}

/* ================================================================ canvas */

static void b_canvas_1x1(ef_genb *b, int arg)
{
    (void)arg;
    ef_genb_canvas(b, 1, 1);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    tri(b, 0, 0, PX(1), 0, 0, PX(1));
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 128);
    RECT(b, 64, 64, 192, 192);
}

static void b_canvas_max(ef_genb *b, int arg)
{
    const int32_t m = EF_MAX_CANVAS;
    (void)arg;
    ef_genb_canvas(b, m, m);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 0, 0, 255);
    tri(b, 0, 0, PX(3), 0, 0, PX(3));
    RECT(b, PX(m - 3), PX(m - 3), PX(m), PX(m));
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 0, 255, 255);
    RECT(b, PX(m / 2) - 128, 0, PX(m / 2) + 128, PX(m)); /* every row */
    RECT(b, 0, PX(m / 2) - 128, PX(m), PX(m / 2) + 128); /* every column */
}

static void b_canvas_max_full(ef_genb *b, int arg)
{
    const int32_t m = EF_MAX_CANVAS;
    (void)arg;
    ef_genb_canvas(b, m, m);
    ef_genb_shape(b, EF_RULE_NONZERO, 0, 255, 0, 255);
    RECT(b, 0, 0, PX(m), PX(m));
}

static void b_canvas_wide(ef_genb *b, int arg)
{
    const int32_t m = EF_MAX_CANVAS;
    (void)arg;
    ef_genb_canvas(b, m, 1);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    tri(b, 0, 0, PX(m), 0, PX(m), PX(1));
}

static void b_canvas_tall(ef_genb *b, int arg)
{
    const int32_t m = EF_MAX_CANVAS;
    (void)arg;
    ef_genb_canvas(b, 1, m);
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 255);
    tri(b, 0, 0, PX(1), PX(m), 0, PX(m));
}

/* =========================================================== compositing */

static void b_alpha_steps(ef_genb *b, int arg)
{
    static const uint8_t c[8][4] = { { 255, 0, 0, 0 }, { 255, 255, 255, 1 }, { 0, 0, 0, 127 }, { 255, 255, 255, 128 },
                                     { 1, 2, 3, 129 }, { 255, 0, 255, 254 }, { 0, 0, 0, 255 }, { 255, 255, 255, 255 } };
    (void)arg;
    ef_genb_canvas(b, 8, 8);
    for (int i = 0; i < 8; i++) {
        ef_genb_shape(b, EF_RULE_NONZERO, c[i][0], c[i][1], c[i][2], c[i][3]);
        RECT(b, PX(i), 0, PX(i + 1), PX(8));
    }
    ef_genb_shape(b, EF_RULE_EVENODD, 0, 255, 0, 128);
    RECT(b, 0, PX(3), PX(8), PX(5));
    ef_genb_shape(b, EF_RULE_NONZERO, 255, 255, 255, 0); /* paints nothing */
    RECT(b, 0, 0, PX(8), PX(8));
}

static void b_many_shapes(ef_genb *b, int arg)
{
    ef_genb_canvas(b, 4, 4);
    for (int i = 0; i < arg; i++) {
        ef_genb_shape(b, (i & 1) ? EF_RULE_EVENODD : EF_RULE_NONZERO, (uint8_t)i, (uint8_t)(255 - i), (uint8_t)(i * 7),
                      (uint8_t)(1 + i % 254));
        RECT(b, PX(1) - (i % 5), PX(1) + (i % 3), PX(3) + (i % 7), PX(3));
    }
}

/* ================================================================ the table */

#define G EF_GEN_F_GRID
#define L2 EF_GEN_F_LEVEL2
#define NS EF_GEN_F_NOSWAP

const ef_gen_dcase ef_gen_dcases[] = {
    /* ---- vertices exactly on sample rows and columns (spec 4 and 5.1) ---- */
    { "sample-points", EF_GEN_CAT_SAMPLE_GRID, G, X_ANY, b_sample_points, 0,
      "Quad and triangle whose vertices are exactly sample points (X_s(i), Y_r): the tie rule decides "
      "every sample a vertex sits on (crossing counted when x_r <= X_s; rows Y0 <= Y_r < Y1)." },
    { "sample-rows", EF_GEN_CAT_SAMPLE_GRID, G, X_ANY, b_sample_rows, 0,
      "Rectangles whose top and bottom edges lie exactly on sample rows, 1 to 1+N/4 rows tall: the "
      "top row is covered, the bottom row is not (half-open in y)." },
    { "sample-columns", EF_GEN_CAT_SAMPLE_GRID, G, X_ANY, b_sample_cols, 0,
      "For each sub-scanline s, a rectangle on pixel row s whose left and right edges are exactly at "
      "sample s of pixel columns 1 and 2: pixel 1's sample s is covered, pixel 2's is not (half-open in x)." },
    { "sample-plus-minus-1", EF_GEN_CAT_SAMPLE_GRID, G, X_ANY, b_sample_pm1, 0,
      "Four rectangles whose sides are one Q16.8 unit (1/256 px) left/right of sample columns and "
      "above/below sample rows, in all four combinations: the smallest offset that flips a tie." },
    { "sample-diagonals", EF_GEN_CAT_SAMPLE_GRID, G, X_ANY, b_sample_diag, 0,
      "Two triangles joining sample points by sloped edges and sharing one edge (even-odd), so the "
      "crossings between the end points fall between samples with exact remainders." },

    /* ---- horizontal edges ---- */
    { "staircase", EF_GEN_CAT_HORIZONTAL, 0, X_PROBE(2, 12, 255, 0), b_staircase, 0,
      "Rectilinear staircase with pixel and half-pixel steps: half its edges are horizontal and "
      "dropped by edge setup; the vertical ones alone must fill it." },
    { "horizontal-on-rows", EF_GEN_CAT_HORIZONTAL, G, X_ANY, b_horizontal_rows, 0,
      "A contour whose every edge is horizontal on a sample row (nothing is drawn), a triangle whose "
      "horizontal top lies on a sample row (that row counts) and one whose horizontal bottom does "
      "(that row does not)." },

    /* ---- vertical edges ---- */
    { "vertical-pixel-aligned", EF_GEN_CAT_VERTICAL, 0, X_PROBE(2, 4, 255, 0), b_vertical_pixel, 0,
      "Pixel-aligned rectangles (integer x and y), one running past the top and bottom, one only "
      "1/256 px wide on a pixel boundary (covers no sample), and an even-odd frame: covers exactly "
      "[left, right) x [top, bottom)." },
    { "vertical-sample-columns", EF_GEN_CAT_VERTICAL, G, X_ANY, b_vertical_subpixel, 0,
      "For each sample column k of the sub-grid a strip 2 units wide around it and one exactly "
      "[X, X + 1 unit): each covers exactly one sample per pixel row." },
    { "vertical-full-height", EF_GEN_CAT_VERTICAL, 0, X_PROBE(3, 40, 255, 0), b_vertical_long, 0,
      "Vertical edges from y = -(2^23 - 1) to +(2^23 - 1) Q16.8 at fractional x: clipped at the top "
      "(DDA started at row 0) and the bottom." },

    /* ---- zero-length edges ---- */
    { "repeated-vertices", EF_GEN_CAT_ZERO_LENGTH, 0, X_PROBE(8, 8, 255, 0), b_repeated_vertices, 0,
      "A hexagon with every vertex repeated two or three times and the first point repeated at the "
      "end, and a triangle of thrice-repeated vertices: zero-length edges contribute nothing." },
    { "zero-length-on-samples", EF_GEN_CAT_ZERO_LENGTH, G, X_ANY, b_zero_length_samples, 0,
      "Zero-length edges exactly on sample points (repeated sample-point vertices), and a contour of "
      "one sample point three times." },

    /* ---- slopes ---- */
    { "slope-1-sample-per-row", EF_GEN_CAT_SLOPE, G, X_ANY, b_slope_45, 0,
      "A diamond centred on a sample point with edges of slope +1 and -1 (one sample column per "
      "sample row: dX = +-h per sample row) and vertices on the sample lattice, and a 45-degree band "
      "(dX = +h per sample row) running down to the right from the first sample row." },
    { "slope-1-unit-per-row", EF_GEN_CAT_SLOPE, G, X_ANY, b_slope_unit, 0,
      "A trapezoid whose sloped edges move exactly +-1 Q16.8 unit per sample row (qs = +-1, rs = 0) "
      "over 32 pixel rows." },
    { "near-horizontal", EF_GEN_CAT_SLOPE, 0, X_ANY, b_near_horizontal, 0,
      "Edges with dY = 1 unit across the whole width and dY = 2 units across most of it, at y offsets "
      "3, 4, 7, 8, 15, 16, 47, 48 "
      "units into the pixel (sample rows of N = 32, 16, 8 sit at 4, 8, 16 + multiples): each "
      "crosses a sample row only if one lies in [Y0, Y1)." },
    { "near-vertical", EF_GEN_CAT_SLOPE, 0, X_ANY, b_near_vertical, 0,
      "Edges with dX = +-1 and +-3 units over 512 px (dY = 131072): the exact DDA's remainder "
      "carries over up to 16384 sample rows without drift." },
    { "long-exact", EF_GEN_CAT_SLOPE, 0, X_ANY, b_long_exact, 0,
      "Long edges with large, odd-valued dX and dY (one from y = -32767.5 to +32767.25 px) across a "
      "64 x 2048 canvas: any slope rounding would drift by the bottom." },

    /* ---- degenerate and zero-area polygons ---- */
    { "single-point", EF_GEN_CAT_DEGENERATE, 0, X_EMPTY, b_single_point, 0,
      "Contours of one point repeated 3 or 5 times, at integer, pixel-centre, corner, canvas-corner "
      "and odd positions: nothing is drawn." },
    { "collinear", EF_GEN_CAT_DEGENERATE, 0, X_EMPTY, b_collinear, 0,
      "Contours whose points all lie on one line (sloped, vertical, horizontal), going out and "
      "back: zero area, nothing is drawn." },
    { "spike", EF_GEN_CAT_DEGENERATE, 0, X_PROBE(12, 9, 0, 0), b_spike, 0,
      "A square with a zero-width spike out and back along one diagonal segment: the spike's "
      "coincident opposite edges cancel, so pixel (12, 9) on it stays empty." },
    { "touching-vertex", EF_GEN_CAT_DEGENERATE, 0, X_ANY, b_touching, 0,
      "One contour of two triangles that touch at a single vertex (5, 5), visited twice." },
    { "tiny", EF_GEN_CAT_DEGENERATE, G, X_ANY, b_tiny, 0,
      "Polygons smaller than the sample spacing: a triangle strictly between two sample rows (covers "
      "nothing), one around exactly one sample point, a 1-unit square on a sample point (covers "
      "exactly it) and one just left of one (covers nothing)." },
    { "empty-shapes", EF_GEN_CAT_DEGENERATE, 0, X_ANY, b_empty_shape, 0,
      "A shape with no contours before and after a shape with one triangle: empty shapes paint "
      "nothing and change nothing." },
    { "empty-scene", EF_GEN_CAT_DEGENERATE, NS, X_EMPTY, b_empty_scene, 0, "A 5 x 3 canvas with no shapes at all." },

    /* ---- coincident and overlapping edges ---- */
    { "shared-edges", EF_GEN_CAT_COINCIDENT, 0, X_PROBE(12, 4, 128, 0), b_shared_edges, 0,
      "Translucent (alpha 128) squares and triangles sharing vertical, horizontal, diagonal and "
      "sloped edges in one shape: every sample is in exactly one of them, so no pixel shows double "
      "or missing coverage (pixel (12, 4) on the shared diagonal has alpha 128)." },
    { "identical-evenodd", EF_GEN_CAT_COINCIDENT, 0, X_EMPTY, b_identical_evenodd, 0,
      "Even-odd: two identical rectangles in the same direction, and two in opposite directions: "
      "both pairs cancel, nothing is drawn." },
    { "identical-nonzero", EF_GEN_CAT_COINCIDENT, 0, X_PROBE(4, 4, 255, 0), b_identical_nonzero, 0,
      "Non-zero: two identical squares in the same direction (winding 2: covered once) and three "
      "identical translucent triangles (covered once, not three times)." },
    { "overlapping-collinear", EF_GEN_CAT_COINCIDENT, 0, X_PROBE(4, 5, 0, 0), b_overlap_collinear, 0,
      "Rectangles whose vertical or horizontal edges overlap over part of their length, in the same "
      "and in opposite directions; the even-odd overlap (4 <= y < 7) is empty." },
    { "t-junction", EF_GEN_CAT_COINCIDENT, 0, X_PROBE(5, 4, 255, 0), b_t_junction, 0,
      "Polygons whose edge lies inside another's edge, and a vertex on another's edge (T-junctions)." },

    /* ---- windings that cancel ---- */
    { "reversed-pair", EF_GEN_CAT_CANCEL, 0, X_EMPTY, b_reversed_pair, 0,
      "A square and the same square reversed (non-zero), a triangle and its reverse (even-odd): "
      "windings cancel to 0, nothing is drawn." },
    { "self-cancel", EF_GEN_CAT_CANCEL, 0, X_EMPTY, b_self_cancel, 0,
      "One contour that goes round a square clockwise and then counter-clockwise: it cancels itself." },
    { "hole", EF_GEN_CAT_CANCEL, 0, X_PROBE(5, 5, 0, 0), b_hole, 0,
      "Non-zero: a square with an opposite inner square (winding 0: a hole, pixel (5, 5) empty) next "
      "to one with a same-direction inner square (winding 2: filled)." },
    { "bow-tie", EF_GEN_CAT_CANCEL, 0, X_ANY, b_figure8, 0,
      "Bow ties with lobes of winding +1 and -1 (both filled under non-zero), and one overlapped by a "
      "square of winding +1 so that one lobe cancels to 0 and the other reaches 2." },
    { "pentagram", EF_GEN_CAT_CANCEL, 0, X_PROBE(6, 6, 255, 0), b_star, 0,
      "Pentagrams: the inner pentagon has winding 2 (filled under non-zero, a hole under even-odd)." },
    { "alternating-rings", EF_GEN_CAT_CANCEL, 0, X_PROBE(4, 8, 0, 0), b_rings, 0,
      "Four nested squares of alternating direction: windings 1, 0, 1, 0 from the outside in." },

    /* ---- winding counter overflow past 127 (spec 6.3, 6.4) ---- */
    { "overflow-63", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(4, 4, 255, 0), b_overflow, 63,
      "63 coincident clockwise squares, non-zero: windings -63 and +63 in the cells, the largest "
      "that fit a signed 7-bit counter; covered, no overflow." },
    { "overflow-64", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(4, 4, 255, 1), b_overflow, 64,
      "64 coincident clockwise squares, non-zero: the right edges' cell reaches +64, a signed 7-bit "
      "overflow (diagnosed), yet 64 mod 128 != 0 so the square is still covered." },
    { "overflow-127", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(4, 4, 255, 1), b_overflow, 127,
      "127 coincident clockwise squares, non-zero: winding 127, covered." },
    { "overflow-128", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(4, 4, 0, 1), b_overflow, 128,
      "128 coincident clockwise squares, non-zero: winding 128 wraps to 0 in the 7-bit counters, so "
      "the square reads as uncovered (defined behaviour, docs/spec.md 6.4)." },
    { "overflow-129", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(4, 4, 255, 1), b_overflow, 129,
      "129 coincident clockwise squares, non-zero: winding 129 reads as 1, covered." },
    { "overflow-minus-128", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(4, 4, 0, 1), b_overflow, -128,
      "128 coincident counter-clockwise squares, non-zero: winding +128 wraps to 0, uncovered." },
    { "overflow-nested-130", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(8, 8, 255, 1), b_overflow_nested, 130,
      "130 nested counter-clockwise squares 12 units apart: the winding rises 1..130 inwards, so "
      "only the 12-unit ring of winding 128 reads as uncovered; the centre (130) is covered." },
    { "overflow-staggered-128", EF_GEN_CAT_OVERFLOW, 0, X_PROBE(6, 4, 0, 1), b_overflow_staggered, 128,
      "128 counter-clockwise rectangles each shifted 8 units right: the flags land in different "
      "cells and the filler's accumulator reaches 128 (wraps to 0) between x = 6 and 10 px." },
    { "overflow-minus-63", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 255, 0), b_overflow, -63,
      "63 coincident counter-clockwise squares, non-zero: covered, no overflow." },
    { "overflow-minus-64", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 255, 1), b_overflow, -64,
      "64 coincident counter-clockwise squares, non-zero: the left edges' cell reaches +64 "
      "(diagnosed overflow), still covered." },
    { "overflow-minus-129", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 255, 1), b_overflow, -129,
      "129 coincident counter-clockwise squares, non-zero: covered." },
    { "overflow-255", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 255, 1), b_overflow, 255,
      "255 coincident clockwise squares, non-zero: covered." },
    { "overflow-256", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 0, 1), b_overflow, 256,
      "256 coincident clockwise squares, non-zero: winding 256 wraps to 0, uncovered." },
    { "overflow-257", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 255, 1), b_overflow, 257,
      "257 coincident clockwise squares, non-zero: covered." },
    { "overflow-384", EF_GEN_CAT_OVERFLOW, L2, X_PROBE(4, 4, 0, 1), b_overflow, 384,
      "384 coincident clockwise squares, non-zero: winding 3 x 128 wraps to 0, uncovered." },
    { "evenodd-128", EF_GEN_CAT_OVERFLOW, L2 | NS, X_PROBE(4, 4, 0, 0), b_overflow_evenodd, 128,
      "128 coincident squares under even-odd: even, uncovered, and no counter to overflow." },
    { "evenodd-129", EF_GEN_CAT_OVERFLOW, L2 | NS, X_PROBE(4, 4, 255, 0), b_overflow_evenodd, 129,
      "129 coincident squares under even-odd: odd, covered." },

    /* ---- coordinates at the format's limits: +-(2^23 - 1) Q16.8 ---- */
    { "limit-corners", EF_GEN_CAT_LIMITS, 0, X_FULL, b_limit_corners, 0,
      "A square with corners at (+-(2^23 - 1), +-(2^23 - 1)) Q16.8 (+-32767.99609375 px) covering the "
      "canvas, and a triangle whose edge of dX, dY near 2^24 runs along x + y = 16 px." },
    { "limit-long-edges", EF_GEN_CAT_LIMITS, 0, X_ANY, b_limit_long_edges, 0,
      "Edges with dX = 2^24 - 2 and dY = 1 (step quotient qs = 32 dX, just below 2^29, at N = 8), with dX = 1 and "
      "dY = 2^24 - 2, and with both near 2^24: the DDA's widest values." },

    /* ---- far outside the clip rectangle ---- */
    { "outside-all-sides", EF_GEN_CAT_OUTSIDE, 0, X_EMPTY, b_outside_sides, 0,
      "Rectangles wholly left (to x = -1 unit: flags clamp to cell 0 and cancel), right (from x = W: "
      "the sink cell), above (to y = 0) and below (from y = H), and triangles at the far corners: "
      "nothing is drawn." },
    { "outside-left-partial", EF_GEN_CAT_OUTSIDE, 0, X_PROBE(0, 8, 255, 0), b_outside_partial, 0,
      "A rectangle from x = -(2^23 - 1) to 10 px (the left flags clamp into cell 0 without changing "
      "a visible sample) and a quad reaching x = +(2^23 - 1) on the right." },
    { "outside-crossing", EF_GEN_CAT_OUTSIDE, 0, X_ANY, b_outside_crossing, 0,
      "A zigzag and a triangle whose vertices are all far outside on every side but whose edges "
      "cross the canvas." },

    /* ---- edges on the clip borders ---- */
    { "canvas-rect", EF_GEN_CAT_CLIP_BORDER, 0, X_FULL, b_canvas_rect, 0,
      "A rectangle exactly equal to the 7 x 5 canvas: every sample covered." },
    { "border-strips", EF_GEN_CAT_CLIP_BORDER, 0, X_PROBE(0, 0, 0, 0), b_border_strips, 0,
      "One-pixel strips along the four borders (even-odd): the corners, covered twice, are empty." },
    { "border-plus-minus-1", EF_GEN_CAT_CLIP_BORDER, 0, X_FULL, b_border_pm1, 0,
      "A rectangle one unit outside every border (opaque) and one one unit inside (translucent)." },
    { "border-sample-rows", EF_GEN_CAT_CLIP_BORDER, G, X_ANY, b_border_rows, 0,
      "Strips starting and ending exactly at the first and last sample rows of the canvas and one "
      "unit either side, and one exactly from y = 0 to y = H: row clipping r0 = 0, r1 = N H - 1." },
    { "right-sink", EF_GEN_CAT_CLIP_BORDER, 0, X_ANY, b_right_sink, 0,
      "Rectangles crossing x = W, starting exactly at x = W (all flags in the sink cell W), ending "
      "exactly at W, and crossing x = 0." },

    /* ---- maximum edges per scanline ---- */
    { "zigzag-4096", EF_GEN_CAT_EDGES_PER_ROW, 0, X_ANY, b_zigzag, 4096,
      "One zigzag contour of 4096 edges, 4 units apart, every one crossing every sample row from "
      "y = 0.5 to 7.5 px of a 64-pixel-wide canvas (even-odd)." },
    { "same-cell-4096", EF_GEN_CAT_EDGES_PER_ROW, 0, X_ANY, b_same_cell, 4096,
      "4096 edges all crossing the rows inside pixel column 1: thousands of flags in one or two "
      "cells per sample row (non-zero)." },
    { "zigzag-256", EF_GEN_CAT_EDGES_PER_ROW, L2, X_ANY, b_zigzag, 256,
      "One zigzag contour of 256 edges across a 64-pixel-wide canvas (even-odd)." },
    { "zigzag-65536", EF_GEN_CAT_EDGES_PER_ROW, L2, X_ANY, b_zigzag, 65536,
      "One zigzag contour of 65536 edges, 1 unit apart, across a 256-pixel-wide canvas (even-odd)." },

    /* ---- canvas sizes ---- */
    { "canvas-1x1", EF_GEN_CAT_CANVAS, 0, X_ANY, b_canvas_1x1, 0,
      "A 1 x 1 canvas: a half-pixel triangle and a translucent square inside the pixel." },
    { "canvas-max", EF_GEN_CAT_CANVAS, 0, X_PROBE(16383, 16383, 255, 0), b_canvas_max, 0,
      "The largest canvas, 16384 x 16384: small shapes in the top-left and bottom-right corners and "
      "one-pixel strips through the middle over every row and every column." },
    { "canvas-max-wide", EF_GEN_CAT_CANVAS, 0, X_ANY, b_canvas_wide, 0,
      "A 16384 x 1 canvas with a triangle across its whole width." },
    { "canvas-max-tall", EF_GEN_CAT_CANVAS, 0, X_ANY, b_canvas_tall, 0,
      "A 1 x 16384 canvas with a sliver across its whole height." },
    { "canvas-max-full", EF_GEN_CAT_CANVAS, L2, X_FULL, b_canvas_max_full, 0,
      "The largest canvas filled completely: 2^28 pixels of solid spans." },

    /* ---- compositing ---- */
    { "alpha-steps", EF_GEN_CAT_COMPOSITING, 0, X_PROBE(0, 0, 0, 0), b_alpha_steps, 0,
      "Eight stripes of alpha 0, 1, 127, 128, 129, 254, 255, 255 with extreme colours, a translucent "
      "band over them and a final alpha-0 shape over everything (paints nothing)." },
    { "many-shapes", EF_GEN_CAT_COMPOSITING, 0, X_ANY, b_many_shapes, 300,
      "300 overlapping shapes of varying colour, alpha and rule composited in order onto a 4 x 4 "
      "canvas." },
};
const uint32_t ef_gen_ndcases = sizeof ef_gen_dcases / sizeof ef_gen_dcases[0];
