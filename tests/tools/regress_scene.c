/*
 * regress_scene.c - writes one seeded, deliberately nasty `.scene` for the
 * same-bits-everywhere checks (tests/portability.sh): every coordinate an
 * exact multiple of 1/256 written as its exact decimal, so every build reads
 * the same vertices, and shapes chosen to stress what a port could get wrong:
 *
 *   - random polygons of 3..40 vertices, partly far outside the canvas
 *     (clipping at the top and bottom, clamping left and right);
 *   - 130 coincident squares (the 7-bit winding counters wrap, spec 6.4);
 *   - vertices at the extremes of the device range (+-32767.99609375 px);
 *   - long nearly horizontal and nearly vertical edges (the DDA's remainder);
 *   - many tiny triangles smaller than a sub-pixel;
 *   - colours with every kind of alpha (compositing in every channel).
 *
 *   regress_scene [SEED] > regress.scene     (default seed 20070101)
 *
 * The generator is xorshift64* on uint64_t only: the text is the same on
 * every machine, and it is written by the reference build anyway.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#define W 257
#define H 131

static uint64_t st;
static uint64_t rnd(void)
{
    st ^= st >> 12;
    st ^= (st << 25) & UINT64_C(0xFFFFFFFFFFFFFFFF);
    st ^= st >> 27;
    return (st * UINT64_C(0x2545F4914F6CDD1D)) & UINT64_C(0xFFFFFFFFFFFFFFFF);
}
/* uniform in [lo, hi] (hi - lo < 2^32) */
static int64_t range(int64_t lo, int64_t hi) { return lo + (int64_t)((rnd() >> 32) % (uint64_t)(hi - lo + 1)); }

/* v / 256 as an exact decimal */
static void q8(int64_t v)
{
    int64_t a = v < 0 ? -v : v;
    printf(" %s%" PRId64, v < 0 ? "-" : "", a / 256);
    if (a % 256) {
        char d[16];
        int n = snprintf(d, sizeof d, "%08" PRId64, (a % 256) * 390625);
        while (n > 0 && d[n - 1] == '0')
            d[--n] = '\0';
        printf(".%s", d);
    }
}

static void shape(const char *rule)
{
    static const int alphas[] = { 255, 255, 128, 1, 254, 77 };
    printf("shape %s %d %d %d %d\n", rule, (int)range(0, 255), (int)range(0, 255), (int)range(0, 255),
           alphas[range(0, 5)]);
}

static void point(int64_t x, int64_t y)
{
    const int64_t lim = 32767 * 256 + 255; /* |v| < 2^23 */
    q8(x < -lim ? -lim : x > lim ? lim : x);
    q8(y < -lim ? -lim : y > lim ? lim : y);
}

int main(int argc, char **argv)
{
    st = argc > 1 ? strtoull(argv[1], NULL, 10) : 20070101u;
    if (st == 0)
        st = 1;
    printf("# tests/tools/regress_scene %s\nscene %d %d\n", argc > 1 ? argv[1] : "20070101", W, H);
    for (int i = 0; i < 40; i++) { /* random polygons, some far outside */
        shape(i % 2 ? "evenodd" : "nonzero");
        int n = (int)range(3, 40), c = (int)range(1, 3);
        for (int k = 0; k < c; k++) {
            printf("contour");
            int64_t reach = i % 5 == 0 ? 20000 : 300;
            for (int j = 0; j < n; j++)
                point(range(-reach * 256, (W + reach) * 256), range(-reach * 64, (H + reach / 4) * 256));
            printf("\n");
        }
    }
    shape("nonzero"); /* 130 coincident squares: winding wraps at 128 */
    for (int k = 0; k < 130; k++) {
        printf("contour");
        point(10 * 256 + 3, 10 * 256 + 5), point(60 * 256 + 1, 10 * 256 + 5), point(60 * 256 + 1, 50 * 256 + 7),
            point(10 * 256 + 3, 50 * 256 + 7);
        printf("\n");
    }
    shape("evenodd"); /* the extremes of the device range */
    printf("contour");
    point(-32767 * 256 - 255, -32767 * 256 - 255), point(32767 * 256 + 255, 3 * 256),
        point(100 * 256, 32767 * 256 + 255);
    printf("\n");
    shape("nonzero"); /* long nearly horizontal / vertical edges */
    printf("contour");
    point(-30000 * 256, 20 * 256), point(30000 * 256 + 17, 21 * 256 + 3), point(30000 * 256, 90 * 256 + 255),
        point(129 * 256 + 1, 30000 * 256), point(128 * 256, -30000 * 256 + 9);
    printf("\n");
    shape("evenodd"); /* tiny triangles */
    for (int k = 0; k < 300; k++) {
        int64_t x = range(0, W * 256), y = range(0, H * 256);
        printf("contour");
        point(x, y), point(x + range(-9, 9), y + range(1, 9)), point(x + range(-9, 9), y - range(1, 9));
        printf("\n");
    }
    return ferror(stdout) ? 1 : 0;
}
