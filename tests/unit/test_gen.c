/*
 * test_gen.c - the scene generator of `edgeflag gen` (rtl_vectors/,
 * docs/gen.md): the PRNG against known values, levels and "-n can raise,
 * never lower", determinism (twice the same bytes, and a pinned hash of the
 * whole level-1 run so any change of content must bump EF_GEN_VERSION),
 * random cases that depend only on (seed, j), shards as exact partitions,
 * every directed and many random cases read back by the .scene reader with
 * every vertex bit for bit, every category of the issue present, and every
 * stated expectation ("# expect: ...") true at 8, 16 and 32 samples.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ef_gen.h"

/* ------------------------------------------------------------ helpers */

static ef_gen_config cfg(int level, int grid, uint32_t nrandom)
{
    ef_gen_config c;
    assert_int_equal(ef_gen_config_defaults(&c, level), EF_OK);
    c.grid = grid;
    if (nrandom)
        c.nrandom = nrandom;
    return c;
}

/* Builds and formats case k; the caller frees both. */
static void make(const ef_gen_config *c, uint32_t k, ef_gen_case *gc, ef_gen_text *t)
{
    ef_status st = ef_gen_build(c, k, gc);
    if (st != EF_OK)
        fail_msg("case %u: build: %s", (unsigned)k, ef_strerror(st));
    st = ef_gen_format(c, gc, t);
    if (st != EF_OK)
        fail_msg("case %u (%s): format: %s", (unsigned)k, gc->name, ef_strerror(st));
}

static uint64_t fnv1a(uint64_t h, const char *p, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        h ^= (unsigned char)p[i];
        h *= UINT64_C(0x100000001B3);
    }
    return h;
}

/* The lines that do not start with '#': the drawing. */
static char *drawing(const char *text)
{
    size_t n = strlen(text);
    char *out = malloc(n + 1), *o = out;
    assert_non_null(out);
    while (*text) {
        const char *e = strchr(text, '\n');
        size_t len = e ? (size_t)(e - text) + 1 : strlen(text);
        if (text[0] != '#') {
            memcpy(o, text, len);
            o += len;
        }
        text += len;
    }
    *o = '\0';
    return out;
}

/* The text parses back into exactly the generator's scene. */
static void check_roundtrip(const ef_gen_case *gc, const ef_gen_text *t)
{
    ef_scene s;
    ef_error err;
    ef_load_opts o = { 0, 0, NULL, NULL };
    const ef_scene *g = &gc->scene;
    ef_status st = ef_scene_load_text("case.scene", t->data, t->len, &o, &s, &err);
    if (st != EF_OK) {
        char buf[600];
        ef_error_format(&err, buf, sizeof buf);
        fail_msg("case %u (%s) does not parse: %s", (unsigned)gc->number, gc->name, buf);
    }
    assert_int_equal(s.width, g->width);
    assert_int_equal(s.height, g->height);
    assert_int_equal(s.nshapes, g->nshapes);
    assert_int_equal(s.ncontours, g->ncontours);
    assert_int_equal(s.npoints, g->npoints);
    for (uint32_t i = 0; i < g->nshapes; i++) {
        assert_int_equal(s.shapes[i].rule, g->shapes[i].rule);
        assert_memory_equal(&s.shapes[i].color, &g->shapes[i].color, sizeof(ef_rgba8));
        assert_int_equal(s.shapes[i].first_contour, g->shapes[i].first_contour);
        assert_int_equal(s.shapes[i].ncontours, g->shapes[i].ncontours);
    }
    if (g->ncontours)
        assert_memory_equal(s.start, g->start, (g->ncontours + 1) * sizeof *g->start);
    for (uint32_t i = 0; i < g->npoints; i++) {
        if (s.points[i].x != g->points[i].x || s.points[i].y != g->points[i].y)
            fail_msg("case %u (%s): vertex %u reads back as (%d, %d), written (%d, %d)", (unsigned)gc->number, gc->name,
                     (unsigned)i, (int)s.points[i].x, (int)s.points[i].y, (int)g->points[i].x, (int)g->points[i].y);
    }
    ef_scene_destroy(&s);
}

static void append(ef_gen_text *t, const char *s)
{
    size_t n = strlen(s);
    char *p = realloc(t->data, t->len + n + 1);
    assert_non_null(p);
    memcpy(p + t->len, s, n + 1);
    t->data = p;
    t->len += n;
    t->cap = t->len + 1;
}

/* ---------------------------------------------------------------- PRNG */

static void test_splitmix64(void **state)
{
    uint64_t s = 0;
    (void)state;
    assert_true(ef_gen_splitmix64(&s) == UINT64_C(0xE220A8397B1DCDAF));
    assert_true(ef_gen_splitmix64(&s) == UINT64_C(0x6E789E6AA1B965F4));
    assert_true(ef_gen_splitmix64(&s) == UINT64_C(0x06C45D188009454F));
    /* case seed j = output j of the stream seeded with `seed` */
    s = EF_GEN_DEFAULT_SEED;
    for (uint32_t j = 0; j < 1000; j++)
        assert_true(ef_gen_case_seed(EF_GEN_DEFAULT_SEED, j) == ef_gen_splitmix64(&s));
    s = UINT64_MAX - 5;
    for (uint32_t j = 0; j < 10; j++)
        assert_true(ef_gen_case_seed(UINT64_MAX - 5, j) == ef_gen_splitmix64(&s));
}

/* ------------------------------------------------------- configuration */

static void test_levels_and_counts(void **state)
{
    ef_gen_config c;
    (void)state;
    assert_int_equal(ef_gen_config_defaults(&c, 0), EF_ERR_ARG);
    assert_int_equal(ef_gen_config_defaults(&c, 3), EF_ERR_ARG);

    c = cfg(1, 0, 0);
    assert_true(c.seed == EF_GEN_DEFAULT_SEED);
    assert_int_equal(c.nrandom, EF_GEN_LEVEL1_RANDOM);
    assert_int_equal(ef_gen_config_check(&c), EF_OK);
    assert_int_equal(ef_gen_total(&c), ef_gen_directed_count(&c) + EF_GEN_LEVEL1_RANDOM);

    /* -n can raise the level's count, never lower it */
    c.nrandom = EF_GEN_LEVEL1_RANDOM - 1;
    assert_int_equal(ef_gen_config_check(&c), EF_ERR_ARG);
    c.nrandom = 0;
    assert_int_equal(ef_gen_config_check(&c), EF_ERR_ARG);
    c.nrandom = EF_GEN_LEVEL1_RANDOM + 1;
    assert_int_equal(ef_gen_config_check(&c), EF_OK);
    c = cfg(2, 0, 0);
    assert_int_equal(c.nrandom, EF_GEN_LEVEL2_RANDOM);
    c.nrandom = EF_GEN_LEVEL2_RANDOM - 1;
    assert_int_equal(ef_gen_config_check(&c), EF_ERR_ARG);

    /* at most EF_GEN_MAX_CASES in all */
    c = cfg(1, 0, 0);
    c.nrandom = EF_GEN_MAX_CASES - ef_gen_directed_count(&c);
    assert_int_equal(ef_gen_config_check(&c), EF_OK);
    assert_int_equal(ef_gen_total(&c), EF_GEN_MAX_CASES);
    c.nrandom++;
    assert_int_equal(ef_gen_config_check(&c), EF_ERR_LIMIT);

    /* grids */
    c = cfg(1, 12, 0);
    assert_int_equal(ef_gen_config_check(&c), EF_ERR_ARG);
    {
        ef_gen_config l1 = cfg(1, 0, 0), l1g8 = cfg(1, 8, 0), l2 = cfg(2, 0, 0), l2g16 = cfg(2, 16, 0);
        assert_int_equal(ef_gen_directed_count(&l1), ef_gen_directed_count(&l1g8));
        assert_true(ef_gen_directed_count(&l2) > ef_gen_directed_count(&l2g16));
        assert_true(ef_gen_directed_count(&l2g16) > ef_gen_directed_count(&l1));
    }

    /* a case number past the end */
    {
        ef_gen_case gc;
        c = cfg(1, 0, 0);
        assert_int_equal(ef_gen_build(&c, ef_gen_total(&c), &gc), EF_ERR_ARG);
        ef_gen_case_destroy(&gc);
    }
}

static void test_shard_rule(void **state)
{
    (void)state;
    assert_true(ef_gen_in_shard(0, 1, 1));
    assert_true(ef_gen_in_shard(7, 1, 1));
    assert_true(ef_gen_in_shard(0, 1, 3));
    assert_true(ef_gen_in_shard(4, 2, 3));
    assert_true(ef_gen_in_shard(5, 3, 3));
    assert_false(ef_gen_in_shard(5, 1, 3));
    assert_false(ef_gen_in_shard(0, 0, 3)); /* 1-based */
    assert_false(ef_gen_in_shard(0, 4, 3));
    assert_false(ef_gen_in_shard(0, 1, 0));
    /* every case in exactly one shard, for many shard counts */
    for (uint32_t n = 1; n <= 17; n++) {
        for (uint32_t k = 0; k < 1000; k++) {
            int in = 0;
            for (uint32_t i = 1; i <= n; i++)
                in += ef_gen_in_shard(k, i, n);
            assert_int_equal(in, 1);
        }
    }
}

/* The CLI writes shard I/N as the cases k = I-1, I-1+N, ... with the same
 * bytes as the unsharded run: build a whole run's index both ways. */
static void test_shard_union(void **state)
{
    ef_gen_config c = cfg(1, 0, 0);
    uint32_t total = ef_gen_total(&c);
    ef_gen_text whole = { NULL, 0, 0 };
    char **rows = calloc(total, sizeof *rows);
    (void)state;
    assert_non_null(rows);
    for (uint32_t k = 0; k < total; k++) {
        ef_gen_case gc;
        ef_gen_text t = { NULL, 0, 0 };
        assert_int_equal(ef_gen_build(&c, k, &gc), EF_OK);
        assert_int_equal(ef_gen_index_row(&gc, &t), EF_OK);
        rows[k] = t.data;
        assert_int_equal(ef_gen_index_row(&gc, &whole), EF_OK);
        ef_gen_case_destroy(&gc);
    }
    for (uint32_t n = 2; n <= 5; n++) {
        ef_gen_text joined = { NULL, 0, 0 };
        uint32_t seen = 0;
        char *got = calloc(total, 1);
        assert_non_null(got);
        for (uint32_t i = 1; i <= n; i++) {
            for (uint32_t k = i - 1; k < total; k += n) {
                ef_gen_case gc;
                ef_gen_text t = { NULL, 0, 0 };
                assert_true(ef_gen_in_shard(k, i, n));
                assert_int_equal(got[k], 0);
                got[k] = 1;
                seen++;
                assert_int_equal(ef_gen_build(&c, k, &gc), EF_OK);
                assert_int_equal(ef_gen_index_row(&gc, &t), EF_OK);
                assert_string_equal(t.data, rows[k]);
                ef_gen_text_destroy(&t);
                ef_gen_case_destroy(&gc);
            }
        }
        assert_int_equal(seen, total);
        /* in case order the shards' rows are the whole index */
        for (uint32_t k = 0; k < total; k++)
            append(&joined, rows[k]);
        assert_int_equal(joined.len, whole.len);
        assert_memory_equal(joined.data, whole.data, whole.len);
        ef_gen_text_destroy(&joined);
        free(got);
    }
    for (uint32_t k = 0; k < total; k++)
        free(rows[k]);
    free(rows);
    ef_gen_text_destroy(&whole);
}

/* ---------------------------------------------------------- determinism */

/* FNV-1a of every file of the default level-1 run, in case order.  Pinned:
 * if this changes, the content of some case changed -- bump EF_GEN_VERSION
 * (docs/gen.md) and update the value. */
#define LEVEL1_HASH UINT64_C(0x4a33aa649280979e)

static uint64_t run_hash(const ef_gen_config *c, uint32_t first, uint32_t step)
{
    uint64_t h = UINT64_C(0xCBF29CE484222325);
    ef_gen_text t = { NULL, 0, 0 };
    for (uint32_t k = first; k < ef_gen_total(c); k += step) {
        ef_gen_case gc;
        make(c, k, &gc, &t);
        h = fnv1a(h, t.data, t.len);
        ef_gen_case_destroy(&gc);
    }
    ef_gen_text_destroy(&t);
    return h;
}

static void test_determinism(void **state)
{
    ef_gen_config c = cfg(1, 0, 0), other = cfg(1, 0, 0);
    uint64_t a, b;
    (void)state;
    a = run_hash(&c, 0, 1);
    b = run_hash(&c, 0, 1);
    assert_true(a == b);
    print_message("level-1 hash 0x%016llx\n", (unsigned long long)a);
    if (LEVEL1_HASH != 0)
        assert_true(a == LEVEL1_HASH);
    other.seed = c.seed + 1;
    assert_true(run_hash(&other, 0, 1) != a);
}

/* Random case j's drawing depends on (seed, j) only: not on -n, the level,
 * the grid option or its case number. */
static void test_random_depends_on_seed_and_j(void **state)
{
    ef_gen_config a = cfg(1, 0, 0), b = cfg(1, 0, 300), l2 = cfg(2, 0, 0), g8 = cfg(1, 8, 0);
    uint32_t da = ef_gen_directed_count(&a), d2 = ef_gen_directed_count(&l2), d8 = ef_gen_directed_count(&g8);
    ef_gen_text ta = { NULL, 0, 0 }, tb = { NULL, 0, 0 };
    (void)state;
    for (uint32_t j = 0; j < 200; j += 7) {
        ef_gen_case ga, gb;
        char *x, *y;
        make(&a, da + j, &ga, &ta);
        make(&b, da + j, &gb, &tb);
        assert_int_equal(ga.directed, 0);
        assert_int_equal(ga.index, j);
        x = drawing(ta.data);
        y = drawing(tb.data);
        assert_string_equal(x, y);
        free(y);
        ef_gen_case_destroy(&gb);
        make(&l2, d2 + j, &gb, &tb);
        y = drawing(tb.data);
        assert_string_equal(x, y);
        free(y);
        ef_gen_case_destroy(&gb);
        make(&g8, d8 + j, &gb, &tb);
        y = drawing(tb.data);
        assert_string_equal(x, y);
        free(y);
        free(x);
        assert_true(ga.case_seed == ef_gen_case_seed(a.seed, j));
        ef_gen_case_destroy(&ga);
        ef_gen_case_destroy(&gb);
    }
    ef_gen_text_destroy(&ta);
    ef_gen_text_destroy(&tb);
}

/* ------------------------------------------------------------- round trip */

static void roundtrip_directed(const ef_gen_config *c)
{
    ef_gen_text t = { NULL, 0, 0 };
    for (uint32_t k = 0; k < ef_gen_directed_count(c); k++) {
        ef_gen_case gc;
        make(c, k, &gc, &t);
        assert_int_equal(gc.directed, 1);
        assert_non_null(strstr(t.data, "# edgeflag gen: generator "));
        assert_null(strchr(t.data, '\t'));
        assert_null(strchr(gc.desc, '\t'));
        assert_null(strchr(gc.desc, '\n'));
        check_roundtrip(&gc, &t);
        ef_gen_case_destroy(&gc);
    }
    ef_gen_text_destroy(&t);
}

static void test_roundtrip_directed(void **state)
{
    ef_gen_config l1 = cfg(1, 0, 0), l1g8 = cfg(1, 8, 0), l1g32 = cfg(1, 32, 0), l2 = cfg(2, 0, 0);
    (void)state;
    roundtrip_directed(&l1);
    roundtrip_directed(&l1g8);
    roundtrip_directed(&l1g32);
    roundtrip_directed(&l2);
}

static void test_roundtrip_random(void **state)
{
    ef_gen_config c = cfg(1, 0, 600), l2 = cfg(2, 0, 0);
    ef_gen_text t = { NULL, 0, 0 };
    uint32_t d = ef_gen_directed_count(&c), d2 = ef_gen_directed_count(&l2);
    (void)state;
    for (uint32_t k = d; k < ef_gen_total(&c); k++) {
        ef_gen_case gc;
        make(&c, k, &gc, &t);
        check_roundtrip(&gc, &t);
        ef_gen_case_destroy(&gc);
    }
    for (uint32_t j = 600; j < l2.nrandom; j += 173) {
        ef_gen_case gc;
        make(&l2, d2 + j, &gc, &t);
        check_roundtrip(&gc, &t);
        ef_gen_case_destroy(&gc);
    }
    ef_gen_text_destroy(&t);
}

static void test_q8_decimals(void **state)
{
    static const struct {
        int32_t v;
        const char *s;
    } cases[] = {
        { 0, "0" },
        { 1, "0.00390625" },
        { -1, "-0.00390625" },
        { 128, "0.5" },
        { -128, "-0.5" },
        { 256, "1" },
        { -256, "-1" },
        { 257, "1.00390625" },
        { 4194304, "16384" },
        { 8388607, "32767.99609375" },
        { -8388607, "-32767.99609375" },
        { 56, "0.21875" },
    };
    (void)state;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        ef_gen_text t = { NULL, 0, 0 };
        assert_int_equal(ef_gen_append_q8(&t, cases[i].v), EF_OK);
        assert_string_equal(t.data, cases[i].s);
        ef_gen_text_destroy(&t);
    }
    {
        char name[32];
        ef_gen_file_name(0, name, sizeof name);
        assert_string_equal(name, "case_000000.scene");
        ef_gen_file_name(999999, name, sizeof name);
        assert_string_equal(name, "case_999999.scene");
    }
}

/* ------------------------------------------------------------ categories */

static void test_categories_present(void **state)
{
    ef_gen_config c = cfg(1, 0, 0);
    int seen[EF_GEN_NCATEGORIES] = { 0 };
    (void)state;
    for (uint32_t k = 0; k < ef_gen_total(&c); k++) {
        ef_gen_case gc;
        assert_int_equal(ef_gen_build(&c, k, &gc), EF_OK);
        assert_true((unsigned)gc.category < EF_GEN_NCATEGORIES);
        seen[gc.category]++;
        /* directed names are unique within a level-1 run */
        if (gc.directed) {
            for (uint32_t k2 = 0; k2 < k; k2++) {
                ef_gen_case g2;
                assert_int_equal(ef_gen_build(&c, k2, &g2), EF_OK);
                assert_string_not_equal(g2.name, gc.name);
                ef_gen_case_destroy(&g2);
            }
        }
        ef_gen_case_destroy(&gc);
    }
    for (int i = 0; i < EF_GEN_NCATEGORIES; i++) {
        if (!seen[i])
            fail_msg("level 1 has no case of category %s", ef_gen_category_name((ef_gen_category)i));
    }
    assert_int_equal(seen[EF_GEN_CAT_RANDOM], EF_GEN_LEVEL1_RANDOM);
    assert_null(ef_gen_category_name(EF_GEN_NCATEGORIES));
}

/* Specific items of the issue's list, by what the scenes contain. */
static void test_issue_items(void **state)
{
    ef_gen_config c = cfg(1, 0, 0);
    int max_canvas = 0, at_limit = 0, wide_row = 0, overflow128 = 0;
    (void)state;
    for (uint32_t k = 0; k < ef_gen_directed_count(&c); k++) {
        ef_gen_case gc;
        const ef_scene *s = &gc.scene;
        assert_int_equal(ef_gen_build(&c, k, &gc), EF_OK);
        if (s->width == EF_MAX_CANVAS && s->height == EF_MAX_CANVAS)
            max_canvas = 1;
        for (uint32_t i = 0; i < s->npoints; i++)
            if (s->points[i].x == EF_COORD_LIMIT - 1 || s->points[i].x == -(EF_COORD_LIMIT - 1))
                at_limit = 1;
        for (uint32_t i = 0; i < s->ncontours; i++)
            if (s->start[i + 1] - s->start[i] >= 4096)
                wide_row = 1;
        if (s->ncontours >= 128 && gc.category == EF_GEN_CAT_OVERFLOW)
            overflow128 = 1;
        ef_gen_case_destroy(&gc);
    }
    assert_true(max_canvas);
    assert_true(at_limit);
    assert_true(wide_row);
    assert_true(overflow128);
}

/* ---------------------------------------------------------- expectations */

static void check_expect(const ef_gen_case *gc, int n)
{
    const ef_scene *s = &gc->scene;
    const ef_gen_expect *e = &gc->expect;
    ef_ctx *ctx = NULL;
    ef_image img;
    ef_diag d;
    assert_int_equal(ef_ctx_create(&ctx, s->width, s->height, n), EF_OK);
    assert_int_equal(ef_image_create(&img, s->width, s->height), EF_OK);
    memset(img.px, 0, img.stride * (size_t)img.height);
    assert_int_equal(ef_scene_render(ctx, s, -1, &img), EF_OK);
    ef_ctx_diag(ctx, &d);
    for (int32_t y = 0; y < s->height; y++) {
        for (int32_t x = 0; x < s->width; x++) {
            const uint8_t *p = img.px + (size_t)y * img.stride + 4 * (size_t)x;
            if (e->kind == EF_GEN_EXPECT_EMPTY && (p[0] | p[1] | p[2] | p[3]))
                fail_msg("%s at N = %d: pixel (%d, %d) is %u %u %u %u, expected empty", gc->name, n, (int)x, (int)y,
                         p[0], p[1], p[2], p[3]);
            if (e->kind == EF_GEN_EXPECT_FULL && p[3] != 255)
                fail_msg("%s at N = %d: pixel (%d, %d) has alpha %u, expected 255", gc->name, n, (int)x, (int)y, p[3]);
            if (e->kind == EF_GEN_EXPECT_PROBE && x == e->x && y == e->y && p[3] != e->alpha)
                fail_msg("%s at N = %d: pixel (%d, %d) has alpha %u, expected %u", gc->name, n, (int)x, (int)y, p[3],
                         e->alpha);
        }
    }
    if (e->overflow == 1 && d.winding_overflows == 0)
        fail_msg("%s at N = %d: no winding overflow counted", gc->name, n);
    if (e->overflow == 0 && d.winding_overflows != 0)
        fail_msg("%s at N = %d: %llu winding overflows counted, expected none", gc->name, n,
                 (unsigned long long)d.winding_overflows);
    ef_image_destroy(&img);
    ef_ctx_destroy(ctx);
}

static void test_expectations(void **state)
{
    /* level 2 has every row; the 16384 x 16384 canvases (1 GiB images) are left
     * to tests/gen/run.sh, which renders canvas-max through the CLI */
    ef_gen_config c = cfg(2, 0, 0);
    int checked = 0;
    (void)state;
    for (uint32_t k = 0; k < ef_gen_directed_count(&c); k++) {
        ef_gen_case gc;
        assert_int_equal(ef_gen_build(&c, k, &gc), EF_OK);
        if ((gc.expect.kind != EF_GEN_EXPECT_ANY || gc.expect.overflow >= 0) &&
            (int64_t)gc.scene.width * gc.scene.height <= (1 << 22)) {
            check_expect(&gc, 8);
            check_expect(&gc, 16);
            check_expect(&gc, 32);
            checked++;
        }
        ef_gen_case_destroy(&gc);
    }
    print_message("expectations checked on %d directed cases x 3 sample counts\n", checked);
    assert_true(checked >= 30);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_splitmix64),       cmocka_unit_test(test_levels_and_counts),
        cmocka_unit_test(test_shard_rule),       cmocka_unit_test(test_shard_union),
        cmocka_unit_test(test_determinism),      cmocka_unit_test(test_random_depends_on_seed_and_j),
        cmocka_unit_test(test_q8_decimals),      cmocka_unit_test(test_roundtrip_directed),
        cmocka_unit_test(test_roundtrip_random), cmocka_unit_test(test_categories_present),
        cmocka_unit_test(test_issue_items),      cmocka_unit_test(test_expectations),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
