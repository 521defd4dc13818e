/*
 * cordic.c - sin/cos of a binary angle and atan2 to a binary angle.
 *
 * Place in the pipeline: rotate() transforms and elliptical arcs in the front
 * end.  The algorithm is specified bit for bit in docs/fixed.md ("CORDIC") so
 * that an RTL implementation reproduces these outputs exactly; keep the two in
 * step.  Summary:
 *   - quadrant reduction to the nearest multiple of 90 degrees, then folding
 *     the residual to t in [0, 45] degrees using sin(-t) = -sin(t);
 *   - 34 CORDIC iterations (shift 0..33) on x, y with 40 fraction bits and the
 *     angle z in units of 2^-48 turn (angle table below);
 *   - rotation mode for sincos starting from x = 1/K (gain pre-compensated),
 *     vectoring mode for atan2 on the operands normalised to [2^40, 2^41);
 *   - results rounded once at the end (round half up).
 * Every right shift is ef_asr_i64 (floor), as in the hardware.
 */
#include "fixed_internal.h"

#define CORDIC_ITER 34  /* iterations, shifts 0 .. 33 */
#define CORDIC_FRAC 40  /* fraction bits of x and y */
#define CORDIC_ZBITS 48 /* z unit: 2^-48 turn */
/* Extra angle bits over ef_angle (2^-32 turn). */
#define CORDIC_ZSHIFT (CORDIC_ZBITS - 32)

/* ATAN_TAB[i] = round(atan(2^-i) / (2*pi) * 2^48), computed offline with 300-bit
 * arithmetic.  Entry 0 is exactly 1/8 turn = 2^45. */
static const int64_t ATAN_TAB[CORDIC_ITER] = {
    INT64_C(35184372088832), INT64_C(20770547670515), INT64_C(10974586953444), INT64_C(5570871696862),
    INT64_C(2796246208089),  INT64_C(1399486241028),  INT64_C(699913886760),   INT64_C(349978300884),
    INT64_C(174991820497),   INT64_C(87496244017),    INT64_C(43748163730),    INT64_C(21874087080),
    INT64_C(10937044192),    INT64_C(5468522177),     INT64_C(2734261099),     INT64_C(1367130551),
    INT64_C(683565276),      INT64_C(341782638),      INT64_C(170891319),      INT64_C(85445659),
    INT64_C(42722830),       INT64_C(21361415),       INT64_C(10680707),       INT64_C(5340354),
    INT64_C(2670177),        INT64_C(1335088),        INT64_C(667544),         INT64_C(333772),
    INT64_C(166886),         INT64_C(83443),          INT64_C(41722),          INT64_C(20861),
    INT64_C(10430),          INT64_C(5215),
};
_Static_assert(sizeof ATAN_TAB / sizeof ATAN_TAB[0] == CORDIC_ITER, "one angle per iteration");

/* round(2^40 / K), K = prod_{i=0}^{33} sqrt(1 + 2^-2i) = 1.646760258121...;
 * 2^40 / K = 667681663043.3686 (the same to 12 digits for any count >= 32). */
#define CORDIC_KINV INT64_C(667681663043)

/* Bit budgets (docs/fixed.md 4.3).  sincos: the vector length stays ~2^40
 * (plus at most 68 units of floor error), so |x|, |y| < 2^(FRAC+1).  atan2:
 * x0 < 2^(FRAC+1), y0 <= x0, and the length grows by K < 1.65 to at most
 * 1.65 * sqrt(2) * 2^(FRAC+1) < 2^(FRAC+3).  z: |z| <= sum of the table
 * = 0.2775 turn < 2^(ZBITS-1) in vectoring mode, <= 2 * ATAN_TAB[0] =
 * 2^(ZBITS-2) in rotation mode.  All of it fits int64 with room to spare. */
_Static_assert(CORDIC_FRAC + 3 < 63, "atan2: |x| < 2^43 fits int64");
_Static_assert(CORDIC_ZBITS - 1 < 63, "z fits int64");
_Static_assert(CORDIC_ITER - 1 < CORDIC_FRAC, "the last shift still sees bits of x and y");
_Static_assert(CORDIC_FRAC >= 30 + 1, "rounding to Q1.30 shifts right by at least 1");

/* Rotation mode: z0 = t * 2^16 (t in [0, 2^29] units of 2^-32 turn, i.e.
 * 0..45 degrees), x0 = 1/K, y0 = 0.  Returns cos t, sin t with 40 fraction
 * bits. */
static void cordic_rotate(uint32_t t, int64_t *xc, int64_t *ys)
{
    int64_t x = CORDIC_KINV, y = 0;
    int64_t z = (int64_t)t * ((int64_t)1 << CORDIC_ZSHIFT);
    for (unsigned i = 0; i < CORDIC_ITER; i++) {
        int64_t dx = ef_asr_i64(y, i), dy = ef_asr_i64(x, i);
        if (z >= 0) { /* rotate counter-clockwise */
            x -= dx;
            y += dy;
            z -= ATAN_TAB[i];
        } else {
            x += dx;
            y -= dy;
            z += ATAN_TAB[i];
        }
    }
    *xc = x;
    *ys = y;
}

/* Vectoring mode: x0 >= y0 >= 0, x0 in [2^40, 2^41).  Drives y to 0 and
 * returns the accumulated angle atan(y0 / x0) in units of 2^-48 turn. */
static int64_t cordic_vector(int64_t x, int64_t y)
{
    int64_t z = 0;
    for (unsigned i = 0; i < CORDIC_ITER; i++) {
        int64_t dx = ef_asr_i64(y, i), dy = ef_asr_i64(x, i);
        if (y >= 0) { /* rotate clockwise */
            x += dx;
            y -= dy;
            z += ATAN_TAB[i];
        } else {
            x -= dx;
            y += dy;
            z -= ATAN_TAB[i];
        }
    }
    return z;
}

/* Round a 40-fraction-bit value to Q1.30 (half up) and clamp to [-1, 1]. */
static int32_t to_q30(int64_t v)
{
    int64_t r = ef_round_shr_i64(v, CORDIC_FRAC - 30);
    return (int32_t)ef_clamp_i64(r, -(int64_t)EF_Q30_ONE, (int64_t)EF_Q30_ONE);
}

void ef_sincos(ef_angle a, int32_t *sin_q30, int32_t *cos_q30)
{
    /* Nearest quadrant q (mod 4) and the residual r = a - q * 2^30 as a
     * signed value in [-2^29, 2^29). */
    uint32_t q = ((a + (EF_ANGLE_QUARTER_TURN >> 1)) >> 30) & 3u;
    uint32_t ru = a - (q << 30);
    bool negative = ru >= EF_ANGLE_HALF_TURN;
    uint32_t t = negative ? 0u - ru : ru; /* |r| in [0, 2^29] */

    int32_t s, c;
    if (t == 0) {
        s = 0; /* exact at multiples of 90 deg */
        c = EF_Q30_ONE;
    } else {
        int64_t x, y;
        cordic_rotate(t, &x, &y);
        s = to_q30(y);
        c = to_q30(x);
        if (negative)
            s = -s; /* sin(-t) = -sin t, cos(-t) = cos t */
    }
    /* Rotate by q quarter turns: exact swaps and negations. */
    switch (q) {
    case 0:
        *sin_q30 = s;
        *cos_q30 = c;
        break;
    case 1:
        *sin_q30 = c;
        *cos_q30 = -s;
        break;
    case 2:
        *sin_q30 = -s;
        *cos_q30 = -c;
        break;
    default:
        *sin_q30 = -c;
        *cos_q30 = s;
        break;
    }
}

ef_angle ef_atan2(int64_t y, int64_t x)
{
    uint64_t ax = ef_abs_u64(x), ay = ef_abs_u64(y);
    if (ax == 0 && ay == 0)
        return 0;

    /* Fold to the first octant: phi = atan(lo / hi) in [0, 45] degrees. */
    bool swap = ay > ax;
    uint64_t hi = swap ? ay : ax, lo = swap ? ax : ay;
    uint32_t phi;
    if (lo == 0) {
        phi = 0; /* exact on the axes */
    } else if (lo == hi) {
        phi = EF_ANGLE_QUARTER_TURN >> 1; /* exact on the diagonals */
    } else {
        /* Normalise hi into [2^40, 2^41) with the same shift on lo (the ratio
         * is kept to 2^-40 relative when shifting right, exactly otherwise). */
        unsigned lz = ef_clz_u64(hi), want = 63u - CORDIC_FRAC;
        if (lz > want) {
            hi <<= lz - want;
            lo <<= lz - want;
        } else {
            hi >>= want - lz;
            lo >>= want - lz;
        }
        int64_t z = cordic_vector((int64_t)hi, (int64_t)lo);
        int64_t p = ef_round_shr_i64(z, CORDIC_ZSHIFT);
        phi = (uint32_t)ef_clamp_i64(p, 0, (int64_t)(EF_ANGLE_QUARTER_TURN >> 1));
    }
    if (swap)
        phi = EF_ANGLE_QUARTER_TURN - phi; /* atan(h/l) = 90 - atan(l/h) */

    /* Unfold the quadrant; all arithmetic is modulo one turn. */
    if (x >= 0)
        return y >= 0 ? phi : (ef_angle)(0u - phi);
    return y >= 0 ? (ef_angle)(EF_ANGLE_HALF_TURN - phi) : (ef_angle)(EF_ANGLE_HALF_TURN + phi);
}

ef_angle ef_angle_from_deg_q32(ef_q32 deg)
{
    /* deg.v / 2^32 degrees = deg.v / 360 units of 2^-32 turn.  Rounded to
     * nearest with ties away from zero (so negating the input negates the
     * angle exactly), via floor division because -INT64_MIN overflows. */
    int64_t q, r;
    ef_divmod_floor_i64(deg.v, 360, &q, &r); /* deg.v = 360 q + r, 0 <= r < 360 */
    if (r > 180 || (r == 180 && q >= 0))
        q += 1;
    return (ef_angle)(uint32_t)(uint64_t)q; /* modulo one turn */
}
