/*
 * args.c - strict argument parsing for `edgeflag` subcommands.
 *
 * Hand-written rather than strtol/getopt: strtol accepts leading blanks, a
 * sign, "0x" and trailing junk unless every caller checks carefully, and a
 * model used as a golden reference should refuse "--samples 8x" rather than
 * quietly render something else.
 */
#include "cli.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Digits s[0..n) only, value in [min, max]. */
static int parse_digits(const char *s, size_t n, int32_t min, int32_t max, int32_t *out)
{
    int64_t v = 0;
    if (n == 0)
        return 0;
    for (size_t i = 0; i < n; i++) {
        if (s[i] < '0' || s[i] > '9')
            return 0;
        v = v * 10 + (s[i] - '0');
        if (v > max)
            return 0; /* also keeps v far from int64 overflow */
    }
    if (v < min)
        return 0;
    *out = (int32_t)v;
    return 1;
}

int ef_cli_parse_int(const char *s, int32_t min, int32_t max, int32_t *out)
{
    return s ? parse_digits(s, strlen(s), min, max, out) : 0;
}

int ef_cli_parse_size(const char *s, int32_t max, int32_t *w, int32_t *h)
{
    const char *x;
    int32_t tw, th;

    if (!s || (x = strchr(s, 'x')) == NULL)
        return 0;
    /* Both sides parsed alike (leading zeros included), stored only if both are good. */
    if (!parse_digits(s, (size_t)(x - s), 1, max, &tw) || !parse_digits(x + 1, strlen(x + 1), 1, max, &th))
        return 0;
    *w = tw;
    *h = th;
    return 1;
}

int ef_cli_option_value(const char *cmd, int argc, char **argv, int *i, const char *name,
                        const char **value)
{
    const char *arg = argv[*i];
    size_t n = strlen(name);

    if (strncmp(arg, name, n) != 0)
        return 0;
    if (arg[n] == '=') {
        *value = arg + n + 1;
        *i += 1;
        return 1;
    }
    if (arg[n] != '\0')
        return 0;
    if (*i + 1 >= argc) {
        ef_cli_usage_error(cmd, "option '%s' needs a value", name);
        return -1;
    }
    *value = argv[*i + 1];
    *i += 2;
    return 1;
}

static int quiet;

void ef_cli_set_quiet(int q) { quiet = q; }

int ef_cli_usage_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    if (quiet)
        return EF_CLI_EXIT_USAGE;
    fprintf(stderr, "edgeflag: %s: ", cmd);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\nTry 'edgeflag %s --help'.\n", cmd);
    return EF_CLI_EXIT_USAGE;
}

void ef_cli_error(const char *fmt, ...)
{
    va_list ap;
    if (quiet)
        return;
    fputs("edgeflag: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}
