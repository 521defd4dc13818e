// tb_lockstep: an RTL and the C reference model in lockstep through DPI-C
// (ef_model_pkg.sv, with the generated ef_ifaces_pkg.sv; docs/dpi.md).  The
// example to copy.
//
// The model is the scoreboard.  The bench reads a command stream (the cmd
// payloads of a cmd.stim.hex from `edgeflag vectors`; any source of commands
// would do), feeds each command to the model as the bench needs its
// predictions, and at every transfer (valid && ready at a rising edge) on a
// DUT interface it hands the model the actual transaction with its cycle
// (ef_dpi_expect).  The first difference stops the simulation with one line:
//
//   tb_lockstep: FAIL at time T ns, cycle C: IFACE: cycle C, ...: fields differ:
//       expected f=v ...; actual f=v* ...
//
// naming the simulation time, the interface and every decoded field of both
// (a `*` marks each differing actual field), and the exit status is non-zero.
//
// DUT.  Until the whole pipeline (ef_raster: cmd in, pix out) is in the tree,
// the DUT is the scanline buffer + filler block (rtl_vectors/rtl/ef_slb_fill.v):
// its input, `plot`, comes from the model's expected plot transactions at
// their stamped cycles, its configuration (canvas width, each shape's rule)
// from the model's cmd transactions, and its output, `span`, is checked
// against the model.  Everything that names the DUT is between the "DUT"
// markers below; for ef_raster the stimulus goes to its cmd port instead
// (drive cmd from `stim`, check seg/et_wr/et_rd/plot/span/pix the way span is
// checked here): see docs/dpi.md, "switching the DUT".
//
// Cycle numbering is the vectors': cycle 0 is the FRAME command's transfer,
// the first cycle after the DUT's reset sweep (init_done).  Inputs for cycle
// c are set with non-blocking assignments at the edge that ends cycle c-1.
//
// Plusargs: +cmd=FILE (required), +samples=N (8), +rule=scene|nonzero|evenodd,
// +timeout=CYCLES, +cov_lag=N.  Parameters: NS, W_MAX, H_MAX, E_MAX (the DUT's).
// A fault (build-time, to prove the loop fails): -DEF_TB_FAULT_SPAN_SHORT cuts
// every span the DUT produces one pixel short.  +cov_lag=N makes the bench's
// COV take N cycles more per span (an environment with other timing: the
// DUT's spans come late, and the cycle check must say so).
// Result: "tb_lockstep: PASS ..." or "tb_lockstep: FAIL ..." and $fatal.
module tb_lockstep #(
    parameter int NS    = 8,
    parameter int W_MAX = 1024,
    parameter int H_MAX = 1024,
    parameter int E_MAX = 1 << 22
);
    import ef_ifaces_pkg::*;   // generated: edgeflag vectors --rtl-headers
    import ef_model_pkg::*;

    bit clk = 1'b0;
    always #5 clk = ~clk;
    bit rst = 1'b1;
    int rst_cycles = 3;         // reset held for the first edges
    always @(posedge clk)
        if (rst_cycles > 0) begin
            rst_cycles <= rst_cycles - 1;
            rst <= rst_cycles > 1;
        end

    chandle model;
    bit [CMD_W-1:0] stim[$];    // the command stream, in order
    string stim_name;
    int    stim_line[$];              // its line numbers, for messages
    int    fed = 0;                   // commands fed to the model so far
    longint cyc = 0;                  // the cycle being presented
    longint timeout = 0;
    bit     running = 1'b0;
    longint n_checked[EF_IF_COUNT];

    // ------------------------------------------------------------ the model
    bit done = 1'b0;
    function automatic void die(string what);
        done = 1'b1;
        $display("tb_lockstep: FAIL at time %t, cycle %0d: %s", $time, cyc, what);
        $fatal(1, "tb_lockstep: stopped at the first mismatch");
    endfunction

    // Feeds the next command to the model; false when the stream is over.
    function automatic bit feed_one();
        int st;
        if (fed >= stim.size())
            return 1'b0;
        st = ef_dpi_cmd(model, stim[fed]);
        if (st != EF_MS_OK)
            die($sformatf("%s:%0d: the model refused the command: %s", stim_name, stim_line[fed],
                          ef_dpi_message(model)));
        fed++;
        return 1'b1;
    endfunction

    // The next expected transaction of iface, feeding commands until the
    // model has one: EF_MS_OK (and cycle, payload) or EF_MS_END.
    function automatic int next_expected(int iface, output longint c, output ef_payload_t p, input bit pop);
        int st;
        forever begin
            // A call with side effects never goes in a ?: or after && / ||:
            // both sides of such an expression ran here under Verilator 5.006.
            if (pop)
                st = ef_dpi_pop(model, iface, c, p);
            else
                st = ef_dpi_peek(model, iface, c, p);
            if (st != EF_MS_EMPTY)
                return st;
            if (!feed_one())
                return EF_MS_END;   // the stream ended without FRAME_END: nothing more will come
        end
    endfunction

    // The scoreboard step for one transfer the DUT made on iface at cycle c.
    function automatic void check(int iface, longint c, ef_payload_t actual);
        int st;
        bit more;
        forever begin
            st = ef_dpi_expect(model, iface, c, actual, 1);
            if (st != EF_MS_EMPTY)
                break;
            more = feed_one();   // (not inside the condition: see next_expected)
            if (!more)
                break;
        end
        if (st == EF_MS_EMPTY)
            die($sformatf("%s: the DUT produced a transaction but the command stream has ended without FRAME_END",
                          ef_dpi_iface_name(iface)));
        if (st != EF_MS_OK)
            die(ef_dpi_message(model));
        n_checked[iface]++;
    endfunction

    // ------------------------------------------------------------ DUT
    // ef_slb_fill: plot in, span out, configuration registers.
    bit        plot_valid = 1'b0;
    plot_t  plot = '0;
    bit        span_ready = 1'b0;
    bit [14:0] cfg_width = 15'd1;
    bit        cfg_rule = 1'b0;
    wire       plot_ready, span_valid, init_done, idle;
    wire [13:0] span_y, span_x;
    wire [14:0] span_len_dut, span_len;
    wire [31:0] span_mask;

    ef_slb_fill #(.NS(NS), .W_MAX(W_MAX)) dut (
        .clk(clk), .rst(rst), .init_done(init_done),
        .cfg_width(cfg_width), .cfg_rule(cfg_rule),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot.last),
        .plot_row(plot.row), .plot_s(plot.s), .plot_q(plot.q), .plot_dir(plot.dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y),
        .span_x(span_x), .span_len(span_len_dut), .span_mask(span_mask),
        .idle(idle)
    );
`ifdef EF_TB_FAULT_SPAN_SHORT
    assign span_len = span_len_dut - 15'd1;   // injected fault: every span one pixel short
`else
    assign span_len = span_len_dut;
`endif

    // COV, the span's consumer, as the reference schedule has it: it takes a
    // span of len pixels at cycle a and is ready again at a + len
    // (docs/microarch.md 4, item 6).
    longint cov_free = 0;
    longint cov_lag = 0;                      // +cov_lag=N: N cycles more per span

    // The transfers of cycle cyc, seen at the edge that ends it.
    function automatic void observe();
        if (plot_valid && !plot_ready)
            die($sformatf("plot: the DUT is not ready in the plot's stamped cycle (reference schedule): %p", plot));
        if (span_valid && span_ready) begin
            check(IF_SPAN, cyc, ef_payload_t'(span_t'{y: span_y, x: span_x, len: span_len, mask: span_mask}));
            cov_free = cyc + longint'(span_len) + cov_lag;
        end
    endfunction

    // The DUT's inputs for cycle c: commands (configuration registers) and
    // the plot stamped c, from the model.
    function automatic void present(longint c);
        longint t;
        ef_payload_t p;
        cmd_t cmd;
        while (next_expected(IF_CMD, t, p, 1'b0) == EF_MS_OK && t <= c) begin
            void'(ef_dpi_pop(model, IF_CMD, t, p));
            cmd = cmd_t'(p[CMD_W-1:0]);
            if (cmd.op == OP_FRAME) cfg_width <= cmd.a[14:0];
            if (cmd.op == OP_SHAPE) cfg_rule <= cmd.a[0];
        end
        plot_valid <= 1'b0;
        if (next_expected(IF_PLOT, t, p, 1'b0) == EF_MS_OK && t == c) begin
            void'(ef_dpi_pop(model, IF_PLOT, t, p));
            plot_valid <= 1'b1;
            plot <= plot_t'(p[PLOT_W-1:0]);
        end
        span_ready <= c >= cov_free;
    endfunction

    // Over when every command is in, the model has nothing more to drive and
    // the DUT has nothing in flight.
    function automatic bit finished();
        longint t;
        ef_payload_t p;
        return next_expected(IF_PLOT, t, p, 1'b0) == EF_MS_END && fed == stim.size() && !plot_valid && idle;
    endfunction
    localparam int CHECKED[1] = '{IF_SPAN};   // the interfaces this DUT shows
    // What the model keeps: what the bench drives from it and what it checks.
    localparam int KEEP = (1 << IF_CMD) | (1 << IF_PLOT) | (1 << IF_SPAN);
    // ------------------------------------------------------------ end of DUT

    // ------------------------------------------------------------ stimulus
    // The stamps are not used (the model times the commands), but a file
    // whose stamps go backwards is not a command stream: refused.
    function automatic void read_stim(string name);
        int fd, line = 0, n;
        string s;
        bit [48+CMD_W-1:0] word;
        bit [47:0] last = '0;
        fd = $fopen(name, "r");
        if (fd == 0) begin
            $display("tb_lockstep: FAIL cannot open %s", name);
            $fatal(1, "tb_lockstep: no stimulus");
        end
        while ($fgets(s, fd) > 0) begin
            line++;
            if (s.len() == 0 || s[0] == "/" || s[0] == "\n")
                continue;
            n = $sscanf(s, "%h", word);
            if (n != 1) begin
                $display("tb_lockstep: FAIL %s:%0d: not a hex word", name, line);
                $fatal(1, "tb_lockstep: bad stimulus");
            end
            if (stim.size() > 0 && word[48+CMD_W-1:CMD_W] <= last) begin
                $display("tb_lockstep: FAIL %s:%0d: cycle stamp %0d does not follow the previous one, %0d",
                         name, line, word[48+CMD_W-1:CMD_W], last);
                $fatal(1, "tb_lockstep: bad stimulus");
            end
            last = word[48+CMD_W-1:CMD_W];
            stim.push_back(word[CMD_W-1:0]);   // the payload; the model decides the timing
            stim_line.push_back(line);
        end
        $fclose(fd);
    endfunction

    initial begin
        int samples = NS, rule = EF_MS_RULE_CMD, st;
        string rs;
        $timeformat(-9, 0, " ns", 0);
        if (!$value$plusargs("cmd=%s", stim_name)) begin
            $display("tb_lockstep: FAIL no +cmd=FILE (a cmd.stim.hex)");
            $fatal(1, "tb_lockstep: usage");
        end
        if ($value$plusargs("rule=%s", rs))
            rule = rs == "nonzero" ? 0 : rs == "evenodd" ? 1 : EF_MS_RULE_CMD;
        if (!$value$plusargs("cov_lag=%d", cov_lag))
            cov_lag = 0;
        if (!$value$plusargs("timeout=%d", timeout))
            timeout = 64'd50_000_000;
        if (ef_check_layout() != 0)
            $fatal(1, "tb_lockstep: ef_ifaces_pkg (generated by another edgeflag?) differs from the linked model's interface table");
        model = ef_dpi_create(samples, W_MAX, H_MAX, E_MAX, rule, KEEP, st);
        if (st != EF_MS_OK)
            $fatal(1, "tb_lockstep: ef_dpi_create: %s", ef_dpi_strerror(st));
        read_stim(stim_name);
        foreach (n_checked[i]) n_checked[i] = 0;
    end

    // done: the run has ended (PASS or the first mismatch).  $finish ends the
    // simulation after the current time step, so nothing may run after it
    // in this block (the model is destroyed only in the final block).
    always @(posedge clk) begin
        bit fin;
        int st;
        if (done) begin
            // nothing: the simulation is ending
        end else if (!running) begin
            if (!rst && init_done) begin
                running <= 1'b1;
                cyc = 0;
                present(0);
            end
        end else begin
            observe();
            fin = 1'b0;
            if (!done)
                fin = finished();    // (its own statement: it feeds the model)
            if (fin) begin
                foreach (CHECKED[k]) begin
                    st = ef_dpi_expect_done(model, CHECKED[k]);
                    if (st != EF_MS_OK && !done)
                        die(ef_dpi_message(model));
                end
                if (!done) begin
                    $display("tb_lockstep: PASS NS=%0d: %0d commands, %0d spans checked in lockstep, frame of %0d cycles (model), %0d simulated",
                             NS, fed, n_checked[IF_SPAN], ef_dpi_frame_cycles(model), cyc + 1);
                    done = 1'b1;
                    $finish;
                end
            end else if (!done) begin
                if (cyc > timeout)
                    die($sformatf("timeout: %0d commands of %0d fed", fed, stim.size()));
                cyc = cyc + 1;
                present(cyc);
            end
        end
    end

    final
        if (model != null)
            ef_dpi_destroy(model);
endmodule
