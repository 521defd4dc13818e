// tb_dec: block-level testbench of rtl/ef_dec.v (DEC).
//
// Replays cmd.stim.hex at its stamped cycles (cycle 0 = the first cycle after
// reset, the FRAME command), records every seg transfer with its cycle as
// seg.actual.hex (docs/vectors.md section 3) for
// `edgeflag check seg.expected.hex seg.actual.hex --cycles`.
// Bit positions come from the generated header ef_ifaces.vh
// (`edgeflag vectors --rtl-headers`, docs/vectors.md section 8).
//
// The bench plays the sequencer's part in the drain rule (microarch 4 item
// 1): shape_done is high in the cycle the command after a SHAPE_END is
// stamped, and the bench asserts that DEC takes no command between a
// SHAPE_END and that cycle (cmd_ready low while shape_done is low), and that
// it is ready in every stamped cycle.  A stream DEC cannot take (stamps that
// go backwards, a FRAME over W_MAX x H_MAX) is refused before it runs.
//
// Parameters: W_MAX, H_MAX, NCMD; plusargs +cmd= +seg= (paths, required).
// Result line: "tb_dec: DONE ..." (exit 0) or "tb_dec: FAIL ..." (exit
// non-zero: a bench check, a refused stream, a file that cannot be opened, a
// missing plusarg; the file helpers are dv/tb/tb_files.vh).
`include "ef_ifaces.vh"
module tb_dec #(
    parameter W_MAX = 16384,
    parameter H_MAX = 16384,
    parameter NCMD  = 1
);
    localparam CWD = `EF_CMD_WORD_W;
    localparam SWD = `EF_SEG_WORD_W;

    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    reg        cmd_valid = 1'b0, shape_done = 1'b0;
    reg [3:0]  cmd_op = 4'd0;
    reg [23:0] cmd_a = 24'd0, cmd_b = 24'd0, cmd_c = 24'd0, cmd_d = 24'd0;
    wire       cmd_ready, seg_valid, seg_eos;
    wire [23:0] seg_xa, seg_ya, seg_xb, seg_yb;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [14:0] cfg_width, cfg_height;   // DEC's configuration outputs: not the bench's business
    wire [23:0] cfg_rgb;
    wire [7:0]  cfg_alpha;
    wire        cfg_rule, frame_start, frame_end;
    /* verilator lint_on UNUSEDSIGNAL */
    wire        cfg_err;

    ef_dec #(.W_MAX(W_MAX), .H_MAX(H_MAX)) dut (
        .clk(clk), .rst(rst),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_op(cmd_op), .cmd_a(cmd_a), .cmd_b(cmd_b),
        .cmd_c(cmd_c), .cmd_d(cmd_d), .shape_done(shape_done),
        .seg_valid(seg_valid), .seg_ready(1'b1), .seg_eos(seg_eos), .seg_xa(seg_xa), .seg_ya(seg_ya),
        .seg_xb(seg_xb), .seg_yb(seg_yb),
        .cfg_width(cfg_width), .cfg_height(cfg_height), .cfg_rule(cfg_rule), .cfg_rgb(cfg_rgb),
        .cfg_alpha(cfg_alpha), .frame_start(frame_start), .frame_end(frame_end), .cfg_err(cfg_err)
    );

    reg [CWD-1:0] cmd_mem [0:NCMD];
    reg [8*240-1:0] cmd_name, seg_name;
    integer ic, k, nseg, errors, fo;
    reg [47:0] cyc, last;
    reg        running, done, after_end;
    reg [SWD-1:0] word;

    // Present the command stamped c (if any) and the drain handshake.
    task present;
        input [47:0] c;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [CWD-1:0] cw;               // the payload; the stamp is compared apart
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            cmd_valid  <= 1'b0;
            shape_done <= 1'b0;
            if (ic < NCMD && cmd_mem[ic][CWD-1 -: 48] == c) begin
                cw = cmd_mem[ic];
                cmd_valid <= 1'b1;
                cmd_op <= cw[`EF_CMD_OP_MSB:`EF_CMD_OP_LSB];
                cmd_a  <= cw[`EF_CMD_A_MSB:`EF_CMD_A_LSB];
                cmd_b  <= cw[`EF_CMD_B_MSB:`EF_CMD_B_LSB];
                cmd_c  <= cw[`EF_CMD_C_MSB:`EF_CMD_C_LSB];
                cmd_d  <= cw[`EF_CMD_D_MSB:`EF_CMD_D_LSB];
                shape_done <= after_end;
                ic = ic + 1;
            end
        end
    endtask

    localparam TB_NAME = "tb_dec";
`include "tb_files.vh"

    initial begin
        tb_arg($value$plusargs("cmd=%s", cmd_name), "cmd=FILE (the command stream, cmd.stim.hex)");
        tb_arg($value$plusargs("seg=%s", seg_name), "seg=FILE (where the seg dump goes)");
        if (NCMD > 0)
            begin tb_need(cmd_name); $readmemh(cmd_name, cmd_mem, 0, NCMD - 1); end
        errors = 0;
        // Refuse what the hardware cannot take, naming the word (the line is
        // word + 5 in a file written by edgeflag: 4 header lines).
        for (k = 0; k < NCMD; k = k + 1) begin
            if (k > 0 && cmd_mem[k][CWD-1 -: 48] <= cmd_mem[k-1][CWD-1 -: 48]) begin
                $display("tb_dec: FAIL %0s: word %0d (line %0d): cycle stamp %0d does not increase (previous %0d)",
                         cmd_name, k, k + 5, cmd_mem[k][CWD-1 -: 48], cmd_mem[k-1][CWD-1 -: 48]);
                $fatal(1, "tb_dec: FAIL");
            end
            if (cmd_mem[k][`EF_CMD_OP_MSB:`EF_CMD_OP_LSB] == `EF_OP_FRAME &&
                (cmd_mem[k][`EF_CMD_A_MSB:`EF_CMD_A_LSB] > W_MAX || cmd_mem[k][`EF_CMD_B_MSB:`EF_CMD_B_LSB] > H_MAX)) begin
                $display("tb_dec: FAIL %0s: word %0d (line %0d): FRAME %0dx%0d is over W_MAX x H_MAX = %0dx%0d",
                         cmd_name, k, k + 5, cmd_mem[k][`EF_CMD_A_MSB:`EF_CMD_A_LSB],
                         cmd_mem[k][`EF_CMD_B_MSB:`EF_CMD_B_LSB], W_MAX, H_MAX);
                $fatal(1, "tb_dec: FAIL");
            end
        end
        ic = 0; nseg = 0; running = 1'b0; done = 1'b0; after_end = 1'b0; cyc = 0;
        last = NCMD > 0 ? cmd_mem[NCMD-1][CWD-1 -: 48] : 48'd0;
        tb_open_out(fo, seg_name, "seg", "DEC -> SETUP");
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
            if (cmd_valid && !cmd_ready) begin
                if (errors < 10) $display("tb_dec: cycle %0d: DEC not ready for the stamped command", cyc);
                errors = errors + 1;
            end
            if (!cmd_valid && after_end && cmd_ready && !shape_done) begin
                if (errors < 10) $display("tb_dec: cycle %0d: DEC ready before the shape drained", cyc);
                errors = errors + 1;
            end
            if (cmd_valid && cmd_ready)
                after_end = (cmd_op == `EF_OP_SHAPE_END);
            if (seg_valid) begin
                word = {SWD{1'b0}};
                word[SWD-1 -: 48] = cyc;
                word[`EF_SEG_EOS_MSB:`EF_SEG_EOS_LSB] = seg_eos;
                word[`EF_SEG_XA_MSB:`EF_SEG_XA_LSB] = seg_xa;
                word[`EF_SEG_YA_MSB:`EF_SEG_YA_LSB] = seg_ya;
                word[`EF_SEG_XB_MSB:`EF_SEG_XB_LSB] = seg_xb;
                word[`EF_SEG_YB_MSB:`EF_SEG_YB_LSB] = seg_yb;
                $fwrite(fo, "%h\n", word);
                nseg = nseg + 1;
            end
            if (cfg_err) begin
                $display("tb_dec: cycle %0d: cfg_err raised", cyc);
                errors = errors + 1;
            end
            if (cyc > last + 4) begin
                done <= 1'b1;
                $fclose(fo);
                if (errors == 0)
                    $display("tb_dec: DONE %0d commands, %0d segs, %0d cycles", NCMD, nseg, cyc);
                else
                    $display("tb_dec: FAIL %0d errors (%0d commands, %0d segs)", errors, NCMD, nseg);
                if (errors != 0) $fatal(1, "tb_dec: FAIL");
                $finish;
            end
            cyc <= cyc + 48'd1;
            present(cyc + 48'd1);
        end
    end
endmodule
