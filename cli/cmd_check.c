/*
 * cmd_check.c - `edgeflag check EXPECTED ACTUAL`: the command's shell around
 * the verifier library (rtl_vectors/ef_check.h, docs/vectors.md section 7):
 * options, then ef_check_run with the mismatch lines on standard output and
 * status on standard error, then the --junit and --diff-image files written
 * atomically.  Exit 0 pass, 1 mismatch, 2 usage or an input that cannot be
 * read, 4 a report not written, 70 internal (docs/cli.md).
 */
#include "check_files.h"
#include "cli.h"
#include "ef_check.h"

#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

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

static const struct option OPTIONS[] = { { "errors", required_argument, NULL, EF_OPT_ERRORS },
                                         { "cycles", no_argument, NULL, EF_OPT_CYCLES },
                                         { "transactions", no_argument, NULL, EF_OPT_TRANSACTIONS },
                                         { "interfaces", required_argument, NULL, EF_OPT_INTERFACES },
                                         { "allow-missing", required_argument, NULL, EF_OPT_ALLOW_MISSING },
                                         { "name", required_argument, NULL, EF_OPT_NAME },
                                         { "junit", required_argument, NULL, EF_OPT_JUNIT },
                                         { "diff-image", required_argument, NULL, EF_OPT_DIFF_IMAGE },
                                         { NULL, 0, NULL, 0 } };

/* The line as read: the request, and which of --cycles/--transactions came. */
typedef struct check_line {
    ef_cli_check_args *a;
    int timing; /* 0, or the EF_OPT_ of the first of the two */
} check_line;

static int on_option(void *p, int val, const char *v)
{
    check_line *l = p;
    ef_cli_check_args *a = l->a;
    switch (val) {
    case EF_OPT_CYCLES:
    case EF_OPT_TRANSACTIONS:
        if (l->timing)
            return ef_cli_usage_error(CMD, "--cycles and --transactions exclude each other");
        l->timing = val;
        a->cycles = val == EF_OPT_CYCLES;
        return -1;
    case EF_OPT_ERRORS:
        if (!ef_util_parse_int(v, 0, INT32_MAX, &a->errors))
            return ef_cli_usage_error(CMD, "--errors must be a number 0..%d (0 = all), not '%s'", INT32_MAX, v);
        return -1;
    case EF_OPT_INTERFACES:
        if (!ef_cli_parse_ifaces(CMD, "--interfaces", v, &a->only)) /* `edge` read as `seg` */
            return EF_CLI_EXIT_USAGE;
        if (!(a->only >> EF_IF_PIX & 1u))
            return ef_cli_usage_error(CMD, "--interfaces must include pix (the DUT's output is always checked)");
        return -1;
    case EF_OPT_ALLOW_MISSING:
        if (!ef_cli_parse_ifaces(CMD, "--allow-missing", v, &a->allow_missing))
            return EF_CLI_EXIT_USAGE;
        if (a->allow_missing >> EF_IF_PIX & 1u)
            return ef_cli_usage_error(CMD, "--allow-missing cannot name pix (the DUT's output is always checked)");
        return -1;
    case EF_OPT_NAME:
        if (!*v)
            return ef_cli_usage_error(CMD, "empty --name");
        a->name = v;
        return -1;
    case EF_OPT_JUNIT:
        if (!*v)
            return ef_cli_usage_error(CMD, "empty --junit file name");
        a->junit = v;
        return -1;
    default: /* EF_OPT_DIFF_IMAGE */
        a->diff_fmt = ef_util_format_from_path(v);
        if (a->diff_fmt != EF_UTIL_FMT_PNG && a->diff_fmt != EF_UTIL_FMT_PAM)
            return ef_cli_usage_error(CMD, "--diff-image must name a .png (or .pam) file, not '%s'", v);
        if (!ef_util_format_available(a->diff_fmt))
            return ef_cli_usage_error(CMD,
                                      "'%s': this edgeflag was built without PNG support (WITH_PNG=0); "
                                      "use .pam",
                                      v);
        a->diff_image = v;
        return -1;
    }
}

static int on_operand(void *p, const char *arg)
{
    ef_cli_check_args *a = ((check_line *)p)->a;
    if (!a->expected)
        a->expected = arg;
    else if (!a->actual)
        a->actual = arg;
    else
        return ef_cli_usage_error(CMD, "more than two files ('%s' after '%s' and '%s')", arg, a->expected, a->actual);
    return -1;
}

static int finish(void *p)
{
    ef_cli_check_args *a = ((check_line *)p)->a;
    if (!a->expected || !a->actual)
        return ef_cli_usage_error(CMD, "two files or directories needed: EXPECTED ACTUAL");
    if (a->junit && a->diff_image && strcmp(a->junit, a->diff_image) == 0)
        return ef_cli_usage_error(CMD, "--junit and --diff-image name the same file");
    return -1;
}

static const ef_cli_command COMMAND = { "check", OPTIONS, 1, usage, on_option, on_operand, NULL, finish, NULL };

int ef_cli_check_parse(int argc, char **argv, ef_cli_check_args *a)
{
    check_line l = { a, 0 };
    memset(a, 0, sizeof *a);
    a->errors = 20;
    a->cycles = 1;
    a->only = EF_IF_ALL;
    return ef_cli_getopt(&COMMAND, argc, argv, &l);
}

/* ---------------------------------------------------------------- the command */

/* The command's exit code for a run's status (docs/cli.md). */
static int exit_code(ef_check_status st)
{
    switch (st) {
    case EF_CHECK_PASS: return EF_CLI_EXIT_OK;
    case EF_CHECK_FAIL: return EF_CLI_EXIT_MISMATCH;
    case EF_CHECK_INPUT: return EF_CLI_EXIT_USAGE; /* unreadable or malformed input: 2, as a usage error */
    case EF_CHECK_NOMEM: break;
    }
    return EF_CLI_EXIT_INTERNAL;
}

int ef_cli_check(int argc, char **argv)
{
    ef_cli_check_args a;
    ef_check_opts o;
    ef_check_result res;
    int rc = ef_cli_check_parse(argc, argv, &a);
    if (rc >= 0)
        return rc;
#if defined(__GLIBC__) && defined(M_MMAP_THRESHOLD) && defined(M_TRIM_THRESHOLD)
    /* Each pair of files is read into arrays sized from their counts and
     * freed after the comparison.  As glibc's own mmap'd blocks every pair's
     * arrays were new pages, faulted in one by one (a fifth of check's time on
     * the tiger); from the heap, and not trimmed, the next pair reuses them.
     * The peak is the same: the largest pair's.  (Malloc tuning only: no
     * result depends on it.) */
    mallopt(M_MMAP_THRESHOLD, 256 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif

    ef_check_opts_defaults(&o);
    o.expected = a.expected;
    o.actual = a.actual;
    o.errors = a.errors;
    o.cycles = a.cycles;
    o.only = a.only;
    o.allow_missing = a.allow_missing;
    o.name = a.name;
    o.keep_marks = a.diff_image != NULL;
    o.report = stdout;
    o.status = stderr;
    const ef_check_status st = ef_check_run(&o, &res);

    int out_rc = 0;
    if (a.junit && st != EF_CHECK_NOMEM && ef_util_check_junit(&res, a.junit) != 0) {
        ef_cli_error("cannot write '%s': %s", a.junit, strerror(errno));
        out_rc = EF_CLI_EXIT_OUTPUT;
    }
    if (a.diff_image && (st == EF_CHECK_PASS || st == EF_CHECK_FAIL)) {
        char err[256];
        if (ef_util_check_diff_image(&res, a.diff_image, a.diff_fmt, err, sizeof err) != 0) {
            ef_cli_error("cannot write '%s': %s", a.diff_image, err);
            out_rc = errno == ENOMEM ? EF_CLI_EXIT_INTERNAL : EF_CLI_EXIT_OUTPUT;
        } else {
            fprintf(stderr, "edgeflag check: wrote %s (%" PRIu64 " mismatching pixel runs marked)\n", a.diff_image,
                    res.marks);
        }
    }
    ef_check_result_destroy(&res);
    if (st != EF_CHECK_PASS && st != EF_CHECK_FAIL)
        return exit_code(st);
    if (out_rc != 0)
        return out_rc;
    return exit_code(st);
}
