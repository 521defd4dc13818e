/*
 * coverage.c - coverage block (docs/spec.md section 7.3): the number of
 * covered samples to an 8-bit alpha, rounded to nearest with ties up:
 *   alpha = floor((255 * popcount(mask) + N/2) / N).
 * The tables below are that formula evaluated by the compiler (constant
 * expressions), so the compositor looks alpha up instead of dividing, by
 * sample count; for N = 8 the count of each mask is a table too.
 */
#include "internal.h"

#define ALPHA(c, n) (uint8_t)((255u * (unsigned)(c) + (unsigned)(n) / 2u) / (unsigned)(n))

/* popcount of every 8-bit mask, built up two bits at a time */
#define P2(c) (c), (c) + 1, (c) + 1, (c) + 2
#define P4(c) P2(c), P2((c) + 1), P2((c) + 1), P2((c) + 2)
#define P6(c) P4(c), P4((c) + 1), P4((c) + 1), P4((c) + 2)
static const uint8_t count_mask8[256] = { P6(0), P6(1), P6(1), P6(2) };

#define C8(n, b) \
    ALPHA(b, n), ALPHA((b) + 1, n), ALPHA((b) + 2, n), ALPHA((b) + 3, n), ALPHA((b) + 4, n), ALPHA((b) + 5, n), \
        ALPHA((b) + 6, n), ALPHA((b) + 7, n)
static const uint8_t alpha_count8[9] = { C8(8, 0), ALPHA(8, 8) };
static const uint8_t alpha_count16[17] = { C8(16, 0), C8(16, 8), ALPHA(16, 16) };
static const uint8_t alpha_count32[33] = { C8(32, 0), C8(32, 8), C8(32, 16), C8(32, 24), ALPHA(32, 32) };

const uint8_t *ef_count_of_mask8(void) { return count_mask8; }

const uint8_t *ef_alpha_of_count(int samples)
{
    return samples == 8 ? alpha_count8 : samples == 16 ? alpha_count16 : alpha_count32;
}

uint8_t ef_coverage_alpha(ef_mask mask, int samples)
{
    uint32_t n = (uint32_t)samples;
    return (uint8_t)((255u * ef_popcount32(mask) + n / 2u) / n);
}
