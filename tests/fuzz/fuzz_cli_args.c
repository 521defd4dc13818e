/*
 * fuzz_cli_args.c - libFuzzer target for the command line's parsers
 * (cli/args.c and the option parsers of `render` and `patterns`).
 *
 * The whole input, as one string, goes to ef_cli_parse_int (several ranges)
 * and ef_cli_parse_size, each checked against a reference written here from
 * docs/cli.md ("decimal digits only, no sign, no spaces, no trailing
 * characters; a lower-case x separates the size").  Then the input, split at
 * newlines, is an argument vector for `edgeflag render ...` and `edgeflag
 * patterns ...`: a parse that succeeds must leave a complete, valid request
 * (an input, an output with a known format, N in {8, 16, 32}, a rule, a size
 * in range or none); any other result is 0 (help) or 2 (usage error), and the
 * same vector gives the same answer twice.  Nothing is read or written: the
 * parsers never touch a file.
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "edgeflag.h"

#define FAIL(...)                                                                  \
    do {                                                                           \
        fprintf(stderr, "fuzz_cli_args: property violated: ");                     \
        fprintf(stderr, __VA_ARGS__);                                              \
        fputc('\n', stderr);                                                       \
        abort();                                                                   \
    } while (0)

/* digits only, value in [min, max] */
static bool ref_int(const char *s, size_t n, int64_t min, int64_t max, int64_t *out)
{
    if (n == 0) return false;
    for (size_t i = 0; i < n; i++)
        if (s[i] < '0' || s[i] > '9') return false;
    size_t i = 0;
    while (i < n && s[i] == '0') i++;
    if (n - i > 12) return false;             /* >= 10^12: far above any max */
    int64_t v = 0;
    for (; i < n; i++) v = v * 10 + (s[i] - '0');
    if (v < min || v > max) return false;
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
        int ok = ef_cli_parse_int(s, ranges[r][0], ranges[r][1], &got);
        bool wok = ref_int(s, n, ranges[r][0], ranges[r][1], &want);
        if (ok != (int)wok || (ok && got != want))
            FAIL("parse_int('%s', %" PRId32 ", %" PRId32 ") = %d/%" PRId32 ", reference %d/%" PRId64, s,
                 ranges[r][0], ranges[r][1], ok, got, (int)wok, want);
        if (!ok && got != -12345) FAIL("a refused number was stored");
    }
    int32_t w = -1, h = -1;
    int64_t rw = 0, rh = 0;
    int ok = ef_cli_parse_size(s, EF_MAX_CANVAS, &w, &h);
    const char *x = strchr(s, 'x');
    bool wok = x && ref_int(s, (size_t)(x - s), 1, EF_MAX_CANVAS, &rw) &&
               ref_int(x + 1, strlen(x + 1), 1, EF_MAX_CANVAS, &rh);
    if (ok != (int)wok || (ok && (w != rw || h != rh)))
        FAIL("parse_size('%s') = %d %" PRId32 "x%" PRId32 ", reference %d %" PRId64 "x%" PRId64, s, ok, w, h, (int)wok,
             rw, rh);
}

static bool has_help(int argc, char **argv)
{
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) return true;
    return false;
}

static void check_render(int argc, char **argv)
{
    ef_cli_render_args a, b;
    int rc = ef_cli_render_parse(argc, argv, &a);
    int rc2 = ef_cli_render_parse(argc, argv, &b);
    if (rc != rc2) FAIL("render: %d then %d", rc, rc2);
    if (has_help(argc, argv) != (rc == EF_CLI_EXIT_OK)) FAIL("render: --help and exit %d disagree", rc);
    if (rc != -1 && rc != EF_CLI_EXIT_OK && rc != EF_CLI_EXIT_USAGE) FAIL("render: exit code %d", rc);
    if (rc != -1) return;
    if (!a.input || !a.output || !a.output[0]) FAIL("render: accepted without input or output");
    if (!ef_samples_valid(a.samples)) FAIL("render: accepted %" PRId32 " samples", a.samples);
    if (a.rule != -1 && a.rule != EF_RULE_NONZERO && a.rule != EF_RULE_EVENODD) FAIL("render: rule %d", a.rule);
    if (!((a.fit_w == 0 && a.fit_h == 0) ||
          (a.fit_w >= 1 && a.fit_w <= EF_MAX_CANVAS && a.fit_h >= 1 && a.fit_h <= EF_MAX_CANVAS)))
        FAIL("render: size %" PRId32 "x%" PRId32, a.fit_w, a.fit_h);
    if (!ef_cli_format_available(a.fmt) || a.fmt != ef_cli_format_from_path(a.output))
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
    if (rc != rc2) FAIL("patterns: %d then %d", rc, rc2);
    bool help = false;
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) help = true;
    if (help != (rc == EF_CLI_EXIT_OK)) FAIL("patterns: --help and exit %d disagree", rc);
    if (rc != -1 && rc != EF_CLI_EXIT_OK && rc != EF_CLI_EXIT_USAGE) FAIL("patterns: exit code %d", rc);
    if (rc != -1) return;
    if (!(a.samples == 0 || ef_samples_valid(a.samples))) FAIL("patterns: %" PRId32 " samples", a.samples);
    if (a.emit_c && a.samples) FAIL("patterns: --emit-c with --samples accepted");
    if (a.samples != b.samples || a.emit_c != b.emit_c) FAIL("patterns: two parses differ");
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    ef_cli_set_quiet(1);
    /* --help prints usage on stdout; libFuzzer and the sanitizers use stderr. */
    if (!freopen("/dev/null", "w", stdout)) abort();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    enum { MAXARG = 64 };
    if (size > 65536) return 0;
    char *s = malloc(size + 1);
    if (!s) abort();
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
        if (!nl) nl = end;
        *nl = '\0';
        argv[argc++] = p;
        p = nl + 1;
    }
    argv[argc] = NULL;
    char render[] = "render", patterns[] = "patterns";
    argv[0] = render;
    check_render(argc, argv);
    argv[0] = patterns;
    check_patterns(argc, argv);
    free(s);
    return 0;
}
