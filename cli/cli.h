/*
 * cli.h - shared pieces of the `edgeflag` command-line tool: exit codes,
 * strict argument parsing and diagnostics.  Only the CLI prints; the
 * library reports status codes (docs/cli.md lists what each exit code means).
 */
#ifndef EF_CLI_H
#define EF_CLI_H

#include <getopt.h>
#include <stdint.h>
#include <stdio.h>

#include "ef_vec.h"
#include "image_write.h"
#include "parse.h" /* ef_util_parse_int, ef_util_parse_size */

/* Exit codes, documented in docs/cli.md.  Scripts depend on them: do not
 * renumber.  70 is EX_SOFTWARE from BSD sysexits.h. */
enum {
    EF_CLI_EXIT_OK = 0,
    EF_CLI_EXIT_MISMATCH = 1, /* check: a mismatch, or a dump missing */
    EF_CLI_EXIT_USAGE = 2,    /* bad command line (check: also an input it cannot read) */
    EF_CLI_EXIT_INPUT = 3,    /* input unreadable, malformed or over a limit */
    EF_CLI_EXIT_OUTPUT = 4,   /* output could not be written */
    EF_CLI_EXIT_INTERNAL = 70 /* a bug, or out of memory */
};

/* The sample count of `render` and `vectors` without --samples (docs/cli.md):
 * 16, as `gen` level 1 uses for its grid-dependent cases, so the default
 * vectors of a scene are of the picture its default render draws. */
#define EF_CLI_SAMPLES_DEFAULT 16

/* Subcommands: argv[0] is the command name; return an exit code. */
int ef_cli_render(int argc, char **argv);
int ef_cli_patterns(int argc, char **argv);
int ef_cli_gen(int argc, char **argv);      /* cmd_gen.c, docs/gen.md */
int ef_cli_check(int argc, char **argv);    /* cmd_check.c, docs/vectors.md section 7 */
int ef_cli_vectors(int argc, char **argv);  /* cmd_vectors.c, docs/vectors.md */
int ef_cli_coverage(int argc, char **argv); /* cmd_coverage.c, dv/coverage/points.tsv */
int ef_cli_rtl_sim(int argc, char **argv);  /* cmd_rtl_sim.c: dv/rtl-sim.sh, this binary the checker */

/* The subcommands' option parsers, separate from what the commands do so that
 * tests/fuzz/fuzz_cli_args.c can drive them without touching any file.  Each
 * returns -1 when the line parsed and the command should run, else the exit
 * code to return (EF_CLI_EXIT_OK after --help, EF_CLI_EXIT_USAGE after a
 * usage error, which has then been reported). */
typedef struct ef_cli_render_args {
    const char *input, *output;
    int32_t samples;      /* 8, 16 or 32 (default EF_CLI_SAMPLES_DEFAULT) */
    int rule;             /* -1: each shape's own; else an ef_rule */
    int32_t fit_w, fit_h; /* 0, 0: the file's own size */
    ef_util_format fmt;
    int filter, subpixel; /* ef_filter, ef_subpixel: box, none (0, 0) by default */
} ef_cli_render_args;
int ef_cli_render_parse(int argc, char **argv, ef_cli_render_args *a);

typedef struct ef_cli_patterns_args {
    int32_t samples; /* 0: all three */
    int emit_c;
    int emit_verilog;
} ef_cli_patterns_args;
int ef_cli_patterns_parse(int argc, char **argv, ef_cli_patterns_args *a);

typedef struct ef_cli_check_args {
    const char *expected, *actual;
    int32_t errors;          /* mismatches reported: 20 (default), 0 = all */
    int cycles;              /* 1: --cycles (default); 0: --transactions */
    const char *junit;       /* --junit FILE, or NULL */
    const char *diff_image;  /* --diff-image FILE, or NULL */
    ef_util_format diff_fmt; /* its format (.png, or .pam without libpng) */
    uint32_t only;           /* --interfaces: interfaces to compare (default all) */
    uint32_t allow_missing;  /* --allow-missing: interfaces whose dump may be absent */
    const char *name;        /* --name: the JUnit suite and class name, or NULL */
} ef_cli_check_args;
int ef_cli_check_parse(int argc, char **argv, ef_cli_check_args *a);

/* `edgeflag vectors`: formats are the table's EF_VEC_F_* bits (ef_vec.h), interfaces ef_iface bits. */
enum { EF_CLI_VEC_ALL = EF_VEC_F_ALL };
typedef struct ef_cli_vectors_args {
    const char *input, *dir;
    int32_t samples;      /* 8, 16 or 32 (default EF_CLI_SAMPLES_DEFAULT) */
    int rule;             /* -1: each shape's own; else an ef_rule */
    int32_t fit_w, fit_h; /* 0, 0: the file's own size */
    unsigned formats;     /* default EF_CLI_VEC_ALL */
    uint32_t ifaces;      /* default every interface */
    int force;
    int dump;             /* --dump: the model's output named as a DUT's dumps */
    int filter, subpixel; /* ef_filter, ef_subpixel: box, none (0, 0) by default */
    int rtl_headers;      /* --rtl-headers: only ef_ifaces.vh and ef_ifaces_pkg.sv, no INPUT */
    int32_t dut_w, dut_h; /* --dut-limits WxH: the DUT's largest canvas (0, 0: none given) */
    int32_t dut_e;        /* --dut-edges E: the most EDGE commands of a shape (0: none given) */
    int schedule;         /* --schedule: ef_schedule (docs/microarch.md sections 4 and 6) */
} ef_cli_vectors_args;
int ef_cli_vectors_parse(int argc, char **argv, ef_cli_vectors_args *a);

/* The options of all commands, as getopt_long's `val`: a short spelling is
 * its character (-o, -n), a long-only option a number above 255.  One
 * meaning, one value, so the value parsers shared by commands (scene,
 * filter) are keyed by it. */
enum {
    EF_OPT_OUTPUT = 'o',
    EF_OPT_N = 'n',
    EF_OPT_SAMPLES = 256,
    EF_OPT_RULE,
    EF_OPT_SIZE,
    EF_OPT_FILTER,
    EF_OPT_SUBPIXEL,
    EF_OPT_FORCE,
    EF_OPT_DUMP,
    EF_OPT_RTL_HEADERS,
    EF_OPT_FORMATS,
    EF_OPT_INTERFACES,
    EF_OPT_SEED,
    EF_OPT_LEVEL,
    EF_OPT_SHARD,
    EF_OPT_LIST,
    EF_OPT_EMIT_C,
    EF_OPT_ERRORS,
    EF_OPT_CYCLES,
    EF_OPT_TRANSACTIONS,
    EF_OPT_ALLOW_MISSING,
    EF_OPT_NAME,
    EF_OPT_JUNIT,
    EF_OPT_DIFF_IMAGE,
    EF_OPT_EMIT_VERILOG,
    EF_OPT_DUT_LIMITS,
    EF_OPT_DUT_EDGES,
    EF_OPT_SCHEDULE,
    EF_OPT_DUT_SAMPLES,
    EF_OPT_DUT_FILE
};
enum { EF_CLI_MAX_OPTIONS = 24 }; /* entries of one command's table */

/* One command's command line, read by ef_cli_getopt (args.c) with
 * getopt_long.  `options` is the command's getopt_long table (ended by a
 * zero entry): has_arg is the value kind (no_argument: a flag,
 * required_argument: "--NAME VALUE" or "--NAME=VALUE"), flag is NULL, val an
 * EF_OPT_*; an option with only a short spelling has the name "" (and two
 * entries with one val, -o and --output, are one option).  The driver takes
 * --help/-h first, then each option at most once ("--NAME given twice", or
 * twice(val) when that is not NULL), in any order with the operands; "--"
 * ends the options where `dashdash` is set (else it is an operand like any
 * other).  A command without operand() refuses every operand: "unknown
 * option" when it starts with '-' (so "-" and "--" too), else "unexpected
 * argument".  option(), operand() and finish() return
 * -1 to go on, else an exit code (a usage error then reported). */
typedef struct ef_cli_command {
    const char *name;
    const struct option *options;
    int dashdash;
    void (*usage)(FILE *f);
    int (*option)(void *a, int val, const char *value);
    int (*operand)(void *a, const char *arg); /* NULL: the command takes no operands */
    const char *no_operand_hint;              /* then: said after "unexpected argument 'ARG'" */
    int (*finish)(void *a);                   /* after the last word; NULL: nothing to check */
    const char *(*twice)(int val);            /* NULL, or a message for val given twice (NULL: the usual) */
} ef_cli_command;
/* The options `render` and `vectors` share, for their tables. */
#define EF_CLI_SCENE_OPTIONS \
    { "samples", required_argument, NULL, EF_OPT_SAMPLES }, { "rule", required_argument, NULL, EF_OPT_RULE }, \
        { "size", required_argument, NULL, EF_OPT_SIZE }, { "filter", required_argument, NULL, EF_OPT_FILTER }, \
    { \
        "subpixel", required_argument, NULL, EF_OPT_SUBPIXEL \
    }
/* Returns -1 when the line parsed and the command should run, else the exit code. */
int ef_cli_getopt(const ef_cli_command *c, int argc, char **argv, void *a);

/* The scene options of `render` and `vectors` (--samples 8|16|32,
 * --rule nonzero|evenodd, --size WxH, --filter box|tent,
 * --subpixel none|rgb|bgr; docs/spec.md 10 for the last two): where the
 * values go. */
typedef struct ef_cli_scene {
    int32_t *samples;
    int *rule;
    int32_t *fit_w, *fit_h;
    int *filter, *subpixel;
} ef_cli_scene;
/* 1 when val is a scene option and v was stored, -1 after a usage error
 * (reported under cmd), 0 when val is another option. */
int ef_cli_scene_value(const char *cmd, int val, const char *v, ef_cli_scene *s);
/* filter_opts.c: the --filter or --subpixel part of it; ef_cli_apply_filter
 * sets them on ctx: -1 on success, else an exit code (the error reported). */
int ef_cli_filter_value(const char *cmd, int val, const char *v, int *filter, int *subpixel);
/* --samples 8|16|32: 1 and stored, or 0 after a usage error. */
int ef_cli_parse_samples(const char *cmd, const char *v, int32_t *samples);
struct ef_ctx;
int ef_cli_apply_filter(struct ef_ctx *ctx, const char *input, int filter, int subpixel);

/* A comma-separated list of names[0..n-1], each at most once, as bits
 * (1 << k); 1, or 0 after a usage error naming opt and the valid names. */
int ef_cli_parse_list(const char *cmd, const char *opt, const char *v, const char *const *names, int n, uint32_t *out);
/* The same for a list of interface names (ef_trace.h), reading the old name
 * `edge` of `seg` too. */
int ef_cli_parse_ifaces(const char *cmd, const char *opt, const char *v, uint32_t *out);

/* "edgeflag: <cmd>: <message>" + a hint line on stderr; returns
 * EF_CLI_EXIT_USAGE so callers can `return ef_cli_usage_error(...)`. */
int ef_cli_usage_error(const char *cmd, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Silences ef_cli_usage_error and ef_cli_error (for the fuzz target, which
 * calls the parsers millions of times); normal runs never call it. */
void ef_cli_set_quiet(int quiet);

/* "edgeflag: <message>" on stderr. */
void ef_cli_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

#endif /* EF_CLI_H */
