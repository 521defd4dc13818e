/*
 * cmd_render.c - `edgeflag render`: scene file -> model -> image file.
 *
 * Every check that needs no file happens first, so a usage error touches
 * nothing; the input is loaded and rendered completely before the output is
 * created, and the output appears atomically (atomic_file.h).  So on any
 * failure OUTPUT is left exactly as it was.
 */
#include "cli.h"

#include "atomic_file.h"
#include "ef_scene.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *const CMD = "render";

static void usage(FILE *f)
{
    fputs("usage: edgeflag render INPUT -o OUTPUT [--samples 8|16|32] [--rule evenodd|nonzero]\n"
          "                       [--size WxH] [--filter box|tent] [--subpixel none|rgb|bgr]\n"
          "\n"
          "Rasterizes INPUT (.svg, or .scene/.txt in the peerbench scene format) with the\n"
          "bit-exact model and writes OUTPUT; its extension picks the format:\n"
          "  .png   straight-alpha RGBA (un-premultiplied as documented in docs/cli.md)\n"
          "  .pam   the model's premultiplied RGBA bytes exactly (P7, RGB_ALPHA)\n"
          "  .pgm   the alpha (coverage) channel only (P5)\n"
          "\n"
          "options:\n"
          "  -o, --output FILE  file to write (required); replaced atomically, never left\n"
          "                     half-written\n"
          "  --samples N        samples per pixel: 8, 16 (default) or 32\n"
          "  --rule RULE        fill every shape with RULE (evenodd or nonzero) instead of\n"
          "                     its own\n"
          "  --size WxH         fit the drawing into a W x H pixel canvas (1..16384 each)\n"
          "  --filter F         box (default: one-pixel box) or tent (2x2-pixel tent,\n"
          "                     docs/spec.md 10.2)\n"
          "  --subpixel S       none (default), rgb or bgr: per-channel sample offsets for\n"
          "                     striped LCD panels (docs/spec.md 10.1)\n"
          "  -h, --help         show this text\n"
          "  --                 end of options (for an INPUT starting with '-')\n"
          "\n"
          "exit codes: 0 ok, 2 usage, 3 bad input or over a limit, 4 output not written,\n"
          "            70 internal error\n",
          f);
}

typedef ef_cli_render_args render_args;

static const struct option OPTIONS[] = { { "", required_argument, NULL, EF_OPT_OUTPUT }, /* -o */
                                         { "output", required_argument, NULL, EF_OPT_OUTPUT },
                                         EF_CLI_SCENE_OPTIONS,
                                         { NULL, 0, NULL, 0 } };

static int on_option(void *p, int val, const char *v)
{
    render_args *a = p;
    if (val == EF_OPT_OUTPUT) {
        if (!*v)
            return ef_cli_usage_error(CMD, "empty output file name");
        a->output = v;
        return -1;
    }
    ef_cli_scene s = { &a->samples, &a->rule, &a->fit_w, &a->fit_h, &a->filter, &a->subpixel };
    return ef_cli_scene_value(CMD, val, v, &s) > 0 ? -1 : EF_CLI_EXIT_USAGE;
}

static int on_operand(void *p, const char *arg)
{
    render_args *a = p;
    if (a->input)
        return ef_cli_usage_error(CMD, "more than one input ('%s' and '%s')", a->input, arg);
    a->input = arg;
    return -1;
}

static int finish(void *p)
{
    render_args *a = p;
    if (!a->input)
        return ef_cli_usage_error(CMD, "no input file");
    if (!a->output)
        return ef_cli_usage_error(CMD, "no output file (-o OUTPUT)");
    struct stat st;
    if (stat(a->output, &st) == 0 && S_ISDIR(st.st_mode)) { /* docs/cli.md: a directory is exit 4 */
        ef_cli_error("cannot write '%s': %s", a->output, strerror(EISDIR));
        return EF_CLI_EXIT_OUTPUT;
    }
    a->fmt = ef_util_format_from_path(a->output);
    if (a->fmt == EF_UTIL_FMT_UNKNOWN)
        return ef_cli_usage_error(CMD, "cannot tell the format of '%s': use .png, .pam or .pgm", a->output);
    if (!ef_util_format_available(a->fmt))
        return ef_cli_usage_error(CMD,
                                  "'%s': this edgeflag was built without PNG support "
                                  "(WITH_PNG=0); use .pam or .pgm",
                                  a->output);
    return -1;
}

static const char *twice(int val) { return val == EF_OPT_OUTPUT ? "output given twice" : NULL; }

static const ef_cli_command COMMAND = { "render", OPTIONS, 1, usage, on_option, on_operand, NULL, finish, twice };

/* Returns -1 when parsing succeeded, else the exit code to return. */
int ef_cli_render_parse(int argc, char **argv, render_args *a)
{
    memset(a, 0, sizeof *a);
    a->samples = EF_CLI_SAMPLES_DEFAULT;
    a->rule = -1;
    return ef_cli_getopt(&COMMAND, argc, argv, a);
}

/* Failures the input can cause map to 3; running out of memory is not the
 * input's fault as far as a script can tell, so it is grouped with 70. */
static int exit_for(ef_status st) { return st == EF_ERR_NOMEM ? EF_CLI_EXIT_INTERNAL : EF_CLI_EXIT_INPUT; }

static void on_note(void *user, const char *file, uint32_t line, uint32_t col, const char *msg)
{
    (void)user;
    fprintf(stderr, "%s:%" PRIu32 ":%" PRIu32 ": note: %s\n", file, line, col, msg);
}

static int write_output(const render_args *a, const ef_image *img)
{
    ef_util_atomic af;
    char err[256];

    if (ef_util_atomic_open(&af, a->output) != 0) {
        ef_cli_error("cannot write '%s': %s", a->output, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    if (ef_util_write_image(af.fp, a->fmt, img, err, sizeof err) != 0) {
        int nomem = errno == ENOMEM;
        ef_util_atomic_abort(&af);
        ef_cli_error("cannot write '%s': %s", a->output, err);
        return nomem ? EF_CLI_EXIT_INTERNAL : EF_CLI_EXIT_OUTPUT;
    }
    if (ef_util_atomic_commit(&af) != 0) {
        ef_cli_error("cannot write '%s': %s", a->output, strerror(errno));
        return EF_CLI_EXIT_OUTPUT;
    }
    return EF_CLI_EXIT_OK;
}

/* OUTPUT's folder must exist before the render, not only when the file is
 * written after it (a long render would be wasted): 0, or the exit code. */
static int output_dir_ok(const char *path)
{
    const char *slash = strrchr(path, '/');
    struct stat st;
    if (!slash)
        return 0;
    size_t n = slash == path ? 1 : (size_t)(slash - path);
    char *dir = malloc(n + 1);
    if (!dir) {
        ef_cli_error("out of memory");
        return EF_CLI_EXIT_INTERNAL;
    }
    memcpy(dir, path, n);
    dir[n] = '\0';
    int rc = 0;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        ef_cli_error("cannot write '%s': %s", path, strerror(stat(dir, &st) != 0 ? errno : ENOTDIR));
        rc = EF_CLI_EXIT_OUTPUT;
    }
    free(dir);
    return rc;
}

int ef_cli_render(int argc, char **argv)
{
    render_args a;
    ef_load_opts opts;
    ef_scene scene;
    ef_error err;
    ef_ctx *ctx = NULL;
    ef_image img;
    ef_diag diag;
    ef_status st;
    int rc;

    rc = ef_cli_render_parse(argc, argv, &a);
    if (rc >= 0)
        return rc;
    if ((rc = output_dir_ok(a.output)) != 0)
        return rc;

    memset(&opts, 0, sizeof opts);
    opts.fit_width = a.fit_w;
    opts.fit_height = a.fit_h;
    opts.note = on_note;
    memset(&scene, 0, sizeof scene);
    memset(&err, 0, sizeof err);
    memset(&img, 0, sizeof img);

    st = ef_scene_load_file(a.input, &opts, &scene, &err);
    if (st != EF_OK) {
        char buf[sizeof err.file + sizeof err.msg + 64];
        if (err.status == EF_OK)
            err.status = st; /* be robust to a reader that forgot to fill err */
        if (!err.file[0] && !err.msg[0]) {
            snprintf(buf, sizeof buf, "%s: %s", a.input, ef_strerror(st));
        } else {
            ef_error_format(&err, buf, sizeof buf);
        }
        ef_cli_error("%s", buf);
        ef_scene_destroy(&scene);
        return exit_for(st);
    }

    st = ef_ctx_create(&ctx, scene.width, scene.height, (int)a.samples);
    if (st != EF_OK) {
        ef_cli_error("%s: canvas %" PRId32 "x%" PRId32 " at %d samples: %s", a.input, scene.width, scene.height,
                     (int)a.samples, ef_strerror(st));
        rc = exit_for(st);
        goto out;
    }
    if ((rc = ef_cli_apply_filter(ctx, a.input, a.filter, a.subpixel)) >= 0)
        goto out;
    rc = 0;
    st = ef_image_create(&img, scene.width, scene.height);
    if (st != EF_OK) {
        ef_cli_error("%s: image %" PRId32 "x%" PRId32 ": %s", a.input, scene.width, scene.height, ef_strerror(st));
        rc = exit_for(st);
        goto out;
    }
    /* ef_scene_render composites onto what is there: start transparent. */
    memset(img.px, 0, img.stride * (size_t)img.height);
    st = ef_scene_render(ctx, &scene, a.rule, &img);
    if (st == EF_ERR_ARG && (a.filter || a.subpixel)) {
        ef_cli_error("%s: a vertex lies too close to the coordinate limit (+-32768 px) to be shifted for "
                     "--filter/--subpixel (docs/spec.md 10.1)",
                     a.input);
        rc = EF_CLI_EXIT_INPUT;
        goto out;
    }
    if (st != EF_OK) {
        ef_cli_error("%s: %s", a.input, ef_strerror(st));
        rc = exit_for(st);
        goto out;
    }
    ef_ctx_diag(ctx, &diag);
    if (diag.winding_overflows > 0)
        fprintf(stderr,
                "edgeflag: warning: %s: %" PRIu64 " winding counter overflow(s): the 7-bit "
                "counters wrap modulo 128 (docs/spec.md 6.4), so non-zero coverage is wrong "
                "wherever the winding number is a non-zero multiple of 128\n",
                a.input, diag.winding_overflows);
    rc = write_output(&a, &img);
out:
    ef_image_destroy(&img);
    if (ctx)
        ef_ctx_destroy(ctx);
    ef_scene_destroy(&scene);
    return rc;
}
