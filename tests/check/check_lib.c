/*
 * check_lib.c - the verifier as a DPI-C bench or the host tool calls it:
 * through rtl_vectors/ef_check.h alone, no `main` of edgeflag's.
 *
 * usage: check_lib EXPECTED ACTUAL REPORT JUNIT
 * Runs ef_check_run with the mismatch lines to REPORT, no status stream (the
 * library must print nothing else), marks kept; writes the JUnit XML to JUNIT
 * and draws the diff image in memory.  Prints "status S mismatches M reported
 * N marks K magenta P" on stdout (S: ef_check_status_name); tests/check/run.sh compares it and the files
 * with what `edgeflag check` printed for the same pair.
 */
#include "ef_check.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: check_lib EXPECTED ACTUAL REPORT JUNIT\n");
        return 64;
    }
    FILE *rep = fopen(argv[3], "w"), *ju = fopen(argv[4], "w");
    if (!rep || !ju) {
        perror("check_lib");
        return 64;
    }
    ef_check_opts o;
    ef_check_opts_defaults(&o);
    o.expected = argv[1];
    o.actual = argv[2];
    o.errors = 0;
    o.keep_marks = 1;
    o.report = rep;
    ef_check_result res;
    const ef_check_status st = ef_check_run(&o, &res);
    int jrc = ef_check_junit(&res, ju);
    uint64_t magenta = 0;
    ef_image img;
    char err[256];
    if ((st == EF_CHECK_PASS || st == EF_CHECK_FAIL) && ef_check_diff_image(&res, &img, err, sizeof err) == 0) {
        for (int32_t y = 0; y < img.height; y++)
            for (int32_t x = 0; x < img.width; x++)
                magenta += memcmp(img.px + (size_t)y * img.stride + (size_t)x * 4u, "\xff\x00\xff\xff", 4) == 0;
        ef_image_destroy(&img);
    }
    printf("status %s mismatches %" PRIu64 " reported %" PRIu64 " marks %" PRIu64 " magenta %" PRIu64 "\n",
           ef_check_status_name(st), res.mismatches, res.reported, res.marks, magenta);
    ef_check_result_destroy(&res);
    if (fclose(rep) != 0 || fclose(ju) != 0 || jrc != 0) {
        perror("check_lib");
        return 64;
    }
    return 0;
}
