/*
 * filter_check.c - the section 3.5 options (docs/spec.md section 10) against
 * the slow model (tests/oracle/oracle_filter.c, written from the spec text):
 *
 *   - coverage: ef_filter_coverage's per-channel sums equal the oracle's (as
 *     exact rationals: the model's denominator is 4 N^3 or N, the oracle's
 *     65536 N or N) for every shape of every shared SVG at 8/16/32 samples and
 *     for K seeded random polygons (tests/oracle/randpoly.c), under each
 *     option setting; a polygon that a channel's shift takes out of range
 *     must be refused by both;
 *   - compositing: ef_fill (through ef_scene_render) paints, bit for bit,
 *     the image spec 10.4 gives with the oracle's coverage;
 *   - off by default: a context whose options were set back to box/none
 *     renders the same bytes as a fresh one.
 *
 *   filter_check [--shared DIR] [--random K] [--seed S] [--configs LIST]
 *
 * LIST: comma-separated of box-rgb, box-bgr, tent-none, tent-rgb, tent-bgr
 * (default all five).  Ends with "filter: N passed, M failed".
 */
#include <dirent.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "edgeflag.h"
#include "ef_filter.h"
#include "ef_scene.h"
#include "oracle.h"
#include "randpoly.h"

typedef struct config {
    const char *name;
    int filter, subpixel;
} config;
static const config all_configs[] = {
    { "box-rgb", EF_FILTER_BOX, EF_SUBPIXEL_RGB },     { "box-bgr", EF_FILTER_BOX, EF_SUBPIXEL_BGR },
    { "tent-none", EF_FILTER_TENT, EF_SUBPIXEL_NONE }, { "tent-rgb", EF_FILTER_TENT, EF_SUBPIXEL_RGB },
    { "tent-bgr", EF_FILTER_TENT, EF_SUBPIXEL_BGR },
};
#define NCONF ((int)(sizeof all_configs / sizeof all_configs[0]))

static uint64_t passed, failed, compared, refused;

typedef struct grid {
    int32_t w;
    uint32_t *s;
} grid;
static void put_cov(void *user, int32_t y, int32_t x, const uint32_t sum[3])
{
    grid *g = user;
    memcpy(&g->s[((size_t)y * (size_t)g->w + (size_t)x) * 3], sum, 3 * sizeof *sum);
}

static void die(const char *what)
{
    fprintf(stderr, "filter_check: %s\n", what);
    exit(2);
}

/* One polygon, one rule, one config: model against oracle.  want (W*H*3)
 * receives the oracle's sums (for the compositing check).  Returns 0 if equal. */
static int compare_cov(const char *what, const eo_polygon *op, int rule_eo, int samples, int W, int H, const config *cf,
                       ef_ctx *ctx, uint32_t *want, uint32_t *got)
{
    const size_t n = (size_t)W * (size_t)H * 3;
    const int orc = eo_filter_eval(op, samples, W, H, cf->filter, cf->subpixel, rule_eo, want);
    if (orc != EO_OK && orc != EO_ERR_RANGE)
        die("oracle failed");
    memset(got, 0, n * sizeof *got);
    grid g = { W, got };
    ef_polygon mp = { (const ef_point *)op->pts, op->start, op->ncontours };
    const ef_status st = ef_filter_coverage(ctx, &mp, rule_eo ? EF_RULE_EVENODD : EF_RULE_NONZERO, put_cov, &g);
    if (orc == EO_ERR_RANGE || st != EF_OK) {
        if (orc == EO_ERR_RANGE && st == EF_ERR_ARG) {
            refused++;
            return 0; /* both refuse it */
        }
        printf("MISMATCH %s %s N=%d: oracle %s, model %s\n", what, cf->name, samples,
               orc ? "refuses (range)" : "accepts", ef_strerror(st));
        return 1;
    }
    const uint64_t dm = ef_filter_denominator(ctx), dor = eo_filter_denominator(cf->filter, samples);
    compared += n;
    for (size_t i = 0; i < n; i++)
        if ((uint64_t)got[i] * dor != (uint64_t)want[i] * dm) {
            const size_t px = i / 3;
            printf("MISMATCH %s %s N=%d rule=%s: pixel (%zu, %zu) channel %c: model %" PRIu32 "/%" PRIu64
                   ", oracle %" PRIu32 "/%" PRIu64 "\n",
                   what, cf->name, samples, rule_eo ? "evenodd" : "nonzero", px % (size_t)W, px / (size_t)W,
                   "RGB"[i % 3], got[i], dm, want[i], dor);
            if (op->start[op->ncontours] < 40)
                eo_polygon_fprint(stdout, op);
            return 1;
        }
    return 0;
}

static uint8_t mul(uint32_t a, uint32_t b)
{
    uint32_t t = a * b + 128;
    return (uint8_t)(((t >> 8) + t) >> 8);
}

/* Spec 10.4 from the oracle's sums, onto a premultiplied RGBA8 image. */
static void composite(uint8_t *img, int W, int H, const uint32_t *sums, uint32_t den, ef_rgba8 col)
{
    const uint8_t P[4] = { mul(col.r, col.a), mul(col.g, col.a), mul(col.b, col.a), col.a };
    for (size_t i = 0; i < (size_t)W * (size_t)H; i++) {
        const uint32_t *s = &sums[i * 3];
        if (!(s[0] | s[1] | s[2]))
            continue;
        uint32_t cov[4];
        for (int c = 0; c < 3; c++)
            cov[c] = (uint32_t)(((uint64_t)255 * s[c] + den / 2) / den);
        cov[3] = cov[1];
        for (int c = 0; c < 4; c++) {
            uint8_t *d = &img[i * 4 + (size_t)c];
            *d = (uint8_t)(*d + mul(P[c], cov[c]) - mul(*d, mul(col.a, cov[c])));
        }
    }
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void check_shared(const char *dir, const config *cf, int ncf)
{
    DIR *d = opendir(dir);
    if (!d)
        die("cannot open the shared SVG folder");
    char *names[256];
    int nn = 0;
    struct dirent *de;
    while ((de = readdir(d)) && nn < 256) {
        size_t l = strlen(de->d_name);
        if (l > 4 && strcmp(de->d_name + l - 4, ".svg") == 0)
            names[nn++] = strdup(de->d_name);
    }
    closedir(d);
    if (nn == 0)
        die("no SVG in the shared folder");
    qsort(names, (size_t)nn, sizeof names[0], cmp_str);
    for (int f = 0; f < nn; f++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, names[f]);
        ef_scene sc;
        ef_error err;
        ef_load_opts o = { 0 };
        if (ef_scene_load_file(path, &o, &sc, &err) != EF_OK)
            die("a shared SVG does not load");
        const int W = sc.width, H = sc.height;
        const size_t n = (size_t)W * (size_t)H;
        uint32_t *want = malloc(n * 3 * sizeof *want), *got = malloc(n * 3 * sizeof *got);
        uint8_t *oimg = malloc(n * 4);
        if (!want || !got || !oimg)
            die("out of memory");
        uint64_t bad0 = failed;
        for (int c = 0; c < ncf; c++)
            for (int ns = 8; ns <= 32; ns *= 2) {
                ef_ctx *ctx;
                ef_image img;
                if (ef_ctx_create(&ctx, W, H, ns) != EF_OK ||
                    ef_ctx_set_filter(ctx, cf[c].filter, cf[c].subpixel) != EF_OK ||
                    ef_image_create(&img, W, H) != EF_OK)
                    die("context");
                memset(oimg, 0, n * 4);
                int bad = 0;
                for (uint32_t s = 0; s < sc.nshapes; s++) {
                    ef_polygon p = ef_scene_polygon(&sc, s);
                    eo_polygon op = { (const eo_point *)p.pts, p.start, p.ncontours };
                    char what[400];
                    snprintf(what, sizeof what, "%s shape %u", names[f], s);
                    const int eo = sc.shapes[s].rule == EF_RULE_EVENODD;
                    bad |= compare_cov(what, &op, eo, ns, W, H, &cf[c], ctx, want, got);
                    composite(oimg, W, H, want, eo_filter_denominator(cf[c].filter, ns), sc.shapes[s].color);
                }
                if (ef_scene_render(ctx, &sc, -1, &img) != EF_OK || memcmp(img.px, oimg, n * 4) != 0) {
                    printf("MISMATCH %s %s N=%d: ef_fill's image is not spec 10.4 of the oracle's coverage\n", names[f],
                           cf[c].name, ns);
                    bad = 1;
                }
                bad ? failed++ : passed++;
                ef_image_destroy(&img);
                ef_ctx_destroy(ctx);
            }
        printf("filter: %-44s %4u shapes %4dx%-4d %s\n", names[f], sc.nshapes, W, H,
               failed == bad0 ? "agree" : "DIFFER");
        fflush(stdout);
        free(want);
        free(got);
        free(oimg);
        ef_scene_destroy(&sc);
        free(names[f]);
    }
}

static void check_random(uint64_t count, uint64_t seed, const config *cf, int ncf)
{
    eo_rng g;
    eo_rng_seed(&g, seed);
    eo_randpoly rp;
    eo_randpoly_init(&rp);
    uint32_t *want = malloc(200 * 200 * 3 * sizeof *want), *got = malloc(200 * 200 * 3 * sizeof *got);
    if (!want || !got)
        die("out of memory");
    for (uint64_t i = 0; i < count; i++) {
        int W, H, samples, rule_eo;
        eo_rand_config(&g, &W, &H, &samples, &rule_eo);
        const uint64_t pseed = eo_rng_next(&g);
        eo_randpoly_opts o = { samples, 0, 0, 0 };
        if (eo_randpoly_gen(&rp, pseed, W, H, &o) != EO_OK)
            die("generator failed");
        const config *c = &cf[i % (uint64_t)ncf];
        ef_ctx *ctx;
        if (ef_ctx_create(&ctx, W, H, samples) != EF_OK || ef_ctx_set_filter(ctx, c->filter, c->subpixel) != EF_OK)
            die("context");
        eo_polygon op = eo_randpoly_view(&rp);
        char what[200];
        snprintf(what, sizeof what, "random scene %" PRIu64 " (polygon seed 0x%016" PRIx64 ", %dx%d)", i, pseed, W, H);
        compare_cov(what, &op, rule_eo, samples, W, H, c, ctx, want, got) ? failed++ : passed++;
        ef_ctx_destroy(ctx);
    }
    free(want);
    free(got);
    eo_randpoly_free(&rp);
}

/* Options set and then set back to box/none render what a fresh context does. */
static void check_default(void)
{
    static const ef_point pts[] = { { 100, 50 }, { 2000, 700 }, { 900, 2100 }, { 300, 1500 } };
    static const uint32_t start[] = { 0, 4 };
    ef_polygon p = { pts, start, 1 };
    ef_ctx *a, *b;
    ef_image ia, ib;
    if (ef_ctx_create(&a, 10, 10, 16) || ef_ctx_create(&b, 10, 10, 16) || ef_image_create(&ia, 10, 10) ||
        ef_image_create(&ib, 10, 10))
        die("context");
    ef_rgba8 col = { 200, 100, 50, 180 };
    int ok = ef_ctx_set_filter(b, EF_FILTER_TENT, EF_SUBPIXEL_RGB) == EF_OK &&
             ef_ctx_set_filter(b, EF_FILTER_BOX, EF_SUBPIXEL_NONE) == EF_OK &&
             ef_fill(a, &ia, &p, EF_RULE_NONZERO, col) == EF_OK && ef_fill(b, &ib, &p, EF_RULE_NONZERO, col) == EF_OK &&
             memcmp(ia.px, ib.px, 400) == 0 && ef_ctx_set_filter(b, (ef_filter)2, EF_SUBPIXEL_NONE) == EF_ERR_ARG &&
             ef_ctx_set_filter(b, EF_FILTER_BOX, (ef_subpixel)3) == EF_ERR_ARG;
    ef_ctx *big;
    if (ef_ctx_create(&big, EF_MAX_CANVAS, 1, 8) != EF_OK)
        die("context");
    ok = ok && ef_ctx_set_filter(big, EF_FILTER_TENT, EF_SUBPIXEL_NONE) == EF_ERR_ARG &&
         ef_ctx_set_filter(big, EF_FILTER_BOX, EF_SUBPIXEL_RGB) == EF_OK;
    /* Spec 10.2's canvas edge, worked by hand: a shape covering exactly the
     * 4x3 canvas gives the tent's mass inside, 7/8 on a side, about 49/64 in a
     * corner, all of it inside; with RGB offsets the box's R channel at the
     * left border loses the samples of the columns k with 16k + 8 < 85, k <= 4:
     * 5 of 16 (and B at the right border those with 16k + 8 + 85 >= 256). */
    ef_ctx *t;
    static const ef_point full[4] = { { 0, 0 }, { 1024, 0 }, { 1024, 768 }, { 0, 768 } };
    ef_polygon fp = { full, start, 1 };
    uint32_t got[4 * 3 * 3];
    grid g = { 4, got };
    if (ef_ctx_create(&t, 4, 3, 16) != EF_OK || ef_ctx_set_filter(t, EF_FILTER_TENT, EF_SUBPIXEL_NONE) != EF_OK)
        die("context");
    memset(got, 0, sizeof got);
    const uint32_t D = 4 * 16 * 16 * 16;
    /* sides exactly 7/8 (every sample row's weights sum to 2N); a corner is 49/64 of the tent's mass but
     * its samples are the pattern's in one quadrant, so only its alpha is the exact one: 195 */
    ok = ok && ef_filter_coverage(t, &fp, EF_RULE_NONZERO, put_cov, &g) == EF_OK && (255 * got[0] + D / 2) / D == 195 &&
         got[3 * 1] == D / 8 * 7 && got[3 * 4] == D / 8 * 7 && got[3 * 5] == D && got[3 * 6] == D &&
         (255 * got[3 * 11] + D / 2) / D == 195;
    ok = ok && ef_ctx_set_filter(t, EF_FILTER_BOX, EF_SUBPIXEL_RGB) == EF_OK;
    memset(got, 0, sizeof got);
    ok = ok && ef_filter_coverage(t, &fp, EF_RULE_NONZERO, put_cov, &g) == EF_OK && got[0] == 16 - 5 && got[1] == 16 &&
         got[2] == 16 && got[3 * 3 + 2] == 16 - 5 && got[3 * 3] == 16;
    ef_ctx_destroy(t);
    printf("filter: options set back to box/none render as a fresh context; bad values and a %d-px tent refused; "
           "canvas edges worked by hand (tent 7/8 on a side, alpha 195 in a corner, RGB stripes 11/16): %s\n",
           EF_MAX_CANVAS, ok ? "ok" : "FAILED");
    ok ? passed++ : failed++;
    ef_ctx_destroy(big);
    ef_ctx_destroy(a);
    ef_ctx_destroy(b);
    ef_image_destroy(&ia);
    ef_image_destroy(&ib);
}

int main(int argc, char **argv)
{
    const char *shared = NULL;
    uint64_t count = 0, seed = 20070101;
    config cf[NCONF];
    int ncf = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--shared") && i + 1 < argc)
            shared = argv[++i];
        else if (!strcmp(argv[i], "--random") && i + 1 < argc)
            count = strtoull(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--configs") && i + 1 < argc) {
            char *list = argv[++i];
            for (char *tok = strtok(list, ","); tok; tok = strtok(NULL, ",")) {
                int k = 0;
                while (k < NCONF && strcmp(all_configs[k].name, tok) != 0)
                    k++;
                if (k == NCONF || ncf == NCONF) {
                    fprintf(stderr, "filter_check: unknown config '%s'\n", tok);
                    return 2;
                }
                cf[ncf++] = all_configs[k];
            }
        } else {
            fprintf(stderr, "usage: filter_check [--shared DIR] [--random K] [--seed S] [--configs LIST]\n");
            return 2;
        }
    }
    if (!ncf)
        for (; ncf < NCONF; ncf++)
            cf[ncf] = all_configs[ncf];
    check_default();
    if (shared) {
        uint64_t p0 = passed, f0 = failed;
        check_shared(shared, cf, ncf);
        printf("filter: shared SVGs: %" PRIu64 " scene renders (file x config x 8/16/32), %" PRIu64 " failed\n",
               passed + failed - p0 - f0, failed - f0);
    }
    if (count) {
        uint64_t p0 = passed, f0 = failed;
        check_random(count, seed, cf, ncf);
        printf("filter: random scenes: %" PRIu64 " (seed %" PRIu64 ", configs in turn), %" PRIu64 " failed\n",
               passed + failed - p0 - f0, seed, failed - f0);
    }
    printf("filter: %" PRIu64 " coverage values compared exactly; %" PRIu64
           " polygons refused by both (a shifted vertex out of range)\n",
           compared, refused);
    printf("filter: %" PRIu64 " passed, %" PRIu64 " failed\n", passed, failed);
    return failed ? 1 : 0;
}
