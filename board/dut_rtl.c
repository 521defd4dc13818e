/*
 * dut_rtl.c - the Verilated reference RTL (rtl/ef_raster.v) as
 * the DUT behind the board engine (docs/board.md 5.3), the twin of
 * dut_model.c: the command stream goes into the RTL's cmd port and at each
 * FRAME_END the frame's transfers of the requested interfaces come out as
 * vectors.bin records in global order (by cycle, then interface).
 *
 * The clocking is dv/tb/tb_raster.v's, so the stamps are the vectors':
 * FRAME resets the RTL (a fresh frame, as the model starts each frame with a
 * fresh context), cycle 0 is the first cycle after the edge at which
 * init_done is seen, a transfer of cycle t is valid && ready before the
 * edge that ends t, and the frame memory is the bench's: a read port whose
 * data appears one cycle after fb_re (and is held), a write port, all cleared
 * at frame_start.  Commands go in as fast as cmd_ready allows (a command is
 * offered in the cycle after the previous one was taken): the reference
 * schedule issues each command at the first cycle DEC can take it, so a
 * cycle-exact RTL takes each at its stamp.  A frame ends when FRAME_END has
 * been seen and the pipeline has drained (the bench's end condition).
 *
 * Built for real only with EF_RTL_DUT (board/rtl_dut.mk compiles this file
 * a second time with it, beside the C++ shim dut_rtl.cpp); otherwise the
 * constructor returns an empty table, so edgeflag-host and the emulators
 * link without Verilator.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dut_rtl.h"

#ifndef EF_RTL_DUT

ef_board_dut ef_board_dut_rtl(void)
{
    ef_board_dut none;
    memset(&none, 0, sizeof none);
    return none;
}
int ef_board_dut_rtl_built(void) { return 0; }
void ef_board_dut_rtl_limits(uint32_t *w, uint32_t *h, uint32_t *e, uint32_t *s) { *w = *h = *e = *s = 0; }
const char *ef_board_dut_rtl_describe(void)
{
    return "not built in (`make host-rtl` builds it and later builds keep it; it needs Verilator)";
}

#else

#include "ef_trace.h"
#include "ef_vec.h"

#define HANG_CYCLES 10000000u /* a command not taken, or a frame not drained, this long: the RTL hangs */

typedef struct dut_rtl {
    ef_board *b;
    uint32_t mask;
    int samples;
    ef_rtl_sim *sim; /* the model of `samples` samples */
    ef_rtl_in in;
    ef_rtl_out out;
    uint64_t t; /* cycle from the frame's start */
    int in_frame, frame_end_seen;
    int emitting; /* the frame's records are being handed over (ef_board_results_full) */
    size_t emit_pos;
    uint32_t edges; /* EDGE commands of the current shape */
    uint32_t w, h;
    uint32_t *fb; /* the frame memory, w * h words */
    uint8_t *rec; /* the frame's records */
    size_t nrec, rec_cap;
    uint64_t cycles_total;
} dut_rtl;

static int fail(dut_rtl *d, const char *why)
{
    ef_board_fail(d->b, 16, why);
    return -1;
}

static int record(dut_rtl *d, int iface, const uint64_t *f, unsigned nf)
{
    if (!(d->mask >> iface & 1u))
        return 0;
    const ef_iface_desc *desc = ef_iface_get(iface);
    if (!desc || desc->nfields != nf)
        return fail(d, "the RTL DUT's interface layout differs from the vectors' (rebuild edgeflag-host)");
    ef_txn t;
    memset(&t, 0, sizeof t);
    t.iface = (uint8_t)iface;
    t.cycle = d->t;
    for (unsigned k = 0; k < nf; k++)
        ef_txn_set_field(&t, k, f[k]);
    if (d->rec_cap - d->nrec < EF_VEC_BIN_RECORD_MAX) {
        size_t cap = d->rec_cap ? 2 * d->rec_cap : 1 << 16;
        uint8_t *n = realloc(d->rec, cap);
        if (!n)
            return fail(d, "out of memory");
        d->rec = n, d->rec_cap = cap;
    }
    d->nrec += ef_vec_bin_record(&t, d->rec + d->nrec);
    return 0;
}

/* The transfers of cycle t, in interface order (so the records are in
 * global order), and the frame memory's edge. */
static int observe(dut_rtl *d)
{
    const ef_rtl_out *o = &d->out;
    const ef_rtl_in *i = &d->in;
    int r = 0;
    if (o->err)
        return fail(d, "the RTL raised err: a FRAME over its W_MAX x H_MAX or a shape over its E_MAX edges");
    if (i->cmd_valid && o->cmd_ready) {
        const uint64_t f[] = { i->cmd_op, i->cmd_a, i->cmd_b, i->cmd_c, i->cmd_d };
        r |= record(d, EF_IF_CMD, f, 5);
    }
    if (o->seg_valid && o->seg_ready) {
        const uint64_t f[] = { o->seg_eos, o->seg_xa, o->seg_ya, o->seg_xb, o->seg_yb };
        r |= record(d, EF_IF_SEG, f, 5);
    }
    if (o->et_wr_valid && o->et_wr_ready) {
        const uint64_t f[] = { o->et_wr_eos, o->et_wr_slot, o->et_wr_r0, o->et_wr_r1, o->et_wr_x,
                               o->et_wr_e,   o->et_wr_qs,   o->et_wr_rs, o->et_wr_dy, o->et_wr_dir };
        r |= record(d, EF_IF_ET_WR, f, 10);
    }
    if (o->et_rd_valid && o->et_rd_ready) {
        const uint64_t f[] = { o->et_rd_row, o->et_rd_eid };
        r |= record(d, EF_IF_ET_RD, f, 2);
    }
    if (o->plot_valid && o->plot_ready) {
        const uint64_t f[] = { o->plot_last, o->plot_row, o->plot_s, o->plot_q, o->plot_dir };
        r |= record(d, EF_IF_PLOT, f, 5);
    }
    if (o->span_valid && o->span_ready) {
        const uint64_t f[] = { o->span_y, o->span_x, o->span_len, o->span_mask };
        r |= record(d, EF_IF_SPAN, f, 4);
    }
    if (o->pix_valid && i->pix_ready) {
        const uint64_t f[] = { o->pix_y, o->pix_x, o->pix_alpha, o->pix_rgba };
        r |= record(d, EF_IF_PIX, f, 4);
    }
    if (r)
        return -1;
    /* The frame memory at this edge: cleared at frame_start, a read sees
     * the word before this edge's write. */
    if (o->frame_start && d->fb)
        memset(d->fb, 0, (size_t)d->w * d->h * sizeof *d->fb);
    if (o->fb_re) {
        if (o->fb_ry >= d->h || o->fb_rx >= d->w)
            return fail(d, "the RTL read the frame memory outside the canvas");
        d->in.fb_rdata = d->fb[(size_t)o->fb_ry * d->w + o->fb_rx];
    }
    if (o->fb_we) {
        if (o->fb_wy >= d->h || o->fb_wx >= d->w)
            return fail(d, "the RTL wrote the frame memory outside the canvas");
        d->fb[(size_t)o->fb_wy * d->w + o->fb_wx] = o->fb_wdata;
    }
    if (o->frame_end)
        d->frame_end_seen = 1;
    return 0;
}

/* One cycle: settle, observe, clock.  Returns 1 when the command offered
 * was taken, 0 when not, -1 on failure. */
static int cycle(dut_rtl *d)
{
    ef_rtl_sim_eval(d->sim, &d->in, &d->out);
    const int taken = d->in.cmd_valid && d->out.cmd_ready;
    if (observe(d) != 0)
        return -1;
    if (taken)
        d->in.cmd_valid = 0; /* the next command is offered by the next push */
    ef_rtl_sim_tick(d->sim);
    d->t++;
    d->cycles_total++;
    return taken;
}

/* Reset as tb_raster.v does: three edges in reset, then wait for
 * init_done; cycle 0 is the cycle after the edge that sees it. */
static int reset_rtl(dut_rtl *d)
{
    memset(&d->in, 0, sizeof d->in);
    d->in.rst = 1;
    d->in.pix_ready = 1;
    for (int k = 0; k < 3; k++) {
        ef_rtl_sim_eval(d->sim, &d->in, &d->out);
        ef_rtl_sim_tick(d->sim);
    }
    d->in.rst = 0;
    for (uint32_t n = 0;; n++) {
        ef_rtl_sim_eval(d->sim, &d->in, &d->out);
        ef_rtl_sim_tick(d->sim);
        if (d->out.init_done)
            break;
        if (n == HANG_CYCLES)
            return fail(d, "the RTL never raised init_done after reset");
    }
    d->t = 0;
    return 0;
}

static void end_frame_state(dut_rtl *d)
{
    free(d->fb);
    d->fb = NULL;
    d->nrec = d->emit_pos = 0;
    d->in_frame = d->frame_end_seen = d->emitting = 0;
    d->edges = 0;
}

static int start(void *self, ef_board *b, uint32_t mask, int samples)
{
    dut_rtl *d = self;
    end_frame_state(d);
    d->b = b;
    d->mask = mask;
    if (!d->sim || d->samples != samples) {
        ef_rtl_sim_free(d->sim);
        d->sim = NULL;
        d->samples = 0;
        if (!(ef_rtl_sim_samples_mask() >> ef_proto_samples_bit((unsigned)samples) & 1u))
            return fail(d, "the RTL DUT was not built for this sample count");
        if (!(d->sim = ef_rtl_sim_new(samples)))
            return fail(d, "out of memory (the Verilated RTL)");
        d->samples = samples;
    }
    return 0;
}

/* Hands the frame's records to the engine while its result queue has room
 * (back-pressure, docs/board.md 4.2); the frame ends when all are out. */
static int emit_held(dut_rtl *d)
{
    while (d->emit_pos < d->nrec) {
        if (ef_board_results_full(d->b))
            return 0;
        const size_t len = 10u + d->rec[d->emit_pos + 1];
        if (ef_board_emit(d->b, d->rec + d->emit_pos, len) != 0)
            return fail(d, "out of memory");
        d->emit_pos += len;
    }
    end_frame_state(d);
    return 0;
}

static int frame_end(dut_rtl *d)
{
    for (uint32_t n = 0; !(d->frame_end_seen && d->out.drained); n++) {
        if (n == HANG_CYCLES)
            return fail(d, "the RTL did not drain after FRAME_END (it hangs)");
        if (cycle(d) < 0)
            return -1;
    }
    /* the cycle that saw the pipeline drained was observed: nothing more moves */
    d->emit_pos = 0;
    d->emitting = 1;
    return emit_held(d);
}

static int push(void *self, const uint8_t c[EF_PROTO_CMD_BYTES])
{
    dut_rtl *d = self;
    if (!d->sim)
        return fail(d, "no run started");
    if (d->emitting) { /* the last frame's records wait for room: busy until they are out */
        if (emit_held(d) != 0)
            return -1;
        if (d->emitting)
            return 1;
    }
    uint64_t w0 = 0, w1 = 0;
    for (int i = 0; i < 8; i++)
        w0 |= (uint64_t)c[i] << (8 * i);
    for (int i = 8; i < 13; i++)
        w1 |= (uint64_t)c[i] << (8 * (i - 8));
    if (w1 >> 36)
        return fail(d, "a command word has bits above bit 99");
    const unsigned op = (unsigned)(w1 >> 32);
    /* d = bits 0..23, c = 24..47, b = 48..71, a = 72..95 (docs/board.md 2) */
    const uint32_t fd = (uint32_t)(w0 & 0xffffff), fc = (uint32_t)(w0 >> 24 & 0xffffff);
    const uint32_t fb = (uint32_t)((w0 >> 48 | w1 << 16) & 0xffffff), fa = (uint32_t)(w1 >> 8 & 0xffffff);

    if (op == EF_OP_FRAME) {
        if (d->in_frame)
            return fail(d, "FRAME inside a frame");
        if (fa == 0 || fa > EF_RTL_W_MAX || fb == 0 || fb > EF_RTL_H_MAX) {
            char why[160];
            snprintf(why, sizeof why, "FRAME: a %ux%u canvas is over the RTL's W_MAX x H_MAX (%u x %u) or empty",
                     (unsigned)fa, (unsigned)fb, (unsigned)EF_RTL_W_MAX, (unsigned)EF_RTL_H_MAX);
            return fail(d, why);
        }
        if (reset_rtl(d) != 0)
            return -1;
        d->w = fa, d->h = fb;
        if (!(d->fb = calloc((size_t)fa * fb, sizeof *d->fb)))
            return fail(d, "out of memory");
        d->in_frame = 1;
        d->nrec = 0;
    } else if (!d->in_frame) {
        return fail(d, "a command outside a frame (before FRAME)");
    } else if (op == EF_OP_SHAPE) {
        d->edges = 0;
    } else if (op == EF_OP_EDGE && ++d->edges > EF_RTL_E_MAX) {
        char why[120];
        snprintf(why, sizeof why, "a shape of more EDGE commands than the RTL's E_MAX (%u)", (unsigned)EF_RTL_E_MAX);
        return fail(d, why);
    } else if (op < EF_OP_FRAME || op > EF_OP_FRAME_END) {
        return fail(d, "unknown command op");
    }
    d->in.cmd_valid = 1;
    d->in.cmd_op = (uint8_t)op;
    d->in.cmd_a = fa, d->in.cmd_b = fb, d->in.cmd_c = fc, d->in.cmd_d = fd;
    for (uint32_t n = 0;; n++) {
        const int r = cycle(d);
        if (r < 0)
            return -1;
        if (r)
            break;
        if (n == HANG_CYCLES)
            return fail(d, "the RTL did not take a command for 10,000,000 cycles (it hangs)");
    }
    return op == EF_OP_FRAME_END ? frame_end(d) : 0;
}

static int finish(void *self)
{
    dut_rtl *d = self;
    if (d->emitting && emit_held(d) != 0)
        return -1;
    if (d->emitting)
        return 1;
    if (d->in_frame)
        return fail(d, "END inside a frame (no FRAME_END)");
    return 0;
}

static void stop(void *self) { end_frame_state(self); }

static void destroy(void *self)
{
    dut_rtl *d = self;
    end_frame_state(d);
    ef_rtl_sim_free(d->sim);
    free(d->rec);
    free(d);
}

ef_board_dut ef_board_dut_rtl(void)
{
    dut_rtl *d = calloc(1, sizeof *d);
    ef_board_dut dut = { d, start, push, finish, stop, destroy };
    if (!d)
        memset(&dut, 0, sizeof dut);
    return dut;
}

int ef_board_dut_rtl_built(void) { return 1; }

void ef_board_dut_rtl_limits(uint32_t *w, uint32_t *h, uint32_t *e, uint32_t *s)
{
    *w = EF_RTL_W_MAX, *h = EF_RTL_H_MAX, *e = EF_RTL_E_MAX, *s = ef_rtl_sim_samples_mask();
}

const char *ef_board_dut_rtl_describe(void)
{
    static char text[200];
    const uint32_t m = ef_rtl_sim_samples_mask();
    snprintf(text, sizeof text, "built in (Verilated ef_raster: NS%s%s%s, W_MAX %u, H_MAX %u, E_MAX %u%s)",
             m & 8u ? " 8" : "", m & 16u ? " 16" : "", m & 32u ? " 32" : "", (unsigned)EF_RTL_W_MAX,
             (unsigned)EF_RTL_H_MAX, (unsigned)EF_RTL_E_MAX, EF_RTL_FAULT[0] ? ", planted fault " EF_RTL_FAULT : "");
    return text;
}

#endif /* EF_RTL_DUT */
