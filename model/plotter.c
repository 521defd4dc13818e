/*
 * plotter.c - the edge plotter (docs/spec.md section 6.1): for every active
 * edge and every sample row of the current pixel row, one flag into the
 * scanline buffer at pixel floor((x + off[s]) / 256), clamped to [0, W], then
 * one exact DDA step.  This is the hardware's one-edge-row-per-cycle loop.
 *
 * The even-odd buffer takes an XOR of the sample's bit; the non-zero buffer
 * adds the edge direction to the byte that holds the sample's 7-bit lane of
 * a packed word (modulo 256: the filler masks the pad bits, spec 6.3).  The
 * occupancy map gets a bit for every cell that may have been marked, so the
 * filler visits only those (mask tracking, word at a time); a range of cells
 * that contains every marked one bounds the row (edge tracking).  A row's
 * new edges are activated (their DDA started, ef_dda_start) as they are
 * plotted, after the edges already active, and edges past their last sample
 * row leave the AET in the same pass: the AET order of spec 6 is kept.
 *
 * Speed, with exactly the results of the plain loop (efbench hash, and the
 * oracle, check every bit):
 * - N is a compile-time constant per instance; the rows of edges active
 *   from earlier rows are unrolled with constant offsets, bytes and bits
 *   (the paper's 3.8 D), and every row ends where its last sample is
 *   plotted, without a loop counter (ROW_FROM0, ROW_LOOP);
 * - edges with both end points in [1, 256W] (EF_PLOT_INSIDE, EF_PLOT_STEEP)
 *   take x only in [0, 256W - 1], so the clamp of 6.1 cannot act and is
 *   skipped, and the shifts are of non-negative values;
 * - the occupancy bits of a STEEP edge's row at N >= 16 (less than 6 px
 *   of movement per row) are set once for its cell range, and edge tracking of
 *   STEEP and INSIDE edges widens an x range once per edge and row, turned
 *   into cells with a margin at the end of the row: supersets of the marked
 *   cells, which change no span (unmarked cells are zero, spec 7.1);
 * - data-dependent choices (an edge's end, the DDA carry, the floor of a
 *   division) are computed without branches, which would mispredict;
 * - at N = 16 and 32, MASK edges (less than 1 px of movement a row) plot
 *   a whole row at once from two exact compares per sample, SSE2 over the
 *   row's samples, without a loop or a data-dependent branch
 *   (plot_mask_row, spec 6.1);
 * - the winding-overflow diagnostic (spec 6.4) is only evaluated on rows
 *   where 64 edges may plot into one cell (ef_plot_nonzero): with fewer no
 *   counter can leave [-64, 63], so the count is the same.
 *
 * EF_MUTATION (test builds only) injects known bugs so the oracle test can
 * prove that it catches them: 1 = one wrong n-rooks offset, 2 = an off-by-one
 * in the x rounding (crossings up to 1/256 px left of a sample are missed).
 * Mutated offsets may leave [1, 255], so mutant builds always clamp.
 */
#include "internal.h"

#ifndef EF_MUTATION
#define EF_MUTATION 0
#endif
#define EF_FAST_PATH (EF_MUTATION == 0)

/* MASK rows (plot_mask_row) use SSE2, which every x86-64 has; other hosts,
 * big-endian ones (the byte order of the non-zero lanes) and EF_NO_VECTOR
 * builds plot those edges sample by sample, with the same results. */
#if EF_FAST_PATH && !defined(EF_NO_VECTOR) && defined(__SSE2__) && defined(__BYTE_ORDER__) &&                \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#include <emmintrin.h>
#define EF_MASK_ROWS 1
#else
#define EF_MASK_ROWS 0
#endif
/* Whether this plotter instance takes MASK rows: N = 16 and 32 (at N = 8,
 * about 3.5 samples an edge-row on tiger and on text, a whole row measured
 * 18% more instructions and 11% more time than its samples one by one), and
 * not on rows that count winding overflows, which need the plots in AET
 * order. */
#define MASK_ROWS(NS, check) (EF_MASK_ROWS && !(check) && (NS) >= 16)

/* The plot offsets of this context (spec 6.1), with the test mutations. */
static EF_ALWAYS_INLINE void load_offsets(const ef_ctx *ctx, int32_t *off, const int NS)
{
    for (int s = 0; s < NS; s++) {
        off[s] = ctx->off[s];
#if EF_MUTATION == 1
        if (s == 3)
            off[s] += ctx->h;
#elif EF_MUTATION == 2
        off[s] -= 1;
#endif
    }
}

/* One exact DDA step (spec 5 step 5 / 6.1).  Branch-free carry: the error
 * term's overflow is data-dependent and would mispredict about half the time.
 * With rsd = rs - dy and qs1 = qs + 1 (per edge): t = e + rs - dy, carry =
 * t >= 0; neg = -1 without a carry, 0 with one; e = t + (dy & neg) and
 * x += qs + carry = qs1 + neg, so the error term's chain is one add, and no
 * compare or select is needed.  |t| < 2^24. */
#define DDA_STEP()                                              \
    do {                                                        \
        const int32_t t_ = e + rsd;                             \
        const int32_t neg_ = -(int32_t)((uint32_t)t_ >> 31);    \
        e = t_ + (dy & neg_);                                   \
        x += qs1 + neg_;                                        \
    } while (0)

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

/* Edge tracking per edge and row rather than per sample: the filler only
 * needs a range that contains every marked cell. */
static EF_ALWAYS_INLINE void track(const ef_ctx *ctx, int32_t xa, int32_t xb, int32_t *lo, int32_t *hi)
{
    int32_t qa, qb;
    cells_of_x_range(ctx->width, xa, xb, &qa, &qb);
    *lo = qa < *lo ? qa : *lo;
    *hi = qb > *hi ? qb : *hi;
}

/* Sample s's even-odd bit is `bit` in the caller's loop: a constant
 * 1 << s in the unrolled full rows; in the partial rows a register doubled
 * every sample (a shift by the variable s costs two instructions).  64 bits:
 * no bit is shifted out after sample 31. */
#define EO_BIT(s) ((void)(s), (uint32_t)bit)

/* Marks sample s of cell q (6.2 / 6.3) and its occupancy bit.  Non-zero:
 * the counter of sample s is a byte (ef_nz_lane_byte), to which d8 (0x01 or
 * 0xFF) is added modulo 256: its low 7 bits are the spec's lane modulo 128
 * and its top bit is the pad bit, which the filler masks off when it reads
 * the word (fill_nonzero.c).  One byte add replaces the word's load, add,
 * mask, store and the lane rotation, and consecutive samples of an edge touch
 * different bytes, so no store feeds the next load.  limit is the old 7-bit
 * value that overflows (63 for +1, 64 for -1). */
#define PLOT_CELL_NOOCC(q, s)                                                                     \
    do {                                                                                          \
        if (NZ) {                                                                                 \
            uint8_t *b_ = &nzb[(size_t)(q) * (size_t)NS + ef_nz_lane_byte((unsigned)(s))];         \
            if (check)                                                                            \
                *overflows += (*b_ & 0x7Fu) == limit;                                             \
            *b_ = (uint8_t)(*b_ + d8);                                                            \
        } else {                                                                                  \
            eo[q] ^= EO_BIT(s);                                                                   \
        }                                                                                         \
    } while (0)

#define PLOT_CELL(q, s)                                                                           \
    do {                                                                                          \
        PLOT_CELL_NOOCC(q, s);                                                                    \
        occ[(q) >> 6] |= UINT64_C(1) << ((q) & 63);                                               \
    } while (0)

/* Sample rows s0..s1 of one edge in the current pixel row.  Both forms plot
 * each sample, stop after s1, and otherwise take the sample's DDA step, so
 * they leave x at sample s1 (the last plotted x, which edge tracking needs);
 * the caller takes the step to the next row.
 *
 * ROW_FROM0 is for edges active from earlier rows, which start the row at
 * sample 0: the samples are unrolled, each with its offset, byte and bit as
 * constants, and the exit test is all that is left of the loop.  ROW_LOOP is
 * for a row's new edges, which start at a data-dependent sample: entering an
 * unrolled sequence there (a switch) cost a mispredicted jump per edge on top
 * of the exit's, and measured slower than the loop. */
#define ROW_SAMPLE(S, PLOT)                                                       \
    if ((S) < NS) {                                                               \
        const uint64_t bit = UINT64_C(1) << (S);                                  \
        const uint32_t q_ = (uint32_t)(x + off[S]) >> EF_DEV_FRAC_BITS;          \
        PLOT(q_, S);                                                              \
        if ((S) == NS - 1 || (S) == s1)                                           \
            break;                                                                \
        DDA_STEP();                                                               \
    }
#define ROW_SAMPLES8(B, PLOT)                                                     \
    ROW_SAMPLE(B + 0, PLOT) ROW_SAMPLE(B + 1, PLOT) ROW_SAMPLE(B + 2, PLOT)      \
    ROW_SAMPLE(B + 3, PLOT) ROW_SAMPLE(B + 4, PLOT) ROW_SAMPLE(B + 5, PLOT)      \
    ROW_SAMPLE(B + 6, PLOT) ROW_SAMPLE(B + 7, PLOT)
#define ROW_FROM0(PLOT)                                                           \
    do {                                                                          \
        ROW_SAMPLES8(0, PLOT) ROW_SAMPLES8(8, PLOT)                               \
        ROW_SAMPLES8(16, PLOT) ROW_SAMPLES8(24, PLOT)                             \
    } while (0)
#define ROW_LOOP(PLOT)                                                            \
    do {                                                                          \
        uint64_t bit = UINT64_C(1) << s0;                                         \
        for (int s = s0;; s++) {                                                  \
            const uint32_t q_ = (uint32_t)(x + off[s]) >> EF_DEV_FRAC_BITS;      \
            PLOT(q_, s);                                                          \
            if (s == s1)                                                          \
                break;                                                            \
            bit <<= 1;                                                            \
            DDA_STEP();                                                           \
        }                                                                         \
    } while (0)
#define ROW_SAMPLES(PLOT)                                                         \
    do {                                                                          \
        if (first)                                                                \
            ROW_LOOP(PLOT);                                                       \
        else                                                                      \
            ROW_FROM0(PLOT);                                                      \
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

#if EF_MASK_ROWS
/* Byte masks of a sample range s0..s1 for 16 and 32 samples: 32 bytes from
 * mask_from[dir < 0] + 32 - s0 hold d8 from byte s0 on, 32 bytes from mask_to
 * + 31 - s1 are 0xFF up to byte s1. */
#define EF_X32(v) v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v, v
static const uint8_t mask_from[2][64] = { { EF_X32(0), EF_X32(1) }, { EF_X32(0), EF_X32(0xFF) } };
static const uint8_t mask_to[64] = { EF_X32(0xFF), EF_X32(0) };
#undef EF_X32

/* P_s = s*step + dY*off_s for the four samples of pairs[j] (see plot_mask_row). */
static EF_ALWAYS_INLINE __m128i mask_p4(const __m128i *pairs, int j, __m128i bl, __m128i bh)
{
    const __m128i a = _mm_load_si128(&pairs[j]);   /* ctx (calloc) and the array are 16-byte aligned */
    return _mm_add_epi32(_mm_madd_epi16(a, bl), _mm_slli_epi32(_mm_madd_epi16(a, bh), 15));
}

/* Samples 16k..16k+15 as bytes, -1 where P_s > c. */
static EF_ALWAYS_INLINE __m128i mask_ge16(const __m128i *p, __m128i c)
{
    return _mm_packs_epi16(_mm_packs_epi32(_mm_cmpgt_epi32(p[0], c), _mm_cmpgt_epi32(p[1], c)),
                           _mm_packs_epi32(_mm_cmpgt_epi32(p[2], c), _mm_cmpgt_epi32(p[3], c)));
}

/* One pixel row of a MASK edge (less than 1 px of movement over the row; N = 16, 32),
 * all its samples at once and without a branch.  (*px, *pe) is the DDA state
 * at the row's first sample row (extrapolated in the edge's first row); the
 * edge plots samples s0..s1.  Sample s's x is X_s = x + floor((e + s*step) /
 * dY), step = h*dX, and its cell q_s = floor((X_s + off_s) / 256) lies in
 * [B, B + 2], B = floor(x / 256) - (dX < 0) clamped to [0, W - 2] (X_s stays
 * within 255 of x, on the side dX points to).  Since dY > 0 and the right
 * side is a multiple of dY:
 *     q_s >= B + j  <=>  X_s + off_s >= 256(B + j)
 *                   <=>  P_s = s*step + dY*off_s >= dY*(256(B + j) - x) - e = T_j,
 * so two compares per sample (j = 1, 2) give each sample's cell.  |P_s| <=
 * (N-1)|step| + 255 dY < 510 dY and |T_j| < 768 dY: with dY < 2^21 all fit
 * 32 bits.  P_s is two 16-bit multiply-adds of the pairs (s, off_s) with
 * (step, dY) split at bit 15 (pmaddwd).  The compares become byte masks per
 * sample, which the non-zero buffer adds (d8 in the masked bytes; paddb is
 * the byte add modulo 256 of the sample loop) and the even-odd one XORs as
 * bits.  The state then takes the row's whole DDA step, (qn, rn) (a MASK
 * edge's (qs, rs), ef_dda_start). */
static EF_ALWAYS_INLINE void plot_mask_row(ef_ctx *ctx, int32_t *px, int32_t *pe, int32_t dx, int32_t dy, int32_t qn,
                                           int32_t rn, int32_t dir, int s0, int s1, int32_t *lo, int32_t *hi,
                                           const int NS, const int NZ)
{
    int32_t x = *px, e = *pe;
    const int32_t step = dx * (EF_DEV_ONE / NS);
    const int32_t B = ef_clamp_i32(ef_asr_i32(x, EF_DEV_FRAC_BITS) - (dx < 0), 0, ctx->width - 2);
    const int32_t t1 = dy * (EF_DEV_ONE * (B + 1) - x) - e;   /* 256(B+1) - x in [-510, 511] */
    const __m128i bl = _mm_set1_epi32((int32_t)((uint32_t)(dy & 0x7FFF) << 16 | ((uint32_t)step & 0x7FFFu)));
    const __m128i bh = _mm_set1_epi32(
        (int32_t)((uint32_t)(dy >> 15) << 16 | ((uint32_t)ef_asr_i32(step, 15) & 0xFFFFu)));
    const __m128i c1 = _mm_set1_epi32(t1 - 1), c2 = _mm_set1_epi32(t1 - 1 + EF_DEV_ONE * dy);
    const __m128i *pairs = (const __m128i *)ctx->mask_pairs;
    *lo = B < *lo ? B : *lo;
    *hi = B + 2 > *hi ? B + 2 : *hi;
    /* the samples s0..s1 as bits; m1, m2: the samples that reach B + 1, B + 2 */
    const uint32_t r = (~UINT32_C(0) << s0) & (~UINT32_C(0) >> (31 - s1));
    uint32_t m1 = 0, m2 = 0;
    /* groups of 16 samples; the bytes of samples s0..s1 hold d8 */
    const uint8_t *from = mask_from[dir < 0] + 32 - s0, *to = mask_to + 31 - s1;
    uint8_t *cell = (uint8_t *)ctx->nz_cells + (size_t)B * (size_t)NS;
#pragma GCC unroll 2
    for (int k = 0; k < NS / 16; k++) {
        const __m128i p[4] = { mask_p4(pairs, 4 * k, bl, bh), mask_p4(pairs, 4 * k + 1, bl, bh),
                               mask_p4(pairs, 4 * k + 2, bl, bh), mask_p4(pairs, 4 * k + 3, bl, bh) };
        const __m128i G1 = mask_ge16(p, c1), G2 = mask_ge16(p, c2);
        if (NZ) {
            const __m128i rd = _mm_and_si128(_mm_loadu_si128((const __m128i *)(from + 16 * k)),
                                             _mm_loadu_si128((const __m128i *)(to + 16 * k)));
            __m128i *v0 = (__m128i *)(cell + 16 * k), *v1 = (__m128i *)(cell + NS + 16 * k),
                    *v2 = (__m128i *)(cell + 2 * NS + 16 * k);
            _mm_storeu_si128(v0, _mm_add_epi8(_mm_loadu_si128(v0), _mm_andnot_si128(G1, rd)));
            _mm_storeu_si128(v1, _mm_add_epi8(_mm_loadu_si128(v1), _mm_andnot_si128(G2, _mm_and_si128(G1, rd))));
            _mm_storeu_si128(v2, _mm_add_epi8(_mm_loadu_si128(v2), _mm_and_si128(G2, rd)));
        }
        m1 |= (uint32_t)_mm_movemask_epi8(G1) << (16 * k);
        m2 |= (uint32_t)_mm_movemask_epi8(G2) << (16 * k);
    }
    /* the samples of each cell; even-odd: the cells' XORs */
    const uint32_t in0 = r & ~m1, in1 = r & m1 & ~m2, in2 = r & m2;
    if (!NZ) {
        uint32_t *eo = ctx->eo_cells + B;
        eo[0] ^= in0;
        eo[1] ^= in1;
        eo[2] ^= in2;
    }
    /* occupancy of the cells marked (the word after the last one exists and
     * only ever takes zeros: B + 2 <= W) */
    const uint64_t marked = (uint64_t)(in0 != 0) | (uint64_t)(in1 != 0) << 1 | (uint64_t)(in2 != 0) << 2;
    uint64_t *occ = ctx->occ;
    const uint32_t ow = (uint32_t)B >> 6, osh = (uint32_t)B & 63;
    occ[ow] |= marked << osh;
    occ[ow + 1] |= (marked >> 1) >> (63 - osh);
    /* the DDA step over the whole row */
    const int32_t rsd = rn - dy, qs1 = qn + 1;
    DDA_STEP();
    *px = x;
    *pe = e;
}
#endif

/* Plots sample rows s0..s1 (of this pixel row) of one edge, stepping its DDA
 * (*px, *pe).  Edge tracking: a CLAMP edge widens the cell range [*lo, *hi]
 * exactly; the others widen the range [*lox, *hix] of x values, which the
 * caller turns into cells with a margin of 6 and 7: a STEEP edge's cells lie
 * within that margin of its first x (it moves less than 6 px over the row),
 * an INSIDE edge's within 1 of its first and last plotted x. */
static EF_ALWAYS_INLINE void plot_edge_row(ef_ctx *ctx, const int32_t *off, int32_t *px, int32_t *pe, int32_t qs,
                                           int32_t rs, int32_t dx, int32_t dy, int s0, int s1, int32_t dir, int32_t mode,
                                           int32_t *lo, int32_t *hi, int32_t *lox, int32_t *hix,
                                           uint64_t *overflows, const int NS, const int NZ, const int check,
                                           const int first)
{
#if EF_MASK_ROWS
    if (MASK_ROWS(NS, check) && mode == EF_PLOT_MASK) {
        plot_mask_row(ctx, px, pe, dx, dy, qs, rs, dir, s0, s1, lo, hi, NS, NZ);
        return;
    }
#else
    (void)dx;
#endif
    uint32_t *eo = ctx->eo_cells;
    uint8_t *nzb = (uint8_t *)ctx->nz_cells;
    uint64_t *occ = ctx->occ;
    const uint8_t d8 = (uint8_t)dir;                       /* +1 or -1 modulo 256 */
    const unsigned limit = dir > 0 ? 0x3Fu : 0x40u;
    (void)d8;
    (void)limit;
    (void)overflows;
    int32_t x = *px, e = *pe;
    const int32_t xa = x;
    const int32_t rsd = rs - dy, qs1 = qs + 1;
    if (EF_FAST_PATH && mode >= EF_PLOT_STEEP) {   /* MASK edges too, on rows that count overflows */
        /* x in [0, 256W - 1]: q = (x + off) >> 8 in [0, W], no clamp.  For
         * N >= 16 (more samples a row) the occupancy range is marked once;
         * for N = 8 a bit per sample costs less (measured). */
        *lox = xa < *lox ? xa : *lox;
        *hix = xa > *hix ? xa : *hix;
        if (NS >= 16) {
            ROW_SAMPLES(PLOT_CELL_NOOCC);
            const uint32_t a = (uint32_t)(xa < x ? xa : x) >> EF_DEV_FRAC_BITS;
            const uint32_t b = ((uint32_t)(xa < x ? x : xa) >> EF_DEV_FRAC_BITS) + 1;   /* <= W */
            mark_occ_range(occ, a, b);
        } else {
            ROW_SAMPLES(PLOT_CELL);
        }
        DDA_STEP();
    } else if (EF_FAST_PATH && mode == EF_PLOT_INSIDE) {
        ROW_SAMPLES(PLOT_CELL);
        /* the first and last plotted x, both in [0, 256W - 1] */
        const int32_t a = xa < x ? xa : x, b = xa < x ? x : xa;
        *lox = a < *lox ? a : *lox;
        *hix = b > *hix ? b : *hix;
        DDA_STEP();
    } else {
        const int32_t W = ctx->width;
        int32_t xl = x;
        uint64_t bit = UINT64_C(1) << s0;
        for (int s = s0; s <= s1; s++) {
            const int32_t q = ef_clamp_i32(ef_asr_i32(x + off[s], EF_DEV_FRAC_BITS), 0, W);
            PLOT_CELL(q, s);
            bit <<= 1;
            xl = x;
            DDA_STEP();
        }
        track(ctx, xa, xl, lo, hi);
    }
    *px = x;
    *pe = e;
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

/* Plots pixel row `row`.  check: count winding overflows (spec 6.4) per
 * sample.  crowd: instead, save the AET's state first (ctx->aet_saved) and
 * count per cell how many edges may plot there (ctx->crowd), so that
 * ef_plot_nonzero can tell whether the row needs the check at all. */
static EF_ALWAYS_INLINE void plot_row(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax,
                                      const int NS, const int NZ, const int check, const int crowd)
{
    const int32_t base = row * NS;
    const int32_t end = base + NS - 1;
    ef_edge *edges = ctx->edges;
    int32_t *aet = ctx->aet;
    const uint32_t naet = ctx->naet;
    int32_t off[EF_SAMPLES_MAX];
    load_offsets(ctx, off, NS);
    int32_t lo = *xmin, hi = *xmax, lox = INT32_MAX, hix = -1;
    uint64_t overflows = 0;
    uint32_t kept = 0;
    int32_t *const crowd_d = ctx->crowd;
    ef_aet_saved *const saved = ctx->aet_saved;
    const int32_t W = ctx->width;
    int32_t crowd_lo = W + 1, crowd_hi = 0;
    /* Edges active from earlier rows: they start this row at its first
     * sample row. */
    for (uint32_t k = 0; k < naet; k++) {
        const int32_t idx = aet[k];
        ef_edge *E = &edges[idx];
        int32_t x = E->x, e = E->e;
        const int32_t r1 = E->r1;
        const int s1 = (r1 < end ? r1 : end) - base;
        if (crowd)
            saved[k] = (ef_aet_saved){ idx, x, e };
        plot_edge_row(ctx, off, &x, &e, E->qs, E->rs, E->dx, E->dy, 0, s1, E->dir, E->mode, &lo, &hi, &lox, &hix,
                      &overflows, NS, NZ, check, 0);
        if (crowd)
            crowd_add(crowd_d, W, E->x, x, &crowd_lo, &crowd_hi);   /* x is monotonic: first plot to past the last */
        /* Still active below this row: stays, in AET order.  Branch-free:
         * whether an edge ends here is data, and would mispredict. */
        E->x = x;
        E->e = e;
        aet[kept] = idx;
        kept += r1 > end;
    }
    /* This row's new edges, in input order: their DDA starts here. */
    const int32_t h = ctx->h, c = ctx->c, w256 = ctx->width * EF_DEV_ONE;
    for (int32_t idx = head; idx >= 0;) {
        ef_edge *E = &edges[idx];
        ef_dda_start(E, h, c, w256, NS - 1, MASK_ROWS(NS, check));
        int32_t x = E->x, e = E->e;
        const int32_t r1 = E->r1;
        const int s1 = (r1 < end ? r1 : end) - base;
        plot_edge_row(ctx, off, &x, &e, E->qs, E->rs, E->dx, E->dy, E->r0 - base, s1, E->dir, E->mode, &lo, &hi,
                      &lox, &hix, &overflows, NS, NZ, check, 1);
        if (crowd)
            crowd_add(crowd_d, W, E->x, x, &crowd_lo, &crowd_hi);
        E->x = x;
        E->e = e;
        aet[kept] = idx;
        kept += r1 > end;
        idx = E->next;
    }
    ctx->naet = kept;
    if (crowd) {
        ctx->crowd_lo = crowd_lo;
        ctx->crowd_hi = crowd_hi;
    }
    if (NZ)
        ctx->diag.winding_overflows += overflows;
    if (hix >= 0) {
        /* STEEP and INSIDE edges: x in [0, 256W - 1], cells within
         * [x/256 - 6, x/256 + 7] of the x's tracked (clamped to [0, W]). */
        const int32_t a = (int32_t)((uint32_t)lox >> EF_DEV_FRAC_BITS) - 6;
        const int32_t b = (int32_t)((uint32_t)hix >> EF_DEV_FRAC_BITS) + 7;
        lo = a < lo ? (a < 0 ? 0 : a) : lo;
        hi = b > hi ? (b > ctx->width ? ctx->width : b) : hi;
    }
    *xmin = lo;
    *xmax = hi;
}

void ef_plot_evenodd(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax)
{
    switch (ctx->samples) {
    case 8: plot_row(ctx, row, head, xmin, xmax, 8, 0, 0, 0); break;
    case 16: plot_row(ctx, row, head, xmin, xmax, 16, 0, 0, 0); break;
    default: plot_row(ctx, row, head, xmin, xmax, 32, 0, 0, 0); break;
    }
}

/* The most edges that may plot into one cell of the crowded row just
 * plotted; leaves ctx->crowd zero. */
static int32_t crowd_most(ef_ctx *ctx)
{
    int32_t run = 0, most = 0;
    for (int32_t k = ctx->crowd_lo; k <= ctx->crowd_hi; k++) {
        run += ctx->crowd[k];
        ctx->crowd[k] = 0;
        most = run > most ? run : most;
    }
    return most;
}

/* Undoes a crowded row's plot: the AET and its edges' DDA state as they
 * were (new edges restart from their setup), and the cells and occupancy
 * bits it marked, all within [xmin, xmax] (spec 7.1; none if xmax < 0),
 * zero again. */
static void crowd_undo(ef_ctx *ctx, uint32_t naet, int32_t xmin, int32_t xmax)
{
    for (uint32_t k = 0; k < naet; k++) {
        const ef_aet_saved sv = ctx->aet_saved[k];
        ctx->aet[k] = sv.idx;
        ctx->edges[sv.idx].x = sv.x;
        ctx->edges[sv.idx].e = sv.e;
    }
    ctx->naet = naet;
    if (xmax < 0)
        return;
    const size_t words = (size_t)ctx->samples / 8;
    memset(&ctx->nz_cells[(size_t)xmin * words], 0, (size_t)(xmax - xmin + 1) * words * sizeof *ctx->nz_cells);
    memset(&ctx->occ[xmin >> 6], 0, (size_t)((xmax >> 6) - (xmin >> 6) + 1) * sizeof *ctx->occ);
}

/* Before a row plotted with the overflow count (sample by sample, in AET
 * order): the AET's MASK edges become STEEP ones (new edges start as such on
 * those rows, MASK_ROWS). */
static void mask_demote_aet(ef_ctx *ctx)
{
    for (uint32_t k = 0; k < ctx->naet; k++) {
        ef_edge *E = &ctx->edges[ctx->aet[k]];
        if (E->mode == EF_PLOT_MASK)
            ef_mask_demote(E, ctx->h);
    }
}

#define PLOT_NZ(check, crowd)                                                              \
    do {                                                                                   \
        switch (ctx->samples) {                                                            \
        case 8: plot_row(ctx, row, head, xmin, xmax, 8, 1, check, 0); break;               \
        case 16: plot_row(ctx, row, head, xmin, xmax, 16, 1, check, crowd); break;         \
        default: plot_row(ctx, row, head, xmin, xmax, 32, 1, check, crowd); break;         \
        }                                                                                  \
    } while (0)

/* The winding-overflow count (spec 6.4) needs a test per sample, but only
 * where a counter can leave [-64, 63]: it takes one plot per edge crossing
 * its sample row in its cell, so it needs 64 such edges.  Rows with fewer
 * active edges are plotted without the test.  At N = 16 and 32 a crowded
 * row (64 or more) is plotted without it too, counting per cell the edges
 * that may plot there (crowd_add); only if a cell has 64 is the plot undone
 * and redone with the test, so the count is the same.  Text set as one
 * compound path has rows of hundreds of edges and at most about ten in a
 * cell: 32x takes 10% fewer instructions on such a scene, 16x 4%.  At
 * N = 8 (about 4 samples an edge-row) the count costs more than the test
 * it saves, and crowded rows take the test; so do the test builds' mutants,
 * whose offsets may leave [1, 255]. */
void ef_plot_nonzero(ef_ctx *ctx, int32_t row, int32_t head, int32_t *xmin, int32_t *xmax)
{
    if (ctx->naet_row < 64) {
        PLOT_NZ(0, 0);
        return;
    }
    if (ctx->samples == 8 || !EF_FAST_PATH) {
        PLOT_NZ(1, 0);
        return;
    }
    const int32_t xmin0 = *xmin, xmax0 = *xmax;
    const uint32_t naet = ctx->naet;
    PLOT_NZ(0, 1);
    if (crowd_most(ctx) < 64)
        return;
    crowd_undo(ctx, naet, *xmin, *xmax);
    *xmin = xmin0;
    *xmax = xmax0;
    if (EF_MASK_ROWS)
        mask_demote_aet(ctx);
    PLOT_NZ(1, 0);
}
