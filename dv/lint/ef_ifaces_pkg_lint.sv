// ef_ifaces_pkg_lint: a lint wrapper for the generated package
// rtl/ef_ifaces_pkg.sv (`edgeflag vectors --rtl-headers`, docs/vectors.md
// section 8).  A package alone has no top module, which Verilator 5.006's
// --lint-only does not survive (an internal fault); this module imports it
// and decodes a word into every struct, so
//   $ verilator --lint-only -Wall dv/lint/waivers.vlt rtl/ef_ifaces_pkg.sv dv/lint/ef_ifaces_pkg_lint.sv
// checks the package on its own (tests/rtl/rtl-lint.sh does, and compiles it
// with Icarus -g2012 too).
module ef_ifaces_pkg_lint
    import ef_ifaces_pkg::*;
(
    input  logic [CMD_W-1:0]   cmd_word,
    input  logic [SEG_W-1:0]   seg_word,
    input  logic [ET_WR_W-1:0] et_wr_word,
    input  logic [ET_RD_W-1:0] et_rd_word,
    input  logic [PLOT_W-1:0]  plot_word,
    input  logic [SPAN_W-1:0]  span_word,
    input  logic [PIX_W-1:0]   pix_word,
    output cmd_t   cmd,
    output seg_t   seg,
    output et_wr_t et_wr,
    output et_rd_t et_rd,
    output plot_t  plot,
    output span_t  span,
    output pix_t   pix
);
    assign cmd   = cmd_word;
    assign seg   = seg_word;
    assign et_wr = et_wr_word;
    assign et_rd = et_rd_word;
    assign plot  = plot_word;
    assign span  = span_word;
    assign pix   = pix_word;
endmodule
