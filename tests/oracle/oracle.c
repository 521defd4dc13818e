/*
 * oracle.c - the independent slow model of edgeflag's sample coverage.
 *
 * Written from docs/spec.md alone; nothing from model/ or fixed/ is used.
 * Plain int64 arithmetic throughout; every bound the spec states is checked
 * at run time (EO_CHECK aborts, independent of NDEBUG), so a silent int64
 * overflow cannot hide a wrong answer.  See docs/oracle.md.
 *
 * The rule (spec 5.1): sample (Xs, Yr) counts the crossing of edge
 * (X0,Y0)->(X1,Y1) (Y0 < Y1 the sorted ends, dY = Y1-Y0 > 0, dX = X1-X0) when
 *     Y0 <= Yr < Y1   and   x_r = X0 + (Yr-Y0)*dX/dY <= Xs,
 * the latter compared exactly as (X0 - Xs)*dY + (Yr - Y0)*dX <= 0.
 * The winding number is the sum of dir (+1 when the edge runs down, ya < yb)
 * over the counted crossings; horizontal edges are skipped.
 */
#include "oracle.h"

#include <stdlib.h>
#include <string.h>

#define EO_CHECK(cond) \
    do { \
        if (!(cond)) { \
            fprintf(stderr, "%s:%d: oracle invariant failed: %s\n", __FILE__, __LINE__, #cond); \
            abort(); \
        } \
    } while (0)

#define P2(n) ((int64_t)1 << (n))

/* ------------------------------------------------------------ patterns */
/* The spec's constants (spec section 4: N = 8 listed there; N = 16 and 32 as
 * published in docs/patterns.md / model/pattern_tables.c), copied by hand.
 * The harness checks that they still equal ef_pattern(). */
static const uint8_t eo_k8[8] = { 2, 7, 4, 1, 6, 3, 0, 5 };
static const uint8_t eo_k16[16] = { 3, 11, 7, 15, 1, 9, 5, 13, 2, 10, 6, 14, 0, 8, 4, 12 };
static const uint8_t eo_k32[32] = { 6,  27, 17, 11, 22, 3, 31, 15, 8,  25, 0,  20, 13, 29, 5,  18,
                                    10, 23, 1,  28, 16, 7, 24, 12, 19, 2,  30, 9,  21, 14, 26, 4 };

const uint8_t *eo_pattern(int samples)
{
    switch (samples) {
    case 8: return eo_k8;
    case 16: return eo_k16;
    case 32: return eo_k32;
    default: return NULL;
    }
}

static int samples_ok(int n) { return n == 8 || n == 16 || n == 32; }

/* h = 256/N, c = h/2 */
int64_t eo_sample_y(int samples, int64_t r)
{
    int64_t h = 256 / samples, c = h / 2;
    return h * r + c;
}

int64_t eo_sample_x(int samples, int64_t i, int s)
{
    int64_t h = 256 / samples, c = h / 2;
    return 256 * i + h * (int64_t)eo_pattern(samples)[s] + c;
}

/* --------------------------------------------------------------- edges */
typedef struct eo_edge {
    int64_t x0, y0, x1, y1; /* upper end (x0,y0), lower end (x1,y1): y0 < y1 */
    int dir;                /* +1: runs down the screen (ya < yb), else -1 */
} eo_edge;

static int validate(const eo_polygon *p, int samples, int W, int H)
{
    if (!p || !samples_ok(samples) || W < 1 || H < 1 || W > EO_MAX_CANVAS || H > EO_MAX_CANVAS)
        return EO_ERR_ARG;
    if (p->ncontours == 0)
        return EO_OK;
    if (!p->start)
        return EO_ERR_ARG;
    for (uint32_t c = 0; c < p->ncontours; c++)
        if (p->start[c + 1] < p->start[c])
            return EO_ERR_ARG;
    uint32_t first = p->start[0], last = p->start[p->ncontours];
    if (last > first && !p->pts)
        return EO_ERR_ARG;
    for (uint32_t k = first; k < last; k++) {
        int64_t x = p->pts[k].x, y = p->pts[k].y;
        if (x <= -EO_COORD_LIMIT || x >= EO_COORD_LIMIT || y <= -EO_COORD_LIMIT || y >= EO_COORD_LIMIT)
            return EO_ERR_RANGE;
    }
    return EO_OK;
}

/* All non-horizontal edges of all contours, P_i -> P_{(i+1) mod n}. */
static int build_edges(const eo_polygon *p, eo_edge **out, size_t *count)
{
    size_t total = 0, n = 0;
    *out = NULL;
    *count = 0;
    if (p->ncontours == 0)
        return EO_OK;
    total = (size_t)(p->start[p->ncontours] - p->start[0]);
    if (total == 0)
        return EO_OK;
    eo_edge *e = malloc(total * sizeof *e);
    if (!e)
        return EO_ERR_NOMEM;
    for (uint32_t c = 0; c < p->ncontours; c++) {
        uint32_t b = p->start[c], np = p->start[c + 1] - p->start[c];
        for (uint32_t i = 0; i < np; i++) {
            eo_point a = p->pts[b + i], z = p->pts[b + (i + 1) % np];
            if (a.y == z.y)
                continue; /* horizontal (including every edge of a 1-point contour) */
            eo_edge ed;
            if (a.y < z.y) {
                ed.x0 = a.x;
                ed.y0 = a.y;
                ed.x1 = z.x;
                ed.y1 = z.y;
                ed.dir = +1;
            } else {
                ed.x0 = z.x;
                ed.y0 = z.y;
                ed.x1 = a.x;
                ed.y1 = a.y;
                ed.dir = -1;
            }
            EO_CHECK(ed.y1 - ed.y0 >= 1 && ed.y1 - ed.y0 < P2(24));
            EO_CHECK(ed.x1 - ed.x0 > -P2(24) && ed.x1 - ed.x0 < P2(24));
            e[n++] = ed;
        }
    }
    *out = e;
    *count = n;
    return EO_OK;
}

/* Does edge e cross sample row Yr?  Half-open: Y0 <= Yr < Y1. */
static int crosses(const eo_edge *e, int64_t Yr) { return e->y0 <= Yr && Yr < e->y1; }

/* Is the crossing of e with row Yr at or left of Xs?  Exact:
 * x_r <= Xs  <=>  X0*dY + (Yr-Y0)*dX <= Xs*dY  <=>  (X0-Xs)*dY + (Yr-Y0)*dX <= 0. */
static int counts(const eo_edge *e, int64_t Xs, int64_t Yr)
{
    int64_t dY = e->y1 - e->y0, dX = e->x1 - e->x0;
    int64_t a = e->x0 - Xs, b = Yr - e->y0;
    EO_CHECK(crosses(e, Yr));
    EO_CHECK(a > -P2(25) && a < P2(25) && b >= 0 && b < P2(24));
    int64_t t1 = a * dY, t2 = b * dX;
    EO_CHECK(t1 > -P2(49) && t1 < P2(49) && t2 > -P2(49) && t2 < P2(49));
    return t1 + t2 <= 0;
}

/* Smallest pixel column q in [0, W) whose sample (Xs = base + 256 q) counts
 * the crossing, or W if none does.  counts() is monotone in Xs (false ...
 * false, true ... true, because dY > 0), so a binary search is exact. */
static int64_t first_counting_pixel(const eo_edge *e, int64_t base, int64_t Yr, int W)
{
    int64_t lo = 0, hi = W;
    while (lo < hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (counts(e, base + 256 * mid, Yr))
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

static int covered_nonzero(int64_t w) { return w % 128 != 0; } /* 7-bit counters, spec 6.4 */
static int covered_evenodd(int64_t w) { return w % 2 != 0; }

/* ------------------------------------------------------- fast evaluation */
int eo_eval(const eo_polygon *p, int samples, int W, int H, uint32_t *mask_nonzero, uint32_t *mask_evenodd,
            eo_stats *stats)
{
    int rc = validate(p, samples, W, H);
    if (rc)
        return rc;
    eo_edge *edges;
    size_t ne;
    rc = build_edges(p, &edges, &ne);
    if (rc)
        return rc;
    int64_t *diff = calloc((size_t)W + 1, sizeof *diff);
    if (!diff) {
        free(edges);
        return EO_ERR_NOMEM;
    }
    const uint8_t *k = eo_pattern(samples);
    const int64_t h = 256 / samples, c = h / 2;
    eo_stats st;
    memset(&st, 0, sizeof st);
    st.edges = ne;
    int first = 1;
    size_t npx = (size_t)W * (size_t)H;
    if (mask_nonzero)
        memset(mask_nonzero, 0, npx * sizeof *mask_nonzero);
    if (mask_evenodd)
        memset(mask_evenodd, 0, npx * sizeof *mask_evenodd);

    for (int j = 0; j < H; j++) {
        for (int s = 0; s < samples; s++) {
            int64_t r = (int64_t)samples * j + s;
            int64_t Yr = h * r + c;
            int64_t base = h * k[s] + c; /* X_s(0) */
            uint64_t nx = 0;
            memset(diff, 0, ((size_t)W + 1) * sizeof *diff);
            for (size_t q = 0; q < ne; q++) {
                if (!crosses(&edges[q], Yr))
                    continue;
                diff[first_counting_pixel(&edges[q], base, Yr, W)] += edges[q].dir;
                nx++;
            }
            st.crossings += nx;
            if (nx > st.max_row_crossings)
                st.max_row_crossings = nx;
            int64_t w = 0;
            for (int i = 0; i < W; i++) {
                w += diff[i]; /* winding of sample s of pixel i */
                size_t idx = (size_t)j * (size_t)W + (size_t)i;
                if (mask_nonzero && covered_nonzero(w))
                    mask_nonzero[idx] |= (uint32_t)1 << s;
                if (mask_evenodd && covered_evenodd(w))
                    mask_evenodd[idx] |= (uint32_t)1 << s;
                if (first || w < st.min_winding)
                    st.min_winding = w;
                if (first || w > st.max_winding)
                    st.max_winding = w;
                first = 0;
                if (w < -64 || w > 63)
                    st.outside_7bit++;
                if (w <= -64 || w >= 64)
                    st.abs_ge64++;
                if (w != 0 && w % 128 == 0)
                    st.wrapped_uncovered++;
            }
        }
    }
    free(diff);
    free(edges);
    if (stats)
        *stats = st;
    return EO_OK;
}

int eo_coverage(const eo_polygon *p, int rule_evenodd, int samples, int W, int H, uint32_t *mask_out)
{
    if (!mask_out)
        return EO_ERR_ARG;
    return rule_evenodd ? eo_eval(p, samples, W, H, NULL, mask_out, NULL)
                        : eo_eval(p, samples, W, H, mask_out, NULL, NULL);
}

int eo_winding_stats(const eo_polygon *p, int samples, int W, int H, eo_stats *out)
{
    if (!out)
        return EO_ERR_ARG;
    return eo_eval(p, samples, W, H, NULL, NULL, out);
}

/* ------------------------------------------------ brute force, per sample */
static int64_t winding_brute(const eo_edge *edges, size_t ne, int64_t Xs, int64_t Yr)
{
    int64_t w = 0;
    for (size_t q = 0; q < ne; q++)
        if (crosses(&edges[q], Yr) && counts(&edges[q], Xs, Yr))
            w += edges[q].dir;
    return w;
}

int eo_coverage_brute(const eo_polygon *p, int rule_evenodd, int samples, int W, int H, uint32_t *mask_out)
{
    int rc = validate(p, samples, W, H);
    if (rc)
        return rc;
    if (!mask_out)
        return EO_ERR_ARG;
    eo_edge *edges;
    size_t ne;
    rc = build_edges(p, &edges, &ne);
    if (rc)
        return rc;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            uint32_t m = 0;
            for (int s = 0; s < samples; s++) {
                int64_t w = winding_brute(edges, ne, eo_sample_x(samples, i, s),
                                          eo_sample_y(samples, (int64_t)samples * j + s));
                if (rule_evenodd ? covered_evenodd(w) : covered_nonzero(w))
                    m |= (uint32_t)1 << s;
            }
            mask_out[(size_t)j * (size_t)W + (size_t)i] = m;
        }
    free(edges);
    return EO_OK;
}

int64_t eo_sample_winding(const eo_polygon *p, int samples, int64_t i, int64_t j, int s, int *err)
{
    int rc = validate(p, samples, 1, 1);
    /* keep Xs, Yr inside the range the bit budget covers */
    if (!rc && (i < -EO_MAX_CANVAS || i > 2 * EO_MAX_CANVAS || j < -EO_MAX_CANVAS || j > 2 * EO_MAX_CANVAS || s < 0 ||
                s >= samples))
        rc = EO_ERR_ARG;
    eo_edge *edges = NULL;
    size_t ne = 0;
    if (!rc)
        rc = build_edges(p, &edges, &ne);
    if (err)
        *err = rc;
    if (rc)
        return 0;
    int64_t w = winding_brute(edges, ne, eo_sample_x(samples, i, s), eo_sample_y(samples, samples * j + s));
    free(edges);
    return w;
}

/* ------------------------------------------- triangle fan, per sample
 * A second, different algorithm.  The crossing rule of spec 5.1 is the
 * winding number of the perturbed point P' = (Xs + eps, Yr + delta) with
 * 0 < delta << eps << 1 (docs/oracle.md).  P' lies on no line through two
 * distinct points of the integer grid, so its winding number is well defined
 * and equals the sum over edges A->B of the signed containment of P' in the
 * triangle (O, A, B), for any fixed O that is not a vertex.  Each side test
 * is the sign of the edge function at P', evaluated symbolically:
 *   E(P') = E(P) + eps * dE/dx + delta * dE/dy, signs taken in that order. */
static int sgn(int64_t v) { return (v > 0) - (v < 0); }

static int lexsign(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    int64_t ux = bx - ax, uy = by - ay, vx = px - ax, vy = py - ay;
    EO_CHECK(ux > -P2(26) && ux < P2(26) && uy > -P2(26) && uy < P2(26));
    EO_CHECK(vx > -P2(26) && vx < P2(26) && vy > -P2(26) && vy < P2(26));
    int64_t e = ux * vy - uy * vx; /* E(P) */
    if (e)
        return sgn(e);
    if (uy)
        return sgn(-uy); /* dE/dx */
    return sgn(ux);      /* dE/dy */
}

/* O is outside the coordinate range, so it is never a vertex. */
#define FAN_OX (-(P2(23) + 1))
#define FAN_OY (-(P2(23) + 3))

static int64_t winding_fan(const eo_polygon *p, int64_t px, int64_t py)
{
    int64_t sum = 0;
    for (uint32_t c = 0; c < p->ncontours; c++) {
        uint32_t b = p->start[c], np = p->start[c + 1] - p->start[c];
        for (uint32_t i = 0; i < np; i++) {
            eo_point A = p->pts[b + i], B = p->pts[b + (i + 1) % np];
            /* orientation of (O, A, B): E_OA(B) */
            int64_t ux = A.x - FAN_OX, uy = A.y - FAN_OY, vx = B.x - FAN_OX, vy = B.y - FAN_OY;
            int sigma = sgn(ux * vy - uy * vx);
            if (!sigma)
                continue; /* degenerate triangle: winding 0 around P' */
            if (lexsign(FAN_OX, FAN_OY, A.x, A.y, px, py) == sigma && lexsign(A.x, A.y, B.x, B.y, px, py) == sigma &&
                lexsign(B.x, B.y, FAN_OX, FAN_OY, px, py) == sigma)
                sum += sigma;
        }
    }
    /* y grows downward: a triangle with positive E orientation winds -1 in
     * the spec's convention (dir = +1 for downward edges, counted on the left). */
    return -sum;
}

int64_t eo_sample_winding_fan(const eo_polygon *p, int samples, int64_t i, int64_t j, int s, int *err)
{
    int rc = validate(p, samples, 1, 1);
    if (!rc && (i < -EO_MAX_CANVAS || i > 2 * EO_MAX_CANVAS || j < -EO_MAX_CANVAS || j > 2 * EO_MAX_CANVAS || s < 0 ||
                s >= samples))
        rc = EO_ERR_ARG;
    if (err)
        *err = rc;
    if (rc)
        return 0;
    return winding_fan(p, eo_sample_x(samples, i, s), eo_sample_y(samples, samples * j + s));
}

int eo_coverage_fan(const eo_polygon *p, int rule_evenodd, int samples, int W, int H, uint32_t *mask_out)
{
    int rc = validate(p, samples, W, H);
    if (rc)
        return rc;
    if (!mask_out)
        return EO_ERR_ARG;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            uint32_t m = 0;
            for (int s = 0; s < samples; s++) {
                int64_t w = winding_fan(p, eo_sample_x(samples, i, s), eo_sample_y(samples, (int64_t)samples * j + s));
                if (rule_evenodd ? covered_evenodd(w) : covered_nonzero(w))
                    m |= (uint32_t)1 << s;
            }
            mask_out[(size_t)j * (size_t)W + (size_t)i] = m;
        }
    return EO_OK;
}

/* ----------------------------------------------------------- debug aids */
void eo_polygon_fprint(FILE *f, const eo_polygon *p)
{
    if (!p) {
        fprintf(f, "(null polygon)\n");
        return;
    }
    fprintf(f, "polygon: %u contours\n", (unsigned)p->ncontours);
    for (uint32_t c = 0; c < p->ncontours; c++) {
        uint32_t b = p->start[c], np = p->start[c + 1] - p->start[c];
        fprintf(f, "  contour %u (%u points):", (unsigned)c, (unsigned)np);
        for (uint32_t i = 0; i < np; i++)
            fprintf(f, " %ld,%ld", (long)p->pts[b + i].x, (long)p->pts[b + i].y);
        fprintf(f, "\n");
    }
}

void eo_explain_sample(FILE *f, const eo_polygon *p, int samples, int64_t i, int64_t j, int s)
{
    int err;
    (void)eo_sample_winding(p, samples, i, j, s, &err);
    if (err) {
        fprintf(f, "eo_explain_sample: error %d\n", err);
        return;
    }
    eo_edge *edges;
    size_t ne;
    if (build_edges(p, &edges, &ne)) {
        fprintf(f, "eo_explain_sample: out of memory\n");
        return;
    }
    int64_t r = (int64_t)samples * j + s;
    int64_t Xs = eo_sample_x(samples, i, s), Yr = eo_sample_y(samples, r);
    fprintf(f, "sample (i=%ld, j=%ld, s=%d) N=%d: row r=%ld, Xs=%ld, Yr=%ld (Q16.8)\n", (long)i, (long)j, s, samples,
            (long)r, (long)Xs, (long)Yr);
    int64_t w = 0;
    for (size_t q = 0; q < ne; q++) {
        const eo_edge *e = &edges[q];
        if (!crosses(e, Yr))
            continue;
        int64_t dY = e->y1 - e->y0, num = e->x0 * dY + (Yr - e->y0) * (e->x1 - e->x0);
        int cnt = counts(e, Xs, Yr);
        if (cnt)
            w += e->dir;
        fprintf(f, "  edge (%ld,%ld)-(%ld,%ld) dir %+d: x_r = %ld/%ld (Xs*dY = %ld) %s\n", (long)e->x0, (long)e->y0,
                (long)e->x1, (long)e->y1, e->dir, (long)num, (long)dY, (long)(Xs * dY),
                cnt ? "counted" : "right of sample");
    }
    fprintf(f, "  winding %ld: non-zero %s, even-odd %s; fan method winding %ld\n", (long)w,
            covered_nonzero(w) ? "covered" : "empty", covered_evenodd(w) ? "covered" : "empty",
            (long)eo_sample_winding_fan(p, samples, i, j, s, NULL));
    free(edges);
}

uint64_t eo_compare_masks(FILE *f, const uint32_t *expect, const uint32_t *got, int W, int H, int samples,
                          int max_report)
{
    uint64_t bad = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            size_t idx = (size_t)j * (size_t)W + (size_t)i;
            if (expect[idx] == got[idx])
                continue;
            if (f && bad < (uint64_t)(max_report < 0 ? 0 : max_report))
                fprintf(f, "pixel (%d,%d) N=%d: expect 0x%08lx got 0x%08lx xor 0x%08lx\n", i, j, samples,
                        (unsigned long)expect[idx], (unsigned long)got[idx], (unsigned long)(expect[idx] ^ got[idx]));
            bad++;
        }
    return bad;
}
