/*
 * render_time.c - how long the model takes to render one scene: loads the
 * input once, then renders it R times per configuration (8/16/32 samples x
 * even-odd/non-zero) into a cleared RGBA8 image and prints the median
 * ms/frame of each.  Only the ef_scene_render call is timed.  This is a quick
 * number for humans; the side-by-side comparison with other rasterizers is
 * the benchmark's job.
 *
 *   render_time INPUT [--size WxH] [--repeat R]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ef_scene.h"

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    ef_load_opts o = { 0 };
    const char *in = NULL;
    int repeat = 50;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc)
            sscanf(argv[++i], "%dx%d", &o.fit_width, &o.fit_height);
        else if (!strcmp(argv[i], "--repeat") && i + 1 < argc)
            repeat = atoi(argv[++i]);
        else
            in = argv[i];
    }
    if (!in || repeat < 1 || repeat > 100000) {
        fprintf(stderr, "usage: render_time INPUT [--size WxH] [--repeat R]\n");
        return 2;
    }
    ef_scene s;
    ef_error err;
    if (ef_scene_load_file(in, &o, &s, &err) != EF_OK) {
        char buf[600];
        ef_error_format(&err, buf, sizeof buf);
        fprintf(stderr, "render_time: %s\n", buf);
        return 3;
    }
    double *t = malloc(sizeof *t * (size_t)repeat);
    printf("%s %dx%d, %u shapes, %u points, median of %d renders\n", in, s.width, s.height, s.nshapes, s.npoints,
           repeat);
    for (int n = 8; n <= 32; n *= 2) {
        for (int rule = 0; rule < 2; rule++) {
            ef_ctx *ctx;
            ef_image img;
            if (ef_ctx_create(&ctx, s.width, s.height, n) != EF_OK || ef_image_create(&img, s.width, s.height) != EF_OK)
                return 70;
            for (int r = 0; r < repeat; r++) {
                memset(img.px, 0, img.stride * (size_t)img.height);
                double t0 = now_ms();
                ef_scene_render(ctx, &s, rule ? EF_RULE_EVENODD : EF_RULE_NONZERO, &img);
                t[r] = now_ms() - t0;
            }
            qsort(t, (size_t)repeat, sizeof *t, cmp_d);
            printf("  %2d samples %-8s %8.3f ms/frame\n", n, rule ? "evenodd" : "nonzero", t[repeat / 2]);
            ef_image_destroy(&img);
            ef_ctx_destroy(ctx);
        }
    }
    free(t);
    ef_scene_destroy(&s);
    return 0;
}
