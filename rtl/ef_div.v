// ef_div: the pipelined floor divider of SETUP (docs/microarch.md 3.2).
//
// Two lanes over one divisor: qa = floor(na / d), ra = na - qa*d and
// qb = floor(nb / d), rb = nb - qb*d (0 <= r < d) for signed dividends and a
// positive divisor d, one pair accepted per enabled cycle, the results
// QB + 1 enabled cycles later: QB non-restoring stages, one quotient digit
// per lane each, then one floor-correction stage.  SETUP divides both A and
// h*dX by dY, so the divisor pipeline is shared (and delivered as out_d).
//
// Non-restoring division with digits in {-1, +1}: the partial remainder p
// starts at n; stage k (digit i = QB - k) subtracts d*2^i when p >= 0
// (digit +1) and adds it when p < 0 (digit -1).  For |n| < d*2^QB every
// stage keeps |p| <= d*2^i, so after the last one n = Q*d + p with p in
// [-d, d) and Q = sum of digit_i * 2^i = 2*P - (2^QB - 1), P the word of the
// +1 digits.  The floor correction makes the remainder non-negative: when
// p < 0, Q - 1 and p + d.  No stage ever compares magnitudes: only a sign.
//
// Width per stage (why this is small): d*2^i has i zero low bits, so the
// low i bits of p are the dividend's, untouched until their stage, and by
// the bound p >> i lies in [-d, d]: DW + 1 bits signed (`hi`).  Stage k adds
// or subtracts d to {hi, the next dividend bit} (a DW + 1 bit add: the
// result fits by the bound) and shifts its digit into the low end of `lo`,
// a QB-bit word that holds the dividend bits not yet consumed above the
// digits already decided (QB - k + k bits).  So each stage registers
// DW + 1 + QB bits per lane instead of a full-width remainder plus a digit
// word, and its adder is DW + 1 bits, not DW + QB + 2.
//
// The caller guarantees |n| < d * 2^QB (SETUP: |M / dY| <= |dX| < 2^24 and
// |h*dX / dY| < 2^29 with QB = 30); the quotient then fits QB + 1 bits
// signed.  d = 0 gives garbage (SETUP never uses the result then: a
// horizontal edge has no record).
//
// The side band (SBW bits) travels with the operands, so a caller keeps its
// other fields beside the division without counting cycles.  It travels in a
// block-RAM delay line (ef_slb_ram: a ring of SBD entries, SBD the power of
// two >= QB + 1, written at wp and read at wp - QB, both only when `en`, the
// read one cycle ahead for the RAM's registered output) instead of QB + 1
// register stages.  `en` low freezes every stage (the pipeline's
// back-pressure).
//
// Synthesizable Verilog-2005.
module ef_div #(
    parameter NWA    = 50,   // lane a dividend bits (signed)
    parameter NWB    = 30,   // lane b dividend bits (signed)
    parameter DW     = 24,   // divisor bits (unsigned, d > 0)
    parameter QB     = 30,   // quotient stages
    parameter SBW    = 1     // side-band bits
) (
    input  wire                  clk,
    input  wire                  rst,
    input  wire                  en,
    input  wire                  in_valid,
    input  wire signed [NWA-1:0] in_na,
    input  wire signed [NWB-1:0] in_nb,
    input  wire        [DW-1:0]  in_d,
    input  wire       [SBW-1:0]  in_sb,
    output wire                  out_valid,
    output wire signed [QB:0]    out_qa,    // floor(na / d)
    output wire        [DW-1:0]  out_ra,    // na mod d, 0 <= r < d
    output wire signed [QB:0]    out_qb,    // floor(nb / d)
    output wire        [DW-1:0]  out_rb,    // nb mod d
    output wire        [DW-1:0]  out_d,     // the divisor, beside its results
    output wire       [SBW-1:0]  out_sb
);
    localparam HW = DW + 1;                  // hi: p >> i, in [-d, d]
    // Dividends sign-extended to at least HW + QB bits; by the bound the
    // bits above HW + QB are copies of the sign.
    localparam XA = NWA > HW + QB ? NWA : HW + QB;
    localparam XB = NWB > HW + QB ? NWB : HW + QB;
    wire [XA-1:0] na_x = {{(XA-NWA){in_na[NWA-1]}}, in_na};
    wire [XB-1:0] nb_x = {{(XB-NWB){in_nb[NWB-1]}}, in_nb};
    wire [XA-HW-QB:0] unused_na = na_x[XA-1:HW+QB-1];   // sign copies
    wire [XB-HW-QB:0] unused_nb = nb_x[XB-1:HW+QB-1];

    // Stage k (1..QB) decides digit i = QB - k of both lanes.  Each stage's
    // registers live in its generate block; stage k reads stage k-1's
    // (stage 1 the inputs).
    genvar k;
    generate
        for (k = 1; k <= QB; k = k + 1) begin : stage
            reg           v;
            reg [DW-1:0]  d;
            reg [HW-1:0]  ha, hb;     // p >> i
            reg [QB-1:0]  la, lb;     // dividend bits i-1..0, then the k digits
            wire          vin;
            wire [DW-1:0] din;
            wire [HW-1:0] hain, hbin;
            wire [QB-1:0] lain, lbin;
            if (k == 1) begin : first
                assign vin  = in_valid;
                assign din  = in_d;
                assign hain = na_x[HW+QB-1:QB];
                assign hbin = nb_x[HW+QB-1:QB];
                assign lain = na_x[QB-1:0];
                assign lbin = nb_x[QB-1:0];
            end else begin : next
                assign vin  = stage[k-1].v;
                assign din  = stage[k-1].d;
                assign hain = stage[k-1].ha;
                assign hbin = stage[k-1].hb;
                assign lain = stage[k-1].la;
                assign lbin = stage[k-1].lb;
            end
            // p >= 0: subtract, digit +1; the operand is {hi, dividend bit i}
            wire          dga = !hain[HW-1];
            wire          dgb = !hbin[HW-1];
            wire [HW-1:0] ta  = {hain[HW-2:0], lain[QB-1]};
            wire [HW-1:0] tb  = {hbin[HW-2:0], lbin[QB-1]};
            wire [HW-1:0] de  = {1'b0, din};
            // one adder for both signs: t + (d ^ s) + s, the carry-in s as
            // an extra low bit (written as a ? t - d : t + d, Yosys builds
            // two adders and a multiplexer)
            /* verilator lint_off UNUSEDSIGNAL */
            wire [HW:0]   suma  = {ta, 1'b1} + {de ^ {HW{dga}}, dga};
            wire [HW:0]   sumb  = {tb, 1'b1} + {de ^ {HW{dgb}}, dgb};
            /* verilator lint_on UNUSEDSIGNAL */
            always @(posedge clk) begin
                if (rst)
                    v <= 1'b0;
                else if (en) begin
                    v  <= vin;
                    d  <= din;
                    ha <= suma[HW:1];
                    hb <= sumb[HW:1];
                    la <= {lain[QB-2:0], dga};
                    lb <= {lbin[QB-2:0], dgb};
                end
            end
        end
    endgenerate

    // Q = 2P - (2^QB - 1), and the floor correction when the remainder is
    // negative: Q - 1, r + d.  Both are exact modulo 2^(QB+1) and 2^DW, where
    // the true results fit.
    wire [DW-1:0] dq   = stage[QB].d;
    wire          nega = stage[QB].ha[HW-1];
    wire          negb = stage[QB].hb[HW-1];
    wire [QB:0]   qa_nr = {stage[QB].la, 1'b0} - {1'b0, {QB{1'b1}}};
    wire [QB:0]   qb_nr = {stage[QB].lb, 1'b0} - {1'b0, {QB{1'b1}}};
    wire [QB:0]   qa_fl = qa_nr - {{QB{1'b0}}, nega};
    wire [QB:0]   qb_fl = qb_nr - {{QB{1'b0}}, negb};
    wire [DW-1:0] ra_fl = stage[QB].ha[DW-1:0] + (nega ? dq : {DW{1'b0}});
    wire [DW-1:0] rb_fl = stage[QB].hb[DW-1:0] + (negb ? dq : {DW{1'b0}});

    // Correction stage.
    reg          cv;
    reg [QB:0]   cqa, cqb;
    reg [DW-1:0] cra, crb, cd;
    always @(posedge clk) begin
        if (rst)
            cv <= 1'b0;
        else if (en) begin
            cv  <= stage[QB].v;
            cqa <= qa_fl;
            cqb <= qb_fl;
            cra <= ra_fl;
            crb <= rb_fl;
            cd  <= dq;
        end
    end

    assign out_valid = cv;
    assign out_qa    = cqa;
    assign out_ra    = cra;
    assign out_qb    = cqb;
    assign out_rb    = crb;
    assign out_d     = cd;

    // ------------------------------------------------------- side band
    localparam SA  = QB + 1 <= 2 ? 1 : QB + 1 <= 4 ? 2 : QB + 1 <= 8 ? 3 :
                     QB + 1 <= 16 ? 4 : QB + 1 <= 32 ? 5 : QB + 1 <= 64 ? 6 : 7;
    localparam SBD = 1 << SA;
    localparam [SA-1:0] QOFF = QB;
    // An entry written at enabled edge n must be in the RAM's output register
    // after enabled edge n + QB (the correction register's cycle): read at
    // edge m the entry written at m - QB.
    reg  [SA-1:0] wp;
    wire [SA-1:0] rp = wp - QOFF;
    always @(posedge clk) begin
        if (rst)
            wp <= {SA{1'b0}};
        else if (en)
            wp <= wp + 1'b1;
    end
    ef_slb_ram #(.AW(SA), .DW(SBW), .DEPTH(SBD)) u_sb (
        .clk(clk), .we(en), .wa(wp), .wd(in_sb), .re(en), .ra(rp), .rd(out_sb)
    );
endmodule
