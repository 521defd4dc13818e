/*
 * check_run.c - the verifier's entry point (ef_check.h): one comparison of
 * EXPECTED with ACTUAL, in the manner of TestFloat's testfloat_ver:
 * mismatches with decoded fields on the report stream (at most `errors` of
 * them, the count exact), status on the status stream, and an
 * ef_check_status: pass, fail (a mismatch), input (an input that cannot be
 * read: a reader error names its file:line:col or record), out of memory.
 *
 * EXPECTED and ACTUAL are two files (hex or binary, in any combination: the
 * interfaces both hold are compared) or two directories (the manifest's
 * expected files, else every *.expected.hex and vectors.bin, each against
 * its dump in ACTUAL: check_dir.c).  One pair of files is in memory at a
 * time.
 */
#include "check_internal.h"

#include <errno.h>
#include <inttypes.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void ef_check_opts_defaults(ef_check_opts *o)
{
    memset(o, 0, sizeof *o);
    o->errors = 20;
    o->cycles = 1;
    o->only = EF_IF_ALL;
}

void chk_error(const chk_run *r, const char *fmt, ...)
{
    va_list ap;
    if (!r->a->status)
        return;
    fputs("edgeflag: ", r->a->status);
    va_start(ap, fmt);
    vfprintf(r->a->status, fmt, ap);
    va_end(ap);
    fputc('\n', r->a->status);
}

void chk_status(const chk_run *r, const char *fmt, ...)
{
    va_list ap;
    if (!r->a->status)
        return;
    va_start(ap, fmt);
    vfprintf(r->a->status, fmt, ap);
    va_end(ap);
}

/* ---------------------------------------------------------------- one pair */

char *chk_join(const char *dir, const char *name)
{
    size_t n = strlen(dir), k = strlen(name);
    char *p = malloc(n + k + 2);
    if (p) {
        memcpy(p, dir, n);
        p[n] = '/';
        memcpy(p + n + 1, name, k + 1);
    }
    return p;
}

int chk_is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && !S_ISDIR(st.st_mode);
}

/* Reports an input error (status stream, and as a JUnit <error>); the status. */
int chk_input_error(chk_run *r, ef_status st, const char *msg, const char *ename, const char *aname)
{
    chk_error(r, "%s", msg);
    chk_case *tc = chk_case_add(r, ename, aname, "input");
    if (tc) {
        tc->error = malloc(strlen(msg) + 1);
        if (tc->error)
            strcpy(tc->error, msg);
    }
    return st == EF_ERR_NOMEM ? EF_CHECK_NOMEM : EF_CHECK_INPUT;
}

int chk_read_error(chk_run *r, ef_status st, const ef_vec_read_error *err, const char *ename, const char *aname)
{
    char buf[sizeof err->file + sizeof err->msg + 96];
    ef_vec_read_error_format(err, buf, sizeof buf);
    return chk_input_error(r, st, buf, ename, aname);
}

/* The expected pix stay for --diff-image; everything else of d is freed. */
static void keep_background(chk_run *r, ef_vec_dump *d)
{
    if (r->have_bg || !(d->mask >> EF_IF_PIX & 1u))
        return;
    r->bg = *d;
    for (int i = 0; i < EF_IF_COUNT; i++)
        if (i != EF_IF_PIX) {
            free(r->bg.seq[i].cycle);
            free(r->bg.seq[i].pay);
            free(r->bg.seq[i].loc);
            free(r->bg.seq[i].off);
            memset(&r->bg.seq[i], 0, sizeof r->bg.seq[i]);
        }
    memset(d, 0, sizeof *d);
    r->have_bg = 1;
}

static uint64_t total(const ef_vec_dump *d)
{
    uint64_t n = 0;
    for (int i = 0; i < EF_IF_COUNT; i++)
        n += d->seq[i].n;
    return n;
}

static int ends_with(const char *s, const char *suffix);

/* Reads EXPECTED file ep (mf: its manifest entry, or NULL) and, when ap is
 * not NULL, ACTUAL file ap, and compares every interface both hold.  0, or
 * the status of an input error (reported). */
int chk_pair(chk_run *r, const char *ep, const char *ap, const ef_vec_manifest_file *mf, const char *mname)
{
    ef_vec_dump e, a;
    ef_vec_read_error err;
    ef_status st;
    char buf[1024];
    int rc = 0;

    memset(&a, 0, sizeof a);
    /* ACTUAL is read beside EXPECTED when the interface it will be asked for
     * can be told now: EXPECTED binary (none), or hex with a known interface
     * (its header must then name that one, or the guess is dropped below). */
    const int ehint = mf && mf->iface >= 0 ? mf->iface : ef_vec_iface_from_name(ep);
    const int ebin = ends_with(ep, ".bin"), guess = ebin ? -1 : ehint;
    chk_async_read ar;
    int spec = ap && (ebin || guess >= 0);
    if (spec)
        chk_read_start(&ar, ap, guess, guess >= 0 ? guess : ef_vec_iface_from_name(ap));
    st = ef_vec_read_path(ep, NULL, -1, ehint, &e, &err);
    if (st != EF_OK) {
        if (spec)
            chk_read_drop(&ar);
        return chk_read_error(r, st, &err, ep, ap ? ap : "-");
    }
    if (mf && mf->has_count && mf->count != total(&e)) {
        snprintf(buf, sizeof buf,
                 "%s: files[%zu].count: the manifest counts %" PRIu64 " transactions in '%s', the file holds %" PRIu64,
                 mname, mf->index, mf->count, mf->name, total(&e));
        rc = chk_input_error(r, EF_ERR_SYNTAX, buf, ep, ap ? ap : "-");
        goto out;
    }
    if (!r->width && e.width > 0) {
        r->width = e.width;
        r->height = e.height;
    }
    if (!r->seed)
        r->seed = e.seed;
    /* Every interface the expected side holds must be compared, but for the
     * command stream: the DUT's input, compared when a bench dumps it. */
    r->held |= e.mask & ~(1u << EF_IF_CMD);
    if (!ap)
        goto out;
    int want = -1;
    for (int i = 0; e.format == EF_VEC_FMT_HEX && i < EF_IF_COUNT; i++)
        if (e.mask >> i & 1u)
            want = i;
    if (spec && want == guess) {
        chk_read_wait(&ar);
        spec = 0;
        st = ar.st;
        a = ar.dump;
        err = ar.err;
    } else {
        if (spec) {
            chk_read_drop(&ar);
            spec = 0;
        }
        st = ef_vec_read_path(ap, NULL, want, want >= 0 ? want : ef_vec_iface_from_name(ap), &a, &err);
    }
    if (st != EF_OK) {
        rc = chk_read_error(r, st, &err, ep, ap);
        goto out;
    }
    if (!(e.mask & a.mask)) {
        snprintf(buf, sizeof buf, "%s: holds no interface of %s", ap, ep);
        rc = chk_input_error(r, EF_ERR_SYNTAX, buf, ep, ap);
        goto out;
    }
    if (e.width && a.width && (e.width != a.width || e.height != a.height))
        chk_status(r, "edgeflag: warning: %s is a %dx%d frame, %s %dx%d\n", ep, (int)e.width, (int)e.height, ap,
                   (int)a.width, (int)a.height);
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const char *name = ef_iface_get(i)->name;
        if (!(e.mask >> i & 1u) || !(r->a->only >> i & 1u))
            continue;
        if (!(a.mask >> i & 1u)) {
            chk_status(r, "edgeflag check: %s: not recorded in %s\n", name, ap);
            continue;
        }
        r->compared |= 1u << i;
        const uint64_t t0 = chk_now_ns(), before = r->mismatches;
        chk_case *tc = chk_case_add(r, ep, ap, name);
        if (!tc)
            break;
        chk_compare(r, tc, i, &e, ep, &a, ap);
        tc->ns = chk_now_ns() - t0;
        chk_status(r, "edgeflag check: %s: %s vs %s: %zu expected, %zu actual transactions, %" PRIu64 " mismatch%s\n",
                   name, ep, ap, e.seq[i].n, a.seq[i].n, r->mismatches - before,
                   r->mismatches - before == 1 ? "" : "es");
    }
out:
    if (spec)
        chk_read_drop(&ar);
    if (r->a->keep_marks && rc == 0)
        keep_background(r, &e);
    ef_vec_dump_destroy(&e);
    ef_vec_dump_destroy(&a);
    return r->oom ? EF_CHECK_NOMEM : rc;
}

/* ---------------------------------------------------------------- the run */

/* Whether two paths are one file or directory (then ACTUAL would be EXPECTED). */
static int same_node(const struct stat *x, const struct stat *y)
{
    return x->st_dev == y->st_dev && x->st_ino == y->st_ino;
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* After the comparison: every interface the expected side holds and no pair
 * compared becomes a test case, skipped when --interfaces or --allow-missing
 * excuses it, else failed (a dump the bench never wrote is no pass). */
static void close_unchecked(chk_run *r)
{
    const ef_check_opts *a = r->a;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        if (!(r->held >> i & 1u) || (r->compared >> i & 1u))
            continue;
        const char *name = ef_iface_get(i)->name;
        chk_case *tc = chk_case_add(r, a->expected, a->actual, name);
        if (!tc)
            return;
        if (!(a->only >> i & 1u) || (a->allow_missing >> i & 1u)) {
            tc->skipped = 1;
            chk_status(r, "edgeflag check: %s: skipped (%s)\n", name,
                       !(a->only >> i & 1u) ? "not in --interfaces" : "--allow-missing, and no dump in ACTUAL");
        } else {
            tc->missing = 1;
            r->missing++;
            chk_status(r,
                       "edgeflag check: %s: FAIL: %s holds no dump of it (%s.actual.hex, or a binary stream "
                       "recording it); name it in --allow-missing if the bench does not dump it\n",
                       name, a->actual, name);
        }
    }
}

static void run_free(chk_run *r)
{
    for (size_t k = 0; k < r->ncases; k++) {
        free(r->cases[k].classname);
        free(r->cases[k].name);
        free(r->cases[k].text);
        free(r->cases[k].error);
    }
    free(r->cases);
    free(r->marks);
    ef_vec_dump_destroy(&r->bg);
}

void ef_check_result_destroy(ef_check_result *res)
{
    if (res->run) {
        run_free(res->run);
        free(res->run);
    }
    memset(res, 0, sizeof *res);
}

const char *ef_check_status_name(ef_check_status st)
{
    switch (st) {
    case EF_CHECK_PASS: return "pass";
    case EF_CHECK_FAIL: return "fail";
    case EF_CHECK_INPUT: return "input";
    case EF_CHECK_NOMEM: return "nomem";
    }
    return "?";
}

ef_check_status ef_check_run(const ef_check_opts *o, ef_check_result *res)
{
    struct stat se, sa;
    int rc;
    chk_run *r = calloc(1, sizeof *r);

    memset(res, 0, sizeof *res);
    if (!r)
        return EF_CHECK_NOMEM;
    res->run = r;
    r->opts = *o;
    r->a = &r->opts;
    const ef_check_opts *a = r->a;
    if (!a->expected || !a->actual || !(a->only >> EF_IF_PIX & 1u) || (a->allow_missing >> EF_IF_PIX & 1u) ||
        (a->only & ~(uint32_t)EF_IF_ALL) || a->errors < 0) {
        chk_error(r, "check: bad options (two paths needed; pix must be compared and may not be missing)");
        return EF_CHECK_INPUT;
    }
    if (stat(a->expected, &se) != 0 || stat(a->actual, &sa) != 0) {
        const char *bad = stat(a->expected, &se) != 0 ? a->expected : a->actual;
        chk_error(r, "%s: cannot open: %s", bad, strerror(errno));
        rc = EF_CHECK_INPUT;
    } else if (same_node(&se, &sa)) {
        chk_error(r, "%s and %s are the same %s: ACTUAL must be the DUT's dumps, not the expected vectors", a->expected,
                  a->actual, S_ISDIR(se.st_mode) ? "directory" : "file");
        rc = EF_CHECK_INPUT;
    } else if (S_ISDIR(se.st_mode) && S_ISDIR(sa.st_mode)) {
        rc = chk_dirs(r);
    } else if (!S_ISDIR(se.st_mode) && !S_ISDIR(sa.st_mode) && ends_with(a->actual, ".expected.hex")) {
        chk_error(r,
                  "%s is an expected file (*.expected.hex), never a dump: an RTL's dump of an interface is "
                  "IFACE.actual.hex",
                  a->actual);
        rc = EF_CHECK_INPUT;
    } else if (!S_ISDIR(se.st_mode) && !S_ISDIR(sa.st_mode)) {
        rc = chk_pair(r, a->expected, a->actual, NULL, NULL);
    } else {
        chk_error(r, "%s is a directory and %s is not: give two files or two directories",
                  S_ISDIR(se.st_mode) ? a->expected : a->actual, S_ISDIR(se.st_mode) ? a->actual : a->expected);
        rc = EF_CHECK_INPUT;
    }
    if (rc == 0)
        close_unchecked(r);
    if (r->oom)
        rc = EF_CHECK_NOMEM;
    if (a->report)
        fflush(a->report);

    uint64_t compared = 0, txns = 0, failing = 0;
    for (size_t k = 0; k < r->ncases; k++)
        if (!r->cases[k].error && !r->cases[k].missing && !r->cases[k].skipped) {
            compared++;
            txns += r->cases[k].expected;
            failing += r->cases[k].mismatches > 0;
        }
    if (rc == 0 && (r->mismatches || r->missing))
        chk_status(r,
                   "edgeflag check: FAIL: %" PRIu64 " mismatch%s in %" PRIu64 " of %" PRIu64 " comparison%s (%" PRIu64
                   " reported)%s, %" PRIu64 " interface%s without a dump\n",
                   r->mismatches, r->mismatches == 1 ? "" : "es", failing, compared, compared == 1 ? "" : "s",
                   r->reported, a->cycles ? "" : ", transactions only (cycles not compared)", r->missing,
                   r->missing == 1 ? "" : "s");
    else if (rc == 0)
        chk_status(r, "edgeflag check: PASS: %" PRIu64 " comparison%s, %" PRIu64 " transactions, %s\n", compared,
                   compared == 1 ? "" : "s", txns,
                   a->cycles ? "cycle-exact" : "transactions only (cycles not compared)");
    res->mismatches = r->mismatches;
    res->reported = r->reported;
    res->compared = compared;
    res->transactions = txns;
    res->missing = r->missing;
    res->marks = r->nmarks;
    if (rc != 0)
        return (ef_check_status)rc;
    return r->mismatches || r->missing ? EF_CHECK_FAIL : EF_CHECK_PASS;
}
