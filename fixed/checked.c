/*
 * checked.c - int64 addition and multiplication that report overflow.
 *
 * Used where an input file can push a value past its width (scene parsing,
 * transform composition): the caller turns `false` into a range error instead
 * of letting signed overflow (undefined in C) happen.  *out is written only on
 * success.
 */
#include "fixed_internal.h"

bool ef_add_i64_checked(int64_t a, int64_t b, int64_t *out)
{
    /* Overflow happens only when both operands have the same sign and the
     * true sum passes the limit on that side; test before adding. */
    if (b > 0 ? a > INT64_MAX - b : a < INT64_MIN - b)
        return false;
    *out = a + b;
    return true;
}

bool ef_mul_i64_checked(int64_t a, int64_t b, int64_t *out)
{
    /* The exact product fits int64 iff the high word of the 128-bit product
     * is the sign extension of the low word. */
    ef_i128 p = ef_mul_i64_wide(a, b);
    bool fits = (p.hi == 0 && p.lo <= (uint64_t)INT64_MAX) || (p.hi == -1 && p.lo > (uint64_t)INT64_MAX);
    if (!fits)
        return false;
    *out = ef_wrap_i64(p.lo);
    return true;
}
