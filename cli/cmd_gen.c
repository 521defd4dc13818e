/*
 * cmd_gen.c - `edgeflag gen`: writes the seeded regression scenes of
 * rtl_vectors/ (docs/gen.md) as DIR/case_NNNNNN.scene plus an index.
 *
 * Order of work, so that a failure leaves as little as possible behind:
 * the whole command line is checked first (a usage error creates nothing,
 * not even DIR); then DIR is created and every file this run would write is
 * looked for (without --force an existing one stops the run before anything
 * is written); then each case is built, formatted and written atomically
 * (atomic_file.h: a file is whole or absent); the index is written last, so
 * its presence marks a complete run or shard.
 */
#include "cli.h"

#include "atomic_file.h"
#include "dut_file.h"
#include "ef_gen.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

static const char *const CMD = "gen";

static void usage(FILE *f)
{
    fprintf(f,
            "usage: edgeflag gen -o DIR [--seed N] [--level 1|2] [-n K] [--shard I/N]\n"
            "                    [--samples 8|16|32] [--force] [DUT LIMITS]\n"
            "       edgeflag gen --list [--seed N] [--level 1|2] [-n K] [--shard I/N] [--samples N]\n"
            "                    [DUT LIMITS]\n"
            "\n"
            "Writes seeded regression scenes for hardware implementations: first a table of\n"
            "directed corner cases, then random cases, as DIR/case_NNNNNN.scene (the .scene\n"
            "format `edgeflag render` reads, vertices as exact Q16.8 decimals) and an index,\n"
            "DIR/index.tsv (DIR/index_I_of_N.tsv for a shard).  Same options, same bytes, on\n"
            "every machine.  See docs/gen.md.\n"
            "\n"
            "options:\n"
            "  -o, --output DIR  directory to write (created if missing); files are written\n"
            "                    atomically; existing case or index files are refused\n"
            "  --seed N          seed of the random cases, 0 .. 2^64-1 (default %" PRIu64 ")\n"
            "  --level L         1: the directed table and %u random cases (default);\n"
            "                    2: more directed variants and %u random cases\n"
            "  -n K              random cases: at least the level's count (can raise it, never\n"
            "                    lower it); at most %u cases in all\n"
            "  --shard I/N       write only the cases k with k mod N = I-1 (1 <= I <= N); the\n"
            "                    N shards together are exactly the unsharded run\n"
            "  --samples N       grid of the grid-dependent directed cases: 8, 16 or 32\n"
            "                    (default: 16 at level 1, all three at level 2)\n"
            "  --force           replace existing files of the same names\n"
            "  --list            print the index on standard output instead of writing files\n"
            "  -h, --help        show this text\n"
            "\n"
            "DUT limits (docs/gen.md section 11): a case over them is fitted (the canvas\n"
            "scaled by 1/2^k; a shape split into shapes of whole contours where the model\n"
            "renders the same picture) or refused by name (not written; refused.tsv):\n"
            "  --dut-limits WxH  the DUT's largest canvas (W_MAX x H_MAX)\n"
            "  --dut-edges E     the most EDGE commands of one shape (E_MAX)\n"
            "  --dut-samples L   the sample counts it takes, e.g. 8,16\n"
            "  --dut-file FILE   read them from a board's 48-byte identify record\n"
            "                    (docs/board.md 3.1) or from a Verilog or C file that\n"
            "                    defines W_MAX, H_MAX, E_MAX, NS (`define, #define,\n"
            "                    parameter; any prefix ending in _); a flag overrides it\n"
            "\n"
            "Prints one summary line on standard output, and one line per refused case.\n"
            "exit codes: 0 ok, 2 usage, 4 a file could not be written (or exists), 70 internal\n",
            EF_GEN_DEFAULT_SEED, EF_GEN_LEVEL1_RANDOM, EF_GEN_LEVEL2_RANDOM, EF_GEN_MAX_CASES);
}

typedef struct gen_args {
    const char *dir;
    ef_gen_config cfg;
    uint32_t shard_i, shard_n;
    int force, list;
    int fit;           /* any DUT limit given */
    ef_gen_limits lim; /* the DUT's limits (0: none) */
} gen_args;

/* Strict unsigned 64-bit decimal: digits only, value <= 2^64 - 1. */
static int parse_u64(const char *s, uint64_t *out)
{
    uint64_t v = 0;
    if (!s || !*s)
        return 0;
    for (; *s; s++) {
        unsigned d;
        if (*s < '0' || *s > '9')
            return 0;
        d = (unsigned)(*s - '0');
        if (v > (UINT64_MAX - d) / 10)
            return 0;
        v = v * 10 + d;
    }
    *out = v;
    return 1;
}

/* "I/N" with 1 <= I <= N <= EF_GEN_MAX_CASES. */
static int parse_shard(const char *s, uint32_t *i, uint32_t *n)
{
    char buf[16];
    const char *slash = strchr(s, '/');
    size_t len;
    int32_t a, b;
    if (!slash)
        return 0;
    len = (size_t)(slash - s);
    if (len == 0 || len >= sizeof buf)
        return 0;
    memcpy(buf, s, len);
    buf[len] = '\0';
    if (!ef_util_parse_int(buf, 1, (int32_t)EF_GEN_MAX_CASES, &a) ||
        !ef_util_parse_int(slash + 1, 1, (int32_t)EF_GEN_MAX_CASES, &b) || a > b)
        return 0;
    *i = (uint32_t)a;
    *n = (uint32_t)b;
    return 1;
}

static const struct option OPTIONS[] = { { "", required_argument, NULL, EF_OPT_OUTPUT }, /* -o */
                                         { "output", required_argument, NULL, EF_OPT_OUTPUT },
                                         { "seed", required_argument, NULL, EF_OPT_SEED },
                                         { "level", required_argument, NULL, EF_OPT_LEVEL },
                                         { "", required_argument, NULL, EF_OPT_N }, /* -n */
                                         { "shard", required_argument, NULL, EF_OPT_SHARD },
                                         { "samples", required_argument, NULL, EF_OPT_SAMPLES },
                                         { "force", no_argument, NULL, EF_OPT_FORCE },
                                         { "list", no_argument, NULL, EF_OPT_LIST },
                                         { "dut-limits", required_argument, NULL, EF_OPT_DUT_LIMITS },
                                         { "dut-edges", required_argument, NULL, EF_OPT_DUT_EDGES },
                                         { "dut-samples", required_argument, NULL, EF_OPT_DUT_SAMPLES },
                                         { "dut-file", required_argument, NULL, EF_OPT_DUT_FILE },
                                         { NULL, 0, NULL, 0 } };

/* The line as read, before the level's configuration is built from it. */
typedef struct gen_line {
    gen_args *a;
    int32_t level, samples, k;
    int seen_n;
    uint64_t seed;
    int32_t dut_w, dut_h, dut_e; /* from the flags (0: not given) */
    uint32_t dut_s;
    const char *dut_file;
} gen_line;

/* "8,16" -> the identify record's bits (bit 3: 8, bit 4: 16, bit 5: 32). */
static int parse_sample_list(const char *v, uint32_t *mask)
{
    static const char *const names[3] = { "8", "16", "32" };
    uint32_t bits = 0;
    if (!ef_cli_parse_list(CMD, "--dut-samples", v, names, 3, &bits))
        return 0;
    *mask = bits << 3;
    return 1;
}

/* --dut-file: a board's identify record or a Verilog/C file (dut_file.h,
 * docs/gen.md section 11).  Fills lim; -1 on success, else the exit code
 * after the error is reported as every reader's ("FILE:LINE:COL: ...", the
 * record's byte offset, or the whole file): exit 2, as for the limit flags. */
static int read_dut_file(const char *path, ef_gen_limits *lim)
{
    unsigned char *raw;
    size_t n;
    ef_dut_error de;
    char msg[4400];
    FILE *f = fopen(path, "rb");
    memset(lim, 0, sizeof *lim);
    if (!f) {
        ef_cli_error("%s: %s (--dut-file)", path, strerror(errno));
        return EF_CLI_EXIT_USAGE;
    }
    if (!(raw = malloc(EF_DUT_FILE_MAX + 1))) {
        fclose(f);
        ef_cli_error("out of memory");
        return EF_CLI_EXIT_INTERNAL;
    }
    n = fread(raw, 1, EF_DUT_FILE_MAX + 1, f);
    if (ferror(f)) {
        const int e = errno;
        fclose(f);
        free(raw);
        ef_cli_error("%s: %s (--dut-file)", path, strerror(e ? e : EIO));
        return EF_CLI_EXIT_USAGE;
    }
    fclose(f);
    const int bad = ef_dut_file_parse(raw, n, lim, &de) != 0;
    free(raw);
    if (!bad)
        return -1;
    ef_dut_error_format(path, &de, msg, sizeof msg);
    ef_cli_error("%s", msg);
    return EF_CLI_EXIT_USAGE;
}

static int on_option(void *p, int val, const char *v)
{
    gen_line *l = p;
    gen_args *a = l->a;
    switch (val) {
    case EF_OPT_FORCE: a->force = 1; break;
    case EF_OPT_LIST: a->list = 1; break;
    case EF_OPT_OUTPUT:
        if (!*v)
            return ef_cli_usage_error(CMD, "empty output directory name");
        a->dir = v;
        break;
    case EF_OPT_SEED:
        if (!parse_u64(v, &l->seed))
            return ef_cli_usage_error(CMD,
                                      "--seed must be a decimal number 0 .. 18446744073709551615, "
                                      "not '%s'",
                                      v);
        break;
    case EF_OPT_LEVEL:
        if (!ef_util_parse_int(v, 1, 2, &l->level))
            return ef_cli_usage_error(CMD, "--level must be 1 or 2, not '%s'", v);
        break;
    case EF_OPT_N:
        l->seen_n = 1;
        if (!ef_util_parse_int(v, 0, (int32_t)EF_GEN_MAX_CASES, &l->k))
            return ef_cli_usage_error(CMD, "-n must be a number of random cases up to %u, not '%s'", EF_GEN_MAX_CASES,
                                      v);
        break;
    case EF_OPT_SHARD:
        if (!parse_shard(v, &a->shard_i, &a->shard_n))
            return ef_cli_usage_error(CMD, "--shard must be I/N with 1 <= I <= N <= %u, not '%s'", EF_GEN_MAX_CASES, v);
        break;
    case EF_OPT_DUT_LIMITS:
        if (!ef_util_parse_size(v, EF_MAX_CANVAS, &l->dut_w, &l->dut_h))
            return ef_cli_usage_error(CMD, "--dut-limits takes WxH (each 1..%d), not '%s'", EF_MAX_CANVAS, v);
        break;
    case EF_OPT_DUT_EDGES:
        if (!ef_util_parse_int(v, 1, INT32_MAX, &l->dut_e))
            return ef_cli_usage_error(CMD, "--dut-edges takes a positive number, not '%s'", v);
        break;
    case EF_OPT_DUT_SAMPLES:
        if (!parse_sample_list(v, &l->dut_s))
            return EF_CLI_EXIT_USAGE;
        break;
    case EF_OPT_DUT_FILE:
        if (!*v)
            return ef_cli_usage_error(CMD, "empty --dut-file name");
        l->dut_file = v;
        break;
    default: /* EF_OPT_SAMPLES */
        if (!ef_cli_parse_samples(CMD, v, &l->samples))
            return EF_CLI_EXIT_USAGE;
        break;
    }
    return -1;
}

static int finish(void *p)
{
    gen_line *l = p;
    gen_args *a = l->a;
    if (a->list && a->dir)
        return ef_cli_usage_error(CMD, "--list writes no files: it takes no -o");
    if (!a->list && !a->dir)
        return ef_cli_usage_error(CMD, "no output directory (-o DIR)");
    if (a->list && a->force)
        return ef_cli_usage_error(CMD, "--list writes no files: --force makes no sense with it");

    if (l->dut_file) {
        int rc = read_dut_file(l->dut_file, &a->lim);
        if (rc >= 0)
            return rc;
        a->fit = 1;
    }
    if (l->dut_w)
        a->lim.width = l->dut_w, a->lim.height = l->dut_h, a->fit = 1;
    if (l->dut_e)
        a->lim.edges = (uint32_t)l->dut_e, a->fit = 1;
    if (l->dut_s)
        a->lim.samples_mask = l->dut_s, a->fit = 1;
    ef_gen_config_defaults(&a->cfg, l->level);
    a->cfg.seed = l->seed;
    a->cfg.grid = l->samples;
    if (a->fit && l->samples && !ef_gen_limits_takes(&a->lim, l->samples))
        return ef_cli_usage_error(CMD, "--samples %" PRId32 ": the DUT does not take %" PRId32 " samples per pixel",
                                  l->samples, l->samples);
    /* Level 1's grid cases are built on one grid: the DUT's, when it does not take the default 16. */
    if (a->fit && !l->samples && l->level == 1 && !ef_gen_limits_takes(&a->lim, 16))
        a->cfg.grid = ef_gen_limits_takes(&a->lim, 8) ? 8 : 32;
    if (l->seen_n) {
        if ((uint32_t)l->k < a->cfg.nrandom)
            return ef_cli_usage_error(CMD,
                                      "-n %" PRId32 " is below level %" PRId32 "'s %" PRIu32
                                      " random cases: -n can raise the count, never lower it",
                                      l->k, l->level, a->cfg.nrandom);
        a->cfg.nrandom = (uint32_t)l->k;
    }
    if (ef_gen_config_check(&a->cfg) != EF_OK)
        return ef_cli_usage_error(CMD, "-n %" PRId32 " makes more than %u cases (%" PRIu32 " directed)", l->k,
                                  EF_GEN_MAX_CASES, ef_gen_directed_count(&a->cfg));
    return -1;
}

static const char *twice(int val) { return val == EF_OPT_OUTPUT ? "output directory given twice" : NULL; }

static const ef_cli_command COMMAND = { "gen",  OPTIONS, 0, usage, on_option, NULL, " (the directory is given with -o)",
                                        finish, twice };

/* Returns -1 when the line parsed and the command should run, else the exit code. */
static int parse(int argc, char **argv, gen_args *a)
{
    gen_line l;
    memset(&l, 0, sizeof l);
    l.a = a;
    l.level = 1;
    l.seed = EF_GEN_DEFAULT_SEED;
    memset(a, 0, sizeof *a);
    a->shard_i = a->shard_n = 1;
    return ef_cli_getopt(&COMMAND, argc, argv, &l);
}

static int join(char *out, size_t size, const char *dir, const char *name)
{
    size_t n = strlen(dir);
    int w = snprintf(out, size, "%s%s%s", dir, (n && dir[n - 1] == '/') ? "" : "/", name);
    return w >= 0 && (size_t)w < size;
}

static void index_name(const gen_args *a, char *buf, size_t size)
{
    if (a->shard_n == 1)
        snprintf(buf, size, "index.tsv");
    else
        snprintf(buf, size, "index_%" PRIu32 "_of_%" PRIu32 ".tsv", a->shard_i, a->shard_n);
}

/* The cases the DUT's limits refuse: refused.tsv (refused_I_of_N.tsv). */
static void refused_name(const gen_args *a, char *buf, size_t size)
{
    if (a->shard_n == 1)
        snprintf(buf, size, "refused.tsv");
    else
        snprintf(buf, size, "refused_%" PRIu32 "_of_%" PRIu32 ".tsv", a->shard_i, a->shard_n);
}

/* "W_MAX 2048, H_MAX 2048, E_MAX 8192, samples 8,16" (the limits given). */
static void describe_limits(const ef_gen_limits *lim, char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = '\0';
    if (lim->width)
        n += (size_t)snprintf(buf + n, size - n, "W_MAX %" PRId32 ", H_MAX %" PRId32, lim->width, lim->height);
    if (lim->edges && n < size)
        n += (size_t)snprintf(buf + n, size - n, "%sE_MAX %" PRIu32, n ? ", " : "", lim->edges);
    if (lim->samples_mask && n < size)
        snprintf(buf + n, size - n, "%ssamples %s%s%s", n ? ", " : "", (lim->samples_mask & 8u) ? "8," : "",
                 (lim->samples_mask & 16u) ? "16," : "", (lim->samples_mask & 32u) ? "32" : "");
    n = strlen(buf);
    if (n && buf[n - 1] == ',')
        buf[n - 1] = '\0';
}

static int write_file(const char *path, const ef_gen_text *t)
{
    ef_util_atomic af;
    if (ef_util_atomic_open(&af, path) != 0) {
        ef_cli_error("cannot write '%s': %s", path, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    if (t->len && fwrite(t->data, 1, t->len, af.fp) != t->len) {
        int e = errno;
        ef_util_atomic_abort(&af);
        ef_cli_error("cannot write '%s': %s", path, strerror(e ? e : EIO));
        return EF_CLI_EXIT_OUTPUT;
    }
    if (ef_util_atomic_commit(&af) != 0) {
        ef_cli_error("cannot write '%s': %s", path, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    return EF_CLI_EXIT_OK;
}

/* -1 if DIR/NAME does not exist; else reports and returns the exit code. */
static int refuse_existing(const char *dir, const char *name)
{
    char path[4096];
    struct stat sb;
    if (!join(path, sizeof path, dir, name)) {
        ef_cli_error("'%s': path too long", dir);
        return EF_CLI_EXIT_OUTPUT;
    }
    if (lstat(path, &sb) == 0) {
        ef_cli_error("'%s' exists: use --force to replace it, or a new directory", path);
        return EF_CLI_EXIT_OUTPUT;
    }
    return -1;
}

int ef_cli_gen(int argc, char **argv)
{
    gen_args a;
    ef_gen_text text = { NULL, 0, 0 }, index = { NULL, 0, 0 };
    ef_gen_case gc;
    ef_gen_text refused = { NULL, 0, 0 };
    char path[4096], rpath[4096] = "", name[64], limits[128];
    uint32_t total, written = 0, nfitted = 0, nrefused = 0;
    ef_status st;
    int rc = parse(argc, argv, &a);

    if (rc >= 0)
        return rc;
    total = ef_gen_total(&a.cfg);

    if (!a.list) {
        if (ef_util_make_dirs(a.dir) != 0) {
            ef_cli_error("cannot create directory '%s': %s", a.dir, strerror(errno));
            return EF_CLI_EXIT_OUTPUT;
        }
        /* Refuse before writing anything if a file of this run is there already. */
        if (!a.force) {
            for (uint32_t k = a.shard_i - 1; k < total; k += a.shard_n) {
                ef_gen_file_name(k, name, sizeof name);
                if ((rc = refuse_existing(a.dir, name)) >= 0)
                    return rc;
            }
            index_name(&a, name, sizeof name);
            if ((rc = refuse_existing(a.dir, name)) >= 0)
                return rc;
            refused_name(&a, name, sizeof name);
            if (a.fit && (rc = refuse_existing(a.dir, name)) >= 0)
                return rc;
        }
    }
    describe_limits(&a.lim, limits, sizeof limits);
    refused.len = 0;
    if (a.fit &&
        ((st = ef_gen_text_append(&refused, "# edgeflag gen: cases the DUT's limits refuse (")) != EF_OK ||
         (st = ef_gen_text_append(&refused, limits)) != EF_OK ||
         (st = ef_gen_text_append(
              &refused, "; docs/gen.md section 11)\ncase\tkind\tcategory\tname\tgrid\tseed\treason\n")) != EF_OK)) {
        ef_cli_error("out of memory");
        rc = EF_CLI_EXIT_INTERNAL;
        goto out;
    }

    if ((st = ef_gen_index_header(&a.cfg, a.shard_i, a.shard_n, &index)) != EF_OK) {
        ef_cli_error("out of memory");
        rc = EF_CLI_EXIT_INTERNAL;
        goto out;
    }
    for (uint32_t k = a.shard_i - 1; k < total; k += a.shard_n) {
        ef_gen_fit_result fr = EF_GEN_FIT_AS_IS;
        st = ef_gen_build(&a.cfg, k, &gc);
        if (st == EF_OK && a.fit)
            st = ef_gen_fit(&a.lim, &gc, &fr);
        if (st == EF_OK && fr == EF_GEN_FIT_REFUSED) {
            char row[700], seed[24] = "-";
            /* the index's columns for the case (what it would have been), then the reason */
            if (!gc.directed)
                snprintf(seed, sizeof seed, "0x%016" PRIx64, gc.case_seed);
            snprintf(row, sizeof row, "%" PRIu32 "\t%s\t%s\t%s%s\t%d\t%s\t%s\n", k, gc.directed ? "directed" : "random",
                     ef_gen_category_name(gc.category), gc.name, gc.rules_swapped ? "/swapped" : "", gc.grid, seed,
                     gc.fit_note);
            /* one line each; on stderr under --list, whose standard output is the index */
            fprintf(a.list ? stderr : stdout, "edgeflag gen: case %" PRIu32 " (%s%s) refused by the DUT's limits: %s\n",
                    k, gc.name, gc.rules_swapped ? "/swapped" : "", gc.fit_note);
            st = ef_gen_text_append(&refused, row);
            ef_gen_case_destroy(&gc);
            if (st != EF_OK) {
                ef_cli_error("out of memory");
                rc = EF_CLI_EXIT_INTERNAL;
                goto out;
            }
            nrefused++;
            continue;
        }
        if (st == EF_OK && fr == EF_GEN_FIT_FITTED)
            nfitted++;
        if (st == EF_OK)
            st = ef_gen_index_row(&gc, &index);
        if (st == EF_OK && !a.list)
            st = ef_gen_format(&a.cfg, &gc, &text);
        ef_gen_case_destroy(&gc);
        if (st != EF_OK) {
            ef_cli_error("case %" PRIu32 ": %s", k, ef_strerror(st));
            rc = EF_CLI_EXIT_INTERNAL; /* out of memory, or a bug in a builder */
            goto out;
        }
        if (!a.list) {
            ef_gen_file_name(k, name, sizeof name);
            if (!join(path, sizeof path, a.dir, name)) {
                ef_cli_error("'%s': path too long", a.dir);
                rc = EF_CLI_EXIT_OUTPUT;
                goto out;
            }
            if ((rc = write_file(path, &text)) != EF_CLI_EXIT_OK)
                goto out;
        }
        written++;
    }
    if (a.list) {
        if (fwrite(index.data, 1, index.len, stdout) != index.len || fflush(stdout) != 0) {
            ef_cli_error("cannot write to standard output: %s", strerror(errno));
            rc = EF_CLI_EXIT_OUTPUT;
            goto out;
        }
        rc = EF_CLI_EXIT_OK;
        goto out;
    }
    if (a.fit) {
        refused_name(&a, name, sizeof name);
        if (!join(path, sizeof path, a.dir, name)) {
            rc = EF_CLI_EXIT_OUTPUT;
            goto out;
        }
        if ((rc = write_file(path, &refused)) != EF_CLI_EXIT_OK)
            goto out;
        snprintf(rpath, sizeof rpath, "%s", path);
    }
    index_name(&a, name, sizeof name);
    if (!join(path, sizeof path, a.dir, name)) {
        rc = EF_CLI_EXIT_OUTPUT;
        goto out;
    }
    if ((rc = write_file(path, &index)) != EF_CLI_EXIT_OK)
        goto out;
    printf("edgeflag gen: wrote %" PRIu32 " of %" PRIu32 " cases (%" PRIu32 " directed, %" PRIu32
           " random; seed %" PRIu64 ", level %d, shard %" PRIu32 "/%" PRIu32 ") to %s, index %s",
           written, total, ef_gen_directed_count(&a.cfg), a.cfg.nrandom, a.cfg.seed, a.cfg.level, a.shard_i, a.shard_n,
           a.dir, path);
    if (a.fit)
        printf("; the DUT's limits (%s): %" PRIu32 " fitted, %" PRIu32 " refused (%s)", limits, nfitted, nrefused,
               rpath);
    printf("\n");
    rc = fflush(stdout) == 0 ? EF_CLI_EXIT_OK : EF_CLI_EXIT_OUTPUT;
out:
    ef_gen_text_destroy(&text);
    ef_gen_text_destroy(&index);
    ef_gen_text_destroy(&refused);
    return rc;
}
