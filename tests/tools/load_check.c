/*
 * load_check.c - loads an input with the library's readers, exactly as
 * `edgeflag render` does, and prints the outcome as one tab-separated line:
 *
 *   CLASS  LINE:COL  MESSAGE
 *
 * CLASS is "ok" or the error's class (ef_status: syntax, range, limit,
 * unsupported, io, arg, nomem); LINE:COL is "-" when the error concerns the
 * whole file.  tests/bad/run.sh uses it to check each catalogue entry's exact
 * error class, which the command's message does not spell out.
 *
 *   load_check INPUT [--size WxH]
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "ef_scene.h"

static const char *class_of(ef_status st)
{
    switch (st) {
    case EF_OK: return "ok";
    case EF_ERR_NOMEM: return "nomem";
    case EF_ERR_ARG: return "arg";
    case EF_ERR_LIMIT: return "limit";
    case EF_ERR_SYNTAX: return "syntax";
    case EF_ERR_RANGE: return "range";
    case EF_ERR_IO: return "io";
    case EF_ERR_UNSUPPORTED: return "unsupported";
    }
    return "unknown";
}

int main(int argc, char **argv)
{
    ef_load_opts o;
    ef_scene s;
    ef_error e;
    const char *in = NULL;

    memset(&o, 0, sizeof o);
    memset(&e, 0, sizeof e);
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--size") == 0 && i + 1 < argc) {
            if (sscanf(argv[++i], "%" SCNd32 "x%" SCNd32, &o.fit_width, &o.fit_height) != 2)
                return 2;
        } else if (!in) {
            in = argv[i];
        } else {
            return 2;
        }
    }
    if (!in) {
        fprintf(stderr, "usage: load_check INPUT [--size WxH]\n");
        return 2;
    }
    ef_status st = ef_scene_load_file(in, &o, &s, &e);
    if (st == EF_OK) {
        printf("ok\t-\t%" PRIu32 " shapes, %" PRIu32 " points\n", s.nshapes, s.npoints);
        ef_scene_destroy(&s);
    } else if (e.line && e.col) {
        printf("%s\t%" PRIu32 ":%" PRIu32 "\t%s\n", class_of(st), e.line, e.col, e.msg);
    } else {
        printf("%s\t-\t%s\n", class_of(st), e.msg);
    }
    return 0;
}
