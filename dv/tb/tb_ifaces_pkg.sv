// tb_ifaces_pkg: the generated SystemVerilog package ef_ifaces_pkg.sv
// (`edgeflag vectors --rtl-headers`, docs/vectors.md section 8), built
// with Verilator.  Every packed struct is as wide as its interface's payload, and
// a field written through the struct lands at the offset and width the
// package's localparams (and ef_ifaces.vh) give it.  The header's offsets are
// proven by the block benches, whose dumps `edgeflag check` accepts.
// Result line: "tb_ifaces_pkg: PASS ..." or "tb_ifaces_pkg: FAIL ...".
module tb_ifaces_pkg;
    import ef_ifaces_pkg::*;
    integer errors = 0, nfield = 0;

    // FIELD(T, W, f, LSB, FW): set field f of an all-zero T to all ones and
    // check that exactly bits [LSB+FW-1:LSB] of the packed value are set.
`define FIELD(T, W, f, LSB, FW) \
    begin : chk_``T``_``f \
        T v; logic [W-1:0] want; \
        v = '0; v.f = '1; \
        want = ((W)'(1) << (FW)) - (W)'(1); want = want << (LSB); \
        if (W'(v) !== want) begin \
            $display("tb_ifaces_pkg: %s.%s is not at [%0d +: %0d]", `"T`", `"f`", LSB, FW); \
            errors = errors + 1; \
        end \
        nfield = nfield + 1; \
    end

    initial begin
        if ($bits(cmd_t) != CMD_W || $bits(seg_t) != SEG_W || $bits(et_wr_t) != ET_WR_W ||
            $bits(et_rd_t) != ET_RD_W || $bits(plot_t) != PLOT_W || $bits(span_t) != SPAN_W ||
            $bits(pix_t) != PIX_W) begin
            $display("tb_ifaces_pkg: a struct's width differs from its interface's");
            errors = errors + 1;
        end
        if (CMD_WORD_W != CMD_W + CYCLE_BITS || OP_FRAME != 4'd1 || OP_FRAME_END != 4'd5 || IF_SEG != 1) begin
            $display("tb_ifaces_pkg: word width, op or interface number wrong");
            errors = errors + 1;
        end
        `FIELD(cmd_t, CMD_W, op, CMD_OP_LSB, CMD_OP_W)
        `FIELD(cmd_t, CMD_W, a, CMD_A_LSB, CMD_A_W)
        `FIELD(cmd_t, CMD_W, d, CMD_D_LSB, CMD_D_W)
        `FIELD(seg_t, SEG_W, eos, SEG_EOS_LSB, SEG_EOS_W)
        `FIELD(seg_t, SEG_W, xa, SEG_XA_LSB, SEG_XA_W)
        `FIELD(seg_t, SEG_W, yb, SEG_YB_LSB, SEG_YB_W)
        `FIELD(et_wr_t, ET_WR_W, eos, ET_WR_EOS_LSB, ET_WR_EOS_W)
        `FIELD(et_wr_t, ET_WR_W, slot, ET_WR_SLOT_LSB, ET_WR_SLOT_W)
        `FIELD(et_wr_t, ET_WR_W, r0, ET_WR_R0_LSB, ET_WR_R0_W)
        `FIELD(et_wr_t, ET_WR_W, r1, ET_WR_R1_LSB, ET_WR_R1_W)
        `FIELD(et_wr_t, ET_WR_W, x, ET_WR_X_LSB, ET_WR_X_W)
        `FIELD(et_wr_t, ET_WR_W, e, ET_WR_E_LSB, ET_WR_E_W)
        `FIELD(et_wr_t, ET_WR_W, qs, ET_WR_QS_LSB, ET_WR_QS_W)
        `FIELD(et_wr_t, ET_WR_W, rs, ET_WR_RS_LSB, ET_WR_RS_W)
        `FIELD(et_wr_t, ET_WR_W, dy, ET_WR_DY_LSB, ET_WR_DY_W)
        `FIELD(et_wr_t, ET_WR_W, dir, ET_WR_DIR_LSB, ET_WR_DIR_W)
        `FIELD(et_rd_t, ET_RD_W, row, ET_RD_ROW_LSB, ET_RD_ROW_W)
        `FIELD(et_rd_t, ET_RD_W, eid, ET_RD_EID_LSB, ET_RD_EID_W)
        `FIELD(plot_t, PLOT_W, last, PLOT_LAST_LSB, PLOT_LAST_W)
        `FIELD(plot_t, PLOT_W, q, PLOT_Q_LSB, PLOT_Q_W)
        `FIELD(span_t, SPAN_W, len, SPAN_LEN_LSB, SPAN_LEN_W)
        `FIELD(span_t, SPAN_W, mask, SPAN_MASK_LSB, SPAN_MASK_W)
        `FIELD(pix_t, PIX_W, alpha, PIX_ALPHA_LSB, PIX_ALPHA_W)
        `FIELD(pix_t, PIX_W, rgba, PIX_RGBA_LSB, PIX_RGBA_W)
        if (errors == 0)
            $display("tb_ifaces_pkg: PASS 7 structs, %0d fields at their offsets", nfield);
        else
            $display("tb_ifaces_pkg: FAIL %0d errors", errors);
        if (errors != 0) $fatal(1, "tb_ifaces_pkg: FAIL");
        $finish;
    end
endmodule
