// tb_setup: block-level testbench of rtl/ef_setup.v (SETUP with
// its two-lane pipelined divider ef_div.v).
//
// Replays seg.expected.hex (the block's stimulus, docs/vectors.md section 1)
// at its stamped cycles with the canvas height of cmd.stim.hex's FRAME, and
// records every et_wr transfer with its cycle as et_wr.actual.hex for
// `edgeflag check et_wr.expected.hex et_wr.actual.hex --cycles`.  Cycle 0 is
// the first cycle after reset.  Bit positions come from the generated
// ef_ifaces.vh (docs/vectors.md section 8).  ETM is modelled as always ready
// (the reference); the bench asserts seg_ready in every stamped cycle.
//
// Parameters: NS, H_MAX, NSEG, NCMD; plusargs +seg_in= +cmd= +et_wr= (paths,
// required).  Result line: "tb_setup: DONE ..." (exit 0) or "tb_setup: FAIL
// ..." (exit non-zero: a bench check, a refused stream, a file that cannot be
// opened, a missing plusarg; the file helpers are dv/tb/tb_files.vh).
`include "ef_ifaces.vh"
module tb_setup #(
    parameter NS    = 8,
    parameter H_MAX = 16384,
    parameter NSEG  = 1,
    parameter NCMD  = 1
);
    localparam SWD = `EF_SEG_WORD_W;
    localparam CWD = `EF_CMD_WORD_W;
    localparam EWD = `EF_ET_WR_WORD_W;

    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    reg        seg_valid = 1'b0, seg_eos = 1'b0;
    reg [23:0] seg_xa = 24'd0, seg_ya = 24'd0, seg_xb = 24'd0, seg_yb = 24'd0;
    reg [14:0] cfg_height = 15'd1;
    wire       seg_ready, et_wr_valid, et_wr_eos, et_wr_dir;
    wire [13:0] et_wr_slot;
    wire [18:0] et_wr_r0, et_wr_r1;
    wire [24:0] et_wr_x;
    wire [23:0] et_wr_e, et_wr_rs, et_wr_dy;
    wire [29:0] et_wr_qs;

    ef_setup #(.NS(NS)) dut (
        .clk(clk), .rst(rst), .cfg_height(cfg_height),
        .seg_valid(seg_valid), .seg_ready(seg_ready), .seg_eos(seg_eos), .seg_xa(seg_xa), .seg_ya(seg_ya),
        .seg_xb(seg_xb), .seg_yb(seg_yb),
        .et_wr_valid(et_wr_valid), .et_wr_ready(1'b1), .et_wr_eos(et_wr_eos), .et_wr_slot(et_wr_slot),
        .et_wr_r0(et_wr_r0), .et_wr_r1(et_wr_r1), .et_wr_x(et_wr_x), .et_wr_e(et_wr_e), .et_wr_qs(et_wr_qs),
        .et_wr_rs(et_wr_rs), .et_wr_dy(et_wr_dy), .et_wr_dir(et_wr_dir)
    );

    reg [SWD-1:0] seg_mem [0:NSEG];
    reg [CWD-1:0] cmd_mem [0:NCMD];
    reg [8*240-1:0] seg_name, cmd_name, out_name;
    integer is, k, nout, errors, fo, nframe;
    reg [47:0] cyc, last;
    reg        running, done;
    reg [EWD-1:0] word;

    task present;
        input [47:0] c;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [SWD-1:0] w;                // the payload; the stamp is compared apart
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            seg_valid <= 1'b0;
            if (is < NSEG && seg_mem[is][SWD-1 -: 48] == c) begin
                w = seg_mem[is];
                seg_valid <= 1'b1;
                seg_eos <= w[`EF_SEG_EOS_MSB:`EF_SEG_EOS_LSB];
                seg_xa  <= w[`EF_SEG_XA_MSB:`EF_SEG_XA_LSB];
                seg_ya  <= w[`EF_SEG_YA_MSB:`EF_SEG_YA_LSB];
                seg_xb  <= w[`EF_SEG_XB_MSB:`EF_SEG_XB_LSB];
                seg_yb  <= w[`EF_SEG_YB_MSB:`EF_SEG_YB_LSB];
                is = is + 1;
            end
        end
    endtask

    localparam TB_NAME = "tb_setup";
`include "tb_files.vh"

    initial begin
        tb_arg($value$plusargs("seg_in=%s", seg_name), "seg_in=FILE (seg.expected.hex)");
        tb_arg($value$plusargs("cmd=%s", cmd_name), "cmd=FILE (cmd.stim.hex)");
        tb_arg($value$plusargs("et_wr=%s", out_name), "et_wr=FILE (where the et_wr dump goes)");
        tb_need(seg_name); tb_need(cmd_name);
        if (NSEG > 0) $readmemh(seg_name, seg_mem, 0, NSEG - 1);
        if (NCMD > 0) $readmemh(cmd_name, cmd_mem, 0, NCMD - 1);
        errors = 0; nframe = 0;
        // The canvas height: FRAME's b (one frame per vector set).
        for (k = 0; k < NCMD; k = k + 1)
            if (cmd_mem[k][`EF_CMD_OP_MSB:`EF_CMD_OP_LSB] == `EF_OP_FRAME) begin
                nframe = nframe + 1;
                if (cmd_mem[k][`EF_CMD_B_MSB:`EF_CMD_B_LSB] > H_MAX || cmd_mem[k][`EF_CMD_B_MSB:`EF_CMD_B_LSB] == 0) begin
                    $display("tb_setup: FAIL %0s: word %0d (line %0d): FRAME height %0d outside 1..H_MAX=%0d",
                             cmd_name, k, k + 5, cmd_mem[k][`EF_CMD_B_MSB:`EF_CMD_B_LSB], H_MAX);
                    $fatal(1, "tb_setup: FAIL");
                end
                cfg_height = cmd_mem[k][`EF_CMD_B_LSB +: 15];
            end
        if (nframe != 1) begin
            $display("tb_setup: FAIL %0s: %0d FRAME commands (expected 1)", cmd_name, nframe);
            $fatal(1, "tb_setup: FAIL");
        end
        for (k = 1; k < NSEG; k = k + 1)
            if (seg_mem[k][SWD-1 -: 48] <= seg_mem[k-1][SWD-1 -: 48]) begin
                $display("tb_setup: FAIL %0s: word %0d (line %0d): cycle stamp %0d does not increase",
                         seg_name, k, k + 5, seg_mem[k][SWD-1 -: 48]);
                $fatal(1, "tb_setup: FAIL");
            end
        is = 0; nout = 0; running = 1'b0; done = 1'b0; cyc = 0;
        last = NSEG > 0 ? seg_mem[NSEG-1][SWD-1 -: 48] : 48'd0;
        tb_open_out(fo, out_name, "et_wr", "SETUP -> ETM");
        repeat (3) @(posedge clk);
        @(negedge clk);       // no rising edge sees reset change
        rst = 1'b0;
    end

    always @(posedge clk) begin
        if (!running) begin
            if (!rst) begin
                running <= 1'b1;
                cyc <= 48'd0;
                present(48'd0);
            end
        end else if (!done) begin
            if (seg_valid && !seg_ready) begin
                if (errors < 10) $display("tb_setup: cycle %0d: SETUP not ready for the stamped seg", cyc);
                errors = errors + 1;
            end
            if (et_wr_valid) begin
                word = {EWD{1'b0}};
                word[EWD-1 -: 48] = cyc;
                word[`EF_ET_WR_EOS_MSB:`EF_ET_WR_EOS_LSB]   = et_wr_eos;
                word[`EF_ET_WR_SLOT_MSB:`EF_ET_WR_SLOT_LSB] = et_wr_slot;
                word[`EF_ET_WR_R0_MSB:`EF_ET_WR_R0_LSB]     = et_wr_r0;
                word[`EF_ET_WR_R1_MSB:`EF_ET_WR_R1_LSB]     = et_wr_r1;
                word[`EF_ET_WR_X_MSB:`EF_ET_WR_X_LSB]       = et_wr_x;
                word[`EF_ET_WR_E_MSB:`EF_ET_WR_E_LSB]       = et_wr_e;
                word[`EF_ET_WR_QS_MSB:`EF_ET_WR_QS_LSB]     = et_wr_qs;
                word[`EF_ET_WR_RS_MSB:`EF_ET_WR_RS_LSB]     = et_wr_rs;
                word[`EF_ET_WR_DY_MSB:`EF_ET_WR_DY_LSB]     = et_wr_dy;
                word[`EF_ET_WR_DIR_MSB:`EF_ET_WR_DIR_LSB]   = et_wr_dir;
                $fwrite(fo, "%h\n", word);
                nout = nout + 1;
            end
            if (cyc > last + `EF_L_SETUP + 4) begin
                done <= 1'b1;
                $fclose(fo);
                if (errors == 0)
                    $display("tb_setup: DONE NS=%0d: %0d segs, %0d et_wr, %0d cycles", NS, NSEG, nout, cyc);
                else
                    $display("tb_setup: FAIL NS=%0d: %0d errors", NS, errors);
                if (errors != 0) $fatal(1, "tb_setup: FAIL");
                $finish;
            end
            cyc <= cyc + 48'd1;
            present(cyc + 48'd1);
        end
    end
endmodule
