/*
 * vec_load.c - reads EXPECTED and ACTUAL with the vector readers
 * (rtl_vectors/ef_vec_read.h) in the order and with the interface
 * expectations `edgeflag check` uses, and prints the outcome as one
 * tab-separated line, like tests/tools/load_check does for scenes:
 *
 *   CLASS  WHERE  MESSAGE
 *
 * CLASS is "ok" or the first error's class (ef_status: syntax, range, limit,
 * unsupported, io, nomem); WHERE is LINE:COL for a text error, "-" for an
 * error about the whole file or a binary stream's header/record (whose
 * place is in the message).  tests/bad/run.sh uses it for the catalogue's
 * `check` entries: the class and place come from the library, not from the
 * command's wording.
 *
 *   vec_load EXPECTED ACTUAL      (two files, or EXPECTED a directory: its manifest)
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ef_vec_read.h"

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

static int report(ef_status st, const ef_vec_read_error *e)
{
    if (e->at == EF_VEC_AT_LINE)
        printf("%s\t%" PRIu64 ":%" PRIu64 "\t%s\n", class_of(st), e->line, e->col, e->msg);
    else
        printf("%s\t-\t%s\n", class_of(st), e->msg);
    return 0;
}

int main(int argc, char **argv)
{
    ef_vec_dump e, a;
    ef_vec_read_error err;
    struct stat sb;
    ef_status st;

    if (argc != 3) {
        fprintf(stderr, "usage: vec_load EXPECTED ACTUAL\n");
        return 2;
    }
    memset(&err, 0, sizeof err);
    if (stat(argv[1], &sb) == 0 && S_ISDIR(sb.st_mode)) {
        ef_vec_manifest m;
        size_t n = strlen(argv[1]) + sizeof "/manifest.json";
        char *p = malloc(n);
        if (!p)
            return 2;
        snprintf(p, n, "%s/manifest.json", argv[1]);
        st = ef_vec_read_manifest_path(p, NULL, &m, &err);
        free(p);
        if (st != EF_OK)
            return report(st, &err);
        ef_vec_manifest_destroy(&m);
        printf("ok\t-\tmanifest\n");
        return 0;
    }
    st = ef_vec_read_path(argv[1], NULL, -1, ef_vec_iface_from_name(argv[1]), &e, &err);
    if (st != EF_OK)
        return report(st, &err);
    int want = -1;
    for (int i = 0; e.format == EF_VEC_FMT_HEX && i < EF_IF_COUNT; i++)
        if (e.mask >> i & 1u)
            want = i;
    ef_vec_dump_destroy(&e);
    st = ef_vec_read_path(argv[2], NULL, want, want >= 0 ? want : ef_vec_iface_from_name(argv[2]), &a, &err);
    if (st != EF_OK)
        return report(st, &err);
    ef_vec_dump_destroy(&a);
    printf("ok\t-\tboth read\n");
    return 0;
}
