"""The C declarations the package uses, copied by hand from the public headers (include/edgeflag/)
and from rtl_vectors/ (ef_vec.h, ef_vec_read.h, ef_check.h, ef_gen.h, dpi/ef_model_stream.h).
cffi in ABI mode reads them; tests/test_api.py compares every structure's size with the C
compiler's (efpy_sizeof), so a header change that this file misses fails a test, not a user."""

import os
import pathlib

import cffi

CDEF = r"""
typedef enum ef_status { EF_OK = 0, EF_ERR_NOMEM = -1, EF_ERR_ARG = -2, EF_ERR_LIMIT = -3, EF_ERR_SYNTAX = -4,
    EF_ERR_RANGE = -5, EF_ERR_IO = -6, EF_ERR_UNSUPPORTED = -7 } ef_status;
const char *ef_strerror(ef_status s);
typedef enum ef_rule { EF_RULE_NONZERO = 0, EF_RULE_EVENODD = 1 } ef_rule;
typedef uint32_t ef_mask;
typedef struct ef_point { int32_t x, y; } ef_point;
typedef struct ef_polygon { const ef_point *pts; const uint32_t *start; uint32_t ncontours; } ef_polygon;
typedef struct ef_rgba8 { uint8_t r, g, b, a; } ef_rgba8;
typedef struct ef_ctx ef_ctx;
ef_status ef_ctx_create(ef_ctx **out, int32_t width, int32_t height, int samples);
void ef_ctx_destroy(ef_ctx *ctx);
typedef void (*ef_span_fn)(void *user, int32_t y, int32_t x, int32_t len, ef_mask mask);
ef_status ef_rasterize(ef_ctx *ctx, const ef_polygon *poly, ef_rule rule, ef_span_fn span, void *user);
typedef struct ef_diag { uint64_t edges_in; uint64_t edges_dropped; uint64_t winding_overflows; } ef_diag;
void ef_ctx_diag(const ef_ctx *ctx, ef_diag *out);
const uint8_t *ef_pattern(int samples);
uint8_t ef_coverage_alpha(ef_mask mask, int samples);
typedef struct ef_image { uint8_t *px; int32_t width, height; size_t stride; } ef_image;
ef_status ef_image_create(ef_image *img, int32_t width, int32_t height);
void ef_image_destroy(ef_image *img);
ef_status ef_fill(ef_ctx *ctx, ef_image *img, const ef_polygon *poly, ef_rule rule, ef_rgba8 color);

typedef struct ef_shape { ef_rule rule; ef_rgba8 color; uint32_t first_contour; uint32_t ncontours; } ef_shape;
typedef struct ef_scene {
    int32_t width, height; ef_shape *shapes; uint32_t nshapes;
    uint32_t *start; uint32_t ncontours; ef_point *points; uint32_t npoints;
    uint32_t notes;
} ef_scene;
void ef_scene_create(ef_scene *s, int32_t width, int32_t height);
void ef_scene_destroy(ef_scene *s);
ef_status ef_scene_begin_shape(ef_scene *s, ef_rule rule, ef_rgba8 color);
ef_status ef_scene_add_contour(ef_scene *s, const ef_point *pts, uint32_t n);
ef_polygon ef_scene_polygon(const ef_scene *s, uint32_t i);
ef_status ef_scene_render(ef_ctx *ctx, const ef_scene *s, int rule_override, ef_image *img);

typedef struct ef_error { ef_status status; char file[256]; uint32_t line, col; char msg[256]; } ef_error;
void ef_error_format(const ef_error *e, char *buf, size_t size);
typedef void (*ef_note_fn)(void *user, const char *file, uint32_t line, uint32_t col, const char *msg);
typedef struct ef_load_opts { int32_t fit_width, fit_height; ef_note_fn note; void *note_user; } ef_load_opts;
ef_status ef_scene_load_file(const char *path, const ef_load_opts *opts, ef_scene *out, ef_error *err);
ef_status ef_scene_load_svg(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                            ef_scene *out, ef_error *err);
ef_status ef_scene_load_text(const char *name, const char *data, size_t len, const ef_load_opts *opts,
                             ef_scene *out, ef_error *err);

typedef struct ef_field_desc { const char *name; uint8_t width; uint8_t is_signed; } ef_field_desc;
typedef struct ef_iface_desc {
    const char *name; const char *from, *to; uint16_t width; uint8_t nfields; ef_field_desc field[10];
} ef_iface_desc;
const ef_iface_desc *ef_iface_get(int iface);
int ef_iface_find(const char *name);
typedef struct ef_txn { uint64_t cycle; uint64_t w[4]; uint8_t iface; } ef_txn;
uint64_t ef_txn_field(const ef_txn *t, unsigned k);
int64_t ef_txn_field_value(const ef_txn *t, unsigned k);
void ef_txn_set_field(ef_txn *t, unsigned k, uint64_t v);
typedef void (*ef_txn_fn)(void *user, const ef_txn *t);
ef_status ef_trace_enable(ef_ctx *ctx, uint32_t iface_mask, ef_txn_fn sink, void *user);
ef_status ef_trace_frame_begin(ef_ctx *ctx);
ef_status ef_trace_frame_end(ef_ctx *ctx, uint64_t *cycles);
"""

CDEF_VEC = r"""
typedef struct ef_vec_collect ef_vec_collect;
void ef_vec_collect_sink(void *user, const ef_txn *t);
typedef struct ef_vec_info {
    const char *input; int32_t width, height; int samples; int rule; uint64_t seed; uint64_t cycles;
    uint32_t mask; int dump;
} ef_vec_info;
ef_vec_collect *efpy_collect_new(uint32_t mask);
void efpy_collect_free(ef_vec_collect *c);
int efpy_collect_error(const ef_vec_collect *c, char *why, size_t size);
const uint64_t *efpy_collect_records(const ef_vec_collect *c, int iface, size_t *count, unsigned *nw);
int efpy_write(const char *path, const char *format, const ef_vec_info *info, const ef_vec_collect *c, int iface);
size_t efpy_sizeof(const char *name);
void efpy_free(void *p);

typedef enum ef_vec_at { EF_VEC_AT_FILE = 0, EF_VEC_AT_LINE, EF_VEC_AT_HEADER, EF_VEC_AT_RECORD,
    EF_VEC_AT_END } ef_vec_at;
typedef struct ef_vec_read_error {
    ef_status status; ef_vec_at at; char file[512]; uint64_t line, col; uint64_t record; uint64_t offset;
    char msg[256];
} ef_vec_read_error;
void ef_vec_read_error_format(const ef_vec_read_error *e, char *buf, size_t size);
typedef struct ef_vec_seq {
    size_t n, cap; unsigned nw; uint64_t *cycle; uint64_t *pay; uint64_t *loc; uint64_t *off;
} ef_vec_seq;
typedef struct ef_vec_dump {
    int format; uint32_t mask; ef_vec_seq seq[7]; int has_header; int32_t width, height; int samples; int rule;
    uint64_t seed;
} ef_vec_dump;
void ef_vec_dump_destroy(ef_vec_dump *d);
ef_status ef_vec_read_path(const char *path, const char *name, int want, int hint, ef_vec_dump *out,
                           ef_vec_read_error *err);
uint32_t ef_vec_read_crc32(uint32_t crc, const void *data, size_t len);

typedef struct _IO_FILE FILE;
typedef struct ef_check_opts {
    const char *expected, *actual; int32_t errors; int cycles; uint32_t only; uint32_t allow_missing;
    const char *name; int keep_marks; FILE *report; FILE *status;
} ef_check_opts;
void ef_check_opts_defaults(ef_check_opts *o);
typedef struct ef_check_run_state ef_check_run_state;
typedef struct ef_check_result {
    uint64_t mismatches; uint64_t reported; uint64_t compared; uint64_t transactions; uint64_t missing;
    uint64_t marks; ef_check_run_state *run;
} ef_check_result;
void ef_check_result_destroy(ef_check_result *res);
int efpy_check(const ef_check_opts *o, ef_check_result *res, char **report, char **status);

typedef struct ef_mstream_params {
    int samples; int32_t width_max; int32_t height_max; uint32_t edges_max; int rule; uint32_t ifaces;
} ef_mstream_params;
typedef struct ef_mstream ef_mstream;
const char *ef_mstream_strerror(int status);
void ef_mstream_params_default(ef_mstream_params *p);
int ef_mstream_create(ef_mstream **out, const ef_mstream_params *p);
void ef_mstream_destroy(ef_mstream *m);
int ef_mstream_cmd(ef_mstream *m, const uint64_t word[2]);
int ef_mstream_cmd_fields(ef_mstream *m, unsigned op, int32_t a, int32_t b, int32_t c, int32_t d);
int ef_mstream_pop(ef_mstream *m, int iface, ef_txn *out);
int ef_mstream_peek(const ef_mstream *m, int iface, ef_txn *out);
size_t ef_mstream_pending(const ef_mstream *m, int iface);
int ef_mstream_expect(ef_mstream *m, const ef_txn *actual, int check_cycle);
int ef_mstream_expect_done(ef_mstream *m, int iface);
const char *ef_mstream_message(const ef_mstream *m);
uint64_t ef_mstream_commands(const ef_mstream *m);
int ef_mstream_frame_cycles(const ef_mstream *m, uint64_t *cycles);
const ef_image *ef_mstream_frame(const ef_mstream *m);
int ef_mstream_format(const ef_txn *t, const ef_txn *other, char *buf, size_t size);

typedef enum ef_gen_category { EF_GEN_CAT_SAMPLE_GRID = 0, EF_GEN_NCATEGORIES = 16 } ef_gen_category;
const char *ef_gen_category_name(ef_gen_category c);
typedef enum ef_gen_expect_kind { EF_GEN_EXPECT_ANY = 0, EF_GEN_EXPECT_EMPTY, EF_GEN_EXPECT_FULL,
    EF_GEN_EXPECT_PROBE } ef_gen_expect_kind;
typedef struct ef_gen_expect { ef_gen_expect_kind kind; int32_t x, y; uint8_t alpha; int8_t overflow; } ef_gen_expect;
typedef struct ef_gen_config { uint64_t seed; int level; int grid; int rules_swapped; uint32_t nrandom; } ef_gen_config;
ef_status ef_gen_config_defaults(ef_gen_config *c, int level);
uint32_t ef_gen_total(const ef_gen_config *c);
typedef struct ef_gen_case {
    uint32_t number; uint32_t total; int directed; uint32_t index; ef_gen_category category; const char *name;
    int grid; int rules_swapped; uint64_t case_seed; ef_gen_expect expect; char desc[768]; ef_scene scene;
    char fit_note[400];
} ef_gen_case;
ef_status ef_gen_build(const ef_gen_config *c, uint32_t k, ef_gen_case *out);
void ef_gen_case_destroy(ef_gen_case *gc);
typedef struct ef_gen_text { char *data; size_t len, cap; } ef_gen_text;
void ef_gen_text_destroy(ef_gen_text *t);
ef_status ef_gen_format(const ef_gen_config *c, const ef_gen_case *gc, ef_gen_text *t);
"""

ffi = cffi.FFI()
ffi.cdef(CDEF)
ffi.cdef(CDEF_VEC)


def _candidates(name):
    env = os.environ.get("EDGEFLAG_LIBDIR")
    if env:
        yield pathlib.Path(env) / name
    here = pathlib.Path(__file__).resolve().parent
    yield here / "_native" / name            # an installed package (pip install ./python)
    yield here.parent.parent / "build" / name  # the source tree: python/edgeflag -> build/


def _open(name):
    tried = []
    for p in _candidates(name):
        tried.append(str(p))
        if p.is_file():
            return ffi.dlopen(str(p))
    raise ImportError(f"edgeflag: {name} not found (tried {', '.join(tried)}); run `make python` in the "
                      "repository or set EDGEFLAG_LIBDIR")


lib = _open("libedgeflag.so")
vec = _open("libefpy.so")
