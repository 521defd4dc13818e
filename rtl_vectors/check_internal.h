/*
 * check_internal.h - the pieces of the verifier (ef_check.h, docs/vectors.md
 * section 7): check_run.c runs a comparison (a pair of files, the verdict),
 * check_dir.c pairs the files of two directories,
 * check_compare.c aligns and reports one interface's transactions,
 * check_junit.c writes the JUnit XML, check_image.c draws the diff image.
 * cli/cmd_check.c is the command's shell around them.
 */
#ifndef EF_CHECK_INTERNAL_H
#define EF_CHECK_INTERNAL_H

#include <threads.h>
#include <stdint.h>
#include <stdio.h>

#include "ef_check.h"
#include "ef_vec.h" /* the format table */
#include "ef_vec_read.h"

/* One JUnit test case: one interface of one pair of files. */
typedef struct chk_case {
    char *classname;           /* "EXPECTED vs ACTUAL" */
    char *name;                /* the interface */
    uint64_t expected, actual; /* transactions on each side */
    uint64_t mismatches;
    char *text; /* the reported mismatch lines (a failure's body) */
    size_t text_len, text_cap;
    char *error; /* malformed or unreadable input (an <error>), or NULL */
    int missing; /* a required interface without an actual dump (a <failure>) */
    int skipped; /* an interface left out by --interfaces or --allow-missing */
    uint64_t ns; /* time taken */
} chk_case;

/* A run of pixels to mark in the diff image. */
typedef struct chk_mark {
    int32_t y, x, len;
} chk_mark;

typedef struct ef_check_run_state {
    ef_check_opts opts;     /* a copy: the writers run after ef_check_run returns */
    const ef_check_opts *a; /* &opts */
    uint64_t mismatches;    /* in all, exact */
    uint64_t reported;      /* lines printed (at most --errors unless 0) */
    int oom;                /* an allocation failed: EF_CHECK_NOMEM */
    chk_case *cases;
    size_t ncases, capcases;
    uint32_t held;     /* interfaces the EXPECTED side holds */
    uint32_t compared; /* interfaces compared at least once */
    uint64_t seed;     /* the expected vectors' seed (JUnit's default name), 0 if none */
    uint64_t missing;  /* required interfaces without a dump */
    /* --diff-image */
    int32_t width, height; /* frame size from a header or the manifest, 0 if none yet */
    chk_mark *marks;
    size_t nmarks, capmarks;
    ef_vec_dump bg; /* the expected pix (the picture under the marks) */
    int have_bg;
} chk_run;

/* "edgeflag: <message>" on the status stream (input errors, as the command
 * always printed them); chk_status prints the line as given. */
void chk_error(const chk_run *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void chk_status(const chk_run *r, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* check_run.c: reads EXPECTED file ep (mf: its manifest entry in mname, or
 * NULL) and, when ap is not NULL, ACTUAL file ap, and compares every
 * interface both hold.  0, or the ef_check_status of an input error (reported). */
int chk_pair(chk_run *r, const char *ep, const char *ap, const ef_vec_manifest_file *mf, const char *mname);
/* check_read.c: a dump read in a second thread while the caller reads the
 * expected file (or at once, when no thread can be started). */
typedef struct chk_async_read {
    thrd_t thr;
    int started;
    const char *path;
    int want, hint; /* as ef_vec_read_path's */
    ef_status st;   /* after chk_read_wait */
    ef_vec_dump dump;
    ef_vec_read_error err;
} chk_async_read;
void chk_read_start(chk_async_read *ar, const char *path, int want, int hint);
void chk_read_wait(chk_async_read *ar);
/* Waits and frees what was read. */
void chk_read_drop(chk_async_read *ar);
/* check_dir.c: two directories (r->a->expected, r->a->actual); as chk_pair. */
int chk_dirs(chk_run *r);
/* Reports an input error on stderr and as a JUnit <error>; the status
 * (EF_CHECK_INPUT, or EF_CHECK_NOMEM for EF_ERR_NOMEM).  chk_read_error formats a reader's error. */
int chk_input_error(chk_run *r, ef_status st, const char *msg, const char *ename, const char *aname);
int chk_read_error(chk_run *r, ef_status st, const ef_vec_read_error *err, const char *ename, const char *aname);
/* "dir/name" (malloc'ed, NULL when out of memory); whether path is a file. */
char *chk_join(const char *dir, const char *name);
int chk_is_file(const char *path);

/* Adds a test case; NULL when out of memory (r->oom set). */
chk_case *chk_case_add(chk_run *r, const char *ename, const char *aname, const char *iface);

/* Compares interface iface of e (file ename) and a (file aname) into tc:
 * aligns the two sequences by content in order, reports each mismatch on
 * the report stream (while under `errors`) and counts every one. */
void chk_compare(chk_run *r, chk_case *tc, int iface, const ef_vec_dump *e, const char *ename, const ef_vec_dump *a,
                 const char *aname);

/* Records the pixels of a pix/span transaction for the diff image. */
void chk_mark_txn(chk_run *r, const ef_txn *t);

/* Monotonic nanoseconds (JUnit times; integers only). */
uint64_t chk_now_ns(void);

#endif /* EF_CHECK_INTERNAL_H */
