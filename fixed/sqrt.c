/*
 * sqrt.c - exact integer square roots.
 *
 * Place in the pipeline: arc set-up (radius correction, centre distance) and
 * vector lengths in the front end.  Both functions return the floor of the
 * exact root, computed with the restoring digit-by-digit method (two radicand
 * bits per result bit), which maps one-for-one onto a shift/subtract RTL loop.
 */
#include "fixed_internal.h"

#define ISQRT_MAX_ZERO_PAIRS 16u /* Q32 root: a * 2^32 = a * 4^16 */
/* root < 2^(32 + zero_pairs), rem <= 2 * root < 2^(33 + zero_pairs), so
 * (rem << 2) | 3 < 2^(35 + zero_pairs) and 4 * root + 1 < 2^(34 + zero_pairs). */
_Static_assert(35u + ISQRT_MAX_ZERO_PAIRS <= 64u, "isqrt_pairs remainder fits uint64");

/* floor(sqrt(a * 4^zero_pairs)) for a < 2^64, 0 <= zero_pairs <= 16.
 *
 * The radicand is consumed two bits at a time from the top: 32 pairs of a,
 * then zero_pairs pairs of zeros.  Invariant after each step: root = floor of
 * the root of the radicand consumed so far, rem = consumed - root^2, and
 * 0 <= rem <= 2 * root.  Bit budget: root < 2^(32 + zero_pairs) <= 2^48, so
 * rem <= 2^49 and (rem << 2) | pair < 2^51: everything fits uint64. */
static uint64_t isqrt_pairs(uint64_t a, unsigned zero_pairs)
{
    uint64_t root = 0, rem = 0;
    unsigned total = 32u + zero_pairs;
    for (unsigned k = total; k-- > 0;) {
        /* Pair k of the radicand a * 4^zero_pairs. */
        uint64_t pair = k >= zero_pairs ? (a >> (2u * (k - zero_pairs))) & 3u : 0u;
        rem = (rem << 2) | pair;
        uint64_t trial = (root << 2) | 1u; /* (2*root + 1) with root doubled */
        root <<= 1;
        if (rem >= trial) {
            rem -= trial;
            root |= 1u;
        }
    }
    return root;
}

uint32_t ef_isqrt_u64(uint64_t v) { return (uint32_t)isqrt_pairs(v, 0); /* root < 2^32 */ }

ef_q32 ef_q32_sqrt(ef_q32 a)
{
    /* sqrt(a / 2^32) * 2^32 = sqrt(a * 2^32): the Q32 root is the integer
     * root of a * 4^16, floored.  a < 2^63 gives a root < 2^47.5.
     * Negative input is outside the contract; it yields 0. */
    if (a.v <= 0)
        return ef_q32_raw(0);
    return ef_q32_raw((int64_t)isqrt_pairs((uint64_t)a.v, ISQRT_MAX_ZERO_PAIRS));
}
