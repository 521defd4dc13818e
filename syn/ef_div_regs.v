// ef_div_regs: a stand-in for ef_div (rtl/ef_div.v) for place and
// route only (make rtl-synth, docs/synthesis.md).  SETUP with its divider
// needs more logic cells than an iCE40 HX8K has, so rtl-synth places the
// divider alone and, to time SETUP's own logic (P1, P2 with its multiplier,
// and the et_wr outputs), SETUP with this module in the divider's place: the
// same ports, one register stage that keeps every input bit observable
// (folded by XOR into the outputs), no division.  Never simulated against
// the vectors: it computes nothing of the spec.
/* verilator lint_off DECLFILENAME */
module ef_div #(
    parameter NWA = 50,
    parameter NWB = 30,
    parameter DW  = 24,
    parameter QB  = 30,
    parameter SBW = 1
) (
    input  wire                  clk,
    input  wire                  rst,
    input  wire                  en,
    input  wire                  in_valid,
    input  wire signed [NWA-1:0] in_na,
    input  wire signed [NWB-1:0] in_nb,
    input  wire        [DW-1:0]  in_d,
    input  wire       [SBW-1:0]  in_sb,
    output reg                   out_valid,
    output reg  signed [QB:0]    out_qa,
    output reg         [DW-1:0]  out_ra,
    output reg  signed [QB:0]    out_qb,
    output reg         [DW-1:0]  out_rb,
    output reg         [DW-1:0]  out_d,
    output reg        [SBW-1:0]  out_sb
);
    // every dividend bit reaches an output: na folded over QB + 1 bits
    wire [2*(QB+1)-1:0] na_x = {{(2*(QB+1)-NWA){1'b0}}, in_na};
    wire [QB:0]         nb_x = {{(QB+1-NWB){1'b0}}, in_nb};
    always @(posedge clk) begin
        if (rst)
            out_valid <= 1'b0;
        else if (en) begin
            out_valid <= in_valid;
            out_qa <= na_x[QB:0] ^ na_x[2*(QB+1)-1:QB+1];
            out_qb <= nb_x;
            out_ra <= in_d ^ in_nb[DW-1:0];
            out_rb <= in_d;
            out_d  <= in_d;
            out_sb <= in_sb;
        end
    end
endmodule
