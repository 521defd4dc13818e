/*
 * efpy.c - the few entry points the Python package (python/edgeflag) needs
 * beyond the declarations it reads directly: objects whose layout the
 * package should not know (ef_vec_collect, ef_vec_out with its hash state),
 * FILE streams (the writers and the checker print to them), and the sizes of
 * the structures it does declare, so a test can prove its declarations match
 * the headers (python/tests/test_api.py).  Linked with the vectors and
 * checker library (rtl_vectors/) and the model stream (dv/dpi/)
 * into libefpy.so (python/module.mk); docs/python.md.
 */
#define _GNU_SOURCE /* open_memstream */
#include <stdio.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "ef_check.h"
#include "ef_gen.h"
#include "ef_model_stream.h"
#include "ef_scene.h"
#include "ef_vec.h"
#include "ef_vec_read.h"

#define EFPY_API __attribute__((visibility("default")))

EFPY_API ef_vec_collect *efpy_collect_new(uint32_t mask)
{
    ef_vec_collect *c = malloc(sizeof *c);
    if (c)
        ef_vec_collect_create(c, mask);
    return c;
}

EFPY_API void efpy_collect_free(ef_vec_collect *c)
{
    if (c) {
        ef_vec_collect_destroy(c);
        free(c);
    }
}

EFPY_API int efpy_collect_error(const ef_vec_collect *c, char *why, size_t size)
{
    snprintf(why, size, "%s", c->why);
    return c->error;
}

/* The records of iface: count records of 1 + nw words (cycle, payload). */
EFPY_API const uint64_t *efpy_collect_records(const ef_vec_collect *c, int iface, size_t *count, unsigned *nw)
{
    *count = c->list[iface].count;
    *nw = c->list[iface].nw;
    return c->list[iface].rec;
}

/* Writes one file of format `format` ("hex", "bin", "vcd") to path: 0, or
 * an errno value (-1: out of memory, -2: unknown format). */
EFPY_API int efpy_write(const char *path, const char *format, const ef_vec_info *info, const ef_vec_collect *c,
                        int iface)
{
    const ef_vec_format *fm = ef_vec_format_named(format);
    ef_vec_out *o;
    FILE *fp;
    int rc, e;

    if (!fm)
        return -2;
    o = malloc(sizeof *o);
    if (!o)
        return -1;
    fp = fopen(path, "wb");
    if (!fp) {
        e = errno;
        free(o);
        return e ? e : -1;
    }
    ef_vec_out_init(o, fp, 0);
    rc = fm->write(o, info, c, iface);
    e = ef_vec_out_finish(o, NULL) != 0 ? (errno ? errno : -1) : 0;
    if (fclose(fp) != 0 && !e)
        e = errno ? errno : -1;
    free(o);
    if (rc != 0)
        return -1;
    return e;
}

/* ef_check_run with the report and status lines captured as text (free
 * both with efpy_free). */
EFPY_API int efpy_check(const ef_check_opts *o_in, ef_check_result *res, char **report, char **status)
{
    ef_check_opts o = *o_in;
    size_t n1 = 0, n2 = 0;
    FILE *r = open_memstream(report, &n1), *s = open_memstream(status, &n2);
    int rc;

    o.report = r;
    o.status = s;
    rc = ef_check_run(&o, res);
    if (r)
        fclose(r);
    if (s)
        fclose(s);
    return rc;
}

EFPY_API void efpy_free(void *p) { free(p); }

/* sizeof of the structures python/edgeflag/_ffi.py declares, by name; 0 for
 * a name not listed. */
EFPY_API size_t efpy_sizeof(const char *name)
{
#define S(T) \
    if (strcmp(name, #T) == 0) \
    return sizeof(T)
    S(ef_point);
    S(ef_polygon);
    S(ef_rgba8);
    S(ef_diag);
    S(ef_image);
    S(ef_shape);
    S(ef_scene);
    S(ef_error);
    S(ef_load_opts);
    S(ef_field_desc);
    S(ef_iface_desc);
    S(ef_txn);
    S(ef_vec_info);
    S(ef_vec_read_error);
    S(ef_vec_seq);
    S(ef_vec_dump);
    S(ef_check_opts);
    S(ef_check_result);
    S(ef_mstream_params);
    S(ef_gen_config);
    S(ef_gen_expect);
    S(ef_gen_case);
    S(ef_gen_text);
#undef S
    return 0;
}
