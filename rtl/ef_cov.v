// ef_cov: COV/BLEND of the edgeflag reference microarchitecture
// (docs/microarch.md 3.4 and section 4, item 6; docs/spec.md 7.3 and 8).
// span in, pix out, and the frame memory OUTSIDE the core behind two ports
// (docs/microarch.md 3.5): a synchronous read port (fb_re, fb_ry, fb_rx ->
// fb_rdata one cycle later, held while fb_re is low) and a write port
// (fb_we, fb_wy, fb_wx, fb_wdata) written in the cycle pix transfers.  The
// memory holds premultiplied RGBA8, R in bits 31:24; its owner clears it to
// 0 before FRAME (the core never clears it).
//
// Pipeline (L_COV = 3): a span accepted at cycle a gives
//   a+1+i  stage A: read of pixel x+i issued
//   a+2+i  stage B: the destination is here; blend, register
//   a+3+i  stage C: pix valid; the frame write happens at its transfer
// and span_ready rises again in the cycle the span's last read issues
// (a + len): cov_free of the schedule.  A pix that is not taken (pix_ready
// low) holds the whole pipeline: no read issues, so fb_rdata holds too.
//
// Arithmetic (spec 7.3, 8), per span (it depends on the mask and the shape
// only): cov = (255 * popcount(mask) + NS/2) >> log2(NS);
// P = (mul(r,a), mul(g,a), mul(b,a), a);  s = mul(P_ch, cov);  sa = mul(a, cov);
// per pixel and channel: d' = d + s - mul(d, sa) mod 256, with
// mul(a, b) = ((t >> 8) + t) >> 8, t = a*b + 128.
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_cov #(
    parameter NS = 8
) (
    input  wire        clk,
    input  wire        rst,
    input  wire [23:0] cfg_rgb,     // SHAPE b: {r, g, b}, straight colour
    input  wire [7:0]  cfg_alpha,   // SHAPE c

    // span: y[13:0] x[13:0] len[14:0] mask[31:0]
    input  wire        span_valid,
    output wire        span_ready,
    input  wire [`EF_SPAN_Y_W-1:0] span_y,
    input  wire [`EF_SPAN_X_W-1:0] span_x,
    input  wire [`EF_SPAN_LEN_W-1:0] span_len,
    input  wire [`EF_SPAN_MASK_W-1:0] span_mask,

    // pix: y[13:0] x[13:0] alpha[7:0] rgba[31:0]
    output reg         pix_valid,
    input  wire        pix_ready,
    output reg  [`EF_PIX_Y_W-1:0] pix_y,
    output reg  [`EF_PIX_X_W-1:0] pix_x,
    output reg  [`EF_PIX_ALPHA_W-1:0] pix_alpha,
    output reg  [`EF_PIX_RGBA_W-1:0] pix_rgba,

    // frame memory (outside the core)
    output wire        fb_re,
    output wire [`EF_PIX_Y_W-1:0] fb_ry,
    output wire [`EF_PIX_X_W-1:0] fb_rx,
    input  wire [`EF_PIX_RGBA_W-1:0] fb_rdata,
    output wire        fb_we,
    output wire [`EF_PIX_Y_W-1:0] fb_wy,
    output wire [`EF_PIX_X_W-1:0] fb_wx,
    output wire [`EF_PIX_RGBA_W-1:0] fb_wdata,

    output wire        busy
);
    `include "ef_ns.vh"

    function [7:0] mul;
        input [7:0] a, b;
        reg [15:0] t;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [16:0] u;                  // the product fits 16 bits: u[15:8] is it
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            t = a * b + 16'd128;
            u = {9'd0, t[15:8]} + {1'b0, t};
            mul = u[15:8];
        end
    endfunction

    function [5:0] popcount;
        input [31:0] m;
        integer i;
        begin
            popcount = 6'd0;
            for (i = 0; i < 32; i = i + 1)
                popcount = popcount + {5'd0, m[i]};
        end
    endfunction

    // ------------------------------------------------ per span
    wire [13:0] pc255 = {8'd0, popcount(span_mask)} * 14'd255 + (14'd1 << (LOG2NS - 1));
    /* verilator lint_off UNUSEDSIGNAL */
    wire [13:0] cov_w = pc255 >> LOG2NS;                 // <= 255
    /* verilator lint_on UNUSEDSIGNAL */
    wire [7:0]  cov   = cov_w[7:0];
    // P, premultiplied, registered (issue 25: one multiplier fewer in the
    // span's cycle): SHAPE sets cfg_rgb/cfg_alpha at least L_SETUP cycles
    // before the shape's first span, so the register has long caught up.
    reg [7:0] p_r, p_g, p_b;
    always @(posedge clk) begin
        p_r <= mul(cfg_rgb[23:16], cfg_alpha);
        p_g <= mul(cfg_rgb[15:8], cfg_alpha);
        p_b <= mul(cfg_rgb[7:0], cfg_alpha);
    end

    // ------------------------------------------------ stages
    reg [14:0] a_cnt;
    reg [13:0] a_y, a_x;
    reg [7:0]  a_cov;
    reg        b_valid;
    reg [13:0] b_y, b_x;
    reg [7:0]  b_cov, b_sr, b_sg, b_sb, b_sa;

    wire stall = pix_valid && !pix_ready;
    wire issue = !stall && (a_cnt != 15'd0);
    assign span_ready = !stall && (a_cnt <= 15'd1);
    wire take = span_valid && span_ready;

    assign fb_re = issue;
    assign fb_ry = a_y;
    assign fb_rx = a_x;
    assign fb_we = pix_valid && pix_ready;
    assign fb_wy = pix_y;
    assign fb_wx = pix_x;
    assign fb_wdata = pix_rgba;
    assign busy = (a_cnt != 15'd0) || b_valid || pix_valid;

    wire [7:0] d_r = fb_rdata[31:24], d_g = fb_rdata[23:16], d_b = fb_rdata[15:8], d_a = fb_rdata[7:0];
    wire [7:0] n_r = d_r + b_sr - mul(d_r, b_sa);
    wire [7:0] n_g = d_g + b_sg - mul(d_g, b_sa);
    wire [7:0] n_b = d_b + b_sb - mul(d_b, b_sa);
    wire [7:0] n_a = d_a + b_sa - mul(d_a, b_sa);

    always @(posedge clk) begin
        if (rst) begin
            a_cnt <= 15'd0;
            b_valid <= 1'b0;
            pix_valid <= 1'b0;
        end else if (!stall) begin
            // C <- B
            pix_valid <= b_valid;
            if (b_valid) begin
                pix_y <= b_y;
                pix_x <= b_x;
                pix_alpha <= b_cov;
                pix_rgba <= {n_r, n_g, n_b, n_a};
            end
            // B <- A
            b_valid <= issue;
            if (issue) begin
                // the span's products from its registered coverage (issue
                // 25: popcount and coverage, then the products, each in
                // a cycle of its own; the schedule is unchanged)
                b_y <= a_y; b_x <= a_x; b_cov <= a_cov;
                b_sr <= mul(p_r, a_cov); b_sg <= mul(p_g, a_cov); b_sb <= mul(p_b, a_cov);
                b_sa <= mul(cfg_alpha, a_cov);
                a_x <= a_x + 14'd1;
            end
            // A: the span's fields load whenever COV is ready, offered or
            // not (issue 25: only a_cnt waits for span_valid, which comes
            // from SLB's cell read); when nothing is taken they are unused
            // (a_cnt is 0 after this edge, or was 1 and its last read
            // issued with the old fields in this cycle)
            if (span_ready) begin
                a_y <= span_y;
                a_x <= span_x;
                a_cov <= cov;
            end
            if (take)
                a_cnt <= span_len;
            else if (issue)
                a_cnt <= a_cnt - 15'd1;
        end
    end
endmodule
