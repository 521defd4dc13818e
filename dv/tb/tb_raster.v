// tb_raster: whole-pipeline testbench of rtl/ef_raster.v under
// Icarus (iverilog -g2005) and Verilator (--binary --timing).
//
// Feeds cmd.stim.hex: each command is presented from its cycle stamp on and
// held until the DUT takes it (a cycle-exact DUT takes it at the stamp);
// provides the frame memory (docs/microarch.md 3.6; cleared at FRAME) and
// dumps every interface's transfers, stamped with the cycle, as
// OUT/IFACE.actual.hex (seg, et_wr, et_rd, plot, span, pix) for
// `edgeflag check --cycles`.  Cycle 0 is the first cycle after init_done.
//
// +bp=SEED: seeded random back-pressure on pix (ready 3 cycles in 4); the
// schedule then slips and only `edgeflag check --transactions` applies.
//
// The bench refuses a stream the hardware cannot take, before simulating,
// with FILE:LINE: a FRAME over W_MAX x H_MAX (or of size 0), a shape of more
// than E_MAX EDGE commands, a cycle stamp that goes backwards, a word that is
// not hex, more than CMD_MAX commands.
//
// The bench compares nothing against the vectors (`edgeflag check` does, on
// its dumps); its own checks are the DUT's readiness for every command at
// its stamp, `err` never raised, no timeout, frame_start and frame_end high
// exactly in the cycle after a FRAME's and a FRAME_END's transfer, and no
// valid on any interface between reset and the first command.  Result, the last line:
//   "tb_raster: DONE ..." (exit 0): the dumps are written and closed, the
//        bench's own checks held; the verdict is edgeflag check's;
//   "tb_raster: FAIL ..." (exit non-zero): a bench check failed, a file
//        could not be opened or written, no +cmd or +out was given;
//   "tb_raster: REFUSED FILE:LINE: ..." (exit non-zero): the stream does
//        not fit this build (W_MAX, H_MAX, E_MAX, CMD_MAX) or is malformed.
// A non-zero exit is $fatal's: vvp exits 1, a Verilator binary aborts
// (status 134).
//
// Defines: EF_TB_USER_DUT for a DUT other than rtl/'s ef_raster with its
// ports (the bench then reaches into nothing inside it; dv/rtl-sim.sh --top);
// EF_FAST for rtl/'s ef_raster with SCHEDULE = 1, the overlap schedule
// (docs/microarch.md section 6; dv/rtl-sim.sh --fast).
// Plusargs: +cmd=FILE (required) +out=DIR (required: the dumps go to
// DIR/IFACE.actual.hex, nothing else is written) +bp=SEED
// Parameters: NS, W_MAX, H_MAX, E_MAX, CMD_MAX, FB_BITS.
module tb_raster #(
    parameter NS      = 8,
    parameter W_MAX   = 1024,
    parameter H_MAX   = 1024,
    parameter E_MAX   = 4096,
    parameter CMD_MAX = 65536,
    parameter FB_BITS = 20
);
    localparam CWD = 48 + 100;

    reg clk = 1'b0;
    always #5 clk = ~clk;
    reg rst = 1'b1;

    reg         cmd_valid = 1'b0;
    reg  [3:0]  cmd_op = 4'd0;
    reg  [23:0] cmd_a = 0, cmd_b = 0, cmd_c = 0, cmd_d = 0;
    wire        cmd_ready, init_done;
    wire        pix_valid;
    reg         pix_ready = 1'b1;
    wire [13:0] pix_y, pix_x;
    wire [7:0]  pix_alpha;
    wire [31:0] pix_rgba;
    wire        fb_re, fb_we;
    wire [13:0] fb_ry, fb_rx, fb_wy, fb_wx;
    wire [31:0] fb_wdata;
    reg  [31:0] fb_rdata = 32'd0;
    wire [14:0] cfg_width;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [14:0] cfg_height;              // the frame memory model needs the width only
    /* verilator lint_on UNUSEDSIGNAL */
    wire        frame_start, frame_end, err;
    wire        seg_valid, seg_ready, seg_eos;
    wire [23:0] seg_xa, seg_ya, seg_xb, seg_yb;
    wire        et_wr_valid, et_wr_ready, et_wr_eos, et_wr_dir;
    wire [13:0] et_wr_slot;
    wire [18:0] et_wr_r0, et_wr_r1;
    wire [24:0] et_wr_x;
    wire [23:0] et_wr_e, et_wr_rs, et_wr_dy;
    wire [29:0] et_wr_qs;
    wire        et_rd_valid, et_rd_ready;
    wire [13:0] et_rd_row;
    wire [21:0] et_rd_eid;
    wire        plot_valid, plot_ready, plot_last, plot_dir;
    wire [13:0] plot_row;
    wire [4:0]  plot_s;
    wire [14:0] plot_q;
    wire        span_valid, span_ready;
    wire [13:0] span_y, span_x;
    wire [14:0] span_len;
    wire [31:0] span_mask;

    ef_raster
`ifdef EF_FAST
        #(.NS(NS), .W_MAX(W_MAX), .H_MAX(H_MAX), .E_MAX(E_MAX), .SCHEDULE(1)) dut (
`else
        #(.NS(NS), .W_MAX(W_MAX), .H_MAX(H_MAX), .E_MAX(E_MAX)) dut (
`endif
`include "ef_raster_conn.vh"
    );

    // ------------------------------------------------ frame memory
    // A hash table over the pixel number y*W + x (open addressing, each word
    // tagged with its pixel and frame number, so FRAME clears it at once):
    // a 16384 x 16384 canvas costs only the pixels drawn.  Full: FAIL.
    reg [31:0] fb     [0:(1<<FB_BITS)-1];
    reg [31:0] fb_tag [0:(1<<FB_BITS)-1];
    reg [15:0] fb_gen [0:(1<<FB_BITS)-1];
    reg [15:0] frame_no;
    reg [31:0] fb_a;
    integer    fb_used;
    reg [FB_BITS-1:0] fi;

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

    always @(posedge clk) begin
        if (frame_start) begin
            frame_no = frame_no + 16'd1;
            fb_used = 0;
        end
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
                    $display("tb_raster: FAIL the frame memory model is full (%0d pixels drawn): raise FB_BITS", fb_used);
                    $fatal(1, "tb_raster: FAIL");
                end
            end
            fb[fi] <= fb_wdata;
            fb_tag[fi] <= fb_a;
            fb_gen[fi] <= frame_no;
        end
    end

    // ------------------------------------------------ the command file
    reg [CWD-1:0]   cmd_mem [0:CMD_MAX-1];
    reg [8*400-1:0] cmd_name, out_name;
    reg [8*1024-1:0] line;
    integer ncmd, fd, lineno, nedge;
    reg     refused;
    reg [CWD-1:0] w;
    reg [47:0] prev;

    task refuse;
        input [8*200-1:0] why;
        begin
            $display("tb_raster: REFUSED %0s:%0d: %0s", cmd_name, lineno, why);
            refused = 1'b1;
        end
    endtask

    // Reads cmd.stim.hex line by line (so a refusal can name its line):
    // `//` comment and blank lines, else one hex word.
    task load;
        integer c, i, k;
        reg [7:0] ch;
        reg any;
        begin
            fd = $fopen(cmd_name, "r");
            if (fd == 0) begin
                $display("tb_raster: FAIL cannot open %0s", cmd_name);
                $fatal(1, "tb_raster: FAIL");
            end
            ncmd = 0; lineno = 0; nedge = 0; refused = 1'b0; prev = 48'd0;
            while (!$feof(fd) && !refused) begin
                line = 0;
                c = $fgets(line, fd);
                if (c > 0) begin
                    lineno = lineno + 1;
                    // skip blank lines and // comments; any other character
                    // but hex digits and white space is refused
                    w = 0; any = 1'b0; k = 0;
                    for (i = c - 1; i >= 0 && !refused; i = i - 1) begin
                        ch = line[8*i +: 8];
                        if (ch == "/" && i > 0 && line[8*(i-1) +: 8] == "/")
                            i = -1;
                        else if (ch >= "0" && ch <= "9") begin w = {w[CWD-5:0], ch[3:0]}; any = 1'b1; k = k + 1; end
                        else if ((ch >= "a" && ch <= "f") || (ch >= "A" && ch <= "F")) begin
                            w = {w[CWD-5:0], ch[3:0] + 4'd9}; any = 1'b1; k = k + 1;
                        end
                        else if (ch == " " || ch == "\t" || ch == "\n" || ch == "\r") ;
                        else refuse("not a hex word");
                    end
                    if (any && !refused) begin
                        if (k > CWD / 4)
                            refuse("a word of more than 37 hex digits (148 bits: cycle[47:0] and the 100-bit cmd)");
                        else if (ncmd >= CMD_MAX)
                            refuse("more commands than the bench holds (CMD_MAX)");
                        else if (ncmd > 0 && w[CWD-1 -: 48] <= prev)
                            refuse("cycle stamp does not increase (commands go out one per cycle at most)");
                        else begin
                            prev = w[CWD-1 -: 48];
                            case (w[99:96])
                                4'd1: if (w[95:72] == 0 || {8'd0, w[95:72]} > W_MAX || w[71:48] == 0 || {8'd0, w[71:48]} > H_MAX)
                                          refuse("FRAME canvas over the hardware's W_MAX x H_MAX (or empty)");
                                4'd2: nedge = 0;
                                4'd3: begin
                                          nedge = nedge + 1;
                                          if (nedge > E_MAX)
                                              refuse("a shape of more EDGE commands than the hardware's E_MAX");
                                      end
                                default: ;
                            endcase
                            cmd_mem[ncmd] = w;
                            ncmd = ncmd + 1;
                        end
                    end
                end
            end
            $fclose(fd);
            if (refused) begin
                $display("tb_raster: REFUSED (W_MAX %0d, H_MAX %0d, E_MAX %0d)", W_MAX, H_MAX, E_MAX);
                $fatal(1, "tb_raster: REFUSED");
            end
            if (ncmd == 0) begin
                $display("tb_raster: FAIL %0s holds no command", cmd_name);
                $fatal(1, "tb_raster: FAIL");
            end
        end
    endtask

    // ------------------------------------------------ dumps
    integer f_seg, f_etw, f_etr, f_plot, f_span, f_pix;
    task open_dump;
        output integer f;
        input [8*16-1:0] iface;
        input [8*40-1:0] desc;
        reg [8*440-1:0] fname;
        begin
            $sformat(fname, "%0s/%0s.actual.hex", out_name, iface);
            f = $fopen(fname, "w");
            if (f == 0) begin
                $display("tb_raster: FAIL cannot open %0s for writing", fname);
                $fatal(1, "tb_raster: FAIL");
            end
            $fwrite(f, "// edgeflag vectors format 1: interface %0s (%0s), role actual: dv/tb/tb_raster.v\n", iface, desc);
        end
    endtask

    integer ic, bp_seed, n_pix, n_bp, errors;
    integer n_seg, n_etw, n_etr, n_plot, n_span;
    reg [47:0] cyc, limit;
    reg [47:0] frame_len;      // one past the last transfer on any interface (docs/microarch.md 4, item 7)
    reg        running, use_bp;
    reg [31:0] rnd;

    initial begin
        if (!$value$plusargs("cmd=%s", cmd_name)) begin
            $display("tb_raster: FAIL no +cmd=FILE (the command stream, cmd.stim.hex)");
            $fatal(1, "tb_raster: FAIL");
        end
        if (!$value$plusargs("out=%s", out_name)) begin
            $display("tb_raster: FAIL no +out=DIR (where the dumps IFACE.actual.hex go)");
            $fatal(1, "tb_raster: FAIL");
        end
        use_bp = $value$plusargs("bp=%d", bp_seed);
        rnd = use_bp ? bp_seed : 0;
        load;
        for (fb_used = 0; fb_used < (1 << FB_BITS); fb_used = fb_used + 1)
            fb_gen[fb_used] = 16'd0;
        frame_no = 16'd0; fb_used = 0;
        ic = 0; n_pix = 0; n_bp = 0; errors = 0; cyc = 0; running = 1'b0; frame_len = 48'd0;
        n_seg = 0; n_etw = 0; n_etr = 0; n_plot = 0; n_span = 0;
        // generous: every cycle of the stamps and then some per command
        // twice the stamps and then some: a slower DUT (back-pressure) fits,
        // a runaway one (a fault build) stops soon, its dumps closed
        limit = (ncmd > 0 ? cmd_mem[ncmd-1][CWD-1 -: 48] : 48'd0) * 48'd2 + 48'd20000;
        open_dump(f_seg, "seg", "DEC -> SETUP");
        open_dump(f_etw, "et_wr", "SETUP -> ETM");
        open_dump(f_etr, "et_rd", "ETM -> AET");
        open_dump(f_plot, "plot", "PLOT -> SLB");
        open_dump(f_span, "span", "FILL -> COV");
        open_dump(f_pix, "pix", "COV -> memory");
        // reset low from the negative edge after the third rising one, so no
        // rising edge sees it change
        repeat (3) @(posedge clk);
        @(negedge clk);
        rst = 1'b0;
    end

    task present;              // the command for cycle c (set at the edge ending c-1)
        input [47:0] c;
        begin
            if (ic < ncmd && cmd_mem[ic][CWD-1 -: 48] <= c) begin
                cmd_valid <= 1'b1;
                cmd_op <= cmd_mem[ic][99:96];
                cmd_a <= cmd_mem[ic][95:72];
                cmd_b <= cmd_mem[ic][71:48];
                cmd_c <= cmd_mem[ic][47:24];
                cmd_d <= cmd_mem[ic][23:0];
            end else
                cmd_valid <= 1'b0;
        end
    endtask

    // Port checks of the control pulses (docs/microarch.md 3.1): frame_start and frame_end
    // are high exactly in the cycle after a FRAME's and a FRAME_END's transfer, and nothing
    // moves on an interface (nor is err raised) between reset and the first command.
    reg exp_fs = 1'b0, exp_fe = 1'b0;
    always @(posedge clk) begin
        exp_fs <= running && cmd_valid && cmd_ready && cmd_op == 4'd1;
        exp_fe <= running && cmd_valid && cmd_ready && cmd_op == 4'd5;
        if (!rst && (frame_start !== exp_fs || frame_end !== exp_fe)) begin
            if (errors < 10) $display("tb_raster: cycle %0d: frame_start %b frame_end %b, expected %b %b (the cycle after FRAME, FRAME_END)",
                                      cyc, frame_start, frame_end, exp_fs, exp_fe);
            errors = errors + 1;
        end
        if (!rst && !running && (seg_valid || et_wr_valid || et_rd_valid || plot_valid || span_valid || pix_valid || err)) begin
            if (errors < 10) $display("tb_raster: a valid or err before the first command (seg %b et_wr %b et_rd %b plot %b span %b pix %b err %b)",
                                      seg_valid, et_wr_valid, et_rd_valid, plot_valid, span_valid, pix_valid, err);
            errors = errors + 1;
        end
        if (!running) begin
            if (!rst && init_done) begin
                running <= 1'b1;
                cyc <= 48'd0;
                present(48'd0);
            end
        end else begin
            // the transfers of cycle cyc happen at this edge
            if (cmd_valid && cmd_ready)
                ic = ic + 1;
            if ((cmd_valid && cmd_ready) || (seg_valid && seg_ready) || (et_wr_valid && et_wr_ready) ||
                (et_rd_valid && et_rd_ready) || (plot_valid && plot_ready) || (span_valid && span_ready) ||
                (pix_valid && pix_ready))
                frame_len = cyc + 48'd1;
            if (cmd_valid && !cmd_ready && cmd_mem[ic][CWD-1 -: 48] == cyc && !use_bp) begin
`ifdef EF_TB_USER_DUT
                if (errors < 10) $display("tb_raster: cycle %0d: the DUT is not ready for the command stamped here", cyc);
`else
                if (errors < 10) $display("tb_raster: cycle %0d: the DUT is not ready for the command stamped here (eos_seen %0d, aet_busy %0d, slb_idle %0d, cov_busy %0d)", cyc, dut.eos_seen, dut.aet_busy, dut.slb_idle, dut.cov_busy);
`endif
                errors = errors + 1;
            end
            if (seg_valid && seg_ready) begin
                $fwrite(f_seg, "%h\n", {cyc, seg_eos, seg_xa, seg_ya, seg_xb, seg_yb}); n_seg = n_seg + 1;
            end
            if (et_wr_valid && et_wr_ready) begin
                $fwrite(f_etw, "%h\n", {cyc, et_wr_eos, et_wr_slot, et_wr_r0, et_wr_r1, et_wr_x, et_wr_e,
                                       et_wr_qs, et_wr_rs, et_wr_dy, et_wr_dir}); n_etw = n_etw + 1;
            end
            if (et_rd_valid && et_rd_ready) begin
                $fwrite(f_etr, "%h\n", {cyc, et_rd_row, et_rd_eid}); n_etr = n_etr + 1;
            end
            if (plot_valid && plot_ready) begin
                $fwrite(f_plot, "%h\n", {cyc, plot_last, plot_row, plot_s, plot_q, plot_dir}); n_plot = n_plot + 1;
            end
            if (span_valid && span_ready) begin
                $fwrite(f_span, "%h\n", {cyc, span_y, span_x, span_len, span_mask}); n_span = n_span + 1;
            end
            if (pix_valid && pix_ready) begin
                $fwrite(f_pix, "%h\n", {cyc, pix_y, pix_x, pix_alpha, pix_rgba}); n_pix = n_pix + 1;
            end
            if (pix_valid && !pix_ready)
                n_bp = n_bp + 1;
            if (err) begin
                $display("tb_raster: FAIL the DUT raised err at cycle %0d", cyc);
                errors = errors + 1;
            end
            if (use_bp) begin
                rnd = rnd * 32'd1103515245 + 32'd12345;
                pix_ready <= rnd[17:16] != 2'd0;
            end
            if (ic >= ncmd && frame_end_seen && drained) begin
                $fclose(f_seg); $fclose(f_etw); $fclose(f_etr); $fclose(f_plot); $fclose(f_span); $fclose(f_pix);
                if (errors == 0) begin
                    if (use_bp)
                        $display("tb_raster: DONE NS=%0d: %0d cmd, %0d seg, %0d et_wr, %0d et_rd, %0d plot, %0d span, %0d pix, a frame of %0d cycles (random back-pressure on pix); the dumps are for edgeflag check",
                                 NS, ncmd, n_seg, n_etw, n_etr, n_plot, n_span, n_pix, frame_len);
                    else
                        $display("tb_raster: DONE NS=%0d: %0d cmd, %0d seg, %0d et_wr, %0d et_rd, %0d plot, %0d span, %0d pix, a frame of %0d cycles; the dumps are for edgeflag check",
                                 NS, ncmd, n_seg, n_etw, n_etr, n_plot, n_span, n_pix, frame_len);
                    $finish;
                end else begin
                    $display("tb_raster: FAIL NS=%0d: %0d errors", NS, errors);
                    $fatal(1, "tb_raster: FAIL");
                end
            end else if (cyc > limit) begin
                $fclose(f_seg); $fclose(f_etw); $fclose(f_etr); $fclose(f_plot); $fclose(f_span); $fclose(f_pix);
                $display("tb_raster: FAIL timeout at cycle %0d (command %0d of %0d)", cyc, ic, ncmd);
                $fatal(1, "tb_raster: FAIL");
            end
            cyc <= cyc + 48'd1;
            present(cyc + 48'd1);
        end
    end

    reg frame_end_seen = 1'b0;
    always @(posedge clk)
        if (frame_end) frame_end_seen <= 1'b1;

    // Drained: nothing left in the DUT.  The reference ef_raster's blocks
    // say so (busy and idle flags); another DUT with ef_raster's ports
    // (EF_TB_USER_DUT: `dv/rtl-sim.sh --top`) is taken as drained after
    // W_MAX + 64 cycles with no valid on any interface, longer than any
    // row's scan, so a DUT still working after FRAME_END is waited for.
`ifdef EF_TB_USER_DUT
    integer quiet = 0;
    always @(posedge clk)
        if (seg_valid || et_wr_valid || et_rd_valid || plot_valid || span_valid || pix_valid || !frame_end_seen)
            quiet <= 0;
        else
            quiet <= quiet + 1;
    wire drained = quiet > W_MAX + 64;
`else
    wire drained = !dut.aet_busy && dut.slb_idle && !dut.cov_busy && !seg_valid && !et_wr_valid;
`endif
endmodule
