/*
 * transform.c - the current transformation matrix (CTM) in Q31.32 and the
 * SVG transform-list grammar.
 *
 * Place in the pipeline: between parsed user coordinates (Q31.32) and the
 * device formats.  The CTM maps user space to device pixels:
 *
 *     x' = a x + c y + e,   y' = b x + d y + f      (a..f in Q31.32)
 *
 * Images of points are computed EXACTLY (each product a*x is the full 128-bit
 * product of two Q31.32 values, i.e. a value in units of 2^-64) and rounded
 * ONCE to the target format with floor(v + 1/2) (ties toward +inf): Q16.8 for
 * straight-segment vertices, Q47.16 for curve control points.  So a vertex's
 * device position depends only on the text and the CTM, never on an order
 * of intermediate roundings.
 *
 * Composing matrices (nested transforms, viewBox) rounds each coefficient
 * once to Q31.32 from its exact sum of products; that rounding is part of the
 * contract (docs/input.md, "Transforms").
 */
#include "input_internal.h"

/* ---------------------------------------------------------- 128 bits */

bool ef_in_i128_exceeds(ef_i128 v, unsigned bits)
{
    uint64_t hi = (uint64_t)v.hi, lo = v.lo;
    if (v.hi < 0) { /* magnitude: two's complement negate */
        lo = ~lo + 1u;
        hi = ~hi + (lo == 0 ? 1u : 0u);
        if (hi >> 63)
            return true; /* -2^127 */
    }
    if (bits >= 64)
        return (hi >> (bits - 64)) != 0;
    return hi != 0 || (lo >> bits) != 0;
}

bool ef_in_i128_round_shr(ef_i128 v, unsigned n, int64_t *out)
{
    /* t = v + 2^(n-1); callers keep |v| < 2^126, so this cannot wrap. */
    ef_i128 half;
    if (n - 1 < 64) {
        half.hi = 0;
        half.lo = (uint64_t)1 << (n - 1);
    } else {
        half.hi = (int64_t)((uint64_t)1 << (n - 1 - 64));
        half.lo = 0;
    }
    ef_i128 t = ef_in_i128_add(v, half);
    uint64_t rlo;
    int64_t rhi;
    if (n < 64) {
        rlo = (t.lo >> n) | ((uint64_t)t.hi << (64 - n));
        rhi = ef_asr_i64(t.hi, n);
    } else if (n == 64) {
        rlo = (uint64_t)t.hi;
        rhi = t.hi < 0 ? -1 : 0;
    } else {
        rlo = (uint64_t)ef_asr_i64(t.hi, n - 64);
        rhi = t.hi < 0 ? -1 : 0;
    }
    /* Fits int64 iff the high word is the sign extension of the low one. */
    if (!((rhi == 0 && (rlo >> 63) == 0) || (rhi == -1 && (rlo >> 63) == 1)))
        return false;
    *out = ef_wrap_i64(rlo);
    return true;
}

/* ------------------------------------------------------------ matrices */

ef_in_affine ef_in_affine_identity(void)
{
    ef_in_affine m = { ef_q32_raw(EF_Q32_ONE), ef_q32_raw(0), ef_q32_raw(0),
                       ef_q32_raw(EF_Q32_ONE), ef_q32_raw(0), ef_q32_raw(0) };
    return m;
}

ef_in_affine ef_in_affine_scale_translate(ef_q32 sx, ef_q32 sy, ef_q32 tx, ef_q32 ty)
{
    ef_in_affine m = { sx, ef_q32_raw(0), ef_q32_raw(0), sy, tx, ty };
    return m;
}

/* p*q + r*s + t*2^32 rounded once to Q31.32.  Operands are Q31.32, so each
 * product is below 2^126 in magnitude; a product at or above 2^125 makes the
 * result far outside Q31.32 anyway, and is rejected before summing so that
 * the 128-bit sum cannot wrap. */
bool ef_in_q32_dot2(ef_q32 p, ef_q32 q, ef_q32 r, ef_q32 s, ef_q32 t, ef_q32 *out)
{
    ef_i128 a = ef_mul_i64_wide(p.v, q.v), b = ef_mul_i64_wide(r.v, s.v);
    if (ef_in_i128_exceeds(a, 125) || ef_in_i128_exceeds(b, 125))
        return false;
    ef_i128 sum = ef_in_i128_add(ef_in_i128_add(a, b), ef_in_i128_from_i64_shl(t.v, 32));
    int64_t v;
    if (!ef_in_i128_round_shr(sum, 32, &v))
        return false;
    *out = ef_q32_raw(v);
    return true;
}

ef_status ef_in_affine_mul(const ef_in_affine *m, const ef_in_affine *n, ef_in_affine *out)
{
    ef_in_affine r;
    ef_q32 z = ef_q32_raw(0);
    if (!ef_in_q32_dot2(m->a, n->a, m->c, n->b, z, &r.a) || !ef_in_q32_dot2(m->b, n->a, m->d, n->b, z, &r.b) ||
        !ef_in_q32_dot2(m->a, n->c, m->c, n->d, z, &r.c) || !ef_in_q32_dot2(m->b, n->c, m->d, n->d, z, &r.d) ||
        !ef_in_q32_dot2(m->a, n->e, m->c, n->f, m->e, &r.e) || !ef_in_q32_dot2(m->b, n->e, m->d, n->f, m->f, &r.f))
        return EF_ERR_RANGE;
    *out = r;
    return EF_OK;
}

/* Exact image in units of 2^-64 px; false if it is 2^125 or more (far
 * outside every format we round to), so later sums never wrap. */
static bool apply_exact(const ef_in_affine *m, ef_q32 x, ef_q32 y, ef_i128 *X, ef_i128 *Y)
{
    ef_i128 ax = ef_mul_i64_wide(m->a.v, x.v), cy = ef_mul_i64_wide(m->c.v, y.v);
    ef_i128 bx = ef_mul_i64_wide(m->b.v, x.v), dy = ef_mul_i64_wide(m->d.v, y.v);
    if (ef_in_i128_exceeds(ax, 124) || ef_in_i128_exceeds(cy, 124) || ef_in_i128_exceeds(bx, 124) ||
        ef_in_i128_exceeds(dy, 124))
        return false;
    *X = ef_in_i128_add(ef_in_i128_add(ax, cy), ef_in_i128_from_i64_shl(m->e.v, 32));
    *Y = ef_in_i128_add(ef_in_i128_add(bx, dy), ef_in_i128_from_i64_shl(m->f.v, 32));
    return true;
}

ef_status ef_in_affine_apply_dev(const ef_in_affine *m, ef_q32 x, ef_q32 y, ef_point *out)
{
    ef_i128 X, Y;
    int64_t vx, vy;
    if (!apply_exact(m, x, y, &X, &Y) || !ef_in_i128_round_shr(X, 56, &vx) || !ef_in_i128_round_shr(Y, 56, &vy))
        return EF_ERR_RANGE;
    if (vx <= -EF_COORD_LIMIT || vx >= EF_COORD_LIMIT || vy <= -EF_COORD_LIMIT || vy >= EF_COORD_LIMIT)
        return EF_ERR_RANGE;
    out->x = (int32_t)vx;
    out->y = (int32_t)vy;
    return EF_OK;
}

ef_status ef_in_affine_apply_q16(const ef_in_affine *m, ef_q32 x, ef_q32 y, int64_t *X, int64_t *Y)
{
    const int64_t lim = (int64_t)1 << 31;
    ef_i128 ex, ey;
    if (!apply_exact(m, x, y, &ex, &ey) || !ef_in_i128_round_shr(ex, 48, X) || !ef_in_i128_round_shr(ey, 48, Y))
        return EF_ERR_RANGE;
    if (*X <= -lim || *X >= lim || *Y <= -lim || *Y >= lim)
        return EF_ERR_RANGE;
    return EF_OK;
}

ef_status ef_in_affine_apply_q32(const ef_in_affine *m, ef_q32 x, ef_q32 y, ef_q32 *X, ef_q32 *Y)
{
    ef_i128 ex, ey;
    int64_t vx, vy;
    if (!apply_exact(m, x, y, &ex, &ey) || !ef_in_i128_round_shr(ex, 32, &vx) || !ef_in_i128_round_shr(ey, 32, &vy))
        return EF_ERR_RANGE;
    *X = ef_q32_raw(vx);
    *Y = ef_q32_raw(vy);
    return EF_OK;
}

void ef_in_sincos_deg(ef_q32 deg, ef_q32 *s, ef_q32 *c)
{
    int32_t sq, cq;
    ef_sincos(ef_angle_from_deg_q32(deg), &sq, &cq);
    /* Q1.30 -> Q31.32: exact (times 4). */
    *s = ef_q32_raw(ef_shl_i64(sq, 2));
    *c = ef_q32_raw(ef_shl_i64(cq, 2));
}

/* ------------------------------------------------------ transform list */

static bool name_is(const char *s, size_t n, const char *lit)
{
    size_t k = 0;
    while (lit[k] != '\0')
        k++;
    if (k != n)
        return false;
    for (size_t i = 0; i < n; i++)
        if (s[i] != lit[i])
            return false;
    return true;
}

static ef_status one_transform(const char *name, size_t nlen, const ef_q32 *v, int n, ef_in_affine *t, ef_error *err)
{
    const ef_q32 zero = ef_q32_raw(0), one = ef_q32_raw(EF_Q32_ONE);
    if (name_is(name, nlen, "matrix")) {
        if (n != 6)
            goto arity;
        t->a = v[0];
        t->b = v[1];
        t->c = v[2];
        t->d = v[3];
        t->e = v[4];
        t->f = v[5];
    } else if (name_is(name, nlen, "translate")) {
        if (n != 1 && n != 2)
            goto arity;
        *t = ef_in_affine_scale_translate(one, one, v[0], n == 2 ? v[1] : zero);
    } else if (name_is(name, nlen, "scale")) {
        if (n != 1 && n != 2)
            goto arity;
        *t = ef_in_affine_scale_translate(v[0], n == 2 ? v[1] : v[0], zero, zero);
    } else if (name_is(name, nlen, "rotate")) {
        if (n != 1 && n != 3)
            goto arity;
        ef_q32 s, c;
        ef_in_sincos_deg(v[0], &s, &c);
        ef_in_affine r = { c, s, ef_q32_raw(-s.v), c, zero, zero };
        if (n == 3) {
            /* translate(cx, cy) rotate(a) translate(-cx, -cy) */
            if (v[1].v == INT64_MIN || v[2].v == INT64_MIN)
                goto range;
            ef_in_affine to = ef_in_affine_scale_translate(one, one, v[1], v[2]);
            ef_in_affine back = ef_in_affine_scale_translate(one, one, ef_q32_raw(-v[1].v), ef_q32_raw(-v[2].v));
            if (ef_in_affine_mul(&to, &r, &r) != EF_OK || ef_in_affine_mul(&r, &back, &r) != EF_OK)
                goto range;
        }
        *t = r;
    } else if (name_is(name, nlen, "skewX") || name_is(name, nlen, "skewY")) {
        if (n != 1)
            goto arity;
        ef_q32 s, c, tn;
        ef_in_sincos_deg(v[0], &s, &c);
        if (c.v == 0 || !ef_q32_div(s, c, &tn))
            return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0, "skew angle too close to 90 degrees");
        *t = ef_in_affine_identity();
        if (name[4] == 'X')
            t->c = tn;
        else
            t->b = tn;
    } else {
        return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "unknown transform '%.*s'", (int)(nlen > 32 ? 32 : nlen),
                            name);
    }
    return EF_OK;
arity:
    return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "wrong number of arguments (%d) for %.*s()", n, (int)nlen,
                        name);
range:
    return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0, "transform out of range");
}

ef_status ef_in_transform_parse(const char *s, size_t len, ef_in_affine *out, size_t *err_off, ef_error *err)
{
    ef_in_lex l = { s, len, 0 };
    ef_in_affine m = ef_in_affine_identity();
    ef_status st;
    ef_in_lex_wsp(&l);
    while (!ef_in_lex_end(&l)) {
        size_t name0 = l.pos;
        while (!ef_in_lex_end(&l) &&
               ((l.s[l.pos] >= 'a' && l.s[l.pos] <= 'z') || (l.s[l.pos] >= 'A' && l.s[l.pos] <= 'Z')))
            l.pos++;
        size_t nlen = l.pos - name0;
        if (nlen == 0) {
            *err_off = l.pos;
            return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "transform name expected");
        }
        ef_in_lex_wsp(&l);
        if (ef_in_lex_peek(&l) != '(') {
            *err_off = l.pos;
            return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "'(' expected after '%.*s'",
                                (int)(nlen > 32 ? 32 : nlen), s + name0);
        }
        l.pos++;
        ef_in_lex_wsp(&l);
        ef_q32 v[6];
        int n = 0;
        while (ef_in_lex_peek(&l) != ')') {
            if (n > 0 && ef_in_lex_sep(&l) == 2 && ef_in_lex_peek(&l) == ')') {
                *err_off = l.pos;
                return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "number expected after ','");
            }
            if (ef_in_lex_end(&l)) {
                *err_off = l.pos;
                return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "')' expected");
            }
            if (n == 6) {
                *err_off = l.pos;
                return ef_error_set(err, EF_ERR_SYNTAX, NULL, 0, 0, "too many arguments");
            }
            if ((st = ef_in_lex_number(&l, &v[n], err)) != EF_OK) {
                *err_off = l.pos;
                return st;
            }
            n++;
            ef_in_lex_wsp(&l);
        }
        l.pos++; /* ')' */
        ef_in_affine t;
        if ((st = one_transform(s + name0, nlen, v, n, &t, err)) != EF_OK) {
            *err_off = name0;
            return st;
        }
        if (ef_in_affine_mul(&m, &t, &m) != EF_OK) {
            *err_off = name0;
            return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0, "transform out of range");
        }
        /* Separators between transforms are optional (SVG 2 / CSS). */
        while (ef_in_lex_sep(&l) != 0) {
        }
    }
    *out = m;
    return EF_OK;
}
