// ef_aet_pins: a pin-light wrapper of ef_aet for place and route only
// (docs/synthesis.md): every input of the block comes from one shift
// register fed by a single pin, and every output is folded into one
// registered parity pin, so nextpnr can place the block on a small package
// and report its Fmax without logic being optimised away.
module ef_aet_pins #(
    parameter NS = 8, parameter H_MAX = 240, parameter E_MAX = 255
) (
    input  wire clk,
    input  wire rst,
    input  wire din,
    output reg  dout
);
    localparam NI = 15 + 1 + 1 + 14 + 1 + 14 + 22 + 1 + 19 + 19 + 25 + 24 + 30 + 24 + 24 + 1 + 1;
    reg [NI-1:0] sr;
    always @(posedge clk) sr <= {sr[NI-2:0], din};
    wire        row_req, et_rd_ready, rec_re, plot_valid, plot_last, plot_dir, busy;
    wire [13:0] row_req_row, plot_row;
    wire [21:0] rec_ra;
    wire [4:0]  plot_s;
    wire [14:0] plot_q;
    ef_aet #(.NS(NS), .H_MAX(H_MAX), .E_MAX(E_MAX)) u (
        .clk(clk), .rst(rst), .cfg_width(sr[14:0]),
        .etw_valid(sr[15]), .etw_eos(sr[16]), .etw_slot(sr[30:17]),
        .row_req(row_req), .row_req_row(row_req_row),
        .et_rd_valid(sr[31]), .et_rd_ready(et_rd_ready), .et_rd_row(sr[45:32]), .et_rd_eid(sr[67:46]),
        .et_rd_last(sr[68]),
        .rec_re(rec_re), .rec_ra(rec_ra), .rec_r0(sr[87:69]), .rec_r1(sr[106:88]), .rec_x(sr[131:107]),
        .rec_e(sr[155:132]), .rec_qs(sr[185:156]), .rec_rs(sr[209:186]), .rec_dy(sr[233:210]), .rec_dir(sr[234]),
        .plot_valid(plot_valid), .plot_ready(sr[235]), .plot_last(plot_last), .plot_row(plot_row),
        .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir), .busy(busy)
    );
    always @(posedge clk)
        dout <= ^{row_req, row_req_row, et_rd_ready, rec_re, rec_ra, plot_valid, plot_last, plot_row, plot_s, plot_q, plot_dir, busy};
endmodule
