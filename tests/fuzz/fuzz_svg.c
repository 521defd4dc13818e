/*
 * fuzz_svg.c - libFuzzer target for the SVG reader (model/input/svg*.c and
 * everything under it: expat tree, CSS, paths, transforms, arcs, curves).
 *
 * For each input: load it as is and fitted into a small canvas; both runs
 * must satisfy the reader contract (fuzz_common.h).  Each successful load is
 * loaded a second time (same result: no hidden state) and written as exact
 * `.scene` text and read back (same vertices: the chain SVG -> dump -> render
 * that tests/bitexact.sh and `make portability` rely on).  The fitted scene
 * is small, so it is also rasterized once at 8 samples with each rule.
 */
#include "fuzz_common.h"

static const char NAME[] = "fuzz.svg";

static void span_in_canvas(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    const ef_scene *s = user;
    FUZZ_CHECK(y >= 0 && y < s->height && x >= 0 && len >= 1 && x + len <= s->width && mask != 0 && mask <= 0xFFu,
               "span y=%" PRId32 " x=%" PRId32 " len=%" PRId32 " mask=%" PRIx32 " outside the canvas", y, x, len, mask);
}

static void one(const char *data, size_t size, const ef_load_opts *opts, int render)
{
    ef_scene s, t;
    ef_error e;
    if (!fuzz_load_checked(ef_scene_load_svg, NAME, data, size, opts, &s))
        return;

    if (s.npoints > 65536) { /* a big scene (up to the work limit): checked above, not dumped */
        ef_scene_destroy(&s);
        return;
    }
    fuzz_buf b = { 0 };
    fuzz_scene_text(&s, &b);
    ef_status ts = ef_scene_load_text("dump.scene", b.p, b.n, NULL, &t, &e);
    FUZZ_CHECK(ts == EF_OK, "the exact dump does not load: %s at %" PRIu32 ":%" PRIu32 "\n%s", e.msg, e.line, e.col,
               b.p);
    FUZZ_CHECK(fuzz_same_geometry(&s, &t), "the exact dump reads back different vertices");
    ef_scene_destroy(&t);
    free(b.p);

    if (render) {
        ef_ctx *ctx;
        FUZZ_CHECK(ef_ctx_create(&ctx, s.width, s.height, 8) == EF_OK, "context");
        for (uint32_t i = 0; i < s.nshapes; i++) {
            ef_polygon poly = ef_scene_polygon(&s, i);
            FUZZ_CHECK(ef_rasterize(ctx, &poly, EF_RULE_NONZERO, span_in_canvas, &s) == EF_OK, "rasterize");
            FUZZ_CHECK(ef_rasterize(ctx, &poly, EF_RULE_EVENODD, span_in_canvas, &s) == EF_OK, "rasterize");
        }
        ef_ctx_destroy(ctx);
    }
    ef_scene_destroy(&s);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ef_load_opts fit;
    memset(&fit, 0, sizeof fit);
    fit.fit_width = 37;
    fit.fit_height = 23;
    one((const char *)data, size, NULL, 0);
    one((const char *)data, size, &fit, 1);
    return 0;
}
