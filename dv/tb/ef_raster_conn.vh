// ef_raster_conn.vh - the named port connections of an ef_raster instance
// whose every port goes to a net of the same name, `included between the
// instance's parentheses (Verilog-2005; the build needs -I dv/tb):
//     ef_raster #(.NS(NS), ...) dut (
//     `include "ef_raster_conn.vh"
//     );
// One list for the benches that instantiate the whole pipeline
// (tb_raster.v, tb_err.v) and the board DUT's wrapper (dut_rtl.v), so a
// port added to ef_raster is connected in one place.  A bench that ties a
// port off declares a net of the port's name with the tie-off value.
        .clk(clk), .rst(rst), .init_done(init_done),
        .cmd_valid(cmd_valid), .cmd_ready(cmd_ready), .cmd_op(cmd_op),
        .cmd_a(cmd_a), .cmd_b(cmd_b), .cmd_c(cmd_c), .cmd_d(cmd_d),
        .pix_valid(pix_valid), .pix_ready(pix_ready), .pix_y(pix_y), .pix_x(pix_x),
        .pix_alpha(pix_alpha), .pix_rgba(pix_rgba),
        .fb_re(fb_re), .fb_ry(fb_ry), .fb_rx(fb_rx), .fb_rdata(fb_rdata),
        .fb_we(fb_we), .fb_wy(fb_wy), .fb_wx(fb_wx), .fb_wdata(fb_wdata),
        .cfg_width(cfg_width), .cfg_height(cfg_height), .frame_start(frame_start),
        .frame_end(frame_end), .err(err),
        .seg_valid(seg_valid), .seg_ready(seg_ready), .seg_eos(seg_eos),
        .seg_xa(seg_xa), .seg_ya(seg_ya), .seg_xb(seg_xb), .seg_yb(seg_yb),
        .et_wr_valid(et_wr_valid), .et_wr_ready(et_wr_ready), .et_wr_eos(et_wr_eos),
        .et_wr_slot(et_wr_slot), .et_wr_r0(et_wr_r0), .et_wr_r1(et_wr_r1), .et_wr_x(et_wr_x),
        .et_wr_e(et_wr_e), .et_wr_qs(et_wr_qs), .et_wr_rs(et_wr_rs), .et_wr_dy(et_wr_dy),
        .et_wr_dir(et_wr_dir),
        .et_rd_valid(et_rd_valid), .et_rd_ready(et_rd_ready), .et_rd_row(et_rd_row), .et_rd_eid(et_rd_eid),
        .plot_valid(plot_valid), .plot_ready(plot_ready), .plot_last(plot_last), .plot_row(plot_row),
        .plot_s(plot_s), .plot_q(plot_q), .plot_dir(plot_dir),
        .span_valid(span_valid), .span_ready(span_ready), .span_y(span_y), .span_x(span_x),
        .span_len(span_len), .span_mask(span_mask)
