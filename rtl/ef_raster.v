// ef_raster: the whole edgeflag pipeline (docs/microarch.md 3): cmd in,
// pix out (valid/ready), the frame memory outside behind COV's read and
// write ports (docs/microarch.md 3.6).  Every internal interface is a port
// (observation only: seg, et_wr, et_rd, plot, span), so a bench dumps them
// for `edgeflag check --cycles` without reaching into the hierarchy.
//
//   cmd -> DEC -seg-> SETUP -et_wr-> ETM -et_rd-> AET+PLOT -plot-> SLB+FILL
//       -span-> COV -pix->
//
// init_done rises when the reset sweeps of ETM (H_MAX slots) and SLB
// (W_MAX+1 cells) are over; cmd_ready is low before.  cycle 0 of the vectors
// is the first cycle after it.
//
// Drain (schedule item 1): shape_done to DEC is high when the eos et_wr of
// the shape has passed and AET, SLB+FILL and COV hold nothing (registers
// only, so cmd_ready can rise in the cycle T_free itself).
//
// SCHEDULE selects the cycle rules: 0 (the default) the reference schedule
// (docs/microarch.md section 4), 1 the overlap schedule (section 6, 6.1;
// `edgeflag vectors --schedule overlap`): SLB + FILL with the skipping scan
// (ef_slb_fill SKIP = 1) and a queue of `EF_SPANQ spans (ef_spanq) between
// FILL and COV.  The observed `span` is FILL's output (the queue's input),
// and the drain's cov_busy includes "the queue is not empty".  Any other
// value fails elaboration naming ef_error_SCHEDULE_must_be_0_or_1.
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_raster #(
    parameter NS    = 8,
    parameter W_MAX = 16384,
    parameter H_MAX = 16384,
    parameter E_MAX = 4096,
    parameter SCHEDULE = 0      // 0 reference, 1 overlap (see above)
) (
    input  wire        clk,
    input  wire        rst,
    output wire        init_done,

    // cmd: op[3:0] a[23:0] b[23:0] c[23:0] d[23:0]
    input  wire        cmd_valid,
    output wire        cmd_ready,
    input  wire [`EF_CMD_OP_W-1:0] cmd_op,
    input  wire [`EF_CMD_A_W-1:0] cmd_a,
    input  wire [`EF_CMD_B_W-1:0] cmd_b,
    input  wire [`EF_CMD_C_W-1:0] cmd_c,
    input  wire [`EF_CMD_D_W-1:0] cmd_d,

    // pix: y[13:0] x[13:0] alpha[7:0] rgba[31:0]
    output wire        pix_valid,
    input  wire        pix_ready,
    output wire [`EF_PIX_Y_W-1:0] pix_y,
    output wire [`EF_PIX_X_W-1:0] pix_x,
    output wire [`EF_PIX_ALPHA_W-1:0] pix_alpha,
    output wire [`EF_PIX_RGBA_W-1:0] pix_rgba,

    // frame memory
    output wire        fb_re,
    output wire [`EF_PIX_Y_W-1:0] fb_ry,
    output wire [`EF_PIX_X_W-1:0] fb_rx,
    input  wire [`EF_PIX_RGBA_W-1:0] fb_rdata,
    output wire        fb_we,
    output wire [`EF_PIX_Y_W-1:0] fb_wy,
    output wire [`EF_PIX_X_W-1:0] fb_wx,
    output wire [`EF_PIX_RGBA_W-1:0] fb_wdata,

    // configuration and status
    output wire [14:0] cfg_width,
    output wire [14:0] cfg_height,
    output wire        frame_start,
    output wire        frame_end,
    output wire        err,          // sticky: a FRAME over W_MAX x H_MAX, or a shape over E_MAX edges

    // observation: seg
    output wire        seg_valid,
    output wire        seg_ready,
    output wire        seg_eos,
    output wire [`EF_SEG_XA_W-1:0] seg_xa,
    output wire [`EF_SEG_YA_W-1:0] seg_ya,
    output wire [`EF_SEG_XB_W-1:0] seg_xb,
    output wire [`EF_SEG_YB_W-1:0] seg_yb,
    // observation: et_wr
    output wire        et_wr_valid,
    output wire        et_wr_ready,
    output wire        et_wr_eos,
    output wire [`EF_ET_WR_SLOT_W-1:0] et_wr_slot,
    output wire [`EF_ET_WR_R0_W-1:0] et_wr_r0,
    output wire [`EF_ET_WR_R1_W-1:0] et_wr_r1,
    output wire [`EF_ET_WR_X_W-1:0] et_wr_x,
    output wire [`EF_ET_WR_E_W-1:0] et_wr_e,
    output wire [`EF_ET_WR_QS_W-1:0] et_wr_qs,
    output wire [`EF_ET_WR_RS_W-1:0] et_wr_rs,
    output wire [`EF_ET_WR_DY_W-1:0] et_wr_dy,
    output wire        et_wr_dir,
    // observation: et_rd
    output wire        et_rd_valid,
    output wire        et_rd_ready,
    output wire [`EF_ET_RD_ROW_W-1:0] et_rd_row,
    output wire [`EF_ET_RD_EID_W-1:0] et_rd_eid,
    // observation: plot
    output wire        plot_valid,
    output wire        plot_ready,
    output wire        plot_last,
    output wire [`EF_PLOT_ROW_W-1:0] plot_row,
    output wire [`EF_PLOT_S_W-1:0] plot_s,
    output wire [`EF_PLOT_Q_W-1:0] plot_q,
    output wire        plot_dir,
    // observation: span
    output wire        span_valid,
    output wire        span_ready,
    output wire [`EF_SPAN_Y_W-1:0] span_y,
    output wire [`EF_SPAN_X_W-1:0] span_x,
    output wire [`EF_SPAN_LEN_W-1:0] span_len,
    output wire [`EF_SPAN_MASK_W-1:0] span_mask
);
    `include "ef_ns.vh"
    generate
        if (SCHEDULE != 0 && SCHEDULE != 1) begin : schedule_check
            ef_error_SCHEDULE_must_be_0_or_1 u_schedule_must_be_0_or_1 ();
        end
    endgenerate
    wire        cfg_rule, cfg_err;
    wire [23:0] cfg_rgb;
    wire [7:0]  cfg_alpha;
    wire        shape_done;

    ef_dec #(.W_MAX(W_MAX), .H_MAX(H_MAX)) u_dec (
        .clk(clk), .rst(rst || !init_done),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_op(cmd_op),
        .cmd_a(cmd_a), .cmd_b(cmd_b), .cmd_c(cmd_c), .cmd_d(cmd_d),
        .shape_done(shape_done),
        .seg_valid(seg_valid), .seg_ready(seg_ready), .seg_eos(seg_eos),
        .seg_xa(seg_xa), .seg_ya(seg_ya), .seg_xb(seg_xb), .seg_yb(seg_yb),
        .cfg_width(cfg_width), .cfg_height(cfg_height), .cfg_rule(cfg_rule),
        .cfg_rgb(cfg_rgb), .cfg_alpha(cfg_alpha),
        .frame_start(frame_start), .frame_end(frame_end), .cfg_err(cfg_err)
    );

    ef_setup #(.NS(NS)) u_setup (
        .clk(clk), .rst(rst), .cfg_height(cfg_height),
        .seg_valid(seg_valid), .seg_ready(seg_ready), .seg_eos(seg_eos),
        .seg_xa(seg_xa), .seg_ya(seg_ya), .seg_xb(seg_xb), .seg_yb(seg_yb),
        .et_wr_valid(et_wr_valid), .et_wr_ready(et_wr_ready), .et_wr_eos(et_wr_eos),
        .et_wr_slot(et_wr_slot), .et_wr_r0(et_wr_r0), .et_wr_r1(et_wr_r1), .et_wr_x(et_wr_x),
        .et_wr_e(et_wr_e), .et_wr_qs(et_wr_qs), .et_wr_rs(et_wr_rs), .et_wr_dy(et_wr_dy),
        .et_wr_dir(et_wr_dir)
    );

    wire        etm_init, slb_init;
    wire        row_req, row_req_ready, et_rd_last;
    wire [`EF_ET_RD_ROW_W-1:0] row_req_row;
    wire        rec_re, rec_dir;
    wire [`EF_ET_RD_EID_W-1:0] rec_ra;
    wire [`EF_ET_WR_R0_W-1:0] rec_r0;
    wire [`EF_ET_WR_R1_W-1:0] rec_r1;
    wire [`EF_ET_WR_X_W-1:0]  rec_x;
    wire [`EF_ET_WR_E_W-1:0]  rec_e;
    wire [`EF_ET_WR_RS_W-1:0] rec_rs;
    wire [`EF_ET_WR_DY_W-1:0] rec_dy;
    wire [`EF_ET_WR_QS_W-1:0] rec_qs;
    wire        shape_go, shape_any, err_full;
    wire [`EF_ET_WR_SLOT_W-1:0] row_first, row_last;

    ef_etm #(.NS(NS), .H_MAX(H_MAX), .E_MAX(E_MAX)) u_etm (
        .clk(clk), .rst(rst), .init_done(etm_init),
        .et_wr_valid(et_wr_valid), .et_wr_ready(et_wr_ready), .et_wr_eos(et_wr_eos), .et_wr_slot(et_wr_slot),
        .et_wr_r0(et_wr_r0), .et_wr_r1(et_wr_r1), .et_wr_x(et_wr_x), .et_wr_e(et_wr_e), .et_wr_qs(et_wr_qs),
        .et_wr_rs(et_wr_rs), .et_wr_dy(et_wr_dy), .et_wr_dir(et_wr_dir),
        .shape_go(shape_go), .shape_any(shape_any), .row_first(row_first), .row_last(row_last),
        .err_full(err_full),
        .row_req(row_req), .row_req_ready(row_req_ready), .row_req_row(row_req_row),
        .et_rd_valid(et_rd_valid), .et_rd_ready(et_rd_ready), .et_rd_row(et_rd_row), .et_rd_eid(et_rd_eid),
        .et_rd_last(et_rd_last),
        .rec_re(rec_re), .rec_ra(rec_ra), .rec_r0(rec_r0), .rec_r1(rec_r1), .rec_x(rec_x), .rec_e(rec_e),
        .rec_qs(rec_qs), .rec_rs(rec_rs), .rec_dy(rec_dy), .rec_dir(rec_dir)
    );

    wire etw_take = et_wr_valid && et_wr_ready;
    wire aet_busy;
    ef_aet #(.NS(NS), .H_MAX(H_MAX), .E_MAX(E_MAX)) u_aet (
        .clk(clk), .rst(rst), .cfg_width(cfg_width),
        .etw_valid(etw_take), .etw_eos(et_wr_eos), .etw_slot(et_wr_slot),
        .row_req(row_req), .row_req_row(row_req_row),
        .et_rd_valid(et_rd_valid), .et_rd_ready(et_rd_ready), .et_rd_row(et_rd_row), .et_rd_eid(et_rd_eid),
        .et_rd_last(et_rd_last),
        .rec_re(rec_re), .rec_ra(rec_ra), .rec_r0(rec_r0), .rec_r1(rec_r1), .rec_x(rec_x),
        .rec_e(rec_e), .rec_qs(rec_qs), .rec_rs(rec_rs), .rec_dy(rec_dy), .rec_dir(rec_dir),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot_last), .plot_row(plot_row),
        .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir), .busy(aet_busy)
    );

    wire slb_idle, slb_idle_unused;
    ef_slb_fill #(.NS(NS), .W_MAX(W_MAX), .SKIP(SCHEDULE)) u_slb (
        .clk(clk), .rst(rst), .init_done(slb_init),
        .cfg_width(cfg_width), .cfg_rule(cfg_rule),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot_last),
        .plot_row(plot_row), .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y),
        .span_x(span_x), .span_len(span_len), .span_mask(span_mask), .idle(slb_idle_unused),
        .scan_done(slb_idle)
    );

    // What COV takes: FILL's span itself (reference), or the head of the
    // span queue (overlap, section 6).
    wire        cs_valid, cs_ready;
    wire [`EF_SPAN_Y_W-1:0] cs_y;
    wire [`EF_SPAN_X_W-1:0] cs_x;
    wire [`EF_SPAN_LEN_W-1:0] cs_len;
    wire [`EF_SPAN_MASK_W-1:0] cs_mask;
    wire cov_core_busy;
    // COV holds something: a span in its pipeline (or, overlap, in its queue).
    wire cov_busy;
    generate
        if (SCHEDULE == 1) begin : spanq
            wire q_empty;
            wire [`EF_SPAN_W-1:0] q_data;
            ef_spanq u_spanq (
                .clk(clk), .rst(rst),
                .in_valid(span_valid), .in_ready(span_ready), .in_data({span_y, span_x, span_len, span_mask}),
                .out_valid(cs_valid), .out_ready(cs_ready), .out_data(q_data), .empty(q_empty)
            );
            assign {cs_y, cs_x, cs_len, cs_mask} = q_data;
            assign cov_busy = cov_core_busy || !q_empty;
        end else begin : direct
            assign cs_valid   = span_valid;
            assign span_ready = cs_ready;
            assign {cs_y, cs_x, cs_len, cs_mask} = {span_y, span_x, span_len, span_mask};
            assign cov_busy   = cov_core_busy;
        end
    endgenerate

    ef_cov #(.NS(NS)) u_cov (
        .clk(clk), .rst(rst), .cfg_rgb(cfg_rgb), .cfg_alpha(cfg_alpha),
        .span_valid(cs_valid), .span_ready(cs_ready), .span_y(cs_y), .span_x(cs_x),
        .span_len(cs_len), .span_mask(cs_mask),
        .pix_valid(pix_valid), .pix_ready(pix_ready), .pix_y(pix_y), .pix_x(pix_x),
        .pix_alpha(pix_alpha), .pix_rgba(pix_rgba),
        .fb_re(fb_re), .fb_ry(fb_ry), .fb_rx(fb_rx), .fb_rdata(fb_rdata),
        .fb_we(fb_we), .fb_wy(fb_wy), .fb_wx(fb_wx), .fb_wdata(fb_wdata), .busy(cov_core_busy)
    );

    assign init_done = etm_init && slb_init;

    // The shape's eos et_wr has passed (set at its transfer, cleared when
    // DEC takes the next command).
    reg eos_seen;
    always @(posedge clk) begin
        if (rst)
            eos_seen <= 1'b0;
        else if (etw_take && et_wr_eos)
            eos_seen <= 1'b1;
        else if (cmd_valid && cmd_ready)
            eos_seen <= 1'b0;
    end
    assign shape_done = eos_seen && !aet_busy && slb_idle && !cov_busy;

    assign err = cfg_err || err_full;

    /* verilator lint_off UNUSEDSIGNAL */
    wire unused = slb_idle_unused ^ row_req_ready ^ shape_go ^ shape_any ^ (^row_first) ^ (^row_last);
    /* verilator lint_on UNUSEDSIGNAL */
endmodule
