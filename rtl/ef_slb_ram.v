// ef_slb_ram: the scanline buffer's cell memory (docs/microarch.md 3.4).
//
// One write port and one synchronous read port on one clock: the shape a
// block RAM (FPGA) or a two-port SRAM macro (ASIC) has, so the filler's
// memory of W_MAX+1 cells of 7*NS bits never has to be flip-flops.
//
// Read-during-write to the same address returns the OLD contents (read
// first, which is what the non-blocking assignments below simulate).  The
// client (ef_slb_fill) forwards the latest write itself on every address
// match, so its results do not depend on this choice: a vendor RAM with
// "write first" or "don't care" collision behaviour gives the same bits.
//
// Synthesizable Verilog-2005.
module ef_slb_ram #(
    parameter AW    = 15,      // address bits
    parameter DW    = 56,      // data bits (7 * NS)
    parameter DEPTH = 16385    // W_MAX + 1 cells
) (
    input  wire          clk,
    input  wire          we,
    input  wire [AW-1:0] wa,
    input  wire [DW-1:0] wd,
    input  wire          re,    // rd holds its value while re is low
    input  wire [AW-1:0] ra,
    output reg  [DW-1:0] rd
);
    reg [DW-1:0] mem [0:DEPTH-1];

    always @(posedge clk) begin
        if (we)
            mem[wa] <= wd;
        if (re)
            rd <= mem[ra];
    end
endmodule
