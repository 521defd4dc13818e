/*
 * coverage.c - coverage block (docs/spec.md section 7.3): the number of
 * covered samples to an 8-bit alpha, rounded to nearest with ties up:
 *   alpha = floor((255 * popcount(mask) + N/2) / N).
 * The tables below are that formula evaluated by the compiler (constant
 * expressions), so the compositor looks alpha up instead of dividing: by
 * mask for N = 8 (256 entries), by sample count for every N.
 */
#include "internal.h"

#define ALPHA(c, n) (uint8_t)((255u * (unsigned)(c) + (unsigned)(n) / 2u) / (unsigned)(n))

/* alpha of every 8-bit mask: entry m is ALPHA(popcount(m), 8), the popcount
 * built up two bits at a time. */
#define A2(c) ALPHA(c, 8), ALPHA((c) + 1, 8), ALPHA((c) + 1, 8), ALPHA((c) + 2, 8)
#define A4(c) A2(c), A2((c) + 1), A2((c) + 1), A2((c) + 2)
#define A6(c) A4(c), A4((c) + 1), A4((c) + 1), A4((c) + 2)
static const uint8_t alpha_mask8[256] = { A6(0), A6(1), A6(1), A6(2) };

#define C8(n, b) ALPHA(b, n), ALPHA((b) + 1, n), ALPHA((b) + 2, n), ALPHA((b) + 3, n), \
                 ALPHA((b) + 4, n), ALPHA((b) + 5, n), ALPHA((b) + 6, n), ALPHA((b) + 7, n)
static const uint8_t alpha_count8[9] = { C8(8, 0), ALPHA(8, 8) };
static const uint8_t alpha_count16[17] = { C8(16, 0), C8(16, 8), ALPHA(16, 16) };
static const uint8_t alpha_count32[33] = { C8(32, 0), C8(32, 8), C8(32, 16), C8(32, 24), ALPHA(32, 32) };

const uint8_t *ef_alpha_of_mask8(void) { return alpha_mask8; }

const uint8_t *ef_alpha_of_count(int samples)
{
    return samples == 8 ? alpha_count8 : samples == 16 ? alpha_count16 : alpha_count32;
}

uint8_t ef_coverage_alpha(uint32_t mask, int samples)
{
    uint32_t n = (uint32_t)samples;
    return (uint8_t)((255u * ef_popcount32(mask) + n / 2u) / n);
}
