/*
 * test_model.c - unit tests of the model's blocks through the public API,
 * against values worked out by hand from docs/spec.md.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "edgeflag.h"
#include "internal.h" /* ef_gather_pads, tested exhaustively below */

#define PX(v) ((int32_t)((v)*256))

typedef struct grid {
    int32_t w, h;
    uint32_t *mask; /* per pixel, OR of reported masks */
    int spans;
    int overlaps; /* a pixel reported twice would be a filler bug */
} grid;

static void grid_span(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    grid *g = user;
    assert_true(len >= 1);
    assert_true(x >= 0 && x + len <= g->w && y >= 0 && y < g->h);
    assert_true(mask != 0);
    g->spans++;
    for (int32_t i = 0; i < len; i++) {
        if (g->mask[y * g->w + x + i])
            g->overlaps++;
        g->mask[y * g->w + x + i] |= mask;
    }
}

static void render(ef_ctx *ctx, const ef_point *pts, const uint32_t *start, uint32_t nc, ef_rule rule, grid *g)
{
    g->w = ef_ctx_width(ctx);
    g->h = ef_ctx_height(ctx);
    free(g->mask);
    g->mask = calloc((size_t)g->w * (size_t)g->h, sizeof *g->mask);
    g->spans = g->overlaps = 0;
    ef_polygon poly = { pts, start, nc };
    assert_int_equal(ef_rasterize(ctx, &poly, rule, grid_span, g), EF_OK);
    assert_int_equal(g->overlaps, 0);
}

static uint32_t full_mask(int n) { return n == 32 ? UINT32_MAX : (UINT32_C(1) << n) - 1; }

static unsigned popc(uint32_t v)
{
    unsigned c = 0;
    for (; v; v &= v - 1)
        c++;
    return c;
}

/* A pixel-aligned rectangle owns exactly its pixels: [left, right) x [top, bottom). */
static void test_aligned_rect(void **state)
{
    (void)state;
    static const int ns[3] = { 8, 16, 32 };
    for (int t = 0; t < 3; t++) {
        for (int rule = 0; rule < 2; rule++) {
            ef_ctx *ctx;
            assert_int_equal(ef_ctx_create(&ctx, 10, 8, ns[t]), EF_OK);
            ef_point pts[4] = { { PX(2), PX(1) }, { PX(5), PX(1) }, { PX(5), PX(4) }, { PX(2), PX(4) } };
            uint32_t start[2] = { 0, 4 };
            grid g = { 0 };
            render(ctx, pts, start, 1, (ef_rule)rule, &g);
            for (int y = 0; y < 8; y++)
                for (int x = 0; x < 10; x++) {
                    int in = x >= 2 && x < 5 && y >= 1 && y < 4;
                    assert_int_equal(g.mask[y * 10 + x], in ? full_mask(ns[t]) : 0);
                }
            assert_int_equal(g.spans, 3); /* one solid span per row */
            free(g.mask);
            ef_ctx_destroy(ctx);
        }
    }
}

/* Edges through pixel centres: left edge x = 2.5 keeps samples with k >= N/2,
 * top edge y = 1.5 keeps sub-scanlines s >= N/2 (spec 4: positions (2k+1)/2N). */
static void test_half_pixel_rect(void **state)
{
    (void)state;
    static const int ns[3] = { 8, 16, 32 };
    for (int t = 0; t < 3; t++) {
        int n = ns[t];
        const uint8_t *k = ef_pattern(n);
        uint32_t left = 0, top = 0, corner = 0;
        for (int s = 0; s < n; s++) {
            if (k[s] >= n / 2)
                left |= UINT32_C(1) << s;
            if (s >= n / 2)
                top |= UINT32_C(1) << s;
        }
        corner = left & top;
        ef_ctx *ctx;
        assert_int_equal(ef_ctx_create(&ctx, 8, 8, n), EF_OK);
        ef_point pts[4] = { { PX(2.5), PX(1.5) }, { PX(6), PX(1.5) }, { PX(6), PX(5) }, { PX(2.5), PX(5) } };
        uint32_t start[2] = { 0, 4 };
        grid g = { 0 };
        render(ctx, pts, start, 1, EF_RULE_NONZERO, &g);
        assert_int_equal(g.mask[1 * 8 + 2], corner);
        assert_int_equal(g.mask[1 * 8 + 3], top);
        assert_int_equal(g.mask[2 * 8 + 2], left);
        assert_int_equal(g.mask[2 * 8 + 3], full_mask(n));
        assert_int_equal(g.mask[1 * 8 + 6], 0);
        assert_int_equal(popc(left), (unsigned)n / 2);
        free(g.mask);
        ef_ctx_destroy(ctx);
    }
}

/* Clamping left/right is exact: a shape whose side edges lie far outside the
 * canvas gives the same samples as one whose sides sit just outside (spec 6.1). */
static void test_clamp_exact(void **state)
{
    (void)state;
    ef_ctx *ctx;
    assert_int_equal(ef_ctx_create(&ctx, 12, 9, 16), EF_OK);
    const int32_t far = EF_COORD_LIMIT - 1;
    ef_point wide[4] = { { -far, PX(0.3) }, { far, PX(0.3) }, { far - 999, PX(8.2) }, { -far + 777, PX(8.2) } };
    ef_point near[4] = { { -3, PX(0.3) }, { PX(12) + 7, PX(0.3) }, { PX(12) + 7, PX(8.2) }, { -3, PX(8.2) } };
    uint32_t start[2] = { 0, 4 };
    grid a = { 0 }, b = { 0 };
    render(ctx, wide, start, 1, EF_RULE_EVENODD, &a);
    render(ctx, near, start, 1, EF_RULE_NONZERO, &b);
    assert_memory_equal(a.mask, b.mask, 12 * 9 * sizeof(uint32_t));
    for (int y = 1; y < 8; y++)
        for (int x = 0; x < 12; x++)
            assert_int_equal(a.mask[y * 12 + x], full_mask(16));
    assert_int_not_equal(a.mask[0], 0);
    assert_int_not_equal(a.mask[0], full_mask(16));
    free(a.mask);
    free(b.mask);
    ef_ctx_destroy(ctx);
}

static void wound_square(int times, ef_point *pts, uint32_t *start)
{
    for (int i = 0; i < times; i++) {
        pts[4 * i + 0] = (ef_point){ PX(1), PX(1) };
        pts[4 * i + 1] = (ef_point){ PX(3), PX(1) };
        pts[4 * i + 2] = (ef_point){ PX(3), PX(3) };
        pts[4 * i + 3] = (ef_point){ PX(1), PX(3) };
        start[i] = (uint32_t)(4 * i);
    }
    start[times] = (uint32_t)(4 * times);
}

/* Non-zero counters are 7 bits and wrap (spec 6.4): winding 127 covers,
 * winding 128 reads as zero, and the diagnostic reports the overflow. */
static void test_winding_wrap(void **state)
{
    (void)state;
    static ef_point pts[4 * 128];
    static uint32_t start[129];
    ef_ctx *ctx;
    ef_diag d;
    grid g = { 0 };

    assert_int_equal(ef_ctx_create(&ctx, 4, 4, 8), EF_OK);
    wound_square(63, pts, start);
    render(ctx, pts, start, 63, EF_RULE_NONZERO, &g);
    assert_int_equal(g.mask[1 * 4 + 1], 0xffu);
    ef_ctx_diag(ctx, &d);
    assert_int_equal(d.winding_overflows, 0);
    ef_ctx_destroy(ctx);

    assert_int_equal(ef_ctx_create(&ctx, 4, 4, 8), EF_OK);
    wound_square(127, pts, start);
    render(ctx, pts, start, 127, EF_RULE_NONZERO, &g);
    assert_int_equal(g.mask[1 * 4 + 1], 0xffu);
    ef_ctx_diag(ctx, &d);
    assert_true(d.winding_overflows > 0);
    ef_ctx_destroy(ctx);

    assert_int_equal(ef_ctx_create(&ctx, 4, 4, 8), EF_OK);
    wound_square(128, pts, start);
    render(ctx, pts, start, 128, EF_RULE_NONZERO, &g);
    assert_int_equal(g.mask[1 * 4 + 1], 0);
    assert_int_equal(g.mask[2 * 4 + 2], 0);
    /* even-odd of an even count is empty too, without any diagnostic */
    render(ctx, pts, start, 128, EF_RULE_EVENODD, &g);
    assert_int_equal(g.mask[1 * 4 + 1], 0);
    free(g.mask);
    ef_ctx_destroy(ctx);
}

/* The pentagram's centre: winding 2, so non-zero fills it and even-odd not. */
static void test_pentagram_rules(void **state)
{
    (void)state;
    /* Vertices of a pentagram inscribed in a circle of radius 40 about (50, 50),
     * visiting every second point: (50,10) (73.51,82.36) (11.96,37.64) (88.04,37.64)
     * (26.49,82.36), rounded to 1/256 px by hand. */
    ef_point pts[5] = { { PX(50), PX(10) },
                        { 73 * 256 + 131, 82 * 256 + 92 },
                        { 11 * 256 + 246, 37 * 256 + 164 },
                        { 88 * 256 + 10, 37 * 256 + 164 },
                        { 26 * 256 + 125, 82 * 256 + 92 } };
    uint32_t start[2] = { 0, 5 };
    ef_ctx *ctx;
    assert_int_equal(ef_ctx_create(&ctx, 100, 100, 16), EF_OK);
    grid g = { 0 };
    render(ctx, pts, start, 1, EF_RULE_NONZERO, &g);
    assert_int_equal(g.mask[55 * 100 + 50], full_mask(16));
    render(ctx, pts, start, 1, EF_RULE_EVENODD, &g);
    assert_int_equal(g.mask[55 * 100 + 50], 0);
    assert_int_equal(g.mask[20 * 100 + 50], full_mask(16)); /* a spike: winding 1 */
    free(g.mask);
    ef_ctx_destroy(ctx);
}

static void test_bad_args_leave_no_state(void **state)
{
    (void)state;
    ef_ctx *ctx = (ef_ctx *)1;
    assert_int_equal(ef_ctx_create(&ctx, 0, 4, 8), EF_ERR_ARG);
    assert_null(ctx);
    assert_int_equal(ef_ctx_create(&ctx, 4, 4, 12), EF_ERR_ARG);
    assert_int_equal(ef_ctx_create(&ctx, EF_MAX_CANVAS + 1, 4, 8), EF_ERR_ARG);
    assert_int_equal(ef_ctx_create(&ctx, 6, 6, 32), EF_OK);
    ef_point bad[4] = { { PX(1), PX(1) }, { PX(3), PX(1) }, { EF_COORD_LIMIT, PX(3) }, { PX(1), PX(3) } };
    ef_point good[4] = { { PX(1), PX(1) }, { PX(3), PX(1) }, { PX(3), PX(3) }, { PX(1), PX(3) } };
    uint32_t start2[3] = { 0, 4, 8 };
    ef_point both[8];
    memcpy(both, good, sizeof good);
    memcpy(both + 4, bad, sizeof bad);
    ef_polygon poly = { both, start2, 2 };
    grid g = { 6, 6, calloc(36, 4), 0, 0 };
    assert_int_equal(ef_rasterize(ctx, &poly, EF_RULE_NONZERO, grid_span, &g), EF_ERR_ARG);
    assert_int_equal(g.spans, 0);
    uint32_t start1[2] = { 0, 4 };
    render(ctx, good, start1, 1, EF_RULE_NONZERO, &g);
    assert_int_equal(g.mask[1 * 6 + 1], UINT32_MAX);
    assert_int_equal(g.mask[3 * 6 + 3], 0);
    assert_int_equal(g.spans, 2);
    free(g.mask);
    ef_ctx_destroy(ctx);
}

/* Coverage rule (spec 7.3) and compositing (spec 8) against direct formulas. */
static void test_coverage_alpha(void **state)
{
    (void)state;
    assert_int_equal(ef_coverage_alpha(0, 8), 0);
    assert_int_equal(ef_coverage_alpha(0xff, 8), 255);
    assert_int_equal(ef_coverage_alpha(0x1, 8), 32);  /* 31.875 rounds to 32 */
    assert_int_equal(ef_coverage_alpha(0xf, 8), 128); /* 127.5 ties up */
    assert_int_equal(ef_coverage_alpha(0x1, 16), 16); /* 15.9375 */
    assert_int_equal(ef_coverage_alpha(0x1, 32), 8);  /* 7.97 */
    assert_int_equal(ef_coverage_alpha(UINT32_MAX, 32), 255);
    for (uint32_t a = 0; a < 256; a++)
        for (uint32_t b = 0; b < 256; b++) {
            uint32_t exact2 = 2 * a * b; /* round(ab/255) with ties up: floor((2ab + 255) / 510) */
            assert_int_equal(ef_mul255(a, b), (exact2 + 255) / 510);
        }
}

static void test_composite(void **state)
{
    (void)state;
    ef_ctx *ctx;
    ef_image img;
    assert_int_equal(ef_ctx_create(&ctx, 4, 2, 8), EF_OK);
    assert_int_equal(ef_image_create(&img, 4, 2), EF_OK);
    /* Opaque red over everything, then half-transparent blue on pixel 1 with
     * half coverage (left edge at x = 1.5 -> 4 of 8 samples). */
    ef_point full[4] = { { 0, 0 }, { PX(4), 0 }, { PX(4), PX(2) }, { 0, PX(2) } };
    ef_point half[4] = { { PX(1.5), 0 }, { PX(2), 0 }, { PX(2), PX(1) }, { PX(1.5), PX(1) } };
    uint32_t start[2] = { 0, 4 };
    ef_polygon p1 = { full, start, 1 }, p2 = { half, start, 1 };
    assert_int_equal(ef_fill(ctx, &img, &p1, EF_RULE_NONZERO, (ef_rgba8){ 255, 0, 0, 255 }), EF_OK);
    assert_int_equal(ef_fill(ctx, &img, &p2, EF_RULE_NONZERO, (ef_rgba8){ 0, 0, 255, 128 }), EF_OK);
    const uint8_t *px = img.px + 4; /* pixel (1, 0) */
    /* cov = 128; P = (0, 0, 128, 128); s = (0, 0, 64, 64); sa = 64.
     * d' = d + s - mul(d, 64): R 255 - 64 = 191, B 0 + 64 = 64, A 255 + 64 - 64 = 255. */
    assert_int_equal(px[0], 191);
    assert_int_equal(px[1], 0);
    assert_int_equal(px[2], 64);
    assert_int_equal(px[3], 255);
    assert_int_equal(img.px[0], 255);
    assert_int_equal(img.px[8], 255);
    assert_int_equal(img.px[8 + 2], 0);
    ef_image_destroy(&img);
    ef_ctx_destroy(ctx);
}

/* The non-zero filler's pad-bit gather: every one of the 256 patterns of the
 * eight pad bits comes out as the lane bitmap, lane L at bit L. */
static void test_gather_pads_exhaustive(void **state)
{
    (void)state;
    for (uint32_t b = 0; b < 256; b++) {
        uint64_t pads = 0;
        for (int lane = 0; lane < 8; lane++)
            if (b >> lane & 1u)
                pads |= UINT64_C(1) << (8 * lane + 7);
        if (ef_gather_pads(pads) != b)
            fail_msg("pads 0x%016llx gathered as 0x%02x, want 0x%02x", (unsigned long long)pads,
                     (unsigned)ef_gather_pads(pads), (unsigned)b);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gather_pads_exhaustive),
        cmocka_unit_test(test_aligned_rect),
        cmocka_unit_test(test_half_pixel_rect),
        cmocka_unit_test(test_clamp_exact),
        cmocka_unit_test(test_winding_wrap),
        cmocka_unit_test(test_pentagram_rules),
        cmocka_unit_test(test_bad_args_leave_no_state),
        cmocka_unit_test(test_coverage_alpha),
        cmocka_unit_test(test_composite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
