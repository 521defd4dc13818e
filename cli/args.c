/*
 * args.c - strict argument parsing for `edgeflag` subcommands.
 *
 * Hand-written rather than strtol/getopt: strtol accepts leading blanks, a
 * sign, "0x" and trailing junk unless every caller checks carefully, and a
 * model used as a golden reference should refuse "--samples 8x" rather than
 * quietly render something else.
 */
#include "cli.h"
#include "ef_trace.h"

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

int ef_cli_scene_option(const char *cmd, int argc, char **argv, int *i, int32_t *samples, int *rule,
                        int32_t *fit_w, int32_t *fit_h, int seen[3])
{
    const char *v;
    int r;
    if ((r = ef_cli_option_value(cmd, argc, argv, i, "--samples", &v)) != 0) {
        if (r < 0)
            return -1;
        if (seen[0]++)
            return ef_cli_usage_error(cmd, "--samples given twice"), -1;
        if (!ef_cli_parse_int(v, 1, EF_SAMPLES_MAX, samples) || !ef_samples_valid(*samples))
            return ef_cli_usage_error(cmd, "--samples must be " EF_SAMPLES_TEXT ", not '%s'", v), -1;
    } else if ((r = ef_cli_option_value(cmd, argc, argv, i, "--rule", &v)) != 0) {
        if (r < 0)
            return -1;
        if (seen[1]++)
            return ef_cli_usage_error(cmd, "--rule given twice"), -1;
        if (strcmp(v, "evenodd") == 0)
            *rule = EF_RULE_EVENODD;
        else if (strcmp(v, "nonzero") == 0)
            *rule = EF_RULE_NONZERO;
        else
            return ef_cli_usage_error(cmd, "--rule must be nonzero or evenodd, not '%s'", v), -1;
    } else if ((r = ef_cli_option_value(cmd, argc, argv, i, "--size", &v)) != 0) {
        if (r < 0)
            return -1;
        if (seen[2]++)
            return ef_cli_usage_error(cmd, "--size given twice"), -1;
        if (!ef_cli_parse_size(v, EF_MAX_CANVAS, fit_w, fit_h))
            return ef_cli_usage_error(cmd, "--size must be WxH with 1 <= W, H <= %d, not '%s'", EF_MAX_CANVAS, v), -1;
    } else {
        return 0;
    }
    return 1;
}

/* The position in the list does not matter.  A member equal to alias (when
 * not NULL) stands for names[alias_k]. */
static int parse_list(const char *cmd, const char *opt, const char *v, const char *const *names, int n,
                      const char *alias, int alias_k, uint32_t *out)
{
    uint32_t bits = 0;
    const char *p = v;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        int k;
        for (k = 0; k < n; k++)
            if (strlen(names[k]) == len && strncmp(names[k], p, len) == 0)
                break;
        if (k == n && alias && strlen(alias) == len && strncmp(alias, p, len) == 0)
            k = alias_k;
        if (k == n) {
            char all[96] = "";
            for (int i = 0; i < n; i++) {
                strcat(all, i ? "," : "");
                strcat(all, names[i]);
            }
            ef_cli_usage_error(cmd, "%s must be a comma-separated list of %s, not '%s'", opt, all, v);
            return 0;
        }
        if (bits >> k & 1u) {
            ef_cli_usage_error(cmd, "%s names '%s' twice", opt, names[k]);
            return 0;
        }
        bits |= 1u << k;
        if (!comma)
            break;
        p = comma + 1;
    }
    *out = bits;
    return 1;
}

int ef_cli_parse_list(const char *cmd, const char *opt, const char *v, const char *const *names, int n,
                      uint32_t *out)
{
    return parse_list(cmd, opt, v, names, n, NULL, 0, out);
}

int ef_cli_parse_ifaces(const char *cmd, const char *opt, const char *v, uint32_t *out)
{
    const char *names[EF_IF_COUNT];
    for (int k = 0; k < EF_IF_COUNT; k++)
        names[k] = ef_iface_get(k)->name;
    /* `edge`: the old name of `seg` (a Verilog keyword), still read. */
    return parse_list(cmd, opt, v, names, EF_IF_COUNT, "edge", EF_IF_SEG, out);
}
