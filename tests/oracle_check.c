/*
 * oracle_check.c - the central correctness property (docs/spec.md 5.1): for
 * every visible sample the model's coverage bit equals the independent slow
 * model's exact point-in-polygon answer (tests/oracle/, written from the spec
 * alone), under both fill rules, at 8, 16 and 32 samples.
 *
 *   oracle_check [--shared DIR] [--random K] [--seed S] [--max-report M]
 *
 * --shared renders every *.svg in DIR (each shape, 3 sample counts x 2 rules);
 * --random K generates K seeded random polygons (tests/oracle/randpoly.c),
 * each checked under both rules at a random sample count and canvas.  Also
 * checks the two implications between the oracle's true winding numbers and
 * the model's overflow diagnostic (docs/oracle.md).  Prints the counts and the
 * seed, ends with "N passed, M failed", exits 1 on any mismatch.
 */
#include <dirent.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "edgeflag.h"
#include "ef_scene.h"
#include "oracle.h"
#include "randpoly.h"

typedef struct mask_grid {
    int32_t w, h;
    uint32_t *m;
} mask_grid;

static void grid_span(void *user, int32_t y, int32_t x, int32_t len, uint32_t mask)
{
    mask_grid *g = user;
    for (int32_t i = 0; i < len; i++)
        g->m[(size_t)y * (size_t)g->w + (size_t)(x + i)] = mask;
}

typedef struct tally {
    uint64_t cases, samples, failed;
    int max_report;
} tally;

/* Rasterizes poly with the model and compares with the oracle's masks.
 * Returns 0 when equal. */
static int compare_one(tally *t, const char *what, const eo_polygon *op, int samples, int W, int H)
{
    size_t n = (size_t)W * (size_t)H;
    uint32_t *want_nz = calloc(n, 4), *want_eo = calloc(n, 4), *got = calloc(n, 4);
    eo_stats st;
    int bad = 0;
    if (!want_nz || !want_eo || !got) {
        fprintf(stderr, "oracle_check: out of memory\n");
        exit(2);
    }
    if (eo_eval(op, samples, W, H, want_nz, want_eo, &st) != EO_OK) {
        fprintf(stderr, "oracle_check: %s: oracle rejected the polygon\n", what);
        exit(2);
    }
    ef_polygon mp = { (const ef_point *)op->pts, op->start, op->ncontours };
    t->cases++; /* one case = one polygon at one sample count, both rules */
    for (int rule = 0; rule < 2; rule++) {
        ef_ctx *ctx;
        if (ef_ctx_create(&ctx, W, H, samples) != EF_OK) {
            fprintf(stderr, "oracle_check: ef_ctx_create failed\n");
            exit(2);
        }
        memset(got, 0, n * 4);
        mask_grid g = { W, H, got };
        ef_rule r = rule ? EF_RULE_EVENODD : EF_RULE_NONZERO;
        ef_status s = ef_rasterize(ctx, &mp, r, grid_span, &g);
        const uint32_t *want = rule ? want_eo : want_nz;
        t->samples += (uint64_t)n * (uint64_t)samples;
        if (s != EF_OK) {
            printf("MISMATCH %s: model returned %s\n", what, ef_strerror(s));
            bad = 1;
        } else if (memcmp(want, got, n * 4) != 0) {
            printf("MISMATCH %s samples=%d rule=%s canvas=%dx%d\n", what, samples, rule ? "evenodd" : "nonzero", W, H);
            if (t->failed < (uint64_t)t->max_report) {
                eo_compare_masks(stdout, want, got, W, H, samples, 5);
                for (size_t k = 0; k < n; k++) {
                    uint32_t d = want[k] ^ got[k];
                    if (!d)
                        continue;
                    int sbit = 0;
                    while (!(d >> sbit & 1))
                        sbit++;
                    eo_explain_sample(stdout, op, samples, (int64_t)(k % (size_t)W), (int64_t)(k / (size_t)W), sbit);
                    break;
                }
                if (op->start[op->ncontours] < 64)
                    eo_polygon_fprint(stdout, op);
            }
            bad = 1;
        }
        if (!rule) {
            ef_diag d;
            ef_ctx_diag(ctx, &d);
            if (st.outside_7bit > 0 && d.winding_overflows == 0) {
                printf("MISMATCH %s: %" PRIu64
                       " samples have winding outside [-64,63] but the model reported no overflow\n",
                       what, st.outside_7bit);
                bad = 1;
            }
            if (st.max_row_crossings <= 63 && d.winding_overflows != 0) {
                printf("MISMATCH %s: at most %" PRIu64 " crossings per row, yet %" PRIu64 " overflows reported\n", what,
                       st.max_row_crossings, d.winding_overflows);
                bad = 1;
            }
        }
        ef_ctx_destroy(ctx);
    }
    free(want_nz);
    free(want_eo);
    free(got);
    if (bad)
        t->failed++;
    return bad;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static int check_shared(tally *t, const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "oracle_check: cannot open %s\n", dir);
        return -1;
    }
    char *names[256];
    int nn = 0;
    struct dirent *de;
    while ((de = readdir(d)) && nn < 256) {
        size_t l = strlen(de->d_name);
        if (l > 4 && strcmp(de->d_name + l - 4, ".svg") == 0)
            names[nn++] = strdup(de->d_name);
    }
    closedir(d);
    qsort(names, (size_t)nn, sizeof names[0], cmp_str);
    int files = 0;
    for (int i = 0; i < nn; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        ef_scene sc;
        ef_error err;
        ef_load_opts o = { 0 };
        if (ef_scene_load_file(path, &o, &sc, &err) != EF_OK) {
            char buf[600];
            ef_error_format(&err, buf, sizeof buf);
            printf("MISMATCH %s: does not load: %s\n", names[i], buf);
            t->failed++;
            continue;
        }
        uint64_t before = t->failed;
        for (int ns = 8; ns <= 32; ns *= 2) {
            for (uint32_t s = 0; s < sc.nshapes; s++) {
                ef_polygon p = ef_scene_polygon(&sc, s);
                eo_polygon op = { (const eo_point *)p.pts, p.start, p.ncontours };
                char what[400];
                snprintf(what, sizeof what, "%s shape %u", names[i], s);
                compare_one(t, what, &op, ns, sc.width, sc.height);
            }
        }
        printf("oracle: %-44s %4u shapes %6u points %4dx%-4d %s\n", names[i], sc.nshapes, sc.npoints, sc.width,
               sc.height, t->failed == before ? "agree" : "DIFFER");
        fflush(stdout);
        files++;
        ef_scene_destroy(&sc);
        free(names[i]);
    }
    return files;
}

static void check_random(tally *t, uint64_t count, uint64_t seed)
{
    eo_rng g;
    eo_rng_seed(&g, seed);
    eo_randpoly rp;
    eo_randpoly_init(&rp);
    for (uint64_t i = 0; i < count; i++) {
        int W, H, samples, rule_eo;
        eo_rand_config(&g, &W, &H, &samples, &rule_eo);
        uint64_t pseed = eo_rng_next(&g);
        eo_randpoly_opts o = { samples, 0, 0, 0 };
        if (eo_randpoly_gen(&rp, pseed, W, H, &o) != EO_OK) {
            fprintf(stderr, "oracle_check: generator failed\n");
            exit(2);
        }
        eo_polygon op = eo_randpoly_view(&rp);
        char what[200];
        snprintf(what, sizeof what, "random scene %" PRIu64 " (polygon seed 0x%016" PRIx64 ")", i, pseed);
        compare_one(t, what, &op, samples, W, H);
    }
    eo_randpoly_free(&rp);
}

int main(int argc, char **argv)
{
    const char *shared = NULL;
    uint64_t count = 0, seed = 20070101;
    tally t = { 0, 0, 0, 3 };
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--shared") && i + 1 < argc)
            shared = argv[++i];
        else if (!strcmp(argv[i], "--random") && i + 1 < argc)
            count = strtoull(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else if (!strcmp(argv[i], "--max-report") && i + 1 < argc)
            t.max_report = atoi(argv[++i]);
        else {
            fprintf(stderr, "usage: oracle_check [--shared DIR] [--random K] [--seed S] [--max-report M]\n");
            return 2;
        }
    }
    /* The oracle copies the spec's n-rooks tables; they must be the model's. */
    for (int ns = 8; ns <= 32; ns *= 2) {
        if (memcmp(ef_pattern(ns), eo_pattern(ns), (size_t)ns) != 0) {
            printf("MISMATCH: n-rooks table for %d samples differs between model and spec copy\n", ns);
            t.failed++;
        }
    }
    if (shared) {
        uint64_t c0 = t.cases, f0 = t.failed;
        int files = check_shared(&t, shared);
        if (files < 0)
            return 2;
        printf("oracle: shared SVGs: %d files, %" PRIu64 " cases (shape x 3 sample counts, both rules each), %" PRIu64
               " failed\n",
               files, t.cases - c0, t.failed - f0);
    }
    if (count) {
        uint64_t c0 = t.cases, f0 = t.failed;
        check_random(&t, count, seed);
        printf("oracle: random scenes: %" PRIu64 " scenes (seed %" PRIu64 "), %" PRIu64
               " cases (both rules each), %" PRIu64 " failed\n",
               count, seed, t.cases - c0, t.failed - f0);
    }
    printf("oracle: %" PRIu64 " samples compared bit for bit\n", t.samples);
    printf("oracle: %" PRIu64 " passed, %" PRIu64 " failed\n", t.cases - t.failed, t.failed);
    return t.failed ? 1 : 0;
}
