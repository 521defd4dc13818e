/*
 * filter_opts.c - the section 3.5 options shared by `render` and `vectors`
 * (docs/spec.md section 10, docs/cli.md): --filter box|tent and
 * --subpixel none|rgb|bgr, both off (box, none) by default.
 */
#include "cli.h"

#include <string.h>

#include "ef_filter.h"

int ef_cli_filter_value(const char *cmd, int val, const char *v, int *filter, int *subpixel)
{
    if (val == EF_OPT_FILTER) {
        if (strcmp(v, "box") == 0)
            *filter = EF_FILTER_BOX;
        else if (strcmp(v, "tent") == 0)
            *filter = EF_FILTER_TENT;
        else
            return ef_cli_usage_error(cmd, "--filter must be box or tent, not '%s'", v), -1;
    } else {
        if (strcmp(v, "none") == 0)
            *subpixel = EF_SUBPIXEL_NONE;
        else if (strcmp(v, "rgb") == 0)
            *subpixel = EF_SUBPIXEL_RGB;
        else if (strcmp(v, "bgr") == 0)
            *subpixel = EF_SUBPIXEL_BGR;
        else
            return ef_cli_usage_error(cmd, "--subpixel must be none, rgb or bgr, not '%s'", v), -1;
    }
    return 1;
}

int ef_cli_apply_filter(ef_ctx *ctx, const char *input, int filter, int subpixel)
{
    if (filter == EF_FILTER_BOX && subpixel == EF_SUBPIXEL_NONE)
        return -1;
    ef_status st = ef_ctx_set_filter(ctx, (ef_filter)filter, (ef_subpixel)subpixel);
    if (st == EF_OK)
        return -1;
    if (st == EF_ERR_ARG) {
        ef_cli_error("%s: canvas %dx%d: --filter tent needs width and height of at most %d (docs/limits.md)", input,
                     (int)ef_ctx_width(ctx), (int)ef_ctx_height(ctx), EF_MAX_CANVAS - 1);
        return EF_CLI_EXIT_INPUT;
    }
    ef_cli_error("%s: %s", input, ef_strerror(st));
    return EF_CLI_EXIT_INTERNAL;
}
