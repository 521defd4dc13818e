/*
 * area_check.c - the model's coverage against exact-area coverage.
 *
 * The slow model (tests/oracle/) proves the model implements the spec; this
 * proves the spec itself samples well: that the n-rooks tables and the sample
 * offsets (2k+1)/(2N) give coverage close to the true area, without bias.  A
 * spec error the oracle would copy faithfully — samples shifted by half a
 * sub-pixel, a table that is not a good n-rooks pattern, an edge rule that
 * loses a row — shows up here as bias or a large error.
 *
 * For seeded random convex polygons (so area and winding coverage coincide
 * under both rules) on a small canvas, the exact covered area of every pixel is
 * computed in double precision by clipping the polygon to the pixel square
 * (Sutherland-Hodgman) and the shoelace formula (test code, outside the
 * integer-only model).  Over all partially covered pixels it reports the mean
 * signed error, RMS and max of (alpha - 255 * area) per sample count and
 * checks:
 *   |mean| <= 1.0 level, overall and on each side of the polygon (no bias;
 *   a sideways shift of the samples cancels overall but not per side)
 *   RMS(8) <= 16, RMS(16) <= 9, RMS(32) <= 6 levels, and RMS falls with N
 *   the covered area summed over all polygons within 0.1% of the exact sum
 * The bounds hold with a wide margin for good tables (see the printed values)
 * and fail for a biased or degenerate pattern.
 *
 *   area_check [--polygons K] [--seed S]     ends with "N passed, M failed"
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "edgeflag.h"
#include "ef_filter.h"

#define W 48
#define H 48

typedef struct {
    double x, y;
} dpt;

static uint64_t rng_state;
static uint64_t rng_next(void)
{
    uint64_t z = (rng_state += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}
static int64_t rng_range(int64_t lo, int64_t hi) { return lo + (int64_t)(rng_next() % (uint64_t)(hi - lo + 1)); }

/* Clips polygon `in` (n points) to the half-plane a*x + b*y <= c. */
static int clip_half(const dpt *in, int n, double a, double b, double c, dpt *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        dpt p = in[i], q = in[(i + 1) % n];
        double fp = a * p.x + b * p.y - c, fq = a * q.x + b * q.y - c;
        if (fp <= 0)
            out[m++] = p;
        if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
            double t = fp / (fp - fq);
            out[m++] = (dpt){ p.x + t * (q.x - p.x), p.y + t * (q.y - p.y) };
        }
    }
    return m;
}

static double area_abs(const dpt *p, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++)
        s += p[i].x * p[(i + 1) % n].y - p[(i + 1) % n].x * p[i].y;
    return fabs(s) / 2;
}

static double pixel_area_at(const dpt *poly, int n, double px, double py)
{
    dpt a[64], b[64];
    int m = clip_half(poly, n, -1, 0, -px, a);
    m = clip_half(a, m, 1, 0, px + 1, b);
    m = clip_half(b, m, 0, -1, -py, a);
    m = clip_half(a, m, 0, 1, py + 1, b);
    return m >= 3 ? area_abs(b, m) : 0;
}

static double pixel_area(const dpt *poly, int n, int px, int py)
{
    dpt a[64], b[64];
    int m = clip_half(poly, n, -1, 0, -px, a); /* x >= px */
    m = clip_half(a, m, 1, 0, px + 1, b);      /* x <= px+1 */
    m = clip_half(b, m, 0, -1, -py, a);        /* y >= py */
    m = clip_half(a, m, 0, 1, py + 1, b);      /* y <= py+1 */
    return m >= 3 ? area_abs(b, m) : 0;
}

static unsigned popcount32(uint32_t v)
{
    unsigned c = 0;
    for (; v; v &= v - 1)
        c++;
    return c;
}

static uint32_t masks[W * H];
static void put(void *u, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    (void)u;
    for (int32_t i = 0; i < len; i++)
        masks[y * W + x + i] = mask;
}

/* A random convex polygon: points on an ellipse at sorted random angles,
 * snapped to 1/256 px, counter- or clockwise. */
static int make_convex(ef_point *pts, dpt *d)
{
    int n = (int)rng_range(3, 12);
    double cx = (double)rng_range(256 * 4, 256 * (W - 4)) / 256, cy = (double)rng_range(256 * 4, 256 * (H - 4)) / 256;
    double rx = (double)rng_range(256 * 1, 256 * 20) / 256, ry = (double)rng_range(256 * 1, 256 * 20) / 256;
    double ang[12];
    for (int i = 0; i < n; i++)
        ang[i] = (double)(rng_next() % 1000000) / 1000000 * 6.283185307179586;
    for (int i = 1; i < n; i++) /* insertion sort */
        for (int j = i; j > 0 && ang[j] < ang[j - 1]; j--) {
            double t = ang[j];
            ang[j] = ang[j - 1];
            ang[j - 1] = t;
        }
    int rev = (int)(rng_next() & 1);
    for (int i = 0; i < n; i++) {
        double a = ang[rev ? n - 1 - i : i];
        pts[i].x = (int32_t)lround((cx + rx * cos(a)) * 256);
        pts[i].y = (int32_t)lround((cy + ry * sin(a)) * 256);
        d[i] = (dpt){ pts[i].x / 256.0, pts[i].y / 256.0 };
    }
    return n;
}

/* ---- --filter: docs/spec.md section 10 against exact filtered coverage ----
 * The tent's exact coverage of pixel (i, j) for a channel shifted by d px is
 * the integral over the polygon of t(x - xc) t(y - yc), t(u) = 1 - |u| on
 * [-1, 1], centre (xc, yc) = (i + 1/2 + d, j + 1/2).  On each of the base's
 * four unit squares the kernel is a product of linear functions,
 * (a0 + a1 u)(b0 + b1 v) in the square's local coordinates, so its integral
 * over the polygon clipped to the square is a combination of the clipped
 * polygon's moments A, Sx, Sy, Sxy (closed forms of Green's theorem). */
static void moments(const dpt *p, int n, double ox, double oy, double m[4])
{
    double A = 0, Sx = 0, Sy = 0, Sxy = 0;
    for (int i = 0; i < n; i++) {
        const double x0 = p[i].x - ox, y0 = p[i].y - oy, x1 = p[(i + 1) % n].x - ox, y1 = p[(i + 1) % n].y - oy;
        const double cr = x0 * y1 - x1 * y0;
        A += cr;
        Sx += (x0 + x1) * cr;
        Sy += (y0 + y1) * cr;
        Sxy += cr * (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0);
    }
    const double sg = A < 0 ? -1 : 1;
    m[0] = sg * A / 2;
    m[1] = sg * Sx / 6;
    m[2] = sg * Sy / 6;
    m[3] = sg * Sxy / 24;
}

static double clip_box(const dpt *poly, int n, double x0, double y0, double x1, double y1, dpt *out)
{
    dpt a[64];
    int m = clip_half(poly, n, -1, 0, -x0, a);
    m = clip_half(a, m, 1, 0, x1, out);
    m = clip_half(out, m, 0, -1, -y0, a);
    m = clip_half(a, m, 0, 1, y1, out);
    return m;
}

static double tent_exact(const dpt *poly, int n, double xc, double yc)
{
    double total = 0;
    for (int sx = 0; sx < 2; sx++)
        for (int sy = 0; sy < 2; sy++) {
            dpt c[64];
            const double ox = xc - 1 + sx, oy = yc - 1 + sy;
            const int m = (int)clip_box(poly, n, ox, oy, ox + 1, oy + 1, c);
            if (m < 3)
                continue;
            double mo[4];
            moments(c, m, ox, oy, mo);
            /* left/top square: weight u (resp. v); right/bottom: 1 - u */
            const double a0 = sx ? 1 : 0, a1 = sx ? -1 : 1, b0 = sy ? 1 : 0, b1 = sy ? -1 : 1;
            total += a0 * b0 * mo[0] + a1 * b0 * mo[1] + a0 * b1 * mo[2] + a1 * b1 * mo[3];
        }
    return total;
}

static uint32_t fsum[W * H * 3];
static void put_cov(void *u, int32_t y, int32_t x, const uint32_t sum[3])
{
    (void)u;
    memcpy(&fsum[(y * W + x) * 3], sum, sizeof fsum[0] * 3);
}

/* Per filter setting and N: alpha of each channel against 255 x the exact
 * filtered coverage, over the pixels the shape covers partly.  Bounds: no
 * bias (|mean| <= 1 level), RMS below the box's bound for N, falling with N. */
static int filter_check(int polys, uint64_t seed)
{
    static const struct {
        const char *name;
        ef_filter f;
        ef_subpixel s;
    } cfs[] = {
        { "tent", EF_FILTER_TENT, EF_SUBPIXEL_NONE },
        { "tent, RGB offsets", EF_FILTER_TENT, EF_SUBPIXEL_RGB },
        { "box, RGB offsets", EF_FILTER_BOX, EF_SUBPIXEL_RGB },
    };
    /* the box's bounds; the tent (4N weighted samples) must do better than half of them */
    static const double rms_bound[3] = { 16, 9, 6 };
    int pass = 0, fail = 0;
    for (int k = 0; k < 3; k++) {
        double rms_prev = 1e9;
        for (int t = 0; t < 3; t++) {
            const int n = 8 << t;
            rng_state = seed;
            ef_ctx *ctx;
            if (ef_ctx_create(&ctx, W, H, n) != EF_OK || ef_ctx_set_filter(ctx, cfs[k].f, cfs[k].s) != EF_OK)
                return 70;
            const double den = ef_filter_denominator(ctx);
            double sum = 0, sum2 = 0, maxe = 0;
            long count = 0;
            for (int p = 0; p < polys; p++) {
                ef_point pts[12];
                dpt d[12];
                const int np = make_convex(pts, d);
                uint32_t start[2] = { 0, (uint32_t)np };
                ef_polygon poly = { pts, start, 1 };
                memset(fsum, 0, sizeof fsum);
                if (ef_filter_coverage(ctx, &poly, (p & 1) ? EF_RULE_EVENODD : EF_RULE_NONZERO, put_cov, NULL) != EF_OK)
                    return 70;
                for (int c = 0; c < 3; c++) {
                    const double shift = cfs[k].s == EF_SUBPIXEL_NONE ? 0 : (c - 1) * 85 / 256.0;
                    for (int y = 0; y < H; y++)
                        for (int x = 0; x < W; x++) {
                            const double a = cfs[k].f == EF_FILTER_TENT ? tent_exact(d, np, x + 0.5 + shift, y + 0.5)
                                                                        : pixel_area_at(d, np, x + shift, y);
                            if (a <= 1e-12 || a >= 1 - 1e-12)
                                continue;
                            const double alpha = floor((255.0 * fsum[(y * W + x) * 3 + c] + den / 2) / den);
                            const double e = alpha - 255 * a;
                            sum += e;
                            sum2 += e * e;
                            maxe = fabs(e) > maxe ? fabs(e) : maxe;
                            count++;
                        }
                }
            }
            ef_ctx_destroy(ctx);
            const double mean = sum / (double)count, rms = sqrt(sum2 / (double)count);
            const double bound = cfs[k].f == EF_FILTER_TENT ? rms_bound[t] / 2 : rms_bound[t];
            const int ok = fabs(mean) <= 1.0 && rms <= bound && rms < rms_prev;
            printf(
                "area: %-18s N=%2d  %ld partial channel values of %d convex polygons: mean %+.3f, RMS %.3f, max %.1f levels %s\n",
                cfs[k].name, n, count, polys, mean, rms, maxe, ok ? "ok" : "FAILED");
            ok ? pass++ : fail++;
            rms_prev = rms;
        }
    }
    printf("area: %d passed, %d failed\n", pass, fail);
    return fail ? 1 : 0;
}

int main(int argc, char **argv)
{
    int polys = 400;
    uint64_t seed = 20070101;
    int filter = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--filter"))
            filter = 1;
        else if (!strcmp(argv[i], "--polygons") && i + 1 < argc)
            polys = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else {
            fprintf(stderr, "usage: area_check [--filter] [--polygons K] [--seed S]\n");
            return 2;
        }
    }
    if (filter)
        return filter_check(polys, seed);
    static const double rms_bound[3] = { 16, 9, 6 };
    double rms_prev = 1e9;
    int pass = 0, fail = 0;
    for (int t = 0; t < 3; t++) {
        int n = 8 << t;
        rng_state = seed;
        double sum = 0, sum2 = 0, maxe = 0, cov_model = 0, cov_exact = 0;
        double side_sum[4] = { 0, 0, 0, 0 }; /* left, right, top, bottom of the centre */
        long side_n[4] = { 0, 0, 0, 0 };
        long count = 0;
        ef_ctx *ctx;
        if (ef_ctx_create(&ctx, W, H, n) != EF_OK)
            return 70;
        for (int p = 0; p < polys; p++) {
            ef_point pts[12];
            dpt d[12];
            int np = make_convex(pts, d);
            uint32_t start[2] = { 0, (uint32_t)np };
            ef_polygon poly = { pts, start, 1 };
            memset(masks, 0, sizeof masks);
            if (ef_rasterize(ctx, &poly, (p & 1) ? EF_RULE_EVENODD : EF_RULE_NONZERO, put, NULL) != EF_OK)
                return 70;
            double total = 0, total_exact = 0, gx = 0, gy = 0;
            for (int k = 0; k < np; k++) {
                gx += d[k].x / np;
                gy += d[k].y / np;
            }
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++) {
                    double a = pixel_area(d, np, x, y);
                    uint32_t m = masks[y * W + x];
                    total_exact += a;
                    total += (double)popcount32(m) / n;
                    if (a <= 0 || a >= 1)
                        continue; /* interior and exterior pixels are exact */
                    double e = ef_coverage_alpha(m, n) - 255 * a;
                    sum += e;
                    sum2 += e * e;
                    int sx = x + 0.5 < gx ? 0 : 1, sy = y + 0.5 < gy ? 2 : 3;
                    side_sum[sx] += e;
                    side_n[sx]++;
                    side_sum[sy] += e;
                    side_n[sy]++;
                    maxe = fabs(e) > maxe ? fabs(e) : maxe;
                    count++;
                }
            cov_model += total;
            cov_exact += total_exact;
        }
        ef_ctx_destroy(ctx);
        double mean = sum / (double)count, rms = sqrt(sum2 / (double)count);
        double total_err = fabs(cov_model - cov_exact) / cov_exact;
        /* A sample grid shifted sideways errs one way on left edges and the
         * other way on right edges, which cancels in the overall mean: so the
         * bias is checked per side of the polygon. */
        double side_bias = 0;
        for (int k = 0; k < 4; k++) {
            double m = side_sum[k] / (double)side_n[k];
            side_bias = fabs(m) > side_bias ? fabs(m) : side_bias;
        }
        printf(
            "area: N=%2d  %ld partial pixels of %d convex polygons (seed %llu): mean %+.3f (worst side %.3f), RMS %.3f, max %.1f levels;"
            " covered area %.1f px^2 vs exact %.1f (%.4f%%)\n",
            n, count, polys, (unsigned long long)seed, mean, side_bias, rms, maxe, cov_model, cov_exact,
            100 * total_err);
        int ok = fabs(mean) <= 1.0 && side_bias <= 1.0 && rms <= rms_bound[t] && rms < rms_prev && total_err <= 0.001;
        printf(
            "area: N=%2d %s (bounds: |mean| and each side's mean <= 1, RMS <= %.0f and below the previous N, total area within 0.1%%)\n",
            n, ok ? "ok" : "FAILED", rms_bound[t]);
        ok ? pass++ : fail++;
        rms_prev = rms;
    }
    printf("area: %d passed, %d failed\n", pass, fail);
    return fail ? 1 : 0;
}
