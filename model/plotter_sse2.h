/*
 * plotter_sse2.h - a speed device of the plotter (included by plotter_fast.h
 * when EF_MASK_ROWS): a MASK edge's whole pixel row at once, from two exact
 * compares per sample (docs/spec.md 6.1, "A whole pixel row at once"), SSE2
 * over the row's samples, without a loop or a data-dependent branch.  Same
 * marks as the sample loop of plotter.c; N = 16 and 32 only (MASK_ROWS).
 * Uses plotter.c's DDA_STEP.
 */
#ifndef EF_PLOTTER_SSE2_H
#define EF_PLOTTER_SSE2_H

#include <emmintrin.h>

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
    const __m128i a = _mm_load_si128(&pairs[j]); /* ctx (calloc) and the array are 16-byte aligned */
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
    const int32_t t1 = dy * (EF_DEV_ONE * (B + 1) - x) - e; /* 256(B+1) - x in [-510, 511] */
    const __m128i bl = _mm_set1_epi32((int32_t)((uint32_t)(dy & 0x7FFF) << 16 | ((uint32_t)step & 0x7FFFu)));
    const __m128i bh =
        _mm_set1_epi32((int32_t)((uint32_t)(dy >> 15) << 16 | ((uint32_t)ef_asr_i32(step, 15) & 0xFFFFu)));
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
