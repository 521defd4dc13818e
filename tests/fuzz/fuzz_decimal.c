/*
 * fuzz_decimal.c - libFuzzer target for ef_parse_decimal_q32 (fixed/decimal.c),
 * checked against an independent slow exact parse written here.
 *
 * The reference follows docs/input.md section 1 literally: it reads the
 * grammar on its own, keeps the digits as a big integer D and the exponent E
 * (value = D * 10^E), and computes q = floor(|v| * 2^32 + 1/2) by big-integer
 * long division, with no digit window and none of decimal.c's reasoning about
 * which digits matter.  Only the obviously-decided cases are short-cut:
 * v >= 10^10 (range) and v < 10^-12 (rounds to 0).  Both must agree on the
 * status, on the characters consumed and on every bit of the value; the
 * value must be odd in the sign, and ef_q32_format's exact decimal of every
 * result must parse back to the same value.
 *
 * Input: the bytes are the text (any bytes; the parser stops where the
 * grammar does).  The reference handles up to 4000 characters, a few
 * thousand digits; longer inputs only run the parser.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ef_fixed.h"

#define FAIL(...) \
    do { \
        fprintf(stderr, "fuzz_decimal: property violated: "); \
        fprintf(stderr, __VA_ARGS__); \
        fputc('\n', stderr); \
        abort(); \
    } while (0)

/* ------------------------------------------------------- big naturals */
#define LIMBS 520 /* 16640 bits: 4000 digits (13288 bits) + 10^k, k <= 4012 */
#define MAXREF 4000

typedef struct big {
    uint32_t l[LIMBS];
} big;

static void big_zero(big *a) { memset(a, 0, sizeof *a); }

static void big_mul_add(big *a, uint32_t m, uint32_t add)
{
    uint64_t c = add;
    for (int i = 0; i < LIMBS; i++) {
        uint64_t t = (uint64_t)a->l[i] * m + c;
        a->l[i] = (uint32_t)t;
        c = t >> 32;
    }
    if (c)
        FAIL("reference bignum overflow");
}

static void big_add(big *a, const big *b)
{
    uint64_t c = 0;
    for (int i = 0; i < LIMBS; i++) {
        uint64_t t = (uint64_t)a->l[i] + b->l[i] + c;
        a->l[i] = (uint32_t)t;
        c = t >> 32;
    }
    if (c)
        FAIL("reference bignum overflow");
}

/* a <<= s; the bits shifted out must be zero. */
static void big_shl(big *a, unsigned s)
{
    unsigned w = s / 32, b = s % 32;
    for (int i = LIMBS - 1; i >= LIMBS - (int)w - 1 && i >= 0; i--)
        if (i >= LIMBS - (int)w ? a->l[i] != 0 : b && (a->l[i] >> (32 - b)) != 0)
            FAIL("reference bignum overflow");
    for (int i = LIMBS - 1; i >= 0; i--) {
        uint64_t v = 0;
        if (i >= (int)w)
            v = (uint64_t)a->l[i - (int)w] << b;
        if (b && i >= (int)w + 1)
            v |= a->l[i - (int)w - 1] >> (32 - b);
        a->l[i] = (uint32_t)v;
    }
}

static int big_cmp(const big *a, const big *b)
{
    for (int i = LIMBS - 1; i >= 0; i--)
        if (a->l[i] != b->l[i])
            return a->l[i] < b->l[i] ? -1 : 1;
    return 0;
}

static void big_sub(big *a, const big *b) /* a >= b */
{
    int64_t br = 0;
    for (int i = 0; i < LIMBS; i++) {
        int64_t t = (int64_t)a->l[i] - b->l[i] - br;
        br = t < 0;
        a->l[i] = (uint32_t)(t + (br ? ((int64_t)1 << 32) : 0));
    }
}

/* floor(a / b) if below 2^63 (true), else false.  a is destroyed. */
static bool big_div_q63(big *a, const big *b, uint64_t *q)
{
    big t = *b;
    big_shl(&t, 63);
    if (big_cmp(a, &t) >= 0)
        return false;
    uint64_t r = 0;
    for (int bit = 62; bit >= 0; bit--) {
        t = *b;
        big_shl(&t, (unsigned)bit);
        if (big_cmp(a, &t) >= 0) {
            big_sub(a, &t);
            r |= (uint64_t)1 << bit;
        }
    }
    *q = r;
    return true;
}

/* ------------------------------------------------------ the reference */
static bool dig(char c) { return c >= '0' && c <= '9'; }

static ef_num_status ref_parse(const char *s, size_t len, int64_t *out, size_t *consumed)
{
    size_t i = 0;
    bool neg = false;
    if (i < len && (s[i] == '-' || s[i] == '+'))
        neg = s[i++] == '-';
    size_t a0 = i;
    while (i < len && dig(s[i]))
        i++;
    size_t a1 = i, f0 = i, f1 = i;
    if (i < len && s[i] == '.') {
        size_t j = i + 1;
        while (j < len && dig(s[j]))
            j++;
        if (a1 > a0 || j > i + 1) {
            f0 = i + 1;
            f1 = j;
            i = j;
        }
    }
    if (a1 == a0 && f1 == f0) {
        *consumed = 0;
        return EF_NUM_SYNTAX;
    }
    int64_t e = 0;
    if (i < len && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        bool en = false;
        if (j < len && (s[j] == '-' || s[j] == '+'))
            en = s[j++] == '-';
        size_t d0 = j;
        while (j < len && dig(s[j])) {
            if (e < 1000000000)
                e = e * 10 + (s[j] - '0');
            j++;
        }
        if (j > d0) {
            i = j;
            if (en)
                e = -e;
        }
    }
    *consumed = i;

    /* digits of D, without leading and trailing zeros; E adjusted */
    static char d[MAXREF + 8];
    size_t nd = 0;
    for (size_t k = a0; k < a1; k++)
        d[nd++] = s[k];
    for (size_t k = f0; k < f1; k++)
        d[nd++] = s[k];
    e -= (int64_t)(f1 - f0);
    size_t lead = 0;
    while (lead < nd && d[lead] == '0')
        lead++;
    while (nd > lead && d[nd - 1] == '0') {
        nd--;
        e++;
    }
    if (nd == lead) {
        *out = 0;
        return EF_NUM_OK;
    }
    int64_t n = (int64_t)(nd - lead);
    if (n - 1 + e >= 10)
        return EF_NUM_RANGE; /* v >= 10^10 > 2^31 */
    if (n + e <= -12) {      /* v < 10^-12 < 2^-33: rounds to 0 */
        *out = 0;
        return EF_NUM_OK;
    }
    static big A, B;
    big_zero(&A);
    for (size_t k = lead; k < nd; k++)
        big_mul_add(&A, 10, (uint32_t)(d[k] - '0'));
    big_zero(&B);
    B.l[0] = 1;
    if (e >= 0) {
        for (int64_t k = 0; k < e; k++)
            big_mul_add(&A, 10, 0);
    } else {
        for (int64_t k = 0; k < -e; k++)
            big_mul_add(&B, 10, 0);
    }
    /* q = floor((2 D 10^e+ 2^32 + 10^k) / (2 10^k)), the magnitude rounded half up */
    big_shl(&A, 33);
    big_add(&A, &B);
    big_shl(&B, 1);
    uint64_t q;
    if (!big_div_q63(&A, &B, &q))
        return EF_NUM_RANGE;
    *out = neg ? -(int64_t)q : (int64_t)q;
    return EF_NUM_OK;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *s = (const char *)data;
    ef_q32 v = ef_q32_raw(0x5A5A5A5A);
    size_t used = 12345;
    ef_num_status st = ef_parse_decimal_q32(s, size, &v, &used);
    if (used > size)
        FAIL("consumed %zu of %zu", used, size);
    if (st == EF_NUM_SYNTAX && used != 0)
        FAIL("syntax error consumed %zu", used);
    if (st != EF_NUM_SYNTAX && used == 0)
        FAIL("a number of no characters");
    if (st == EF_NUM_RANGE && v.v != 0x5A5A5A5A)
        FAIL("a range error wrote the output");

    if (size <= MAXREF) {
        int64_t want = 0;
        size_t wused = 0;
        ef_num_status ws = ref_parse(s, size, &want, &wused);
        if (ws != st)
            FAIL("status %d, reference %d for '%.*s'", (int)st, (int)ws, (int)(size > 200 ? 200 : size), s);
        if (wused != used)
            FAIL("consumed %zu, reference %zu", used, wused);
        if (st == EF_NUM_OK && want != v.v)
            FAIL("value %" PRId64 ", reference %" PRId64 " for '%.*s'", v.v, want, (int)(size > 200 ? 200 : size), s);
    }

    if (st == EF_NUM_OK) {
        /* The sign is symmetric: "-x" is exactly -"x" (when x has no sign). */
        if (size > 0 && size < 8192 && s[0] != '-' && s[0] != '+') {
            static char t[8193];
            t[0] = '-';
            memcpy(t + 1, s, size);
            ef_q32 m;
            size_t mu;
            if (ef_parse_decimal_q32(t, size + 1, &m, &mu) != EF_NUM_OK || mu != used + 1 || m.v != -v.v)
                FAIL("parse(\"-x\") != -parse(\"x\")");
        }
        /* The exact decimal of the result reads back to the same bits. */
        char buf[48];
        size_t n = ef_q32_format(v, buf);
        ef_q32 r;
        size_t ru;
        if (n != strlen(buf) || ef_parse_decimal_q32(buf, n, &r, &ru) != EF_NUM_OK || ru != n || r.v != v.v)
            FAIL("format/parse round trip of %" PRId64 " gave '%s'", v.v, buf);
    }
    return 0;
}
