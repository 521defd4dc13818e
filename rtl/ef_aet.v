// ef_aet: the sequencer and the active edge table (AET) of the edgeflag
// reference microarchitecture (docs/microarch.md 3.3, 3.6 and section 4,
// item 4), with PLOT (ef_plot) inside: it takes et_rd from ETM (ef_etm) and
// issues one plot per cycle.
//
// What it talks to:
//  * it snoops et_wr (SETUP -> ETM): a bit per pixel row whose slot holds
//    edges (`occ`) and the shape's first row.  A row whose slot is empty
//    while the AET is empty costs no cycle (schedule item 4), so after the
//    AET empties the next row must be known at once: the least set bit of
//    occ (rows are taken in increasing order, each clears its bit);
//  * ETM's row requests (row_req, a cycle or more before the row starts;
//    ETM then presents the slot's list on et_rd and holds it until
//    et_rd_ready) and its record read port (rec_*, the record one cycle
//    after the read, held while rec_re is low).
//
// Row j, starting at cycle t (the first cycle SLB takes plots again, or
// T0 for the shape's first row):
//   t .. t+n-1  et_rd of the slot's n new edges (et_rd_ready high), each
//               with a record read; the records arrive at t+1 .. t+n and
//               all but the last are appended to the ring;
//   t+n         (n > 0 only) the last record into its register (EF_L_REC)
//   t+n+r ..    one plot per cycle, r = EF_L_REC if n > 0 else 0 (computed
//               here, presented on plot EF_L_PLOT = 2 cycles later by the
//               plot pipeline: t+n+r+2 ..): the ring's edges in order (those
//               active from earlier rows, then the new ones), the last new
//               edge from the record register (rec_q); each edge
//               goes back to the ring's tail after its last plot in the row
//               if its last sample row is below the row.  So the ring is
//               a FIFO whose order is the AET order of the schedule, and
//               the new edges' arrivals never meet a push (they end before
//               the first plot).
//   then        the scan (ef_slb_fill).
// In the cycle after the row's last plot the sequencer picks the next row
// (j+1 if the ring holds edges, else the least row whose slot holds edges;
// none: the shape is done), requests it from ETM if its slot holds edges,
// and reads the ring's front (the next row's first edge): the scan takes at
// least two cycles, so both are there when the row starts.
//
// The ring: one synchronous memory of E_MAX+1 entries (never full, so the
// tail write never lands on the entry held at the read port) with one
// forwarding register: the front read in the cycle an arrival is written
// to that entry (two new edges and nothing older) takes the written data.
// An entry is {x, e, qs, rs, drs, dir, s0, r1, h}: the et_wr fields
// (ef_ifaces.vh) with drs = dy - rs in dy's place, of r0 only s0 = r0's
// sample row within its pixel row (0 for a survivor), and h: r1 lies in
// the row the entry is plotted in next (set on arrival and on the push):
// 153 bits at the widths of ef_ifaces.vh.
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

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
    input  wire [`EF_ET_WR_SLOT_W-1:0] etw_slot,

    // ETM row requests
    output wire        row_req,
    output wire [`EF_ET_RD_ROW_W-1:0] row_req_row,

    // et_rd: row[13:0] eid[21:0] (+ ETM's side band et_rd_last)
    input  wire        et_rd_valid,
    output wire        et_rd_ready,
    input  wire [`EF_ET_RD_ROW_W-1:0] et_rd_row,
    input  wire [`EF_ET_RD_EID_W-1:0] et_rd_eid,
    input  wire        et_rd_last,

    // ETM record read port
    output wire        rec_re,
    output wire [`EF_ET_RD_EID_W-1:0] rec_ra,
    input  wire [`EF_ET_WR_R0_W-1:0] rec_r0,
    input  wire [`EF_ET_WR_R1_W-1:0] rec_r1,
    input  wire [`EF_ET_WR_X_W-1:0] rec_x,
    input  wire [`EF_ET_WR_E_W-1:0] rec_e,
    input  wire [`EF_ET_WR_QS_W-1:0] rec_qs,
    input  wire [`EF_ET_WR_RS_W-1:0] rec_rs,
    input  wire [`EF_ET_WR_DY_W-1:0] rec_dy,
    input  wire        rec_dir,

    // plot: last[0] row[13:0] s[4:0] q[14:0] dir[0]
    output wire        plot_valid,
    input  wire        plot_ready,
    output wire        plot_last,
    output wire [`EF_PLOT_ROW_W-1:0] plot_row,
    output wire [`EF_PLOT_S_W-1:0] plot_s,
    output wire [`EF_PLOT_Q_W-1:0] plot_q,
    output wire        plot_dir,

    output wire        busy          // a shape's rows are not all plotted
);
    localparam EA     = (E_MAX > 1) ? $clog2(E_MAX) : 1;
    localparam RDEPTH = E_MAX + 1;
    localparam RA     = $clog2(RDEPTH);
    `include "ef_ns.vh"
    // a ring entry {x, e, qs, rs, dy, dir, r0, r1}: each field's position
    localparam O_H    = 0;                          // r1 lies in the row the entry is plotted in next
    localparam O_R1   = O_H + 1;
    localparam O_R0   = O_R1 + `EF_ET_WR_R1_W;
    localparam O_DIR  = O_R0 + `EF_PLOT_S_W;        // s0, not r0
    localparam O_DY   = O_DIR + `EF_ET_WR_DIR_W;
    localparam O_RS   = O_DY + `EF_ET_WR_DY_W;      // O_DY: drs = dy - rs, not dy
    localparam O_QS   = O_RS + `EF_ET_WR_RS_W;
    localparam O_E    = O_QS + `EF_ET_WR_QS_W;
    localparam O_X    = O_E + `EF_ET_WR_E_W;
    localparam RW     = O_X + `EF_ET_WR_X_W;
    localparam ROWW   = `EF_PLOT_ROW_W;          // a pixel row
    localparam SRW    = `EF_ET_WR_R0_W;          // a sample row
    localparam HA     = (H_MAX > 1) ? $clog2(H_MAX) : 1;
    localparam integer NSM1I  = NS - 1;
    localparam integer RLASTI = RDEPTH - 1;
    localparam [SRW-1:0] NSM1 = NSM1I[SRW-1:0];
    localparam [RA-1:0] RLAST = RLASTI[RA-1:0];

    localparam [2:0] PH_IDLE = 3'd0, PH_RD = 3'd1, PH_P0 = 3'd2, PH_PL = 3'd3, PH_W1 = 3'd4, PH_W = 3'd5,
                     PH_W2 = 3'd6,   // the row's last plot in stage p (EF_L_PLOT = 2)
                     PH_RX = 3'd7;   // the last record into its register (EF_L_REC = 1)

    // ------------------------------------------------------------ state
    reg [2:0]       ph;
    reg [H_MAX-1:0] occ;          // rows whose slot holds edges not yet taken
    reg             any_rec;
    reg [ROWW-1:0]  rmin;

    reg [ROWW-1:0] row;
    reg [ROWW-1:0] nx_row;
    reg          nx_occ;

    reg [RA-1:0] rd_ptr, wr_ptr;
    reg [RA:0]   n_old;           // edges active from earlier rows
    reg [RA:0]   aet_cnt;         // survivors pushed in this row
    reg [EA:0]   n_new;           // new edges of the row
    // the row's position (issue 25: registered, off the ring's read path):
    reg [RA+1:0] rem;             // edges of the row after the one plotted
    reg          rem_is0;         // rem == 0
    reg          nn_nz;           // the row has new edges (n_new != 0)
    reg [RA+1:0] fo_m1;           // n_old - 1: a row without new edges' first plot
    reg          fo_is0, fo_is1;  // fo_m1 == 0, == 1
    reg [RA+1:0] fb_m1;           // n_old + n_new - 1: after the row's et_rd
    reg          fb_is0, fb_is1;  // fb_m1 == 0, == 1
    reg          arr_v, arr_last; // a record arrives this cycle

    reg          fresh;           // this plot starts an edge
    reg signed [31:0] cur_x;
    reg [`EF_ET_WR_E_W-1:0]  cur_e;
    reg [`EF_ET_WR_RS_W-1:0] cur_rs;
    reg [`EF_ET_WR_DY_W-1:0] cur_drs;
    reg [`EF_ET_WR_QS_W-1:0] cur_qs;
    reg          cur_dir;
    reg [SRW-1:0] cur_r1;
    reg          cur_h;
    reg [`EF_PLOT_S_W-1:0] cur_s;

    // ------------------------------------------------------------ the ring
    wire          ring_we, ring_re;
    wire [RW-1:0] ring_wd, ring_q;
    ef_slb_ram #(.AW(RA), .DW(RW), .DEPTH(RDEPTH)) u_ring (
        .clk(clk), .we(ring_we), .wa(wr_ptr), .wd(ring_wd),
        .re(ring_re), .ra(rd_ptr), .rd(ring_q)
    );
    reg          lw_v;
    reg [RA-1:0] lw_addr, rq_addr;
    reg [RW-1:0] lw_data;
    // the front read in the cycle its entry was written: the written data
    wire          fwd_hit = lw_v && (lw_addr == rq_addr);

    // ------------------------------------------------------------ row data
    wire        row_start = (ph == PH_W) && plot_ready;
    // In PH_W the row's data mean something only when it starts: taking them
    // from the phase alone keeps SLB's plot_ready out of the datapath (issue
    // 25: it only enables).
    wire            in_w = (ph == PH_W);
    wire [ROWW-1:0] row_now = in_w ? nx_row : row;

    // The least set bit of occ in log depth instead of a priority chain as
    // long as H_MAX (the critical path of the block in docs/synthesis.md),
    // over groups of 64 rows (the two-level bitmap of docs/microarch.md 3.5):
    // a per-group "any" (an OR of 64 bits), the least group with a set bit
    // and the least set bit of that group's word, each by a binary tree
    // (pass l halves the nodes, each the OR of its two children and the
    // index of the least set bit below it: the lower child's when it has
    // one, else the upper's with bit l-1 set; in place, node j reads nodes 2j
    // and 2j+1, never one already rewritten in the same pass).  0 when occ is
    // empty, as before.  Written with loops in a function, not generate (a
    // generate loop is unrolled by Verilator, and H_MAX reaches 16384), over
    // groups so that a simulator takes about NG + 64 steps per evaluation,
    // not H_MAX.
    localparam GA  = 6;                              // 64 rows per group
    localparam NG  = (H_MAX + 63) / 64;
    localparam NGA = (NG > 1) ? $clog2(NG) : 1;
    localparam PG  = 1 << NGA;                       // groups, a power of two
    localparam [NGA-1:0] G_ONE = 1;
    localparam [GA-1:0]  B_ONE = 1;
    localparam [PG*64-1:0] W_NONE = 0;              // (a replication this wide is a lint warning)
    localparam [H_MAX-1:0] OCC_NONE = 0;
    /* verilator lint_off UNUSEDSIGNAL */
    function [HA-1:0] first_occ;
        input [H_MAX-1:0] occ_v;
        reg [PG*64-1:0]   w;
        reg [PG-1:0]      gv;      // group node has a set bit
        reg [PG*NGA-1:0]  gi;      // its least group with one
        reg [63:0]        bv;      // bit node of the chosen word has a set bit
        reg [64*GA-1:0]   bi;      // its least set bit
        reg [NGA+GA-1:0]  full;
        integer g, lv, j;
        begin
            w = W_NONE;
            w[H_MAX-1:0] = occ_v;
            for (g = 0; g < PG; g = g + 1)
                gv[g] = |w[g*64 +: 64];
            gi = {(PG*NGA){1'b0}};
            for (lv = 1; lv <= NGA; lv = lv + 1)
                for (j = 0; j < (PG >> lv); j = j + 1) begin
                    gi[j*NGA +: NGA] = gv[2*j] ? gi[(2*j)*NGA +: NGA]
                                               : (gi[(2*j+1)*NGA +: NGA] | (G_ONE << (lv - 1)));
                    gv[j] = gv[2*j] | gv[2*j+1];
                end
            bv = w[gi[NGA-1:0]*64 +: 64];
            bi = {(64*GA){1'b0}};
            for (lv = 1; lv <= GA; lv = lv + 1)
                for (j = 0; j < (64 >> lv); j = j + 1) begin
                    bi[j*GA +: GA] = bv[2*j] ? bi[(2*j)*GA +: GA]
                                             : (bi[(2*j+1)*GA +: GA] | (B_ONE << (lv - 1)));
                    bv[j] = bv[2*j] | bv[2*j+1];
                end
            // the index is below H_MAX <= 2^HA: the bits above HA are 0
            full = {gi[NGA-1:0], bi[GA-1:0]};
            first_occ = gv[0] ? full[HA-1:0] : {HA{1'b0}};
        end
    endfunction
    /* verilator lint_on UNUSEDSIGNAL */
    wire [HA-1:0] ffs_ix = first_occ(occ);

    // ------------------------------------------------------------ et_rd
    wire in_rd = (ph == PH_RD) || (row_start && nx_occ);
    assign et_rd_ready = in_rd;
    wire rd_take = et_rd_valid && in_rd;
    assign rec_re = rd_take;
    assign rec_ra = et_rd_eid;
    wire [EA:0] n_new_now = in_w ? {(EA+1){1'b0}} : n_new;
    wire rd_end = rd_take && et_rd_last;
    // n_all - 1 once this et_rd is taken (the row's edges: n_old and the new ones so far)
    wire [RA+1:0] n_rd = {1'b0, n_old} + {{(RA+1-EA){1'b0}}, n_new_now};

    // ------------------------------------------------------------ plotting
    wire in_plot = (ph == PH_P0) || (ph == PH_PL) || (row_start && !nx_occ);
    wire first   = (ph != PH_PL);             // the row's first plot
    wire fr      = first || fresh;
    // edges of the row, and which come from the record port (the last new)
    // rem_now: the edges of the row after this one (n_all - 1 - k with n_all
    // = n_old + the row's new edges, k the edges done), from registers: at
    // the row's first plot the count set up in W1 (no new edges) or by the
    // et_rd (with new edges), else the running count
    wire        rec_edge = !in_w && nn_nz;     // the last edge comes from rec_*
    wire [RA+1:0] rem_now = first ? (in_w ? fo_m1 : fb_m1) : rem;
    wire        is0_now = first ? (in_w ? fo_is0 : fb_is0) : rem_is0;
    wire        is1_now = first ? (in_w ? fo_is1 : fb_is1) : (rem == {{(RA+1){1'b0}}, 1'b1});
    wire        from_rec = fr && rec_edge && is0_now;

    // The record port's entry (as the ring keeps it: s0 for r0, drs = dy -
    // rs for dy), written to the ring on arrival and registered (rec_q):
    // the last new edge is taken from that register, a cycle after it
    // arrives (EF_L_REC = 1, the PH_RX cycle), not from ETM's memory port.
    wire [`EF_PLOT_S_W-1:0] rec_s0 = rec_r0[`EF_PLOT_S_W-1:0] & NSM1[`EF_PLOT_S_W-1:0];   // a new edge: r0 in this row
    /* verilator lint_off UNUSEDSIGNAL */
    wire [`EF_ET_WR_R0_W-1:0] unused_rec_r0 = rec_r0;   // (s0 and h use parts of it)
    /* verilator lint_on UNUSEDSIGNAL */
    wire [`EF_ET_WR_DY_W-1:0] rec_drs = rec_dy - rec_rs;
    // a new edge is plotted first in its slot's row, r0's: r1 in that row too?
    wire          rec_h = ((rec_r1 >> LOG2NS) == (rec_r0 >> LOG2NS));
    wire [RW-1:0] rec_ent = {rec_x, rec_e, rec_qs, rec_rs, rec_drs, rec_dir, rec_s0, rec_r1, rec_h};
    reg  [RW-1:0] rec_q;
    // The edge's state: the ring's read port, else (decoded from registers
    // alone, so the memory's output passes one multiplexer) the record
    // register, the forwarded write or the edge's running state.
    wire          use_ring = fr && !from_rec && !fwd_hit;
    wire [RW-1:0] alt = from_rec ? rec_q : lw_data;
    wire signed [31:0] S_x = use_ring ? {{(32-`EF_ET_WR_X_W){ring_q[RW-1]}}, ring_q[O_X +: `EF_ET_WR_X_W]}
                           : fr ? {{(32-`EF_ET_WR_X_W){alt[RW-1]}}, alt[O_X +: `EF_ET_WR_X_W]} : cur_x;
    wire [`EF_ET_WR_E_W-1:0]  S_e   = use_ring ? ring_q[O_E +: `EF_ET_WR_E_W]
                                    : fr ? alt[O_E +: `EF_ET_WR_E_W] : cur_e;
    wire [`EF_ET_WR_QS_W-1:0] S_qs  = use_ring ? ring_q[O_QS +: `EF_ET_WR_QS_W]
                                    : fr ? alt[O_QS +: `EF_ET_WR_QS_W] : cur_qs;
    wire [`EF_ET_WR_RS_W-1:0] S_rs  = use_ring ? ring_q[O_RS +: `EF_ET_WR_RS_W]
                                    : fr ? alt[O_RS +: `EF_ET_WR_RS_W] : cur_rs;
    wire [`EF_ET_WR_DY_W-1:0] S_drs = use_ring ? ring_q[O_DY +: `EF_ET_WR_DY_W]
                                    : fr ? alt[O_DY +: `EF_ET_WR_DY_W] : cur_drs;
    wire        S_dir = use_ring ? ring_q[O_DIR] : fr ? alt[O_DIR] : cur_dir;
    wire [`EF_PLOT_S_W-1:0] S_s0 = use_ring ? ring_q[O_R0 +: `EF_PLOT_S_W] : alt[O_R0 +: `EF_PLOT_S_W];
    wire [SRW-1:0] S_r1 = use_ring ? ring_q[O_R1 +: SRW] : fr ? alt[O_R1 +: SRW] : cur_r1;
    wire        S_h  = use_ring ? ring_q[O_H] : fr ? alt[O_H] : cur_h;

    // The edge's first and last sample rows in this row, and whether it
    // survives it, without compares or subtractions against the row's
    // first sample row (issue 25: they were on the ring's read path): an
    // edge plotted in row j has r1 >= j*NS (a survivor of row j-1 has r1
    // past that row's last sample row, a new edge r1 >= r0), and r0 either
    // in row j (a new edge: its slot is r0's row) or 0 (a survivor, written
    // so), so s0 = r0 - j*NS is r0's low bits (0 for a survivor: the ring
    // keeps only these bits, s0, for every edge); the last
    // sample row is r1 - j*NS if r1 is in row j, else NS-1; it survives iff
    // r1 is past row j.
    wire [SRW-1:0] row_sr = {{(SRW-ROWW){1'b0}}, row_now};
    // a survivor is plotted next in row j+1: r1 in that row?
    wire        push_h = ((S_r1 >> LOG2NS) == row_sr + 1'b1);
    wire        r1_here = S_h;     // kept with the entry (issue 25: no compare on the ring's read path)
    wire [`EF_PLOT_S_W-1:0] s0w = S_s0;
    wire [`EF_PLOT_S_W-1:0] slw = r1_here ? S_r1[`EF_PLOT_S_W-1:0] & NSM1[`EF_PLOT_S_W-1:0] : NSM1[`EF_PLOT_S_W-1:0];
    wire [`EF_PLOT_S_W-1:0] s_now = fr ? s0w : cur_s;
    wire        edge_done = (s_now == slw);
    wire        survive   = !r1_here;
    wire        row_last  = is0_now;
    // the next edge is in the ring (not the record port's)
    wire        next_ring = !row_last && !(rec_edge && is1_now);

    // PLOT's DDA step here, in the sequencer's cycle (its state feeds the
    // next plot of the edge); its q is formed a cycle later (below).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [`EF_PLOT_Q_W-1:0] q_unused;
    /* verilator lint_on UNUSEDSIGNAL */
    wire signed [31:0] x_next;
    wire [`EF_ET_WR_E_W-1:0] e_next;
    ef_plot #(.NS(NS)) u_plot (
        .s(s_now), .x(S_x), .e(S_e), .qs(S_qs), .rs(S_rs), .drs(S_drs), .width(cfg_width),
        .q(q_unused), .x_next(x_next), .e_next(e_next)
    );

    // The plot pipeline (issue 25), EF_L_PLOT = 2 registers deep: the
    // sequencer's cycle registers the plot's sample row and x (stage a);
    // the next cycle forms q (PLOT's offset add, shift and clamp: a second
    // ef_plot whose DDA outputs are unused) and registers it with the rest
    // of the plot (stage p, the plot outputs).  So no combinational path
    // runs from the ring, the record port or PLOT's carry chains into SLB,
    // nor from the ring's read port through PLOT's clamp.  SLB is ready for
    // every plot of a row (it drops plot_ready only after taking the row's
    // last), so the registers never hold a plot that is not taken.
    reg        a_valid, a_last, a_dir;
    reg [`EF_PLOT_ROW_W-1:0] a_row;
    reg [`EF_PLOT_S_W-1:0]   a_s;
    reg signed [31:0]        a_x;
    always @(posedge clk) begin
        if (rst)
            a_valid <= 1'b0;
        else
            a_valid <= in_plot;
        a_last <= in_plot && edge_done && row_last;
        a_row  <= row_now;
        a_s    <= s_now;
        a_x    <= S_x;
        a_dir  <= S_dir;
    end

    wire [`EF_PLOT_Q_W-1:0] q;
    /* verilator lint_off UNUSEDSIGNAL */
    wire signed [31:0] a_x_unused;
    wire [`EF_ET_WR_E_W-1:0] a_e_unused;
    /* verilator lint_on UNUSEDSIGNAL */
    ef_plot #(.NS(NS)) u_plot_q (
        .s(a_s), .x(a_x), .e({`EF_ET_WR_E_W{1'b0}}), .qs({`EF_ET_WR_QS_W{1'b0}}),
        .rs({`EF_ET_WR_RS_W{1'b0}}), .drs({`EF_ET_WR_DY_W{1'b0}}), .width(cfg_width),
        .q(q), .x_next(a_x_unused), .e_next(a_e_unused)
    );

    reg        p_valid, p_last, p_dir;
    reg [`EF_PLOT_ROW_W-1:0] p_row;
    reg [`EF_PLOT_S_W-1:0]   p_s;
    reg [`EF_PLOT_Q_W-1:0]   p_q;
    always @(posedge clk) begin
        if (rst)
            p_valid <= 1'b0;
        else
            p_valid <= a_valid;
        p_last <= a_last;
        p_row  <= a_row;
        p_s    <= a_s;
        p_q    <= q;
        p_dir  <= a_dir;
    end
    assign plot_valid = p_valid;
    assign plot_last  = p_last;
    assign plot_row   = p_row;
    assign plot_s     = p_s;
    assign plot_q     = p_q;
    assign plot_dir   = p_dir;

    // ------------------------------------------------------------ ring ports
    wire push   = in_plot && edge_done && survive;
    wire arrive = arr_v && !arr_last;            // t+1 .. t+n-1: no plot yet
    assign ring_we = push || arrive;
    // the write data chosen by the arrival (registers), not by the push
    // (PLOT's edge_done: issue 25), as the two never meet
    // a survivor's r0 is 0: in later rows it starts at sample row 0
    assign ring_wd = arrive ? rec_ent
                            : {x_next[`EF_ET_WR_X_W-1:0], e_next, S_qs, S_rs, S_drs, S_dir, {`EF_PLOT_S_W{1'b0}}, S_r1, push_h};
    wire w1 = (ph == PH_W1);
    // reads: the next row's first edge (after the last plot), the first new
    // edge of a row without older ones (with the last et_rd), the next edge
    // after an edge's last plot
    assign ring_re = (w1 && aet_cnt != 0)
                   || (rd_end && n_old == 0 && n_new_now != 0)
                   || (in_plot && edge_done && next_ring);

    // ------------------------------------------------------------ next row
    wire [ROWW-1:0] row1 = row + {{(ROWW-1){1'b0}}, 1'b1};
    wire        occ1 = occ[row1[HA-1:0]];
    wire [ROWW-1:0] ffs;                       // changes only with occ
    generate
        if (HA < ROWW) begin : ffs_ext
            assign ffs = {{(ROWW-HA){1'b0}}, ffs_ix};
        end else begin : ffs_full
            assign ffs = ffs_ix[ROWW-1:0];
        end
    endgenerate
    wire [ROWW-1:0] nx_calc = (aet_cnt != 0) ? row1 : ffs;
    wire        nx_occ_calc = (aet_cnt != 0) ? occ1 : 1'b1;
    wire        shape_end = (aet_cnt == 0) && (occ == OCC_NONE);
    wire        eos_go = etw_valid && etw_eos && any_rec;
    assign row_req     = eos_go || (w1 && !shape_end && nx_occ_calc);
    assign row_req_row = eos_go ? rmin : nx_calc;

    assign busy = (ph != PH_IDLE) || a_valid || p_valid;

    // et_rd's row field is not used here: the sequencer knows the row it
    // requested, and ETM presents that row's list.  The field is on the
    // port because et_rd is a dumped interface (docs/microarch.md 3.3);
    // nothing compares it in the RTL (the benches' `edgeflag check` does).
    /* verilator lint_off UNUSEDSIGNAL */
    wire [`EF_ET_RD_ROW_W-1:0] unused_rd_row = et_rd_row;
    /* verilator lint_on UNUSEDSIGNAL */

    function [RA-1:0] inc;
        input [RA-1:0] p;
        begin
            inc = (p == RLAST) ? {RA{1'b0}} : p + 1'b1;
        end
    endfunction

    // ------------------------------------------------------------ registers
    always @(posedge clk) begin
        if (rst) begin
            ph <= PH_IDLE;
            occ <= OCC_NONE;
            any_rec <= 1'b0;
            rd_ptr <= {RA{1'b0}};
            wr_ptr <= {RA{1'b0}};
            aet_cnt <= {(RA+1){1'b0}};
            n_old <= {(RA+1){1'b0}};
            n_new <= {(EA+1){1'b0}};
            arr_v <= 1'b0;
            lw_v <= 1'b0;
            fresh <= 1'b1;
        end else begin
            // snoop et_wr: the shape's records, before its rows start
            if (etw_valid && !etw_eos) begin
                occ[etw_slot[HA-1:0]] <= 1'b1;
                if (!any_rec || etw_slot < rmin)
                    rmin <= etw_slot;
                any_rec <= 1'b1;
            end
            if (etw_valid && etw_eos) begin
                any_rec <= 1'b0;
                if (any_rec) begin
                    ph <= PH_W;
                    nx_row <= rmin;
                    nx_occ <= 1'b1;
                    n_old <= {(RA+1){1'b0}};
                    aet_cnt <= {(RA+1){1'b0}};
                end
            end

            if (ring_we)
                wr_ptr <= inc(wr_ptr);
            // The forwarding register keeps the last arrival: only an
            // arrival's entry is ever read in the cycle it is written (the
            // first of two new edges with no older one; a push goes to the
            // tail while the front is read, and the ring is never full); a
            // push invalidates it, so it never shadows a newer write.
            if (arrive) begin
                lw_v <= 1'b1;
                lw_addr <= wr_ptr;
                lw_data <= rec_ent;
            end else if (push) begin
                lw_v <= 1'b0;
            end
            if (ring_re) begin
                rd_ptr <= inc(rd_ptr);
                rq_addr <= rd_ptr;
            end

            arr_v <= rd_take;
            arr_last <= rd_end;
            if (arr_v)
                rec_q <= rec_ent;

            if (row_start) begin
                row <= nx_row;
                occ[nx_row[HA-1:0]] <= 1'b0;
                n_new <= {(EA+1){1'b0}};
                nn_nz <= 1'b0;
                if (nx_occ)
                    ph <= PH_RD;
            end
            if (rd_take) begin
                n_new <= n_new_now + 1'b1;
                nn_nz <= 1'b1;
                fb_m1 <= n_rd;
                fb_is0 <= (n_rd == {(RA+2){1'b0}});
                fb_is1 <= (n_rd == {{(RA+1){1'b0}}, 1'b1});
                if (rd_end)
                    ph <= PH_RX;
            end

            if (in_plot) begin
                ph <= PH_PL;
                if (edge_done) begin
                    fresh <= 1'b1;
                    rem <= rem_now - 1'b1;
                    rem_is0 <= is1_now;
                    if (push)
                        aet_cnt <= aet_cnt + 1'b1;
                    if (row_last) begin
                        ph <= PH_W1;
                    end
                end else begin
                    fresh <= 1'b0;
                    rem <= rem_now;
                    rem_is0 <= is0_now;
                end
                // the edge's running state, loaded whatever edge_done says
                // (after an edge's last plot the next is fresh: unused)
                cur_x <= x_next; cur_e <= e_next; cur_qs <= S_qs; cur_rs <= S_rs; cur_drs <= S_drs;
                cur_dir <= S_dir; cur_r1 <= S_r1; cur_h <= S_h; cur_s <= s_now + 1'b1;
            end

            if (w1) begin
                n_old <= aet_cnt;
                fo_m1 <= {1'b0, aet_cnt} - 1'b1;
                fo_is0 <= (aet_cnt == {{RA{1'b0}}, 1'b1});
                fo_is1 <= (aet_cnt == {{(RA-1){1'b0}}, 2'd2});
                aet_cnt <= {(RA+1){1'b0}};
                nx_row <= nx_calc;
                nx_occ <= nx_occ_calc;
                ph <= shape_end ? PH_IDLE : PH_W2;
            end
            // one cycle more: SLB takes the row's last plot now (it left
            // the sequencer two cycles ago), so its plot_ready is still high
            if (ph == PH_W2)
                ph <= PH_W;
            if (ph == PH_RX)
                ph <= PH_P0;
        end
    end
endmodule
