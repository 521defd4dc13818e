// ef_slb_fill: scanline buffer (SLB) + filler (FILL) of the edgeflag
// reference microarchitecture, written from docs/microarch.md 3.4 and the
// reference schedule (section 4, items 4-6) plus docs/spec.md 6.2, 6.3, 7.2.
// Interfaces:  plot (PLOT -> SLB) in,  span (FILL -> COV) out.
//
// The aim is cycle-exact agreement with `edgeflag vectors` (checked with
// `edgeflag check span.expected.hex span.actual.hex --cycles`), so every
// timing decision below is traced to the sentence of the schedule it meets.
//
// Cell storage.  One cell per pixel column 0..W (W = the right-clamp sink),
// NS lanes of 7 bits: lane s is sample s's winding counter (spec 6.3 without
// the pad bit, which in the 64-bit word only exists to absorb the carry; a
// 7-bit adder drops it by construction).  Even-odd uses bit 0 of each lane as
// the flag (spec 6.2), so the same memory serves both rules, which the
// command stream may switch per shape.
//
// Pipeline.  Every memory access is a 2-cycle read-modify-write through one
// pipeline (microarch 3.4):
//   stage 1 (cycle t):   the op is issued; the RAM samples its read address
//                        at the rising edge that ends cycle t;
//   stage 2 (cycle t+1): the cell value (RAM output, or the latest write when
//                        its address matches: forwarding) is combined, and
//                        written back at the edge that ends cycle t+1.
// Ops: PLOT (plot.q: XOR or lane add), CELL (a scan step: read, accumulate,
// clear-on-read), FLUSH (the scan's final step: no memory access).
// Because a write lands one edge after the read of the next op, the only
// hazard is "read at the edge of the previous op's write"; one forwarding
// register (the latest write) covers it, so back-to-back plots to one cell
// and a scan that starts on the cell of the row's last plot need no stall.
//
// Schedule (microarch section 4, items 4-6):
//  * The scan's step for cell xmin is issued in the cycle after the row's
//    last plot (item 5), then one cell per cycle up to xmax, then the flush.
//  * A step issued in cycle t that closes a span offers it in cycle t+1: the
//    span's valid is therefore decided in stage 2 from the cell just read
//    (only "cell != 0 and mask != 0"; the payload is all registers).  A
//    registered span_valid would need the xmin read one cycle earlier, in
//    the cycle of the row's last plot, whose own read uses the port then:
//    two read ports (or an asynchronous-read memory).  One OR-reduction
//    after the RAM's output register is the cheaper price.
//  * While the span is offered and COV is not ready (span_ready low) the
//    whole pipeline holds (no issue, no write-back): the scan's next step is
//    issued in the span's transfer cycle a = max(t+1, cov_free) (item 5).
//  * The flush is issued in the cycle after the last cell's step (or in that
//    step's span transfer cycle); from the cycle after the flush (or in the
//    flush span's transfer cycle) plot_ready is high again: the next row's
//    first cycle (plot_ready does not depend on the cell RAM's output).
//    The scan needs no idle cycle between rows: the last clear-on-read
//    write lands before the next row's first read.
//
// COV's acceptance (cov_free, item 6) is COV's business: this block sees it
// only as span_ready.  The reference COV raises ready at cov_free = a + len.
//
// Edge tracking is exact: xmin/xmax are the least/greatest q plotted in the
// row (microarch 3.4).  Reset: rst (synchronous, active high) starts a sweep
// that clears cells 0..W_MAX one per cycle (microarch 2); init_done rises when
// the buffer is clean and plots may be accepted.
//
// SKIP = 1: the overlap schedule's scan (docs/microarch.md section 6, 6.1;
// ef_raster with SCHEDULE = 1).  The scan visits only the cells plotted in
// the row instead of every cell of xmin .. xmax; everything else above
// holds.  Plotted cells: a bit per cell, in NG = (W_MAX+1)/64 words of 64
// bits (flip-flops), and a bit per word (gnz) that says it is non-zero and
// not yet taken by the scan; a word's bits count only while its gnz bit is
// set (reset clears gnz alone).  A plot sets its cell's bit and its word's
// gnz bit in its stage 1.  The next plotted cell is known a step ahead, so
// no search sits between a step's stall and ptr (issue 25): while the row
// is plotted, lwx and lw2 follow its two lowest non-empty words (the lowest
// without xmin's own bit; the second with its index g2); the row's last
// plot moves them into cw (the plotted cells of ptr's word right of ptr)
// and nw (the next non-empty word, ng) and takes both words (clears their
// gnz bits).  A step at ptr moves ptr to the least set bit of cw and clears
// it there, or, with cw empty, to the least set bit of nw, whose other bits
// become cw; only that word change reads the bitmap: nw takes the least
// word gnz still holds (a priority encoder over NG bits and a multiplexer,
// into a register).  Cells are visited once each in increasing order.
// Plots and scan steps never share a cycle (plot_ready is low while
// scanning).  Spans are unchanged: a cell never plotted is empty, so
// stepping over it changes no mask, and a span closed at a visited cell p
// is start .. p-1.  The scan's first step is at xmin in the cycle after the
// row's last plot, as in the reference; the flush step follows the last
// plotted cell.  SKIP = 0 (the default) is the reference scan above, and
// none of this logic exists.
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_slb_fill #(
    parameter NS    = 8,       // samples per pixel: 8, 16 or 32
    parameter W_MAX = 16384,   // largest canvas width (cells 0..W_MAX)
    parameter SKIP  = 0        // 1: the skipping scan of the overlap schedule (see above)
) (
    input  wire        clk,
    input  wire        rst,
    output reg         init_done,   // reset sweep finished

    // Configuration registers (FRAME width, SHAPE rule): stable while a
    // shape is rasterized.
    input  wire [14:0] cfg_width,   // W, 1..W_MAX
    input  wire        cfg_rule,    // SHAPE encoding: 0 non-zero, 1 even-odd

    // plot: last[0] row[13:0] s[4:0] q[14:0] dir[0]
    input  wire        plot_valid,
    output wire        plot_ready,
    input  wire        plot_last,
    input  wire [`EF_PLOT_ROW_W-1:0] plot_row,
    input  wire [`EF_PLOT_S_W-1:0] plot_s,
    input  wire [`EF_PLOT_Q_W-1:0] plot_q,
    input  wire        plot_dir,    // 0: +1 (downward edge), 1: -1

    // span: y[13:0] x[13:0] len[14:0] mask[31:0]
    output wire        span_valid,
    input  wire        span_ready,
    output wire [`EF_SPAN_Y_W-1:0] span_y,
    output wire [`EF_SPAN_X_W-1:0] span_x,
    output wire [`EF_SPAN_LEN_W-1:0] span_len,
    output wire [`EF_SPAN_MASK_W-1:0] span_mask,

    output wire        idle,        // nothing in flight (for testbenches)
    output wire        scan_done    // no scan in progress: from the cycle after the
                                    // flush step (its span, if any, transferring)
);
    `include "ef_ns.vh"
    localparam CW = 7 * NS;                 // cell width
    localparam AW = $clog2(W_MAX + 1);      // cell address width

    localparam [1:0] OP_NONE  = 2'd0;
    localparam [1:0] OP_PLOT  = 2'd1;
    localparam [1:0] OP_CELL  = 2'd2;
    localparam [1:0] OP_FLUSH = 2'd3;

    // ---------------------------------------------------------------- state
    reg [AW-1:0] sweep_addr;

    // Edge tracking of the row being plotted.
    reg          trk_any;
    reg [14:0]   trk_xmin, trk_xmax;

    // Filler: scan cursor and accumulator of the row being scanned.
    reg          scanning;
    reg [14:0]   ptr;          // next cell to issue (SKIP = 0: up to xmax + 1;
                               // SKIP = 1: a plotted one)
    wire         ptr_in;       // ptr is a cell to visit (else the flush is next)
    wire [14:0]  ptr_step;     // the cell after ptr's step
    reg [14:0]   xend;         // xmax of the row
    reg [14:0]   start;        // first cell of the open span
    reg [13:0]   fy;           // row being scanned
    reg          f_rule;
    reg [14:0]   f_width;
    reg [CW-1:0] acc;          // per-lane accumulated winding (7-bit lanes)
    reg [NS-1:0] mask;         // coverage mask of the open span

    // Stage 2.
    reg [1:0]    s2_op;
    reg [14:0]   s2_addr;
    reg [4:0]    s2_s;
    reg          s2_dir;
    reg          s2_rule;

    // The cell of a stalled CELL op (issue 25): the RAM keeps reading while
    // a span waits for COV, so stage 2 holds its cell here.
    reg          hold_v;
    reg [CW-1:0] hold_d;

    // Latest write, for forwarding.
    reg          lw_valid;
    reg [AW-1:0] lw_addr;
    reg [CW-1:0] lw_data;

    // ------------------------------------------------------------ the RAM
    wire          ram_we;
    wire [AW-1:0] ram_wa;
    wire [CW-1:0] ram_wd;
    wire          ram_re;
    wire [AW-1:0] ram_ra;
    wire [CW-1:0] ram_rd;

    ef_slb_ram #(.AW(AW), .DW(CW), .DEPTH(W_MAX + 1)) u_ram (
        .clk(clk), .we(ram_we), .wa(ram_wa), .wd(ram_wd),
        .re(ram_re), .ra(ram_ra), .rd(ram_rd)
    );

    // ------------------------------------------------------------ stage 2
    // cur: the cell as it is now: the RAM read missed a write made at the same
    // edge (read first), so the latest write wins on an address match.
    wire          fwd  = lw_valid && (lw_addr == s2_addr[AW-1:0]);
    wire [CW-1:0] cur  = hold_v ? hold_d : fwd ? lw_data : ram_rd;

    wire [NS-1:0] s2_sel = {{(NS-1){1'b0}}, 1'b1} << s2_s;  // one-hot sample
    wire [CW-1:0] plot_new;     // cell after the PLOT op
    wire [CW-1:0] acc_next;     // accumulator after a CELL op
    wire [NS-1:0] mask_next;

    genvar l;
    generate
        for (l = 0; l < NS; l = l + 1) begin : lane
            wire [6:0] c = cur[7*l +: 7];
            wire [6:0] a = acc[7*l +: 7];
            // spec 6.2: toggle bit s;  spec 6.3: lane add of +1 / -1 mod 128
            wire [6:0] marked = s2_rule ? (c ^ 7'd1)
                                        : (c + (s2_dir ? 7'h7f : 7'h01));
            assign plot_new[7*l +: 7] = s2_sel[l] ? marked : c;
            // spec 7.2: acc ^= cell (even-odd), lane-wise add mod 128 (non-zero)
            wire [6:0] an = f_rule ? (a ^ c) : (a + c);
            assign acc_next[7*l +: 7] = an;
            // mask bit: parity (even-odd) or counter != 0 (non-zero)
            assign mask_next[l] = f_rule ? an[0] : (|an);
        end
    endgenerate

    wire cell_nz = |cur;       // "the scan reads a non-zero cell"
    wire mask_nz = |mask;

    // microarch 3.4: a span closes when the scan reads a non-zero cell while
    // the mask is non-zero (it ends before that cell), or at the flush if
    // the mask is non-zero and the span starts left of W (cut at W).
    wire [15:0] xend1     = {1'b0, xend} + 16'd1;
    wire [14:0] flush_end = (xend1 < {1'b0, f_width}) ? xend1[14:0] : f_width;
    wire span_cell  = (s2_op == OP_CELL)  && cell_nz && mask_nz;
    wire span_flush = (s2_op == OP_FLUSH) && mask_nz && (start < f_width);

    assign span_valid = span_cell || span_flush;
    assign span_y     = fy;
    assign span_x     = start[13:0];   // start < W <= 16384 whenever valid
    // span_end <= W <= 16384 and start < span_end whenever valid: 15 bits.
    wire [14:0] span_end = (s2_op == OP_CELL) ? s2_addr : flush_end;
    assign span_len   = span_end - start;
    generate
        if (NS < `EF_SPAN_MASK_W) begin : mask_pad
            assign span_mask = {{(`EF_SPAN_MASK_W-NS){1'b0}}, mask};
        end else begin : mask_full
            assign span_mask = mask;
        end
    endgenerate

    // Back-pressure: an offered span that COV does not take holds everything.
    wire stall = span_valid && !span_ready;
    wire s2_done = !stall;     // stage 2 completes at this edge

    // ------------------------------------------------------------ stage 1
    // No path from the cell RAM's output into AET/PLOT (issue 25): while
    // no scan is in progress stage 2 holds no CELL op (a CELL op is issued
    // only while scanning, and only the flush ends the scan), so the only
    // span that can stall is the flush's, which depends on registers alone.
    wire flush_stall = span_flush && !span_ready;
    assign plot_ready = init_done && !scanning && !flush_stall;
    wire take_plot  = plot_valid && plot_ready;
    wire scan_go    = init_done && scanning && !stall;
    wire scan_cell  = scan_go && ptr_in;
    wire scan_flush = scan_go && !ptr_in;

    // The read and write enables do not wait for the stall (issue 25: the
    // stall comes from the cell just read and from COV, and gating the
    // memory's enables with it made the block's critical path): a stalled
    // CELL op rewrites its cell's zero, the same write it makes when it
    // completes, and the read of the next cell is issued again when the
    // stall ends; stage 2 keeps its cell in hold_d meanwhile.  (ptr and,
    // with SKIP, the bitmap still move only when the step is taken.)
    wire scan_rd    = init_done && scanning && ptr_in;
    assign ram_re = take_plot || scan_rd;
    assign ram_ra = take_plot ? plot_q[AW-1:0] : ptr[AW-1:0];

    // Write port: the reset sweep, else stage 2's write-back (the new cell of
    // a PLOT, zero for a CELL: clear-on-read).
    wire s2_writes = (s2_op == OP_PLOT) || (s2_op == OP_CELL);
    assign ram_we = !init_done || s2_writes;
    assign ram_wa = !init_done ? sweep_addr : s2_addr[AW-1:0];
    assign ram_wd = (!init_done || (s2_op == OP_CELL)) ? {CW{1'b0}} : plot_new;

    // Range of the row including the plot being taken (exact tracking).
    wire [14:0] new_xmin = (!trk_any || plot_q < trk_xmin) ? plot_q : trk_xmin;
    wire [14:0] new_xmax = (!trk_any || plot_q > trk_xmax) ? plot_q : trk_xmax;

    assign idle = init_done && !scanning && !trk_any && (s2_op == OP_NONE);
    // The schedule's cursor after a row (item 5): the cycle after the flush
    // step, or the flush span's transfer cycle.  The drain (item 6) counts it.
    assign scan_done = init_done && !scanning && !trk_any
                    && ((s2_op == OP_NONE) || ((s2_op == OP_FLUSH) && !flush_stall));

    // ------------------------------------------------------------ the scan's next cell
    generate
        if (SKIP == 0) begin : scan_all
            // The reference scan: every cell of xmin .. xmax.
            assign ptr_in   = (ptr <= xend);
            assign ptr_step = ptr + 15'd1;
        end else begin : scan_skip
            // The skipping scan: only the plotted cells (see the head comment).
            localparam NG = (W_MAX + 1 + 63) / 64;  // words of the plotted-cell bitmap
            localparam GW = (NG > 1) ? $clog2(NG) : 1;
            reg [64*NG-1:0] bm;        // plotted cells: word g is bm[64*g +: 64], valid if gnz[g]
            reg [NG-1:0]    gnz;       // word g is non-zero and the scan has not taken it
            // Plotting: shadows of the row's two lowest non-empty words.
            reg [63:0]      lwx;       // the lowest (xmin's) but xmin's own cell
            reg [63:0]      lw2;       // the second lowest, word g2, if v2
            reg [GW-1:0]    g2;
            reg             v2;
            // Scanning.
            reg             ptr_ok;    // ptr holds a plotted cell (else: the flush is next)
            reg [63:0]      cw;        // the plotted cells of ptr's word right of ptr
            reg [63:0]      nw;        // the next non-empty word (ng), taken from bm, if nw_ok
            reg [GW-1:0]    ng;
            reg             nw_ok;

            function [5:0] low64;           // index of the least set bit (0 if none)
                input [63:0] v;
                integer k;
                begin
                    low64 = 6'd0;
                    for (k = 63; k >= 0; k = k - 1)
                        if (v[k]) low64 = k[5:0];
                end
            endfunction
            function [GW-1:0] lowg;         // index of the least set bit (0 if none)
                input [NG-1:0] v;
                integer k;
                begin
                    lowg = {GW{1'b0}};
                    for (k = NG - 1; k >= 0; k = k - 1)
                        if (v[k]) lowg = k[GW-1:0];
                end
            endfunction

            // ---- plotting: the two lowest words after this plot
            wire [GW-1:0] qg = plot_q[6 +: GW];
            wire [GW-1:0] g1 = trk_xmin[6 +: GW];
            wire [63:0]   qb = 64'd1 << plot_q[5:0];
            wire [63:0]   xb = 64'd1 << trk_xmin[5:0];
            reg  [63:0]   lwx_n, lw2_n;
            reg  [GW-1:0] g2_n;
            reg           v2_n;
            always @* begin
                lwx_n = lwx; lw2_n = lw2; g2_n = g2; v2_n = v2;
                if (!trk_any) begin             // the row's first plot
                    lwx_n = 64'd0; v2_n = 1'b0;
                end else if (qg < g1) begin     // a new lowest word: the old one is second
                    lw2_n = lwx | xb; g2_n = g1; v2_n = 1'b1; lwx_n = 64'd0;
                end else if (qg == g1) begin
                    if (plot_q < trk_xmin)
                        lwx_n = lwx | xb;
                    else if (plot_q > trk_xmin)
                        lwx_n = lwx | qb;
                end else if (!v2 || qg < g2) begin  // a new second word (it was empty)
                    lw2_n = qb; g2_n = qg; v2_n = 1'b1;
                end else if (qg == g2) begin
                    lw2_n = lw2 | qb;
                end
            end
            wire [GW-1:0] g1_n = new_xmin[6 +: GW];
            // the words the scan takes at its start (cleared from gnz)
            wire [NG-1:0] start_take = ({{(NG-1){1'b0}}, 1'b1} << g1_n)
                                     | ({{(NG-1){1'b0}}, v2_n} << g2_n);

            // ---- scanning: the next plotted cell after ptr
            wire          cw_any = |cw;
            wire [GW-1:0] g3     = lowg(gnz);
            wire          g3_ok  = |gnz;
            wire          w_take = scan_cell && !cw_any && nw_ok;   // the step moves to word ng
            wire [8:0]    ng9    = {{(9-GW){1'b0}}, ng};  // GW <= 9: W_MAX < 32768
            assign ptr_in   = ptr_ok;
            assign ptr_step = cw_any ? {ptr[14:6], low64(cw)} : {ng9, low64(nw)};
            always @(posedge clk) begin
                if (rst) begin
                    gnz    <= {NG{1'b0}};
                    ptr_ok <= 1'b0;
                    nw_ok  <= 1'b0;
                end else begin
                    if (scan_cell) begin
                        ptr_ok <= cw_any || nw_ok;
                        cw     <= cw_any ? (cw & (cw - 64'd1)) : (nw & (nw - 64'd1));
                    end
                    if (w_take) begin
                        nw    <= bm[64*g3 +: 64];
                        ng    <= g3;
                        nw_ok <= g3_ok;
                        gnz   <= gnz & ~({{(NG-1){1'b0}}, 1'b1} << g3);
                    end
                    // (No scan step at this edge: plots are taken only
                    // when the scan is over.)
                    if (take_plot) begin
                        lwx <= lwx_n;
                        lw2 <= lw2_n;
                        g2  <= g2_n;
                        v2  <= v2_n;
                        if (plot_last) begin
                            ptr_ok <= 1'b1;
                            cw     <= lwx_n;
                            nw     <= lw2_n;
                            ng     <= g2_n;
                            nw_ok  <= v2_n;
                            gnz    <= (gnz | ({{(NG-1){1'b0}}, 1'b1} << qg)) & ~start_take;
                        end else begin
                            gnz    <= gnz | ({{(NG-1){1'b0}}, 1'b1} << qg);
                        end
                    end
                end
            end

            // A word's bits count only while its gnz bit is set, so a word
            // the scan takes is never cleared: the row's first plot into
            // it starts it afresh (no write that waits for a scan step).
            genvar g;
            for (g = 0; g < NG; g = g + 1) begin : word
                localparam [GW-1:0] GI = g;
                always @(posedge clk) begin
                    if (take_plot && qg == GI)
                        bm[64*g +: 64] <= (gnz[g] ? bm[64*g +: 64] : 64'd0) | qb;
                end
            end
        end
    endgenerate

    // ------------------------------------------------------------ registers
    always @(posedge clk) begin
        if (rst) begin
            init_done  <= 1'b0;
            sweep_addr <= {AW{1'b0}};
            trk_any    <= 1'b0;
            scanning   <= 1'b0;
            s2_op      <= OP_NONE;
            lw_valid   <= 1'b0;
            hold_v     <= 1'b0;
        end else begin
            if (!init_done) begin
                sweep_addr <= sweep_addr + 1'b1;
                if ({{(32-AW){1'b0}}, sweep_addr} == W_MAX)
                    init_done <= 1'b1;
            end

            hold_v <= stall;
            if (stall)
                hold_d <= cur;

            if (ram_we) begin
                lw_valid <= 1'b1;
                lw_addr  <= ram_wa;
                lw_data  <= ram_wd;
            end

            // Stage 2 completes: the accumulator takes a non-zero cell, and
            // a new span starts there (spec 7.2).
            if (s2_done && (s2_op == OP_CELL) && cell_nz) begin
                start <= s2_addr;
                acc   <= acc_next;
                mask  <= mask_next;
            end

            // Stage 1 -> stage 2.
            if (s2_done) begin
                if (take_plot) begin
                    s2_op   <= OP_PLOT;
                    s2_addr <= plot_q;
                    s2_s    <= plot_s;
                    s2_dir  <= plot_dir;
                    s2_rule <= cfg_rule;
                end else if (scan_cell) begin
                    s2_op   <= OP_CELL;
                    s2_addr <= ptr;
                end else if (scan_flush) begin
                    s2_op   <= OP_FLUSH;
                end else begin
                    s2_op   <= OP_NONE;
                end
            end

            if (scan_cell)
                ptr <= ptr_step;
            if (scan_flush)
                scanning <= 1'b0;

            // Plots: track the row's range; the last one starts the scan.
            // (No CELL op can complete at this edge: plots are taken only
            // when the scan is over, so these writes never collide.)
            if (take_plot) begin
                if (plot_last) begin
                    trk_any  <= 1'b0;
                    scanning <= 1'b1;
                    ptr      <= new_xmin;
                    xend     <= new_xmax;
                    start    <= new_xmin;
                    fy       <= plot_row;
                    f_rule   <= cfg_rule;
                    f_width  <= cfg_width;
                    acc      <= {CW{1'b0}};
                    mask     <= {NS{1'b0}};
                end else begin
                    trk_any  <= 1'b1;
                    trk_xmin <= new_xmin;
                    trk_xmax <= new_xmax;
                end
            end
        end
    end
endmodule
