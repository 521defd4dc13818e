/*
 * wide.c - 64 x 64 -> 128-bit products, 128 / 64 division, and the Q31.32
 * multiply / divide and a*b/c built on them.
 *
 * Place in the pipeline: the front end (transforms, arc set-up) multiplies and
 * divides Q31.32 numbers; the exact product of two int64 needs 127 bits.  We
 * build the 128-bit product from four 32 x 32 -> 64 partial products (no
 * __int128, so -m32 builds and every compiler agree bit for bit) and divide
 * with Knuth's algorithm D specialised to a two-digit (2 x 32-bit) divisor.
 *
 * Rounding contracts (docs/fixed.md, docs/spec.md 2.1):
 *   ef_q32_mul     floor(a*b / 2^32 + 1/2)               ties toward +inf
 *   ef_q32_div     sign * floor(|a| * 2^32 / |b| + 1/2)  ties away from zero
 *   ef_muldiv_i64  sign * floor(|a*b| / |c| + 1/2)       ties away from zero
 * Each reports overflow (result outside int64) by returning false and leaving
 * *out untouched.
 */
#include "fixed_internal.h"

#define LO32 UINT64_C(0xFFFFFFFF)

ef_u128 ef_mul_u64_wide(uint64_t a, uint64_t b)
{
    uint64_t a0 = a & LO32, a1 = a >> 32;
    uint64_t b0 = b & LO32, b1 = b >> 32;
    /* Each partial product is < 2^64. */
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    /* Column 32..63 plus carries: three terms each < 2^32, so < 3 * 2^32. */
    uint64_t mid = (p00 >> 32) + (p01 & LO32) + (p10 & LO32);
    ef_u128 r;
    r.lo = (mid << 32) | (p00 & LO32);
    /* Cannot wrap: the full product is < 2^128. */
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

ef_i128 ef_mul_i64_wide(int64_t a, int64_t b)
{
    /* Read a and b as unsigned bit patterns ua = a + 2^64 [a<0] etc.; then
     * a*b = ua*ub - 2^64 ([a<0] ub + [b<0] ua)  (mod 2^128), so only the high
     * word needs correcting, modulo 2^64. */
    uint64_t ua = (uint64_t)a, ub = (uint64_t)b;
    ef_u128 p = ef_mul_u64_wide(ua, ub);
    uint64_t hi = p.hi;
    if (a < 0)
        hi -= ub;
    if (b < 0)
        hi -= ua;
    ef_i128 r;
    r.hi = ef_wrap_i64(hi);
    r.lo = p.lo;
    return r;
}

uint64_t ef_div_u128_u64(ef_u128 n, uint64_t d, uint64_t *rem)
{
    /* Knuth, TAOCP vol. 2, 4.3.1 algorithm D with base 2^32: a 4-digit
     * dividend over a 2-digit divisor gives 2 quotient digits.  The divisor is
     * normalised (top bit set) so each trial digit is at most 2 too large; the
     * refined test against the second divisor digit makes it exact because
     * the divisor has only two digits. */
    const uint64_t base = (uint64_t)1 << 32;
    unsigned s = ef_clz_u64(d);
    uint64_t v = d << s;
    uint64_t v1 = v >> 32, v0 = v & LO32;
    /* n << s; its top 64 bits stay < v because n.hi < d. */
    uint64_t u32 = s ? (n.hi << s) | (n.lo >> (64 - s)) : n.hi;
    uint64_t u10 = n.lo << s;
    uint64_t u1 = u10 >> 32, u0 = u10 & LO32;

    uint64_t q1 = u32 / v1, rh = u32 % v1;
    /* q1 * v0 is evaluated only when q1 < base, and rh << 32 only when
     * rh < base: neither product can wrap. */
    while (q1 >= base || q1 * v0 > ((rh << 32) | u1)) {
        q1--;
        rh += v1;
        if (rh >= base)
            break;
    }
    /* Partial remainder (u32:u1) - q1*v is < v < 2^64, so computing it
     * modulo 2^64 gives it exactly. */
    uint64_t u21 = ((u32 << 32) | u1) - q1 * v;

    uint64_t q0 = u21 / v1;
    rh = u21 % v1;
    while (q0 >= base || q0 * v0 > ((rh << 32) | u0)) {
        q0--;
        rh += v1;
        if (rh >= base)
            break;
    }
    uint64_t r = ((u21 << 32) | u0) - q0 * v;
    *rem = r >> s;
    return (q1 << 32) | q0;
}

/* sign * round_half_away(n / d) into *out, or false if it does not fit int64.
 * The tie rule is applied to the magnitude, which makes it symmetric. */
static bool round_div_signed(ef_u128 n, uint64_t d, bool negative, int64_t *out)
{
    if (n.hi >= d)
        return false; /* quotient >= 2^64 */
    uint64_t r;
    uint64_t q = ef_div_u128_u64(n, d, &r);
    bool up = r >= d - r; /* 2r >= d without overflow */
    uint64_t limit = negative ? (uint64_t)1 << 63 : ((uint64_t)1 << 63) - 1u;
    if (q > limit || (up && q == limit))
        return false;
    q += up ? 1u : 0u;
    *out = negative ? ef_wrap_i64((uint64_t)0 - q) : (int64_t)q;
    return true;
}

bool ef_q32_mul(ef_q32 a, ef_q32 b, ef_q32 *out)
{
    /* p = a*b exactly, |p| <= 2^126.  floor(p / 2^32 + 1/2) is
     * floor((p + 2^31) / 2^32): add 2^31 into the 128-bit value, then take
     * bits 32..95.  hi + carry cannot overflow since |hi| <= 2^62. */
    ef_i128 p = ef_mul_i64_wide(a.v, b.v);
    uint64_t lo = p.lo + ((uint64_t)1 << 31);
    int64_t hi = p.hi + (lo < p.lo ? 1 : 0);
    /* The result hi * 2^32 + (lo >> 32) fits int64 iff -2^31 <= hi < 2^31. */
    if (hi < -((int64_t)1 << 31) || hi >= ((int64_t)1 << 31))
        return false;
    out->v = ef_wrap_i64(((uint64_t)hi << 32) | (lo >> 32));
    return true;
}

bool ef_q32_div(ef_q32 a, ef_q32 b, ef_q32 *out)
{
    if (b.v == 0)
        return false; /* caller's duty; fail safe */
    uint64_t ua = ef_abs_u64(a.v), ub = ef_abs_u64(b.v);
    ef_u128 n; /* |a| * 2^32 < 2^96 */
    n.hi = ua >> 32;
    n.lo = ua << 32;
    int64_t q;
    if (!round_div_signed(n, ub, (a.v < 0) != (b.v < 0), &q))
        return false;
    out->v = q;
    return true;
}

bool ef_muldiv_i64(int64_t a, int64_t b, int64_t c, int64_t *out)
{
    if (c == 0)
        return false; /* caller's duty; fail safe */
    ef_u128 n = ef_mul_u64_wide(ef_abs_u64(a), ef_abs_u64(b));
    bool negative = ((a < 0) != (b < 0)) != (c < 0);
    if (n.hi == 0 && n.lo == 0)
        negative = false; /* 0, never "-0" */
    return round_div_signed(n, ef_abs_u64(c), negative, out);
}
