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

int ef_cli_parse_int(const char *s, int32_t min, int32_t max, int32_t *out)
{
    int64_t v = 0;
    if (!s || !*s)
        return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9')
            return 0;
        v = v * 10 + (*s - '0');
        if (v > max)
            return 0; /* also keeps v far from int64 overflow */
    }
    if (v < min)
        return 0;
    *out = (int32_t)v;
    return 1;
}

int ef_cli_parse_size(const char *s, int32_t max, int32_t *w, int32_t *h)
{
    char buf[32];
    const char *x;
    size_t len;

    if (!s)
        return 0;
    x = strchr(s, 'x');
    if (!x)
        return 0;
    len = (size_t)(x - s);
    if (len == 0 || len >= sizeof buf)
        return 0;
    memcpy(buf, s, len);
    buf[len] = '\0';
    return ef_cli_parse_int(buf, 1, max, w) && ef_cli_parse_int(x + 1, 1, max, h);
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

int ef_cli_usage_error(const char *cmd, const char *fmt, ...)
{
    va_list ap;
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
    fputs("edgeflag: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}
