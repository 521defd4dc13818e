/*
 * test_trace_filter.c - the timing model with the spec 10 options
 * (model/trace_filter.c, docs/microarch.md section 5) against the fast path
 * (model/filter.c): every shared SVG (fitted to 160x120) and an edge-case
 * scene, at 8/16/32 samples, under each option setting, render to the same
 * bytes and diagnostics traced as untraced (the two compute the channels'
 * cells and the tent sums differently: one DDA with per-channel offsets and
 * spec 10.2's formula against translated copies and per-byte tables).  The
 * transactions obey section 5's schedule: FRAME carries the options, every
 * interface in cycle order, each pass's last plot carries `last`, spans lie
 * on the (W+e) x (H+e) mask canvas, one pix per pixel with coverage in some
 * channel (counted with ef_filter_coverage), its alpha the centre channel's.
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ef_filter.h"
#include "ef_scene.h"
#include "ef_trace.h"

static const struct {
    ef_filter f;
    ef_subpixel s;
} settings[] = {
    { EF_FILTER_TENT, EF_SUBPIXEL_NONE }, { EF_FILTER_TENT, EF_SUBPIXEL_RGB }, { EF_FILTER_TENT, EF_SUBPIXEL_BGR },
    { EF_FILTER_BOX, EF_SUBPIXEL_RGB },   { EF_FILTER_BOX, EF_SUBPIXEL_BGR },
};

typedef struct stats {
    uint64_t n[EF_IF_COUNT], last_cycle[EF_IF_COUNT], max_cycle, frame_c;
    int ordered, spans_ok;
    int32_t wm, hm;
    uint64_t plots_since_last;
} stats;

static void sink(void *user, const ef_txn *t)
{
    stats *s = user;
    const int i = t->iface;
    if (s->n[i] && t->cycle <= s->last_cycle[i])
        s->ordered = 0;
    s->n[i]++;
    s->last_cycle[i] = t->cycle;
    s->max_cycle = t->cycle > s->max_cycle ? t->cycle : s->max_cycle;
    if (i == EF_IF_CMD && ef_txn_field(t, 0) == EF_OP_FRAME)
        s->frame_c = ef_txn_field(t, 3);
    if (i == EF_IF_PLOT)
        s->plots_since_last = ef_txn_field(t, 0) ? 0 : s->plots_since_last + 1;
    if (i == EF_IF_SPAN &&
        (ef_txn_field(t, 0) >= (uint64_t)s->hm || ef_txn_field(t, 1) + ef_txn_field(t, 2) > (uint64_t)s->wm))
        s->spans_ok = 0;
}

static uint64_t covered;
static void count_cov(void *user, int32_t y, int32_t x, const uint32_t sum[3])
{
    (void)user, (void)y, (void)x, (void)sum;
    covered++;
}

static void check_scene(const char *name, const ef_scene *sc)
{
    for (size_t k = 0; k < sizeof settings / sizeof settings[0]; k++)
        for (int samples = 8; samples <= 32; samples *= 2) {
            ef_ctx *a, *b;
            ef_image ia, ib;
            static stats st;
            memset(&st, 0, sizeof st);
            st.ordered = st.spans_ok = 1;
            st.wm = sc->width + (settings[k].f == EF_FILTER_TENT);
            st.hm = sc->height + (settings[k].f == EF_FILTER_TENT);
            assert_int_equal(ef_ctx_create(&a, sc->width, sc->height, samples), EF_OK);
            assert_int_equal(ef_ctx_create(&b, sc->width, sc->height, samples), EF_OK);
            assert_int_equal(ef_ctx_set_filter(a, settings[k].f, settings[k].s), EF_OK);
            assert_int_equal(ef_ctx_set_filter(b, settings[k].f, settings[k].s), EF_OK);
            assert_int_equal(ef_image_create(&ia, sc->width, sc->height), EF_OK);
            assert_int_equal(ef_image_create(&ib, sc->width, sc->height), EF_OK);
            assert_int_equal(ef_trace_enable(b, EF_IF_ALL, sink, &st), EF_OK);
            assert_int_equal(ef_trace_frame_begin(b), EF_OK);
            assert_int_equal(ef_scene_render(a, sc, -1, &ia), EF_OK);
            assert_int_equal(ef_scene_render(b, sc, -1, &ib), EF_OK);
            uint64_t cycles;
            assert_int_equal(ef_trace_frame_end(b, &cycles), EF_OK);
            ef_diag da, db;
            ef_ctx_diag(a, &da);
            ef_ctx_diag(b, &db);
            if (memcmp(ia.px, ib.px, ia.stride * (size_t)ia.height) != 0 || memcmp(&da, &db, sizeof da) != 0)
                fail_msg("%s at %d samples, setting %zu: the traced render differs", name, samples, k);
            covered = 0;
            for (uint32_t s = 0; s < sc->nshapes; s++) {
                ef_polygon p = ef_scene_polygon(sc, s);
                assert_int_equal(ef_filter_coverage(a, &p, sc->shapes[s].rule, count_cov, NULL), EF_OK);
            }
            assert_int_equal(st.frame_c, (uint64_t)settings[k].f | (uint64_t)settings[k].s << 1);
            assert_true(st.ordered);
            assert_true(st.spans_ok);
            assert_int_equal(st.plots_since_last, 0);
            assert_int_equal(st.n[EF_IF_PIX], covered);
            assert_true(cycles == st.max_cycle + 1);
            assert_int_equal(st.n[EF_IF_SEG], sc->nshapes + db.edges_in);
            ef_image_destroy(&ia);
            ef_image_destroy(&ib);
            ef_ctx_destroy(a);
            ef_ctx_destroy(b);
        }
}

static void shared_svgs(void **state)
{
    (void)state;
    const char *svg = getenv("EF_SVG");
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", svg && *svg ? svg : "tests/data/svg");
    DIR *d = opendir(dir);
    if (!d)
        fail_msg("SVG folder %s not found (EF_SVG)", dir);
    struct dirent *e;
    int n = 0;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".svg") != 0)
            continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        ef_load_opts opts = { .fit_width = 160, .fit_height = 120 };
        ef_scene sc;
        ef_error err;
        assert_int_equal(ef_scene_load_file(path, &opts, &sc, &err), EF_OK);
        check_scene(e->d_name, &sc);
        ef_scene_destroy(&sc);
        n++;
    }
    closedir(d);
    assert_true(n >= 20);
}

#define PX(v) ((int32_t)((v)*256))

/* Clamping and clipping on every side of the mask canvas, windings past 127,
 * a shape covering the whole canvas, one outside, a translucent one. */
static void edge_cases(void **state)
{
    (void)state;
    ef_scene sc;
    ef_scene_create(&sc, 40, 24);
    const ef_point all[4] = { { 0, 0 }, { PX(40), 0 }, { PX(40), PX(24) }, { 0, PX(24) } };
    assert_int_equal(ef_scene_begin_shape(&sc, EF_RULE_NONZERO, (ef_rgba8){ 20, 40, 60, 255 }), EF_OK);
    assert_int_equal(ef_scene_add_contour(&sc, all, 4), EF_OK);
    const ef_point wide[4] = { { PX(-30), PX(-5) }, { PX(70.3), PX(2.2) }, { PX(65), PX(40) }, { PX(-12), PX(20.7) } };
    assert_int_equal(ef_scene_begin_shape(&sc, EF_RULE_EVENODD, (ef_rgba8){ 200, 30, 40, 160 }), EF_OK);
    assert_int_equal(ef_scene_add_contour(&sc, wide, 4), EF_OK);
    const ef_point tri[3] = { { PX(3.1), PX(3.3) }, { PX(39.9), PX(8.45) }, { PX(7), PX(23.9) } };
    assert_int_equal(ef_scene_begin_shape(&sc, EF_RULE_NONZERO, (ef_rgba8){ 10, 200, 90, 128 }), EF_OK);
    for (int k = 0; k < 140; k++)
        assert_int_equal(ef_scene_add_contour(&sc, tri, 3), EF_OK);
    const ef_point out[3] = { { PX(100), PX(100) }, { PX(120), PX(100) }, { PX(110), PX(130) } };
    assert_int_equal(ef_scene_begin_shape(&sc, EF_RULE_EVENODD, (ef_rgba8){ 0, 0, 255, 255 }), EF_OK);
    assert_int_equal(ef_scene_add_contour(&sc, out, 3), EF_OK);
    check_scene("edge cases", &sc);
    ef_scene_destroy(&sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(edge_cases),
        cmocka_unit_test(shared_svgs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
