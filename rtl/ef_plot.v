// ef_plot: PLOT of the edgeflag reference microarchitecture
// (docs/microarch.md 3.3, docs/spec.md 6.1): for one active edge at one
// sample row, the cell it marks and the edge's DDA state for the next
// sample row.  Purely combinational; the sequencer (ef_aet) owns the state
// registers and issues one plot per cycle.
//
//   q  = clamp(asr(x + off[s], 8), 0, W)          offset add, shift, clamp
//   e' = e + rs;  x' = x + qs;
//   if (e' >= dy) { e' -= dy; x' += 1 }            exact DDA step
//
// off[s] = 256 - h*k[s] - c (h = 256/NS, c = h/2) with k the n-rooks table
// of docs/patterns.md (model/pattern_tables.c holds the same numbers); it
// lies in 1..255, so it is an 8-bit constant per sample row.
//
// Widths: x is the et_wr field x[24:0] (Q16.8, signed), kept at 32 bits here
// so that the step past an edge's last sample row (whose result is thrown
// away) cannot wrap into a value that matters; qs is 30 bits signed; e, rs,
// dy are below 2^24 and e + rs < 2^25.
//
// Fault defines (tests/rtl/rtl-test.sh): EF_FAULT_ROOKS puts a wrong
// offset in one n-rooks entry (sample row 1 uses row 2's).
//
// Synthesizable Verilog-2005.
module ef_plot #(
    parameter NS = 8
) (
    input  wire [4:0]         s,       // sample row within the pixel row
    input  wire signed [31:0] x,       // Q16.8
    input  wire [23:0]        e,
    input  wire signed [29:0] qs,
    input  wire [23:0]        rs,
    input  wire [23:0]        dy,
    input  wire [14:0]        width,   // W: q is clamped to [0, W]
    output wire [14:0]        q,
    output wire signed [31:0] x_next,
    output wire [23:0]        e_next
);
    localparam integer HI = 256 / NS;
    localparam [8:0] H = HI[8:0];        // h: sub-pixel height and width
    localparam [8:0] C = H / 2;          // c
    // ------------------------------------------------ n-rooks offsets
    // k tables: docs/patterns.md (8: the paper's table).
    function [7:0] off_of;
        input [4:0] si;
        reg [4:0] k;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [8:0] t;                     // 256 - h*k - c < 256
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            k = 5'd0;
            if (NS == 8) begin
                case (si[2:0])
                    3'd0: k = 5'd2;  3'd1: k = 5'd7;  3'd2: k = 5'd4;  3'd3: k = 5'd1;
                    3'd4: k = 5'd6;  3'd5: k = 5'd3;  3'd6: k = 5'd0;  default: k = 5'd5;
                endcase
            end else if (NS == 16) begin
                case (si[3:0])
                    4'd0: k = 5'd3;   4'd1: k = 5'd11;  4'd2: k = 5'd7;   4'd3: k = 5'd15;
                    4'd4: k = 5'd1;   4'd5: k = 5'd9;   4'd6: k = 5'd5;   4'd7: k = 5'd13;
                    4'd8: k = 5'd2;   4'd9: k = 5'd10;  4'd10: k = 5'd6;  4'd11: k = 5'd14;
                    4'd12: k = 5'd0;  4'd13: k = 5'd8;  4'd14: k = 5'd4;  default: k = 5'd12;
                endcase
            end else begin
                case (si)
                    5'd0: k = 5'd6;    5'd1: k = 5'd27;   5'd2: k = 5'd17;   5'd3: k = 5'd11;
                    5'd4: k = 5'd22;   5'd5: k = 5'd3;    5'd6: k = 5'd31;   5'd7: k = 5'd15;
                    5'd8: k = 5'd8;    5'd9: k = 5'd25;   5'd10: k = 5'd0;   5'd11: k = 5'd20;
                    5'd12: k = 5'd13;  5'd13: k = 5'd29;  5'd14: k = 5'd5;   5'd15: k = 5'd18;
                    5'd16: k = 5'd10;  5'd17: k = 5'd23;  5'd18: k = 5'd1;   5'd19: k = 5'd28;
                    5'd20: k = 5'd16;  5'd21: k = 5'd7;   5'd22: k = 5'd24;  5'd23: k = 5'd12;
                    5'd24: k = 5'd19;  5'd25: k = 5'd2;   5'd26: k = 5'd30;  5'd27: k = 5'd9;
                    5'd28: k = 5'd21;  5'd29: k = 5'd14;  5'd30: k = 5'd26;  default: k = 5'd4;
                endcase
            end
            // 256 - h*k - h/2 with h = 256/NS: at most 255, at least h/2 >= 4.
            t = 9'd256 - {4'd0, k} * H - C;
            off_of = t[7:0];
        end
    endfunction

`ifdef EF_FAULT_ROOKS
    wire [4:0] s_tab = (s == 5'd1) ? 5'd2 : s;
`else
    wire [4:0] s_tab = s;
`endif
    wire [7:0] off = off_of(s_tab);

    // ------------------------------------------------ q
    /* verilator lint_off UNUSEDSIGNAL */
    wire signed [31:0] xo = x + $signed({24'd0, off});   // xo[7:0]: the fraction, shifted out
    /* verilator lint_on UNUSEDSIGNAL */
    wire signed [23:0] qi = xo[31:8];                   // arithmetic shift by 8
    assign q = qi[23] ? 15'd0
             : (qi > $signed({9'd0, width})) ? width
             : qi[14:0];

    // ------------------------------------------------ exact DDA step
    wire [24:0] es = {1'b0, e} + {1'b0, rs};
    wire        carry = es >= {1'b0, dy};
    /* verilator lint_off UNUSEDSIGNAL */
    wire [24:0] ed = es - {1'b0, dy};                   // < dy when used: 24 bits
    /* verilator lint_on UNUSEDSIGNAL */
    assign e_next = carry ? ed[23:0] : es[23:0];
    assign x_next = x + {{2{qs[29]}}, qs} + {31'd0, carry};
endmodule
