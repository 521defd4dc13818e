// tb_backend: block-level testbench of the back end of the pipeline:
// ef_aet (sequencer + AET, with ef_plot) -> ef_slb_fill -> ef_cov, from
// `et_wr.expected.hex` (the ETM's input) to pix, with a behavioural ETM
// (edge records, slot lists in written order, the read ports of
// docs/microarch.md 3.3) and the frame memory of docs/microarch.md 3.5.
//
// Replays et_wr at its stamped cycles and the configuration commands of
// cmd.stim.hex (FRAME: width, clears the frame; SHAPE: rule, colour) at
// theirs, and dumps every transfer of et_rd, plot, span and pix, stamped
// with its cycle, as OUT/IFACE.actual.hex for `edgeflag check --cycles
// --interfaces et_rd,plot,span,pix`.  Cycle 0 is the first cycle after the
// reset sweep (init_done).
//
// Plusargs: +cmd=FILE +etw=FILE (the stimulus, required) +out=DIR (required:
// the dumps go to DIR/IFACE.actual.hex, nothing else is written) +bp=SEED
// (random back-pressure on pix: ready 3 cycles in 4; then only
// --transactions applies; et_wr is still replayed by its stamps, which stays
// correct because a shape's records all precede its rows).
// Parameters: NS, W_MAX, H_MAX, E_MAX, NCMD, NETW (the files' counts).
// Result line: "tb_backend: DONE ..." (exit 0; the dumps are for edgeflag
// check) or "tb_backend: FAIL ..." (exit non-zero, $fatal: a bench check, a
// file that cannot be opened, a missing plusarg; dv/tb/tb_files.vh).
module tb_backend #(
    parameter NS    = 8,
    parameter W_MAX = 1024,
    parameter H_MAX = 1024,
    parameter E_MAX = 4096,
    parameter NCMD  = 1,
    parameter NETW  = 1,
    parameter FB_BITS = 20
);
    localparam CWD = 48 + 100;
    localparam EW  = 48 + 181;

    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    // ------------------------------------------------ configuration
    reg [14:0] cfg_width = 15'd1;
    reg        cfg_rule = 1'b0;
    reg [23:0] cfg_rgb = 24'd0;
    reg [7:0]  cfg_alpha = 8'd0;

    // ------------------------------------------------ et_wr stimulus
    reg          etw_valid = 1'b0, etw_eos = 1'b0, etw_dir = 1'b0;
    reg [13:0]   etw_slot = 14'd0;
    reg [18:0]   etw_r0 = 0, etw_r1 = 0;
    reg [24:0]   etw_x = 0;
    reg [23:0]   etw_e = 0, etw_rs = 0, etw_dy = 0;
    reg [29:0]   etw_qs = 0;

    // ------------------------------------------------ ETM <-> AET
    wire          row_req, row_req_ready, etm_init;
    wire [13:0]   row_req_row;
    wire          rd_valid, rd_ready, rd_last;
    wire [13:0]   rd_row;
    wire [21:0]   rd_eid;
    wire          rec_re, rec_dir;
    wire [21:0]   rec_ra;
    wire [18:0]   rec_r0, rec_r1;
    wire [24:0]   rec_x;
    wire [23:0]   rec_e, rec_rs, rec_dy;
    wire [29:0]   rec_qs;
    wire          etw_ready;
    /* verilator lint_off UNUSEDSIGNAL */
    wire          shape_go, shape_any, err_full;
    wire [13:0]   row_first, row_last;
    /* verilator lint_on UNUSEDSIGNAL */

    // ------------------------------------------------ DUT
    wire        plot_valid, plot_ready, plot_last, plot_dir, aet_busy;
    wire [13:0] plot_row;
    wire [4:0]  plot_s;
    wire [14:0] plot_q;
    wire        span_valid, span_ready, init_done, slb_idle;
    /* verilator lint_off UNUSEDSIGNAL */
    wire        slb_scan_done;           // the bench waits for idle
    /* verilator lint_on UNUSEDSIGNAL */
    wire [13:0] span_y, span_x;
    wire [14:0] span_len;
    wire [31:0] span_mask;
    wire        pix_valid;
    reg         pix_ready = 1'b1;
    wire [13:0] pix_y, pix_x;
    wire [7:0]  pix_alpha;
    wire [31:0] pix_rgba;
    wire        fb_re, fb_we, cov_busy;
    wire [13:0] fb_ry, fb_rx, fb_wy, fb_wx;
    wire [31:0] fb_wdata;
    reg  [31:0] fb_rdata = 32'd0;

    ef_etm #(.NS(NS), .H_MAX(H_MAX), .E_MAX(E_MAX)) u_etm (
        .clk(clk), .rst(rst), .init_done(etm_init),
        .et_wr_valid(etw_valid), .et_wr_ready(etw_ready), .et_wr_eos(etw_eos), .et_wr_slot(etw_slot),
        .et_wr_r0(etw_r0), .et_wr_r1(etw_r1), .et_wr_x(etw_x), .et_wr_e(etw_e), .et_wr_qs(etw_qs),
        .et_wr_rs(etw_rs), .et_wr_dy(etw_dy), .et_wr_dir(etw_dir),
        .shape_go(shape_go), .shape_any(shape_any), .row_first(row_first), .row_last(row_last),
        .err_full(err_full),
        .row_req(row_req), .row_req_ready(row_req_ready), .row_req_row(row_req_row),
        .et_rd_valid(rd_valid), .et_rd_ready(rd_ready), .et_rd_row(rd_row), .et_rd_eid(rd_eid),
        .et_rd_last(rd_last),
        .rec_re(rec_re), .rec_ra(rec_ra), .rec_r0(rec_r0), .rec_r1(rec_r1), .rec_x(rec_x), .rec_e(rec_e),
        .rec_qs(rec_qs), .rec_rs(rec_rs), .rec_dy(rec_dy), .rec_dir(rec_dir)
    );
    ef_aet #(.NS(NS), .H_MAX(H_MAX), .E_MAX(E_MAX)) u_aet (
        .clk(clk), .rst(rst), .cfg_width(cfg_width),
        .etw_valid(etw_valid), .etw_eos(etw_eos), .etw_slot(etw_slot),
        .row_req(row_req), .row_req_row(row_req_row),
        .et_rd_valid(rd_valid), .et_rd_ready(rd_ready), .et_rd_row(rd_row), .et_rd_eid(rd_eid),
        .et_rd_last(rd_last),
        .rec_re(rec_re), .rec_ra(rec_ra), .rec_r0(rec_r0), .rec_r1(rec_r1), .rec_x(rec_x),
        .rec_e(rec_e), .rec_qs(rec_qs), .rec_rs(rec_rs), .rec_dy(rec_dy), .rec_dir(rec_dir),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot_last), .plot_row(plot_row),
        .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir), .busy(aet_busy)
    );
    ef_slb_fill #(.NS(NS), .W_MAX(W_MAX)) u_slb (
        .clk(clk), .rst(rst), .init_done(init_done),
        .cfg_width(cfg_width), .cfg_rule(cfg_rule),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot_last),
        .plot_row(plot_row), .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y),
        .span_x(span_x), .span_len(span_len), .span_mask(span_mask), .idle(slb_idle), .scan_done(slb_scan_done)
    );
    ef_cov #(.NS(NS)) u_cov (
        .clk(clk), .rst(rst), .cfg_rgb(cfg_rgb), .cfg_alpha(cfg_alpha),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y), .span_x(span_x),
        .span_len(span_len), .span_mask(span_mask),
        .pix_valid(pix_valid), .pix_ready(pix_ready), .pix_y(pix_y), .pix_x(pix_x),
        .pix_alpha(pix_alpha), .pix_rgba(pix_rgba),
        .fb_re(fb_re), .fb_ry(fb_ry), .fb_rx(fb_rx), .fb_rdata(fb_rdata),
        .fb_we(fb_we), .fb_wy(fb_wy), .fb_wx(fb_wx), .fb_wdata(fb_wdata), .busy(cov_busy)
    );

    // ------------------------------------------------ frame memory
    // A hash table over the pixel number y*W + x (open addressing, 2^FB_BITS
    // words, each tagged with its pixel number and frame number, so FRAME
    // clears it all at once): the canvas may be 16384 x 16384 while only the
    // pixels drawn take room.  A full table stops the bench.
    reg [31:0] fb     [0:(1<<FB_BITS)-1];
    reg [31:0] fb_tag [0:(1<<FB_BITS)-1];
    reg [15:0] fb_gen [0:(1<<FB_BITS)-1];
    reg [15:0] frame_no;
    reg [31:0] fb_a;
    integer    fb_used;

    function [FB_BITS-1:0] fb_find;      // the word of pixel a, or a free one
        input [31:0] a;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [63:0] h;                    // its bits 31 -: FB_BITS are the hash
        /* verilator lint_on UNUSEDSIGNAL */
        reg [FB_BITS-1:0] i;
        integer n;
        begin
            h = a * 64'd2654435761;
            i = h[31 -: FB_BITS];
            n = 0;
            while (fb_gen[i] == frame_no && fb_tag[i] != a && n < (1 << FB_BITS)) begin
                i = i + 1'b1;
                n = n + 1;
            end
            fb_find = i;
        end
    endfunction
    reg [FB_BITS-1:0] fi;
    integer fj;

    // ------------------------------------------------ files
    reg [CWD-1:0] cmd_mem [0:NCMD];
    reg [EW-1:0]  etw_mem [0:NETW];
    reg [8*240-1:0] cmd_name, etw_name, out_name;
    integer f_rd, f_pl, f_sp, f_px;
    integer ic, ie, errors, bp_seed, n_rd, n_pl, n_sp, n_px, n_bp;
    reg [47:0] cyc, limit, sclk;
    reg        wait_drain;
    integer    n_freeze;

    function due;
        input [47:0] c;
        begin
            due = (ic < NCMD && cmd_mem[ic][CWD-1 -: 48] <= c) || (ie < NETW && etw_mem[ie][EW-1 -: 48] <= c);
        end
    endfunction
    reg        running, done, use_bp;
    reg [31:0] rnd;

    localparam TB_NAME = "tb_backend";
`include "tb_files.vh"

    task open_dump;
        output integer f;
        input [8*16-1:0] iface;
        input [8*40-1:0] desc;
        reg [8*240-1:0] fname;
        begin
            $sformat(fname, "%0s/%0s.actual.hex", out_name, iface);
            tb_open_out(f, fname, iface, desc);
        end
    endtask

    // Present the stimulus of cycle c (set at the edge that ends c-1).
    task present;
        input [47:0] c;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [CWD-1:0] cw;               // the fields COV and SLB need
        reg [EW-1:0]  ew;               // the payload; the stamp is compared apart
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            while (ic < NCMD && cmd_mem[ic][CWD-1 -: 48] <= c) begin
                cw = cmd_mem[ic];
                case (cw[99:96])
                    4'd1: begin
                        cfg_width <= cw[86:72];
                        frame_no = frame_no + 16'd1;    // the frame is all zero
                        fb_used = 0;
                    end
                    4'd2: begin
                        cfg_rule <= cw[72];
                        cfg_rgb <= cw[71:48];
                        cfg_alpha <= cw[31:24];
                    end
                    default: ;
                endcase
                ic = ic + 1;
            end
            etw_valid <= 1'b0;
            if (ie < NETW && etw_mem[ie][EW-1 -: 48] <= c) begin
                ew = etw_mem[ie];
                etw_valid <= 1'b1;
                etw_eos  <= ew[180];
                etw_slot <= ew[179:166];
                etw_r0   <= ew[165:147];
                etw_r1   <= ew[146:128];
                etw_x    <= ew[127:103];
                etw_e    <= ew[102:79];
                etw_qs   <= ew[78:49];
                etw_rs   <= ew[48:25];
                etw_dy   <= ew[24:1];
                etw_dir  <= ew[0];
                ie = ie + 1;
            end
        end
    endtask

    initial begin
        tb_arg($value$plusargs("cmd=%s", cmd_name), "cmd=FILE (cmd.stim.hex)");
        tb_arg($value$plusargs("etw=%s", etw_name), "etw=FILE (et_wr.expected.hex)");
        tb_arg($value$plusargs("out=%s", out_name), "out=DIR (where the dumps IFACE.actual.hex go)");
        use_bp = $value$plusargs("bp=%d", bp_seed);
        rnd = use_bp ? bp_seed : 0;
        tb_need(cmd_name);
        $readmemh(cmd_name, cmd_mem, 0, NCMD - 1);
        tb_need(etw_name);
        if (NETW > 0)
            $readmemh(etw_name, etw_mem, 0, NETW - 1);
        // a stream the bench cannot replay (stamps that do not increase) is refused
        for (fj = 1; fj < NCMD; fj = fj + 1)
            if (cmd_mem[fj][CWD-1 -: 48] <= cmd_mem[fj-1][CWD-1 -: 48])
                tb_fail("the command stamps do not increase (+cmd)");
        for (fj = 1; fj < NETW; fj = fj + 1)
            if (etw_mem[fj][EW-1 -: 48] <= etw_mem[fj-1][EW-1 -: 48])
                tb_fail("the et_wr stamps do not increase (+etw)");
        for (fj = 0; fj < (1 << FB_BITS); fj = fj + 1)
            fb_gen[fj] = 16'd0;
        frame_no = 16'd0;
        fb_used = 0;
        ic = 0; ie = 0; errors = 0; n_rd = 0; n_pl = 0; n_sp = 0; n_px = 0; n_bp = 0;
        running = 1'b0; done = 1'b0; cyc = 0; wait_drain = 1'b0; n_freeze = 0;
        limit = (NETW > 0 ? etw_mem[NETW-1][EW-1 -: 48] : 48'd0) * 48'd4 + 48'd4000000;
        open_dump(f_rd, "et_rd", "ETM -> AET");
        open_dump(f_pl, "plot", "PLOT -> SLB");
        open_dump(f_sp, "span", "FILL -> COV");
        open_dump(f_px, "pix", "COV -> memory");
        repeat (3) @(posedge clk);
        @(negedge clk);       // no rising edge sees reset change
        rst = 1'b0;
    end

    // ETM and frame memory: synchronous ports.
    always @(posedge clk) begin
        if (fb_re) begin
            fb_a = {18'd0, fb_ry} * {17'd0, cfg_width} + {18'd0, fb_rx};
            fi = fb_find(fb_a);
            fb_rdata <= (fb_gen[fi] == frame_no) ? fb[fi] : 32'd0;
        end
        if (fb_we) begin
            fb_a = {18'd0, fb_wy} * {17'd0, cfg_width} + {18'd0, fb_wx};
            fi = fb_find(fb_a);
            if (fb_gen[fi] != frame_no) begin
                fb_used = fb_used + 1;
                if (fb_used * 4 > 3 * (1 << FB_BITS)) begin
                    $display("tb_backend: FAIL the frame memory model is full (%0d pixels drawn): raise FB_BITS", fb_used);
                    $fatal(1, "tb_backend: FAIL");
                end
            end
            fb[fi] <= fb_wdata;
            fb_tag[fi] <= fb_a;
            fb_gen[fi] <= frame_no;
        end
    end

    always @(posedge clk) begin
        if (!running) begin
            if (!rst && init_done && etm_init) begin
                running <= 1'b1;
                cyc <= 48'd0;
                sclk = 48'd0;
                present(48'd0);
            end
        end else if (!done) begin
            if (rd_valid && rd_ready) begin
                $fwrite(f_rd, "%h\n", {cyc, rd_row, rd_eid}); n_rd = n_rd + 1;
            end
            if (row_req && !row_req_ready) begin
                if (errors < 10) $display("tb_backend: cycle %0d: ETM not ready for a row request", cyc);
                errors = errors + 1;
            end
            if (etw_valid && !etw_ready) begin
                if (errors < 10) $display("tb_backend: cycle %0d: ETM not ready for et_wr", cyc);
                errors = errors + 1;
            end
            if (plot_valid && plot_ready) begin
                $fwrite(f_pl, "%h\n", {cyc, plot_last, plot_row, plot_s, plot_q, plot_dir}); n_pl = n_pl + 1;
            end
            if (plot_valid && !plot_ready) begin
                if (errors < 10) $display("tb_backend: cycle %0d: SLB not ready for a plot", cyc);
                errors = errors + 1;
            end
            if (span_valid && span_ready) begin
                $fwrite(f_sp, "%h\n", {cyc, span_y, span_x, span_len, span_mask}); n_sp = n_sp + 1;
            end
            if (pix_valid && pix_ready) begin
                $fwrite(f_px, "%h\n", {cyc, pix_y, pix_x, pix_alpha, pix_rgba}); n_px = n_px + 1;
            end
            if (pix_valid && !pix_ready)
                n_bp = n_bp + 1;
            if (use_bp) begin
                rnd = rnd * 32'd1103515245 + 32'd12345;
                pix_ready <= rnd[17:16] != 2'd0;
            end
            if (ic >= NCMD && ie >= NETW && !etw_valid && !aet_busy && slb_idle && !cov_busy) begin
                done <= 1'b1;
                $fclose(f_rd); $fclose(f_pl); $fclose(f_sp); $fclose(f_px);
                if (errors == 0)
                    $display("tb_backend: DONE NS=%0d: %0d et_rd, %0d plots, %0d spans, %0d pix, %0d cycles, %0d cycles of pix back-pressure, %0d cycles of stimulus held",
                             NS, n_rd, n_pl, n_sp, n_px, cyc, n_bp, n_freeze);
                else
                    $display("tb_backend: FAIL NS=%0d: %0d errors", NS, errors);
                if (errors != 0) $fatal(1, "tb_backend: FAIL");
                $finish;
            end else if (cyc > limit) begin
                $display("tb_backend: FAIL timeout at cycle %0d (et_wr %0d of %0d)", cyc, ie, NETW);
                $fatal(1, "tb_backend: FAIL");
            end
            cyc <= cyc + 48'd1;
            // A shape's records all precede its rows, and the next shape's
            // stimulus is stamped after it drained (schedule item 1): when
            // back-pressure makes the back end slower than the stamps, the
            // stimulus clock waits for the drain (wait_drain) instead.
            if (etw_valid && etw_eos)
                wait_drain = 1'b1;
            if (wait_drain && !aet_busy && slb_idle && !cov_busy && !etw_valid)
                wait_drain = 1'b0;
            if (use_bp && wait_drain && due(sclk + 48'd1)) begin
                etw_valid <= 1'b0;
                n_freeze = n_freeze + 1;
            end else begin
                sclk = sclk + 48'd1;
                present(sclk);
            end
        end
    end
endmodule
