/*
 * fixed_internal.h - helpers shared by the fixed/ sources, not part of the API.
 *
 * Everything here is static inline so that no symbol leaks out of the library.
 * The 128-bit helpers exist because the model must not use __int128: a -m32
 * build and a compiler without that extension must produce the same bits.
 */
#ifndef EF_FIXED_INTERNAL_H
#define EF_FIXED_INTERNAL_H

#include "ef_fixed.h"

/* Unsigned 128-bit value hi:lo, used for magnitudes of wide products. */
typedef struct ef_u128 {
    uint64_t hi, lo;
} ef_u128;

/* uint64 -> int64 modulo 2^64 is ef_wrap_i64 and |v| is ef_abs_u64 (ef_fixed.h). */

/* Number of leading zero bits of a non-zero uint64 (0..63).  A portable
 * binary search: no compiler builtin, so every toolchain agrees. */
static inline unsigned ef_clz_u64(uint64_t v)
{
    unsigned n = 0;
    if ((v >> 32) == 0) {
        n += 32;
        v <<= 32;
    }
    if ((v >> 48) == 0) {
        n += 16;
        v <<= 16;
    }
    if ((v >> 56) == 0) {
        n += 8;
        v <<= 8;
    }
    if ((v >> 60) == 0) {
        n += 4;
        v <<= 4;
    }
    if ((v >> 62) == 0) {
        n += 2;
        v <<= 2;
    }
    if ((v >> 63) == 0) {
        n += 1;
    }
    return n;
}

/* Full unsigned 64 x 64 -> 128 product (defined in wide.c). */
ef_u128 ef_mul_u64_wide(uint64_t a, uint64_t b);

/* Unsigned 128 / 64 division: q = floor(n / d), *rem = n mod d.
 * Precondition d != 0 and n.hi < d (so that q fits in 64 bits); callers
 * test n.hi >= d first and treat it as overflow.  Defined in wide.c. */
uint64_t ef_div_u128_u64(ef_u128 n, uint64_t d, uint64_t *rem);

#endif /* EF_FIXED_INTERNAL_H */
