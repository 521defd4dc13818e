// ef_gate (ECP5): the clock of ef_raster, the ef clock gated by `en`.
// `en` is registered on the falling edge, so the enable of the DCCA clock
// buffer changes only while the clock is low: no glitch reaches the DUT.
// `tick` is that register: high before a rising edge at which the DUT's
// clock rises too (board/soc/ef_periph.py counts and observes those edges).
module ef_gate (
    input  wire clk,
    input  wire en,
    output wire gclk,
    output reg  tick
);
    initial tick = 1'b0;
    always @(negedge clk) tick <= en;
    DCCA u_dcc (.CLKI(clk), .CE(tick), .CLKO(gclk));
endmodule
