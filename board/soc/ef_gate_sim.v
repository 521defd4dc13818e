// ef_gate (simulation): ef_gate_ecp5.v with the DCCA clock buffer as an
// AND of the clock and the falling-edge enable register (the same
// waveform: the enable changes only while the clock is low).
module ef_gate (
    input  wire clk,
    input  wire en,
    output wire gclk,
    output reg  tick
);
    initial tick = 1'b0;
    always @(negedge clk) tick <= en;
    assign gclk = clk & tick;
endmodule
