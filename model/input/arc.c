/*
 * arc.c - elliptical arcs: SVG endpoint parameterisation to centre
 * parameterisation (SVG 1.1 appendix F.6.5, radii correction F.6.6) in
 * Q31.32, and flattening by stepping the binary angle.
 *
 * Place in the pipeline: beside the Bezier flattener (flatten.c); circles,
 * ellipses and rounded rectangle corners come here too.
 *
 * Centre parameterisation.  With (x1', y1') the half chord rotated by -phi,
 * the unit-space half chord is (X, Y) = (x1'/rx, y1'/ry), d = |(X, Y)|.
 * d >= 1: the radii are too small and are scaled up so that d = 1 (F.6.6);
 * the centre is the chord's midpoint.  Otherwise, in unit space, the centre
 * sits at distance e = sqrt(1 - d^2) from the midpoint, on the side given by
 * the flags, and with alpha = direction of (X, Y) and beta = atan2(e, d):
 *
 *   t0 = alpha + s beta,  |delta| = 1/2 turn - 2 beta (small arc) or
 *   1/2 turn + 2 beta (large arc),  s = +1 if large != sweep else -1,
 *   direction + if sweep else -.
 *
 * (This is F.6.5's formula rewritten so that no quantity grows without bound:
 * alpha comes from the exact 128-bit direction (x1' ry, y1' rx), and e, d are
 * at most 1.)
 *
 * Flattening.  The device image of the ellipse is P(t) = D + A (cos t,
 * sin t), A = (CTM linear part) R(phi) diag(rx, ry), and |P''(t)| <= K with
 * K = hypot(|A11| + |A12|, |A21| + |A22|) >= ||A||.  A chord over a parameter
 * step h deviates from the curve by at most K h^2 / 8, so with
 * n = ceil(theta sqrt(2 K)) steps (theta = the arc's angle in radians,
 * bounded above with pi <= 355/113) the error is <= 1/16 px.  n is capped at
 * 4096 (reached only by arcs whose device radius exceeds 2^17 px).  Point i
 * is D + A (cos t_i, sin t_i), t_i = t0 + dir round(i |delta| / n), computed
 * exactly from the Q1.30 ef_sincos values and rounded once to Q16.8; the last
 * point is the arc's end point transformed and rounded once, like a line's.
 * Add the Q16.8 rounding (1/512 px) and ef_sincos's 4*2^-30 relative error
 * times the radius (< 0.002 px below 2^17 px) for the total deviation.
 */
#include "input_internal.h"

bool ef_in_hypot_q32(ef_q32 a, ef_q32 b, ef_q32 *out)
{
    if (a.v == INT64_MIN || b.v == INT64_MIN)
        return false;
    int64_t x = a.v < 0 ? -a.v : a.v, y = b.v < 0 ? -b.v : b.v;
    int64_t m = x > y ? x : y, s = x > y ? y : x;
    if (m == 0) {
        *out = ef_q32_raw(0);
        return true;
    }
    /* m sqrt(1 + (s/m)^2): every intermediate stays in [0, 2]. */
    ef_q32 r, r2, root;
    if (!ef_q32_div(ef_q32_raw(s), ef_q32_raw(m), &r) || !ef_q32_mul(r, r, &r2))
        return false;
    root = ef_q32_sqrt(ef_q32_raw(EF_Q32_ONE + r2.v));
    return ef_q32_mul(ef_q32_raw(m), root, out);
}

static ef_status range_error(ef_error *err)
{
    return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0,
                        "arc out of range after transformation (|x|, |y| must stay below 32768 px)");
}

static uint64_t uabs(int64_t v) { return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v; }

ef_status ef_in_build_ellarc(ef_in_builder *b, const ef_in_ellarc *arc, ef_error *err)
{
    ef_status st;
    /* E maps (cos t, sin t) to user space: centre + R(phi) diag(rx, ry). */
    ef_q32 cphi = ef_q32_raw(ef_shl_i64(arc->cos_phi, 2)), sphi = ef_q32_raw(ef_shl_i64(arc->sin_phi, 2));
    ef_in_affine E, A;
    if (!ef_q32_mul(cphi, arc->rx, &E.a) || !ef_q32_mul(sphi, arc->rx, &E.b) || !ef_q32_mul(sphi, arc->ry, &E.c) ||
        !ef_q32_mul(cphi, arc->ry, &E.d))
        return range_error(err);
    E.c.v = -E.c.v;
    E.e = arc->cx;
    E.f = arc->cy;
    if (ef_in_affine_mul(&b->ctm, &E, &A) != EF_OK)
        return range_error(err);

    /* K / 2 (Q31.32 px) from the row sums, halved so they fit int64. */
    uint64_t kx = uabs(A.a.v) + uabs(A.c.v), ky = uabs(A.b.v) + uabs(A.d.v);
    ef_q32 khalf;
    if (!ef_in_hypot_q32(ef_q32_raw((int64_t)(kx >> 1)), ef_q32_raw((int64_t)(ky >> 1)), &khalf))
        return range_error(err);
    /* sqrt(2K) = 2 sqrt(K/2) <= s2 (Q31.32, rounded up by one unit). */
    int64_t s2 = 2 * (ef_q32_sqrt(khalf).v + 1);
    /* theta * 2^32 <= 2 * (355/113) * delta, rounded up. */
    int64_t theta = ef_ceildiv_i64(710 * arc->delta, 113);
    ef_i128 p = ef_mul_i64_wide(theta, s2); /* < 2^35 * 2^50 */
    uint64_t n = (uint64_t)p.hi + (p.lo != 0 ? 1u : 0u);
    if (n < 1)
        n = 1;
    if (n > EF_IN_ARC_MAX_SEGMENTS)
        n = EF_IN_ARC_MAX_SEGMENTS;

    for (uint64_t i = 1; i < n; i++) {
        uint32_t step = (uint32_t)(((uint64_t)arc->delta * i + n / 2) / n);
        ef_angle t = arc->dir > 0 ? arc->t0 + step : arc->t0 - step;
        int32_t s, c;
        ef_point q;
        ef_sincos(t, &s, &c);
        if (ef_in_affine_apply_dev(&A, ef_q32_raw(ef_shl_i64(c, 2)), ef_q32_raw(ef_shl_i64(s, 2)), &q) != EF_OK)
            return range_error(err);
        if ((st = ef_in_build_point(b, q, err)) != EF_OK)
            return st;
    }
    return ef_in_build_line(b, arc->ex, arc->ey, err);
}

/* Direction of the exact vector (px, py) given as 128-bit values, as a
 * binary angle: both are shifted right together until they fit 62 bits. */
static ef_angle atan2_wide(ef_i128 py, ef_i128 px)
{
    while (ef_in_i128_exceeds(px, 62) || ef_in_i128_exceeds(py, 62)) {
        px.lo = (px.lo >> 1) | ((uint64_t)px.hi << 63);
        px.hi = ef_asr_i64(px.hi, 1);
        py.lo = (py.lo >> 1) | ((uint64_t)py.hi << 63);
        py.hi = ef_asr_i64(py.hi, 1);
    }
    return ef_atan2(ef_wrap_i64(py.lo), ef_wrap_i64(px.lo));
}

ef_status ef_in_build_svg_arc(ef_in_builder *b, ef_q32 x0, ef_q32 y0, ef_q32 rx, ef_q32 ry, ef_q32 phi_deg, bool large,
                              bool sweep, ef_q32 x, ef_q32 y, ef_error *err)
{
    const ef_q32 zero = ef_q32_raw(0), one = ef_q32_raw(EF_Q32_ONE);
    if (x0.v == x.v && y0.v == y.v)
        return EF_OK; /* F.6.2: omitted */
    if (rx.v == INT64_MIN || ry.v == INT64_MIN)
        return range_error(err);
    rx.v = rx.v < 0 ? -rx.v : rx.v; /* F.6.6: signs dropped */
    ry.v = ry.v < 0 ? -ry.v : ry.v;
    if (rx.v == 0 || ry.v == 0)
        return ef_in_build_line(b, x, y, err); /* F.6.2: a line */

    int32_t sq, cq;
    ef_sincos(ef_angle_from_deg_q32(phi_deg), &sq, &cq);
    ef_q32 sphi = ef_q32_raw(ef_shl_i64(sq, 2)), cphi = ef_q32_raw(ef_shl_i64(cq, 2));

    /* Half chord (floored halving) and midpoint. */
    int64_t dx, dy;
    if (x.v == INT64_MIN || y.v == INT64_MIN || !ef_add_i64_checked(x0.v, -x.v, &dx) ||
        !ef_add_i64_checked(y0.v, -y.v, &dy))
        return range_error(err);
    ef_q32 hx = ef_q32_raw(ef_asr_i64(dx, 1)), hy = ef_q32_raw(ef_asr_i64(dy, 1));
    ef_q32 mx = ef_q32_raw(x.v + hx.v), my = ef_q32_raw(y.v + hy.v); /* between x and x0: no overflow */
    ef_q32 x1, y1;                                                   /* rotated by -phi */
    if (!ef_in_q32_dot2(cphi, hx, sphi, hy, zero, &x1) || !ef_in_q32_dot2(ef_q32_raw(-sphi.v), hx, cphi, hy, zero, &y1))
        return range_error(err);

    /* Unit-space half chord length d; scaled when d >= 1 or not representable. */
    ef_q32 X, Y, d = one, e = zero;
    bool scaled = !ef_q32_div(x1, rx, &X) || !ef_q32_div(y1, ry, &Y) || !ef_in_hypot_q32(X, Y, &d) || d.v >= EF_Q32_ONE;
    if (!scaled && d.v == 0)
        return ef_in_build_line(b, x, y, err); /* chord below 2^-32 radius */

    ef_angle alpha = atan2_wide(ef_mul_i64_wide(y1.v, rx.v), ef_mul_i64_wide(x1.v, ry.v));
    ef_angle beta = 0;
    if (scaled) {
        /* F.6.6: radii multiplied by the same factor so that d = 1. */
        int64_t t;
        ef_q32 r;
        if (rx.v >= ry.v) {
            /* ry' = hypot(x1' ry / rx, y1'), rx' = ry' rx / ry */
            if (!ef_muldiv_i64(x1.v, ry.v, rx.v, &t) || !ef_in_hypot_q32(ef_q32_raw(t), y1, &r) ||
                !ef_muldiv_i64(r.v, rx.v, ry.v, &t))
                return range_error(err);
            rx = ef_q32_raw(t);
            ry = r;
        } else {
            /* rx' = hypot(x1', y1' rx / ry), ry' = rx' ry / rx */
            if (!ef_muldiv_i64(y1.v, rx.v, ry.v, &t) || !ef_in_hypot_q32(x1, ef_q32_raw(t), &r) ||
                !ef_muldiv_i64(r.v, ry.v, rx.v, &t))
                return range_error(err);
            ry = ef_q32_raw(t);
            rx = r;
        }
        if (rx.v == 0 || ry.v == 0)
            return ef_in_build_line(b, x, y, err);
    } else {
        ef_q32 e2;
        if (!ef_q32_mul(ef_q32_raw(EF_Q32_ONE - d.v), ef_q32_raw(EF_Q32_ONE + d.v), &e2))
            return range_error(err);
        e = ef_q32_sqrt(e2);
        beta = ef_atan2(e.v, d.v);
    }

    /* Centre: rotated-frame offset (s e rx n_y, -s e ry n_x), n = direction alpha. */
    int sgn = large != sweep ? 1 : -1;
    int32_t nsq, ncq;
    ef_sincos(alpha, &nsq, &ncq);
    ef_q32 ex_, ey_, cxr, cyr, cx, cy;
    if (!ef_q32_mul(e, ef_q32_raw(ef_shl_i64(nsq, 2)), &ex_) || !ef_q32_mul(e, ef_q32_raw(ef_shl_i64(ncq, 2)), &ey_) ||
        !ef_q32_mul(ex_, rx, &cxr) || !ef_q32_mul(ey_, ry, &cyr))
        return range_error(err);
    if (sgn > 0)
        cyr.v = -cyr.v;
    else
        cxr.v = -cxr.v;
    if (!ef_in_q32_dot2(cphi, cxr, ef_q32_raw(-sphi.v), cyr, mx, &cx) || !ef_in_q32_dot2(sphi, cxr, cphi, cyr, my, &cy))
        return range_error(err);

    ef_in_ellarc arc;
    arc.cx = cx;
    arc.cy = cy;
    arc.rx = rx;
    arc.ry = ry;
    arc.cos_phi = cq;
    arc.sin_phi = sq;
    arc.t0 = sgn > 0 ? alpha + beta : alpha - beta;
    arc.delta =
        large ? (int64_t)EF_ANGLE_HALF_TURN + 2 * (int64_t)beta : (int64_t)EF_ANGLE_HALF_TURN - 2 * (int64_t)beta;
    arc.dir = sweep ? 1 : -1;
    arc.ex = x;
    arc.ey = y;
    if (arc.delta <= 0)
        return ef_in_build_line(b, x, y, err);
    return ef_in_build_ellarc(b, &arc, err);
}
