/*
 * test_trace.c - the timing model (model/trace*.c, docs/microarch.md 4):
 * - tracing never changes a result: every shared SVG (fitted to 160x120) and
 *   a set of edge cases, at 8/16/32 samples under each shape's rule and both
 *   overrides, render to the same bytes and diagnostics with the trace on as
 *   with it off (the traced path is a second, plain implementation of the
 *   plotter, fillers and compositing, so this also cross-checks those);
 * - the transactions obey the schedule's invariants: at most one transfer
 *   per interface per cycle, in cycle order; a shape's commands back to back;
 *   DEC and SETUP latencies; `last` on exactly each row's final plot; one pix
 *   per span pixel, L_COV after the span at the earliest, with the span's
 *   alpha; every transfer inside the frame's length;
 * - the overlap schedule (docs/microarch.md section 6) gives the same
 *   transactions in the same order per interface (a hash of each interface's
 *   payloads, cycles left out), the same image, the same invariants, and a
 *   frame no longer than the reference one.
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "ef_filter.h"
#include "ef_scene.h"
#include "ef_trace.h"

typedef struct stats {
    uint64_t n[EF_IF_COUNT];
    uint64_t last_cycle[EF_IF_COUNT];
    uint64_t max_cycle;
    int ordered; /* every interface strictly increasing in cycle */
    uint64_t span_pixels, pix_left;
    uint64_t span_cycle;
    uint32_t span_x, span_y, span_mask, next_pix_x;
    int pix_ok;
    uint64_t edge_cmd_cycle, edge_ok;
    uint64_t plots_since_last;
    int samples;
    uint64_t hash[EF_IF_COUNT]; /* FNV-1a of the payloads in order, cycles left out */
} stats;

static void sink(void *user, const ef_txn *t)
{
    stats *s = user;
    const int i = t->iface;
    if (s->n[i] && t->cycle <= s->last_cycle[i])
        s->ordered = 0;
    s->n[i]++;
    s->last_cycle[i] = t->cycle;
    for (int w = 0; w < EF_TXN_WORDS; w++)
        for (int b = 0; b < 64; b += 8)
            s->hash[i] = (s->hash[i] ^ ((t->w[w] >> b) & 0xFFu)) * UINT64_C(0x100000001B3);
    if (t->cycle > s->max_cycle)
        s->max_cycle = t->cycle;
    switch (i) {
    case EF_IF_CMD:
        if (ef_txn_field(t, 0) == EF_OP_EDGE)
            s->edge_cmd_cycle = t->cycle;
        break;
    case EF_IF_SEG:
        if (ef_txn_field(t, 0) == 0 && t->cycle != s->edge_cmd_cycle + EF_L_DEC)
            s->edge_ok = 0;
        break;
    case EF_IF_PLOT:
        s->plots_since_last++;
        if (ef_txn_field(t, 0))
            s->plots_since_last = 0;
        break;
    case EF_IF_SPAN:
        if (s->pix_left)
            s->pix_ok = 0; /* COV accepted a span before finishing the last */
        s->span_y = (uint32_t)ef_txn_field(t, 0);
        s->span_x = s->next_pix_x = (uint32_t)ef_txn_field(t, 1);
        s->pix_left = ef_txn_field(t, 2);
        s->span_pixels += s->pix_left;
        s->span_mask = (uint32_t)ef_txn_field(t, 3);
        s->span_cycle = t->cycle;
        break;
    case EF_IF_PIX:
        if (!s->pix_left || ef_txn_field(t, 0) != s->span_y || ef_txn_field(t, 1) != s->next_pix_x ||
            t->cycle < s->span_cycle + EF_L_COV || ef_txn_field(t, 2) != ef_coverage_alpha(s->span_mask, s->samples))
            s->pix_ok = 0;
        s->pix_left--;
        s->next_pix_x++;
        break;
    default: break;
    }
}

typedef struct frame {
    uint8_t *px;
    size_t bytes;
    ef_diag diag;
    uint64_t cycles;
} frame;

static ef_schedule schedule; /* of the traced renders */

static void render(const ef_scene *sc, int samples, int rule, stats *st, frame *out)
{
    ef_ctx *ctx;
    assert_int_equal(ef_ctx_create(&ctx, sc->width, sc->height, samples), EF_OK);
    ef_image img;
    assert_int_equal(ef_image_create(&img, sc->width, sc->height), EF_OK);
    if (st) {
        memset(st, 0, sizeof *st);
        st->ordered = st->pix_ok = 1;
        st->edge_ok = 1;
        st->samples = samples;
        assert_int_equal(ef_trace_enable(ctx, EF_IF_ALL, sink, st), EF_OK);
        assert_int_equal(ef_trace_set_schedule(ctx, schedule), EF_OK);
        assert_int_equal(ef_trace_frame_begin(ctx), EF_OK);
    }
    assert_int_equal(ef_scene_render(ctx, sc, rule, &img), EF_OK);
    out->cycles = 0;
    if (st)
        assert_int_equal(ef_trace_frame_end(ctx, &out->cycles), EF_OK);
    ef_ctx_diag(ctx, &out->diag);
    out->px = img.px;
    out->bytes = img.stride * (size_t)img.height;
    ef_ctx_destroy(ctx);
}

/* Renders sc both ways and checks equality and the invariants. */
static void check_scene(const char *name, const ef_scene *sc)
{
    static const int rules[3] = { -1, EF_RULE_NONZERO, EF_RULE_EVENODD };
    static stats st, ref;
    for (int si = 0; si < 3; si++) {
        const int samples = 8 << si;
        for (int ri = 0; ri < 3; ri++)
            for (int sched = 0; sched < 2; sched++) {
                frame plain, traced;
                schedule = sched ? EF_SCHEDULE_OVERLAP : EF_SCHEDULE_REFERENCE;
                render(sc, samples, rules[ri], NULL, &plain);
                render(sc, samples, rules[ri], &st, &traced);
                if (memcmp(plain.px, traced.px, plain.bytes) != 0 ||
                    memcmp(&plain.diag, &traced.diag, sizeof plain.diag) != 0)
                    fail_msg("%s at %d samples, rule %d: the traced render differs", name, samples, rules[ri]);
                assert_true(st.ordered);
                assert_true(st.pix_ok);
                assert_true(st.edge_ok);
                assert_int_equal(st.pix_left, 0);
                assert_int_equal(st.span_pixels, st.n[EF_IF_PIX]);
                assert_int_equal(st.plots_since_last, 0); /* the final plot carried `last` */
                assert_true(traced.cycles == st.max_cycle + 1);
                /* FRAME + per shape SHAPE, EDGEs, SHAPE_END + FRAME_END */
                assert_int_equal(st.n[EF_IF_CMD], 2 + 2 * (uint64_t)sc->nshapes + traced.diag.edges_in);
                assert_int_equal(st.n[EF_IF_SEG], sc->nshapes + traced.diag.edges_in);
                assert_int_equal(st.n[EF_IF_ET_WR], sc->nshapes + traced.diag.edges_in - traced.diag.edges_dropped);
                if (!sched) {
                    ref = st;
                    ref.max_cycle = traced.cycles;
                } else {
                    for (int i = 0; i < EF_IF_COUNT; i++)
                        if (st.n[i] != ref.n[i] || st.hash[i] != ref.hash[i])
                            fail_msg("%s at %d samples, rule %d: interface %d differs under the overlap schedule", name,
                                     samples, rules[ri], i);
                    if (traced.cycles > ref.max_cycle)
                        fail_msg("%s at %d samples, rule %d: overlap frame %llu cycles, reference %llu", name, samples,
                                 rules[ri], (unsigned long long)traced.cycles, (unsigned long long)ref.max_cycle);
                }
                free(plain.px);
                free(traced.px);
            }
    }
}

static void shared_svgs(void **state)
{
    (void)state;
    const char *svg = getenv("EF_SVG");
    char dir[1024];
    snprintf(dir, sizeof dir, "%s", svg && *svg ? svg : "tests/data/svg");
    DIR *d = opendir(dir);
    if (!d)
        fail_msg("SVG folder %s not found (EF_SVG)", dir);
    struct dirent *e;
    int n = 0;
    while ((e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 5 || strcmp(e->d_name + len - 4, ".svg") != 0)
            continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        ef_load_opts opts = { .fit_width = 160, .fit_height = 120 };
        ef_scene sc;
        ef_error err;
        assert_int_equal(ef_scene_load_file(path, &opts, &sc, &err), EF_OK);
        check_scene(e->d_name, &sc);
        ef_scene_destroy(&sc);
        n++;
    }
    closedir(d);
    assert_true(n >= 20);
}

#define PX(v) ((int32_t)((v)*256))

static void add(ef_scene *sc, ef_rule rule, ef_rgba8 c, const ef_point *p, uint32_t n)
{
    assert_int_equal(ef_scene_begin_shape(sc, rule, c), EF_OK);
    assert_int_equal(ef_scene_add_contour(sc, p, n), EF_OK);
}

/* Clamping at both sides, clipping at top and bottom, winding counters past
 * 127, horizontal and zero-length edges, a translucent shape over another,
 * an empty shape and one entirely outside. */
static void edge_cases(void **state)
{
    (void)state;
    ef_scene sc;
    ef_scene_create(&sc, 40, 24);
    const ef_point wide[4] = { { PX(-30), PX(-5) }, { PX(70.3), PX(2.2) }, { PX(65), PX(40) }, { PX(-12), PX(20.7) } };
    add(&sc, EF_RULE_NONZERO, (ef_rgba8){ 200, 30, 40, 255 }, wide, 4);
    const ef_point tri[3] = { { PX(3.1), PX(3.3) }, { PX(30.9), PX(8.45) }, { PX(7), PX(21.2) } };
    assert_int_equal(ef_scene_begin_shape(&sc, EF_RULE_NONZERO, (ef_rgba8){ 10, 200, 90, 128 }), EF_OK);
    for (int k = 0; k < 140; k++) /* winding 140 */
        assert_int_equal(ef_scene_add_contour(&sc, tri, 3), EF_OK);
    const ef_point flat[4] = { { PX(1), PX(5) }, { PX(9), PX(5) }, { PX(9), PX(5) }, { PX(1), PX(5) } };
    add(&sc, EF_RULE_EVENODD, (ef_rgba8){ 0, 0, 255, 255 }, flat, 4);
    const ef_point out[3] = { { PX(100), PX(100) }, { PX(120), PX(100) }, { PX(110), PX(130) } };
    add(&sc, EF_RULE_EVENODD, (ef_rgba8){ 0, 0, 255, 255 }, out, 3);
    assert_int_equal(ef_scene_begin_shape(&sc, EF_RULE_EVENODD, (ef_rgba8){ 1, 2, 3, 4 }), EF_OK);
    const ef_point right[4] = { { PX(38.5), PX(1) }, { PX(40), PX(1) }, { PX(40), PX(23) }, { PX(38.5), PX(23) } };
    add(&sc, EF_RULE_EVENODD, (ef_rgba8){ 90, 90, 90, 200 }, right, 4);
    check_scene("edge cases", &sc);
    ef_scene_destroy(&sc);
}

/* Off means off: a context with tracing disabled again emits nothing. */
static void disable(void **state)
{
    (void)state;
    ef_ctx *ctx;
    stats st;
    memset(&st, 0, sizeof st);
    assert_int_equal(ef_ctx_create(&ctx, 8, 8, 8), EF_OK);
    assert_int_equal(ef_trace_enable(ctx, EF_IF_ALL, sink, &st), EF_OK);
    assert_int_equal(ef_trace_enable(ctx, 1u << EF_IF_COUNT, sink, &st), EF_ERR_ARG);
    assert_int_equal(ef_trace_enable(ctx, 0, NULL, NULL), EF_OK);
    assert_int_equal(ef_trace_frame_begin(ctx), EF_ERR_ARG);
    ef_image img;
    assert_int_equal(ef_image_create(&img, 8, 8), EF_OK);
    const ef_point p[3] = { { 0, 0 }, { PX(8), 0 }, { 0, PX(8) } };
    const uint32_t start[2] = { 0, 3 };
    ef_polygon poly = { p, start, 1 };
    assert_int_equal(ef_fill(ctx, &img, &poly, EF_RULE_NONZERO, (ef_rgba8){ 1, 2, 3, 255 }), EF_OK);
    for (int i = 0; i < EF_IF_COUNT; i++)
        assert_int_equal(st.n[i], 0);
    ef_image_destroy(&img);
    ef_ctx_destroy(ctx);
}

/* The schedule's setter refuses what it must; the overlap schedule refuses
 * the spec 10 options (docs/microarch.md section 6). */
static void schedule_api(void **state)
{
    (void)state;
    ef_ctx *ctx;
    stats st;
    memset(&st, 0, sizeof st);
    assert_int_equal(ef_ctx_create(&ctx, 8, 8, 8), EF_OK);
    assert_int_equal(ef_trace_set_schedule(ctx, EF_SCHEDULE_OVERLAP), EF_ERR_ARG); /* tracing off */
    assert_int_equal(ef_trace_enable(ctx, EF_IF_ALL, sink, &st), EF_OK);
    assert_int_equal(ef_trace_set_schedule(ctx, (ef_schedule)2), EF_ERR_ARG);
    assert_int_equal(ef_trace_set_schedule(ctx, EF_SCHEDULE_OVERLAP), EF_OK);
    assert_int_equal(ef_ctx_set_filter(ctx, EF_FILTER_TENT, EF_SUBPIXEL_NONE), EF_OK);
    ef_image img;
    assert_int_equal(ef_image_create(&img, 8, 8), EF_OK);
    const ef_point p[3] = { { 0, 0 }, { PX(8), 0 }, { 0, PX(8) } };
    const uint32_t start[2] = { 0, 3 };
    ef_polygon poly = { p, start, 1 };
    assert_int_equal(ef_fill(ctx, &img, &poly, EF_RULE_NONZERO, (ef_rgba8){ 1, 2, 3, 255 }), EF_ERR_UNSUPPORTED);
    ef_image_destroy(&img);
    ef_ctx_destroy(ctx);
}

/* Field packing round trip at every field of every interface. */
static void fields(void **state)
{
    (void)state;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        unsigned sum = 0;
        for (unsigned k = 0; k < d->nfields; k++)
            sum += d->field[k].width;
        assert_int_equal(sum, d->width);
        assert_int_equal(ef_iface_find(d->name), i);
        ef_txn t = { .iface = (uint8_t)i };
        for (unsigned k = 0; k < d->nfields; k++)
            ef_txn_set_field(&t, k, UINT64_C(0x9E3779B97F4A7C15) >> k);
        for (unsigned k = 0; k < d->nfields; k++) {
            const unsigned w = d->field[k].width;
            const uint64_t want = (UINT64_C(0x9E3779B97F4A7C15) >> k) & ((UINT64_C(1) << w) - 1);
            assert_int_equal(ef_txn_field(&t, k), want);
            if (d->field[k].is_signed && (want >> (w - 1)))
                assert_true(ef_txn_field_value(&t, k) < 0);
        }
    }
    assert_null(ef_iface_get(EF_IF_COUNT));
    assert_int_equal(ef_iface_find("nope"), -1);
    assert_int_equal(ef_iface_find("edge"), EF_IF_SEG); /* the old name, still read */
}

/* Every interface and field name must be usable as a wire's name in a
 * testbench: none is a keyword of Verilog-2005 (IEEE 1364-2005 annex B) or
 * of SystemVerilog (IEEE 1800-2017 annex B, the words it adds that are
 * short enough to be field names).  `edge` was one, hence `seg` and `eid`. */
static void names_not_keywords(void **state)
{
    /* clang-format off */
    static const char *const kw[] = {
        "always", "and", "assign", "automatic", "begin", "buf", "bufif0", "bufif1", "case", "casex", "casez",
        "cell", "cmos", "config", "deassign", "default", "defparam", "design", "disable", "edge", "else", "end",
        "endcase", "endconfig", "endfunction", "endgenerate", "endmodule", "endprimitive", "endspecify",
        "endtable", "endtask", "event", "for", "force", "forever", "fork", "function", "generate", "genvar",
        "highz0", "highz1", "if", "ifnone", "incdir", "include", "initial", "inout", "input", "instance",
        "integer", "join", "large", "liblist", "library", "localparam", "macromodule", "medium", "module",
        "nand", "negedge", "nmos", "nor", "noshowcancelled", "not", "notif0", "notif1", "or", "output",
        "parameter", "pmos", "posedge", "primitive", "pull0", "pull1", "pulldown", "pullup", "rcmos", "real",
        "realtime", "reg", "release", "repeat", "rnmos", "rpmos", "rtran", "rtranif0", "rtranif1", "scalared",
        "signed", "small", "specify", "specparam", "strong0", "strong1", "supply0", "supply1", "table", "task",
        "time", "tran", "tranif0", "tranif1", "tri", "tri0", "tri1", "triand", "trior", "trireg", "unsigned",
        "use", "uwire", "vectored", "wait", "wand", "weak0", "weak1", "while", "wire", "wor", "xnor", "xor",
        /* SystemVerilog */
        "alias", "bind", "bins", "bit", "break", "byte", "chandle", "class", "const", "context", "cover",
        "dist", "do", "enum", "export", "extends", "extern", "final", "first_match", "global", "iff", "import",
        "inside", "int", "interface", "let", "logic", "longint", "matches", "modport", "new", "null",
        "package", "packed", "priority", "program", "property", "protected", "pure", "rand", "randc", "ref",
        "restrict", "return", "s_always", "sequence", "shortint", "soft", "solve", "static", "string",
        "struct", "super", "this", "throughout", "type", "typedef", "union", "unique", "var", "virtual",
        "void", "wait_order", "weak", "with", "within",
    };
    /* clang-format on */
    (void)state;
    for (int i = 0; i < EF_IF_COUNT; i++) {
        const ef_iface_desc *d = ef_iface_get(i);
        for (size_t k = 0; k < sizeof kw / sizeof kw[0]; k++) {
            if (strcmp(d->name, kw[k]) == 0)
                fail_msg("interface '%s' is a Verilog keyword", d->name);
            for (unsigned f = 0; f < d->nfields; f++)
                if (strcmp(d->field[f].name, kw[k]) == 0)
                    fail_msg("field '%s' of '%s' is a Verilog keyword", d->field[f].name, d->name);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fields),       cmocka_unit_test(names_not_keywords), cmocka_unit_test(disable),
        cmocka_unit_test(schedule_api), cmocka_unit_test(edge_cases),         cmocka_unit_test(shared_svgs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
