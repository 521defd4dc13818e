// ef_spanq: COV's span queue of the overlap schedule (docs/microarch.md
// section 6): DEPTH spans between FILL's `span` output and COV, so the scan
// runs ahead of COV's one pixel per cycle.
//
// The `span` interface of the vectors is the queue's input (in_valid &&
// in_ready).  Span k enters at a_k and COV starts it at b_k (out_valid &&
// out_ready):
//  * in_ready = not full, a register (issue 25: no path from COV's ready
//    through the queue into FILL's stall): span k enters in the cycle
//    after span k-DEPTH has left, a_k >= b_(k-DEPTH) + 1 (a head leaving
//    in cycle c frees its entry from cycle c+1 on);
//  * an empty queue is bypassed: a span offered while COV is ready goes to
//    COV in the same cycle (b_k = a_k), so with COV free the queue adds no
//    cycle; else COV takes the head when it is ready (b_k = max(a_k,
//    cov_free)).
// Storage: DEPTH words of 75 bits (distributed RAM or flip-flops) with a
// read and a write pointer and a count, and a copy of the head in
// flip-flops, so what COV reads is a register or FILL's span (the bypass):
// the RAM's read is on the way into the head register, not into COV's
// coverage arithmetic.  `empty` and `full` are registers (the drain
// condition reads `empty`).
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_spanq #(
    parameter DEPTH = `EF_SPANQ
) (
    input  wire        clk,
    input  wire        rst,

    input  wire        in_valid,
    output wire        in_ready,
    input  wire [`EF_SPAN_W-1:0] in_data,

    output wire        out_valid,
    input  wire        out_ready,
    output wire [`EF_SPAN_W-1:0] out_data,

    output reg         empty
);
    localparam PW = (DEPTH > 1) ? $clog2(DEPTH) : 1;
    localparam integer  LASTI = DEPTH - 1;
    localparam [PW-1:0] LAST = LASTI[PW-1:0];
    localparam [PW:0]   FULL = {1'b0, LAST} + 1'b1;
    localparam [PW:0]   ONE  = {{PW{1'b0}}, 1'b1};

    reg [`EF_SPAN_W-1:0] mem [0:DEPTH-1];
    reg [`EF_SPAN_W-1:0] head;     // mem[rp] whenever the queue is not empty
    reg [PW-1:0] rp, wp;
    reg [PW:0]   count;
    reg          full;             // count == DEPTH

    assign out_valid = !empty || in_valid;
    assign out_data  = empty ? in_data : head;
    wire   pop       = !empty && out_ready;
    assign in_ready  = !full;
    wire   bypass    = empty && in_valid && out_ready;
    wire   push      = in_valid && in_ready && !bypass;

    wire [PW-1:0] wp1 = (wp == LAST) ? {PW{1'b0}} : wp + 1'b1;
    wire [PW-1:0] rp1 = (rp == LAST) ? {PW{1'b0}} : rp + 1'b1;

    always @(posedge clk) begin
        if (rst) begin
            rp    <= {PW{1'b0}};
            wp    <= {PW{1'b0}};
            count <= {(PW+1){1'b0}};
            full  <= 1'b0;
            empty <= 1'b1;
        end else begin
            if (push) begin
                mem[wp] <= in_data;
                wp      <= wp1;
            end
            if (pop)
                rp <= rp1;
            // The head: the span pushed into an empty queue, or after a
            // pop the next one (stored, or the one pushed in this cycle).
            if (push && (empty || (pop && count == ONE)))
                head <= in_data;
            else if (pop && count != ONE)
                head <= mem[rp1];
            if (push && !pop) begin
                count <= count + 1'b1;
                full  <= (count + 1'b1 == FULL);
                empty <= 1'b0;
            end else if (pop && !push) begin
                count <= count - 1'b1;
                full  <= 1'b0;
                empty <= (count == ONE);
            end
        end
    end
endmodule
