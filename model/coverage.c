/*
 * coverage.c - coverage block (docs/spec.md section 7.3): the number of
 * covered samples to an 8-bit alpha, rounded to nearest with ties up:
 *   alpha = floor((255 * popcount(mask) + N/2) / N).
 */
#include "internal.h"

uint8_t ef_coverage_alpha(uint32_t mask, int samples)
{
    uint32_t n = (uint32_t)samples;
    return (uint8_t)((255u * ef_popcount32(mask) + n / 2u) / n);
}
