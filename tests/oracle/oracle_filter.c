/*
 * oracle_filter.c - the slow model of docs/spec.md section 10 (the 2x2-pixel
 * tent filter and the per-channel sample offsets), written from that text.
 *
 * Where the model translates the geometry and reuses its blocks on a larger
 * mask canvas (model/filter.c), this evaluates spec 5.1 directly at the
 * shifted sample positions, and weighs each sample by its distance from the
 * output pixel's centre (256 - |X - Xc|) (256 - |Y - Yc|) in Q16.8 units,
 * not by the per-k, per-s table of the spec's integer form: the two agree only
 * if the spec's algebra is right.  Sums come with the denominator
 * D = 65536 N (tent) or N (box).
 */
#include "oracle.h"

#include <stdlib.h>
#include <string.h>

#define EOF_CHECK(cond) \
    do { \
        if (!(cond)) { \
            fprintf(stderr, "%s:%d: oracle invariant failed: %s\n", __FILE__, __LINE__, #cond); \
            abort(); \
        } \
    } while (0)

typedef struct fedge {
    int64_t x0, y0, x1, y1;
    int dir;
} fedge;

int eo_filter_shift(int subpixel, int colour)
{
    /* spec 10.1: R, G, B sample offsets, Q16.8 */
    static const int shift[3][3] = { { 0, 0, 0 }, { -85, 0, 85 }, { 85, 0, -85 } };
    return shift[subpixel][colour];
}

uint32_t eo_filter_denominator(int filter, int samples)
{
    return filter ? 65536u * (uint32_t)samples : (uint32_t)samples;
}

/* Spec 5.1 at (Xs, Yr), exact: Y0 <= Yr < Y1 and (X0 - Xs) dY + (Yr - Y0) dX <= 0. */
static int counts_at(const fedge *e, int64_t Xs, int64_t Yr)
{
    const int64_t dY = e->y1 - e->y0, dX = e->x1 - e->x0, a = e->x0 - Xs, b = Yr - e->y0;
    EOF_CHECK(b >= 0 && b < ((int64_t)1 << 25) && a > -((int64_t)1 << 26) && a < ((int64_t)1 << 26));
    return a * dY + b * dX <= 0;
}

/* Masks of the samples at the spec's positions shifted by (sx, sy), for
 * pixels (p, q) in [0, Wm) x [0, Hm): bit s of m[q*Wm + p] is covered. */
static void shifted_masks(const fedge *E, size_t ne, int samples, int Wm, int Hm, int64_t sx, int64_t sy, int evenodd,
                          uint32_t *m, int64_t *diff)
{
    const uint8_t *k = eo_pattern(samples);
    const int64_t h = 256 / samples, c = h / 2;
    memset(m, 0, (size_t)Wm * (size_t)Hm * sizeof *m);
    int64_t ylo = INT64_MAX, yhi = INT64_MIN; /* rows no edge crosses stay empty */
    for (size_t i = 0; i < ne; i++) {
        ylo = E[i].y0 < ylo ? E[i].y0 : ylo;
        yhi = E[i].y1 > yhi ? E[i].y1 : yhi;
    }
    for (int q = 0; q < Hm; q++)
        for (int s = 0; s < samples; s++) {
            const int64_t Yr = h * ((int64_t)samples * q + s) + c + sy, base = h * k[s] + c + sx;
            if (Yr < ylo || Yr >= yhi)
                continue;
            memset(diff, 0, ((size_t)Wm + 1) * sizeof *diff);
            for (size_t i = 0; i < ne; i++) {
                if (!(E[i].y0 <= Yr && Yr < E[i].y1))
                    continue;
                int64_t lo = 0, hi = Wm; /* first pixel whose sample counts it */
                while (lo < hi) {
                    const int64_t mid = lo + (hi - lo) / 2;
                    if (counts_at(&E[i], base + 256 * mid, Yr))
                        hi = mid;
                    else
                        lo = mid + 1;
                }
                diff[lo] += E[i].dir;
            }
            int64_t w = 0;
            for (int p = 0; p < Wm; p++) {
                w += diff[p];
                if (evenodd ? w % 2 != 0 : w % 128 != 0)
                    m[(size_t)q * (size_t)Wm + (size_t)p] |= UINT32_C(1) << s;
            }
        }
}

int eo_filter_eval(const eo_polygon *p, int samples, int W, int H, int filter, int subpixel, int evenodd,
                   uint32_t *sums)
{
    if (!p || !eo_pattern(samples) || W < 1 || H < 1 || W > EO_MAX_CANVAS - 1 || H > EO_MAX_CANVAS - 1 || filter < 0 ||
        filter > 1 || subpixel < 0 || subpixel > 2 || !sums)
        return EO_ERR_ARG;
    const int e = filter, Wm = W + e, Hm = H + e, nch = subpixel ? 3 : 1;
    const int64_t t = filter ? 128 : 0;
    const uint32_t npts = p->ncontours ? p->start[p->ncontours] - p->start[0] : 0;
    /* spec 10.1: every vertex moved by -(shift) must stay inside |v| < 2^23 */
    for (int ch = 0; ch < nch; ch++)
        for (uint32_t i = p->ncontours ? p->start[0] : 0; i < (p->ncontours ? p->start[p->ncontours] : 0); i++) {
            const int64_t x = (int64_t)p->pts[i].x - (eo_filter_shift(subpixel, ch) - t), y = (int64_t)p->pts[i].y + t;
            if (x <= -EO_COORD_LIMIT || x >= EO_COORD_LIMIT || y <= -EO_COORD_LIMIT || y >= EO_COORD_LIMIT)
                return EO_ERR_RANGE;
        }
    fedge *E = malloc(((size_t)npts + 1) * sizeof *E);
    uint32_t *m = malloc((size_t)Wm * (size_t)Hm * sizeof *m);
    int64_t *diff = malloc(((size_t)Wm + 1) * sizeof *diff);
    if (!E || !m || !diff) {
        free(E);
        free(m);
        free(diff);
        return EO_ERR_NOMEM;
    }
    size_t ne = 0;
    for (uint32_t ci = 0; ci < p->ncontours; ci++) {
        const uint32_t b = p->start[ci], n = p->start[ci + 1] - b;
        for (uint32_t i = 0; i < n; i++) {
            const eo_point a = p->pts[b + i], z = p->pts[b + (i + 1) % n];
            if (a.y == z.y)
                continue;
            E[ne++] = a.y < z.y ? (fedge){ a.x, a.y, z.x, z.y, 1 } : (fedge){ z.x, z.y, a.x, a.y, -1 };
        }
    }
    const uint8_t *k = eo_pattern(samples);
    const int64_t h = 256 / samples, c = h / 2;
    memset(sums, 0, (size_t)W * (size_t)H * 3 * sizeof *sums);
    for (int ch = 0; ch < 3; ch++) {
        if (ch >= nch) { /* no offsets: every channel is channel 0 */
            for (size_t i = 0; i < (size_t)W * (size_t)H; i++)
                sums[i * 3 + (size_t)ch] = sums[i * 3];
            continue;
        }
        const int64_t delta = eo_filter_shift(subpixel, ch);
        shifted_masks(E, ne, samples, Wm, Hm, delta - t, -t, evenodd, m, diff);
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++) {
                uint64_t acc = 0;
                if (!filter) {
                    for (uint32_t v = m[(size_t)j * (size_t)Wm + (size_t)i]; v; v &= v - 1)
                        acc++;
                } else {
                    /* the base's four pixels; weights from the samples' distances to the centre */
                    const int64_t Xc = 256 * (int64_t)i + 128 + delta, Yc = 256 * (int64_t)j + 128;
                    const uint32_t *m0 = &m[(size_t)j * (size_t)Wm + (size_t)i], *m1 = m0 + Wm;
                    if (!(m0[0] | m0[1] | m1[0] | m1[1]))
                        continue; /* nothing covered in the base (sums are 0) */
                    for (int b = 0; b < 2; b++)
                        for (int a = 0; a < 2; a++) {
                            const uint32_t v = m[(size_t)(j + b) * (size_t)Wm + (size_t)(i + a)];
                            for (int s = 0; s < samples; s++) {
                                if (!(v >> s & 1))
                                    continue;
                                const int64_t X = 256 * (int64_t)(i + a) + h * k[s] + c + delta - t;
                                const int64_t Y = 256 * (int64_t)(j + b) + h * s + c - t;
                                const int64_t dx = X > Xc ? X - Xc : Xc - X, dy = Y > Yc ? Y - Yc : Yc - Y;
                                EOF_CHECK(dx < 256 && dy < 256);
                                acc += (uint64_t)((256 - dx) * (256 - dy));
                            }
                        }
                }
                sums[((size_t)j * (size_t)W + (size_t)i) * 3 + (size_t)ch] = (uint32_t)acc;
            }
    }
    free(E);
    free(m);
    free(diff);
    return EO_OK;
}
