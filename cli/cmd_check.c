/*
 * cmd_check.c - `edgeflag check EXPECTED ACTUAL`: the verifier of an RTL's
 * vector dumps against `edgeflag vectors` output (docs/vectors.md section
 * 7), in the manner of TestFloat's testfloat_ver: mismatches with decoded
 * fields on standard output (at most --errors of them, the count exact),
 * status on standard error, exit 0 pass, 1 mismatch, 2 usage or an input
 * that cannot be read (a reader error names its file:line:col or record).
 *
 * EXPECTED and ACTUAL are two files (hex or binary, in any combination: the
 * interfaces both hold are compared) or two directories (the manifest's
 * expected files, else every *.expected.hex and vectors.bin, each against
 * its dump in ACTUAL: check_dir.c).  One pair of files is in memory at a
 * time.
 *
 * Strict by default, so that no verification passes by accident: every
 * interface the expected side holds must be compared (or be named by
 * --interfaces or --allow-missing, never pix); an expected file, or EXPECTED
 * itself, is never taken for the dump.
 */
#include "check.h"

#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *const CMD = "check";

static void usage(FILE *f)
{
    fputs("usage: edgeflag check EXPECTED ACTUAL [--errors N] [--cycles|--transactions]\n"
          "                      [--interfaces LIST] [--allow-missing LIST] [--name NAME]\n"
          "                      [--junit FILE] [--diff-image FILE.png]\n"
          "\n"
          "Compares an RTL's vector dumps (ACTUAL) with the expected vectors of `edgeflag\n"
          "vectors` (EXPECTED): two hex files of one interface, two binary streams, or two\n"
          "directories (each IFACE.expected.hex against IFACE.actual.hex, vectors.bin\n"
          "against vectors.actual.bin).  Every interface EXPECTED holds must be compared:\n"
          "one without a dump fails unless --interfaces leaves it out or --allow-missing\n"
          "names it, and pix (the DUT's output) is always required.  An expected file is\n"
          "never taken for a dump.  See docs/vectors.md section 7.\n"
          "\n"
          "Each mismatch is one line on standard output: file and line (or record),\n"
          "interface, cycle, scanline and pixel, and the decoded fields expected against\n"
          "actual, the differing ones marked '*'; missing and extra transactions are named\n"
          "as such.  Status goes to standard error.\n"
          "\n"
          "options:\n"
          "  --errors N           report at most N mismatches (default 20, 0 = all); the\n"
          "                       count is exact either way\n"
          "  --cycles             equal payloads at equal cycles (the default)\n"
          "  --transactions       only the order and content of each interface's\n"
          "                       transactions (an RTL with other timing)\n"
          "  --interfaces LIST    compare only these interfaces (comma-separated; must\n"
          "                       include pix); the others are reported as skipped\n"
          "                       (edge, the old name of seg, is read too)\n"
          "  --allow-missing LIST these interfaces may lack a dump (skipped, not failed);\n"
          "                       never pix\n"
          "  --name NAME          the JUnit suite and class name (default: EXPECTED's\n"
          "                       base name and the vectors' seed)\n"
          "  --junit FILE         write JUnit XML, one test case per interface\n"
          "  --diff-image FILE    draw the expected frame with every pixel of a mismatching\n"
          "                       pix or span transaction in magenta (.png; .pam too)\n"
          "  -h, --help           show this text\n"
          "  --                   end of options\n"
          "\n"
          "exit codes: 0 pass, 1 mismatch or a missing dump, 2 usage or unreadable/\n"
          "            malformed input (or ACTUAL is an expected file or EXPECTED itself),\n"
          "            4 --junit or --diff-image not written, 70 internal error\n",
          f);
}

int ef_cli_check_parse(int argc, char **argv, ef_cli_check_args *a)
{
    int i, only_positional = 0, seen_errors = 0, seen_cycles = 0, seen_txn = 0, seen_only = 0, seen_allow = 0;

    memset(a, 0, sizeof *a);
    a->errors = 20;
    a->cycles = 1;
    a->only = EF_IF_ALL;
    for (i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            usage(stdout);
            return EF_CLI_EXIT_OK;
        }
    for (i = 1; i < argc;) {
        const char *arg = argv[i], *v = NULL;
        int r;
        if (only_positional || arg[0] != '-' || arg[1] == '\0') {
            if (!a->expected)
                a->expected = arg;
            else if (!a->actual)
                a->actual = arg;
            else
                return ef_cli_usage_error(CMD, "more than two files ('%s' after '%s' and '%s')", arg, a->expected,
                                          a->actual);
            i++;
            continue;
        }
        if (strcmp(arg, "--") == 0) {
            only_positional = 1;
            i++;
        } else if (strcmp(arg, "--cycles") == 0 || strcmp(arg, "--transactions") == 0) {
            int *seen = arg[2] == 'c' ? &seen_cycles : &seen_txn;
            if ((*seen)++)
                return ef_cli_usage_error(CMD, "%s given twice", arg);
            if (seen_cycles && seen_txn)
                return ef_cli_usage_error(CMD, "--cycles and --transactions exclude each other");
            a->cycles = arg[2] == 'c';
            i++;
        } else if (strncmp(arg, "--cycles=", 9) == 0 || strncmp(arg, "--transactions=", 15) == 0) {
            return ef_cli_usage_error(CMD, "option '%.*s' takes no value", (int)(strchr(arg, '=') - arg), arg);
        } else if ((r = ef_cli_option_value(CMD, argc, argv, &i, "--errors", &v)) != 0) {
            if (r < 0)
                return EF_CLI_EXIT_USAGE;
            if (seen_errors++)
                return ef_cli_usage_error(CMD, "--errors given twice");
            if (!ef_cli_parse_int(v, 0, INT32_MAX, &a->errors))
                return ef_cli_usage_error(CMD, "--errors must be a number 0..%d (0 = all), not '%s'", INT32_MAX, v);
        } else if ((r = ef_cli_option_value(CMD, argc, argv, &i, "--interfaces", &v)) != 0) {
            if (r < 0)
                return EF_CLI_EXIT_USAGE;
            if (seen_only++)
                return ef_cli_usage_error(CMD, "--interfaces given twice");
            if (!ef_cli_parse_ifaces(CMD, "--interfaces", v, &a->only))
                return EF_CLI_EXIT_USAGE;
            if (!(a->only >> EF_IF_PIX & 1u))
                return ef_cli_usage_error(CMD, "--interfaces must include pix (the DUT's output is always checked)");
        } else if ((r = ef_cli_option_value(CMD, argc, argv, &i, "--allow-missing", &v)) != 0) {
            if (r < 0)
                return EF_CLI_EXIT_USAGE;
            if (seen_allow++)
                return ef_cli_usage_error(CMD, "--allow-missing given twice");
            if (!ef_cli_parse_ifaces(CMD, "--allow-missing", v, &a->allow_missing))
                return EF_CLI_EXIT_USAGE;
            if (a->allow_missing >> EF_IF_PIX & 1u)
                return ef_cli_usage_error(CMD, "--allow-missing cannot name pix (the DUT's output is always checked)");
        } else if ((r = ef_cli_option_value(CMD, argc, argv, &i, "--name", &v)) != 0) {
            if (r < 0)
                return EF_CLI_EXIT_USAGE;
            if (a->name)
                return ef_cli_usage_error(CMD, "--name given twice");
            if (!*v)
                return ef_cli_usage_error(CMD, "empty --name");
            a->name = v;
        } else if ((r = ef_cli_option_value(CMD, argc, argv, &i, "--junit", &v)) != 0) {
            if (r < 0)
                return EF_CLI_EXIT_USAGE;
            if (a->junit)
                return ef_cli_usage_error(CMD, "--junit given twice");
            if (!*v)
                return ef_cli_usage_error(CMD, "empty --junit file name");
            a->junit = v;
        } else if ((r = ef_cli_option_value(CMD, argc, argv, &i, "--diff-image", &v)) != 0) {
            if (r < 0)
                return EF_CLI_EXIT_USAGE;
            if (a->diff_image)
                return ef_cli_usage_error(CMD, "--diff-image given twice");
            a->diff_fmt = ef_cli_format_from_path(v);
            if (a->diff_fmt != EF_CLI_FMT_PNG && a->diff_fmt != EF_CLI_FMT_PAM)
                return ef_cli_usage_error(CMD, "--diff-image must name a .png (or .pam) file, not '%s'", v);
            if (!ef_cli_format_available(a->diff_fmt))
                return ef_cli_usage_error(CMD, "'%s': this edgeflag was built without PNG support (WITH_PNG=0); "
                                          "use .pam", v);
            a->diff_image = v;
        } else {
            return ef_cli_usage_error(CMD, "unknown option '%s'", arg);
        }
    }
    if (!a->expected || !a->actual)
        return ef_cli_usage_error(CMD, "two files or directories needed: EXPECTED ACTUAL");
    if (a->junit && a->diff_image && strcmp(a->junit, a->diff_image) == 0)
        return ef_cli_usage_error(CMD, "--junit and --diff-image name the same file");
    return -1;
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

/* Reports an input error (stderr, and as a JUnit <error>); the exit code. */
int chk_input_error(chk_run *r, ef_status st, const char *msg, const char *ename, const char *aname)
{
    ef_cli_error("%s", msg);
    chk_case *tc = chk_case_add(r, ename, aname, "input");
    if (tc) {
        tc->error = malloc(strlen(msg) + 1);
        if (tc->error)
            strcpy(tc->error, msg);
    }
    return st == EF_ERR_NOMEM ? EF_CLI_EXIT_INTERNAL : EF_CLI_EXIT_USAGE;
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

static int ends_with(const char *s, const char *suffix);

static uint64_t total(const ef_vec_dump *d)
{
    uint64_t n = 0;
    for (int i = 0; i < EF_IF_COUNT; i++)
        n += d->seq[i].n;
    return n;
}

/* Reads EXPECTED file ep (mf: its manifest entry, or NULL) and, when ap is
 * not NULL, ACTUAL file ap, and compares every interface both hold.  0, or
 * the exit code of an input error (reported). */
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
        snprintf(buf, sizeof buf, "%s: files[%zu].count: the manifest counts %" PRIu64
                 " transactions in '%s', the file holds %" PRIu64, mname, mf->index, mf->count, mf->name, total(&e));
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
        fprintf(stderr, "edgeflag: warning: %s is a %dx%d frame, %s %dx%d\n", ep, (int)e.width, (int)e.height, ap,
                (int)a.width, (int)a.height);
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const char *name = ef_iface_get(i)->name;
        if (!(e.mask >> i & 1u) || !(r->a->only >> i & 1u))
            continue;
        if (!(a.mask >> i & 1u)) {
            fprintf(stderr, "edgeflag check: %s: not recorded in %s\n", name, ap);
            continue;
        }
        r->compared |= 1u << i;
        const uint64_t t0 = chk_now_ns(), before = r->mismatches;
        chk_case *tc = chk_case_add(r, ep, ap, name);
        if (!tc)
            break;
        chk_compare(r, tc, i, &e, ep, &a, ap);
        tc->ns = chk_now_ns() - t0;
        fprintf(stderr, "edgeflag check: %s: %s vs %s: %zu expected, %zu actual transactions, %" PRIu64 " mismatch%s\n",
                name, ep, ap, e.seq[i].n, a.seq[i].n, r->mismatches - before, r->mismatches - before == 1 ? "" : "es");
    }
out:
    if (spec)
        chk_read_drop(&ar);
    if (r->a->diff_image && rc == 0)
        keep_background(r, &e);
    ef_vec_dump_free(&e);
    ef_vec_dump_free(&a);
    return r->oom ? EF_CLI_EXIT_INTERNAL : rc;
}

/* ---------------------------------------------------------------- the command */

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
    const ef_cli_check_args *a = r->a;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        if (!(r->held >> i & 1u) || (r->compared >> i & 1u))
            continue;
        const char *name = ef_iface_get(i)->name;
        chk_case *tc = chk_case_add(r, a->expected, a->actual, name);
        if (!tc)
            return;
        if (!(a->only >> i & 1u) || (a->allow_missing >> i & 1u)) {
            tc->skipped = 1;
            fprintf(stderr, "edgeflag check: %s: skipped (%s)\n", name,
                    !(a->only >> i & 1u) ? "not in --interfaces" : "--allow-missing, and no dump in ACTUAL");
        } else {
            tc->missing = 1;
            r->missing++;
            fprintf(stderr, "edgeflag check: %s: FAIL: %s holds no dump of it (%s.actual.hex, or a binary stream "
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
    ef_vec_dump_free(&r->bg);
}

int ef_cli_check(int argc, char **argv)
{
    ef_cli_check_args a;
    chk_run r;
    struct stat se, sa;
    int rc = ef_cli_check_parse(argc, argv, &a);
    if (rc >= 0)
        return rc;

    memset(&r, 0, sizeof r);
    r.a = &a;
    r.out = stdout;
    if (stat(a.expected, &se) != 0 || stat(a.actual, &sa) != 0) {
        const char *bad = stat(a.expected, &se) != 0 ? a.expected : a.actual;
        ef_cli_error("%s: cannot open: %s", bad, strerror(errno));
        rc = EF_CLI_EXIT_USAGE;
    } else if (same_node(&se, &sa)) {
        ef_cli_error("%s and %s are the same %s: ACTUAL must be the DUT's dumps, not the expected vectors",
                     a.expected, a.actual, S_ISDIR(se.st_mode) ? "directory" : "file");
        rc = EF_CLI_EXIT_USAGE;
    } else if (S_ISDIR(se.st_mode) && S_ISDIR(sa.st_mode)) {
        rc = chk_dirs(&r);
    } else if (!S_ISDIR(se.st_mode) && !S_ISDIR(sa.st_mode) && ends_with(a.actual, ".expected.hex")) {
        ef_cli_error("%s is an expected file (*.expected.hex), never a dump: an RTL's dump of an interface is "
                     "IFACE.actual.hex", a.actual);
        rc = EF_CLI_EXIT_USAGE;
    } else if (!S_ISDIR(se.st_mode) && !S_ISDIR(sa.st_mode)) {
        rc = chk_pair(&r, a.expected, a.actual, NULL, NULL);
    } else {
        ef_cli_error("%s is a directory and %s is not: give two files or two directories",
                     S_ISDIR(se.st_mode) ? a.expected : a.actual, S_ISDIR(se.st_mode) ? a.actual : a.expected);
        rc = EF_CLI_EXIT_USAGE;
    }
    if (rc == 0)
        close_unchecked(&r);
    if (r.oom)
        rc = EF_CLI_EXIT_INTERNAL;
    fflush(stdout);

    uint64_t compared = 0, txns = 0, failing = 0;
    for (size_t k = 0; k < r.ncases; k++)
        if (!r.cases[k].error && !r.cases[k].missing && !r.cases[k].skipped) {
            compared++;
            txns += r.cases[k].expected;
            failing += r.cases[k].mismatches > 0;
        }
    if (rc == 0 && (r.mismatches || r.missing))
        fprintf(stderr, "edgeflag check: FAIL: %" PRIu64 " mismatch%s in %" PRIu64 " of %" PRIu64
                " comparison%s (%" PRIu64 " reported)%s, %" PRIu64 " interface%s without a dump\n",
                r.mismatches, r.mismatches == 1 ? "" : "es", failing, compared, compared == 1 ? "" : "s", r.reported,
                a.cycles ? "" : ", transactions only (cycles not compared)", r.missing, r.missing == 1 ? "" : "s");
    else if (rc == 0)
        fprintf(stderr, "edgeflag check: PASS: %" PRIu64 " comparison%s, %" PRIu64 " transactions, %s\n", compared,
                compared == 1 ? "" : "s", txns, a.cycles ? "cycle-exact" : "transactions only (cycles not compared)");

    int out_rc = 0;
    if (a.junit && rc != EF_CLI_EXIT_INTERNAL && chk_junit_write(&r, a.junit) != 0) {
        ef_cli_error("cannot write '%s': %s", a.junit, strerror(errno));
        out_rc = EF_CLI_EXIT_OUTPUT;
    }
    if (a.diff_image && rc == 0) {
        char err[256];
        if (chk_image_write(&r, a.diff_image, a.diff_fmt, err, sizeof err) != 0) {
            ef_cli_error("cannot write '%s': %s", a.diff_image, err);
            out_rc = errno == ENOMEM ? EF_CLI_EXIT_INTERNAL : EF_CLI_EXIT_OUTPUT;
        } else {
            fprintf(stderr, "edgeflag check: wrote %s (%" PRIu64 " mismatching pixel runs marked)\n", a.diff_image,
                    (uint64_t)r.nmarks);
        }
    }
    run_free(&r);
    if (rc != 0)
        return rc;
    if (out_rc != 0)
        return out_rc;
    return r.mismatches || r.missing ? 1 : EF_CLI_EXIT_OK;
}
