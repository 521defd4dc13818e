// ef_aet: the sequencer and the active edge table (AET) of the edgeflag
// reference microarchitecture (docs/microarch.md 3.3 and section 4, item 4),
// with PLOT (ef_plot) inside: et_rd and plot out, one transfer per cycle.
//
// What it talks to (docs/microarch.md 3.3, "ETM read side"):
//  * it snoops et_wr (SETUP -> ETM) to learn, before the shape starts, which
//    pixel rows hold new edges (a bit per row: `occ`), the first row and the
//    first record written into that row's slot (so the first row needs no
//    read of the slot heads; the last record may be written two cycles
//    before the row starts);
//  * ETM's slot-head read port (hd_*): one synchronous read, issued at least
//    two cycles before the row starts (there is always the scan between);
//  * ETM's record read port (rec_*): one synchronous read per cycle, giving
//    the record of edge `rec_eid` and the next edge of the same slot in
//    written order (rec_last = none); rec_* hold while rec_re is low.
//
// Row j (schedule item 4), starting at cycle t:
//   t .. t+n-1   et_rd of the slot's n new edges: the head at t, then each
//                record read names the next; the read of edge k gives its
//                record at the next cycle, so the walk learns that edge
//                n-1 was the last at t+n, the row's first plot cycle;
//   then         one plot per cycle: the edges active from earlier rows in
//                AET order (a ring: popped at the front, pushed back at the
//                tail after their last plot in the row if they go on), then
//                the new ones in et_rd order, read again from ETM (edge 0's
//                record is kept from the walk, the walk's last read still
//                holds it when n = 1); the row's last plot has last = 1;
//   then         the scan (ef_slb_fill): the next row starts in the first
//                cycle in which plot_ready is high again.
// In the cycle after the last plot the sequencer picks the next row (j+1 if
// edges stay active, else the first row whose slot still holds edges: rows
// in between cost no cycle), reads its slot head and primes the ring's read.
//
// Ring: depth E_MAX+1 entries, so the push of a survivor never lands on the
// entry being read in the same cycle.  Entries: x (25 bits, enough for any
// sample row inside an edge), e, qs, rs, dy, dir, r1.
//
// Fault defines: EF_FAULT_LASTEDGE drops the last new edge of a shape's
// first row (the walk stops one early when the slot holds two or more).
//
// Synthesizable Verilog-2005.
module ef_aet #(
    parameter NS    = 8,
    parameter H_MAX = 16384,
    parameter E_MAX = 4096
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [14:0] cfg_width,

    // et_wr snoop (transfers only)
    input  wire        etw_valid,
    input  wire        etw_eos,
    input  wire [13:0] etw_slot,

    // ETM slot-head read port
    output wire        hd_re,
    output wire [13:0] hd_row,
    input  wire [EA-1:0] hd_eid,
    output wire        hd_take,     // the row hd_take_row starts: its slot is emptied
    output wire [13:0] hd_take_row,

    // ETM record read port
    output wire        rec_re,
    output wire [EA-1:0] rec_eid,
    input  wire [18:0] rec_r0,
    input  wire [18:0] rec_r1,
    input  wire [24:0] rec_x,
    input  wire [23:0] rec_e,
    input  wire [29:0] rec_qs,
    input  wire [23:0] rec_rs,
    input  wire [23:0] rec_dy,
    input  wire        rec_dir,
    input  wire        rec_last,
    input  wire [EA-1:0] rec_next,

    // et_rd (observation: ETM -> AET)
    output wire        et_rd_valid,
    output wire [13:0] et_rd_row,
    output wire [21:0] et_rd_eid,

    // plot
    output wire        plot_valid,
    input  wire        plot_ready,
    output wire        plot_last,
    output wire [13:0] plot_row,
    output wire [4:0]  plot_s,
    output wire [14:0] plot_q,
    output wire        plot_dir,

    output wire        busy
);
    localparam EA     = (E_MAX > 1) ? $clog2(E_MAX) : 1;
    localparam RDEPTH = E_MAX + 1;
    localparam RA     = $clog2(RDEPTH);
    localparam LOG2NS = (NS == 8) ? 3 : (NS == 16) ? 4 : 5;
    localparam RW     = 25 + 24 + 30 + 24 + 24 + 1 + 19;   // ring entry
    localparam integer NSM1I = NS - 1;
    localparam integer RLASTI = RDEPTH - 1;
    localparam [18:0] NSM1 = NSM1I[18:0];
    localparam [RA-1:0] RLAST = RLASTI[RA-1:0];
    localparam HA     = (H_MAX > 1) ? $clog2(H_MAX) : 1;

    localparam [2:0] PH_IDLE = 3'd0, PH_RD = 3'd1, PH_PL = 3'd2, PH_W1 = 3'd3, PH_W = 3'd4;
    localparam [1:0] SRC_RING = 2'd0, SRC_FIRST = 2'd1, SRC_REC = 2'd2;

    // ------------------------------------------------------------ state
    reg [2:0]    ph;
    reg [H_MAX-1:0] occ;          // rows whose slot holds edges not yet taken
    reg          any_rec;
    reg [13:0]   rmin;
    reg [EA-1:0] rmin_head;
    reg [EA-1:0] wr_eid;          // next record number of the shape

    reg [13:0]   row;
    reg [13:0]   nx_row;
    reg          nx_occ;
    reg          nx_snoop;        // first row: its head is rmin_head

    reg [RA-1:0] rd_ptr, wr_ptr;
    reg [RA:0]   n_old, k_old, aet_cnt;
    reg [EA:0]   n_new, n_new_row;
    /* verilator lint_off UNUSEDSIGNAL */
    reg [EA-1:0] n_rec;           // records of the shape (fault builds only)
    /* verilator lint_on UNUSEDSIGNAL */

    reg          fresh;           // the next plot starts an edge
    reg [1:0]    src;
    // the edge being plotted (after its first cycle)
    reg signed [31:0] cur_x;
    reg [23:0]   cur_e, cur_rs, cur_dy;
    reg [29:0]   cur_qs;
    reg          cur_dir;
    reg [18:0]   cur_r1;
    reg [4:0]    cur_s;
    reg          cur_old, cur_lastnew;
    reg [EA-1:0] cur_next;
    // edge 0 of the row's new edges, kept from the walk
    reg [18:0]   f_r0, f_r1;
    reg [24:0]   f_x;
    reg [23:0]   f_e, f_rs, f_dy;
    reg [29:0]   f_qs;
    reg          f_dir, f_last;
    reg [EA-1:0] f_next;

    // ------------------------------------------------------------ the ring
    wire          ring_we;
    wire [RW-1:0] ring_wd;
    wire          ring_re;
    wire [RW-1:0] ring_rd;
    ef_slb_ram #(.AW(RA), .DW(RW), .DEPTH(RDEPTH)) u_ring (
        .clk(clk), .we(ring_we), .wa(wr_ptr), .wd(ring_wd),
        .re(ring_re), .ra(rd_ptr), .rd(ring_rd)
    );
    wire [24:0] g_x  = ring_rd[RW-1 -: 25];
    wire [23:0] g_e  = ring_rd[RW-26 -: 24];
    wire [29:0] g_qs = ring_rd[RW-50 -: 30];
    wire [23:0] g_rs = ring_rd[RW-80 -: 24];
    wire [23:0] g_dy = ring_rd[RW-104 -: 24];
    wire        g_dir = ring_rd[19];
    wire [18:0] g_r1 = ring_rd[18:0];

    // ------------------------------------------------------------ row data
    wire row_start = (ph == PH_W) && plot_ready;
    wire [13:0] row_now = row_start ? nx_row : row;
    wire [18:0] base = {5'd0, row_now} << LOG2NS;
    wire [18:0] rend = base + NSM1;       // the row's last sample row

    // first row whose slot still holds edges
    function [13:0] first_occ;
        input [H_MAX-1:0] v;
        integer i;
        begin
            first_occ = 14'd0;
            for (i = H_MAX - 1; i >= 0; i = i - 1)
                if (v[i]) first_occ = i[13:0];
        end
    endfunction

    // ------------------------------------------------------------ cycle
    // Row start: the first row right after the eos et_wr, later rows in the
    // first cycle SLB takes plots again.
    wire start_rd  = row_start && nx_occ;
    wire [EA-1:0] head = nx_snoop ? rmin_head : hd_eid;

    // The walk: in PH_RD the record read of the previous cycle is here.
    wire walk_stop;
    wire walk_end  = (ph == PH_RD) && walk_stop;
    wire walk_more = (ph == PH_RD) && !walk_stop;

    // Plotting this cycle.
    wire in_plot = (ph == PH_PL) || (row_start && !nx_occ) || walk_end;
    wire first_plot = (ph != PH_PL);     // the row's first plot (always fresh)
    wire [EA:0] n_new_now = (ph == PH_RD) ? n_new : {(EA+1){1'b0}};
    wire [EA:0] nn = first_plot ? n_new_now : n_new_row;   // new edges of the row
    wire [1:0] src_now = !first_plot ? src
                       : (n_old != 0) ? SRC_RING
                       : (n_new_now == 1) ? SRC_REC : SRC_FIRST;
    wire fr = fresh || first_plot;

    // The edge's state this cycle.
    reg signed [31:0] S_x;
    reg [23:0] S_e, S_rs, S_dy;
    reg [29:0] S_qs;
    reg        S_dir;
    reg [18:0] S_r0, S_r1;
    reg        S_old, S_lastnew;
    reg [EA-1:0] S_next;
    always @* begin
        S_x = cur_x; S_e = cur_e; S_qs = cur_qs; S_rs = cur_rs; S_dy = cur_dy; S_dir = cur_dir;
        S_r0 = base; S_r1 = cur_r1; S_old = cur_old; S_lastnew = cur_lastnew; S_next = cur_next;
        if (fr) begin
            case (src_now)
                SRC_RING: begin
                    S_x = {{7{g_x[24]}}, g_x}; S_e = g_e; S_qs = g_qs; S_rs = g_rs; S_dy = g_dy;
                    S_dir = g_dir; S_r0 = base; S_r1 = g_r1; S_old = 1'b1; S_lastnew = 1'b0;
                    S_next = {EA{1'b0}};
                end
                SRC_FIRST: begin
                    S_x = {{7{f_x[24]}}, f_x}; S_e = f_e; S_qs = f_qs; S_rs = f_rs; S_dy = f_dy;
                    S_dir = f_dir; S_r0 = f_r0; S_r1 = f_r1; S_old = 1'b0; S_lastnew = f_last;
                    S_next = f_next;
                end
                default: begin
                    S_x = {{7{rec_x[24]}}, rec_x}; S_e = rec_e; S_qs = rec_qs; S_rs = rec_rs; S_dy = rec_dy;
                    S_dir = rec_dir; S_r0 = rec_r0; S_r1 = rec_r1; S_old = 1'b0; S_lastnew = rec_last;
                    S_next = rec_next;
                end
            endcase
        end
    end
    /* verilator lint_off UNUSEDSIGNAL */
    wire [18:0] s0w   = (S_r0 > base) ? (S_r0 - base) : 19'd0;   // < NS
    wire [4:0]  s_now = fr ? s0w[4:0] : cur_s;
    wire [18:0] sl_w  = ((S_r1 < rend) ? S_r1 : rend) - base;     // < NS
    /* verilator lint_on UNUSEDSIGNAL */
    wire        edge_done = (s_now == sl_w[4:0]);
    wire        survive   = S_r1 > rend;
    wire [RA:0] k_old_now = first_plot ? {(RA+1){1'b0}} : k_old;
    wire        more_old  = S_old && (k_old_now + 1'b1 < n_old);
    wire        row_last  = S_old ? (!more_old && nn == 0) : S_lastnew;

    wire [14:0] q;
    wire signed [31:0] x_next;
    wire [23:0] e_next;
    ef_plot #(.NS(NS)) u_plot (
        .s(s_now), .x(S_x), .e(S_e), .qs(S_qs), .rs(S_rs), .dy(S_dy), .width(cfg_width),
        .q(q), .x_next(x_next), .e_next(e_next)
    );

    // next edge's source when this one is done
    wire rd_ring_next = in_plot && edge_done && more_old;
    wire rd_rec_next  = in_plot && edge_done && !S_old && !S_lastnew;
    // leaving the old edges for the new ones: edge 0 needs no read
    wire [1:0] src_next = more_old ? SRC_RING
                        : S_old ? ((nn == 1) ? SRC_REC : SRC_FIRST)
                        : SRC_REC;

    // ------------------------------------------------------------ outputs
    assign plot_valid = in_plot;
    assign plot_last  = in_plot && edge_done && row_last;
    assign plot_row   = row_now;
    assign plot_s     = s_now;
    assign plot_q     = q;
    assign plot_dir   = S_dir;

    assign et_rd_valid = start_rd || walk_more;
    assign et_rd_row   = row_now;
    wire [EA-1:0] rd_eid = start_rd ? head : rec_next;
    assign et_rd_eid   = {{(22-EA){1'b0}}, rd_eid};

    // ETM ports
    wire w1 = (ph == PH_W1);
    wire [13:0] row1 = row + 14'd1;
    wire        occ1 = occ[row1[HA-1:0]];
    wire [13:0] nx_calc = (aet_cnt != 0) ? row1 : first_occ(occ);
    assign hd_re  = w1 && (aet_cnt != 0 ? occ1 : (occ != {H_MAX{1'b0}}));
    assign hd_row = nx_calc;
    assign hd_take = start_rd;
    assign hd_take_row = row_now;
    assign rec_re  = et_rd_valid || rd_rec_next;
    assign rec_eid = et_rd_valid ? rd_eid : S_next;

    assign ring_re = (w1 && aet_cnt != 0) || rd_ring_next;
    assign ring_we = in_plot && edge_done && survive;
    assign ring_wd = {x_next[24:0], e_next, S_qs, S_rs, S_dy, S_dir, S_r1};

    assign busy = (ph != PH_IDLE);

`ifdef EF_FAULT_LASTEDGE
    assign walk_stop = rec_last || (rec_next == n_rec - 1'b1);
`else
    assign walk_stop = rec_last;
`endif

    // ------------------------------------------------------------ registers
    function [RA-1:0] inc;
        input [RA-1:0] p;
        begin
            inc = (p == RLAST) ? {RA{1'b0}} : p + 1'b1;
        end
    endfunction

    always @(posedge clk) begin
        if (rst) begin
            ph <= PH_IDLE;
            occ <= {H_MAX{1'b0}};
            any_rec <= 1'b0;
            wr_eid <= {EA{1'b0}};
            rd_ptr <= {RA{1'b0}};
            wr_ptr <= {RA{1'b0}};
            aet_cnt <= {(RA+1){1'b0}};
            n_old <= {(RA+1){1'b0}};
            fresh <= 1'b1;
        end else begin
            // snoop et_wr: the shape's records, before its rows start
            if (etw_valid && !etw_eos) begin
                occ[etw_slot[HA-1:0]] <= 1'b1;
                wr_eid <= wr_eid + 1'b1;
                if (!occ[etw_slot[HA-1:0]] && (!any_rec || etw_slot < rmin)) begin
                    rmin <= etw_slot;
                    rmin_head <= wr_eid;
                end
                any_rec <= 1'b1;
            end
            if (etw_valid && etw_eos) begin
                wr_eid <= {EA{1'b0}};
                n_rec <= wr_eid;
                any_rec <= 1'b0;
                if (any_rec) begin
                    ph <= PH_W;
                    nx_row <= rmin;
                    nx_occ <= 1'b1;
                    nx_snoop <= 1'b1;
                    n_old <= {(RA+1){1'b0}};
                    aet_cnt <= {(RA+1){1'b0}};
                end
            end

            if (row_start) begin
                row <= nx_row;
                occ[nx_row[HA-1:0]] <= 1'b0;
                nx_snoop <= 1'b0;
                if (nx_occ) begin
                    ph <= PH_RD;
                    n_new <= {{EA{1'b0}}, 1'b1};
                end
            end
            if (ph == PH_RD) begin
                if (n_new == 1) begin
                    f_r0 <= rec_r0; f_r1 <= rec_r1; f_x <= rec_x; f_e <= rec_e; f_qs <= rec_qs;
                    f_rs <= rec_rs; f_dy <= rec_dy; f_dir <= rec_dir; f_last <= rec_last; f_next <= rec_next;
                end
                if (walk_more)
                    n_new <= n_new + 1'b1;
            end

            if (in_plot) begin
                if (first_plot) begin
                    ph <= PH_PL;
                    k_old <= {(RA+1){1'b0}};
                    n_new_row <= n_new_now;
                end
                if (edge_done) begin
                    fresh <= 1'b1;
                    src <= src_next;
                    if (S_old)
                        k_old <= k_old_now + 1'b1;
                    if (survive) begin
                        wr_ptr <= inc(wr_ptr);
                        aet_cnt <= aet_cnt + 1'b1;
                    end
                    if (row_last)
                        ph <= PH_W1;
                end else begin
                    fresh <= 1'b0;
                    cur_x <= x_next; cur_e <= e_next; cur_qs <= S_qs; cur_rs <= S_rs; cur_dy <= S_dy;
                    cur_dir <= S_dir; cur_r1 <= S_r1; cur_s <= s_now + 1'b1;
                    cur_old <= S_old; cur_lastnew <= S_lastnew; cur_next <= S_next;
                end
            end

            if (ring_re)
                rd_ptr <= inc(rd_ptr);

            if (w1) begin
                n_old <= aet_cnt;
                aet_cnt <= {(RA+1){1'b0}};
                nx_row <= nx_calc;
                nx_occ <= (aet_cnt != 0) ? occ1 : 1'b1;
                if (aet_cnt == 0 && occ == {H_MAX{1'b0}})
                    ph <= PH_IDLE;
                else
                    ph <= PH_W;
            end
        end
    end
endmodule
