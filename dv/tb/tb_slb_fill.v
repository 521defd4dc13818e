// tb_slb_fill: block-level testbench of rtl/ef_slb_fill.v.
//
// Replays `plot.expected.hex` into the DUT at the stamped cycles (valid in
// the stamp's cycle, as the reference schedule presents it: docs/vectors.md
// section 1 names plot.expected.hex the filler's stimulus), takes the canvas
// width and each shape's rule from the FRAME and SHAPE commands of
// `cmd.stim.hex` (configuration registers, microarch 3.1), and records every
// span transfer (valid && ready at a rising edge) with its cycle in the hex
// layout of docs/vectors.md section 3: span.actual.hex, for
// `edgeflag check span.expected.hex span.actual.hex --cycles`.
//
// COV is modelled here, as a ready: the reference COV accepts a span of len
// pixels at cycle a and is ready again at cov_free = a + len (microarch
// section 4, item 6), so span_ready = (cycle >= cov_free).
//
// Cycle numbering: cycle 0 is the FRAME command (microarch 4); it is the
// first cycle after the DUT's reset sweep.  The transfer of cycle c happens
// at the c-th rising edge counted from there; inputs for cycle c are set
// with non-blocking assignments at the edge that ends cycle c-1.
//
// The bench also asserts what the schedule promises a cycle-exact DUT:
// plot_ready is high in every stamped plot cycle (ELASTIC = 0).  Optional EXP_FILE/NEXP:
// compare the spans in order with an expected file as they are produced
// (a quick self-check; `edgeflag check` is the judge).
//
// Parameters: NS, W_MAX, NPLOT, NCMD, PLOT_FILE, CMD_FILE, SPAN_FILE,
// EXP_FILE, NEXP, COV_LAG, ELASTIC (plusargs +plot= +cmd= +span= +exp= override the paths).
// Result line: "tb_slb_fill: PASS ..." (its own comparison, NEXP > 0) or
// "DONE ..." (exit 0), or "tb_slb_fill: FAIL ..." (exit non-zero: a bench
// check, a file that cannot be opened; the file helpers are dv/tb/tb_files.vh).
module tb_slb_fill #(
    parameter NS        = 8,
    parameter W_MAX     = 16384,
    parameter NPLOT     = 1,
    parameter NCMD      = 1,
    parameter NEXP      = 0,
    parameter PLOT_FILE = "plot.expected.hex",
    parameter CMD_FILE  = "cmd.stim.hex",
    parameter SPAN_FILE = "span.actual.hex",
    parameter EXP_FILE  = "",
    parameter COV_LAG   = 0,    // extra cycles per span in the COV model
    parameter ELASTIC   = 0     // 1: replay plots by valid/ready, not by stamp
    // run.sh uses COV_LAG = 1, ELASTIC = 1 as "an RTL with other timing":
    // --cycles must fail, --transactions must pass.
);
    localparam PW = 48 + 36;    // plot word
    localparam CWD = 48 + 100;  // cmd word
    localparam SW = 48 + 75;    // span word

    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    reg        plot_valid = 1'b0, plot_last = 1'b0, plot_dir = 1'b0;
    reg [13:0] plot_row = 14'd0;
    reg [4:0]  plot_s = 5'd0;
    reg [14:0] plot_q = 15'd0;
    reg        span_ready = 1'b0;
    reg [14:0] cfg_width = 15'd1;
    reg        cfg_rule = 1'b0;
    wire       plot_ready, span_valid, init_done, idle;
    /* verilator lint_off UNUSEDSIGNAL */
    wire       scan_done;               // the scan's end: the bench waits for idle
    /* verilator lint_on UNUSEDSIGNAL */
    wire [13:0] span_y, span_x;
    wire [14:0] span_len;
    wire [31:0] span_mask;

    ef_slb_fill #(.NS(NS), .W_MAX(W_MAX)) dut (
        .clk(clk), .rst(rst), .init_done(init_done),
        .cfg_width(cfg_width), .cfg_rule(cfg_rule),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot_last),
        .plot_row(plot_row), .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y),
        .span_x(span_x), .span_len(span_len), .span_mask(span_mask),
        .idle(idle), .scan_done(scan_done)
    );

    reg [PW-1:0]  plot_mem [0:NPLOT];
    reg [CWD-1:0] cmd_mem  [0:NCMD];
    reg [SW-1:0]  exp_mem  [0:NEXP];
    reg [8*240-1:0] plot_name, cmd_name, span_name, exp_name;

    integer ip, ic, nspan, errors, fo, nframe;
    // Coverage of the paths the schedule makes interesting (hierarchical
    // references into the DUT; printed with the result).
    integer n_stall, n_fwd, n_flush_span;
    reg [47:0] cyc, cov_free, last_stamp, limit;
    reg        running, done;
    reg [SW-1:0] word;

    // Present cycle c.  Fixed timing (ELASTIC = 0): the plot stamped c, and
    // the commands stamped <= c (a register write takes effect at its
    // transfer; a shape's plots come long after its SHAPE command).
    // Elastic (ELASTIC = 1, for a DUT or COV with other timing): a plot is
    // presented from its stamp on and held, payload stable, until the DUT
    // takes it; a command is applied only once every plot stamped before it
    // has been taken, so order, not time, decides which shape a plot is in.
    // hold: the plot presented in cycle c-1 was not taken.
    task present;
        input [47:0] c;
        input        hold;
        reg [PW-1:0] pw;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [CWD-1:0] cw;               // the FRAME and SHAPE fields are what it needs
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            while (ic < NCMD && cmd_mem[ic][CWD-1 -: 48] <= c && !hold &&
                   (ip >= NPLOT || cmd_mem[ic][CWD-1 -: 48] < plot_mem[ip][PW-1 -: 48])) begin
                cw = cmd_mem[ic];
                case (cw[99:96])
                    4'd1: begin
                        cfg_width <= cw[86:72];
                        nframe = nframe + 1;
                        if (cw[95:72] > W_MAX || cw[95:72] == 0) begin
                            $display("tb_slb_fill: FRAME width %0d outside 1..W_MAX=%0d", cw[95:72], W_MAX);
                            errors = errors + 1;
                        end
                    end
                    4'd2: cfg_rule <= cw[72];
                    default: ;
                endcase
                ic = ic + 1;
            end
            if (!hold) begin
                plot_valid <= 1'b0;
                if (ip < NPLOT) begin
                    pw = plot_mem[ip];
                    if (pw[PW-1 -: 48] < c && !ELASTIC) begin
                        $display("tb_slb_fill: plot %0d stamped %0d is out of order (now %0d)", ip, pw[PW-1 -: 48], c);
                        errors = errors + 1;
                        ip = ip + 1;
                    end else if (pw[PW-1 -: 48] <= c) begin
                        plot_valid <= 1'b1;
                        plot_last  <= pw[35];
                        plot_row   <= pw[34:21];
                        plot_s     <= pw[20:16];
                        plot_q     <= pw[15:1];
                        plot_dir   <= pw[0];
                        if (pw[20:16] >= NS) begin
                            $display("tb_slb_fill: plot %0d: sample %0d >= NS", ip, pw[20:16]);
                            errors = errors + 1;
                        end
                        ip = ip + 1;
                    end
                end
            end
            span_ready <= (c >= cov_free);
        end
    endtask

    localparam TB_NAME = "tb_slb_fill";
`include "tb_files.vh"

    initial begin
        // (string parameters into the name registers: zero-extended, as meant)
        /* verilator lint_off WIDTH */
        plot_name = PLOT_FILE; cmd_name = CMD_FILE; span_name = SPAN_FILE; exp_name = EXP_FILE;
        if (!$value$plusargs("plot=%s", plot_name)) plot_name = PLOT_FILE;
        if (!$value$plusargs("cmd=%s", cmd_name))   cmd_name = CMD_FILE;
        if (!$value$plusargs("span=%s", span_name)) span_name = SPAN_FILE;
        if (!$value$plusargs("exp=%s", exp_name))   exp_name = EXP_FILE;
        /* verilator lint_on WIDTH */
        if (NPLOT > 0)
            begin tb_need(plot_name); $readmemh(plot_name, plot_mem, 0, NPLOT - 1); end
        if (NCMD > 0)
            begin tb_need(cmd_name); $readmemh(cmd_name, cmd_mem, 0, NCMD - 1); end
        if (NEXP > 0) begin
            if (exp_name == 0) begin
                $display("tb_slb_fill: FAIL NEXP > 0 needs EXP_FILE or +exp=");
                $fatal(1, "tb_slb_fill: FAIL");
            end
            $readmemh(exp_name, exp_mem, 0, NEXP - 1);
        end
        ip = 0; ic = 0; nspan = 0; errors = 0; nframe = 0;
        n_stall = 0; n_fwd = 0; n_flush_span = 0;
        cov_free = 0; running = 1'b0; done = 1'b0; cyc = 0;
        last_stamp = NPLOT > 0 ? plot_mem[NPLOT-1][PW-1 -: 48] : 48'd0;
        // Generous: every row could scan W_MAX+2 cells and wait for COV.
        limit = last_stamp + 48'd4 * (W_MAX + 2) + 48'd100000;
        // `edgeflag check` refuses an empty file (it cannot tell "no spans"
        // from "dump never flushed"), so the dump always starts with a
        // comment naming its interface (docs/vectors.md 3 allows it).
        tb_open_out(fo, span_name, "span", "FILL -> COV");
        repeat (3) @(posedge clk);
        @(negedge clk);       // no rising edge sees reset change
        rst = 1'b0;
    end

    always @(posedge clk) begin
        if (!running) begin
            if (!rst && init_done) begin
                running <= 1'b1;
                cyc     <= 48'd0;
                present(48'd0, 1'b0);
            end
        end else if (!done) begin
            // The transfers of cycle cyc happen at this edge.
            if (plot_valid && !plot_ready && !ELASTIC) begin
                if (errors < 10)
                    $display("tb_slb_fill: cycle %0d: DUT not ready for the stamped plot", cyc);
                errors = errors + 1;
            end
            if (span_valid && !span_ready)
                n_stall = n_stall + 1;
            if (dut.fwd && (dut.s2_op == 2'd1 || dut.s2_op == 2'd2) && !(span_valid && !span_ready))
                n_fwd = n_fwd + 1;
            if (span_valid && span_ready && dut.s2_op == 2'd3)
                n_flush_span = n_flush_span + 1;
            if (span_valid && span_ready) begin
                word = {cyc, span_y, span_x, span_len, span_mask};
                $fwrite(fo, "%h\n", word);
                if (nspan < NEXP && exp_mem[nspan] !== word) begin
                    if (errors < 10)
                        $display("tb_slb_fill: span %0d: got %h, expected %h", nspan, word, exp_mem[nspan]);
                    errors = errors + 1;
                end
                cov_free = cyc + {33'd0, span_len} + COV_LAG;
                nspan = nspan + 1;
            end
            if (ip >= NPLOT && !plot_valid && idle) begin
                done <= 1'b1;
                $fclose(fo);
                if (NEXP > 0 && nspan != NEXP) begin
                    $display("tb_slb_fill: %0d spans, expected %0d", nspan, NEXP);
                    errors = errors + 1;
                end
                if (nframe != 1) begin
                    $display("tb_slb_fill: %0d FRAME commands (expected 1)", nframe);
                    errors = errors + 1;
                end
                $display("tb_slb_fill: coverage: %0d cycles of COV back-pressure, %0d forwarded reads, %0d spans closed by the flush",
                         n_stall, n_fwd, n_flush_span);
                // PASS after its own comparison with the expected spans
                // (NEXP > 0); else DONE: the dump is for edgeflag check
                if (errors == 0)
                    $display("tb_slb_fill: %0s NS=%0d: %0d plots, %0d spans, %0d cycles%0s", NEXP > 0 ? "PASS" : "DONE",
                             NS, NPLOT, nspan, cyc, NEXP > 0 ? " (self-check against the expected spans: equal)" : "");
                else
                    $display("tb_slb_fill: FAIL NS=%0d: %0d errors (%0d plots, %0d spans, %0d cycles)",
                             NS, errors, NPLOT, nspan, cyc);
                if (errors != 0) $fatal(1, "tb_slb_fill: FAIL");
                $finish;
            end else if (cyc > limit) begin
                $display("tb_slb_fill: FAIL timeout at cycle %0d (plot %0d of %0d)", cyc, ip, NPLOT);
                $fclose(fo);
                $fatal(1, "tb_slb_fill: FAIL");
            end
            cyc <= cyc + 48'd1;
            present(cyc + 48'd1, ELASTIC && plot_valid && !plot_ready);
        end
    end
endmodule
