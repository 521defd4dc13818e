/*
 * oracle.h - the independent slow model ("oracle") of edgeflag's coverage.
 *
 * Written from docs/spec.md alone (sections 4, 5.1 and 6.4); it shares no
 * code with model/ or fixed/ and includes nothing from them.  It answers, for
 * every sample of a W x H canvas, the exact point-in-polygon question of
 * spec 5.1 with plain int64 arithmetic: no DDA, no packed words, no clamping
 * tricks.  See docs/oracle.md.
 *
 * Three independent evaluations are provided:
 *   eo_coverage        per sample row: collect the crossings of the row, find
 *                      for each the first pixel whose sample counts it (binary
 *                      search with the exact cross-multiplied predicate),
 *                      prefix-sum the windings.  Fast enough for the harness.
 *   eo_coverage_brute  per sample, per edge: the literal text of spec 5.1.
 *   eo_coverage_fan    per sample: winding number as a sum of signed
 *                      triangle-fan containments with symbolic perturbation
 *                      (a different algorithm; see docs/oracle.md).
 * All three must agree bit for bit; tests/oracle/oracle_selftest.c checks it.
 */
#ifndef EO_ORACLE_H
#define EO_ORACLE_H

#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Return codes. */
#define EO_OK 0
#define EO_ERR_ARG (-1)   /* samples not 8/16/32, W or H outside [1, EO_MAX_CANVAS], bad start[] */
#define EO_ERR_RANGE (-2) /* a coordinate with |v| >= 2^23 */
#define EO_ERR_NOMEM (-3)

#define EO_MAX_CANVAS 16384
#define EO_COORD_LIMIT (1 << 23) /* |x|, |y| < 2^23 (Q16.8) */

/* Same layout as ef_point / ef_polygon (include/edgeflag/edgeflag.h), defined here so the
 * oracle does not include the model's header.  Coordinates are Q16.8 device
 * units (v / 256 px), y grows downward.  Contour c is
 * pts[start[c] .. start[c+1]-1]; start has ncontours+1 entries.  A contour of
 * n >= 1 points is closed implicitly; an empty contour contributes nothing. */
typedef struct eo_point {
    int32_t x, y;
} eo_point;
typedef struct eo_polygon {
    const eo_point *pts;
    const uint32_t *start;
    uint32_t ncontours;
} eo_polygon;

/* n-rooks table k_s (s = 0..N-1) for N = 8, 16, 32, copied from the spec's
 * constants (spec section 4 / docs/patterns.md); NULL for other N. */
const uint8_t *eo_pattern(int samples);

/* Sample positions, Q16.8 (spec section 4). */
int64_t eo_sample_y(int samples, int64_t r);        /* Y_r = h*r + c */
int64_t eo_sample_x(int samples, int64_t i, int s); /* X_s(i) = 256 i + h k_s + c */

/* Coverage masks: mask_out[j*W + i], bit s = sample s of pixel (i, j) covered.
 * rule_evenodd != 0: covered iff winding odd; 0 (non-zero): covered iff
 * winding mod 128 != 0 (7-bit counters, spec 6.4).  mask_out has W*H entries
 * and is fully written.  Returns EO_OK or an EO_ERR_* code. */
int eo_coverage(const eo_polygon *p, int rule_evenodd, int samples, int W, int H, uint32_t *mask_out);
int eo_coverage_brute(const eo_polygon *p, int rule_evenodd, int samples, int W, int H, uint32_t *mask_out);
int eo_coverage_fan(const eo_polygon *p, int rule_evenodd, int samples, int W, int H, uint32_t *mask_out);

/* True (unwrapped) winding numbers over the visible samples, for the overflow
 * diagnostic (spec 6.4).  Two implications hold for the model's
 * ef_diag.winding_overflows counted on a non-zero rasterization (docs/oracle.md):
 *   outside_7bit > 0          =>  the model counts at least one overflow;
 *   max_row_crossings <= 63   =>  the model counts no overflow.            */
typedef struct eo_stats {
    int64_t min_winding, max_winding; /* over all W*H*N samples */
    uint64_t outside_7bit;            /* samples with winding outside [-64, 63] */
    uint64_t abs_ge64;                /* samples with |winding| >= 64 */
    uint64_t wrapped_uncovered;       /* winding != 0 but a multiple of 128 */
    uint64_t max_row_crossings;       /* max over sample rows 0..N*H-1 of the
                                           number of edges crossing that row
                                           (left of, inside and right of the canvas) */
    uint64_t crossings;               /* total crossings over those rows */
    uint64_t edges;                   /* non-horizontal edges */
} eo_stats;
int eo_winding_stats(const eo_polygon *p, int samples, int W, int H, eo_stats *out);

/* Everything at once (any output may be NULL): one pass gives the non-zero
 * and even-odd masks and the statistics. */
int eo_eval(const eo_polygon *p, int samples, int W, int H, uint32_t *mask_nonzero, uint32_t *mask_evenodd,
            eo_stats *stats);

/* Winding number of one sample (pixel i, row j, sample s), any i, j (also
 * outside the canvas), by the literal spec 5.1 rule.  *err gets the status. */
int64_t eo_sample_winding(const eo_polygon *p, int samples, int64_t i, int64_t j, int s, int *err);
/* The same by the triangle-fan method (must be equal). */
int64_t eo_sample_winding_fan(const eo_polygon *p, int samples, int64_t i, int64_t j, int s, int *err);

/* docs/spec.md section 10 (tests/oracle/oracle_filter.c): per-pixel coverage
 * sums with the tent filter (filter 1; 0 the box) and the per-channel sample
 * offsets (subpixel 0 none, 1 RGB, 2 BGR) under one rule.  sums[(j*W + i)*3 + c]
 * for c = R, G, B, over the denominator eo_filter_denominator (65536 N for the
 * tent, N for the box).  EO_ERR_RANGE when a vertex moved by a channel's shift
 * leaves |v| < 2^23; W, H <= 16383. */
int eo_filter_eval(const eo_polygon *p, int samples, int W, int H, int filter, int subpixel, int evenodd,
                   uint32_t *sums);
uint32_t eo_filter_denominator(int filter, int samples);
int eo_filter_shift(int subpixel, int colour); /* Q16.8 shift of colour c's samples */

/* Debug aids for the harness. */
/* Prints the polygon as text: "contour c (n points): x,y x,y ...". */
void eo_polygon_fprint(FILE *f, const eo_polygon *p);
/* Prints the sample's row crossings, which ones it counts, and its winding. */
void eo_explain_sample(FILE *f, const eo_polygon *p, int samples, int64_t i, int64_t j, int s);
/* Compares two mask images; returns the number of differing pixels and, if
 * f != NULL, prints up to max_report of them (pixel, both masks, xor). */
uint64_t eo_compare_masks(FILE *f, const uint32_t *expect, const uint32_t *got, int W, int H, int samples,
                          int max_report);

#ifdef __cplusplus
}
#endif

#endif /* EO_ORACLE_H */
