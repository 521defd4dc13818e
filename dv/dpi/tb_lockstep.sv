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
// DUT.  By default the whole pipeline, ef_raster (rtl/, from the
// RTL branch): the bench drives its cmd port with the model's cmd
// transactions at their stamped cycles (the stimulus words, with the rule of
// +rule= when it is overridden), provides the frame memory, and checks all
// seven interfaces (cmd, seg, et_wr, et_rd, plot, span, pix) on every
// transfer.  With -DEF_TB_DUT_SLB the DUT is the scanline buffer + filler
// block alone (ef_slb_fill.v): its plots come from the model's expected plot
// transactions at their stamps, its configuration from the model's cmd
// transactions, and its spans are checked.  With -DEF_FAST the DUT is
// ef_raster with SCHEDULE = 1 (the overlap schedule, docs/microarch.md
// section 6) checked in transaction order against the model's reference
// schedule: every
// transaction's payload and per-interface order, not its cycle; the bench
// presents each command as soon as the DUT can take it (not at the model's
// stamp), and the frame length printed is the DUT's.  Everything that names
// a DUT is between the "DUT" markers below (docs/dpi.md, "the DUT").
//
// Cycle numbering is the vectors': cycle 0 is the FRAME command's transfer,
// the first cycle after the DUT's reset sweep (init_done).  Inputs for cycle
// c are set with non-blocking assignments at the edge that ends cycle c-1.
//
// Plusargs: +cmd=FILE (required), +rule=scene|nonzero|evenodd, +timeout=CYCLES,
// +cov_lag=N.  Parameters: NS, W_MAX, H_MAX, E_MAX (the DUT's; E_MAX sizes
// ef_raster's edge memories).
// A fault to see the loop fail: build from the RTL variant
// `dv/rtl-variant.sh DIR span` (dv/faults/span.sed), which cuts every span of
// two or more pixels one short.  With the SLB + FILL DUT,
// +cov_lag=N makes the bench's COV take N cycles more per span (an
// environment with other timing: the spans come late, and the cycle check
// must say so).
// Result: "tb_lockstep: PASS ..." or "tb_lockstep: FAIL ..." and $fatal.
module tb_lockstep #(
    parameter int NS    = 8,
    parameter int W_MAX = 1024,
    parameter int H_MAX = 1024,
    parameter int E_MAX = 4096
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

    // The frame's length as the DUT's transfers give it: one past the last
    // transfer on any checked interface (docs/microarch.md section 4, item 7).
    longint frame_len = 0;

    // The scoreboard step for one transfer the DUT made on iface at cycle c.
`ifdef EF_FAST
    localparam int CHECK_CYCLE = 0;   // transaction order (the fast top's timing is its own)
`else
    localparam int CHECK_CYCLE = 1;
`endif
    function automatic void check(int iface, longint c, ef_payload_t actual);
        int st;
        bit more;
        if (c + 1 > frame_len)
            frame_len = c + 1;
        forever begin
            st = ef_dpi_expect(model, iface, c, actual, CHECK_CYCLE);
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
`ifndef EF_TB_DUT_SLB
    // ef_raster, the whole pipeline: cmd in, pix out, the frame memory
    // outside, every internal interface a port (observed, all checked).
    bit        cmd_valid = 1'b0;
    cmd_t      cmd = '0;
    wire       cmd_ready, init_done, pix_valid;
    bit        pix_ready = 1'b1;      // the reference schedule's COV consumer is always ready
    pix_t      pix;
    wire       fb_re, fb_we;
    wire [13:0] fb_ry, fb_rx, fb_wy, fb_wx;
    wire [31:0] fb_wdata;
    bit  [31:0] fb_rdata = '0;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [14:0] cfg_width, cfg_height;   // the model gives the frame; the DUT's copy is not checked here
    wire       frame_end;
    /* verilator lint_on UNUSEDSIGNAL */
    wire       frame_start, err;
    wire       seg_valid, seg_ready, et_wr_valid, et_wr_ready, et_rd_valid, et_rd_ready;
    wire       plot_valid, plot_ready, span_valid, span_ready;
    seg_t      seg;
    et_wr_t    et_wr;
    et_rd_t    et_rd;
    plot_t     plot;
    span_t     span;

    ef_raster
`ifdef EF_FAST
        #(.NS(NS), .W_MAX(W_MAX), .H_MAX(H_MAX), .E_MAX(E_MAX), .SCHEDULE(1)) dut (
`else
        #(.NS(NS), .W_MAX(W_MAX), .H_MAX(H_MAX), .E_MAX(E_MAX)) dut (
`endif
        .clk(clk), .rst(rst), .init_done(init_done),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_op(cmd.op),
        .cmd_a(cmd.a), .cmd_b(cmd.b), .cmd_c(cmd.c), .cmd_d(cmd.d),
        .pix_valid(pix_valid), .pix_ready(pix_ready), .pix_y(pix.y), .pix_x(pix.x),
        .pix_alpha(pix.alpha), .pix_rgba(pix.rgba),
        .fb_re(fb_re), .fb_ry(fb_ry), .fb_rx(fb_rx), .fb_rdata(fb_rdata),
        .fb_we(fb_we), .fb_wy(fb_wy), .fb_wx(fb_wx), .fb_wdata(fb_wdata),
        .cfg_width(cfg_width), .cfg_height(cfg_height),
        .frame_start(frame_start), .frame_end(frame_end), .err(err),
        .seg_valid(seg_valid), .seg_ready(seg_ready), .seg_eos(seg.eos),
        .seg_xa(seg.xa), .seg_ya(seg.ya), .seg_xb(seg.xb), .seg_yb(seg.yb),
        .et_wr_valid(et_wr_valid), .et_wr_ready(et_wr_ready), .et_wr_eos(et_wr.eos),
        .et_wr_slot(et_wr.slot), .et_wr_r0(et_wr.r0), .et_wr_r1(et_wr.r1), .et_wr_x(et_wr.x),
        .et_wr_e(et_wr.e), .et_wr_qs(et_wr.qs), .et_wr_rs(et_wr.rs), .et_wr_dy(et_wr.dy),
        .et_wr_dir(et_wr.dir),
        .et_rd_valid(et_rd_valid), .et_rd_ready(et_rd_ready), .et_rd_row(et_rd.row), .et_rd_eid(et_rd.eid),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot.last), .plot_row(plot.row),
        .plot_s(plot.s), .plot_q(plot.q), .plot_dir(plot.dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span.y), .span_x(span.x),
        .span_len(span.len), .span_mask(span.mask)
    );

    // The frame memory (docs/microarch.md 3.6): one word per pixel drawn,
    // transparent black at FRAME; synchronous read.
    bit [31:0] fb[int];
    always @(posedge clk) begin
        int ra, wa;
        ra = int'(fb_ry) * W_MAX + int'(fb_rx);
        wa = int'(fb_wy) * W_MAX + int'(fb_wx);
        if (frame_start)
            fb.delete();
        if (fb_re) begin
            if (fb.exists(ra) != 0)
                fb_rdata <= fb[ra];
            else
                fb_rdata <= '0;
        end
        if (fb_we)
            fb[wa] = fb_wdata;
    end

    // The transfers of cycle cyc, seen at the edge that ends it: the
    // command taken and every interface the DUT shows.
    function automatic void observe();
        if (err)
            die("the DUT raised err (a FRAME over W_MAX x H_MAX or a shape over E_MAX edges)");
        if (!done && cmd_valid && cmd_ready)
            check(IF_CMD, cyc, ef_payload_t'(cmd));
        if (!done && seg_valid && seg_ready)
            check(IF_SEG, cyc, ef_payload_t'(seg));
        if (!done && et_wr_valid && et_wr_ready)
            check(IF_ET_WR, cyc, ef_payload_t'(et_wr));
        if (!done && et_rd_valid && et_rd_ready)
            check(IF_ET_RD, cyc, ef_payload_t'(et_rd));
        if (!done && plot_valid && plot_ready)
            check(IF_PLOT, cyc, ef_payload_t'(plot));
        if (!done && span_valid && span_ready)
            check(IF_SPAN, cyc, ef_payload_t'(span));
        if (!done && pix_valid && pix_ready)
            check(IF_PIX, cyc, ef_payload_t'(pix));
    endfunction

    // The DUT's input for cycle c: the next command, from the cycle the
    // model's schedule gives it (its cmd transaction) on, held until taken.
    // The word is the model's cmd transaction, which is the stimulus word
    // (with the rule of +rule= when the rule is overridden).
    function automatic void present(longint c);
        /* verilator lint_off UNUSEDSIGNAL */
        longint t;                       // next_expected's out-arguments, partly used
        ef_payload_t p;
        /* verilator lint_on UNUSEDSIGNAL */
        int st;
        st = next_expected(IF_CMD, t, p, 1'b0);
        cmd_valid <= 1'b0;
        if (st == EF_MS_OK && (t <= c || CHECK_CYCLE == 0)) begin
            cmd_valid <= 1'b1;
            cmd <= cmd_t'(p[CMD_W-1:0]);
        end
    endfunction

    // Over when every command has been taken and nothing is left to check;
    // then DRAIN more cycles watch for transactions the model does not have.
    localparam int DRAIN = 64;
    int drain = -1;
    function automatic bit finished();
        /* verilator lint_off UNUSEDSIGNAL */
        longint t;                       // next_expected's out-arguments, partly used
        ef_payload_t p;
        /* verilator lint_on UNUSEDSIGNAL */
        int st;
        st = next_expected(IF_CMD, t, p, 1'b0);
        if (st != EF_MS_END)
            return 1'b0;
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (ef_dpi_pending(model, i) != 0)
                return 1'b0;
        if (drain < 0)
            drain = DRAIN;
        drain--;
        return drain == 0;
    endfunction
    localparam int CHECKED[7] = '{IF_CMD, IF_SEG, IF_ET_WR, IF_ET_RD, IF_PLOT, IF_SPAN, IF_PIX};
    localparam int KEEP = 0;                   // all
    localparam bit WHOLE = CHECK_CYCLE != 0;   // the DUT's transfers span the model's frame
`else
    localparam bit WHOLE = 1'b0;               // SLB + FILL alone: its spans are not the frame
    // ef_slb_fill: plot in, span out, configuration registers.
    bit        plot_valid = 1'b0;
    plot_t  plot = '0;
    bit        span_ready = 1'b0;
    bit [14:0] cfg_width = 15'd1;
    bit        cfg_rule = 1'b0;
    wire       plot_ready, span_valid, init_done, idle;
    wire [13:0] span_y, span_x;
    wire [14:0] span_len;
    wire [31:0] span_mask;

    // (outputs this bench does not use, such as a newer block's scan_done, are left open)
    /* verilator lint_off PINMISSING */
    ef_slb_fill #(.NS(NS), .W_MAX(W_MAX)) dut (
        .clk(clk), .rst(rst), .init_done(init_done),
        .cfg_width(cfg_width), .cfg_rule(cfg_rule),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot.last),
        .plot_row(plot.row), .plot_s(plot.s), .plot_q(plot.q), .plot_dir(plot.dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y),
        .span_x(span_x), .span_len(span_len), .span_mask(span_mask),
        .idle(idle)
    );
    /* verilator lint_on PINMISSING */

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
        /* verilator lint_off UNUSEDSIGNAL */
        longint t;                       // next_expected's out-arguments, partly used
        ef_payload_t p;
        /* verilator lint_on UNUSEDSIGNAL */
        /* verilator lint_off UNUSEDSIGNAL */
        cmd_t cmd;                       // FRAME's width and SHAPE's rule are what SLB needs
        /* verilator lint_on UNUSEDSIGNAL */
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
        /* verilator lint_off UNUSEDSIGNAL */
        longint t;                       // next_expected's out-arguments, partly used
        ef_payload_t p;
        /* verilator lint_on UNUSEDSIGNAL */
        return next_expected(IF_PLOT, t, p, 1'b0) == EF_MS_END && fed == stim.size() && !plot_valid && idle;
    endfunction
    localparam int CHECKED[1] = '{IF_SPAN};   // the interfaces this DUT shows
    // What the model keeps: what the bench drives from it and what it checks.
    localparam int KEEP = (1 << IF_CMD) | (1 << IF_PLOT) | (1 << IF_SPAN);
`endif
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
        if (stim.size() == 0) begin
            $display("tb_lockstep: FAIL %s holds no command", name);
            $fatal(1, "tb_lockstep: no stimulus");
        end
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
`ifdef EF_TB_DUT_SLB
        if (!$value$plusargs("cov_lag=%d", cov_lag))
            cov_lag = 0;
`endif
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
                // the whole pipeline's frame length must be the model's
                if (WHOLE && !done && frame_len != ef_dpi_frame_cycles(model))
                    die($sformatf("the DUT's frame is %0d cycles (one past its last transfer), the model's %0d",
                                  frame_len, ef_dpi_frame_cycles(model)));
                if (!done) begin
                    $display("tb_lockstep: PASS NS=%0d: %0d commands; checked in lockstep: %0d cmd, %0d seg, %0d et_wr, %0d et_rd, %0d plot, %0d span, %0d pix; a frame of %0d cycles%0s",
                             NS, fed, n_checked[IF_CMD], n_checked[IF_SEG], n_checked[IF_ET_WR], n_checked[IF_ET_RD],
                             n_checked[IF_PLOT], n_checked[IF_SPAN], n_checked[IF_PIX],
                             CHECK_CYCLE != 0 || KEEP != 0 ? ef_dpi_frame_cycles(model) : frame_len,
                             CHECK_CYCLE == 0 && KEEP == 0 ? " (the DUT's, ef_raster SCHEDULE=1: in transaction order; the model's reference frame is longer)"
                             : WHOLE ? "" : " (the model's: the DUT is SLB + FILL alone)");
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
