/*
 * test_patterns.c - the frozen n-rooks tables (model/pattern_tables.c) are
 * exactly what the pattern search (model/pattern_search.c) selects, the
 * 8-sample one is the paper's, and the scoring is right on cases worked out
 * by hand (docs/patterns.md).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "ef_patterns.h"

static const int sizes[3] = { 8, 16, 32 };

/* Paper, Algorithm 1: offsets 0.25, 0.875, 0.5, ... = k/8. */
static const uint8_t paper8[8] = { 2, 7, 4, 1, 6, 3, 0, 5 };

static void test_tables_are_nrooks(void **state)
{
    (void)state;
    for (int i = 0; i < 3; i++) {
        const uint8_t *k = ef_pattern(sizes[i]);
        assert_non_null(k);
        assert_true(ef_pattern_is_nrooks(sizes[i], k));
    }
    assert_null(ef_pattern(12));
}

static void test_paper_table_8(void **state)
{
    (void)state;
    assert_memory_equal(ef_pattern(8), paper8, 8);
}

/* The acceptance test of the tool: searching again reproduces every frozen
 * table bit for bit (so the tables are derived, not typed in). */
static void test_search_reproduces_tables(void **state)
{
    (void)state;
    for (int i = 0; i < 3; i++) {
        int n = sizes[i];
        uint8_t k[EF_PATTERN_MAX];
        ef_pattern_score found, frozen;
        assert_int_equal(ef_pattern_search(n, k, &found), EF_OK);
        assert_true(ef_pattern_is_nrooks(n, k));
        assert_memory_equal(k, ef_pattern(n), (size_t)n);
        assert_int_equal(ef_pattern_score_of(n, ef_pattern(n), &frozen), EF_OK);
        assert_int_equal(ef_pattern_compare(&found, &frozen), 0);
        assert_int_equal(found.star, frozen.star);
    }
}

/* Scores of the paper's table, worked out by hand (docs/patterns.md):
 * the worst boxes, e.g. [0,2/8) x [0,3/8), hold no sample for an area of
 * 6/64, |8*0 - 2*3| = 6, and none is worse;
 * nearest-neighbour squared distances 8,10,8,8,8,8,10,8 sum to 68. */
static void test_score_paper8(void **state)
{
    (void)state;
    ef_pattern_score sc;
    assert_int_equal(ef_pattern_score_of(8, paper8, &sc), EF_OK);
    assert_int_equal(sc.discrepancy, 6);
    assert_int_equal(sc.spread, 68);
    assert_int_equal(sc.star, 47);
}

/* The diagonal k = s: box [0,4/8)^2 holds 4 samples for area 16/64, so
 * |8*4 - 16| = 16; every sample's nearest neighbour is one step diagonal
 * away (squared distance 2), spread 8*2 = 16. */
static void test_score_diagonal(void **state)
{
    (void)state;
    uint8_t k[8];
    ef_pattern_score sc;
    for (int s = 0; s < 8; s++)
        k[s] = (uint8_t)s;
    assert_int_equal(ef_pattern_score_of(8, k, &sc), EF_OK);
    assert_int_equal(sc.discrepancy, 16);
    assert_int_equal(sc.spread, 16);
}

/* Discrepancy and spread do not depend on orientation: all 8 images of
 * each table score the same, and the table is its own canonical image. */
static void test_symmetry_invariance(void **state)
{
    (void)state;
    for (int i = 0; i < 3; i++) {
        int n = sizes[i];
        const uint8_t *k = ef_pattern(n);
        ef_pattern_score base;
        uint8_t canon[EF_PATTERN_MAX];
        assert_int_equal(ef_pattern_score_of(n, k, &base), EF_OK);
        for (int g = 0; g < 8; g++) {
            uint8_t t[EF_PATTERN_MAX], img[EF_PATTERN_MAX];
            ef_pattern_score sc;
            for (int s = 0; s < n; s++) {
                if (g & 4)
                    t[k[s]] = (uint8_t)s; /* transpose */
                else
                    t[s] = k[s];
            }
            for (int s = 0; s < n; s++) {
                uint8_t v = t[(g & 2) ? n - 1 - s : s];
                img[s] = (uint8_t)((g & 1) ? n - 1 - v : v);
            }
            assert_int_equal(ef_pattern_score_of(n, img, &sc), EF_OK);
            assert_int_equal(sc.discrepancy, base.discrepancy);
            assert_int_equal(sc.spread, base.spread);
            assert_int_equal(ef_pattern_canonical(n, img, canon), EF_OK);
            assert_memory_equal(canon, k, (size_t)n);
        }
    }
}

/* The original implementation's tables (docs/ANCHORS.md, code order,
 * mirrored to positions) never beat ours under the criterion. */
static void test_not_worse_than_original(void **state)
{
    (void)state;
    static const uint8_t c8[8] = { 5, 0, 3, 6, 1, 4, 7, 2 };
    static const uint8_t c16[16] = { 1, 8, 4, 15, 11, 2, 6, 14, 10, 3, 7, 12, 0, 9, 5, 13 };
    static const uint8_t c32[32] = { 28, 13, 6,  23, 0,  17, 10, 27, 4,  21, 14, 31, 8,  25, 18, 3,
                                     12, 29, 22, 7,  16, 1,  26, 11, 20, 5,  30, 15, 24, 9,  2,  19 };
    const uint8_t *code[3] = { c8, c16, c32 };
    for (int i = 0; i < 3; i++) {
        int n = sizes[i];
        uint8_t orig[EF_PATTERN_MAX];
        ef_pattern_score so, sm;
        for (int s = 0; s < n; s++)
            orig[s] = (uint8_t)(n - 1 - code[i][s]);
        assert_int_equal(ef_pattern_score_of(n, orig, &so), EF_OK);
        assert_int_equal(ef_pattern_score_of(n, ef_pattern(n), &sm), EF_OK);
        assert_true(ef_pattern_compare(&sm, &so) <= 0);
    }
}

static void test_rejects_bad_input(void **state)
{
    (void)state;
    uint8_t dup[8] = { 0, 1, 2, 3, 4, 5, 6, 6 };
    uint8_t big[8] = { 0, 1, 2, 3, 4, 5, 6, 8 };
    uint8_t out[EF_PATTERN_MAX];
    ef_pattern_score sc;
    assert_false(ef_pattern_is_nrooks(8, dup));
    assert_false(ef_pattern_is_nrooks(8, big));
    assert_false(ef_pattern_is_nrooks(4, paper8));
    assert_false(ef_pattern_is_nrooks(8, NULL));
    assert_int_equal(ef_pattern_score_of(8, dup, &sc), EF_ERR_ARG);
    assert_int_equal(ef_pattern_canonical(8, big, out), EF_ERR_ARG);
    assert_int_equal(ef_pattern_search(12, out, &sc), EF_ERR_ARG);
    assert_int_equal(ef_pattern_search(8, NULL, &sc), EF_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tables_are_nrooks),   cmocka_unit_test(test_paper_table_8),
        cmocka_unit_test(test_score_paper8),        cmocka_unit_test(test_score_diagonal),
        cmocka_unit_test(test_symmetry_invariance), cmocka_unit_test(test_not_worse_than_original),
        cmocka_unit_test(test_rejects_bad_input),   cmocka_unit_test(test_search_reproduces_tables),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
