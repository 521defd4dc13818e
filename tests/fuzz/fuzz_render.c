/*
 * fuzz_render.c - libFuzzer target for the whole model: a `.scene` text is
 * loaded (fitted into at most 64 x 64 pixels when larger, so every input
 * stays cheap) and each shape is rasterized at 8, 16 and 32 samples under
 * both rules.
 *
 * Properties: no crash and no undefined behaviour (the build has ASan and
 * UBSan); every span lies inside the canvas with a non-empty mask of at most
 * N bits, rows in order, spans of a row left to right and disjoint; a second
 * rasterization on a fresh context gives the same masks (deterministic, no
 * state carried between contexts) and so does re-using the context; every
 * mask equals the independent slow model's (tests/oracle/, exact
 * point-in-polygon per sample); the winding-overflow diagnostic agrees with
 * the oracle's true winding numbers (docs/oracle.md); compositing the whole
 * scene twice gives the same image.
 */
#include "fuzz_common.h"
#include "oracle.h"

#define MAXDIM 64

typedef struct grid {
    int32_t w, h, last_y, last_end;
    uint32_t allowed; /* mask bits the sample count allows */
    uint32_t *m;
} grid;

static void span_to_grid(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    grid *g = user;
    FUZZ_CHECK(y >= 0 && y < g->h && x >= 0 && len >= 1 && x + len <= g->w,
               "span y=%" PRId32 " x=%" PRId32 " len=%" PRId32 " outside %" PRId32 "x%" PRId32, y, x, len, g->w, g->h);
    FUZZ_CHECK(mask != 0 && (mask & ~g->allowed) == 0, "span mask %" PRIx32 " invalid", mask);
    FUZZ_CHECK(y > g->last_y || (y == g->last_y && x >= g->last_end), "spans out of order or overlapping");
    g->last_y = y;
    g->last_end = x + len;
    for (int32_t i = 0; i < len; i++)
        g->m[(size_t)y * (size_t)g->w + (size_t)(x + i)] = mask;
}

static void raster(ef_ctx *ctx, const ef_polygon *p, ef_rule rule, grid *g)
{
    memset(g->m, 0, (size_t)g->w * (size_t)g->h * sizeof *g->m);
    g->last_y = -1;
    g->last_end = 0;
    FUZZ_CHECK(ef_rasterize(ctx, p, rule, span_to_grid, g) == EF_OK, "ef_rasterize failed on a loaded scene");
}

static void check_scene(const ef_scene *s)
{
    const int32_t W = s->width, H = s->height;
    size_t n = (size_t)W * (size_t)H;
    uint32_t *m1 = calloc(n, 4), *m2 = calloc(n, 4), *onz = calloc(n, 4), *oeo = calloc(n, 4);
    FUZZ_CHECK(m1 && m2 && onz && oeo, "out of memory in the harness");
    static const int ns[3] = { 8, 16, 32 };
    for (int k = 0; k < 3; k++) {
        int N = ns[k];
        ef_ctx *shared, *fresh;
        FUZZ_CHECK(ef_ctx_create(&shared, W, H, N) == EF_OK, "context");
        grid g1 = { W, H, -1, 0, N == 32 ? UINT32_MAX : (UINT32_C(1) << N) - 1u, m1 };
        grid g2 = g1;
        g2.m = m2;
        for (uint32_t i = 0; i < s->nshapes; i++) {
            ef_polygon p = ef_scene_polygon(s, i);
            eo_polygon op = { (const eo_point *)p.pts, p.start, p.ncontours };
            eo_stats stats;
            FUZZ_CHECK(eo_eval(&op, N, W, H, onz, oeo, &stats) == EO_OK, "the oracle rejected a loaded shape");
            for (int r = 0; r < 2; r++) {
                ef_rule rule = r ? EF_RULE_EVENODD : EF_RULE_NONZERO;
                ef_diag d;
                FUZZ_CHECK(ef_ctx_create(&fresh, W, H, N) == EF_OK, "context");
                raster(fresh, &p, rule, &g1);
                ef_ctx_diag(fresh, &d);
                ef_ctx_destroy(fresh);
                raster(shared, &p, rule, &g2);
                FUZZ_CHECK(memcmp(m1, m2, n * 4) == 0, "shape %" PRIu32 " N=%d rule=%d: a used context differs", i, N,
                           r);
                const uint32_t *want = r ? oeo : onz;
                for (size_t q = 0; q < n; q++)
                    FUZZ_CHECK(m1[q] == want[q],
                               "shape %" PRIu32 " N=%d %s: pixel (%zu, %zu) mask %08" PRIx32 ", oracle %08" PRIx32, i,
                               N, r ? "evenodd" : "nonzero", q % (size_t)W, q / (size_t)W, m1[q], want[q]);
                if (!r) {
                    if (stats.outside_7bit > 0)
                        FUZZ_CHECK(d.winding_overflows > 0, "winding outside 7 bits but no overflow counted");
                    if (stats.max_row_crossings <= 63)
                        FUZZ_CHECK(d.winding_overflows == 0, "overflow counted with at most 63 crossings a row");
                }
            }
        }
        ef_ctx_destroy(shared);

        /* The composited scene, twice, on fresh contexts. */
        ef_image a, b;
        ef_ctx *c1, *c2;
        FUZZ_CHECK(ef_image_create(&a, W, H) == EF_OK && ef_image_create(&b, W, H) == EF_OK, "image");
        memset(a.px, 0, a.stride * (size_t)H);
        memset(b.px, 0, b.stride * (size_t)H);
        FUZZ_CHECK(ef_ctx_create(&c1, W, H, N) == EF_OK && ef_ctx_create(&c2, W, H, N) == EF_OK, "context");
        FUZZ_CHECK(ef_scene_render(c1, s, -1, &a) == EF_OK && ef_scene_render(c2, s, -1, &b) == EF_OK, "render");
        FUZZ_CHECK(memcmp(a.px, b.px, a.stride * (size_t)H) == 0, "compositing not deterministic");
        ef_ctx_destroy(c1);
        ef_ctx_destroy(c2);
        ef_image_destroy(&a);
        ef_image_destroy(&b);
    }
    free(m1);
    free(m2);
    free(onz);
    free(oeo);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ef_scene s;
    ef_error e;
    if (ef_scene_load_text("fuzz.scene", (const char *)data, size, NULL, &s, &e) != EF_OK)
        return 0;
    if (s.width > MAXDIM || s.height > MAXDIM) {
        ef_load_opts fit;
        memset(&fit, 0, sizeof fit);
        fit.fit_width = s.width > MAXDIM ? MAXDIM : s.width;
        fit.fit_height = s.height > MAXDIM ? MAXDIM : s.height;
        ef_scene_destroy(&s);
        if (ef_scene_load_text("fuzz.scene", (const char *)data, size, &fit, &s, &e) != EF_OK)
            return 0;
    }
    fuzz_check_scene(&s);
    check_scene(&s);
    ef_scene_destroy(&s);
    return 0;
}
