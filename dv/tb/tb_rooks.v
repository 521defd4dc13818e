// tb_rooks: prints the RTL's n-rooks table (rtl/ef_rooks.vh, included as
// ef_plot includes it) as "rooks NS s k" lines, for tests/rtl/rtl-lint.sh to
// compare with model/pattern_tables.c.  Parameter NS (8, 16 or 32).
module tb_rooks #(
    parameter NS = 8
);
    `include "ef_ns.vh"
    `include "ef_rooks.vh"
    integer s;
    reg [4:0] sv;
    initial begin
        for (s = 0; s < NS; s = s + 1) begin
            sv = s[4:0];
            $display("rooks %0d %0d %0d", NS, s, rooks_k(sv));
        end
        $finish;
    end
endmodule
