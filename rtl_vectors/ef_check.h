/*
 * ef_check.h - the verifier: an RTL's vector dumps against the expected
 * vectors of `edgeflag vectors` (docs/vectors.md section 7), as a library
 * (libedgeflag_vectors; `pkg-config --cflags --libs edgeflag-vectors`).
 *
 * `edgeflag check` (cli/cmd_check.c) is a thin shell around it: options, the
 * run, the JUnit file and the diff image written atomically, and its exit
 * code mapped from the status.  `edgeflag-host verify` (host/main.c) calls
 * ef_check_run the same way, in-process, and so can a testbench.  Like
 * TestFloat's verifier it reports each mismatch with decoded fields (on
 * opts.report), counts every one exactly, and ends with a status; it never
 * exits, and it prints only to the FILEs it is given.
 *
 *     #include <edgeflag/ef_check.h>
 *     ef_check_opts o;
 *     ef_check_opts_defaults(&o);
 *     o.expected = "out/vectors"; o.actual = "sim/dumps";
 *     o.report = stdout; o.status = stderr;
 *     ef_check_result res;
 *     ef_check_status st = ef_check_run(&o, &res);   // EF_CHECK_PASS, _FAIL, _INPUT, _NOMEM
 *     ... ef_check_junit(&res, f) ... ef_check_diff_image(&res, &img, err, sizeof err) ...
 *     ef_check_result_destroy(&res);
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

#include "ef_api.h"
#include "ef_trace.h" /* ef_iface bits, ef_image */

#ifdef __cplusplus
extern "C" {
#endif

/* What a run found.  Not an exit code: `edgeflag check` maps it to its
 * exit codes by name (docs/cli.md), edgeflag-host to its own (docs/board.md
 * section 7). */
typedef enum ef_check_status {
    EF_CHECK_PASS = 0,  /* every required interface compared, no mismatch */
    EF_CHECK_FAIL = 1,  /* a mismatch, or a required interface without a dump */
    EF_CHECK_INPUT = 2, /* unreadable or malformed input, ACTUAL is EXPECTED or an expected file, bad options */
    EF_CHECK_NOMEM = 3  /* out of memory */
} ef_check_status;

/* "pass", "fail", "input" or "nomem" ("?" for another value). */
EF_API const char *ef_check_status_name(ef_check_status st);

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

/* The defaults above (expected, actual, report and status NULL).  It fills
 * the struct and allocates nothing. */
EF_API void ef_check_opts_defaults(ef_check_opts *o);

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

/* Compares o->expected with o->actual.  Returns the status above; res (not
 * NULL) is filled in every case and must be released with
 * ef_check_result_destroy. */
EF_API ef_check_status ef_check_run(const ef_check_opts *o, ef_check_result *res);

/* Writes res's JUnit XML (one test case per interface compared, skipped or
 * missing; input errors as <error>) to f.  0, or -1 when f reports an error. */
EF_API int ef_check_junit(const ef_check_result *res, FILE *f);

/* Draws the expected frame (every expected pix, the last of a pixel winning)
 * with each pixel of a mismatching pix or span transaction in opaque magenta
 * into *img (allocated here; release with ef_image_destroy).  Needs o.keep_marks.
 * 0, or -1 with a message in err and errno (ENOMEM, or 0 when the frame
 * size is unknown). */
EF_API int ef_check_diff_image(const ef_check_result *res, ef_image *img, char *err, size_t errsize);

/* Draws a dump's frame (every pix transaction, the last of a pixel winning,
 * premultiplied as the frame buffer holds it) into *img (allocated here, the
 * dump's width x height; release with ef_image_destroy): edgeflag-host
 * verify's --save-frame.  0, or -1 with a message in err and errno. */
struct ef_vec_dump;
EF_API int ef_check_frame_image(const struct ef_vec_dump *d, ef_image *img, char *err, size_t errsize);

/* Frees what the run kept; res is then empty. */
EF_API void ef_check_result_destroy(ef_check_result *res);

#ifdef __cplusplus
}
#endif

#endif /* EF_CHECK_H */
