/*
 * args.c - strict argument parsing for `edgeflag` subcommands: one driver
 * (ef_cli_getopt) that reads every command's line with getopt_long and that
 * command's option table, and the value parsers the commands share (the
 * numbers themselves are util/parse.c's, shared with edgeflag-host).
 */
#include "cli.h"
#include "ef_trace.h"

#include <getopt.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* getopt_long's own extras are switched off here, so that what the command
 * line means is docs/cli.md and not the C library's version of it:
 *  - "+" (stop at the first operand): operands are taken here one by one and
 *    getopt restarted, which gives "options and operands in any order"
 *    without argv being permuted, and independent of POSIXLY_CORRECT;
 *  - ":" and opterr = 0: getopt prints nothing, the messages are ours;
 *  - no abbreviations: a long option is accepted only under its full name
 *    (exact_long), so `--err` never means `--errors`;
 *  - no clusters and no attached short values: `-o` is a word of its own
 *    (`-o=VALUE` is read as `--output=VALUE` is), `-ox` is unknown. */

/* The index in the table of the long option that arg ("--NAME" or
 * "--NAME=VALUE") names exactly, or -1. */
static int exact_long(const struct option *opts, const char *arg)
{
    if (arg[0] != '-' || arg[1] != '-')
        return -1;
    size_t n = strcspn(arg + 2, "=");
    for (int k = 0; opts[k].name; k++)
        if (opts[k].name[0] && strlen(opts[k].name) == n && strncmp(opts[k].name, arg + 2, n) == 0)
            return k;
    return -1;
}

/* "--NAME", or "-C" for an option with only a short spelling (val < 256). */
static void option_label(const struct option *o, char *buf, size_t size)
{
    if (o->name[0] == '\0')
        snprintf(buf, size, "-%c", o->val);
    else
        snprintf(buf, size, "--%s", o->name);
}

/* operand(), or the refusal of a command that takes none. */
static int take_operand(const ef_cli_command *c, void *a, const char *arg)
{
    if (c->operand)
        return c->operand(a, arg);
    if (arg[0] == '-')
        return ef_cli_usage_error(c->name, "unknown option '%s'", arg);
    return ef_cli_usage_error(c->name, "unexpected argument '%s'%s", arg, c->no_operand_hint);
}

int ef_cli_getopt(const ef_cli_command *c, int argc, char **argv, void *a)
{
    const struct option *opts = c->options;
    char shorts[32] = "+:", label[48];
    int nopts = 0, seen[EF_CLI_MAX_OPTIONS] = { 0 };
    int operands_only = 0;

    /* --help wins over anything else on the line, even earlier junk (and,
     * where "--" ends options, only before it). */
    for (int i = 1; i < argc && !(c->dashdash && strcmp(argv[i], "--") == 0); i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            c->usage(stdout);
            return EF_CLI_EXIT_OK;
        }

    while (opts[nopts].name)
        nopts++;
    if (nopts > EF_CLI_MAX_OPTIONS) { /* a table too long for seen[]: a bug, caught by any test */
        ef_cli_error("%s: %d options, more than EF_CLI_MAX_OPTIONS", c->name, nopts);
        return EF_CLI_EXIT_INTERNAL;
    }
    for (int k = 0; k < nopts; k++) /* the short spellings, each "C:" (all take a value) */
        if (opts[k].val < 256 && strlen(shorts) + 3 <= sizeof shorts) {
            size_t n = strlen(shorts);
            shorts[n] = (char)opts[k].val;
            shorts[n + 1] = ':';
            shorts[n + 2] = '\0';
        }

    opterr = 0;
    optind = 0; /* glibc: a full restart (the fuzz target parses many lines) */
    for (;;) {
        int at = optind ? optind : 1, k = -1, r;
        const char *v = NULL;

        if (operands_only || at >= argc) {
            if (at >= argc)
                break;
            r = take_operand(c, a, argv[at]);
            if (r >= 0)
                return r;
            optind = at + 1;
            continue;
        }
        int ch = getopt_long(argc, argv, shorts, opts, &k);
        const char *arg = argv[at];
        if (ch == -1) {
            if (strcmp(arg, "--") == 0 && c->dashdash) {
                operands_only = 1;
                optind = at + 1;
                continue;
            }
            /* An operand (or, without c->dashdash, "--"). */
            r = take_operand(c, a, arg);
            if (r >= 0)
                return r;
            optind = at + 1;
            continue;
        }
        if (ch == '?' || ch == ':') {
            int e = exact_long(opts, arg);
            if (ch == ':' && (e >= 0 || (arg[0] == '-' && arg[1] != '-' && arg[2] == '\0')))
                return ef_cli_usage_error(c->name, "option '%s' needs a value", arg);
            if (ch == '?' && e >= 0 && opts[e].has_arg == no_argument && strchr(arg, '='))
                return ef_cli_usage_error(c->name, "option '%.*s' takes no value", (int)(strchr(arg, '=') - arg), arg);
            return ef_cli_usage_error(c->name, "unknown option '%s'", arg);
        }
        if (k >= 0) { /* a long option: only under its full name */
            if (exact_long(opts, arg) != k)
                return ef_cli_usage_error(c->name, "unknown option '%s'", arg);
        } else { /* a short one: "-C VALUE" or "-C=VALUE", nothing else */
            for (k = 0; k < nopts && opts[k].val != ch; k++)
                ;
            if (k == nopts)
                return ef_cli_usage_error(c->name, "unknown option '%s'", arg);
            if (arg[2] == '=')
                optarg++;
            else if (arg[2] != '\0')
                return ef_cli_usage_error(c->name, "unknown option '%s'", arg);
        }
        v = opts[k].has_arg == no_argument ? NULL : optarg;
        /* -o and --output are one option: "given twice" counts by meaning (val). */
        int first;
        for (first = 0; opts[first].val != opts[k].val; first++)
            ;
        if (seen[first]++) {
            const char *msg = c->twice ? c->twice(opts[k].val) : NULL;
            if (msg)
                return ef_cli_usage_error(c->name, "%s", msg);
            option_label(&opts[first], label, sizeof label);
            return ef_cli_usage_error(c->name, "%s given twice", label);
        }
        r = c->option(a, opts[k].val, v);
        if (r >= 0)
            return r;
    }
    return c->finish ? c->finish(a) : -1;
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

int ef_cli_parse_samples(const char *cmd, const char *v, int32_t *samples)
{
    if (!ef_util_parse_int(v, 1, EF_SAMPLES_MAX, samples) || !ef_samples_valid(*samples))
        return ef_cli_usage_error(cmd, "--samples must be " EF_SAMPLES_TEXT ", not '%s'", v), 0;
    return 1;
}

int ef_cli_scene_value(const char *cmd, int val, const char *v, ef_cli_scene *s)
{
    switch (val) {
    case EF_OPT_SAMPLES: return ef_cli_parse_samples(cmd, v, s->samples) ? 1 : -1;
    case EF_OPT_RULE:
        if (strcmp(v, "evenodd") == 0)
            *s->rule = EF_RULE_EVENODD;
        else if (strcmp(v, "nonzero") == 0)
            *s->rule = EF_RULE_NONZERO;
        else
            return ef_cli_usage_error(cmd, "--rule must be nonzero or evenodd, not '%s'", v), -1;
        return 1;
    case EF_OPT_SIZE:
        if (!ef_util_parse_size(v, EF_MAX_CANVAS, s->fit_w, s->fit_h))
            return ef_cli_usage_error(cmd, "--size must be WxH with 1 <= W, H <= %d, not '%s'", EF_MAX_CANVAS, v), -1;
        return 1;
    case EF_OPT_FILTER:
    case EF_OPT_SUBPIXEL: return ef_cli_filter_value(cmd, val, v, s->filter, s->subpixel);
    default: return 0;
    }
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

int ef_cli_parse_list(const char *cmd, const char *opt, const char *v, const char *const *names, int n, uint32_t *out)
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
