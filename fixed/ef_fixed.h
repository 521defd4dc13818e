/*
 * ef_fixed.h - the fixed-point library edgeflag stands on.
 *
 * Every operation here is a contract: its range, its rounding and what happens
 * past its width are stated beside it, and nothing relies on behaviour C leaves
 * to the implementation (right shift of a negative value, signed overflow,
 * division rounding of negative operands, the width of `long`).  The same
 * inputs give the same bits on every C11 compiler, at every optimisation level,
 * on 32- and 64-bit, little- and big-endian targets.
 *
 * Formats used across the project (docs/spec.md section 2 is normative):
 *   ef_q32   Q31.32 in int64_t: the front end (parsed numbers, transforms,
 *            arc geometry).  Range [-2^31, 2^31) with resolution 2^-32.
 *   ef_q16   Q47.16 in int64_t: device-space control points during flattening.
 *   device   Q16.8 in int32_t: vertex coordinates handed to the rasterizer
 *            (1/256 px units, |v| < 2^23).  See include/edgeflag/edgeflag.h.
 *   ef_angle an unsigned 32-bit binary angle: one full turn = 2^32, so angle
 *            arithmetic wraps modulo a turn by construction.
 *   ef_q30   Q1.30 in int32_t: sines, cosines and other values in [-1, 1].
 *
 * Wrapped in structs where they cross module boundaries (ef_q32), so that
 * native arithmetic on them does not compile; the hot model paths use plain
 * integers with the format written in the name of the field.
 */
#ifndef EF_FIXED_H
#define EF_FIXED_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

_Static_assert(sizeof(int32_t) == 4 && sizeof(int64_t) == 8, "exact-width integers");
_Static_assert((-1 & 3) == 3, "two's complement representation");

/* ---------------------------------------------------------------------------
 * Formats
 * ------------------------------------------------------------------------ */

/* Q31.32: value = v / 2^32. */
typedef struct ef_q32 {
    int64_t v;
} ef_q32;
#define EF_Q32_FRAC_BITS 32
#define EF_Q32_ONE ((int64_t)1 << EF_Q32_FRAC_BITS)

/* Binary angle: value = a / 2^32 turns. */
typedef uint32_t ef_angle;
#define EF_ANGLE_HALF_TURN ((ef_angle)0x80000000u)
#define EF_ANGLE_QUARTER_TURN ((ef_angle)0x40000000u)

/* Q1.30 in int32_t: value = v / 2^30, range [-2, 2). */
#define EF_Q30_ONE ((int32_t)1 << 30)

/* Device coordinates: Q16.8, value = v / 256 px. */
#define EF_DEV_FRAC_BITS 8
#define EF_DEV_ONE (1 << EF_DEV_FRAC_BITS)

static inline ef_q32 ef_q32_raw(int64_t v)
{
    ef_q32 r = { v };
    return r;
}
/* Exact: n * 2^32.  Range: |n| < 2^31 (caller's duty; debug-asserted in tests). */
static inline ef_q32 ef_q32_from_int(int32_t n) { return ef_q32_raw((int64_t)n * EF_Q32_ONE); }

/* ---------------------------------------------------------------------------
 * Shifts as named operations
 * ------------------------------------------------------------------------ */

/* Arithmetic shift right = floor(v / 2^n), for any sign, 0 <= n <= 31 (63).
 * Written without `>>` on a negative operand, whose result C11 leaves to the
 * implementation; compilers fold this to one sar instruction. */
static inline int32_t ef_asr_i32(int32_t v, unsigned n)
{
    return v >= 0 ? (int32_t)((uint32_t)v >> n) : (int32_t) ~((uint32_t)~v >> n);
}
static inline int64_t ef_asr_i64(int64_t v, unsigned n)
{
    return v >= 0 ? (int64_t)((uint64_t)v >> n) : (int64_t) ~((uint64_t)~v >> n);
}

/* Shift left = v * 2^n computed modulo 2^64 (wraps; never UB).  The caller
 * guarantees |v| * 2^n < 2^63 where the exact value matters. */
static inline int64_t ef_wrap_i64(uint64_t u)
{
    /* Modular unsigned -> signed without the implementation-defined cast of a
     * value above INT64_MAX; compilers turn it into a no-op.  The one such
     * conversion of the tree (the readers and fixed/ used copies of it). */
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : (int64_t)(u - (uint64_t)INT64_MAX - 1u) + INT64_MIN;
}
static inline int64_t ef_shl_i64(int64_t v, unsigned n) { return ef_wrap_i64((uint64_t)v << n); }
static inline int32_t ef_shl_i32(int32_t v, unsigned n)
{
    uint32_t u = (uint32_t)v << n;
    return u <= (uint32_t)INT32_MAX ? (int32_t)u : (int32_t)(u - (uint32_t)INT32_MAX - 1u) + INT32_MIN;
}

/* Round-to-nearest shift right: floor(v / 2^n + 1/2), i.e. ties toward +inf.
 * 1 <= n <= 62; exact for every int64 v (the bias is added in 128 bits worth of
 * reasoning: v + 2^(n-1) cannot overflow because it is done as floor + bit). */
static inline int64_t ef_round_shr_i64(int64_t v, unsigned n)
{
    int64_t q = ef_asr_i64(v, n);
    return q + (int64_t)(((uint64_t)v >> (n - 1)) & 1u);
}

/* ---------------------------------------------------------------------------
 * Division with defined rounding.  d > 0 in every function (caller's duty).
 * ------------------------------------------------------------------------ */

/* floor(a / d) and the remainder r = a - d * floor(a / d), 0 <= r < d.
 * This is the DDA's quotient/remainder pair (the remainder is the error term). */
static inline int64_t ef_floordiv_i64(int64_t a, int64_t d)
{
    int64_t q = a / d, r = a % d; /* C11: truncation toward zero */
    return (r < 0) ? q - 1 : q;
}
static inline int64_t ef_floormod_i64(int64_t a, int64_t d)
{
    int64_t r = a % d;
    return (r < 0) ? r + d : r;
}
static inline void ef_divmod_floor_i64(int64_t a, int64_t d, int64_t *q, int64_t *r)
{
    int64_t qq = a / d, rr = a % d;
    if (rr < 0) {
        qq -= 1;
        rr += d;
    }
    *q = qq;
    *r = rr;
}
/* ceil(a / d).  a != INT64_MIN. */
static inline int64_t ef_ceildiv_i64(int64_t a, int64_t d) { return -ef_floordiv_i64(-a, d); }

/* Round to nearest, ties away from zero: sign(a) * floor(|a| / d + 1/2).
 * |a| <= INT64_MAX - d/2 (caller's duty). */
static inline int64_t ef_rounddiv_i64(int64_t a, int64_t d) { return a >= 0 ? (a + d / 2) / d : -((-a + d / 2) / d); }

/* ---------------------------------------------------------------------------
 * Saturation and wrap, made explicit
 * ------------------------------------------------------------------------ */

static inline int32_t ef_clamp_i32(int32_t v, int32_t lo, int32_t hi) { return v < lo ? lo : v > hi ? hi : v; }
static inline int64_t ef_clamp_i64(int64_t v, int64_t lo, int64_t hi) { return v < lo ? lo : v > hi ? hi : v; }
/* Two's complement wrap to 32 bits (modular conversion, never UB). */
static inline int32_t ef_wrap_i32(int64_t v)
{
    uint32_t u = (uint32_t)(uint64_t)v;
    return u <= 0x7fffffffu ? (int32_t)u : (int32_t)(u - 0x80000000u) + INT32_MIN;
}
/* Wrap modulo 2^bits into [0, 2^bits): the packed winding counters' rule. */
static inline uint32_t ef_wrap_u(int64_t v, unsigned bits) { return (uint32_t)((uint64_t)v & ((1ull << bits) - 1u)); }
/* Checked add/sub/mul on int64: return false (and leave *out untouched) on overflow. */
bool ef_add_i64_checked(int64_t a, int64_t b, int64_t *out);
bool ef_mul_i64_checked(int64_t a, int64_t b, int64_t *out);

/* ---------------------------------------------------------------------------
 * Wide products (portable: no __int128, so -m32 and every compiler agree)
 * ------------------------------------------------------------------------ */

/* Signed 64 x 64 -> 128 product as hi:lo (two's complement). */
typedef struct ef_i128 {
    int64_t hi;
    uint64_t lo;
} ef_i128;
ef_i128 ef_mul_i64_wide(int64_t a, int64_t b);

/* Q32 multiply: round_nearest(a * b / 2^32), ties toward +inf.
 * Returns false on overflow of the Q31.32 range (out untouched). */
bool ef_q32_mul(ef_q32 a, ef_q32 b, ef_q32 *out);
/* Q32 divide: round_nearest(a * 2^32 / b), ties away from zero.  b != 0.
 * Returns false on overflow (out untouched). */
bool ef_q32_div(ef_q32 a, ef_q32 b, ef_q32 *out);
/* a * b / c with a 128-bit intermediate, rounded to nearest (ties away from
 * zero).  c != 0.  Returns false if the result does not fit int64. */
bool ef_muldiv_i64(int64_t a, int64_t b, int64_t c, int64_t *out);

/* ---------------------------------------------------------------------------
 * Roots and trigonometry (integer-only; bit-exact by construction)
 * ------------------------------------------------------------------------ */

/* floor(sqrt(v)) for every uint64_t v. */
uint32_t ef_isqrt_u64(uint64_t v);
/* Q32 square root: floor(sqrt(a / 2^32) * 2^32), i.e. the exact root truncated
 * to the 2^-32 grid.  a >= 0 (a negative argument gives 0). */
ef_q32 ef_q32_sqrt(ef_q32 a);
/* sin and cos of a binary angle in Q1.30, |error| < 1 * 2^-30 (CORDIC with a
 * fixed, documented iteration count: docs/fixed.md section 4). */
void ef_sincos(ef_angle a, int32_t *sin_q30, int32_t *cos_q30);
/* atan2(y, x) as a binary angle in [0, 2^32); atan2(0, 0) = 0.  Same CORDIC. */
ef_angle ef_atan2(int64_t y, int64_t x);
/* Degrees (Q32) to a binary angle: round_nearest(deg * 2^32 / 360) mod 2^32. */
ef_angle ef_angle_from_deg_q32(ef_q32 deg);

/* ---------------------------------------------------------------------------
 * Integer primitives shared by every layer (fixed/ is the bottom one)
 * ------------------------------------------------------------------------ */

/* Bits set in v (0..32).  SWAR, branch-free, the same on every target (no
 * dependence on a popcnt instruction). */
static inline unsigned ef_popcount32(uint32_t v)
{
    v = v - ((v >> 1) & 0x55555555u);
    v = (v & 0x33333333u) + ((v >> 2) & 0x33333333u);
    v = (v + (v >> 4)) & 0x0F0F0F0Fu;
    return (v * 0x01010101u) >> 24;
}

/* Floor division of int32: q = floor(a / d), r = a - q*d with 0 <= r < d.
 * d > 0; a any int32.  C's `/` truncates toward zero, so a negative remainder
 * moves q down one and r up by d, without a branch (the sign of a is data and
 * would mispredict in the DDA start of every edge, docs/spec.md 5 step 5). */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void
ef_divmod_floor_i32(int32_t a, int32_t d, int32_t *q, int32_t *r)
{
    const int32_t q0 = a / d, r0 = a % d, neg = -(int32_t)(r0 < 0);
    *q = q0 + neg;
    *r = r0 + (d & neg);
}

/* |v| as uint64; exact for every v including INT64_MIN (2^63). */
static inline uint64_t ef_abs_u64(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

/* The length (1..4) of the well-formed UTF-8 sequence at s[0..n) (RFC 3629:
 * shortest form, no surrogates, at most U+10FFFF; an ASCII byte, control
 * characters included, is 1), or 0 when s does not start one (or n is 0). */
size_t ef_utf8_len(const unsigned char *s, size_t n);

/* ---------------------------------------------------------------------------
 * Exact decimal text -> fixed point
 * ------------------------------------------------------------------------ */

/* Status of a number parse. */
typedef enum ef_num_status {
    EF_NUM_OK = 0,
    EF_NUM_SYNTAX, /* not a number at all: no digits where one was needed */
    EF_NUM_RANGE   /* a number, but its value does not fit Q31.32 */
} ef_num_status;

/* Parses the longest prefix of s[0..len) that is a decimal number:
 *   [+-]? ( digits ( '.' digits? )? | '.' digits ) ( [eE] [+-]? digits )?
 * (the SVG/CSS and peerbench scene grammar: no inf, nan, hex, locale forms;
 * an 'e' not followed by digits is not consumed).  The value is rounded ONCE,
 * exactly, to the nearest multiple of 2^-32, ties away from zero, however many
 * digits are given; so parse("-x") == -parse("x").  Any number of digits and
 * exponents up to +-100000 are accepted; values with |v| >= 2^31 give
 * EF_NUM_RANGE, values that round to zero give zero.
 * *consumed receives the prefix length (0 on EF_NUM_SYNTAX). */
ef_num_status ef_parse_decimal_q32(const char *s, size_t len, ef_q32 *out, size_t *consumed);

/* Writes the exact decimal value of a Q32 number (at most 32 fraction digits,
 * trailing zeros removed) into buf; returns the length.  buf >= 48 bytes. */
size_t ef_q32_format(ef_q32 v, char *buf);

#ifdef __cplusplus
}
#endif

#endif /* EF_FIXED_H */
