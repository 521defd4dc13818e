/*
 * scene_dump.c - writes the device-space polygons the rasterizer would see
 * for an input file as a peerbench .scene, with every coordinate as the exact
 * decimal of its Q16.8 value.  Reading the dump back gives the same vertices
 * bit for bit (docs/spec.md 2.1: a multiple of 1/256 parses exactly), so a
 * build without the SVG reader (the 32-bit one of tests/bitexact.sh) can
 * render exactly what a full build renders from the SVG.
 *
 *   scene_dump INPUT [--size WxH] > OUT.scene
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ef_scene.h"

/* Exact decimal of v / 256: at most 8 fraction digits. */
static void print_q8(int32_t v)
{
    int64_t a = v < 0 ? -(int64_t)v : v;
    int64_t ip = a / 256, frac = a % 256;
    printf(" %s%" PRId64, v < 0 ? "-" : "", ip);
    if (frac) {
        /* frac/256 = frac * 390625 / 10^8 */
        char digits[9];
        snprintf(digits, sizeof digits, "%08" PRId64, frac * 390625);
        size_t n = strlen(digits);
        while (n > 0 && digits[n - 1] == '0')
            digits[--n] = '\0';
        printf(".%s", digits);
    }
}

int main(int argc, char **argv)
{
    ef_load_opts o = { 0 };
    const char *in = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            if (sscanf(argv[++i], "%dx%d", &o.fit_width, &o.fit_height) != 2)
                return 2;
        } else if (!in) {
            in = argv[i];
        } else {
            return 2;
        }
    }
    if (!in) {
        fprintf(stderr, "usage: scene_dump INPUT [--size WxH]\n");
        return 2;
    }
    ef_scene s;
    ef_error err;
    if (ef_scene_load_file(in, &o, &s, &err) != EF_OK) {
        char buf[600];
        ef_error_format(&err, buf, sizeof buf);
        fprintf(stderr, "scene_dump: %s\n", buf);
        return 3;
    }
    printf("# device-space polygons of %s, exact Q16.8 coordinates\n", in);
    printf("scene %d %d\n", s.width, s.height);
    for (uint32_t i = 0; i < s.nshapes; i++) {
        const ef_shape *sh = &s.shapes[i];
        printf("shape %s %u %u %u %u\n", sh->rule == EF_RULE_EVENODD ? "evenodd" : "nonzero", sh->color.r, sh->color.g,
               sh->color.b, sh->color.a);
        for (uint32_t c = sh->first_contour; c < sh->first_contour + sh->ncontours; c++) {
            uint32_t b = s.start[c], e = s.start[c + 1];
            if (e - b < 3)
                continue; /* 1- and 2-point contours cover nothing (spec 5.1); the format needs 3 */
            printf("contour");
            for (uint32_t k = b; k < e; k++) {
                print_q8(s.points[k].x);
                print_q8(s.points[k].y);
            }
            printf("\n");
        }
    }
    ef_scene_destroy(&s);
    return ferror(stdout) ? 4 : 0;
}
