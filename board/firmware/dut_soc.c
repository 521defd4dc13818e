/*
 * dut_soc.c (board firmware) - the SoC's ef_raster peripheral
 * (board/soc/ef_periph.py) as the DUT behind the board engine: the twin of
 * board/dut_rtl.c on real hardware.  push() checks a command as dut_rtl.c
 * does and writes it into the peripheral's command FIFO; the peripheral runs
 * ef_raster on the reference bench's schedule (its clock stops while it owes
 * the DUT a command or serialises records) and captures every transfer of
 * the chosen interfaces; dut_soc_poll(), called by the main loop and while
 * push() or finish() wait, turns the record words into vectors.bin records
 * for ef_board_emit().  finish() sends the FLUSH marker and waits for it to
 * come back behind the last record.
 */
#include "dut_soc.h"

#include <string.h>

#include <generated/csr.h>
#include <generated/soc.h>

#include "ef_trace.h"
#include "link.h"

#define OP_FLUSH 15u
#define ST_CMD_ROOM 1u
#define ST_REC 2u
#define MARK 0xFFu

typedef struct dut_soc {
    ef_board *b;
    uint32_t mask;
    int running; /* between start and stop, no failure */
    int in_frame, in_shape, flushed, flush_sent;
    uint32_t edges;
    uint32_t npix; /* pix records of this run (EF_SOC_FAULT_PIX) */
} dut_soc;

static dut_soc the_dut;

static int fail(dut_soc *d, const char *why)
{
    d->running = 0;
    ef_board_fail(d->b, 16, why);
    return -1;
}

static uint32_t next_word(void)
{
    while (!(ef_status_read() & ST_REC))
        fw_link_poll();
    const uint32_t w = ef_rec_data_read();
    ef_rec_pop_write(1);
    return w;
}

/* Empties the record FIFO into records (or, stopped, drops them), while the
 * engine's result queue has room: when it is full the FIFO fills, and the
 * peripheral stops ef_raster's clock (back-pressure, docs/board.md 4.2). */
static void drain(dut_soc *d)
{
    while ((ef_status_read() & ST_REC) && !(d->running && ef_board_results_full(d->b))) {
        fw_link_poll(); /* (this loop lasts while ef_raster makes records) */
        const uint32_t w = next_word();
        if ((w & 0xFFu) == MARK) {
            const uint32_t code = w >> 16;
            if (code == 0)
                d->flushed = 1;
            else if (d->running)
                fail(d, code == 1 ? "the RTL raised err: a FRAME over its W_MAX x H_MAX or a shape over its E_MAX edges"
                                  : "the peripheral got a command outside a frame");
            continue;
        }
        uint8_t r[10 + 32];
        const unsigned len = (w >> 8) & 0xFFu;
        const uint32_t hi = next_word();
        r[0] = (uint8_t)w, r[1] = (uint8_t)len;
        r[2] = (uint8_t)(w >> 16), r[3] = (uint8_t)(w >> 24);
        r[4] = (uint8_t)hi, r[5] = (uint8_t)(hi >> 8), r[6] = (uint8_t)(hi >> 16), r[7] = (uint8_t)(hi >> 24);
        r[8] = r[9] = 0;
        for (unsigned i = 0; i < len; i += 4) {
            const uint32_t p = next_word();
            for (unsigned k = 0; k < 4 && i + k < len && i + k < 32; k++)
                r[10 + i + k] = (uint8_t)(p >> (8 * k));
        }
#ifdef EF_SOC_FAULT_PIX /* tests/board/soc_sim.sh: a planted firmware fault, never in a real build */
        if (r[0] == 6 && ++d->npix == 20)
            r[10 + 4] ^= 1u; /* the 20th pix record's alpha, bit 0 (rgba is bytes 0-3) */
#endif
        if (d->running && (len > 32 || ef_board_emit(d->b, r, 10u + len) != 0))
            fail(d, len > 32 ? "the peripheral sent a record longer than any interface's" : "out of memory");
    }
}

void dut_soc_poll(void) { drain(&the_dut); }

/* Resets the peripheral: its FIFOs empty, ef_raster stopped. */
static void hw_reset(dut_soc *d, uint32_t mask)
{
    ef_ctrl_write(1);
    for (int i = 0; i < 64; i++) /* the reset crosses into the ef domain (2 of its cycles) */
        (void)ef_status_read();
    while (ef_status_read() & ST_REC) /* words of a record cut short by the reset too */
        ef_rec_pop_write(1);
    (void)d;
    ef_ctrl_write(mask << 8);
}

static int start(void *self, ef_board *b, uint32_t mask, int samples)
{
    dut_soc *d = self;
    d->b = b;
    d->mask = mask;
    d->in_frame = d->in_shape = d->flushed = d->flush_sent = 0;
    d->edges = 0;
    d->npix = 0;
    d->running = 0;
    hw_reset(d, mask);
    d->running = 1;
    if (samples != EF_NS)
        return fail(d, "the board's ef_raster was not built for this sample count");
    return 0;
}

static int push(void *self, const uint8_t c[EF_PROTO_CMD_BYTES])
{
    dut_soc *d = self;
    if (!d->running)
        return -1;
    /* (a DATA frame's commands come in one call: the UART is read between them) */
    fw_link_poll();
    while (!(ef_status_read() & ST_CMD_ROOM)) { /* busy (not taken) while the engine is full */
        if (ef_board_results_full(d->b))
            return 1;
        fw_link_poll();
        drain(d);
        if (!d->running)
            return -1;
    }
    if (c[12] >> 4)
        return fail(d, "a command word has bits above bit 99");
    const unsigned op = c[12] & 0xFu;
    /* a = bits 72..95, b = 48..71 (docs/board.md 2) */
    const uint32_t fa = (uint32_t)c[9] | (uint32_t)c[10] << 8 | (uint32_t)c[11] << 16;
    const uint32_t fb = (uint32_t)c[6] | (uint32_t)c[7] << 8 | (uint32_t)c[8] << 16;
    if (op == EF_OP_FRAME) {
        if (d->in_frame)
            return fail(d, "FRAME inside a frame");
        if (fa == 0 || fa > EF_W_MAX || fb == 0 || fb > EF_H_MAX)
            return fail(d, "FRAME: the canvas is over the board's W_MAX x H_MAX (identify says them) or empty");
        d->in_frame = 1;
    } else if (!d->in_frame) {
        return fail(d, "a command outside a frame (before FRAME)");
    } else if (op < EF_OP_FRAME || op > EF_OP_FRAME_END) {
        return fail(d, "unknown command op");
    } else if ((op == EF_OP_SHAPE || op == EF_OP_FRAME_END) && d->in_shape) {
        /* FRAME_END inside a shape: the peripheral ends the frame at FRAME_END's transfer,
         * which is drained only after a closed shape (board/soc/ef_periph.py) */
        return fail(d, op == EF_OP_SHAPE ? "SHAPE inside a shape" : "FRAME_END inside a shape (no SHAPE_END)");
    } else if ((op == EF_OP_EDGE || op == EF_OP_SHAPE_END) && !d->in_shape) {
        return fail(d, op == EF_OP_EDGE ? "EDGE outside a shape" : "SHAPE_END outside a shape");
    } else if (op == EF_OP_SHAPE) {
        d->edges = 0;
        d->in_shape = 1;
    } else if (op == EF_OP_SHAPE_END) {
        d->in_shape = 0;
    } else if (op == EF_OP_EDGE && ++d->edges > EF_E_MAX) {
        return fail(d, "a shape of more EDGE commands than the board's E_MAX (identify says it)");
    }
    if (op == EF_OP_FRAME_END)
        d->in_frame = 0;
    uint32_t w[4] = { 0, 0, 0, 0 };
    for (int i = 0; i < EF_PROTO_CMD_BYTES; i++)
        w[i / 4] |= (uint32_t)c[i] << (8 * (i % 4));
    ef_cmd0_write(w[0]);
    ef_cmd1_write(w[1]);
    ef_cmd2_write(w[2]);
    ef_cmd3_write(w[3]);
    ef_push_write(1);
    drain(d);
    return d->running ? 0 : -1;
}

static int finish(void *self)
{
    dut_soc *d = self;
    if (!d->running)
        return -1;
    if (d->in_frame)
        return fail(d, "END inside a frame (no FRAME_END)");
    if (!d->flush_sent) {
        while (!(ef_status_read() & ST_CMD_ROOM)) {
            if (ef_board_results_full(d->b))
                return 1; /* busy: called again once the host took results */
            fw_link_poll();
            drain(d);
        }
        ef_cmd0_write(0);
        ef_cmd1_write(0);
        ef_cmd2_write(0);
        ef_cmd3_write(OP_FLUSH);
        ef_push_write(1);
        d->flushed = 0;
        d->flush_sent = 1;
    }
    while (!d->flushed && d->running) {
        if (ef_board_results_full(d->b))
            return 1;
        fw_link_poll();
        drain(d);
    }
    return d->running ? 0 : -1;
}

static void stop(void *self)
{
    dut_soc *d = self;
    d->running = 0;
    hw_reset(d, 0);
    d->in_frame = d->in_shape = 0;
}

static void destroy(void *self) { stop(self); }

ef_board_dut ef_board_dut_soc(void)
{
    ef_board_dut dut = { &the_dut, start, push, finish, stop, destroy };
    return dut;
}
