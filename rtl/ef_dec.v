// ef_dec: command decoder (DEC) of the edgeflag reference microarchitecture
// (docs/microarch.md 3, 3.1 and section 4 items 1-2).
// Interfaces:  cmd (host -> DEC) in,  seg (DEC -> SETUP) out.
//
// FRAME and SHAPE write the configuration registers the later blocks read
// while a shape is rasterized (cfg_*); EDGE gives one `seg` and SHAPE_END the
// end-of-shape token (eos = 1, other fields 0), L_DEC = 1 cycle after the
// command's transfer: `seg` is a register loaded at the edge that transfers
// the command.  FRAME and FRAME_END give a one-cycle pulse (frame_start,
// frame_end) in the cycle after their transfer, for the frame buffer's clear
// and the end of the frame.
//
// Drain (item 1): after SHAPE_END the next command must wait until the shape
// has drained (T_free).  DEC takes no command after a SHAPE_END until
// `shape_done` is high: cmd_ready is low from the cycle after the SHAPE_END's
// transfer and rises in (combinationally with) the first cycle with
// shape_done high, so the sequencer raises shape_done in cycle T_free.
//
// Canvas limits: a FRAME wider than W_MAX or taller than H_MAX (or of size
// 0) sets the sticky `cfg_err` (cleared by rst); the configuration then holds
// the clamped size so no memory is addressed out of range, and the frame's
// output is not meaningful (the bench refuses such a stream before running).
//
// Synthesizable Verilog-2005.
`include "ef_ifaces.vh"

module ef_dec #(
    parameter W_MAX = 16384,
    parameter H_MAX = 16384
) (
    input  wire        clk,
    input  wire        rst,

    // cmd: op[3:0] a[23:0] b[23:0] c[23:0] d[23:0]
    input  wire        cmd_valid,
    output wire        cmd_ready,
    input  wire [`EF_CMD_OP_W-1:0] cmd_op,
    input  wire [`EF_CMD_A_W-1:0] cmd_a,
    input  wire [`EF_CMD_B_W-1:0] cmd_b,
    input  wire [`EF_CMD_C_W-1:0] cmd_c,
    input  wire [`EF_CMD_D_W-1:0] cmd_d,
    input  wire        shape_done,   // the shape after SHAPE_END has drained

    // seg: eos[0] xa[23:0] ya[23:0] xb[23:0] yb[23:0]
    output reg         seg_valid,
    input  wire        seg_ready,
    output reg         seg_eos,
    output reg  [`EF_SEG_XA_W-1:0] seg_xa,
    output reg  [`EF_SEG_YA_W-1:0] seg_ya,
    output reg  [`EF_SEG_XB_W-1:0] seg_xb,
    output reg  [`EF_SEG_YB_W-1:0] seg_yb,

    // Configuration registers (microarch 3.1).
    output reg  [14:0] cfg_width,    // FRAME a (1..W_MAX)
    output reg  [14:0] cfg_height,   // FRAME b (1..H_MAX)
    output reg         cfg_rule,     // SHAPE a: 0 non-zero, 1 even-odd
    output reg  [23:0] cfg_rgb,      // SHAPE b: {r, g, b}, straight colour
    output reg  [7:0]  cfg_alpha,    // SHAPE c
    output reg         frame_start,  // pulse: the cycle after FRAME
    output reg         frame_end,    // pulse: the cycle after FRAME_END
    output reg         cfg_err       // sticky: a FRAME over W_MAX x H_MAX
);
    // the command codes of docs/microarch.md 3.1, from ef_ifaces.vh
    localparam [`EF_CMD_OP_W-1:0] OP_FRAME = `EF_OP_FRAME, OP_SHAPE = `EF_OP_SHAPE, OP_EDGE = `EF_OP_EDGE,
                                  OP_SHAPE_END = `EF_OP_SHAPE_END, OP_FRAME_END = `EF_OP_FRAME_END;

    reg draining;   // a SHAPE_END was taken and the shape has not drained

    // One output register: a command that gives a seg needs it free (or
    // leaving in this cycle).  SETUP is always ready in the reference.
    wire out_free = !seg_valid || seg_ready;
    assign cmd_ready = !rst && out_free && (!draining || shape_done);
    wire take = cmd_valid && cmd_ready;

    wire [31:0] w_max = W_MAX;
    wire [31:0] h_max = H_MAX;
    wire frame_bad = (cmd_a == 24'd0) || ({8'd0, cmd_a} > w_max) || (cmd_b == 24'd0) || ({8'd0, cmd_b} > h_max);

    always @(posedge clk) begin
        if (rst) begin
            seg_valid   <= 1'b0;
            draining    <= 1'b0;
            frame_start <= 1'b0;
            frame_end   <= 1'b0;
            cfg_err     <= 1'b0;
            cfg_width   <= 15'd1;
            cfg_height  <= 15'd1;
            cfg_rule    <= 1'b0;
            cfg_rgb     <= 24'd0;
            cfg_alpha   <= 8'd0;
        end else begin
            frame_start <= take && (cmd_op == OP_FRAME);
            frame_end   <= take && (cmd_op == OP_FRAME_END);
            if (seg_ready)
                seg_valid <= 1'b0;
            if (draining && shape_done)
                draining <= 1'b0;
            if (take) begin
                case (cmd_op)
                    OP_FRAME: begin
                        cfg_err    <= cfg_err | frame_bad;
                        cfg_width  <= frame_bad ? 15'd1 : cmd_a[14:0];
                        cfg_height <= frame_bad ? 15'd1 : cmd_b[14:0];
                    end
                    OP_SHAPE: begin
                        cfg_rule  <= cmd_a[0];
                        cfg_rgb   <= cmd_b;
                        cfg_alpha <= cmd_c[7:0];
                    end
                    OP_EDGE: begin
                        seg_valid <= 1'b1;
                        seg_eos   <= 1'b0;
                        seg_xa    <= cmd_a;
                        seg_ya    <= cmd_b;
                        seg_xb    <= cmd_c;
                        seg_yb    <= cmd_d;
                    end
                    OP_SHAPE_END: begin
                        seg_valid <= 1'b1;
                        seg_eos   <= 1'b1;
                        seg_xa    <= {`EF_SEG_XA_W{1'b0}};
                        seg_ya    <= {`EF_SEG_YA_W{1'b0}};
                        seg_xb    <= {`EF_SEG_XB_W{1'b0}};
                        seg_yb    <= {`EF_SEG_YB_W{1'b0}};
                        draining  <= 1'b1;
                    end
                    default: ;
                endcase
            end
        end
    end
endmodule
