/*
 * ef_patterns.h - the n-rooks sample-pattern search behind `edgeflag patterns`
 * and model/pattern_tables.c.
 *
 * The paper (section 3.3) selects its patterns "lowest discrepancy first, then
 * the sum of the squares of the minimum distances between the sample points".
 * docs/patterns.md states the exact, integer-only reading of that criterion
 * used here and why it is the one that reproduces the paper's 8-sample table.
 *
 * A pattern is a table k[s], s = 0..N-1: sample s sits at
 * x = (2k[s]+1)/(2N), y = (2s+1)/(2N) inside the pixel (docs/spec.md 4).
 * Everything is exact integer arithmetic and fully deterministic: the same
 * tables on every compiler and machine.
 */
#ifndef EF_PATTERNS_H
#define EF_PATTERNS_H

#include "edgeflag.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest pattern handled (tables are uint8_t[N], N = 8, 16 or 32). */
#define EF_PATTERN_MAX EF_SAMPLES_MAX

/* The criterion's numbers for one pattern, all exact integers.
 *
 * discrepancy: grid star discrepancy, numerator over N^2:
 *     max over 0 <= a, b <= N of | N * #{s < b : k[s] < a} - a*b |
 *   i.e. the largest error, in units of 1/N^2 of a pixel, with which the
 *   samples estimate the area of a box [0, a/N) x [0, b/N) of the sub-grid.
 *   Lower is better.  Invariant under the 8 symmetries of the square.
 * spread: sum over samples of the squared distance to the nearest other
 *   sample of the same pixel, in units of (1/N px)^2.  Higher is better
 *   (docs/patterns.md explains why "higher" is the reading that reproduces
 *   the paper).  Invariant under the 8 symmetries of the square.
 * star: exact star discrepancy of the sample points over all boxes
 *   [0, x) x [0, y) anchored at the pixel's top-left corner, numerator over
 *   4N^2.  Not part of the criterion: it only picks the orientation of the
 *   winner (ef_pattern_canonical). */
typedef struct ef_pattern_score {
    uint32_t discrepancy;
    uint32_t spread;
    uint32_t star;
} ef_pattern_score;

/* 1 when k[0..n-1] is a permutation of 0..n-1 (one sample per sub-row and
 * sub-column) and n is 8, 16 or 32; else 0. */
EF_API int ef_pattern_is_nrooks(int n, const uint8_t *k);

/* Scores k.  EF_ERR_ARG if k is not an n-rooks pattern of a valid n. */
EF_API ef_status ef_pattern_score_of(int n, const uint8_t *k, ef_pattern_score *out);

/* Orders two scores of the same n by the criterion: discrepancy ascending,
 * then spread descending.  <0: a is better, 0: equal, >0: b is better.
 * `star` is ignored (it does not rank patterns, only orientations). */
EF_API int ef_pattern_compare(const ef_pattern_score *a, const ef_pattern_score *b);

/* The canonical orientation of k among its 8 images under the symmetries of
 * the square (mirrors and transposition), which all score the same: least
 * `star`, then the lexicographically least table.  out may alias k. */
EF_API ef_status ef_pattern_canonical(int n, const uint8_t *k, uint8_t *out);

/* Searches the n-rooks patterns of n samples for the best under the
 * criterion and returns it in canonical orientation, with its score (score
 * may be NULL).  n = 8: exhaustive over all 40320 permutations.  n = 16, 32:
 * structured candidates (rank-1 lattices, linearly scrambled bit-reversal
 * nets) followed by a late-acceptance local search with a fixed seed and
 * fixed iteration counts, so the result is reproducible but not proven
 * optimal.  EF_ERR_ARG for any other n. */
EF_API ef_status ef_pattern_search(int n, uint8_t *k_out, ef_pattern_score *score);

#ifdef __cplusplus
}
#endif

#endif /* EF_PATTERNS_H */
