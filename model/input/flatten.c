/*
 * flatten.c - the geometry builder: user-space path commands to device
 * contours, with fixed-point Bezier flattening.
 *
 * Place in the pipeline: the last step of the front end.  Straight-segment
 * end points go through the CTM and are rounded once to Q16.8.  A Bezier
 * curve is flattened in DEVICE space: its control points are transformed
 * exactly and rounded once to Q47.16 (P_k, |P_k| < 2^31), then
 *
 *   L = max over the curve's second differences of |ddx| + |ddy|
 *       (cubic: P0 - 2P1 + P2 and P1 - 2P2 + P3; quadratic: P0 - 2P1 + P2),
 *   n = the smallest n >= 1 with 4 tol n^2 >= 3L (cubic) or >= L (quadratic),
 *       tol = 1/16 px, capped at 256,
 *
 * which bounds the distance between the curve and the chords of n uniform
 * parameter steps by tol: for a polynomial curve the chord error over a step
 * h is at most h^2 max|B''| / 8, and max|B''| <= 6 L (cubic) or 2 L
 * (quadratic) with |ddx| + |ddy| >= the Euclidean length.  Past the cap the
 * bound is 3L / (4 * 256^2) (cubic) or L / (4 * 256^2) (quadratic); L < 2^34
 * in Q47.16 keeps that below 3 px, and only curves spanning thousands of
 * pixels reach the cap.
 *
 * Point i (1 <= i < n) is evaluated EXACTLY at t = i/n as the integer
 * Bernstein sum  sum_k C(3,k) (n-i)^(3-k) i^k P_k  (|sum| < n^3 2^31 <= 2^55)
 * and rounded once: floor(sum / (n^3 2^8) + 1/2) (quadratic: n^2).  The last
 * point (i = n) is the curve's end point transformed and rounded once, exactly
 * as a line's end point would be, so curves and lines meeting at a point meet
 * at the same device vertex and a closing segment lands on the start vertex.
 */
#include <stdlib.h>
#include <string.h>

#include "input_internal.h"

void ef_in_builder_init(ef_in_builder *b)
{
    memset(b, 0, sizeof *b);
    b->ctm = ef_in_affine_identity();
}

void ef_in_builder_free(ef_in_builder *b)
{
    free(b->pts);
    free(b->start);
    ef_in_builder_init(b);
}

void ef_in_builder_reset(ef_in_builder *b, const ef_in_affine *ctm, uint32_t budget)
{
    b->ctm = *ctm;
    b->npts = 0;
    b->ncont = 0;
    b->cur = 0;
    b->open = false;
    b->budget = budget;
}

static ef_status limit_error(ef_error *err)
{
    return ef_error_set(err, EF_ERR_LIMIT, NULL, 0, 0, "too many points (the limit is %u per scene)",
                        (unsigned)EF_MAX_POINTS_PER_SCENE);
}

static ef_status range_error(ef_error *err)
{
    return ef_error_set(err, EF_ERR_RANGE, NULL, 0, 0,
                        "coordinate out of range after transformation (|x|, |y| must stay below 32768 px)");
}

/* Ends the open contour: drops closing points equal to the first and the
 * whole contour if fewer than 3 points remain. */
void ef_in_build_close(ef_in_builder *b)
{
    if (!b->open)
        return;
    b->open = false;
    uint32_t n = b->npts - b->cur;
    while (n > 1 && b->pts[b->cur + n - 1].x == b->pts[b->cur].x && b->pts[b->cur + n - 1].y == b->pts[b->cur].y)
        n--;
    if (n < 3) {
        b->npts = b->cur;
        return;
    }
    b->npts = b->cur + n;
    /* start[] has room: reserved when the contour was opened. */
    b->start[b->ncont++] = b->cur;
}

ef_status ef_in_build_point(ef_in_builder *b, ef_point p, ef_error *err)
{
    if (p.x <= -EF_COORD_LIMIT || p.x >= EF_COORD_LIMIT || p.y <= -EF_COORD_LIMIT || p.y >= EF_COORD_LIMIT)
        return range_error(err);
    if (b->npts > b->cur && b->pts[b->npts - 1].x == p.x && b->pts[b->npts - 1].y == p.y)
        return EF_OK;
    if (b->npts >= b->budget)
        return limit_error(err);
    if (b->npts == b->pts_cap) {
        uint32_t cap = b->pts_cap ? b->pts_cap * 2 : 256;
        if (cap > b->budget)
            cap = b->budget;
        ef_point *np = realloc(b->pts, (size_t)cap * sizeof *np);
        if (!np)
            return ef_error_set(err, EF_ERR_NOMEM, NULL, 0, 0, "out of memory");
        b->pts = np;
        b->pts_cap = cap;
    }
    b->pts[b->npts++] = p;
    return EF_OK;
}

ef_status ef_in_build_move(ef_in_builder *b, ef_q32 x, ef_q32 y, ef_error *err)
{
    ef_point p;
    ef_in_build_close(b);
    if (ef_in_affine_apply_dev(&b->ctm, x, y, &p) != EF_OK)
        return range_error(err);
    /* Reserve the contour's start slot now so closing never allocates. */
    if (b->ncont + 1 >= b->start_cap) {
        if (b->start_cap >= EF_MAX_POINTS_PER_SCENE)
            return limit_error(err);
        uint32_t cap = b->start_cap ? b->start_cap * 2 : 64;
        uint32_t *ns = realloc(b->start, (size_t)cap * sizeof *ns);
        if (!ns)
            return ef_error_set(err, EF_ERR_NOMEM, NULL, 0, 0, "out of memory");
        b->start = ns;
        b->start_cap = cap;
    }
    b->cur = b->npts;
    b->open = true;
    return ef_in_build_point(b, p, err);
}

ef_status ef_in_build_line(ef_in_builder *b, ef_q32 x, ef_q32 y, ef_error *err)
{
    ef_point p;
    if (ef_in_affine_apply_dev(&b->ctm, x, y, &p) != EF_OK)
        return range_error(err);
    return ef_in_build_point(b, p, err);
}

static int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

/* Smallest n >= 1 with n^2 * 4 tol >= k L (k = 3 cubic, 1 quadratic),
 * capped.  L < 2^34, so k L < 2^36 and nothing overflows. */
static uint32_t segments_for(int64_t L, int64_t k)
{
    int64_t need = k * L;                                /* n^2 * 2^14 >= need */
    int64_t m = ef_ceildiv_i64(need, 4 * EF_IN_TOL_Q16); /* n^2 >= m */
    if (m <= 1)
        return 1;
    uint32_t n = ef_isqrt_u64((uint64_t)(m - 1)) + 1; /* ceil(sqrt(m)) */
    return n > EF_IN_CURVE_MAX_SEGMENTS ? EF_IN_CURVE_MAX_SEGMENTS : n;
}

/* floor(num / den + 1/2) for den > 0 (|num| < 2^56 here). */
static int32_t round_div(int64_t num, int64_t den) { return (int32_t)ef_floordiv_i64(2 * num + den, 2 * den); }

ef_status ef_in_build_quad(ef_in_builder *b, const ef_q32 p[6], ef_error *err)
{
    int64_t X[3], Y[3];
    ef_status st;
    for (int k = 0; k < 3; k++)
        if (ef_in_affine_apply_q16(&b->ctm, p[2 * k], p[2 * k + 1], &X[k], &Y[k]) != EF_OK)
            return range_error(err);
    int64_t L = abs64(X[0] - 2 * X[1] + X[2]) + abs64(Y[0] - 2 * Y[1] + Y[2]);
    int64_t n = segments_for(L, 1);
    int64_t den = n * n * EF_DEV_ONE;
    for (int64_t i = 1; i < n; i++) {
        int64_t u = n - i;
        int64_t c0 = u * u, c1 = 2 * u * i, c2 = i * i;
        ef_point q = { round_div(c0 * X[0] + c1 * X[1] + c2 * X[2], den),
                       round_div(c0 * Y[0] + c1 * Y[1] + c2 * Y[2], den) };
        if ((st = ef_in_build_point(b, q, err)) != EF_OK)
            return st;
    }
    return ef_in_build_line(b, p[4], p[5], err);
}

ef_status ef_in_build_cubic(ef_in_builder *b, const ef_q32 p[8], ef_error *err)
{
    int64_t X[4], Y[4];
    ef_status st;
    for (int k = 0; k < 4; k++)
        if (ef_in_affine_apply_q16(&b->ctm, p[2 * k], p[2 * k + 1], &X[k], &Y[k]) != EF_OK)
            return range_error(err);
    int64_t L1 = abs64(X[0] - 2 * X[1] + X[2]) + abs64(Y[0] - 2 * Y[1] + Y[2]);
    int64_t L2 = abs64(X[1] - 2 * X[2] + X[3]) + abs64(Y[1] - 2 * Y[2] + Y[3]);
    int64_t n = segments_for(L1 > L2 ? L1 : L2, 3);
    int64_t den = n * n * n * EF_DEV_ONE;
    for (int64_t i = 1; i < n; i++) {
        int64_t u = n - i;
        int64_t c0 = u * u * u, c1 = 3 * u * u * i, c2 = 3 * u * i * i, c3 = i * i * i;
        ef_point q = { round_div(c0 * X[0] + c1 * X[1] + c2 * X[2] + c3 * X[3], den),
                       round_div(c0 * Y[0] + c1 * Y[1] + c2 * Y[2] + c3 * Y[3], den) };
        if ((st = ef_in_build_point(b, q, err)) != EF_OK)
            return st;
    }
    return ef_in_build_line(b, p[6], p[7], err);
}

ef_status ef_in_builder_commit(ef_in_builder *b, ef_scene *s, ef_rule rule, ef_rgba8 color, ef_error *err)
{
    ef_status st;
    ef_in_build_close(b);
    if (b->ncont == 0)
        return EF_OK;
    if (b->npts > EF_MAX_EDGES_PER_SHAPE)
        return ef_error_set(err, EF_ERR_LIMIT, NULL, 0, 0,
                            "too many edges in one shape: %u (the model takes at most 2^22 = 4194304)",
                            (unsigned)b->npts);
    if ((st = ef_scene_begin_shape(s, rule, color)) != EF_OK)
        return ef_error_set(err, st, NULL, 0, 0, st == EF_ERR_NOMEM ? "out of memory" : "too many shapes");
    for (uint32_t c = 0; c < b->ncont; c++) {
        uint32_t end = c + 1 < b->ncont ? b->start[c + 1] : b->npts;
        if ((st = ef_scene_add_contour(s, b->pts + b->start[c], end - b->start[c])) != EF_OK) {
            if (st == EF_ERR_LIMIT)
                return limit_error(err);
            return ef_error_set(err, st, NULL, 0, 0, "out of memory");
        }
    }
    b->npts = 0;
    b->ncont = 0;
    b->cur = 0;
    return EF_OK;
}
