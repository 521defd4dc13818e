// ef_div: the pipelined floor divider of SETUP (docs/microarch.md 3.2).
//
// q = floor(n / d), r = n - q*d (0 <= r < d) for a signed dividend n and a
// positive divisor d, one division accepted per enabled cycle, the result
// QB + 1 enabled cycles later: QB non-restoring stages, one quotient digit
// each, then one floor-correction stage.
//
// Non-restoring division with digits in {-1, +1}: the partial remainder p
// starts at n; stage i (i = QB-1 .. 0) subtracts d*2^i when p >= 0 (digit
// +1) and adds it when p < 0 (digit -1).  For |n| < d*2^QB every stage keeps
// |p| <= d*2^i, so after the last one n = Q*d + p with p in [-d, d) and
// Q = sum of digit_i * 2^i = 2*P - (2^QB - 1), P the word of the +1 digits.
// The floor correction makes the remainder non-negative: when p < 0,
// Q - 1 and p + d.  No stage ever compares magnitudes: only a sign.
//
// The caller guarantees |n| < d * 2^QB (SETUP: |A / dY| <= 2^23 + 1 and
// |h*dX / dY| < 2^29 with QB = 30); the quotient then fits QB + 1 bits
// signed.  d = 0 gives garbage (SETUP never uses the result then: a
// horizontal edge has no record).
//
// The side band (SBW bits) travels with the operands, so a caller keeps its
// other fields beside the division without counting cycles.  `en` low
// freezes every stage (the pipeline's back-pressure).
//
// Synthesizable Verilog-2005.
module ef_div #(
    parameter NW  = 50,    // dividend bits (signed)
    parameter DW  = 24,    // divisor bits (unsigned, d > 0)
    parameter QB  = 30,    // quotient stages
    parameter SBW = 1      // side-band bits
) (
    input  wire                 clk,
    input  wire                 rst,
    input  wire                 en,
    input  wire                 in_valid,
    input  wire signed [NW-1:0] in_n,
    input  wire        [DW-1:0] in_d,
    input  wire       [SBW-1:0] in_sb,
    output wire                 out_valid,
    output wire signed [QB:0]   out_q,     // floor(n / d)
    output wire        [DW-1:0] out_r,     // n mod d, 0 <= r < d
    output wire       [SBW-1:0] out_sb
);
    // Partial remainders reach |p| <= d * 2^QB: DW + QB + 1 bits signed,
    // and at least the dividend's width.
    localparam PW0 = DW + QB + 2;
    localparam PW  = PW0 > NW + 1 ? PW0 : NW + 1;

    // Correction stage.
    reg          cv;
    reg signed [QB:0] cq;
    reg [DW-1:0] cr;
    reg [SBW-1:0] csb;

    wire [PW-1:0] n_ext = {{(PW-NW){in_n[NW-1]}}, in_n};

    // Stage k (1..QB) computes digit i = QB - k: p -/+ d*2^i by the sign of
    // p.  Each stage's registers live in its generate block; stage k reads
    // stage k-1's (stage 1 the inputs).
    genvar k;
    generate
        for (k = 1; k <= QB; k = k + 1) begin : stage
            reg           v;
            reg [PW-1:0]  p;
            reg [DW-1:0]  d;
            reg [QB-1:0]  pd;     // the +1 digits so far (bit i: digit i)
            reg [SBW-1:0] sb;
            wire          vin;
            wire [PW-1:0] pin;
            wire [DW-1:0] din;
            wire [QB-1:0] pdin;
            wire [SBW-1:0] sbin;
            if (k == 1) begin : first
                assign vin = in_valid;
                assign pin = n_ext;
                assign din = in_d;
                assign pdin = {QB{1'b0}};
                assign sbin = in_sb;
            end else begin : next
                assign vin = stage[k-1].v;
                assign pin = stage[k-1].p;
                assign din = stage[k-1].d;
                assign pdin = stage[k-1].pd;
                assign sbin = stage[k-1].sb;
            end
            wire [PW-1:0] sh    = {{(PW-DW){1'b0}}, din} << (QB - k);
            wire          digit = !pin[PW-1];          // p >= 0: subtract, digit +1
            always @(posedge clk) begin
                if (rst)
                    v <= 1'b0;
                else if (en) begin
                    v  <= vin;
                    p  <= digit ? pin - sh : pin + sh;
                    d  <= din;
                    pd <= pdin | ({{(QB-1){1'b0}}, digit} << (QB - k));
                    sb <= sbin;
                end
            end
        end
    endgenerate

    // Q = 2P - (2^QB - 1), and the floor correction when the remainder is
    // negative: Q - 1, r + d.  Both are exact modulo 2^(QB+1) and 2^DW, where
    // the true results fit.
    wire          neg = stage[QB].p[PW-1];
    wire [QB:0]   q_nr = {stage[QB].pd, 1'b0} - {1'b0, {QB{1'b1}}};
`ifndef EF_FAULT_DIV_FLOOR
    wire [QB:0]   q_fl = q_nr - {{QB{1'b0}}, neg};
`else
    wire [QB:0]   q_fl = q_nr;      // fault injection: Q's floor correction skipped
`endif
    wire [DW-1:0] r_fl = stage[QB].p[DW-1:0] + (neg ? stage[QB].d : {DW{1'b0}});

    always @(posedge clk) begin
        if (rst)
            cv <= 1'b0;
        else if (en) begin
            cv  <= stage[QB].v;
            cq  <= q_fl;
            cr  <= r_fl;
            csb <= stage[QB].sb;
        end
    end

    assign out_valid = cv;
    assign out_q     = cq;
    assign out_r     = cr;
    assign out_sb    = csb;
endmodule
