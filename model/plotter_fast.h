/*
 * plotter_fast.h - the plotter's speed devices (included by plotter.c when
 * EF_PLOT_FAST; uses its DDA_STEP, PLOT_CELL and PLOT_CELL_NOOCC).  Each
 * plots exactly the samples, cells and bits of plotter.c's spec-shaped loop
 * (efbench hash and the oracle check every bit); how much each one saves is
 * in bench/results/PROFILE.md.
 * - Unrolling (ROW_FROM0): N is a compile-time constant per instance; the
 *   rows of edges active from earlier rows are unrolled with constant
 *   offsets, bytes and bits (the paper's 3.8 D), and every row ends where
 *   its last sample is plotted, without a loop counter.
 * - No clamp (PLOT_STEEP_ROW, PLOT_INSIDE_ROW): edges with both end points in [1, 256W]
 *   (EF_PLOT_INSIDE, EF_PLOT_STEEP) take x only in [0, 256W - 1], so the
 *   clamp of spec 6.1 cannot act and is skipped, and the shifts are of
 *   non-negative values.
 * - Ranges instead of bits: the occupancy bits of a STEEP edge's row at
 *   N >= 16 (less than 6 px of movement per row) are set once for its cell
 *   range, and edge tracking of STEEP and INSIDE edges widens an x range
 *   once per edge and row, turned into cells with a margin at the end of
 *   the row (plotter.c, plot_row): supersets of the marked cells, which
 *   change no span (unmarked cells are zero, spec 7.1).
 * - MASK rows (plotter_sse2.h): at N = 16 and 32, a whole row at once.
 * The crowded-row device is plotter_crowd.h.
 */
#ifndef EF_PLOTTER_FAST_H
#define EF_PLOTTER_FAST_H

#if EF_MASK_ROWS
#include "plotter_sse2.h"
#endif

/* Sample rows s0..s1 of one edge in the current pixel row.  Both forms plot
 * each sample, stop after s1, and otherwise take the sample's DDA step, so
 * they leave x at sample s1 (the last plotted x, which edge tracking needs);
 * the caller takes the step to the next row.
 *
 * ROW_FROM0 is for edges active from earlier rows, which start the row at
 * sample 0: the samples are unrolled, each with its offset, byte and bit as
 * constants, and the exit test is all that is left of the loop.  ROW_LOOP is
 * for a row's new edges, which start at a data-dependent sample: entering an
 * unrolled sequence there (a switch) costs a mispredicted jump per edge on
 * top of the exit's (PROFILE.md). */
#define ROW_SAMPLE(S, PLOT) \
    if ((S) < NS) { \
        const uint64_t bit = UINT64_C(1) << (S); \
        const uint32_t q_ = (uint32_t)(x + off[S]) >> EF_DEV_FRAC_BITS; \
        PLOT(q_, S); \
        if ((S) == NS - 1 || (S) == s1) \
            break; \
        DDA_STEP(); \
    }
/* Eight samples a row, as the macro unrolls them. */
/* clang-format off */
#define ROW_SAMPLES8(B, PLOT)                                                     \
    ROW_SAMPLE(B + 0, PLOT) ROW_SAMPLE(B + 1, PLOT) ROW_SAMPLE(B + 2, PLOT)      \
    ROW_SAMPLE(B + 3, PLOT) ROW_SAMPLE(B + 4, PLOT) ROW_SAMPLE(B + 5, PLOT)      \
    ROW_SAMPLE(B + 6, PLOT) ROW_SAMPLE(B + 7, PLOT)
/* clang-format on */
#define ROW_FROM0(PLOT) \
    do { \
        ROW_SAMPLES8(0, PLOT) ROW_SAMPLES8(8, PLOT) ROW_SAMPLES8(16, PLOT) ROW_SAMPLES8(24, PLOT) \
    } while (0)
#define ROW_LOOP(PLOT) \
    do { \
        uint64_t bit = UINT64_C(1) << s0; \
        for (int s = s0;; s++) { \
            const uint32_t q_ = (uint32_t)(x + off[s]) >> EF_DEV_FRAC_BITS; \
            PLOT(q_, s); \
            if (s == s1) \
                break; \
            bit <<= 1; \
            DDA_STEP(); \
        } \
    } while (0)
#define ROW_SAMPLES(PLOT) \
    do { \
        if (first) \
            ROW_LOOP(PLOT); \
        else \
            ROW_FROM0(PLOT); \
    } while (0)

/* Occupancy bits for the cells [a, b], a <= b, b - a < 64. */
static EF_ALWAYS_INLINE void mark_occ_range(uint64_t *occ, uint32_t a, uint32_t b)
{
    const uint32_t wa = a >> 6, wb = b >> 6;
    const uint64_t ma = ~UINT64_C(0) << (a & 63), mb = ~UINT64_C(0) >> (63 - (b & 63));
    if (wa == wb) {
        occ[wa] |= ma & mb;
    } else {
        occ[wa] |= ma;
        occ[wb] |= mb;
    }
}

/* plot_edge_row's rows (plotter.c) for STEEP edges (and MASK ones on rows
 * that count overflows) and for INSIDE edges, written as macros over its
 * locals (x, e, xa, rsd, qs1, off, s0, s1, first, the plotting state) so
 * that the plain loop and these share one body and one exit.  Edge
 * tracking: they widen the range [*lox, *hix] of x values, which plot_row
 * turns into cells with a margin of 6 and 7: a STEEP edge's cells lie within
 * that margin of its first x (it moves less than 6 px over the row), an
 * INSIDE edge's within 1 of its first and last plotted x.
 *
 * STEEP: x in [0, 256W - 1], so q = (x + off) >> 8 lies in [0, W], no
 * clamp.  For N >= 16 (more samples a row) the occupancy range is marked
 * once; for N = 8 a bit per sample costs less (PROFILE.md). */
#define PLOT_STEEP_ROW() \
    do { \
        *lox = xa < *lox ? xa : *lox; \
        *hix = xa > *hix ? xa : *hix; \
        if (NS >= 16) { \
            ROW_SAMPLES(PLOT_CELL_NOOCC); \
            const uint32_t a_ = (uint32_t)(xa < x ? xa : x) >> EF_DEV_FRAC_BITS; \
            const uint32_t b_ = ((uint32_t)(xa < x ? x : xa) >> EF_DEV_FRAC_BITS) + 1; /* <= W */ \
            mark_occ_range(occ, a_, b_); \
        } else { \
            ROW_SAMPLES(PLOT_CELL); \
        } \
        DDA_STEP(); \
    } while (0)

/* INSIDE: as STEEP without the range of occupancy bits; tracks the first and
 * last plotted x, both in [0, 256W - 1]. */
#define PLOT_INSIDE_ROW() \
    do { \
        ROW_SAMPLES(PLOT_CELL); \
        const int32_t a_ = xa < x ? xa : x, b_ = xa < x ? x : xa; \
        *lox = a_ < *lox ? a_ : *lox; \
        *hix = b_ > *hix ? b_ : *hix; \
        DDA_STEP(); \
    } while (0)

#endif
