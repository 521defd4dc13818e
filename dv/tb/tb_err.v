// tb_err: the DUT's own limit checks, which tb_raster cannot reach (it refuses a
// stream over the build's limits before the DUT sees it): ef_raster's sticky
// `err` and its clamped configuration (docs/microarch.md 3.1, DEC's "Canvas
// limits"; ETM's E_MAX records per shape), under Icarus and Verilator.
//
//   1. after reset err is low and, before any FRAME, cfg_width x
//      cfg_height is 1 x 1 (DEC's reset value: no memory addressed out of
//      range before the first FRAME);
//   2. a FRAME of width 0, W_MAX + 1, height 0 or H_MAX + 1 raises err, and
//      cfg_width x cfg_height hold the clamped 1 x 1; err stays high through
//      a following good FRAME (sticky), whose size is then taken; reset
//      clears it;
//   3. a FRAME of exactly W_MAX x H_MAX (and 1 x 1) leaves err low and is
//      taken as it is;
//   4. two shapes of exactly E_MAX edges leave err low (the count restarts
//      with each shape); a shape of E_MAX + 1 raises it.
// Parameters: NS, W_MAX, H_MAX, E_MAX (small: the checks take a few
// thousand cycles).  Result, the last line: "tb_err: PASS N checks" (exit 0)
// or "tb_err: FAIL ..." ($fatal: non-zero exit).  Writes no file.
`include "ef_ifaces.vh"
module tb_err #(
    parameter NS    = 8,
    parameter W_MAX = 16,
    parameter H_MAX = 16,
    parameter E_MAX = 8
);
    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    reg         cmd_valid = 1'b0;
    reg  [`EF_CMD_OP_W-1:0] cmd_op = 0;
    reg  [`EF_CMD_A_W-1:0]  cmd_a = 0;
    reg  [`EF_CMD_B_W-1:0]  cmd_b = 0;
    reg  [`EF_CMD_C_W-1:0]  cmd_c = 0;
    reg  [`EF_CMD_D_W-1:0]  cmd_d = 0;
    wire        cmd_ready, init_done, err;
    wire [14:0] cfg_width, cfg_height;
    /* verilator lint_off UNUSEDSIGNAL */
    wire        pix_valid, fb_re, fb_we, frame_start, frame_end;
    wire [`EF_PIX_Y_W-1:0] pix_y, fb_ry, fb_wy;
    wire [`EF_PIX_X_W-1:0] pix_x, fb_rx, fb_wx;
    wire [`EF_PIX_ALPHA_W-1:0] pix_alpha;
    wire [`EF_PIX_RGBA_W-1:0] pix_rgba, fb_wdata;
    wire        seg_valid, seg_ready, seg_eos;
    wire [`EF_SEG_XA_W-1:0] seg_xa;
    wire [`EF_SEG_YA_W-1:0] seg_ya;
    wire [`EF_SEG_XB_W-1:0] seg_xb;
    wire [`EF_SEG_YB_W-1:0] seg_yb;
    wire        et_wr_valid, et_wr_ready, et_wr_eos, et_wr_dir;
    wire [`EF_ET_WR_SLOT_W-1:0] et_wr_slot;
    wire [`EF_ET_WR_R0_W-1:0] et_wr_r0;
    wire [`EF_ET_WR_R1_W-1:0] et_wr_r1;
    wire [`EF_ET_WR_X_W-1:0] et_wr_x;
    wire [`EF_ET_WR_E_W-1:0] et_wr_e;
    wire [`EF_ET_WR_QS_W-1:0] et_wr_qs;
    wire [`EF_ET_WR_RS_W-1:0] et_wr_rs;
    wire [`EF_ET_WR_DY_W-1:0] et_wr_dy;
    wire        et_rd_valid, et_rd_ready;
    wire [`EF_ET_RD_ROW_W-1:0] et_rd_row;
    wire [`EF_ET_RD_EID_W-1:0] et_rd_eid;
    wire        plot_valid, plot_ready, plot_last, plot_dir;
    wire [`EF_PLOT_ROW_W-1:0] plot_row;
    wire [`EF_PLOT_S_W-1:0] plot_s;
    wire [`EF_PLOT_Q_W-1:0] plot_q;
    wire        span_valid, span_ready;
    wire [`EF_SPAN_Y_W-1:0] span_y;
    wire [`EF_SPAN_X_W-1:0] span_x;
    wire [`EF_SPAN_LEN_W-1:0] span_len;
    wire [`EF_SPAN_MASK_W-1:0] span_mask;
    /* verilator lint_on UNUSEDSIGNAL */
    // tied off: every pixel taken at once, the frame memory reads as 0
    wire       pix_ready = 1'b1;
    wire [`EF_PIX_RGBA_W-1:0] fb_rdata = {`EF_PIX_RGBA_W{1'b0}};

    ef_raster #(.NS(NS), .W_MAX(W_MAX), .H_MAX(H_MAX), .E_MAX(E_MAX)) dut (
`include "ef_raster_conn.vh"
    );

    localparam [`EF_CMD_OP_W-1:0] OP_FRAME = `EF_OP_FRAME, OP_SHAPE = `EF_OP_SHAPE, OP_EDGE = `EF_OP_EDGE,
                                  OP_SHAPE_END = `EF_OP_SHAPE_END, OP_FRAME_END = `EF_OP_FRAME_END;
    integer checks = 0, fails = 0;

    task check;
        input ok;
        input [8*72-1:0] what;
        begin
            checks = checks + 1;
            if (!ok) begin
                fails = fails + 1;
                $display("tb_err: FAIL %0s (err %b, cfg %0d x %0d)", what, err, cfg_width, cfg_height);
            end
        end
    endtask

    // reset, then wait for the memories' initialisation
    task do_reset;
        integer n;
        begin
            @(negedge clk);
            rst = 1'b1; cmd_valid = 1'b0;
            repeat (3) @(negedge clk);
            rst = 1'b0;
            n = 0;
            while (!init_done && n < 100000) begin @(negedge clk); n = n + 1; end
            if (!init_done) begin $display("tb_err: FAIL init_done never rose"); $fatal(1, "tb_err: FAIL"); end
        end
    endtask

    // one command: presented at a falling edge, transferred at the rising edge after
    // the first falling edge with cmd_ready high (it depends on registers only)
    task send;
        input [`EF_CMD_OP_W-1:0] op;
        input [23:0] a, b, c, d;
        integer n;
        begin
            @(negedge clk);
            cmd_valid = 1'b1; cmd_op = op; cmd_a = a; cmd_b = b; cmd_c = c; cmd_d = d;
            n = 0;
            while (!cmd_ready && n < 100000) begin @(negedge clk); n = n + 1; end
            if (!cmd_ready) begin $display("tb_err: FAIL the DUT never takes op %0d", op); $fatal(1, "tb_err: FAIL"); end
            @(negedge clk);
            cmd_valid = 1'b0;
        end
    endtask

    // a shape of n copies of one edge (pixels 1..3 across, rows 1..5 down: 1/256 units)
    task shape;
        input integer n;
        integer i;
        begin
            send(OP_SHAPE, 24'd0, 24'hff0000, 24'd255, 24'd0);
            for (i = 0; i < n; i = i + 1)
                send(OP_EDGE, 24'd256, 24'd256, 24'd768, 24'd1280);
            send(OP_SHAPE_END, 24'd0, 24'd0, 24'd0, 24'd0);
            // DEC is ready again when the shape has drained (docs/microarch.md 4 item 1)
            repeat (2) @(negedge clk);
            i = 0;
            while (!cmd_ready && i < 100000) begin @(negedge clk); i = i + 1; end
            if (!cmd_ready) begin $display("tb_err: FAIL the shape never drains"); $fatal(1, "tb_err: FAIL"); end
        end
    endtask

    task bad_frame;
        input [23:0] a, b;
        begin
            do_reset;
            check(!err, "err low after reset");
            send(OP_FRAME, a, b, 24'd0, 24'd0);
            repeat (2) @(negedge clk);
            check(err, "a FRAME over the limits (or of size 0) raises err");
            check(cfg_width == 15'd1 && cfg_height == 15'd1, "a FRAME over the limits: the configuration is 1 x 1");
            send(OP_FRAME, 24'd3, 24'd2, 24'd0, 24'd0);
            repeat (2) @(negedge clk);
            check(err, "err is sticky through a good FRAME");
            check(cfg_width == 15'd3 && cfg_height == 15'd2, "the good FRAME after a bad one is taken (3 x 2)");
        end
    endtask

    initial begin : main
        do_reset;
        check(!err && cfg_width == 15'd1 && cfg_height == 15'd1, "after reset, before any FRAME: err low, 1 x 1");
        bad_frame(24'd0, 24'd5);
        bad_frame(W_MAX + 1, 24'd5);
        bad_frame(24'd5, 24'd0);
        bad_frame(24'd5, H_MAX + 1);
        bad_frame(24'hffffff, 24'hffffff);
        do_reset;
        check(!err, "reset clears err");
        send(OP_FRAME, W_MAX, H_MAX, 24'd0, 24'd0);
        repeat (2) @(negedge clk);
        check(!err, "a FRAME of exactly W_MAX x H_MAX leaves err low");
        check(cfg_width == W_MAX && cfg_height == H_MAX, "a FRAME of W_MAX x H_MAX is taken as it is");
        shape(E_MAX);
        check(!err, "a shape of exactly E_MAX edges leaves err low");
        shape(E_MAX);
        check(!err, "a second shape of E_MAX edges leaves err low (the count restarts)");
        shape(E_MAX + 1);
        check(err, "a shape of E_MAX + 1 edges raises err");
        send(OP_FRAME_END, 24'd0, 24'd0, 24'd0, 24'd0);
        do_reset;
        send(OP_FRAME, 24'd1, 24'd1, 24'd0, 24'd0);
        repeat (2) @(negedge clk);
        check(!err && cfg_width == 15'd1 && cfg_height == 15'd1, "a FRAME of 1 x 1 is good");
        if (fails == 0) begin
            $display("tb_err: PASS %0d checks (NS %0d, W_MAX %0d, H_MAX %0d, E_MAX %0d)", checks, NS, W_MAX, H_MAX, E_MAX);
            $finish;
        end else begin
            $display("tb_err: FAIL %0d of %0d checks", fails, checks);
            $fatal(1, "tb_err: FAIL");
        end
    end
endmodule
