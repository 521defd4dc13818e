/*
 * ef_check.h - the verifier: an RTL's vector dumps against the expected
 * vectors of `edgeflag vectors` (docs/vectors.md section 7), as a library.
 *
 * `edgeflag check` is a thin shell around it (options, then the JUnit file
 * and the diff image written atomically); the host tool's verify and a DPI-C
 * testbench call it directly, with no `main`.  Like TestFloat's verifier it
 * reports each mismatch with decoded fields (on opts.report), counts every one
 * exactly, and ends with a documented exit status; it never exits, and it
 * prints only to the FILEs it is given.
 *
 *     ef_check_opts o;
 *     ef_check_opts_init(&o);
 *     o.expected = "out/vectors"; o.actual = "sim/dumps";
 *     o.report = stdout; o.status = stderr;
 *     ef_check_result res;
 *     int rc = ef_check_run(&o, &res);     // 0 pass, 1 fail, 2 input, 70 internal
 *     ... ef_check_junit(&res, f) ... ef_check_diff_image(&res, &img, err, sizeof err) ...
 *     ef_check_result_free(&res);
 *
 * Strict, so that no verification passes by accident: every interface the
 * expected side holds must be compared (or be left out by `only` or
 * `allow_missing`, never pix); an expected file, or EXPECTED itself, is never
 * taken for the dump.
 */
#ifndef EF_CHECK_H
#define EF_CHECK_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "ef_trace.h" /* ef_iface bits, ef_image */

#ifdef __cplusplus
extern "C" {
#endif

/* The exit status of a run (docs/cli.md, `edgeflag check`).  4 (a report not
 * written) belongs to the caller that writes the files. */
enum {
    EF_CHECK_PASS = 0,     /* every required interface compared, no mismatch */
    EF_CHECK_FAIL = 1,     /* a mismatch, or a required interface without a dump */
    EF_CHECK_INPUT = 2,    /* unreadable or malformed input, ACTUAL is EXPECTED or an expected file */
    EF_CHECK_INTERNAL = 70 /* out of memory */
};

typedef struct ef_check_opts {
    const char *expected, *actual; /* two files (hex or binary) or two directories */
    int32_t errors;                /* mismatch lines reported: 20 (default), 0 = all; the count is exact */
    int cycles;                    /* 1 (default): equal payloads at equal cycles; 0: order and content only */
    uint32_t only;                 /* interfaces compared (bit = ef_iface); default EF_IF_ALL; must hold pix */
    uint32_t allow_missing;        /* interfaces whose dump may be absent (skipped); never pix */
    const char *name;              /* the JUnit suite and class name, or NULL: EXPECTED's base name and seed */
    int keep_marks;                /* 1: keep what ef_check_diff_image needs (the expected pix, the marks) */
    FILE *report;                  /* one line per reported mismatch; NULL: not printed (still counted) */
    FILE *status;                  /* progress, warnings, input errors and the verdict; NULL: silent */
} ef_check_opts;

/* The defaults above (expected, actual, report and status NULL). */
void ef_check_opts_init(ef_check_opts *o);

typedef struct ef_check_run_state ef_check_run_state;

typedef struct ef_check_result {
    uint64_t mismatches;     /* in all */
    uint64_t reported;       /* lines written to report */
    uint64_t compared;       /* interface comparisons run */
    uint64_t transactions;   /* expected transactions compared */
    uint64_t missing;        /* required interfaces without a dump */
    uint64_t marks;          /* mismatching pixel runs (keep_marks) */
    ef_check_run_state *run; /* the test cases and marks, for the two writers below */
} ef_check_result;

/* Compares o->expected with o->actual.  Returns the exit status above; res
 * (not NULL) is filled in every case and must be freed. */
int ef_check_run(const ef_check_opts *o, ef_check_result *res);

/* Writes res's JUnit XML (one test case per interface compared, skipped or
 * missing; input errors as <error>) to f.  0, or -1 when f reports an error. */
int ef_check_junit(const ef_check_result *res, FILE *f);

/* Draws the expected frame (every expected pix, the last of a pixel winning)
 * with each pixel of a mismatching pix or span transaction in opaque magenta
 * into *img (allocated here; free with ef_image_free).  Needs o.keep_marks.
 * 0, or -1 with a message in err and errno (ENOMEM, or 0 when the frame
 * size is unknown). */
int ef_check_diff_image(const ef_check_result *res, ef_image *img, char *err, size_t errsize);

/* Draws a dump's frame (every pix transaction, the last of a pixel winning,
 * premultiplied as the frame buffer holds it) into *img (allocated here, the
 * dump's width x height; free with ef_image_free): edgeflag-host verify's
 * --save-frame.  0, or -1 with a message in err and errno. */
struct ef_vec_dump;
int ef_check_frame_image(const struct ef_vec_dump *d, ef_image *img, char *err, size_t errsize);

void ef_check_result_free(ef_check_result *res);

#ifdef __cplusplus
}
#endif

#endif /* EF_CHECK_H */
