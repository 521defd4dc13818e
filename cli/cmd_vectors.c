/*
 * cmd_vectors.c - `edgeflag vectors`: a scene rendered with the timing model
 * on (docs/microarch.md), every transfer at every interface written as test
 * vectors (docs/vectors.md).
 *
 * Order of work, as in `render` and `gen`, so that a failure leaves as little
 * as possible: the command line is checked first (a usage error touches
 * nothing); the input is loaded (exit 3, nothing created); existing files
 * are refused without --force before the long part; the frame is rendered
 * and traced into memory; only then is DIR created and each file written
 * atomically, manifest.json last (vectors_files.c).
 */
#include "cli.h"

#include "atomic_file.h"
#include "ef_scene.h"
#include "ef_trace.h"
#include "ef_vec.h"
#include "vectors_files.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <unistd.h>

static const char *const CMD = "vectors";

static void usage(FILE *f)
{
    fputs("usage: edgeflag vectors INPUT -o DIR [--samples 8|16|32] [--rule nonzero|evenodd]\n"
          "                        [--size WxH] [--formats hex,vcd,bin] [--interfaces LIST] [--force]\n"
          "                        [--dump] [--filter box|tent] [--subpixel none|rgb|bgr]\n"
          "                        [--dut-limits WxH] [--dut-edges E]\n"
          "                        [--schedule reference|overlap]\n"
          "       edgeflag vectors --rtl-headers -o DIR [--force]\n"
          "\n"
          "Renders INPUT (.svg, .scene/.txt) with the timing model of the reference\n"
          "microarchitecture and writes every transfer at every interface, stamped with\n"
          "its cycle, as test vectors into DIR (docs/vectors.md):\n"
          "  cmd.stim.hex, IFACE.expected.hex     $readmemh words {cycle[47:0], payload}\n"
          "  vectors.vcd                          every interface signal, one clock\n"
          "  vectors.bin                          binary stream for the host tool\n"
          "  frame.png                            the expected image\n"
          "  manifest.json                        files, counts, SHA-256; written last\n"
          "\n"
          "options:\n"
          "  -o, --output DIR   directory to write (created with its parents if missing)\n"
          "  --samples N        samples per pixel: 8, 16 (default) or 32\n"
          "  --rule RULE        fill every shape with RULE (nonzero or evenodd) instead of\n"
          "                     its own\n"
          "  --size WxH         fit the drawing into a W x H pixel canvas (1..16384 each)\n"
          "  --formats LIST     comma-separated subset of hex,vcd,bin (default all three)\n"
          "  --interfaces LIST  comma-separated subset of cmd,seg,et_wr,et_rd,plot,span,pix\n"
          "                     (default all; edge, the old name of seg, is read too)\n"
          "  --force            replace existing files of the same names\n"
          "  --dump             write the model's transactions as a DUT's dumps would be\n"
          "                     named (IFACE.actual.hex, vectors.actual.bin; no manifest):\n"
          "                     the model standing in for the DUT, to try a bench's or a\n"
          "                     regression's plumbing with `edgeflag check`\n"
          "  --filter F         box (default) or tent: the 2x2-pixel tent (docs/spec.md 10)\n"
          "  --subpixel S       none (default), rgb or bgr: per-channel sample offsets;\n"
          "                     with either, the vectors follow docs/microarch.md section 5\n"
          "  --dut-limits WxH   the DUT's largest canvas: a larger one is refused (exit 3,\n"
          "                     nothing written), naming the limit\n"
          "  --dut-edges E      the most EDGE commands one shape may have in the DUT (the\n"
          "                     RTL's E_MAX): a shape with more is refused the same way\n"
          "                     (needs cmd among --interfaces)\n"
          "  --schedule S       reference (default: docs/microarch.md section 4) or\n"
          "                     overlap (section 6, the fast RTL's): the same\n"
          "                     transactions, stamped at the cycles of that schedule\n"
          "                     (overlap takes neither --filter tent nor --subpixel)\n"
          "  --rtl-headers      write only ef_ifaces.vh (Verilog) and ef_ifaces_pkg.sv\n"
          "                     (SystemVerilog): every interface's widths, field offsets\n"
          "                     and the command codes, for testbenches (no INPUT)\n"
          "  -h, --help         show this text\n"
          "  --                 end of options (for an INPUT starting with '-')\n"
          "\n"
          "Prints one summary line on standard output.\n"
          "exit codes: 0 ok, 2 usage, 3 bad input or over a limit, 4 output not written\n"
          "            (or a file exists), 70 internal error\n",
          f);
}

/* Returns -1 when parsing succeeded, else the exit code to return. */
static const struct option OPTIONS[] = { { "", required_argument, NULL, EF_OPT_OUTPUT }, /* -o */
                                         { "output", required_argument, NULL, EF_OPT_OUTPUT },
                                         EF_CLI_SCENE_OPTIONS,
                                         { "formats", required_argument, NULL, EF_OPT_FORMATS },
                                         { "interfaces", required_argument, NULL, EF_OPT_INTERFACES },
                                         { "force", no_argument, NULL, EF_OPT_FORCE },
                                         { "dump", no_argument, NULL, EF_OPT_DUMP },
                                         { "rtl-headers", no_argument, NULL, EF_OPT_RTL_HEADERS },
                                         { "dut-limits", required_argument, NULL, EF_OPT_DUT_LIMITS },
                                         { "dut-edges", required_argument, NULL, EF_OPT_DUT_EDGES },
                                         { "schedule", required_argument, NULL, EF_OPT_SCHEDULE },
                                         { NULL, 0, NULL, 0 } };

/* The line as read: the request, and whether an option --rtl-headers does
 * not go with was given. */
typedef struct vectors_line {
    ef_cli_vectors_args *a;
    int scene_options; /* any option but -o, --force and --rtl-headers itself */
} vectors_line;

static int on_option(void *p, int val, const char *v)
{
    vectors_line *l = p;
    ef_cli_vectors_args *a = l->a;
    ef_cli_scene s = { &a->samples, &a->rule, &a->fit_w, &a->fit_h, &a->filter, &a->subpixel };
    uint32_t bits;
    int r;

    switch (val) {
    case EF_OPT_FORCE: a->force = 1; return -1;
    case EF_OPT_RTL_HEADERS: a->rtl_headers = 1; return -1;
    case EF_OPT_OUTPUT:
        if (!*v)
            return ef_cli_usage_error(CMD, "empty output directory name");
        a->dir = v;
        return -1;
    case EF_OPT_DUMP:
        a->dump = 1;
        l->scene_options = 1;
        return -1;
    case EF_OPT_DUT_LIMITS:
        if (!ef_util_parse_size(v, EF_MAX_CANVAS, &a->dut_w, &a->dut_h))
            return ef_cli_usage_error(CMD, "--dut-limits takes WxH (each 1..%d), not '%s'", EF_MAX_CANVAS, v);
        l->scene_options = 1;
        return -1;
    case EF_OPT_DUT_EDGES:
        if (!ef_util_parse_int(v, 1, INT32_MAX, &a->dut_e))
            return ef_cli_usage_error(CMD, "--dut-edges takes a positive number, not '%s'", v);
        l->scene_options = 1;
        return -1;
    case EF_OPT_SCHEDULE:
        if (strcmp(v, "reference") == 0)
            a->schedule = EF_SCHEDULE_REFERENCE;
        else if (strcmp(v, "overlap") == 0)
            a->schedule = EF_SCHEDULE_OVERLAP;
        else
            return ef_cli_usage_error(CMD, "--schedule takes reference or overlap, not '%s'", v);
        l->scene_options = 1;
        return -1;
    case EF_OPT_FORMATS: {
        const char *format_names[EF_VEC_NFORMATS];
        for (int k = 0; k < EF_VEC_NFORMATS; k++)
            format_names[k] = ef_vec_formats[k].name;
        if (!ef_cli_parse_list(CMD, "--formats", v, format_names, EF_VEC_NFORMATS, &bits))
            return EF_CLI_EXIT_USAGE;
        a->formats = 0;
        for (int k = 0; k < EF_VEC_NFORMATS; k++)
            a->formats |= (bits >> k & 1u) ? ef_vec_formats[k].bit : 0u;
        l->scene_options = 1;
        return -1;
    }
    case EF_OPT_INTERFACES:
        if (!ef_cli_parse_ifaces(CMD, "--interfaces", v, &a->ifaces))
            return EF_CLI_EXIT_USAGE;
        l->scene_options = 1;
        return -1;
    default:
        if ((r = ef_cli_scene_value(CMD, val, v, &s)) < 0)
            return EF_CLI_EXIT_USAGE;
        l->scene_options = 1; /* --filter and --subpixel too (docs/cli.md: only -o and --force) */
        return -1;
    }
}

static int on_operand(void *p, const char *arg)
{
    ef_cli_vectors_args *a = ((vectors_line *)p)->a;
    if (a->input)
        return ef_cli_usage_error(CMD, "more than one input ('%s' and '%s')", a->input, arg);
    a->input = arg;
    return -1;
}

static int finish(void *p)
{
    vectors_line *l = p;
    ef_cli_vectors_args *a = l->a;
    if (a->rtl_headers) {
        if (a->input)
            return ef_cli_usage_error(CMD, "--rtl-headers takes no input ('%s')", a->input);
        if (l->scene_options)
            return ef_cli_usage_error(CMD, "--rtl-headers takes only -o DIR and --force");
    } else if (!a->input) {
        return ef_cli_usage_error(CMD, "no input file");
    }
    if (!a->dir)
        return ef_cli_usage_error(CMD, "no output directory (-o DIR)");
    if (a->schedule == EF_SCHEDULE_OVERLAP && (a->filter != 0 || a->subpixel != 0))
        return ef_cli_usage_error(CMD, "--schedule overlap covers the box filter without --subpixel "
                                       "(docs/microarch.md section 6)");
    if (a->dut_e && !(a->ifaces & (1u << EF_IF_CMD)))
        return ef_cli_usage_error(CMD,
                                  "--dut-edges counts the cmd interface's EDGE commands: keep cmd in --interfaces");
    return -1;
}

static const char *twice(int val) { return val == EF_OPT_OUTPUT ? "output directory given twice" : NULL; }

static const ef_cli_command COMMAND = { "vectors", OPTIONS, 1, usage, on_option, on_operand, NULL, finish, twice };

int ef_cli_vectors_parse(int argc, char **argv, ef_cli_vectors_args *a)
{
    vectors_line l = { a, 0 };
    memset(a, 0, sizeof *a);
    a->samples = EF_CLI_SAMPLES_DEFAULT;
    a->rule = -1;
    a->formats = EF_CLI_VEC_ALL;
    a->ifaces = EF_IF_ALL;
    return ef_cli_getopt(&COMMAND, argc, argv, &l);
}

/* --rtl-headers: the two files of docs/vectors.md section 8, each atomic;
 * without --force an existing one stops the run before anything is written. */
static int write_rtl_headers(const ef_cli_vectors_args *a)
{
    static const char *const names[2] = { "ef_ifaces.vh", "ef_ifaces_pkg.sv" };
    char path[2][4096];
    for (int k = 0; k < 2; k++) {
        if ((size_t)snprintf(path[k], sizeof path[k], "%s/%s", a->dir, names[k]) >= sizeof path[k]) {
            ef_cli_error("output directory name too long");
            return EF_CLI_EXIT_OUTPUT;
        }
        if (!a->force && access(path[k], F_OK) == 0) {
            ef_cli_error("%s exists (--force replaces it)", path[k]);
            return EF_CLI_EXIT_OUTPUT;
        }
    }
    if (ef_util_make_dirs(a->dir) != 0) {
        ef_cli_error("cannot create '%s': %s", a->dir, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    for (int k = 0; k < 2; k++) {
        ef_util_atomic af;
        if (ef_util_atomic_open(&af, path[k]) != 0) {
            ef_cli_error("cannot write '%s': %s", path[k], strerror(errno));
            return EF_CLI_EXIT_OUTPUT;
        }
        ef_vec_rtl_header_write(af.fp, k);
        if (ferror(af.fp)) {
            ef_util_atomic_abort(&af);
            ef_cli_error("cannot write '%s'", path[k]);
            return EF_CLI_EXIT_OUTPUT;
        }
        if (ef_util_atomic_commit(&af) != 0) {
            ef_cli_error("cannot write '%s': %s", path[k], strerror(errno));
            return EF_CLI_EXIT_OUTPUT;
        }
    }
    printf("edgeflag vectors: wrote 2 files (ef_ifaces.vh, ef_ifaces_pkg.sv) to %s\n", a->dir);
    return fflush(stdout) == 0 ? EF_CLI_EXIT_OK : EF_CLI_EXIT_OUTPUT;
}

/* Failures the input can cause map to 3; running out of memory is not the
 * input's fault as far as a script can tell, so it is grouped with 70. */
static int exit_for(ef_status st) { return st == EF_ERR_NOMEM ? EF_CLI_EXIT_INTERNAL : EF_CLI_EXIT_INPUT; }

static void on_note(void *user, const char *file, uint32_t line, uint32_t col, const char *msg)
{
    (void)user;
    fprintf(stderr, "%s:%" PRIu32 ":%" PRIu32 ": note: %s\n", file, line, col, msg);
}

static int load(const ef_cli_vectors_args *a, ef_scene *scene)
{
    ef_load_opts opts;
    ef_error err;
    ef_status st;

    memset(&opts, 0, sizeof opts);
    memset(&err, 0, sizeof err);
    opts.fit_width = a->fit_w;
    opts.fit_height = a->fit_h;
    opts.note = on_note;
    st = ef_scene_load_file(a->input, &opts, scene, &err);
    if (st != EF_OK) {
        char buf[sizeof err.file + sizeof err.msg + 64];
        if (!err.file[0] && !err.msg[0])
            snprintf(buf, sizeof buf, "%s: %s", a->input, ef_strerror(st));
        else
            ef_error_format(&err, buf, sizeof buf);
        ef_cli_error("%s", buf);
        return exit_for(st);
    }
    return -1;
}

/* Renders the scene with the trace on into c; fills info's frame facts. */
static int trace_frame(const ef_cli_vectors_args *a, const ef_scene *scene, ef_ctx *ctx, ef_image *img,
                       ef_vec_collect *c, ef_vec_info *info)
{
    ef_diag diag;
    ef_status st;

    memset(img->px, 0, img->stride * (size_t)img->height); /* composited onto transparent black */
    st = ef_trace_enable(ctx, a->ifaces, ef_vec_collect_sink, c);
    if (st == EF_OK)
        st = ef_trace_set_schedule(ctx, (ef_schedule)a->schedule);
    if (st == EF_OK)
        st = ef_trace_frame_begin(ctx);
    if (st == EF_OK)
        st = ef_scene_render(ctx, scene, a->rule, img);
    if (st == EF_OK)
        st = ef_trace_frame_end(ctx, &info->cycles);
    if (st != EF_OK) {
        ef_cli_error("%s: %s", a->input, ef_strerror(st));
        return exit_for(st);
    }
    if (c->error == EF_ERR_NOMEM) {
        ef_cli_error("%s: out of memory collecting the trace", a->input);
        return EF_CLI_EXIT_INTERNAL;
    }
    if (c->error != EF_OK || ef_vec_collect_end(c, a->ifaces) > info->cycles) {
        ef_cli_error("internal error: %s", c->error != EF_OK ? c->why : "a transfer after the frame's end");
        return EF_CLI_EXIT_INTERNAL;
    }
    ef_ctx_diag(ctx, &diag);
    if (diag.winding_overflows > 0)
        fprintf(stderr,
                "edgeflag: warning: %s: %" PRIu64 " winding counter overflow(s): the 7-bit "
                "counters wrap modulo 128 (docs/spec.md 6.4), so non-zero coverage is wrong "
                "wherever the winding number is a non-zero multiple of 128\n",
                a->input, diag.winding_overflows);
    return -1;
}

/* --dut-edges: the most EDGE commands between a SHAPE and its SHAPE_END (the
 * RTL's E_MAX counts those); over the limit: refused, nothing written. */
static int check_dut_edges(const ef_cli_vectors_args *a, const ef_vec_collect *c)
{
    size_t n = ef_vec_collect_count(c, EF_IF_CMD), k, edges = 0, most = 0, shape = 0, worst = 0;
    for (k = 0; k < n; k++) {
        ef_txn t;
        ef_vec_collect_get(c, EF_IF_CMD, k, &t);
        const uint64_t op = ef_txn_field(&t, 0);
        if (op == EF_OP_SHAPE) {
            edges = 0;
            shape++;
        } else if (op == EF_OP_EDGE && ++edges > most) {
            most = edges;
            worst = shape;
        }
    }
    if (most > (size_t)a->dut_e) {
        ef_cli_error("%s: shape %zu has %zu edges, over the DUT's %" PRId32 " (--dut-edges): refused", a->input, worst,
                     most, a->dut_e);
        return EF_CLI_EXIT_INPUT;
    }
    return -1;
}

int ef_cli_vectors(int argc, char **argv)
{
    ef_cli_vectors_args a;
    ef_scene scene;
    ef_ctx *ctx = NULL;
    ef_image img;
    ef_vec_collect *c = NULL;
    ef_vec_info info;
    ef_cli_vec_job job;
    ef_status st;
    size_t nfiles = 0;
    int rc = ef_cli_vectors_parse(argc, argv, &a);

    if (rc >= 0)
        return rc;
    if (a.rtl_headers)
        return write_rtl_headers(&a);
    memset(&scene, 0, sizeof scene);
    memset(&img, 0, sizeof img);
    if ((rc = load(&a, &scene)) >= 0)
        goto out;
    /* The DUT's limits, before anything is written (docs/vectors.md section 2). */
    if (a.dut_w && (scene.width > a.dut_w || scene.height > a.dut_h)) {
        ef_cli_error("%s: canvas %" PRId32 "x%" PRId32 " over the DUT's %" PRId32 "x%" PRId32
                     " (--dut-limits): refused",
                     a.input, scene.width, scene.height, a.dut_w, a.dut_h);
        rc = EF_CLI_EXIT_INPUT;
        goto out;
    }
    memset(&job, 0, sizeof job);
    job.dir = a.dir;
    job.formats = a.formats;
    job.ifaces = a.ifaces;
    job.force = a.force;
    job.dump = a.dump;
    /* Before the long part: an existing file (without --force) or a DIR that
     * cannot be one stops the run with nothing written. */
    if ((rc = ef_cli_vec_check_dir(&job)) >= 0)
        goto out;

    st = ef_ctx_create(&ctx, scene.width, scene.height, (int)a.samples);
    if (st == EF_OK)
        st = ef_image_create(&img, scene.width, scene.height);
    if (st == EF_OK && (c = malloc(sizeof *c)) == NULL)
        st = EF_ERR_NOMEM;
    if (st != EF_OK) {
        ef_cli_error("%s: canvas %" PRId32 "x%" PRId32 " at %d samples: %s", a.input, scene.width, scene.height,
                     (int)a.samples, ef_strerror(st));
        rc = exit_for(st);
        goto out;
    }
    if ((rc = ef_cli_apply_filter(ctx, a.input, a.filter, a.subpixel)) >= 0)
        goto out;
    ef_vec_collect_create(c, a.ifaces);
    memset(&info, 0, sizeof info);
    info.input = ef_vec_base_name(a.input);
    info.width = scene.width;
    info.height = scene.height;
    info.samples = (int)a.samples;
    info.rule = a.rule;
    info.mask = a.ifaces;
    info.dump = a.dump;
    if (!ef_vec_file_seed(a.input, &info.seed))
        info.seed = 0;
    if ((rc = trace_frame(&a, &scene, ctx, &img, c, &info)) >= 0)
        goto out;
    if (a.dut_e && (rc = check_dut_edges(&a, c)) >= 0)
        goto out;

    job.info = &info;
    job.collect = c;
    job.img = &img;
    if ((rc = ef_cli_vec_write(&job, &nfiles)) != EF_CLI_EXIT_OK)
        goto out;
    printf("edgeflag vectors: wrote %zu files (%" PRIu64 " transactions, %" PRIu64 " cycles; %" PRId32 "x%" PRId32
           ", %d samples, rule %s, seed %" PRIu64 ") to %s\n",
           nfiles, ef_vec_collect_total(c, a.ifaces), info.cycles, info.width, info.height, info.samples,
           ef_vec_rule_name(info.rule), info.seed, a.dir);
    rc = fflush(stdout) == 0 ? EF_CLI_EXIT_OK : EF_CLI_EXIT_OUTPUT;
out:
    if (c) {
        ef_vec_collect_destroy(c);
        free(c);
    }
    ef_image_destroy(&img);
    if (ctx)
        ef_ctx_destroy(ctx);
    ef_scene_destroy(&scene);
    return rc;
}
