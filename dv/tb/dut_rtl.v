// dut_rtl.v - the Verilated reference RTL as the board engine's DUT
// (board/dut_rtl.cpp, docs/board.md 5.3): ef_raster with every port
// passed through, plus `drained`, the condition dv/tb/tb_raster.v waits
// for before it ends a run (AET, SLB+FILL and COV hold nothing and no seg
// or et_wr is offered), so the C++ side knows when a frame's last
// transaction has been made.  Verilator only (hierarchical references);
// not part of the synthesizable RTL.
module ef_rtl_dut #(
    parameter NS    = 8,
    parameter W_MAX = 16384,
    parameter H_MAX = 16384,
    parameter E_MAX = 4096
) (
    input  wire        clk,
    input  wire        rst,
    output wire        init_done,
    output wire        drained,
    input  wire        cmd_valid,
    output wire        cmd_ready,
    input  wire [3:0]  cmd_op,
    input  wire [23:0] cmd_a,
    input  wire [23:0] cmd_b,
    input  wire [23:0] cmd_c,
    input  wire [23:0] cmd_d,
    output wire        pix_valid,
    input  wire        pix_ready,
    output wire [13:0] pix_y,
    output wire [13:0] pix_x,
    output wire [7:0]  pix_alpha,
    output wire [31:0] pix_rgba,
    output wire        fb_re,
    output wire [13:0] fb_ry,
    output wire [13:0] fb_rx,
    input  wire [31:0] fb_rdata,
    output wire        fb_we,
    output wire [13:0] fb_wy,
    output wire [13:0] fb_wx,
    output wire [31:0] fb_wdata,
    output wire [14:0] cfg_width,
    output wire [14:0] cfg_height,
    output wire        frame_start,
    output wire        frame_end,
    output wire        err,
    output wire        seg_valid,
    output wire        seg_ready,
    output wire        seg_eos,
    output wire [23:0] seg_xa,
    output wire [23:0] seg_ya,
    output wire [23:0] seg_xb,
    output wire [23:0] seg_yb,
    output wire        et_wr_valid,
    output wire        et_wr_ready,
    output wire        et_wr_eos,
    output wire [13:0] et_wr_slot,
    output wire [18:0] et_wr_r0,
    output wire [18:0] et_wr_r1,
    output wire [24:0] et_wr_x,
    output wire [23:0] et_wr_e,
    output wire [29:0] et_wr_qs,
    output wire [23:0] et_wr_rs,
    output wire [23:0] et_wr_dy,
    output wire        et_wr_dir,
    output wire        et_rd_valid,
    output wire        et_rd_ready,
    output wire [13:0] et_rd_row,
    output wire [21:0] et_rd_eid,
    output wire        plot_valid,
    output wire        plot_ready,
    output wire        plot_last,
    output wire [13:0] plot_row,
    output wire [4:0]  plot_s,
    output wire [14:0] plot_q,
    output wire        plot_dir,
    output wire        span_valid,
    output wire        span_ready,
    output wire [13:0] span_y,
    output wire [13:0] span_x,
    output wire [14:0] span_len,
    output wire [31:0] span_mask
);
    ef_raster #(.NS(NS), .W_MAX(W_MAX), .H_MAX(H_MAX), .E_MAX(E_MAX)) u (
`include "ef_raster_conn.vh"
    );
    assign drained = !u.aet_busy && u.slb_idle && !u.cov_busy && !seg_valid && !et_wr_valid;
endmodule
