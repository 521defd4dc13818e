/*
 * dut_rtl.h - the Verilated reference RTL (rtl/ef_raster.v) as
 * the DUT behind the board engine (docs/board.md 5.3).  Built only when
 * Verilator is present (board/rtl_dut.mk: WITH_RTL_DUT); without it
 * ef_board_dut_rtl_built() is 0 and the constructor returns an empty table.
 *
 * Two layers: dut_rtl.c is the DUT (commands in, vectors.bin records out,
 * the frame memory, the cycle count), plain C; dut_rtl.cpp is the thin C++
 * shim Verilator needs, one Verilated model per sample count, seen from C
 * through the ef_rtl_sim calls below.
 */
#ifndef EF_DUT_RTL_H
#define EF_DUT_RTL_H

#include <stdint.h>

#include "ef_board.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The RTL as the DUT: an empty table (self NULL) when not built in or out of memory. */
ef_board_dut ef_board_dut_rtl(void);
/* 1 when edgeflag-host was built with the RTL DUT. */
int ef_board_dut_rtl_built(void);
/* What identify says with the RTL DUT: its parameters (W_MAX, H_MAX,
 * E_MAX) and the sample counts it was built for (samples_mask bits). */
void ef_board_dut_rtl_limits(uint32_t *width_max, uint32_t *height_max, uint32_t *edges_max, uint32_t *samples_mask);
/* "NS 8/16/32, W_MAX 1024, ..." for --version. */
const char *ef_board_dut_rtl_describe(void);

/* The simulated board's DUT (host/transport_sim.c, `--sim-dut model|rtl`):
 * which one the next sim_open puts behind the engine. */
enum { EF_SIM_DUT_MODEL = 0, EF_SIM_DUT_RTL = 1 };
void ef_transport_sim_select_dut(int which);

/* ---- between dut_rtl.c and dut_rtl.cpp ------------------------------- */
typedef struct ef_rtl_sim ef_rtl_sim;
typedef struct ef_rtl_in {
    uint8_t rst, cmd_valid, cmd_op, pix_ready;
    uint32_t cmd_a, cmd_b, cmd_c, cmd_d, fb_rdata;
} ef_rtl_in;
typedef struct ef_rtl_out {
    uint8_t init_done, drained, cmd_ready, err, frame_start, frame_end;
    uint8_t pix_valid, fb_re, fb_we;
    uint32_t pix_y, pix_x, pix_alpha, pix_rgba;
    uint32_t fb_ry, fb_rx, fb_wy, fb_wx, fb_wdata;
    uint8_t seg_valid, seg_ready, seg_eos;
    uint32_t seg_xa, seg_ya, seg_xb, seg_yb;
    uint8_t et_wr_valid, et_wr_ready, et_wr_eos, et_wr_dir;
    uint32_t et_wr_slot, et_wr_r0, et_wr_r1, et_wr_x, et_wr_e, et_wr_qs, et_wr_rs, et_wr_dy;
    uint8_t et_rd_valid, et_rd_ready;
    uint32_t et_rd_row, et_rd_eid;
    uint8_t plot_valid, plot_ready, plot_last, plot_dir;
    uint32_t plot_row, plot_s, plot_q;
    uint8_t span_valid, span_ready;
    uint32_t span_y, span_x, span_len, span_mask;
} ef_rtl_out;
/* A model of NS samples, clock low, or NULL (NS not built, out of memory). */
ef_rtl_sim *ef_rtl_sim_new(int ns);
void ef_rtl_sim_free(ef_rtl_sim *s);
/* Applies the inputs (clock low), settles, reads every output. */
void ef_rtl_sim_eval(ef_rtl_sim *s, const ef_rtl_in *in, ef_rtl_out *out);
/* One rising clock edge, inputs unchanged; the clock falls at the next eval. */
void ef_rtl_sim_tick(ef_rtl_sim *s);
/* Bit k set: a model of 2^k samples is built in. */
uint32_t ef_rtl_sim_samples_mask(void);

#ifdef __cplusplus
}
#endif

#endif /* EF_DUT_RTL_H */
