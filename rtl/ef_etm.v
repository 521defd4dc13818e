// ef_etm: edge-table memory (ETM) of the edgeflag reference
// microarchitecture (docs/microarch.md 3.3, 3.5 and section 4 item 4; the
// edge table is docs/spec.md section 6).
// Interfaces:  et_wr (SETUP -> ETM) in,  et_rd (ETM -> AET) out,
//              plus a row-request port and a record read port for the
//              AET and sequencer.
//
// Memories (ef_slb_ram: one write port, one synchronous read port):
//   rec  [E_MAX]: the record of edge eid (r0 r1 x e qs rs dy dir), written
//                 at its et_wr transfer, eid = the number of the et_wr in
//                 the shape (0 = the first);
//   nxt  [E_MAX]: the slot list's link from eid to the next edge written
//                 into the same slot;
//   slot [H_MAX]: one list per pixel row {valid, head, tail}.  Head AND
//                 tail: the AET takes a slot's edges in the order they were
//                 written (microarch 3.3), so a new edge is appended.
//
// Write path (one et_wr per cycle): in the transfer cycle t the record is
// written and the slot's entry read; in t+1 the entry (forwarded from the
// latest slot write when it is the same slot: the read at t's edge missed
// a write made at that edge) gets the new tail, and nxt[old tail] the new
// eid.  The shape's row range row_first..row_last (the first row holding
// an edge, the last row any edge reaches) and shape_any are valid from the
// eos et_wr's cycle (T0 - 1) until the next shape's first record; shape_go
// pulses in the cycle after the eos (T0); the edge counter restarts for the
// next shape.  (ef_raster uses none of these: its AET finds rows by its own
// occupancy map.  dv/tb/tb_etm.v checks them.)
//
// Row requests: row_req in cycle u (with row_req_row = j) reads slot j;
// from u+1 the list is presented on et_rd, one edge per cycle while
// et_rd_ready, et_rd_last marking its last edge (an empty slot presents
// nothing).  The slot is cleared in u+1 (a slot head is cleared when
// its row is taken, microarch 2), so the table is clean for the next shape.
// The AET issues row_req for row j in the cycle before j's first cycle (for
// the first row: the eos et_wr's cycle, T0 - 1, with row_first, which is
// valid then; the forwarding covers the last record's slot write landing
// at that edge).  A request while a list is presented is ignored
// (row_req_ready low); et_wr is not taken while one is (et_wr_ready low):
// in the reference schedule neither happens.
//
// Record read port: rec_re/rec_ra in cycle t, the record on rec_* in t+1
// (held while rec_re is low): the AET reads the record of an et_rd's eid in
// its transfer cycle.
//
// Reset: rst starts a sweep clearing the H_MAX slot entries, one per cycle
// (microarch 2); init_done rises when it is over.  A shape of more than
// E_MAX edges sets the sticky err_full (the records beyond are dropped).
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_etm #(
    parameter NS    = 8,        // samples per pixel: 8, 16 or 32
    parameter H_MAX = 16384,    // slots (pixel rows)
    parameter E_MAX = 4096      // edge records per shape
) (
    input  wire        clk,
    input  wire        rst,
    output reg         init_done,

    // et_wr: eos[0] slot[13:0] r0[18:0] r1[18:0] x[24:0] e[23:0] qs[29:0]
    //        rs[23:0] dy[23:0] dir[0]
    input  wire        et_wr_valid,
    output wire        et_wr_ready,
    input  wire        et_wr_eos,
    input  wire [`EF_ET_WR_SLOT_W-1:0] et_wr_slot,
    input  wire [`EF_ET_WR_R0_W-1:0] et_wr_r0,
    input  wire [`EF_ET_WR_R1_W-1:0] et_wr_r1,
    input  wire [`EF_ET_WR_X_W-1:0] et_wr_x,
    input  wire [`EF_ET_WR_E_W-1:0] et_wr_e,
    input  wire [`EF_ET_WR_QS_W-1:0] et_wr_qs,
    input  wire [`EF_ET_WR_RS_W-1:0] et_wr_rs,
    input  wire [`EF_ET_WR_DY_W-1:0] et_wr_dy,
    input  wire        et_wr_dir,

    // the shape closed by eos
    output reg         shape_go,      // pulse in the cycle after the eos et_wr (T0)
    output reg         shape_any,     // the shape has a record (from the eos cycle on)
    output reg  [`EF_ET_WR_SLOT_W-1:0] row_first,     // its first and last rows (valid with shape_any)
    output reg  [`EF_ET_WR_SLOT_W-1:0] row_last,
    output reg         err_full,      // sticky: more than E_MAX records in a shape

    // row requests
    input  wire        row_req,
    output wire        row_req_ready,
    input  wire [`EF_ET_RD_ROW_W-1:0] row_req_row,

    // et_rd: row[13:0] eid[21:0]
    output wire        et_rd_valid,
    input  wire        et_rd_ready,
    output wire [`EF_ET_RD_ROW_W-1:0] et_rd_row,
    output wire [`EF_ET_RD_EID_W-1:0] et_rd_eid,
    output wire        et_rd_last,    // the slot's last edge

    // record read port
    input  wire        rec_re,
    input  wire [`EF_ET_RD_EID_W-1:0] rec_ra,
    output wire [`EF_ET_WR_R0_W-1:0] rec_r0,
    output wire [`EF_ET_WR_R1_W-1:0] rec_r1,
    output wire [`EF_ET_WR_X_W-1:0] rec_x,
    output wire [`EF_ET_WR_E_W-1:0] rec_e,
    output wire [`EF_ET_WR_QS_W-1:0] rec_qs,
    output wire [`EF_ET_WR_RS_W-1:0] rec_rs,
    output wire [`EF_ET_WR_DY_W-1:0] rec_dy,
    output wire        rec_dir
);
    `include "ef_ns.vh"
    localparam EW = E_MAX > 1 ? $clog2(E_MAX) : 1;     // eid bits
    localparam HW = H_MAX > 1 ? $clog2(H_MAX) : 1;     // slot address bits
    localparam SW = 1 + 2 * EW;                        // slot entry {valid, head, tail}
    localparam RW = `EF_ET_WR_R0_W + `EF_ET_WR_R1_W + `EF_ET_WR_X_W + `EF_ET_WR_E_W + `EF_ET_WR_QS_W
                  + `EF_ET_WR_RS_W + `EF_ET_WR_DY_W + `EF_ET_WR_DIR_W;    // a record
    localparam [31:0] EMAX32 = E_MAX;
    localparam [22:0] EMAX23 = EMAX32[22:0];   // E_MAX <= 2^22

    // ------------------------------------------------------------ memories
    wire          s_we, s_re;
    wire [HW-1:0] s_wa, s_ra;
    wire [SW-1:0] s_wd, s_rd;
    ef_slb_ram #(.AW(HW), .DW(SW), .DEPTH(H_MAX)) u_slot (
        .clk(clk), .we(s_we), .wa(s_wa), .wd(s_wd), .re(s_re), .ra(s_ra), .rd(s_rd));

    wire          n_we, n_re;
    wire [EW-1:0] n_wa, n_ra;
    wire [EW-1:0] n_wd, n_rd;
    ef_slb_ram #(.AW(EW), .DW(EW), .DEPTH(E_MAX)) u_nxt (
        .clk(clk), .we(n_we), .wa(n_wa), .wd(n_wd), .re(n_re), .ra(n_ra), .rd(n_rd));

    wire          r_we;
    wire [EW-1:0] r_wa;
    wire [RW-1:0] r_wd, r_rd;
    ef_slb_ram #(.AW(EW), .DW(RW), .DEPTH(E_MAX)) u_rec (
        .clk(clk), .we(r_we), .wa(r_wa), .wd(r_wd), .re(rec_re), .ra(rec_ra[EW-1:0]), .rd(r_rd));

    wire [`EF_ET_RD_EID_W-1:0] unused_ra = rec_ra;   // bits above EW are 0 for a valid eid
    assign {rec_r0, rec_r1, rec_x, rec_e, rec_qs, rec_rs, rec_dy, rec_dir} = r_rd;

    // ------------------------------------------------------------- state
    reg [HW-1:0]  sweep;
    reg [22:0]    wcnt;            // records of the shape so far
    reg           fresh;           // the next record starts a shape

    reg           w2_v;            // write stage 2: link the record into its slot
    reg [HW-1:0]  w2_slot;
    reg [EW-1:0]  w2_eid;

    reg           lw_v;            // the latest slot write, for forwarding
    reg [HW-1:0]  lw_addr;
    reg [SW-1:0]  lw_data;

    localparam [1:0] R_IDLE = 2'd0, R_HEAD = 2'd1, R_HELD = 2'd2, R_CHAIN = 2'd3;
    reg [1:0]     rs;              // list presentation state
    reg [`EF_ET_RD_ROW_W-1:0] rq_row;
    reg [EW-1:0]  hd_head, hd_tail;

    // ------------------------------------------------------------ write path
    wire busy_rd = (rs != R_IDLE);
    assign et_wr_ready = init_done && !busy_rd;
    wire take   = et_wr_valid && et_wr_ready;
    wire take_e = take && !et_wr_eos && (wcnt < EMAX23);

    assign r_we = take_e;
    assign r_wa = wcnt[EW-1:0];
    assign r_wd = {et_wr_r0, et_wr_r1, et_wr_x, et_wr_e, et_wr_qs, et_wr_rs, et_wr_dy, et_wr_dir};

    // The slot entry as it is now (stage 2 of a write, or the head fetch).
    wire [HW-1:0] s2_addr = w2_v ? w2_slot : rq_row[HW-1:0];
    wire [SW-1:0] cur = (lw_v && lw_addr == s2_addr) ? lw_data : s_rd;
    wire          cur_v    = cur[SW-1];
    wire [EW-1:0] cur_head = cur[2*EW-1:EW];
    wire [EW-1:0] cur_tail = cur[EW-1:0];

    // Stage 2 of a write: append w2_eid to its slot.
    wire [SW-1:0] w2_entry = cur_v ? {1'b1, cur_head, w2_eid} : {1'b1, w2_eid, w2_eid};
    assign n_we = w2_v && cur_v;
    assign n_wa = cur_tail;
    assign n_wd = w2_eid;

    // ------------------------------------------------------------ row reads
    assign row_req_ready = init_done && !busy_rd && !take_e;   // one slot read per cycle
    wire req = row_req && row_req_ready;
    wire head_cycle = (rs == R_HEAD);

    assign et_rd_valid = (head_cycle && cur_v) || (rs == R_HELD) || (rs == R_CHAIN);
    wire [EW-1:0] eid  = head_cycle ? cur_head : (rs == R_HELD) ? hd_head : n_rd;
    wire [EW-1:0] tail = head_cycle ? cur_tail : hd_tail;
    assign et_rd_eid  = {{(`EF_ET_RD_EID_W-EW){1'b0}}, eid};
    assign et_rd_row  = rq_row;
    assign et_rd_last = (eid == tail);
    wire rd_take = et_rd_valid && et_rd_ready;

    assign n_re = rd_take;       // nxt[eid] for the next cycle
    assign n_ra = eid;

    // Slot RAM ports: sweep, write stage 2, or the clear of a taken slot;
    // the read is the write path's (slot of the et_wr) or a request's.
    assign s_we = !init_done || w2_v || (head_cycle && cur_v);
    assign s_wa = !init_done ? sweep : w2_v ? w2_slot : rq_row[HW-1:0];
    assign s_wd = (!init_done || !w2_v) ? {SW{1'b0}} : w2_entry;
    assign s_re = take_e || req;
    assign s_ra = take_e ? et_wr_slot[HW-1:0] : row_req_row[HW-1:0];

    wire [`EF_ET_WR_R1_W-1:0] last_row_w = et_wr_r1 >> LOG2NS;
    wire [`EF_ET_WR_R1_W-`EF_ET_WR_SLOT_W-1:0] unused_lr = last_row_w[`EF_ET_WR_R1_W-1:`EF_ET_WR_SLOT_W];

    always @(posedge clk) begin
        if (rst) begin
            init_done <= 1'b0;
            sweep     <= {HW{1'b0}};
            wcnt      <= 23'd0;
            fresh     <= 1'b1;
            w2_v      <= 1'b0;
            lw_v      <= 1'b0;
            rs        <= R_IDLE;
            shape_go  <= 1'b0;
            shape_any <= 1'b0;
            err_full  <= 1'b0;
        end else begin
            if (!init_done) begin
                sweep <= sweep + 1'b1;
                if ({{(32-HW){1'b0}}, sweep} == H_MAX - 1)
                    init_done <= 1'b1;
            end
            if (s_we) begin
                lw_v    <= 1'b1;
                lw_addr <= s_wa;
                lw_data <= s_wd;
            end

            // write path
            w2_v <= take_e;
            // The shape's row range accumulates from its first record and
            // holds from the eos cycle until the next shape's first record,
            // so the AET can request row_first in the eos cycle (T0 - 1).
            if (take_e) begin
                w2_slot <= et_wr_slot[HW-1:0];
                w2_eid  <= wcnt[EW-1:0];
                wcnt    <= wcnt + 23'd1;
                fresh   <= 1'b0;
                shape_any <= 1'b1;
                if (fresh || et_wr_slot < row_first)
                    row_first <= et_wr_slot;
                if (fresh || last_row_w[`EF_ET_WR_SLOT_W-1:0] > row_last)
                    row_last <= last_row_w[`EF_ET_WR_SLOT_W-1:0];
            end
            if (take && !et_wr_eos && !(wcnt < EMAX23))
                err_full <= 1'b1;
            shape_go <= take && et_wr_eos;
            if (take && et_wr_eos) begin
                wcnt      <= 23'd0;
                if (fresh)
                    shape_any <= 1'b0;   // a shape without records
                fresh     <= 1'b1;
            end

            // row reads
            case (rs)
                R_IDLE:
                    if (req) begin
                        rs     <= R_HEAD;
                        rq_row <= row_req_row;
                    end
                R_HEAD: begin
                    hd_head <= cur_head;
                    hd_tail <= cur_tail;
                    if (!cur_v)
                        rs <= R_IDLE;
                    else if (rd_take)
                        rs <= et_rd_last ? R_IDLE : R_CHAIN;
                    else
                        rs <= R_HELD;
                end
                R_HELD:
                    if (rd_take)
                        rs <= et_rd_last ? R_IDLE : R_CHAIN;
                default:   // R_CHAIN
                    if (rd_take && et_rd_last)
                        rs <= R_IDLE;
            endcase
        end
    end
endmodule
