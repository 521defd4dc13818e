/*
 * test_fixed.c - unit tests for fixed/ (ef_fixed.h).
 *
 * Three kinds of checks, as in TestFloat: commented corner-case tables,
 * comparison against an independent slow model written here (256-bit
 * arithmetic on 16-bit limbs, bit-serial division), and seeded random cases
 * (xorshift64*, fixed seed TEST_SEED, so every run is the same).  Trigonometry
 * is compared with libm in long double; the tests may use floating point, the
 * library may not.
 *
 * Build:
 *   cc -std=c11 -Wall -Wextra -Werror -Ifixed -Imodel tests/unit/test_fixed.c \
 *      fixed/[a-z]*.c -lcmocka -lm -o /tmp/test_fixed
 * Without cmocka (e.g. -m32 where no i386 libcmocka is installed) add
 * -DEF_TEST_NO_CMOCKA and drop -lcmocka: a minimal stand-in below runs the
 * same tests.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>

#ifndef EF_TEST_NO_CMOCKA
#include <cmocka.h>
#else
/* The subset of cmocka used below, so the tests also run where the library
 * is not installed for the target (-m32). */
/* The shim keeps cmocka's one-line macros. */
/* clang-format off */
struct CMUnitTest { const char *name; void (*test_func)(void **state); };
#define cmocka_unit_test(f) { #f, f }
static const char *shim_test_name;
#define fail_msg(...) do { \
        fprintf(stderr, "[  FAILED  ] %s: ", shim_test_name); \
        fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); exit(1); } while (0)
#define assert_true(c) do { if (!(c)) fail_msg("%s:%d: assert_true(%s)", __FILE__, __LINE__, #c); } while (0)
#define assert_false(c) assert_true(!(c))
#define assert_int_equal(a, b) do { unsigned long long a_ = (unsigned long long)(a), b_ = (unsigned long long)(b); \
        if (a_ != b_) fail_msg("%s:%d: %llu != %llu", __FILE__, __LINE__, a_, b_); } while (0)
#define assert_string_equal(a, b) do { if (strcmp((a), (b)) != 0) \
        fail_msg("%s:%d: \"%s\" != \"%s\"", __FILE__, __LINE__, (a), (b)); } while (0)
/* clang-format on */
static int shim_run(const struct CMUnitTest *t, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        shim_test_name = t[i].name;
        t[i].test_func(NULL);
        printf("[       OK ] %s\n", t[i].name);
    }
    printf("[  PASSED  ] %zu test(s).\n", n);
    return 0;
}
#define cmocka_run_group_tests(t, setup, teardown) shim_run((t), sizeof(t) / sizeof((t)[0]))
#endif

#include "ef_fixed.h"
#include "fixed_internal.h" /* ef_div_u128_u64 is tested directly */

#define CHECK(cond, ...) \
    do { \
        if (!(cond)) \
            fail_msg(__VA_ARGS__); \
    } while (0)
#define LL(v) ((long long)(v))
#define ULL(v) ((unsigned long long)(v))

/* ------------------------------------------------------------------------
 * Random numbers: xorshift64*, documented default seed.
 * --------------------------------------------------------------------- */
#define TEST_SEED UINT64_C(0x9E3779B97F4A7C15)
static uint64_t rng_state = TEST_SEED;
static uint64_t rnd64(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * UINT64_C(0x2545F4914F6CDD1D);
}
/* Bit patterns of every size and sign: a random value shifted right by a
 * random amount, so small magnitudes are as likely as large ones. */
static int64_t rnd_i64(void)
{
    uint64_t u = rnd64() >> (rnd64() % 64);
    int64_t v = (int64_t)(u >> 1);
    return (rnd64() & 1) ? -v - (int64_t)(rnd64() & 1) : v;
}
static uint64_t rnd_u64(void) { return rnd64() >> (rnd64() % 64); }

/* clang-format off */
static const int64_t CORNERS[] = {
    0, 1, -1, 2, -2, 3, -3, 7, -7, 0x7FFFFFFF, -0x7FFFFFFF, (int64_t)0x80000000u, -(int64_t)0x80000000u,
    (int64_t)0xFFFFFFFFu, -(int64_t)0xFFFFFFFFu, INT64_C(0x100000000), -INT64_C(0x100000000),
    INT64_C(0x100000001), INT64_C(0x7FFFFFFFFFFFFFFF), INT64_C(0x7FFFFFFFFFFFFFFE),
    INT64_MIN, INT64_MIN + 1, INT64_C(0x4000000000000000), -INT64_C(0x4000000000000000),
    INT64_C(0x0000FFFFFFFFFFFF), INT64_C(0x123456789ABCDEF0), -INT64_C(0x0FEDCBA987654321),
};
/* clang-format on */
#define NCORNERS (sizeof CORNERS / sizeof CORNERS[0])

/* ------------------------------------------------------------------------
 * Slow model: unsigned 256-bit integers as 16 little-endian 16-bit limbs.
 * Written independently of fixed/wide.c (different limb size, bit-serial
 * division) so that a shared mistake is unlikely.
 * --------------------------------------------------------------------- */
#define BL 16
typedef struct big {
    uint16_t d[BL];
} big;

static big big_u64(uint64_t v)
{
    big r;
    memset(&r, 0, sizeof r);
    for (int i = 0; i < 4; i++)
        r.d[i] = (uint16_t)(v >> (16 * i));
    return r;
}
static uint64_t big_word(big a, int w) /* 64-bit word w (0 = lowest) */
{
    uint64_t v = 0;
    for (int i = 3; i >= 0; i--)
        v = (v << 16) | a.d[4 * w + i];
    return v;
}
static bool big_fits_u64(big a)
{
    for (int i = 4; i < BL; i++)
        if (a.d[i])
            return false;
    return true;
}
static bool big_is_zero(big a) { return big_fits_u64(a) && big_word(a, 0) == 0; }
static big big_mul(big a, big b)
{
    uint32_t acc[2 * BL];
    memset(acc, 0, sizeof acc);
    for (int i = 0; i < BL; i++)
        for (int j = 0; i + j < BL; j++) {
            uint32_t p = (uint32_t)a.d[i] * b.d[j];
            /* propagate into 16-bit columns held in 32-bit accumulators */
            int k = i + j;
            uint32_t carry = p;
            while (carry && k < BL) {
                uint32_t s = acc[k] + (carry & 0xFFFFu);
                acc[k] = s & 0xFFFFu;
                carry = (carry >> 16) + (s >> 16);
                k++;
            }
        }
    big r;
    for (int i = 0; i < BL; i++)
        r.d[i] = (uint16_t)acc[i];
    return r;
}
static big big_add(big a, big b)
{
    uint32_t c = 0;
    for (int i = 0; i < BL; i++) {
        uint32_t s = (uint32_t)a.d[i] + b.d[i] + c;
        a.d[i] = (uint16_t)s;
        c = s >> 16;
    }
    return a;
}
static big big_sub(big a, big b) /* a >= b */
{
    int32_t br = 0;
    for (int i = 0; i < BL; i++) {
        int32_t s = (int32_t)a.d[i] - b.d[i] - br;
        br = s < 0;
        a.d[i] = (uint16_t)(s + (br ? 0x10000 : 0));
    }
    return a;
}
static int big_cmp(big a, big b)
{
    for (int i = BL - 1; i >= 0; i--)
        if (a.d[i] != b.d[i])
            return a.d[i] < b.d[i] ? -1 : 1;
    return 0;
}
static big big_shl(big a, unsigned n)
{
    while (n--) {
        uint32_t c = 0;
        for (int i = 0; i < BL; i++) {
            uint32_t v = ((uint32_t)a.d[i] << 1) | c;
            a.d[i] = (uint16_t)v;
            c = v >> 16;
        }
    }
    return a;
}
static int big_bit(big a, unsigned i) { return (a.d[i / 16] >> (i % 16)) & 1; }
/* Bit-serial restoring division, d != 0. */
static big big_div(big n, big d, big *rem)
{
    big q = big_u64(0), r = big_u64(0);
    for (int i = 16 * BL - 1; i >= 0; i--) {
        r = big_shl(r, 1);
        r.d[0] |= (uint16_t)big_bit(n, (unsigned)i);
        if (big_cmp(r, d) >= 0) {
            r = big_sub(r, d);
            q.d[i / 16] |= (uint16_t)(1u << (i % 16));
        }
    }
    if (rem)
        *rem = r;
    return q;
}
static uint64_t mag(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

/* Signed magnitude result -> int64 if it fits (|neg| <= 2^63, pos < 2^63). */
static bool ref_fit(big m, bool neg, int64_t *out)
{
    if (!big_fits_u64(m))
        return false;
    uint64_t u = big_word(m, 0);
    if (neg ? u > (UINT64_C(1) << 63) : u >= (UINT64_C(1) << 63))
        return false;
    if (neg)
        *out = u == (UINT64_C(1) << 63) ? INT64_MIN : -(int64_t)u;
    else
        *out = (int64_t)u;
    return true;
}
/* floor(m / d + 1/2) on magnitudes = round half away from zero once signed. */
static big ref_round_half_up(big m, big d) { return big_div(big_add(big_shl(m, 1), d), big_shl(d, 1), NULL); }

/* ------------------------------------------------------------------------
 * Shifts, floor division, rounding helpers (the inline part of ef_fixed.h)
 * --------------------------------------------------------------------- */
static void test_floor_div_mod(void **state)
{
    (void)state;
    /* a, d, floor(a/d), a mod d */
    static const int64_t T[][4] = {
        { 7, 2, 3, 1 },
        { -7, 2, -4, 1 },
        { 7, 3, 2, 1 },
        { -7, 3, -3, 2 },
        { -6, 3, -2, 0 },
        { 6, 3, 2, 0 },
        { 0, 5, 0, 0 },
        { -1, 5, -1, 4 },
        { -5, 5, -1, 0 },
        { -4, 5, -1, 1 },
        { 4, 5, 0, 4 },
        { -1, 1, -1, 0 },
        { INT64_MIN, 1, INT64_MIN, 0 },
        { INT64_MIN, 2, INT64_MIN / 2, 0 },
        { INT64_MIN, 3, INT64_C(-3074457345618258603), 1 },
        { INT64_MAX, 3, INT64_C(3074457345618258602), 1 },
        { INT64_MIN, INT64_MAX, -2, INT64_MAX - 1 },
        { -1, INT64_MAX, -1, INT64_MAX - 1 },
        { -256, 256, -1, 0 },
        { -257, 256, -2, 255 },
        { 255, 256, 0, 255 },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        int64_t q, r;
        CHECK(ef_floordiv_i64(T[i][0], T[i][1]) == T[i][2], "floordiv(%lld,%lld)", LL(T[i][0]), LL(T[i][1]));
        CHECK(ef_floormod_i64(T[i][0], T[i][1]) == T[i][3], "floormod(%lld,%lld)", LL(T[i][0]), LL(T[i][1]));
        ef_divmod_floor_i64(T[i][0], T[i][1], &q, &r);
        CHECK(q == T[i][2] && r == T[i][3], "divmod_floor(%lld,%lld)", LL(T[i][0]), LL(T[i][1]));
    }
    /* Random: a = d*q + r, 0 <= r < d, checked without division. */
    for (int i = 0; i < 100000; i++) {
        int64_t a = rnd_i64(), d = (int64_t)(rnd_u64() >> 1);
        if (d == 0)
            d = 1;
        int64_t q, r;
        ef_divmod_floor_i64(a, d, &q, &r);
        CHECK(r >= 0 && r < d, "remainder range a=%lld d=%lld", LL(a), LL(d));
        /* a = d*q + r (checked modulo 2^64, which with 0 <= r < d and the
         * sign of q pins q down), and q agrees with C's truncating division
         * wherever that is the floor. */
        CHECK((uint64_t)a - (uint64_t)r == (uint64_t)d * (uint64_t)q, "a = d*q + r: a=%lld d=%lld", LL(a), LL(d));
        CHECK((q < 0) == (a < 0), "sign of floor(a/d): a=%lld d=%lld", LL(a), LL(d));
        if (a >= 0)
            CHECK(q == a / d, "floor = trunc for a >= 0");
    }
}

static void test_ceil_round_div(void **state)
{
    (void)state;
    /* a, d, ceil(a/d), round half away(a/d) */
    static const int64_t T[][4] = {
        { 7, 2, 4, 4 }, { -7, 2, -3, -4 }, { 5, 2, 3, 3 },     { -5, 2, -2, -3 }, { 4, 2, 2, 2 }, { -4, 2, -2, -2 },
        { 1, 3, 1, 0 }, { -1, 3, 0, 0 },   { 2, 3, 1, 1 },     { -2, 3, 0, -1 },  { 3, 2, 2, 2 }, { -3, 2, -1, -2 },
        { 0, 9, 0, 0 }, { 13, 26, 1, 1 },  { -13, 26, 0, -1 }, { 12, 26, 1, 0 },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        CHECK(ef_ceildiv_i64(T[i][0], T[i][1]) == T[i][2], "ceildiv(%lld,%lld)", LL(T[i][0]), LL(T[i][1]));
        CHECK(ef_rounddiv_i64(T[i][0], T[i][1]) == T[i][3], "rounddiv(%lld,%lld)", LL(T[i][0]), LL(T[i][1]));
    }
}

static void test_asr_shl_wrap(void **state)
{
    (void)state;
    assert_int_equal(ef_asr_i32(-1, 1), -1);
    assert_int_equal(ef_asr_i32(-1, 31), -1);
    assert_int_equal(ef_asr_i32(-2, 1), -1);
    assert_int_equal(ef_asr_i32(-3, 1), -2);
    assert_int_equal(ef_asr_i32(INT32_MIN, 31), -1);
    assert_int_equal(ef_asr_i32(INT32_MIN, 0), INT32_MIN);
    assert_int_equal(ef_asr_i32(INT32_MAX, 30), 1);
    assert_int_equal(ef_asr_i32(-256, 8), -1);
    assert_int_equal(ef_asr_i32(-257, 8), -2);
    assert_int_equal(ef_asr_i64(INT64_MIN, 63), -1);
    assert_int_equal(ef_asr_i64(INT64_MIN, 62), -2);
    assert_int_equal(ef_asr_i64(INT64_MAX, 62), 1);
    assert_int_equal(ef_asr_i64(-5, 0), -5);
    /* floor(v / 2^n), checked against floor division for n <= 62. */
    for (int i = 0; i < 100000; i++) {
        int64_t v = rnd_i64();
        unsigned n = (unsigned)(rnd64() % 63);
        CHECK(ef_asr_i64(v, n) == ef_floordiv_i64(v, (int64_t)1 << n), "asr_i64(%lld,%u)", LL(v), n);
        int32_t w = (int32_t)(v % 0x7FFFFFFF);
        unsigned m = n % 31;
        CHECK(ef_asr_i32(w, m) == (int32_t)ef_floordiv_i64(w, (int64_t)1 << m), "asr_i32(%d,%u)", (int)w, m);
    }
    assert_int_equal(ef_shl_i64(-1, 63), INT64_MIN);
    assert_int_equal(ef_shl_i64(-3, 2), -12);
    assert_int_equal(ef_shl_i32(-3, 2), -12);
    assert_int_equal(ef_shl_i64(INT64_C(0x4000000000000000), 1), INT64_MIN);
    assert_int_equal(ef_wrap_i32(INT64_C(0x80000000)), INT32_MIN);
    assert_int_equal(ef_wrap_i32(INT64_C(0xFFFFFFFF)), -1);
    assert_int_equal(ef_wrap_i32(INT64_C(-0x80000001)), INT32_MAX);
    assert_int_equal(ef_wrap_i32(INT64_C(0x100000005)), 5);
    assert_int_equal(ef_wrap_u(-1, 7), 127);
    assert_int_equal(ef_wrap_u(128, 7), 0);
    assert_int_equal(ef_wrap_u(-129, 7), 127);
    assert_int_equal(ef_clamp_i64(INT64_MIN, -5, 5), -5);
    assert_int_equal(ef_clamp_i32(7, -5, 5), 5);
    assert_int_equal(ef_q32_from_int(-1).v, -EF_Q32_ONE);
    assert_int_equal(ef_q32_from_int(INT32_MIN).v, INT64_MIN);
}

static void test_round_shr(void **state)
{
    (void)state;
    /* floor(v / 2^n + 1/2): ties toward +inf */
    assert_int_equal(ef_round_shr_i64(1, 1), 1);   /* 0.5 -> 1 */
    assert_int_equal(ef_round_shr_i64(-1, 1), 0);  /* -0.5 -> 0 */
    assert_int_equal(ef_round_shr_i64(3, 1), 2);   /* 1.5 -> 2 */
    assert_int_equal(ef_round_shr_i64(-3, 1), -1); /* -1.5 -> -1 */
    assert_int_equal(ef_round_shr_i64(-5, 2), -1); /* -1.25 -> -1 */
    assert_int_equal(ef_round_shr_i64(-6, 2), -1); /* -1.5 -> -1 */
    assert_int_equal(ef_round_shr_i64(-7, 2), -2); /* -1.75 -> -2 */
    assert_int_equal(ef_round_shr_i64(INT64_MAX, 1), INT64_C(0x4000000000000000));
    assert_int_equal(ef_round_shr_i64(INT64_MIN, 62), -2);
    assert_int_equal(ef_round_shr_i64(INT64_MAX, 62), 2);
    assert_int_equal(ef_round_shr_i64(INT64_C(0x80), 8), 1);
    assert_int_equal(ef_round_shr_i64(-INT64_C(0x80), 8), 0);
    assert_int_equal(ef_round_shr_i64(-INT64_C(0x81), 8), -1);
    for (int i = 0; i < 100000; i++) {
        int64_t v = rnd_i64(), q, r;
        unsigned n = 1u + (unsigned)(rnd64() % 62);
        ef_divmod_floor_i64(v, (int64_t)1 << n, &q, &r);
        int64_t want = q + (r >= ((int64_t)1 << (n - 1)) ? 1 : 0);
        CHECK(ef_round_shr_i64(v, n) == want, "round_shr(%lld,%u)", LL(v), n);
    }
}

/* ------------------------------------------------------------------------
 * Checked arithmetic and wide products
 * --------------------------------------------------------------------- */
static void test_checked_add(void **state)
{
    (void)state;
    int64_t out = 42;
    assert_true(ef_add_i64_checked(INT64_MAX, 0, &out) && out == INT64_MAX);
    assert_true(ef_add_i64_checked(INT64_MAX, INT64_MIN, &out) && out == -1);
    assert_true(ef_add_i64_checked(INT64_MIN, 0, &out) && out == INT64_MIN);
    out = 42;
    assert_false(ef_add_i64_checked(INT64_MAX, 1, &out));
    assert_false(ef_add_i64_checked(INT64_MIN, -1, &out));
    assert_false(ef_add_i64_checked(INT64_MIN, INT64_MIN, &out));
    assert_false(ef_add_i64_checked(INT64_MAX, INT64_MAX, &out));
    assert_int_equal(out, 42); /* untouched on failure */
    assert_true(ef_add_i64_checked(-5, 3, &out) && out == -2);
    for (int i = 0; i < 100000; i++) {
        int64_t a = rnd_i64(), b = rnd_i64();
        /* Exact sum in the slow model: both magnitudes, then compare. */
        bool ok = ef_add_i64_checked(a, b, &out);
        bool fits;
        if ((a < 0) == (b < 0)) {
            big s = big_add(big_u64(mag(a)), big_u64(mag(b)));
            big lim = big_u64(a < 0 ? UINT64_C(1) << 63 : (UINT64_C(1) << 63) - 1);
            fits = big_cmp(s, lim) <= 0;
        } else {
            fits = true;
        }
        CHECK(ok == fits, "add_checked(%lld,%lld) ok=%d", LL(a), LL(b), ok);
        if (ok)
            CHECK((uint64_t)out == (uint64_t)a + (uint64_t)b, "add value");
    }
}

/* Reference 64x64 -> 128 signed product as (hi, lo) bit patterns. */
static void ref_mul_wide(int64_t a, int64_t b, uint64_t *hi, uint64_t *lo)
{
    big m = big_mul(big_u64(mag(a)), big_u64(mag(b)));
    if (((a < 0) != (b < 0)) && !big_is_zero(m))
        m = big_sub(big_shl(big_u64(1), 128), m); /* two's complement in 128 bits */
    *hi = big_word(m, 1);
    *lo = big_word(m, 0);
}

static void test_mul_wide(void **state)
{
    (void)state;
    for (size_t i = 0; i < NCORNERS; i++)
        for (size_t j = 0; j < NCORNERS; j++) {
            uint64_t hi, lo;
            ef_i128 p = ef_mul_i64_wide(CORNERS[i], CORNERS[j]);
            ref_mul_wide(CORNERS[i], CORNERS[j], &hi, &lo);
            CHECK((uint64_t)p.hi == hi && p.lo == lo, "mul_wide(%lld,%lld)", LL(CORNERS[i]), LL(CORNERS[j]));
        }
    /* Specific: INT64_MIN^2 = 2^126; INT64_MIN * INT64_MAX = -2^126 + 2^63. */
    ef_i128 p = ef_mul_i64_wide(INT64_MIN, INT64_MIN);
    assert_true(p.hi == INT64_C(0x4000000000000000) && p.lo == 0);
    p = ef_mul_i64_wide(INT64_MIN, INT64_MAX);
    assert_true(p.hi == -INT64_C(0x4000000000000000) && p.lo == (UINT64_C(1) << 63));
    p = ef_mul_i64_wide(-1, 1);
    assert_true(p.hi == -1 && p.lo == UINT64_MAX);
    for (int i = 0; i < 50000; i++) {
        int64_t a = (i & 1) ? ef_wrap_i64(rnd64()) : rnd_i64(), b = (i & 2) ? ef_wrap_i64(rnd64()) : rnd_i64();
        uint64_t hi, lo;
        p = ef_mul_i64_wide(a, b);
        ref_mul_wide(a, b, &hi, &lo);
        CHECK((uint64_t)p.hi == hi && p.lo == lo, "mul_wide(%lld,%lld)", LL(a), LL(b));
    }
}

static void test_checked_mul(void **state)
{
    (void)state;
    int64_t out = 42;
    assert_true(ef_mul_i64_checked(INT64_MIN, 1, &out) && out == INT64_MIN);
    assert_true(ef_mul_i64_checked(INT64_C(-0x80000000), INT64_C(0x100000000), &out) && out == INT64_MIN);
    assert_true(ef_mul_i64_checked(INT64_MAX, -1, &out) && out == -INT64_MAX);
    out = 42;
    assert_false(ef_mul_i64_checked(INT64_MIN, -1, &out));
    assert_false(ef_mul_i64_checked(INT64_C(0x80000000), INT64_C(0x100000000), &out));
    assert_false(ef_mul_i64_checked(INT64_C(0x100000000), INT64_C(0x100000000), &out));
    assert_false(ef_mul_i64_checked(INT64_MIN, 2, &out));
    assert_int_equal(out, 42);
    for (int i = 0; i < 50000; i++) {
        int64_t a = rnd_i64(), b = rnd_i64(), want = 0;
        bool neg = (a < 0) != (b < 0);
        bool fits = ref_fit(big_mul(big_u64(mag(a)), big_u64(mag(b))), neg, &want);
        bool ok = ef_mul_i64_checked(a, b, &out);
        CHECK(ok == fits && (!ok || out == want), "mul_checked(%lld,%lld)", LL(a), LL(b));
    }
}

/* The internal 128/64 divider (Knuth D) against the bit-serial model. */
static void test_div_u128(void **state)
{
    (void)state;
    /* clang-format off */
    static const uint64_t D[] = {
        1, 2, 3, 10, 0xFFFFFFFFu, UINT64_C(0x100000000), UINT64_C(0x100000001), UINT64_C(0x1FFFFFFFF),
        UINT64_C(0x8000000000000000), UINT64_C(0x8000000000000001), UINT64_C(0xFFFFFFFFFFFFFFFF),
        UINT64_C(0xFFFFFFFF00000000), UINT64_C(0x80000000FFFFFFFF), UINT64_C(0x7FFFFFFFFFFFFFFF),
        UINT64_C(0x00000001FFFFFFFF), UINT64_C(0x8000000080000000), UINT64_C(0xFFFFFFFE00000001),
    };
    /* clang-format on */
    for (int i = 0; i < 60000; i++) {
        uint64_t d = i < 20000 ? D[(size_t)i % (sizeof D / sizeof D[0])] : rnd_u64();
        if (d == 0)
            d = 1;
        ef_u128 n;
        int kind = (int)(rnd64() % 4);
        n.hi = kind == 0 ? d - 1 : kind == 1 ? 0 : rnd64() % d; /* n.hi < d */
        n.lo = kind == 3 ? UINT64_MAX - (rnd64() & 3) : rnd64();
        uint64_t r, q = ef_div_u128_u64(n, d, &r);
        big bn = big_add(big_shl(big_u64(n.hi), 64), big_u64(n.lo)), br;
        big bq = big_div(bn, big_u64(d), &br);
        CHECK(big_fits_u64(bq) && big_word(bq, 0) == q && big_word(br, 0) == r,
              "div_u128(%016llx%016llx / %016llx): q=%016llx r=%016llx", ULL(n.hi), ULL(n.lo), ULL(d), ULL(q), ULL(r));
    }
}

/* ------------------------------------------------------------------------
 * Q32 multiply, divide, muldiv
 * --------------------------------------------------------------------- */
static bool ref_q32_mul(int64_t a, int64_t b, int64_t *out)
{
    /* p = a*b; floor(p/2^32 + 1/2).  For p = M >= 0: floor((M + 2^31) / 2^32);
     * for p = -M: -ceil(M/2^32 - 1/2) = -floor((M + 2^31 - 1) / 2^32). */
    big m = big_mul(big_u64(mag(a)), big_u64(mag(b)));
    bool neg = (a < 0) != (b < 0) && !big_is_zero(m);
    big bias = big_u64(neg ? (UINT64_C(1) << 31) - 1 : UINT64_C(1) << 31);
    big q = big_div(big_add(m, bias), big_u64(UINT64_C(1) << 32), NULL);
    if (big_is_zero(q))
        neg = false;
    return ref_fit(q, neg, out);
}

static void test_q32_mul(void **state)
{
    (void)state;
    ef_q32 r = ef_q32_raw(42);
    /* a, b, expected (exact Q32 bit patterns) */
    static const int64_t T[][3] = {
        { EF_Q32_ONE, EF_Q32_ONE, EF_Q32_ONE },
        { 3 * EF_Q32_ONE / 2, -2 * EF_Q32_ONE, -3 * EF_Q32_ONE },
        { 1, EF_Q32_ONE / 2, 1 },   /* 2^-32 * 0.5 = 0.5 ulp: tie -> +inf -> 1 */
        { -1, EF_Q32_ONE / 2, 0 },  /* -0.5 ulp: tie -> +inf -> 0 */
        { 3, EF_Q32_ONE / 2, 2 },   /* 1.5 ulp -> 2 */
        { -3, EF_Q32_ONE / 2, -1 }, /* -1.5 ulp -> -1 */
        { 1, 1, 0 },                /* 2^-64 -> 0 */
        { -1, 1, 0 },               /* -2^-64 -> 0 (not below zero) */
        { 1, EF_Q32_ONE / 2 + 1, 1 },
        { -1, EF_Q32_ONE / 2 + 1, -1 }, /* just past -0.5 ulp */
        { INT64_MIN, EF_Q32_ONE, INT64_MIN },
        { -((int64_t)1 << 47), (int64_t)1 << 48, INT64_MIN }, /* -2^15 * 2^16 = -2^31 fits */
        { INT64_MAX, EF_Q32_ONE, INT64_MAX },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        bool ok = ef_q32_mul(ef_q32_raw(T[i][0]), ef_q32_raw(T[i][1]), &r);
        CHECK(ok && r.v == T[i][2], "q32_mul(%lld,%lld) = %lld", LL(T[i][0]), LL(T[i][1]), LL(r.v));
    }
    /* Overflow: 2^16 * 2^15 = 2^31 is out of range; INT64_MIN * -1.0 too. */
    r = ef_q32_raw(42);
    assert_false(ef_q32_mul(ef_q32_raw((int64_t)1 << 48), ef_q32_raw((int64_t)1 << 47), &r));
    assert_false(ef_q32_mul(ef_q32_raw(INT64_MIN), ef_q32_raw(-EF_Q32_ONE), &r));
    assert_false(ef_q32_mul(ef_q32_raw(INT64_MIN), ef_q32_raw(INT64_MIN), &r));
    assert_int_equal(r.v, 42);
    /* Just below the top: (2^31 - 2^-32) * 1 fits, * (1 + 2^-32) rounds past. */
    assert_true(ef_q32_mul(ef_q32_raw(INT64_MAX), ef_q32_raw(EF_Q32_ONE), &r) && r.v == INT64_MAX);
    assert_false(ef_q32_mul(ef_q32_raw(INT64_MAX), ef_q32_raw(EF_Q32_ONE + 1), &r));
    for (size_t i = 0; i < NCORNERS; i++)
        for (size_t j = 0; j < NCORNERS; j++) {
            int64_t want = 0;
            bool wok = ref_q32_mul(CORNERS[i], CORNERS[j], &want);
            bool ok = ef_q32_mul(ef_q32_raw(CORNERS[i]), ef_q32_raw(CORNERS[j]), &r);
            CHECK(ok == wok && (!ok || r.v == want), "q32_mul(%lld,%lld)", LL(CORNERS[i]), LL(CORNERS[j]));
        }
    for (int i = 0; i < 30000; i++) {
        int64_t a = rnd_i64(), b = rnd_i64(), want = 0;
        if (i % 4 == 0) { /* b = 2^31 mod 2^32 and a odd: a*b / 2^32 is a tie */
            b = ef_wrap_i64(((uint64_t)b & ~UINT64_C(0xFFFFFFFF)) | UINT64_C(0x80000000));
            a = ef_wrap_i64((uint64_t)a | 1u);
        }
        bool wok = ref_q32_mul(a, b, &want);
        bool ok = ef_q32_mul(ef_q32_raw(a), ef_q32_raw(b), &r);
        CHECK(ok == wok && (!ok || r.v == want), "q32_mul(%lld,%lld): ok=%d got %lld want %lld", LL(a), LL(b), ok,
              LL(r.v), LL(want));
    }
}

/* sign * floor(M / D + 1/2) with M = |n|, D = |d|: ties away from zero. */
static bool ref_round_div(big m, uint64_t d, bool neg, int64_t *out)
{
    big q = ref_round_half_up(m, big_u64(d));
    if (big_is_zero(q))
        neg = false;
    return ref_fit(q, neg, out);
}

static void test_q32_div(void **state)
{
    (void)state;
    ef_q32 r;
    static const int64_t T[][3] = {
        { EF_Q32_ONE, EF_Q32_ONE, EF_Q32_ONE },
        { EF_Q32_ONE, 3 * EF_Q32_ONE, 1431655765 },     /* 1/3 = 1431655765.33 ulp */
        { 2 * EF_Q32_ONE, 3 * EF_Q32_ONE, 2863311531 }, /* 2/3 = 2863311530.67 ulp */
        { -2 * EF_Q32_ONE, 3 * EF_Q32_ONE, -2863311531 },
        { 1, 2 * EF_Q32_ONE, 1 },   /* 0.5 ulp: tie away -> 1 */
        { -1, 2 * EF_Q32_ONE, -1 }, /* -0.5 ulp: tie away -> -1 */
        { 1, -2 * EF_Q32_ONE, -1 },
        { -1, -2 * EF_Q32_ONE, 1 },
        { 3, 2 * EF_Q32_ONE, 2 }, /* 1.5 -> 2 */
        { -3, 2 * EF_Q32_ONE, -2 },
        { 1, 3 * EF_Q32_ONE, 0 }, /* 1/3 ulp -> 0 */
        { INT64_MIN, EF_Q32_ONE, INT64_MIN },
        { INT64_MIN, 2 * EF_Q32_ONE, INT64_MIN / 2 },
        { INT64_MAX, INT64_MAX, EF_Q32_ONE },
        { INT64_MIN, INT64_MIN, EF_Q32_ONE },
        { 1, INT64_MIN, 0 },               /* 2^-32 / -2^31: far below half an ulp */
        { EF_Q32_ONE / 2, INT64_MIN, -1 }, /* 0.5 / -2^31 = -2^-32: exactly -1 ulp */
        { EF_Q32_ONE / 4, INT64_MIN, -1 }, /* -0.5 ulp: tie away from zero */
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        int64_t want = T[i][2];
        bool ok = ef_q32_div(ef_q32_raw(T[i][0]), ef_q32_raw(T[i][1]), &r);
        CHECK(ok && r.v == want, "q32_div(%lld,%lld) = %lld", LL(T[i][0]), LL(T[i][1]), LL(r.v));
    }
    r = ef_q32_raw(42);
    assert_false(ef_q32_div(ef_q32_raw(INT64_MIN), ef_q32_raw(-EF_Q32_ONE), &r)); /* +2^31 */
    assert_false(ef_q32_div(ef_q32_raw(EF_Q32_ONE), ef_q32_raw(1), &r));          /* 2^32 */
    assert_false(ef_q32_div(ef_q32_raw(INT64_MAX), ef_q32_raw(EF_Q32_ONE / 2), &r));
    assert_false(ef_q32_div(ef_q32_raw(1), ef_q32_raw(0), &r)); /* b = 0 */
    assert_int_equal(r.v, 42);
    /* The largest quotient that fits, and one just past it. */
    assert_true(ef_q32_div(ef_q32_raw(INT64_MAX), ef_q32_raw(EF_Q32_ONE), &r) && r.v == INT64_MAX);
    assert_true(ef_q32_div(ef_q32_raw(INT64_C(0x7FFFFFFF)), ef_q32_raw(1), &r) && r.v == INT64_C(0x7FFFFFFF00000000));
    assert_false(ef_q32_div(ef_q32_raw(INT64_C(0x80000000)), ef_q32_raw(1), &r));
    assert_true(ef_q32_div(ef_q32_raw(-INT64_C(0x80000000)), ef_q32_raw(1), &r) && r.v == INT64_MIN);
    for (int i = 0; i < 30000; i++) {
        int64_t a = rnd_i64(), b = rnd_i64(), want = 0;
        if (b == 0)
            b = 1;
        if (i % 5 == 0)
            a = (int64_t)(rnd64() % 4096) - 2048; /* small dividends: ties, zeros */
        big m = big_shl(big_u64(mag(a)), 32);
        bool wok = ref_round_div(m, mag(b), (a < 0) != (b < 0), &want);
        bool ok = ef_q32_div(ef_q32_raw(a), ef_q32_raw(b), &r);
        CHECK(ok == wok && (!ok || r.v == want), "q32_div(%lld,%lld): ok=%d got %lld want %lld", LL(a), LL(b), ok,
              LL(r.v), LL(want));
    }
}

static void test_muldiv(void **state)
{
    (void)state;
    int64_t out = 42;
    assert_true(ef_muldiv_i64(7, 3, 2, &out) && out == 11);   /* 10.5 -> 11 */
    assert_true(ef_muldiv_i64(-7, 3, 2, &out) && out == -11); /* -10.5 -> -11 */
    assert_true(ef_muldiv_i64(7, 3, -2, &out) && out == -11);
    assert_true(ef_muldiv_i64(-7, -3, -2, &out) && out == -11);
    assert_true(ef_muldiv_i64(5, 1, 3, &out) && out == 2); /* 1.67 */
    assert_true(ef_muldiv_i64(4, 1, 3, &out) && out == 1); /* 1.33 */
    assert_true(ef_muldiv_i64(0, INT64_MIN, -1, &out) && out == 0);
    assert_true(ef_muldiv_i64(INT64_MIN, INT64_MIN, INT64_MIN, &out) && out == INT64_MIN);
    assert_true(ef_muldiv_i64(INT64_MAX, INT64_MAX, INT64_MAX, &out) && out == INT64_MAX);
    assert_true(ef_muldiv_i64(INT64_MIN, 1, 1, &out) && out == INT64_MIN);
    assert_true(ef_muldiv_i64(INT64_MAX, INT64_MIN, INT64_MAX, &out) && out == INT64_MIN);
    out = 42;
    assert_false(ef_muldiv_i64(INT64_MIN, 1, -1, &out));
    assert_false(ef_muldiv_i64(INT64_MIN, INT64_MIN, 1, &out));
    assert_false(ef_muldiv_i64(INT64_MAX, 2, 1, &out));
    assert_false(ef_muldiv_i64(INT64_MAX, INT64_MAX, INT64_MAX - 1, &out)); /* rounds past */
    assert_false(ef_muldiv_i64(1, 1, 0, &out));
    assert_int_equal(out, 42);
    for (int i = 0; i < 30000; i++) {
        int64_t a = rnd_i64(), b = rnd_i64(), c = rnd_i64(), want = 0;
        if (c == 0)
            c = -1;
        if (i % 3 == 0)
            c = (int64_t)(rnd64() % 7) + 1;
        big m = big_mul(big_u64(mag(a)), big_u64(mag(b)));
        bool wok = ref_round_div(m, mag(c), ((a < 0) != (b < 0)) != (c < 0), &want);
        bool ok = ef_muldiv_i64(a, b, c, &out);
        CHECK(ok == wok && (!ok || out == want), "muldiv(%lld,%lld,%lld): ok=%d got %lld want %lld", LL(a), LL(b),
              LL(c), ok, LL(out), LL(want));
    }
}

/* ------------------------------------------------------------------------
 * Square roots
 * --------------------------------------------------------------------- */
/* r = floor(sqrt(v)) iff r^2 <= v < (r+1)^2, checked in the slow model. */
static bool is_floor_root(big v, uint64_t r)
{
    big r2 = big_mul(big_u64(r), big_u64(r));
    big r12 = big_mul(big_add(big_u64(r), big_u64(1)), big_add(big_u64(r), big_u64(1)));
    return big_cmp(r2, v) <= 0 && big_cmp(v, r12) < 0;
}

static void test_isqrt(void **state)
{
    (void)state;
    assert_int_equal(ef_isqrt_u64(0), 0);
    assert_int_equal(ef_isqrt_u64(1), 1);
    assert_int_equal(ef_isqrt_u64(2), 1);
    assert_int_equal(ef_isqrt_u64(3), 1);
    assert_int_equal(ef_isqrt_u64(4), 2);
    assert_int_equal(ef_isqrt_u64(UINT64_MAX), UINT32_MAX);
    assert_int_equal(ef_isqrt_u64(UINT64_C(0xFFFFFFFE00000001)), UINT32_MAX); /* (2^32-1)^2 */
    assert_int_equal(ef_isqrt_u64(UINT64_C(0xFFFFFFFE00000000)), UINT32_MAX - 1);
    /* Every k^2 - 1, k^2, k^2 + 1 around small k, at powers of two, and
     * around 2^32 - 1. */
    for (uint64_t k = 1; k < 70000; k++) {
        uint64_t s = k * k;
        CHECK(ef_isqrt_u64(s) == k && ef_isqrt_u64(s - 1) == k - 1 && ef_isqrt_u64(s + 1) == k, "k=%llu", ULL(k));
    }
    for (unsigned e = 1; e < 32; e++) {
        uint64_t ks[] = { (UINT64_C(1) << e) - 1, UINT64_C(1) << e, (UINT64_C(1) << e) + 1 };
        for (int j = 0; j < 3; j++) {
            uint64_t s = ks[j] * ks[j];
            CHECK(ef_isqrt_u64(s) == ks[j] && ef_isqrt_u64(s - 1) == ks[j] - 1 && ef_isqrt_u64(s + 1) == ks[j],
                  "k=%llu", ULL(ks[j]));
        }
    }
    for (uint64_t k = UINT32_MAX - 70000; k <= UINT32_MAX; k++) {
        uint64_t s = k * k;
        CHECK(ef_isqrt_u64(s) == k && ef_isqrt_u64(s - 1) == k - 1, "k=%llu", ULL(k));
        if (k < UINT32_MAX)
            CHECK(ef_isqrt_u64(s + 1) == k, "k=%llu", ULL(k));
    }
    for (int i = 0; i < 100000; i++) {
        uint64_t v = rnd_u64();
        CHECK(is_floor_root(big_u64(v), ef_isqrt_u64(v)), "isqrt(%llu)", ULL(v));
    }
}

static void test_q32_sqrt(void **state)
{
    (void)state;
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(0)).v, 0);
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(-5)).v, 0);    /* outside contract: 0 */
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(1)).v, 65536); /* sqrt(2^-32) = 2^-16 */
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(EF_Q32_ONE)).v, EF_Q32_ONE);
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(4 * EF_Q32_ONE)).v, 2 * EF_Q32_ONE);
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(EF_Q32_ONE / 4)).v, EF_Q32_ONE / 2);
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(2 * EF_Q32_ONE)).v,
                     INT64_C(6074000999)); /* sqrt 2 * 2^32 = 6074000999.95 */
    assert_int_equal(ef_q32_sqrt(ef_q32_raw(INT64_MAX)).v, INT64_C(199032864766430)); /* floor(sqrt(2^95 - 2^32)) */
    for (int i = 0; i < 50000; i++) {
        int64_t a = (int64_t)(rnd_u64() >> 1);
        if (i % 3 == 0) { /* a = j^2: a * 2^32 = (j * 2^16)^2, and neighbours */
            uint64_t j = rnd64() >> (33 + rnd64() % 31);
            a = (int64_t)(j * j) + (int64_t)(rnd64() % 3) - 1;
            if (a < 0)
                a = 0;
        }
        ef_q32 r = ef_q32_sqrt(ef_q32_raw(a));
        CHECK(r.v >= 0 && is_floor_root(big_shl(big_u64((uint64_t)a), 32), (uint64_t)r.v), "q32_sqrt(%lld)", LL(a));
    }
}

/* ------------------------------------------------------------------------
 * Decimal parser and formatter
 * --------------------------------------------------------------------- */
struct parse_case {
    const char *s;
    ef_num_status st;
    size_t consumed;
    int64_t v;
};

/* Expected values computed offline with Python's fractions.Fraction (exact
 * rationals): q = floor(|v| * 2^32 + 1/2), negated for '-', EF_NUM_RANGE when
 * q >= 2^63.  The decimal 0.000000000116415321826934814453125 is exactly
 * 2^-33 (half an ulp), 0.000000000349245965480804443359375 is 3 * 2^-33, and
 * 2147483647.999999999883584678173065185546875 is 2^31 - 2^-33. */
static const struct parse_case PARSE_CASES[] = {
    /* grammar and consumed length */
    { "0", EF_NUM_OK, 1, INT64_C(0) },
    { "-0", EF_NUM_OK, 2, INT64_C(0) },
    { "+0", EF_NUM_OK, 2, INT64_C(0) },
    { "0.0", EF_NUM_OK, 3, INT64_C(0) },
    { ".5", EF_NUM_OK, 2, INT64_C(2147483648) },
    { "-.5", EF_NUM_OK, 3, INT64_C(-2147483648) },
    { "5.", EF_NUM_OK, 2, INT64_C(21474836480) },
    { "1", EF_NUM_OK, 1, INT64_C(4294967296) },
    { "-1", EF_NUM_OK, 2, INT64_C(-4294967296) },
    { "0.1", EF_NUM_OK, 3, INT64_C(429496730) }, /* 429496729.6 */
    { "-0.1", EF_NUM_OK, 4, INT64_C(-429496730) },
    { "1e-2", EF_NUM_OK, 4, INT64_C(42949673) },
    { "2.5E+1", EF_NUM_OK, 6, INT64_C(107374182400) },
    { "2.5e+1x", EF_NUM_OK, 6, INT64_C(107374182400) },
    { "1e", EF_NUM_OK, 1, INT64_C(4294967296) }, /* 'e' without digits: not consumed */
    { "1e+", EF_NUM_OK, 1, INT64_C(4294967296) },
    { "1e-", EF_NUM_OK, 1, INT64_C(4294967296) },
    { "1E5", EF_NUM_OK, 3, INT64_C(429496729600000) },
    { "1.e5", EF_NUM_OK, 4, INT64_C(429496729600000) }, /* digits '.' then exponent */
    { "1.5e", EF_NUM_OK, 3, INT64_C(6442450944) },
    { "1.5e-3;", EF_NUM_OK, 6, INT64_C(6442451) },
    { "e5", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "+.e1", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { ".", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "-", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "+", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "-.", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "..5", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "+-1", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "1..5", EF_NUM_OK, 2, INT64_C(4294967296) },
    { "1.2.3", EF_NUM_OK, 3, INT64_C(5153960755) },
    { " 1", EF_NUM_SYNTAX, 0, INT64_C(0) }, /* no white space skipping */
    { "0x10", EF_NUM_OK, 1, INT64_C(0) },
    { "inf", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "nan", EF_NUM_SYNTAX, 0, INT64_C(0) },
    { "1,5", EF_NUM_OK, 1, INT64_C(4294967296) },
    { "00001", EF_NUM_OK, 5, INT64_C(4294967296) },
    { "1e0005", EF_NUM_OK, 6, INT64_C(429496729600000) },
    { "1e-0", EF_NUM_OK, 4, INT64_C(4294967296) },
    { "-1.5e-3", EF_NUM_OK, 7, INT64_C(-6442451) },
    { "5e-1 ", EF_NUM_OK, 4, INT64_C(2147483648) },
    { "1.0E-0001", EF_NUM_OK, 9, INT64_C(429496730) },
    { "1E+0", EF_NUM_OK, 4, INT64_C(4294967296) },
    { ".0e0", EF_NUM_OK, 4, INT64_C(0) },
    { "0.5e1", EF_NUM_OK, 5, INT64_C(21474836480) },
    /* ties and near-ties at half an ulp */
    { "0.000000000116415321826934814453125", EF_NUM_OK, 35, INT64_C(1) },
    { "-0.000000000116415321826934814453125", EF_NUM_OK, 36, INT64_C(-1) },
    { "0.000000000116415321826934814453124999999999999999", EF_NUM_OK, 50, INT64_C(0) },
    { "0.0000000001164153218269348144531250000000000000001", EF_NUM_OK, 51, INT64_C(1) },
    { "0.000000000349245965480804443359375", EF_NUM_OK, 35, INT64_C(2) },
    { "-0.000000000349245965480804443359375", EF_NUM_OK, 36, INT64_C(-2) },
    { "0.00000000011641532182693481445312", EF_NUM_OK, 34, INT64_C(0) },
    { "116415321826934814453125e-45", EF_NUM_OK, 28, INT64_C(0) },
    { "116415321826934814453125e-33", EF_NUM_OK, 28, INT64_C(1) },
    { "0.116415321826934814453125e-9", EF_NUM_OK, 29, INT64_C(1) },
    { "0.00000000023283064365386962890625", EF_NUM_OK, 34, INT64_C(1) },
    { "12345.000000000116415321826934814453125", EF_NUM_OK, 39, INT64_C(53021371269121) },
    { "12345.000000000116415321826934814453124", EF_NUM_OK, 39, INT64_C(53021371269120) },
    { "-12345.000000000116415321826934814453125", EF_NUM_OK, 40, INT64_C(-53021371269121) },
    { "1073741824.000000000116415321826934814453125", EF_NUM_OK, 44, INT64_C(4611686018427387905) },
    { "0.00000000000000000000000000000000000000000000000000001", EF_NUM_OK, 55, INT64_C(0) },
    { "1e-10", EF_NUM_OK, 5, INT64_C(0) },
    { "-1e-10", EF_NUM_OK, 6, INT64_C(0) },
    /* range boundary: |v| >= 2^31 after rounding is an error, both signs */
    { "2147483647", EF_NUM_OK, 10, INT64_C(9223372032559808512) },
    { "2147483647.99999999976716935634613037109375", EF_NUM_OK, 43, INT64_C(9223372036854775807) },
    { "2147483647.999999999883584678173065185546875", EF_NUM_RANGE, 44, INT64_C(0) },
    { "2147483647.999999999883584678173065185546874", EF_NUM_OK, 44, INT64_C(9223372036854775807) },
    { "2147483647.9999999999", EF_NUM_RANGE, 21, INT64_C(0) },
    { "2147483648", EF_NUM_RANGE, 10, INT64_C(0) },
    { "-2147483648", EF_NUM_RANGE, 11, INT64_C(0) },
    { "-2147483647.99999999976716935634613037109375", EF_NUM_OK, 44, INT64_C(-9223372036854775807) },
    { "-2147483647.999999999883584678173065185546874", EF_NUM_OK, 45, INT64_C(-9223372036854775807) },
    { "-2147483647.999999999883584678173065185546875", EF_NUM_RANGE, 45, INT64_C(0) },
    { "9999999999", EF_NUM_RANGE, 10, INT64_C(0) },
    { "10000000000", EF_NUM_RANGE, 11, INT64_C(0) },
    { "1e10", EF_NUM_RANGE, 4, INT64_C(0) },
    { "1e9", EF_NUM_OK, 3, INT64_C(4294967296000000000) },
    { "2.147483648e9", EF_NUM_RANGE, 13, INT64_C(0) },
    { "2.147483647e9", EF_NUM_OK, 13, INT64_C(9223372032559808512) },
    { "0.2147483647e10", EF_NUM_OK, 15, INT64_C(9223372032559808512) },
    { "21474836470e-1", EF_NUM_OK, 14, INT64_C(9223372032559808512) },
    /* exponent extremes */
    { "1e100000", EF_NUM_RANGE, 8, INT64_C(0) },
    { "-1e100000", EF_NUM_RANGE, 9, INT64_C(0) },
    { "1e-100000", EF_NUM_OK, 9, INT64_C(0) },
    { "1e+99999999999999999999", EF_NUM_RANGE, 23, INT64_C(0) },
    { "1e-99999999999999999999", EF_NUM_OK, 23, INT64_C(0) },
    { "0e99999", EF_NUM_OK, 7, INT64_C(0) },
    { "0.0000e100000", EF_NUM_OK, 13, INT64_C(0) },
    { "-0e-7", EF_NUM_OK, 5, INT64_C(0) },
    /* many digits */
    { "3.14159265358979323846264338327950288419716939937510582097494459", EF_NUM_OK, 64, INT64_C(13493037705) },
    { "-273.15", EF_NUM_OK, 7, INT64_C(-1173170316902) },
    { "1234.5678e-2", EF_NUM_OK, 12, INT64_C(53024283257) },
};

static void check_parse(const char *s, size_t len, ef_num_status st, size_t consumed, int64_t v)
{
    ef_q32 out = ef_q32_raw(INT64_C(0x5A5A5A5A));
    size_t c = 12345;
    ef_num_status got = ef_parse_decimal_q32(s, len, &out, &c);
    CHECK(got == st, "parse(\"%.60s\"%s): status %d, want %d", s, len > 60 ? "..." : "", (int)got, (int)st);
    CHECK(c == consumed, "parse(\"%.60s\"): consumed %zu, want %zu", s, c, consumed);
    if (st == EF_NUM_OK)
        CHECK(out.v == v, "parse(\"%.60s\"%s): %lld, want %lld", s, len > 60 ? "..." : "", LL(out.v), LL(v));
    else
        CHECK(out.v == INT64_C(0x5A5A5A5A), "parse(\"%.60s\"): out written on error", s);
}

static void test_parse_table(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof PARSE_CASES / sizeof PARSE_CASES[0]; i++) {
        const struct parse_case *t = &PARSE_CASES[i];
        check_parse(t->s, strlen(t->s), t->st, t->consumed, t->v);
    }
    /* len bounds the text: nothing at or past s[len] is read. */
    check_parse("123", 2, EF_NUM_OK, 2, 12 * EF_Q32_ONE);
    check_parse("1e5", 2, EF_NUM_OK, 1, EF_Q32_ONE);
    check_parse("1.5", 2, EF_NUM_OK, 2, EF_Q32_ONE);
    check_parse("-1", 1, EF_NUM_SYNTAX, 0, 0);
    check_parse("7", 0, EF_NUM_SYNTAX, 0, 0);
    /* NULL out / consumed are allowed. */
    assert_int_equal(ef_parse_decimal_q32("2", 1, NULL, NULL), EF_NUM_OK);
}

/* Builds strings longer than a table could hold. */
static char *repeat(const char *head, char fill, size_t n, const char *tail)
{
    size_t a = strlen(head), b = strlen(tail);
    char *s = malloc(a + n + b + 1);
    assert_true(s != NULL);
    memcpy(s, head, a);
    memset(s + a, fill, n);
    memcpy(s + a + n, tail, b + 1);
    return s;
}

static void test_parse_long(void **state)
{
    (void)state;
    struct {
        const char *head;
        char fill;
        size_t n;
        const char *tail;
        ef_num_status st;
        int64_t v;
    } T[] = {
        { "0.1", '0', 1000, "1", EF_NUM_OK, 429496730 }, /* 0.1 + 10^-1002 */
        { "", '0', 1000, "1.5", EF_NUM_OK, 6442450944 }, /* leading zeros */
        { "1", '0', 1000, "e-1000", EF_NUM_OK, EF_Q32_ONE },
        { "0.", '0', 1000, "1e1001", EF_NUM_OK, EF_Q32_ONE },
        { "0.", '0', 99999, "1e100000", EF_NUM_OK, EF_Q32_ONE },
        { "-0.", '0', 99999, "25e100000", EF_NUM_OK, -5 * EF_Q32_ONE / 2 },
        { "1", '0', 100000, "e-100000", EF_NUM_OK, EF_Q32_ONE },
        { "1", '0', 2000, "", EF_NUM_RANGE, 0 },
        { "1", '0', 2000, ".5e-2000", EF_NUM_OK, EF_Q32_ONE },
        /* just below the tie by 10^-2035: must round down */
        { "0.000000000116415321826934814453124", '9', 2000, "", EF_NUM_OK, 0 },
        { "-0.000000000116415321826934814453124", '9', 2000, "", EF_NUM_OK, 0 },
        /* just above the tie: up (as the tie itself) */
        { "0.000000000116415321826934814453125", '0', 2000, "1", EF_NUM_OK, 1 },
        /* 0.99999...: rounds to exactly one */
        { "0.", '9', 5000, "", EF_NUM_OK, EF_Q32_ONE },
        /* 2^31 - tiny: rounds to 2^31, out of range */
        { "2147483647.", '9', 3000, "", EF_NUM_RANGE, 0 },
        { "-2147483647.", '9', 3000, "", EF_NUM_RANGE, 0 },
        /* a tie written with an exponent far from the digits */
        { "0.", '0', 5000, "116415321826934814453125e4991", EF_NUM_OK, 1 },
        { "0.", '0', 5000, "116415321826934814453124e4991", EF_NUM_OK, 0 },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        char *s = repeat(T[i].head, T[i].fill, T[i].n, T[i].tail);
        size_t len = strlen(s);
        check_parse(s, len, T[i].st, len, T[i].v);
        free(s);
    }
}

static void test_format_table(void **state)
{
    (void)state;
    static const struct {
        int64_t v;
        const char *s;
    } T[] = {
        { 0, "0" },
        { EF_Q32_ONE, "1" },
        { -EF_Q32_ONE, "-1" },
        { EF_Q32_ONE / 2, "0.5" },
        { -EF_Q32_ONE / 2, "-0.5" },
        { 1, "0.00000000023283064365386962890625" },
        { -1, "-0.00000000023283064365386962890625" },
        { 429496730, "0.1000000000931322574615478515625" },
        { INT64_MAX, "2147483647.99999999976716935634613037109375" },
        { INT64_MIN, "-2147483648" },
        { INT64_MIN + 1, "-2147483647.99999999976716935634613037109375" },
        { 107374182400, "25" },
        { -1173170316902, "-273.1499999999068677425384521484375" },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        char buf[48];
        memset(buf, 'x', sizeof buf);
        size_t n = ef_q32_format(ef_q32_raw(T[i].v), buf);
        assert_string_equal(buf, T[i].s);
        assert_int_equal(n, strlen(T[i].s));
    }
}

static void test_format_roundtrip(void **state)
{
    (void)state;
    /* format prints the exact value, so parsing it back is the identity
     * (except INT64_MIN = -2^31, which the parser rejects by design). */
    for (int i = 0; i < 200000; i++) {
        int64_t v = i < 1000 ? (int64_t)i - 500 : (i & 1) ? ef_wrap_i64(rnd64()) : rnd_i64();
        if (v == INT64_MIN)
            v = INT64_MIN + 1;
        char buf[48];
        size_t n = ef_q32_format(ef_q32_raw(v), buf);
        CHECK(n < 48 && n == strlen(buf), "format length");
        check_parse(buf, n, EF_NUM_OK, n, v);
    }
    char buf[48];
    size_t n = ef_q32_format(ef_q32_raw(INT64_MIN), buf);
    check_parse(buf, n, EF_NUM_RANGE, n, 0);
}

/* Decimal string arithmetic for the random tie test: "I.F" with F padded to
 * 33 digits, plus the 33-digit expansion of 2^-33. */
static void test_parse_random_ties(void **state)
{
    (void)state;
    static const char HALF_ULP[] = "000000000116415321826934814453125"; /* 2^-33, 33 digits */
    for (int i = 0; i < 20000; i++) {
        int64_t q = (int64_t)(rnd64() >> (1 + rnd64() % 63));
        if (q == INT64_MAX)
            q--;
        char buf[48];
        ef_q32_format(ef_q32_raw(q), buf);
        /* split into integer and fraction, pad the fraction to 33 digits */
        char ip[16], fp[40];
        const char *dot = strchr(buf, '.');
        size_t il = dot ? (size_t)(dot - buf) : strlen(buf);
        memcpy(ip, buf, il);
        ip[il] = '\0';
        memset(fp, '0', 33);
        fp[33] = '\0';
        if (dot)
            memcpy(fp, dot + 1, strlen(dot + 1));
        /* fp += HALF_ULP (no carry out: q's fraction < 1 - 2^-32) */
        int carry = 0;
        for (int k = 32; k >= 0; k--) {
            int d = (fp[k] - '0') + (HALF_ULP[k] - '0') + carry;
            fp[k] = (char)('0' + d % 10);
            carry = d / 10;
        }
        assert_int_equal(carry, 0);
        assert_true(fp[32] == '5'); /* the last digit of 2^-33 */
        char s[160];
        /* exact tie (q + 1/2) ulp: away from zero */
        snprintf(s, sizeof s, "%s.%s", ip, fp);
        check_parse(s, strlen(s), EF_NUM_OK, strlen(s), q + 1);
        snprintf(s, sizeof s, "-%s.%s", ip, fp);
        check_parse(s, strlen(s), EF_NUM_OK, strlen(s), -(q + 1));
        /* the same digits as an integer mantissa with exponent -33 */
        snprintf(s, sizeof s, "%s%se-33", ip, fp);
        check_parse(s, strlen(s), EF_NUM_OK, strlen(s), q + 1);
        /* tie + 10^-60: up */
        snprintf(s, sizeof s, "%s.%s000000000000000000000000001", ip, fp);
        check_parse(s, strlen(s), EF_NUM_OK, strlen(s), q + 1);
        /* tie - 10^-60: the 5 becomes 4 followed by 27 nines: down */
        fp[32] = '4';
        snprintf(s, sizeof s, "%s.%s999999999999999999999999999", ip, fp);
        check_parse(s, strlen(s), EF_NUM_OK, strlen(s), q);
        snprintf(s, sizeof s, "-%s.%s999999999999999999999999999", ip, fp);
        check_parse(s, strlen(s), EF_NUM_OK, strlen(s), -q);
    }
}

/* ------------------------------------------------------------------------
 * CORDIC
 * --------------------------------------------------------------------- */
static const long double PI_L = 3.14159265358979323846264338327950288L;
#define SINCOS_BOUND 1.0L /* docs/fixed.md: |error| < 1 * 2^-30 (header: <= 4) */
#define ATAN2_BOUND 1.0L  /* docs/fixed.md: |error| < 1 unit of 2^-32 turn */

static void check_sincos(ef_angle a)
{
    int32_t s, c;
    ef_sincos(a, &s, &c);
    long double th = (long double)a * (2.0L * PI_L / 4294967296.0L);
    long double es = fabsl((long double)s - sinl(th) * 1073741824.0L);
    long double ec = fabsl((long double)c - cosl(th) * 1073741824.0L);
    CHECK(es <= SINCOS_BOUND && ec <= SINCOS_BOUND, "sincos(%lu): sin %ld (err %.3Lf) cos %ld (err %.3Lf)",
          (unsigned long)a, (long)s, es, (long)c, ec);
    CHECK(s >= -EF_Q30_ONE && s <= EF_Q30_ONE && c >= -EF_Q30_ONE && c <= EF_Q30_ONE, "range");
}

static void test_sincos(void **state)
{
    (void)state;
    int32_t s, c;
    /* exact at multiples of a quarter turn */
    static const struct {
        ef_angle a;
        int32_t s, c;
    } Q[] = {
        { 0, 0, EF_Q30_ONE },
        { 0x40000000u, EF_Q30_ONE, 0 },
        { 0x80000000u, 0, -EF_Q30_ONE },
        { 0xC0000000u, -EF_Q30_ONE, 0 },
        { 0x20000000u, 759250125, 759250125 }, /* 45 deg: 2^30/sqrt2 = 759250124.994 */
    };
    for (size_t i = 0; i < sizeof Q / sizeof Q[0]; i++) {
        ef_sincos(Q[i].a, &s, &c);
        CHECK(s == Q[i].s && c == Q[i].c, "sincos(%lu) = %ld %ld", (unsigned long)Q[i].a, (long)s, (long)c);
    }
    /* a sweep with a stride prime to 2^32, both sides of every quadrant and
     * octant boundary, and random angles */
    for (uint32_t k = 0; k < 300000; k++)
        check_sincos((ef_angle)(k * 14316557u));
    for (uint32_t q = 0; q < 8; q++)
        for (uint32_t d = 0; d < 2000; d++) {
            check_sincos((ef_angle)(q * 0x20000000u + d));
            check_sincos((ef_angle)(q * 0x20000000u - d));
        }
    for (int i = 0; i < 200000; i++)
        check_sincos((ef_angle)rnd64());
    /* exact symmetries, by construction of the reduction */
    for (int i = 0; i < 100000; i++) {
        ef_angle a = (ef_angle)rnd64();
        if (i < 64)
            a = (ef_angle)(i * 0x08000000u);
        int32_t s2, c2;
        ef_sincos(a, &s, &c);
        ef_sincos((ef_angle)(0u - a), &s2, &c2);
        CHECK(s2 == -s && c2 == c, "sincos(-a) != (-sin a, cos a) at a=%lu", (unsigned long)a);
        ef_sincos((ef_angle)(a + 0x40000000u), &s2, &c2);
        CHECK(s2 == c && c2 == -s, "sincos(a + 90) != (cos a, -sin a) at a=%lu", (unsigned long)a);
    }
}

static void check_atan2(int64_t y, int64_t x)
{
    ef_angle a = ef_atan2(y, x);
    long double ref = atan2l((long double)y, (long double)x) * (4294967296.0L / (2.0L * PI_L));
    long double e = (long double)a - ref;
    while (e > 2147483648.0L)
        e -= 4294967296.0L;
    while (e < -2147483648.0L)
        e += 4294967296.0L;
    CHECK(fabsl(e) <= ATAN2_BOUND, "atan2(%lld, %lld) = %lu, err %.3Lf", LL(y), LL(x), (unsigned long)a, e);
}

static void test_atan2(void **state)
{
    (void)state;
    static const struct {
        int64_t y, x;
        ef_angle a;
    } T[] = {
        { 0, 0, 0 },
        { 0, 1, 0 },
        { 0, INT64_MAX, 0 },
        { 1, 0, 0x40000000u },
        { 0, -1, 0x80000000u },
        { -1, 0, 0xC0000000u },
        { 0, INT64_MIN, 0x80000000u },
        { INT64_MIN, 0, 0xC0000000u },
        { INT64_MAX, 0, 0x40000000u },
        { 1, 1, 0x20000000u },
        { 1, -1, 0x60000000u },
        { -1, -1, 0xA0000000u },
        { -1, 1, 0xE0000000u },
        { INT64_MIN, INT64_MIN, 0xA0000000u },
        { INT64_MAX, INT64_MAX, 0x20000000u },
        { 7, 7, 0x20000000u },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        ef_angle a = ef_atan2(T[i].y, T[i].x);
        CHECK(a == T[i].a, "atan2(%lld,%lld) = %lu", LL(T[i].y), LL(T[i].x), (unsigned long)a);
    }
    for (int64_t y = -150; y <= 150; y++)
        for (int64_t x = -150; x <= 150; x++)
            check_atan2(y, x);
    for (int i = 0; i < 200000; i++) {
        int64_t y = rnd_i64(), x = rnd_i64();
        if (i % 5 == 0)
            y = ef_wrap_i64((uint64_t)x + rnd64() % 9 - 4); /* near the diagonal */
        if (i % 7 == 0)
            y = (int64_t)(rnd64() % 5) - 2; /* near the axis */
        check_atan2(y, x);
        if (y != INT64_MIN && x != INT64_MIN) {
            ef_angle a = ef_atan2(y, x);
            CHECK(ef_atan2(-y, x) == (ef_angle)(0u - a) || (y == 0 && x < 0), "atan2 odd in y");
            CHECK(ef_atan2(y, -x) == (ef_angle)(0x80000000u - a) || x == 0, "atan2 mirror in x");
            if (x > 0 && y > 0)
                CHECK(ef_atan2(x, y) == (ef_angle)(0x40000000u - a), "atan2 swap");
        }
    }
    /* round trip through sincos */
    for (int i = 0; i < 100000; i++) {
        ef_angle a = (ef_angle)rnd64();
        int32_t s, c;
        ef_sincos(a, &s, &c);
        int32_t d = ef_wrap_i32((int64_t)(uint32_t)(ef_atan2(s, c) - a));
        CHECK(d >= -2 && d <= 2, "atan2(sincos(%lu)) off by %ld", (unsigned long)a, (long)d);
    }
}

/* A second implementation of docs/fixed.md section 4, written from the text
 * (floor shifts as floor divisions, its own copy of the constants), which
 * must agree with fixed/cordic.c bit for bit. */
static const int64_t SPEC_ATAN[34] = {
    35184372088832, 20770547670515, 10974586953444, 5570871696862, 2796246208089, 1399486241028, 699913886760,
    349978300884,   174991820497,   87496244017,    43748163730,   21874087080,   10937044192,   5468522177,
    2734261099,     1367130551,     683565276,      341782638,     170891319,     85445659,      42722830,
    21361415,       10680707,       5340354,        2670177,       1335088,       667544,        333772,
    166886,         83443,          41722,          20861,         10430,         5215,
};
#define SPEC_KINV INT64_C(667681663043)

static int64_t spec_asr(int64_t v, int n) { return ef_floordiv_i64(v, (int64_t)1 << n); }
static int64_t spec_rnd(int64_t v, int n) { return ef_floordiv_i64(v + ((int64_t)1 << (n - 1)), (int64_t)1 << n); }
static int64_t spec_clamp(int64_t v, int64_t lo, int64_t hi) { return v < lo ? lo : v > hi ? hi : v; }

static void spec_sincos(uint32_t a, int32_t *sin_out, int32_t *cos_out)
{
    uint32_t q = ((a + 0x20000000u) >> 30) & 3u;
    uint32_t ru = a - q * 0x40000000u;
    int neg = ru >= 0x80000000u;
    uint32_t t = neg ? 0u - ru : ru;
    int64_t s, c;
    if (t == 0) {
        s = 0;
        c = (int64_t)1 << 30;
    } else {
        int64_t x = SPEC_KINV, y = 0, z = (int64_t)t * 65536;
        for (int i = 0; i < 34; i++) {
            int64_t dx = spec_asr(y, i), dy = spec_asr(x, i);
            if (z >= 0) {
                x -= dx;
                y += dy;
                z -= SPEC_ATAN[i];
            } else {
                x += dx;
                y -= dy;
                z += SPEC_ATAN[i];
            }
        }
        s = spec_clamp(spec_rnd(y, 10), -((int64_t)1 << 30), (int64_t)1 << 30);
        c = spec_clamp(spec_rnd(x, 10), -((int64_t)1 << 30), (int64_t)1 << 30);
        if (neg)
            s = -s;
    }
    int64_t so = q == 0 ? s : q == 1 ? c : q == 2 ? -s : -c;
    int64_t co = q == 0 ? c : q == 1 ? -s : q == 2 ? -c : s;
    *sin_out = (int32_t)so;
    *cos_out = (int32_t)co;
}

static uint32_t spec_atan2(int64_t y, int64_t x)
{
    uint64_t ax = mag(x), ay = mag(y);
    if (ax == 0 && ay == 0)
        return 0;
    int swap = ay > ax;
    uint64_t hi = swap ? ay : ax, lo = swap ? ax : ay;
    uint32_t phi;
    if (lo == 0) {
        phi = 0;
    } else if (lo == hi) {
        phi = 0x20000000u;
    } else {
        int lz = 0;
        while (!((hi << lz) >> 63))
            lz++;
        if (lz > 23) {
            hi <<= lz - 23;
            lo <<= lz - 23;
        } else {
            hi >>= 23 - lz;
            lo >>= 23 - lz;
        }
        int64_t xx = (int64_t)hi, yy = (int64_t)lo, z = 0;
        for (int i = 0; i < 34; i++) {
            int64_t dx = spec_asr(yy, i), dy = spec_asr(xx, i);
            if (yy >= 0) {
                xx += dx;
                yy -= dy;
                z += SPEC_ATAN[i];
            } else {
                xx -= dx;
                yy += dy;
                z -= SPEC_ATAN[i];
            }
        }
        phi = (uint32_t)spec_clamp(spec_rnd(z, 16), 0, 0x20000000);
    }
    if (swap)
        phi = 0x40000000u - phi;
    if (x >= 0)
        return y >= 0 ? phi : 0u - phi;
    return y >= 0 ? 0x80000000u - phi : 0x80000000u + phi;
}

static void test_cordic_spec(void **state)
{
    (void)state;
    /* The constants of the text, re-derived with libm where long double has
     * at least a 64-bit significand (x86): every table entry's fraction is
     * at least 0.01 away from 1/2, far more than long double's error. */
    if (LDBL_MANT_DIG >= 64) {
        for (int i = 0; i < 34; i++) {
            long double v = atanl(ldexpl(1.0L, -i)) / (2.0L * PI_L) * ldexpl(1.0L, 48);
            CHECK((int64_t)floorl(v + 0.5L) == SPEC_ATAN[i], "ATAN[%d]: %.3Lf", i, v);
        }
        long double k = 1.0L;
        for (int i = 0; i < 34; i++)
            k *= sqrtl(1.0L + ldexpl(1.0L, -2 * i));
        CHECK((int64_t)floorl(ldexpl(1.0L, 40) / k + 0.5L) == SPEC_KINV, "KINV");
    }
    for (int i = 0; i < 400000; i++) {
        uint32_t a = i < 65536 ? (uint32_t)i * 65537u : (uint32_t)rnd64();
        int32_t s, c, s2, c2;
        ef_sincos(a, &s, &c);
        spec_sincos(a, &s2, &c2);
        CHECK(s == s2 && c == c2, "sincos(%lu): lib %ld %ld, spec %ld %ld", (unsigned long)a, (long)s, (long)c,
              (long)s2, (long)c2);
    }
    for (int i = 0; i < 200000; i++) {
        int64_t y = rnd_i64(), x = rnd_i64();
        if (i < 1024) {
            y = (i & 31) - 16;
            x = (i >> 5) - 16;
        }
        if (i == 1024) {
            y = INT64_MIN;
            x = INT64_MAX;
        }
        CHECK(ef_atan2(y, x) == spec_atan2(y, x), "atan2(%lld, %lld)", LL(y), LL(x));
    }
}

/* ---------------------------------------------------------------------------
 * Integer primitives, each against something not derived from it.
 * ------------------------------------------------------------------------ */

/* popcount against a bit-by-bit count: every 16-bit value in both halves and
 * a stride through the rest. */
static void test_popcount32(void **state)
{
    (void)state;
    for (uint64_t k = 0; k < (UINT64_C(1) << 32); k += (k < 65536u ? 1u : 65521u * 3u)) {
        uint32_t vs[2] = { (uint32_t)k, (uint32_t)k << 16 | (uint32_t)k >> 16 };
        for (int j = 0; j < 2; j++) {
            unsigned n = 0;
            for (int b = 0; b < 32; b++)
                n += vs[j] >> b & 1u;
            assert_int_equal(ef_popcount32(vs[j]), n);
        }
    }
    assert_int_equal(ef_popcount32(0xFFFFFFFFu), 32);
}

/* floor divmod of int32 against the definition, checked in 64 bits: q*d + r
 * = a and 0 <= r < d, for a near 0, near the ends and d in 1..300 and huge. */
static void test_divmod_floor_i32(void **state)
{
    (void)state;
    static const int32_t ds[] = { 1, 2, 3, 7, 32, 255, 256, 300, 65536, 1 << 24, INT32_MAX };
    for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++)
        for (int64_t a = -70000; a <= 70000; a += (a > -600 && a < 600) ? 1 : 97) {
            static const int64_t ends[] = { INT32_MIN, INT32_MIN + 1, INT32_MAX - 1, INT32_MAX };
            for (int e = -1; e < 4; e++) {
                int32_t av = (int32_t)(e < 0 ? a : ends[e]), q, r;
                ef_divmod_floor_i32(av, ds[i], &q, &r);
                assert_true((int64_t)q * ds[i] + r == av);
                assert_true(r >= 0 && r < ds[i]);
            }
        }
}

/* uint64 -> int64 modulo 2^64: the value plus a multiple of 2^64, in range. */
static void test_wrap_i64(void **state)
{
    (void)state;
    /* clang-format off */
    static const uint64_t us[] = { 0, 1, (uint64_t)INT64_MAX, (uint64_t)INT64_MAX + 1u, UINT64_MAX, UINT64_MAX - 1u,
                                   UINT64_C(0x8000000000000001), UINT64_C(0x0123456789ABCDEF),
                                   UINT64_C(0xFEDCBA9876543210) };
    /* clang-format on */
    for (size_t i = 0; i < sizeof us / sizeof us[0]; i++) {
        int64_t v = ef_wrap_i64(us[i]);
        assert_true((uint64_t)v == us[i]); /* the conversion back is defined: modulo 2^64 */
        assert_true((v < 0) == (us[i] > (uint64_t)INT64_MAX));
    }
    assert_true(ef_abs_u64(INT64_MIN) == (uint64_t)1 << 63);
    assert_true(ef_abs_u64(-5) == 5u && ef_abs_u64(7) == 7u && ef_abs_u64(0) == 0u);
}

/* The UTF-8 validator against an encoder: the sequences it accepts are
 * exactly the shortest encodings of the scalar values (0..10FFFF without the
 * surrogates).  1, 2 and 3 bytes exhaustively (a 4-byte lead in 3 bytes is
 * 0); 4 bytes by count (every
 * 4-byte encoding accepted, and as many accepted 4-byte sequences as there
 * are supplementary values); and never past n. */
static size_t utf8_encode(uint32_t cp, unsigned char *o)
{
    if (cp < 0x80u) {
        o[0] = (unsigned char)cp;
        return 1;
    }
    if (cp < 0x800u) {
        o[0] = (unsigned char)(0xC0u | cp >> 6);
        o[1] = (unsigned char)(0x80u | (cp & 0x3Fu));
        return 2;
    }
    if (cp < 0x10000u) {
        o[0] = (unsigned char)(0xE0u | cp >> 12);
        o[1] = (unsigned char)(0x80u | (cp >> 6 & 0x3Fu));
        o[2] = (unsigned char)(0x80u | (cp & 0x3Fu));
        return 3;
    }
    o[0] = (unsigned char)(0xF0u | cp >> 18);
    o[1] = (unsigned char)(0x80u | (cp >> 12 & 0x3Fu));
    o[2] = (unsigned char)(0x80u | (cp >> 6 & 0x3Fu));
    o[3] = (unsigned char)(0x80u | (cp & 0x3Fu));
    return 4;
}

static void test_utf8_len(void **state)
{
    (void)state;
    static unsigned char valid3[1u << 21]; /* bit per 3-byte sequence */
    static unsigned char valid2[1u << 13];
    memset(valid3, 0, sizeof valid3);
    memset(valid2, 0, sizeof valid2);
    uint64_t n4 = 0;
    for (uint32_t cp = 0; cp <= 0x10FFFFu; cp++) {
        unsigned char e[4];
        if (cp >= 0xD800u && cp <= 0xDFFFu)
            continue;
        size_t len = utf8_encode(cp, e);
        assert_int_equal(ef_utf8_len(e, len), len);
        assert_int_equal(ef_utf8_len(e, len - 1), 0); /* one byte short: never read past n */
        if (len == 2) {
            uint32_t k = (uint32_t)e[0] << 8 | e[1];
            valid2[k >> 3] |= (unsigned char)(1u << (k & 7u));
        } else if (len == 3) {
            uint32_t k = (uint32_t)e[0] << 16 | (uint32_t)e[1] << 8 | e[2];
            valid3[k >> 3] |= (unsigned char)(1u << (k & 7u));
        } else if (len == 4) {
            n4++;
        }
    }
    assert_int_equal(n4, 0x100000u);
    for (uint32_t k = 0; k < (1u << 24); k++) {
        unsigned char s[3] = { (unsigned char)(k >> 16), (unsigned char)(k >> 8), (unsigned char)k };
        size_t got = ef_utf8_len(s, 3);
        uint32_t k2 = k >> 8;
        size_t want = s[0] < 0x80u                          ? 1
                      : (valid2[k2 >> 3] >> (k2 & 7u) & 1u) ? 2
                      : (valid3[k >> 3] >> (k & 7u) & 1u)   ? 3
                                                            : 0;
        assert_int_equal(got, want);
    }
    uint64_t acc4 = 0;
    for (uint32_t k = 0; k < (1u << 24); k++) {
        for (unsigned lead = 0xF0u; lead <= 0xF7u; lead++) {
            unsigned char s[4] = { (unsigned char)lead, (unsigned char)(k >> 16), (unsigned char)(k >> 8),
                                   (unsigned char)k };
            size_t got = ef_utf8_len(s, 4);
            assert_true(got == 0 || got == 4);
            acc4 += got == 4;
        }
    }
    assert_int_equal(acc4, 0x100000u); /* with every encoding accepted: exactly those */
    assert_int_equal(ef_utf8_len((const unsigned char *)"", 0), 0);
}

static void test_angle_from_deg(void **state)
{
    (void)state;
    static const struct {
        int64_t deg;
        ef_angle a;
    } T[] = {
        { 0, 0 },
        { 90 * EF_Q32_ONE, 0x40000000u },
        { 45 * EF_Q32_ONE, 0x20000000u },
        { 180 * EF_Q32_ONE, 0x80000000u },
        { 360 * EF_Q32_ONE, 0 },
        { -90 * EF_Q32_ONE, 0xC0000000u },
        { 450 * EF_Q32_ONE, 0x40000000u },
        { EF_Q32_ONE, 11930465u }, /* 2^32 / 360 = 11930464.71 */
        { -EF_Q32_ONE, 0u - 11930465u },
        { 180, 1 }, /* 0.5 unit: tie away from zero */
        { -180, 0xFFFFFFFFu },
        { 179, 0 },
        { 181, 1 },
        { 540, 2 }, /* 1.5 -> 2 */
        { -540, 0xFFFFFFFEu },
    };
    for (size_t i = 0; i < sizeof T / sizeof T[0]; i++) {
        ef_angle a = ef_angle_from_deg_q32(ef_q32_raw(T[i].deg));
        CHECK(a == T[i].a, "angle_from_deg(%lld) = %lu want %lu", LL(T[i].deg), (unsigned long)a,
              (unsigned long)T[i].a);
    }
    /* Extremes and random values against long division in the slow model. */
    for (int i = 0; i < 50000; i++) {
        int64_t d = i == 0 ? INT64_MIN : i == 1 ? INT64_MAX : rnd_i64();
        big m = ref_round_half_up(big_u64(mag(d)), big_u64(360));
        uint32_t want = (uint32_t)big_word(m, 0);
        if (d < 0)
            want = 0u - want;
        ef_angle a = ef_angle_from_deg_q32(ef_q32_raw(d));
        CHECK(a == want, "angle_from_deg(%lld) = %lu want %lu", LL(d), (unsigned long)a, (unsigned long)want);
        if (d != INT64_MIN)
            CHECK(ef_angle_from_deg_q32(ef_q32_raw(-d)) == (ef_angle)(0u - a), "angle_from_deg odd at %lld", LL(d));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_floor_div_mod),    cmocka_unit_test(test_ceil_round_div),
        cmocka_unit_test(test_asr_shl_wrap),     cmocka_unit_test(test_round_shr),
        cmocka_unit_test(test_checked_add),      cmocka_unit_test(test_mul_wide),
        cmocka_unit_test(test_checked_mul),      cmocka_unit_test(test_div_u128),
        cmocka_unit_test(test_q32_mul),          cmocka_unit_test(test_q32_div),
        cmocka_unit_test(test_muldiv),           cmocka_unit_test(test_isqrt),
        cmocka_unit_test(test_q32_sqrt),         cmocka_unit_test(test_parse_table),
        cmocka_unit_test(test_parse_long),       cmocka_unit_test(test_format_table),
        cmocka_unit_test(test_format_roundtrip), cmocka_unit_test(test_parse_random_ties),
        cmocka_unit_test(test_sincos),           cmocka_unit_test(test_atan2),
        cmocka_unit_test(test_cordic_spec),      cmocka_unit_test(test_angle_from_deg),
        cmocka_unit_test(test_popcount32),       cmocka_unit_test(test_divmod_floor_i32),
        cmocka_unit_test(test_wrap_i64),         cmocka_unit_test(test_utf8_len),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
