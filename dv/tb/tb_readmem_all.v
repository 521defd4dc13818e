// tb_readmem_all: tb_readmem.v for all seven interfaces of one vector set in
// one simulation.  Verilator recompiles its runtime library for every model,
// so seven separate -G builds cost seven times the build time; one build of
// this wrapper checks the same files with the same testbench.  Icarus
// compiles in milliseconds and runs tb_readmem.v once per interface instead.
//
// Parameters: DIR (the vector directory, no trailing slash), OUT (where the
// IFACE.actual.hex dumps go) and the seven counts from manifest.json.
// Needs --timing under Verilator (the #1 below).
module tb_readmem_all #(
    parameter DIR     = ".",
    parameter OUT     = ".",
    parameter D_CMD   = 1,
    parameter D_SEG   = 1,
    parameter D_ET_WR = 1,
    parameter D_ET_RD = 1,
    parameter D_PLOT  = 1,
    parameter D_SPAN  = 1,
    parameter D_PIX   = 1
);
    tb_readmem #(.P(100), .DEPTH(D_CMD),   .IFACE("cmd"),   .FINISH(0),
                 .IN_FILE({DIR, "/cmd.stim.hex"}),        .OUT_FILE({OUT, "/cmd.actual.hex"}))   u_cmd ();
    tb_readmem #(.P(97),  .DEPTH(D_SEG),   .IFACE("seg"),   .FINISH(0),
                 .IN_FILE({DIR, "/seg.expected.hex"}),    .OUT_FILE({OUT, "/seg.actual.hex"}))   u_seg ();
    tb_readmem #(.P(181), .DEPTH(D_ET_WR), .IFACE("et_wr"), .FINISH(0),
                 .IN_FILE({DIR, "/et_wr.expected.hex"}),  .OUT_FILE({OUT, "/et_wr.actual.hex"})) u_et_wr ();
    tb_readmem #(.P(36),  .DEPTH(D_ET_RD), .IFACE("et_rd"), .FINISH(0),
                 .IN_FILE({DIR, "/et_rd.expected.hex"}),  .OUT_FILE({OUT, "/et_rd.actual.hex"})) u_et_rd ();
    tb_readmem #(.P(36),  .DEPTH(D_PLOT),  .IFACE("plot"),  .FINISH(0),
                 .IN_FILE({DIR, "/plot.expected.hex"}),   .OUT_FILE({OUT, "/plot.actual.hex"}))  u_plot ();
    tb_readmem #(.P(75),  .DEPTH(D_SPAN),  .IFACE("span"),  .FINISH(0),
                 .IN_FILE({DIR, "/span.expected.hex"}),   .OUT_FILE({OUT, "/span.actual.hex"}))  u_span ();
    tb_readmem #(.P(68),  .DEPTH(D_PIX),   .IFACE("pix"),   .FINISH(0),
                 .IN_FILE({DIR, "/pix.expected.hex"}),    .OUT_FILE({OUT, "/pix.actual.hex"}))   u_pix ();

    // Every instance does its work in an initial block at time 0; then the
    // run ends, non-zero ($fatal) when any of them failed (its FAIL line
    // printed), so a caller can go by the exit status.
    initial begin
        #1;
        if (u_cmd.errors != 0 || u_seg.errors != 0 || u_et_wr.errors != 0 || u_et_rd.errors != 0 ||
            u_plot.errors != 0 || u_span.errors != 0 || u_pix.errors != 0)
            $fatal(1, "tb_readmem_all: FAIL");
        $finish;
    end
endmodule
