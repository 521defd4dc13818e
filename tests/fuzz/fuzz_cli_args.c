/*
 * fuzz_cli_args.c - libFuzzer target for the command line's parsers
 * (cli/args.c and the option parsers of `render`, `patterns`, `check` and
 * `vectors`).
 *
 * The whole input, as one string, goes to ef_util_parse_int (several ranges)
 * and ef_util_parse_size, each checked against a reference written here from
 * docs/cli.md ("decimal digits only, no sign, no spaces, no trailing
 * characters; a lower-case x separates the size").  Then the input, split at
 * newlines, is an argument vector for `edgeflag render ...`, `edgeflag
 * patterns ...` and `edgeflag check ...`: a parse that succeeds must leave a complete, valid request
 * (an input, an output with a known format, N in {8, 16, 32}, a rule, a size
 * in range or none); any other result is 0 (help) or 2 (usage error), and the
 * same vector gives the same answer twice, and an accepted line has every
 * option word spelt in full (getopt_long's abbreviations and attached short
 * values stay off: ref_full_names).  Nothing is read or written: the
 * parsers never touch a file.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "edgeflag.h"

#define FAIL(...) \
    do { \
        fprintf(stderr, "fuzz_cli_args: property violated: "); \
        fprintf(stderr, __VA_ARGS__); \
        fputc('\n', stderr); \
        abort(); \
    } while (0)

/* digits only, value in [min, max] */
static bool ref_int(const char *s, size_t n, int64_t min, int64_t max, int64_t *out)
{
    if (n == 0)
        return false;
    for (size_t i = 0; i < n; i++)
        if (s[i] < '0' || s[i] > '9')
            return false;
    size_t i = 0;
    while (i < n && s[i] == '0')
        i++;
    if (n - i > 12)
        return false; /* >= 10^12: far above any max */
    int64_t v = 0;
    for (; i < n; i++)
        v = v * 10 + (s[i] - '0');
    if (v < min || v > max)
        return false;
    *out = v;
    return true;
}

static void check_numbers(const char *s)
{
    static const int32_t ranges[][2] = { { 1, 32 }, { 0, 0 }, { 0, INT32_MAX }, { 1, 16384 }, { 7, 9 } };
    size_t n = strlen(s);
    for (size_t r = 0; r < sizeof ranges / sizeof ranges[0]; r++) {
        int32_t got = -12345;
        int64_t want = 0;
        int ok = ef_util_parse_int(s, ranges[r][0], ranges[r][1], &got);
        bool wok = ref_int(s, n, ranges[r][0], ranges[r][1], &want);
        if (ok != (int)wok || (ok && got != want))
            FAIL("parse_int('%s', %" PRId32 ", %" PRId32 ") = %d/%" PRId32 ", reference %d/%" PRId64, s, ranges[r][0],
                 ranges[r][1], ok, got, (int)wok, want);
        if (!ok && got != -12345)
            FAIL("a refused number was stored");
    }
    int32_t w = -1, h = -1;
    int64_t rw = 0, rh = 0;
    int ok = ef_util_parse_size(s, EF_MAX_CANVAS, &w, &h);
    const char *x = strchr(s, 'x');
    bool wok =
        x && ref_int(s, (size_t)(x - s), 1, EF_MAX_CANVAS, &rw) && ref_int(x + 1, strlen(x + 1), 1, EF_MAX_CANVAS, &rh);
    if (ok != (int)wok || (ok && (w != rw || h != rh)))
        FAIL("parse_size('%s') = %d %" PRId32 "x%" PRId32 ", reference %d %" PRId64 "x%" PRId64, s, ok, w, h, (int)wok,
             rw, rh);
}

static bool has_help(int argc, char **argv)
{
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return true;
    return false;
}

/* docs/cli.md: every word in an option's place is a full option name
 * ("NAME" or "NAME=VALUE"; the value of NAME VALUE is skipped) until "--"
 * (where it ends options): the parsers are getopt_long, which on its own
 * would take any unique prefix ("--err" for "--errors") and clustered or
 * attached short values ("-ox.png").  false if some option word is not. */
static bool ref_full_names(int argc, char **argv, const char *const *valued, const char *const *flags, bool dashdash)
{
    for (int i = 1; i < argc; i++) {
        const char *w = argv[i];
        if (dashdash && strcmp(w, "--") == 0)
            return true;
        if (w[0] != '-' || w[1] == '\0')
            continue; /* an operand */
        bool known = false;
        for (int k = 0; valued[k] && !known; k++) {
            size_t n = strlen(valued[k]);
            if (strcmp(w, valued[k]) == 0)
                known = true, i++;
            else if (strncmp(w, valued[k], n) == 0 && w[n] == '=')
                known = true;
        }
        for (int k = 0; flags[k] && !known; k++)
            if (strcmp(w, flags[k]) == 0)
                known = true;
        if (!known)
            return false;
    }
    return true;
}

static void check_render(int argc, char **argv)
{
    ef_cli_render_args a, b;
    int rc = ef_cli_render_parse(argc, argv, &a);
    int rc2 = ef_cli_render_parse(argc, argv, &b);
    if (rc != rc2)
        FAIL("render: %d then %d", rc, rc2);
    if (has_help(argc, argv) != (rc == EF_CLI_EXIT_OK))
        FAIL("render: --help and exit %d disagree", rc);
    /* exit 4 before any work: the output names an existing directory (docs/cli.md) */
    struct stat st;
    if (rc == EF_CLI_EXIT_OUTPUT && (!a.output || stat(a.output, &st) != 0 || !S_ISDIR(st.st_mode)))
        FAIL("render: exit 4 for an output that is not a directory");
    if (rc != -1 && rc != EF_CLI_EXIT_OK && rc != EF_CLI_EXIT_USAGE && rc != EF_CLI_EXIT_OUTPUT)
        FAIL("render: exit code %d", rc);
    if (rc != -1)
        return;
    static const char *const r_valued[] = { "-o",     "--output", "--samples",  "--rule",
                                            "--size", "--filter", "--subpixel", NULL };
    static const char *const r_flags[] = { NULL };
    if (!ref_full_names(argc, argv, r_valued, r_flags, true))
        FAIL("render: accepted a word that is no option");
    if (!a.input || !a.output || !a.output[0])
        FAIL("render: accepted without input or output");
    if (!ef_samples_valid(a.samples))
        FAIL("render: accepted %" PRId32 " samples", a.samples);
    if (a.rule != -1 && a.rule != EF_RULE_NONZERO && a.rule != EF_RULE_EVENODD)
        FAIL("render: rule %d", a.rule);
    if (!((a.fit_w == 0 && a.fit_h == 0) ||
          (a.fit_w >= 1 && a.fit_w <= EF_MAX_CANVAS && a.fit_h >= 1 && a.fit_h <= EF_MAX_CANVAS)))
        FAIL("render: size %" PRId32 "x%" PRId32, a.fit_w, a.fit_h);
    if (!ef_util_format_available(a.fmt) || a.fmt != ef_util_format_from_path(a.output))
        FAIL("render: output '%s' accepted with format %d", a.output, (int)a.fmt);
    if (a.samples != b.samples || a.rule != b.rule || a.fit_w != b.fit_w || a.fit_h != b.fit_h || a.input != b.input ||
        a.output != b.output)
        FAIL("render: two parses differ");
}

static void check_patterns(int argc, char **argv)
{
    ef_cli_patterns_args a, b;
    int rc = ef_cli_patterns_parse(argc, argv, &a);
    int rc2 = ef_cli_patterns_parse(argc, argv, &b);
    if (rc != rc2)
        FAIL("patterns: %d then %d", rc, rc2);
    bool help = false;
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            help = true;
    if (help != (rc == EF_CLI_EXIT_OK))
        FAIL("patterns: --help and exit %d disagree", rc);
    if (rc != -1 && rc != EF_CLI_EXIT_OK && rc != EF_CLI_EXIT_USAGE)
        FAIL("patterns: exit code %d", rc);
    if (rc != -1)
        return;
    static const char *const p_valued[] = { "--samples", NULL }, *const p_flags[] = { "--emit-c", "--emit-verilog",
                                                                                      NULL };
    if (!ref_full_names(argc, argv, p_valued, p_flags, false))
        FAIL("patterns: accepted a word that is no option");
    if (!(a.samples == 0 || ef_samples_valid(a.samples)))
        FAIL("patterns: %" PRId32 " samples", a.samples);
    if ((a.emit_c || a.emit_verilog) && a.samples)
        FAIL("patterns: --emit-c or --emit-verilog with --samples accepted");
    if (a.emit_c && a.emit_verilog)
        FAIL("patterns: --emit-c with --emit-verilog accepted");
    if (a.samples != b.samples || a.emit_c != b.emit_c || a.emit_verilog != b.emit_verilog)
        FAIL("patterns: two parses differ");
}

static void check_check(int argc, char **argv)
{
    ef_cli_check_args a, b;
    int rc = ef_cli_check_parse(argc, argv, &a);
    int rc2 = ef_cli_check_parse(argc, argv, &b);
    if (rc != rc2)
        FAIL("check: %d then %d", rc, rc2);
    if (has_help(argc, argv) != (rc == EF_CLI_EXIT_OK))
        FAIL("check: --help and exit %d disagree", rc);
    if (rc != -1 && rc != EF_CLI_EXIT_OK && rc != EF_CLI_EXIT_USAGE)
        FAIL("check: exit code %d", rc);
    if (rc != -1)
        return;
    static const char *const c_valued[] = { "--errors", "--interfaces", "--allow-missing",
                                            "--name",   "--junit",      "--diff-image",
                                            NULL };
    static const char *const c_flags[] = { "--cycles", "--transactions", NULL };
    if (!ref_full_names(argc, argv, c_valued, c_flags, true))
        FAIL("check: accepted a word that is no option");
    if (!a.expected || !a.actual)
        FAIL("check: accepted without two files");
    if (a.errors < 0)
        FAIL("check: --errors %" PRId32, a.errors);
    if (a.cycles != 0 && a.cycles != 1)
        FAIL("check: cycles %d", a.cycles);
    if (a.junit && !a.junit[0])
        FAIL("check: empty --junit accepted");
    if (a.diff_image &&
        (!ef_util_format_available(a.diff_fmt) || a.diff_fmt != ef_util_format_from_path(a.diff_image) ||
         (a.diff_fmt != EF_UTIL_FMT_PNG && a.diff_fmt != EF_UTIL_FMT_PAM)))
        FAIL("check: --diff-image '%s' accepted with format %d", a.diff_image, (int)a.diff_fmt);
    if (a.junit && a.diff_image && strcmp(a.junit, a.diff_image) == 0)
        FAIL("check: one file for both outputs");
    if (a.expected != b.expected || a.actual != b.actual || a.errors != b.errors || a.cycles != b.cycles ||
        a.junit != b.junit || a.diff_image != b.diff_image)
        FAIL("check: two parses differ");
}

/* `vectors`: the value of option `name` (as "NAME V" or "NAME=V") before any
 * "--", skipping the values of the options that take one; NULL if absent. */
static const char *vec_option(int argc, char **argv, const char *name)
{
    static const char *const valued[] = { "-o",        "--output",     "--samples", "--rule",    "--size",
                                          "--formats", "--interfaces", "--filter",  "--subpixel" };
    const size_t n = strlen(name);
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; i++) {
        if (strncmp(argv[i], name, n) == 0 && argv[i][n] == '=')
            return argv[i] + n + 1;
        if (strcmp(argv[i], name) == 0)
            return i + 1 < argc ? argv[i + 1] : NULL;
        for (size_t k = 0; k < sizeof valued / sizeof valued[0]; k++)
            if (strcmp(argv[i], valued[k]) == 0) {
                i++;
                break;
            }
    }
    return NULL;
}

/* docs/vectors.md: a comma-separated list of known names, each at most once;
 * alias (when not NULL) is another name of names[1] (`edge`, the old name of
 * the interface `seg`). */
static bool ref_list(const char *v, const char *const *names, int n, const char *alias, uint32_t *mask)
{
    uint32_t m = 0;
    for (;;) {
        const char *comma = strchr(v, ',');
        size_t len = comma ? (size_t)(comma - v) : strlen(v);
        int k = 0;
        while (k < n && !(strlen(names[k]) == len && memcmp(names[k], v, len) == 0))
            k++;
        if (k == n && alias && strlen(alias) == len && memcmp(alias, v, len) == 0)
            k = 1;
        if (k == n || (m >> k & 1u))
            return false;
        m |= 1u << k;
        if (!comma)
            break;
        v = comma + 1;
    }
    *mask = m;
    return true;
}

static void check_vectors(int argc, char **argv)
{
    static const char *const formats[] = { "hex", "vcd", "bin" };
    static const char *const ifaces[] = { "cmd", "seg", "et_wr", "et_rd", "plot", "span", "pix" };
    ef_cli_vectors_args a, b;
    int rc = ef_cli_vectors_parse(argc, argv, &a);
    int rc2 = ef_cli_vectors_parse(argc, argv, &b);
    if (rc != rc2)
        FAIL("vectors: %d then %d", rc, rc2);
    if (has_help(argc, argv) != (rc == EF_CLI_EXIT_OK))
        FAIL("vectors: --help and exit %d disagree", rc);
    if (rc != -1 && rc != EF_CLI_EXIT_OK && rc != EF_CLI_EXIT_USAGE)
        FAIL("vectors: exit code %d", rc);
    if (rc != -1)
        return;
    static const char *const v_valued[] = { "-o",         "--output",     "--samples",    "--rule",
                                            "--size",     "--formats",    "--interfaces", "--filter",
                                            "--subpixel", "--dut-limits", "--dut-edges",  NULL };
    static const char *const v_flags[] = { "--force", "--dump", "--rtl-headers", NULL };
    if (!ref_full_names(argc, argv, v_valued, v_flags, true))
        FAIL("vectors: accepted a word that is no option");
    if (a.rtl_headers) { /* --rtl-headers -o DIR [--force], nothing else */
        if (a.input || !a.dir || !a.dir[0] || vec_option(argc, argv, "--samples") || vec_option(argc, argv, "--rule") ||
            vec_option(argc, argv, "--size") || vec_option(argc, argv, "--formats") ||
            vec_option(argc, argv, "--interfaces") || vec_option(argc, argv, "--filter") ||
            vec_option(argc, argv, "--subpixel") || a.dump)
            FAIL("vectors: --rtl-headers accepted with an input or another option");
        if (a.rtl_headers != b.rtl_headers || a.dir != b.dir || a.force != b.force)
            FAIL("vectors: two parses differ");
        return;
    }
    if (!a.input || !a.dir || !a.dir[0])
        FAIL("vectors: accepted without input or directory");
    if (!ef_samples_valid(a.samples))
        FAIL("vectors: accepted %" PRId32 " samples", a.samples);
    if (a.rule != -1 && a.rule != EF_RULE_NONZERO && a.rule != EF_RULE_EVENODD)
        FAIL("vectors: rule %d", a.rule);
    if (!((a.fit_w == 0 && a.fit_h == 0) ||
          (a.fit_w >= 1 && a.fit_w <= EF_MAX_CANVAS && a.fit_h >= 1 && a.fit_h <= EF_MAX_CANVAS)))
        FAIL("vectors: size %" PRId32 "x%" PRId32, a.fit_w, a.fit_h);
    if (a.force != 0 && a.force != 1)
        FAIL("vectors: force %d", a.force);
    /* The lists against the reference: default all, else exactly the names given. */
    const char *fv = vec_option(argc, argv, "--formats"), *iv = vec_option(argc, argv, "--interfaces");
    uint32_t want_f = EF_CLI_VEC_ALL, want_i = (1u << 7) - 1u;
    if ((fv && !ref_list(fv, formats, 3, NULL, &want_f)) || (iv && !ref_list(iv, ifaces, 7, "edge", &want_i)))
        FAIL("vectors: accepted --formats '%s' / --interfaces '%s'", fv ? fv : "", iv ? iv : "");
    if (a.formats != want_f || a.ifaces != want_i)
        FAIL("vectors: formats %u interfaces %u, reference %u %u", a.formats, (unsigned)a.ifaces, (unsigned)want_f,
             (unsigned)want_i);
    if (a.samples != b.samples || a.rule != b.rule || a.fit_w != b.fit_w || a.fit_h != b.fit_h || a.input != b.input ||
        a.dir != b.dir || a.formats != b.formats || a.ifaces != b.ifaces || a.force != b.force)
        FAIL("vectors: two parses differ");
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    ef_cli_set_quiet(1);
    /* --help prints usage on stdout; libFuzzer and the sanitizers use stderr. */
    if (!freopen("/dev/null", "w", stdout))
        abort();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    enum { MAXARG = 64 };
    if (size > 65536)
        return 0;
    char *s = malloc(size + 1);
    if (!s)
        abort();
    memcpy(s, data, size);
    s[size] = '\0';
    check_numbers(s);

    /* argv: "render"/"patterns", then the input's lines (NUL bytes end a line's
     * text early, as they would in a real argv). */
    char *argv[MAXARG + 2];
    int argc = 1;
    char *p = s, *end = s + size;
    while (p <= end && argc <= MAXARG) {
        char *nl = memchr(p, '\n', (size_t)(end - p));
        if (!nl)
            nl = end;
        *nl = '\0';
        argv[argc++] = p;
        p = nl + 1;
    }
    argv[argc] = NULL;
    char render[] = "render", patterns[] = "patterns", check[] = "check";
    argv[0] = render;
    check_render(argc, argv);
    argv[0] = patterns;
    check_patterns(argc, argv);
    argv[0] = check;
    check_check(argc, argv);
    char vectors[] = "vectors";
    argv[0] = vectors;
    check_vectors(argc, argv);
    free(s);
    return 0;
}
