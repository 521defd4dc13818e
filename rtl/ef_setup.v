// ef_setup: edge setup (SETUP) of the edgeflag reference microarchitecture
// (docs/microarch.md 3.2 and section 4 item 3; the arithmetic is
// docs/spec.md section 5).
// Interfaces:  seg (DEC -> SETUP) in,  et_wr (SETUP -> ETM) out.
//
// One edge per cycle, its record L_SETUP = 33 cycles after the seg transfer:
//   P1 (the seg's cycle, registered at its transfer): orientation, dY, dX,
//      first and last sample rows r0 = ceil((Y0 - c) / h) and
//      r1 = ceil((Y1 - c) / h) - 1 as arithmetic shifts (h = 2^(8 - LOG2NS)),
//      the top and bottom clip;
//   P2: the drop decision (horizontal, or r0 > r1 after clipping), the dividends M = (Y_r0 - Y0)*dX - 1 (|M| < 2^48; the spec's
//      A = X0*dY + M, and X0 is added to M's quotient after the divider)
//      and h*dX (a shift, |h*dX| < 2^29);
//   30 non-restoring stages and the floor correction (ef_div, two lanes
//      over one divisor pipeline: x, e = floor divmod(A, dY) and qs, rs =
//      floor divmod(h*dX, dY) in the same cycles; the record's other fields
//      ride in the divider's block-RAM side-band ring).
// A dropped edge travels down the pipeline as a bubble (no et_wr); the
// end-of-shape token (seg eos) leaves as the eos et_wr, every other field 0.
//
// Back-pressure: the whole pipeline advances when et_wr is taken or empty
// (en); seg_ready = en.  The reference ETM is always ready, so this never
// stalls there.
//
// cfg_height (FRAME's height, 1..H_MAX) gives the bottom clip N*H - 1.
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_setup #(
    parameter NS    = 8         // samples per pixel: 8, 16 or 32
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [14:0] cfg_height,

    // seg: eos[0] xa[23:0] ya[23:0] xb[23:0] yb[23:0]
    input  wire        seg_valid,
    output wire        seg_ready,
    input  wire        seg_eos,
    input  wire [`EF_SEG_XA_W-1:0] seg_xa,
    input  wire [`EF_SEG_YA_W-1:0] seg_ya,
    input  wire [`EF_SEG_XB_W-1:0] seg_xb,
    input  wire [`EF_SEG_YB_W-1:0] seg_yb,

    // et_wr: eos[0] slot[13:0] r0[18:0] r1[18:0] x[24:0] e[23:0] qs[29:0]
    //        rs[23:0] dy[23:0] dir[0]
    output wire        et_wr_valid,
    input  wire        et_wr_ready,
    output wire        et_wr_eos,
    output wire [`EF_ET_WR_SLOT_W-1:0] et_wr_slot,
    output wire [`EF_ET_WR_R0_W-1:0] et_wr_r0,
    output wire [`EF_ET_WR_R1_W-1:0] et_wr_r1,
    output wire [`EF_ET_WR_X_W-1:0] et_wr_x,
    output wire [`EF_ET_WR_E_W-1:0] et_wr_e,
    output wire [`EF_ET_WR_QS_W-1:0] et_wr_qs,
    output wire [`EF_ET_WR_RS_W-1:0] et_wr_rs,
    output wire [`EF_ET_WR_DY_W-1:0] et_wr_dy,
    output wire        et_wr_dir
);
    `include "ef_ns.vh"
    localparam SH     = 8 - LOG2NS;           // h = 2^SH
    localparam H      = 1 << SH;
    localparam C      = H / 2;

    wire div_out_valid;
    wire en = et_wr_ready || !et_wr_valid;
    assign seg_ready = en && !rst;
    wire take = seg_valid && seg_ready;

    // ------------------------------------------------------------- P1
    wire signed [23:0] xa = seg_xa, ya = seg_ya, xb = seg_xb, yb = seg_yb;
    wire               down = ya < yb;                 // dir +1
    wire signed [23:0] x0 = down ? xa : xb, y0 = down ? ya : yb;
    wire signed [23:0] x1 = down ? xb : xa, y1 = down ? yb : ya;
    wire signed [25:0] dy_w = {{2{y1[23]}}, y1} - {{2{y0[23]}}, y0};   // 1 .. 2^24 - 1 unless horizontal
    wire signed [25:0] dx_w = {{2{x1[23]}}, x1} - {{2{x0[23]}}, x0};   // |dX| < 2^24
    // ceil((Y0 - c) / h) = floor((Y0 - c + h - 1) / h); floor((Y1 - c - 1) / h)
    wire signed [25:0] r0_num = {{2{y0[23]}}, y0} - C + H - 1;
    wire signed [25:0] r1_num = {{2{y1[23]}}, y1} - C - 1;
    wire signed [25:0] r0_raw = r0_num >>> SH;
    wire signed [25:0] r1_raw = r1_num >>> SH;
    wire signed [25:0] last_row = $signed({6'd0, cfg_height, 5'd0} >> (5 - LOG2NS)) - 26'sd1;  // N*H - 1
    wire signed [25:0] r0_c = r0_raw[25] ? 26'sd0 : r0_raw;
    wire signed [25:0] r1_c = (r1_raw > last_row) ? last_row : r1_raw;
    wire [1:0]         unused_dy = dy_w[25:24];
    // The drop decision (r0 > r1 after the clip) is made in P2 from the
    // registered rows (issue 25: off P1's path; it is used only at the
    // divider's end).

    reg        p1_v, p1_eos, p1_flat, p1_dir;
    reg signed [25:0] p1_r0c, p1_r1c;
    reg signed [23:0] p1_x0, p1_y0;
    reg signed [25:0] p1_dx;
    reg [23:0] p1_dy;
    reg [`EF_ET_WR_R0_W-1:0] p1_r0;
    reg [`EF_ET_WR_R1_W-1:0] p1_r1;

    always @(posedge clk) begin
        if (rst)
            p1_v <= 1'b0;
        else if (en) begin
            p1_v    <= take;
            p1_eos  <= seg_eos;
            p1_flat <= (ya == yb) || seg_eos;
            p1_r0c  <= r0_c;
            p1_r1c  <= r1_c;
            p1_dir  <= !down;
            p1_x0   <= x0;
            p1_y0   <= y0;
            p1_dx   <= dx_w;
            p1_dy   <= dy_w[23:0];
            p1_r0   <= r0_c[`EF_ET_WR_R0_W-1:0];
            p1_r1   <= r1_c[`EF_ET_WR_R1_W-1:0];
        end
    end

    // ------------------------------------------------------------- P2
    // t = Y_r0 - Y0 = h*r0 + c - Y0.  The spec's dividend is
    // A = X0*dY + t*dX - 1; X0*dY is a multiple of dY, so floor(A / dY) =
    // X0 + floor(M / dY) and A mod dY = M mod dY with M = t*dX - 1: the
    // divider takes M and X0 is added to its quotient at the end (one
    // multiplier instead of two).  For an edge that is kept, sample row r0
    // lies in [Y0, Y1): 0 <= t < dY < 2^24, so t*dX takes t's low 24 bits
    // unsigned and |M| < 2^48; a dropped edge's t may be anything (the top
    // clip moves r0 far below Y0), but its division is never used.
    wire signed [27:0] t_w  = $signed({9'd0, p1_r0} << SH) + C - {{4{p1_y0[23]}}, p1_y0};
    wire [3:0]  unused_t = t_w[27:24];
    wire signed [49:0] m_w  = $signed({1'b0, t_w[23:0]}) * $signed(p1_dx[24:0]);
    wire signed [49:0] a_w  = m_w - 50'sd1;
    wire        unused_dx = p1_dx[25];
    wire signed [29:0] hdx  = $signed({{5{p1_dx[24]}}, p1_dx[24:0]} << SH);   // |h*dX| < 2^29

    wire        p1_keep = !p1_flat && !(p1_r0c > p1_r1c);
    wire [`EF_ET_WR_R0_W-1:0] slot_w = p1_r0 >> LOG2NS;    // the pixel row of r0
    wire [`EF_ET_WR_R0_W-`EF_ET_WR_SLOT_W-1:0] unused_slot = slot_w[`EF_ET_WR_R0_W-1:`EF_ET_WR_SLOT_W];

    // The side band beside the divisions: {eos, keep, dir, slot, r0, r1, X0}
    // (dY travels as the divisor), its fields' positions from the et_wr and
    // seg widths.
    localparam SB_R1   = `EF_SEG_XA_W;
    localparam SB_R0   = SB_R1 + `EF_ET_WR_R1_W;
    localparam SB_SLOT = SB_R0 + `EF_ET_WR_R0_W;
    localparam SB_DIR  = SB_SLOT + `EF_ET_WR_SLOT_W;
    localparam SB_KEEP = SB_DIR + 1;
    localparam SB_EOS  = SB_KEEP + 1;
    localparam SBW     = SB_EOS + 1;

    reg        p2_v;
    reg signed [49:0] p2_a;
    reg signed [29:0] p2_b;
    reg [23:0] p2_dy;
    reg [SBW-1:0] p2_sb;

    always @(posedge clk) begin
        if (rst)
            p2_v <= 1'b0;
        else if (en) begin
            p2_v  <= p1_v;
            p2_a  <= a_w;
            p2_b  <= hdx;
            p2_dy <= p1_dy;
            p2_sb <= {p1_eos, p1_keep, p1_dir, slot_w[`EF_ET_WR_SLOT_W-1:0], p1_r0, p1_r1, p1_x0};
        end
    end

    // ------------------------------------------------------- divider
    // Both divisions of an edge by dY in one two-lane divider (one divisor
    // pipeline); the side band in its block-RAM ring.
    wire signed [30:0] qa, qb;
    wire [23:0] ra, rb, dy_o;
    wire [SBW-1:0] sb;
    wire [5:0]  unused_qa = qa[30:25];
    wire        unused_qb = qb[30];

    ef_div #(.NWA(50), .NWB(30), .DW(24), .QB(30), .SBW(SBW)) u_div (
        .clk(clk), .rst(rst), .en(en), .in_valid(p2_v), .in_na(p2_a), .in_nb(p2_b), .in_d(p2_dy),
        .in_sb(p2_sb),
        .out_valid(div_out_valid), .out_qa(qa), .out_ra(ra), .out_qb(qb), .out_rb(rb), .out_d(dy_o),
        .out_sb(sb)
    );

    // ------------------------------------------------------- et_wr
    wire o_eos = sb[SB_EOS];
    wire o_keep = sb[SB_KEEP];
    // x = X0 + floor(M / dY), exact modulo 2^25 where x fits (|x| <= 2^23 + 1)
    wire [`EF_ET_WR_X_W-1:0] x_w = {sb[23], sb[23:0]} + qa[24:0];
    assign et_wr_valid = div_out_valid && (o_eos || o_keep);
    assign et_wr_eos   = o_eos;
    assign et_wr_dir   = !o_eos && sb[SB_DIR];
    assign et_wr_slot  = o_eos ? {`EF_ET_WR_SLOT_W{1'b0}} : sb[SB_SLOT +: `EF_ET_WR_SLOT_W];
    assign et_wr_r0    = o_eos ? {`EF_ET_WR_R0_W{1'b0}} : sb[SB_R0 +: `EF_ET_WR_R0_W];
    assign et_wr_r1    = o_eos ? {`EF_ET_WR_R1_W{1'b0}} : sb[SB_R1 +: `EF_ET_WR_R1_W];
    assign et_wr_dy    = o_eos ? {`EF_ET_WR_DY_W{1'b0}} : dy_o;
    assign et_wr_x     = o_eos ? {`EF_ET_WR_X_W{1'b0}} : x_w;
    assign et_wr_e     = o_eos ? {`EF_ET_WR_E_W{1'b0}} : ra;
    assign et_wr_qs    = o_eos ? {`EF_ET_WR_QS_W{1'b0}} : qb[`EF_ET_WR_QS_W-1:0];
    assign et_wr_rs    = o_eos ? {`EF_ET_WR_RS_W{1'b0}} : rb;
endmodule
