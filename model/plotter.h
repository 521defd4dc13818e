/*
 * plotter.h - what plotter.c and its speed devices share (private to
 * model/plotter*.c): the one switch that turns the speed devices on, the test
 * mutations, and what plot_row needs of the crowded-row device
 * (plotter_crowd.h).
 */
#ifndef EF_PLOTTER_H
#define EF_PLOTTER_H

#include "internal.h"

/* ----------------------------------------------------------- the switch */

/* EF_MUTATION (test builds only, tests/mutants.sh) injects known bugs so the
 * oracle test can prove that it catches them: 1 = one wrong n-rooks offset,
 * 2 = an off-by-one in the x rounding (crossings up to 1/256 px left of a
 * sample are missed); 3 is in ctx.c. */
#ifndef EF_MUTATION
#define EF_MUTATION 0
#endif

/* EF_PLOT_FAST: 1 = the speed devices of plotter_fast.h, plotter_sse2.h and
 * plotter_crowd.h; 0 = every sample through the spec-shaped loop of
 * plotter.c.  Both give the same bits (efbench hash of a -DEF_PLOT_FAST=0
 * build).  Mutant builds always take the plain loop: mutated offsets may
 * leave [1, 255], and only the plain loop clamps every sample. */
#ifndef EF_PLOT_FAST
#define EF_PLOT_FAST (EF_MUTATION == 0)
#endif
#if EF_MUTATION != 0 && EF_PLOT_FAST
#error "mutant builds need the plain plotter (EF_PLOT_FAST 0)"
#endif

/* Within the speed devices, MASK rows (plotter_sse2.h) use SSE2, which every
 * x86-64 has; other hosts, big-endian ones (the byte order of the non-zero
 * lanes) and EF_NO_VECTOR builds plot those edges sample by sample, with the
 * same results. */
#if EF_PLOT_FAST && !defined(EF_NO_VECTOR) && defined(__SSE2__) && defined(__BYTE_ORDER__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define EF_MASK_ROWS 1
#else
#define EF_MASK_ROWS 0
#endif
/* Whether this plotter instance takes MASK rows: N = 16 and 32 (at N = 8, a
 * whole row costs more than its few samples one by one: PROFILE.md), and not
 * on rows that count winding overflows, which need the plots in AET order
 * (spec 6.1, last paragraph). */
#define MASK_ROWS(NS, check) (EF_MASK_ROWS && !(check) && (NS) >= 16)

/* ------------------------------------------------------- test mutations */

/* Plot offset of sample s as the mutant builds see it (off = ctx->off[s]
 * in the real build). */
static EF_ALWAYS_INLINE int32_t ef_plot_mutate_offset(int32_t off, int s, int32_t h)
{
#if EF_MUTATION == 1
    if (s == 3)
        off += h;
#elif EF_MUTATION == 2
    off -= 1;
#endif
    (void)s;
    (void)h;
    return off;
}

/* -------------------------------------------------------------- crowds */

/* The cells an edge can mark while its DDA's x moves from xa to xb: x is
 * monotonic over the row's samples and every offset lies in [1, 255], so
 * every plotted cell lies in [floor(min/256), floor(max/256) + 1], clamped
 * to [0, W]. */
static EF_ALWAYS_INLINE void cells_of_x_range(int32_t W, int32_t xa, int32_t xb, int32_t *qa, int32_t *qb)
{
    const int32_t a = xa < xb ? xa : xb, b = xa < xb ? xb : xa;
    *qa = ef_clamp_i32(ef_asr_i32(a, EF_DEV_FRAC_BITS), 0, W);
    *qb = ef_clamp_i32(ef_asr_i32(b, EF_DEV_FRAC_BITS) + 1, 0, W);
}

/* A crowded row's edge that plots x values between xa and xb (either
 * order): one more edge that may plot into each of its cells
 * (cells_of_x_range), as two updates of the difference array `crowd` (+1 at
 * the first cell, -1 after the last, which is at most W + 1). */
static EF_ALWAYS_INLINE void crowd_add(int32_t *crowd, int32_t W, int32_t xa, int32_t xb, int32_t *lo, int32_t *hi)
{
    int32_t qa, qb;
    cells_of_x_range(W, xa, xb, &qa, &qb);
    crowd[qa]++;
    crowd[qb + 1]--;
    *lo = qa < *lo ? qa : *lo;
    *hi = qb + 1 > *hi ? qb + 1 : *hi;
}

#endif
