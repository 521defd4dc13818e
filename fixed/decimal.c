/*
 * decimal.c - exact decimal text <-> Q31.32.
 *
 * Place in the pipeline: the very first step.  Every coordinate, transform
 * coefficient and angle of a scene file enters through ef_parse_decimal_q32,
 * so its result must not depend on the C library (strtod, locale, float
 * rounding): it is defined on the exact rational value of the text.
 *
 * Why only 43 digit positions are needed, and no sticky bit
 * ---------------------------------------------------------
 * Let v >= 0 be the exact value of the text.  The answer is
 *     q = floor(v * 2^32 + 1/2)  (ties away from zero once the sign is put back)
 *       = floor((floor(v * 2^33) + 1) / 2)                                  (1)
 * and, because 2^33 = 10^33 / 5^33 and floor(floor(x) / n) = floor(x / n) for
 * real x >= 0 and integer n >= 1,
 *     floor(v * 2^33) = floor(floor(v * 10^33) / 5^33).                     (2)
 * So q depends only on N = floor(v * 10^33): the digits at positions 10^9 down
 * to 10^-33.  Digits below 10^-33 cannot change the result, not even break a
 * tie: every tie point (2k+1) / 2^33 is itself a multiple of 10^-33, so the
 * truncated digits can never move v across one (this is why no sticky bit is
 * kept).  A non-zero digit at 10^10 or above means v >= 10^10 > 2^31: range
 * error.  Hence N < 10^43 < 2^143, held exactly in five 32-bit limbs.
 *
 * Cost: one pass over the text, then at most five multiply-by-10^9 steps
 * and three divisions by 5^11 over five limbs; the exponent never drives a
 * loop.
 */
#include "fixed_internal.h"

#define DEC_INT_POS 10  /* positions 10^0 .. 10^9: |v| < 2^31 < 10^10 */
#define DEC_FRAC_POS 33 /* positions 10^-1 .. 10^-33, see (2) */
#define DEC_SLOTS (DEC_INT_POS + DEC_FRAC_POS)
#define DEC_LIMBS 5
#define FIVE_POW_11 UINT32_C(48828125) /* 5^33 = (5^11)^3; 5^11 < 2^26 */
/* Saturation bound for the exponent.  Exact as long as the text is shorter
 * than 10^18 - 43 characters: a larger exponent then moves every non-zero
 * digit out of range (or below 10^-33) just as the capped one does. */
#define DEC_EXP_CAP INT64_C(1000000000000000000)

/* N < 10^43 <= 10^45 = 1000^15 < 1024^15 = 2^150 <= 2^(32 * DEC_LIMBS). */
_Static_assert(((DEC_SLOTS + 2) / 3) * 10 <= 32 * DEC_LIMBS, "N = floor(v*10^33) fits the limbs");
_Static_assert(DEC_FRAC_POS == 3 * 11, "5^33 is divided out as three divisions by 5^11");
/* floor(v*2^33) for v < 10^10 is < 2^67: after dividing out 5^33 it must be
 * tested against 2^64 (limbs 2..4 zero), not assumed to fit. */

static bool is_digit(char c) { return c >= '0' && c <= '9'; }

/* n = n * m + a over little-endian limbs, m <= 10^9, a < m.  Never carries
 * out of the top limb (N < 2^150, static assertion above). */
static void limbs_mul_add(uint32_t n[DEC_LIMBS], uint32_t m, uint32_t a)
{
    uint64_t carry = a;
    for (int k = 0; k < DEC_LIMBS; k++) {
        uint64_t cur = (uint64_t)n[k] * m + carry; /* < 2^62 + 2^32 */
        n[k] = (uint32_t)cur;
        carry = cur >> 32;
    }
}

/* n = floor(n / d) for 0 < d < 2^32, schoolbook from the top limb. */
static void limbs_div_small(uint32_t n[DEC_LIMBS], uint32_t d)
{
    uint64_t rem = 0;
    for (int k = DEC_LIMBS - 1; k >= 0; k--) {
        uint64_t cur = (rem << 32) | n[k]; /* rem < d: < 2^64 */
        n[k] = (uint32_t)(cur / d);
        rem = cur % d;
    }
}

ef_num_status ef_parse_decimal_q32(const char *s, size_t len, ef_q32 *out, size_t *consumed)
{
    size_t i = 0;
    bool negative = false;

    /* ---- syntax: [+-]? ( digits ( '.' digits? )? | '.' digits ) ---- */
    if (i < len && (s[i] == '+' || s[i] == '-')) {
        negative = s[i] == '-';
        i++;
    }
    size_t int_begin = i;
    while (i < len && is_digit(s[i]))
        i++;
    size_t int_end = i;
    size_t frac_begin = i, frac_end = i;
    if (i < len && s[i] == '.') {
        size_t j = i + 1;
        while (j < len && is_digit(s[j]))
            j++;
        if (int_end > int_begin || j > i + 1) { /* "1." and ".5", not "." */
            frac_begin = i + 1;
            frac_end = j;
            i = j;
        }
    }
    if (int_end == int_begin && frac_end == frac_begin) {
        if (consumed)
            *consumed = 0;
        return EF_NUM_SYNTAX;
    }

    /* ---- optional exponent ( [eE] [+-]? digits ); consumed only whole ---- */
    int64_t exp10 = 0;
    if (i < len && (s[i] == 'e' || s[i] == 'E')) {
        size_t j = i + 1;
        bool exp_negative = false;
        if (j < len && (s[j] == '+' || s[j] == '-')) {
            exp_negative = s[j] == '-';
            j++;
        }
        size_t exp_begin = j;
        int64_t e = 0;
        while (j < len && is_digit(s[j])) {
            /* Saturate at the cap (see its comment); never overflows. */
            e = e <= (DEC_EXP_CAP - 9) / 10 ? e * 10 + (s[j] - '0') : DEC_EXP_CAP;
            j++;
        }
        if (j > exp_begin) {
            exp10 = exp_negative ? -e : e;
            i = j;
        }
    }
    if (consumed)
        *consumed = i;

    /* ---- place digits: slot k holds position 10^(DEC_INT_POS - 1 - k) ---- */
    unsigned char slot[DEC_SLOTS] = { 0 };
    int first = DEC_SLOTS; /* first non-zero slot */
    /* Position of the leading digit; counts are text offsets (< 10^18). */
    int64_t pos = exp10 + (int64_t)(int_end - int_begin) - 1;
    for (size_t k = int_begin; k < frac_end; k++) {
        if (k == int_end)
            k = frac_begin; /* step over the '.' */
        if (k >= frac_end)
            break;
        if (pos < -DEC_FRAC_POS)
            break; /* every later digit is below 10^-33 */
        unsigned d = (unsigned)(s[k] - '0');
        if (d != 0) {
            if (pos >= DEC_INT_POS)
                return EF_NUM_RANGE; /* v >= 10^10 */
            int idx = (int)(DEC_INT_POS - 1 - pos);
            slot[idx] = (unsigned char)d;
            if (idx < first)
                first = idx;
        }
        pos--;
    }

    /* ---- N = floor(v * 10^33); t = floor(N / 5^33) = floor(v * 2^33) ---- */
    uint32_t n[DEC_LIMBS] = { 0 };
    for (int k = first; k < DEC_SLOTS;) { /* Horner, nine digits a step */
        uint32_t chunk = 0, scale = 1;
        for (int j = 0; j < 9 && k < DEC_SLOTS; j++, k++) {
            chunk = chunk * 10u + slot[k];
            scale *= 10u;
        }
        limbs_mul_add(n, scale, chunk);
    }
    limbs_div_small(n, FIVE_POW_11);
    limbs_div_small(n, FIVE_POW_11);
    limbs_div_small(n, FIVE_POW_11);
    for (int k = 2; k < DEC_LIMBS; k++)
        if (n[k] != 0)
            return EF_NUM_RANGE; /* v * 2^33 >= 2^64 */
    uint64_t t = ((uint64_t)n[1] << 32) | n[0];

    /* (1): round half up on the magnitude = ties away from zero overall. */
    uint64_t q = (t >> 1) + (t & 1u);
    if (q > (uint64_t)INT64_MAX)
        return EF_NUM_RANGE; /* |v| rounds to >= 2^31 */
    if (out)
        out->v = negative ? -(int64_t)q : (int64_t)q;
    return EF_NUM_OK;
}

size_t ef_q32_format(ef_q32 v, char *buf)
{
    /* |v| < 2^63 + 1, so the integer part has at most 10 digits
     * (2147483648) and the fraction at most 32 (2^-32 needs exactly 32):
     * 1 + 10 + 1 + 32 + NUL = 45 <= 48 bytes. */
    size_t n = 0;
    uint64_t m = ef_abs_u64(v.v);
    if (v.v < 0)
        buf[n++] = '-';

    char tmp[10];
    size_t t = 0;
    uint32_t ip = (uint32_t)(m >> 32);
    do {
        tmp[t++] = (char)('0' + ip % 10u);
        ip /= 10u;
    } while (ip != 0);
    while (t > 0)
        buf[n++] = tmp[--t];

    /* Fraction f / 2^32: each step f*10 < 10 * 2^32 fits uint64; the digit
     * is the part above 2^32.  Stops when the remainder is zero, so no
     * trailing zeros are written. */
    uint64_t f = m & UINT64_C(0xFFFFFFFF);
    if (f != 0) {
        buf[n++] = '.';
        while (f != 0) {
            f *= 10u;
            buf[n++] = (char)('0' + (unsigned)(f >> 32));
            f &= UINT64_C(0xFFFFFFFF);
        }
    }
    buf[n] = '\0';
    return n;
}
