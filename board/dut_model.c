/*
 * dut_model.c - the C model's timing model as the DUT behind the board
 * engine: the command stream of docs/microarch.md 3.1 goes in, and at each
 * FRAME_END the frame's transactions of the requested interfaces come out as
 * vectors.bin records in global cycle order (by cycle, then interface), the
 * order `edgeflag vectors` writes them, so a healthy board's results equal
 * the expected vectors.bin record for record.
 *
 * The DUT rebuilds each shape from its EDGE commands: a contour is a chain of
 * edges, each starting where the previous one ended, and it closes at the
 * edge that returns to its first point.  It then renders the shape with the
 * traced ef_fill and checks that the model's own `cmd` trace equals the
 * commands it received, word for word: a stream the reconstruction could not
 * reproduce is an ERROR, never silently different results.
 */
#include <stdlib.h>
#include <string.h>

#include "ef_board.h"
#include "ef_trace.h"
#include "ef_vec.h"
#include "edgeflag.h"

typedef struct dut_model {
    ef_board *b;
    uint32_t mask;
    int samples;
    ef_ctx *ctx; /* NULL outside FRAME .. FRAME_END */
    ef_image img;
    ef_vec_collect col; /* the frame's transactions (mask + cmd) */
    uint64_t (*rx)[2];  /* the frame's received commands, as payload words */
    size_t nrx, rx_cap;
    int in_shape;
    ef_rule rule;
    ef_rgba8 color;
    ef_point *pts; /* the shape's contours */
    uint32_t *start;
    size_t npts, pts_cap, ncont, cont_cap;
    int open;     /* the last contour is not closed yet */
    int emitting; /* the frame's records are being handed over (ef_board_results_full) */
    ef_vec_merge m;
    ef_point last; /* where the last edge ended */
    uint64_t frames;
} dut_model;

static int fail(dut_model *d, const char *why)
{
    ef_board_fail(d->b, 16, why);
    return -1;
}

static int32_t s24(uint64_t v) { return (int32_t)((uint32_t)(v & 0xffffffu) ^ 0x800000u) - 0x800000; }

static void end_frame_state(dut_model *d)
{
    if (d->ctx) {
        ef_ctx_destroy(d->ctx);
        d->ctx = NULL;
        ef_image_destroy(&d->img);
        ef_vec_collect_destroy(&d->col);
    }
    d->nrx = d->npts = d->ncont = 0;
    d->in_shape = d->open = d->emitting = 0;
}

static int start(void *self, ef_board *b, uint32_t mask, int samples)
{
    dut_model *d = self;
    end_frame_state(d);
    d->b = b;
    d->mask = mask;
    d->samples = samples;
    if (!ef_samples_valid(samples))
        return fail(d, "sample count must be 8, 16 or 32");
    return 0;
}

static int add_point(dut_model *d, ef_point p)
{
    if (d->npts == d->pts_cap) {
        size_t cap = d->pts_cap ? 2 * d->pts_cap : 256;
        ef_point *n = realloc(d->pts, cap * sizeof *n);
        if (!n)
            return fail(d, "out of memory");
        d->pts = n, d->pts_cap = cap;
    }
    d->pts[d->npts++] = p;
    return 0;
}

/* Room for start[ncont + 1]: the next contour's start and the end mark. */
static int reserve_contour(dut_model *d)
{
    if (d->ncont + 2 > d->cont_cap) {
        size_t cap = d->cont_cap ? 2 * d->cont_cap : 64;
        uint32_t *n = realloc(d->start, cap * sizeof *n);
        if (!n)
            return fail(d, "out of memory");
        d->start = n, d->cont_cap = cap;
    }
    return 0;
}

static int add_contour(dut_model *d)
{
    if (reserve_contour(d) != 0)
        return -1;
    d->start[d->ncont++] = (uint32_t)d->npts;
    return 0;
}

static int edge(dut_model *d, ef_point a, ef_point z)
{
    if (!d->open || a.x != d->last.x || a.y != d->last.y) {
        if (d->open)
            return fail(d, "an EDGE starts away from the end of the open contour");
        if (add_contour(d) != 0 || add_point(d, a) != 0)
            return -1;
        d->open = 1;
    }
    const ef_point first = d->pts[d->start[d->ncont - 1]];
    if (z.x == first.x && z.y == first.y)
        d->open = 0; /* the closing edge */
    else if (add_point(d, z) != 0)
        return -1;
    d->last = z;
    return 0;
}

static int shape_end(dut_model *d)
{
    if (d->open)
        return fail(d, "SHAPE_END with a contour that does not return to its first point");
    if (reserve_contour(d) != 0)
        return -1;
    d->start[d->ncont] = (uint32_t)d->npts;
    const ef_polygon poly = { d->pts, d->start, (uint32_t)d->ncont };
    const ef_status st = ef_fill(d->ctx, &d->img, &poly, d->rule, d->color);
    d->npts = d->ncont = 0;
    d->in_shape = 0;
    if (st != EF_OK)
        return fail(d, ef_strerror(st));
    return 0;
}

/* The model's cmd trace must be the received stream. */
static int self_check(dut_model *d)
{
    if (d->col.error != EF_OK)
        return fail(d, d->col.error == EF_ERR_NOMEM ? "out of memory" : d->col.why);
    const size_t n = ef_vec_collect_count(&d->col, EF_IF_CMD);
    if (n != d->nrx)
        return fail(d, "the model's command trace has another length than the received stream");
    for (size_t k = 0; k < n; k++) {
        ef_txn t;
        ef_vec_collect_get(&d->col, EF_IF_CMD, k, &t);
        if (t.w[0] != d->rx[k][0] || t.w[1] != d->rx[k][1])
            return fail(d, "the model's command trace differs from the received stream");
    }
    return 0;
}

/* Hands the frame's records to the engine while its result queue has room
 * (back-pressure, docs/board.md 4.2); the frame ends when all are out. */
static int emit_held(dut_model *d)
{
    ef_txn t;
    uint8_t r[EF_VEC_BIN_RECORD_MAX];
    while (!ef_board_results_full(d->b)) {
        if (!ef_vec_merge_next(&d->m, &t)) {
            end_frame_state(d);
            return 0;
        }
        if (ef_board_emit(d->b, r, ef_vec_bin_record(&t, r)) != 0)
            return fail(d, "out of memory");
    }
    return 0;
}

static int frame_end(dut_model *d)
{
    uint64_t cycles;
    if (ef_trace_frame_end(d->ctx, &cycles) != EF_OK)
        return fail(d, "FRAME_END refused by the model");
    if (self_check(d) != 0)
        return -1;
    ef_vec_merge_init(&d->m, &d->col, d->mask);
    d->emitting = 1;
    d->frames++;
    return emit_held(d);
}

static int remember(dut_model *d, uint64_t w0, uint64_t w1)
{
    if (d->nrx == d->rx_cap) {
        size_t cap = d->rx_cap ? 2 * d->rx_cap : 1024;
        uint64_t(*n)[2] = realloc(d->rx, cap * sizeof *n);
        if (!n)
            return fail(d, "out of memory");
        d->rx = n, d->rx_cap = cap;
    }
    d->rx[d->nrx][0] = w0;
    d->rx[d->nrx][1] = w1;
    d->nrx++;
    return 0;
}

static int push(void *self, const uint8_t c[EF_PROTO_CMD_BYTES])
{
    dut_model *d = self;
    uint64_t w0 = 0, w1 = 0;
    for (int i = 0; i < 8; i++)
        w0 |= (uint64_t)c[i] << (8 * i);
    for (int i = 8; i < 13; i++)
        w1 |= (uint64_t)c[i] << (8 * (i - 8));
    if (w1 >> 36)
        return fail(d, "a command word has bits above bit 99");
    const unsigned op = (unsigned)(w1 >> 32);
    /* op a b c d, most significant first: d = bits 0..23 ... a = 72..95 */
    const uint64_t fd = w0 & 0xffffff, fc = w0 >> 24 & 0xffffff;
    const uint64_t fb = (w0 >> 48 | w1 << 16) & 0xffffff, fa = w1 >> 8 & 0xffffff;

    if (d->emitting) { /* the last frame's records wait for room: busy until they are out */
        if (emit_held(d) != 0)
            return -1;
        if (d->emitting)
            return 1;
    }
    if (d->ctx && remember(d, w0, w1) != 0) /* for the self-check */
        return -1;
    switch (op) {
    case EF_OP_FRAME: {
        if (d->ctx)
            return fail(d, "FRAME inside a frame");
        const int32_t w = (int32_t)fa, h = (int32_t)fb;
        if (ef_ctx_create(&d->ctx, w, h, d->samples) != EF_OK)
            return fail(d, "FRAME: canvas size out of range");
        if (ef_image_create(&d->img, w, h) != EF_OK) {
            ef_ctx_destroy(d->ctx);
            d->ctx = NULL;
            return fail(d, "out of memory");
        }
        ef_vec_collect_create(&d->col, d->mask | 1u << EF_IF_CMD);
        if (ef_trace_enable(d->ctx, d->mask | 1u << EF_IF_CMD, ef_vec_collect_sink, &d->col) != EF_OK ||
            ef_trace_frame_begin(d->ctx) != EF_OK)
            return fail(d, "the model refused to trace");
        d->nrx = 0;
        return remember(d, w0, w1);
    }
    case EF_OP_SHAPE:
        if (!d->ctx || d->in_shape)
            return fail(d, "SHAPE outside a frame or inside a shape");
        if (fa > 1)
            return fail(d, "SHAPE: rule must be 0 (non-zero) or 1 (even-odd)");
        d->rule = fa ? EF_RULE_EVENODD : EF_RULE_NONZERO;
        d->color = (ef_rgba8){ (uint8_t)(fb >> 16), (uint8_t)(fb >> 8), (uint8_t)fb, (uint8_t)fc };
        d->in_shape = 1;
        return 0;
    case EF_OP_EDGE:
        if (!d->in_shape)
            return fail(d, "EDGE outside a shape");
        return edge(d, (ef_point){ s24(fa), s24(fb) }, (ef_point){ s24(fc), s24(fd) });
    case EF_OP_SHAPE_END:
        if (!d->in_shape)
            return fail(d, "SHAPE_END outside a shape");
        return shape_end(d);
    case EF_OP_FRAME_END:
        if (!d->ctx || d->in_shape)
            return fail(d, "FRAME_END outside a frame or inside a shape");
        return frame_end(d);
    default: return fail(d, "unknown command op");
    }
}

static int finish(void *self)
{
    dut_model *d = self;
    if (d->emitting && emit_held(d) != 0)
        return -1;
    if (d->emitting)
        return 1;
    if (d->ctx)
        return fail(d, "END inside a frame (no FRAME_END)");
    return 0;
}

static void stop(void *self) { end_frame_state(self); }

static void destroy(void *self)
{
    dut_model *d = self;
    end_frame_state(d);
    free(d->rx);
    free(d->pts);
    free(d->start);
    free(d);
}

ef_board_dut ef_board_dut_model(void)
{
    dut_model *d = calloc(1, sizeof *d);
    ef_board_dut dut = { d, start, push, finish, stop, destroy };
    if (!d)
        memset(&dut, 0, sizeof dut);
    return dut;
}
