// ef_model_pkg: the edgeflag reference model inside a SystemVerilog
// simulation, through DPI-C (rtl_vectors/dpi/ef_dpi.c over
// ef_model_stream.h; contract: docs/dpi.md).
//
// A testbench creates a model (a chandle; as many as it likes), feeds it the
// commands it sends the DUT (the cmd interface's 100-bit payloads,
// docs/microarch.md 3.1), and for every transfer it sees on a DUT interface
// asks the model for the next expected transaction of that interface, with
// the cycle at which the reference schedule puts it (ef_dpi_pop), or lets the
// model compare (ef_dpi_expect: a message naming the interface and every
// decoded field, expected against actual).
//
// The interface structs below are the field layouts of docs/microarch.md 3,
// most significant field first, so `ef_span_t'(payload[74:0])` decodes a
// span.  They are written out by hand; ef_check_layout() compares every
// field's position and width with the model's own interface table
// (model/trace_iface.c) at run time, and tests/dpi/run.sh calls it, so the
// two cannot drift apart silently.
//
// To build with Verilator, pass this file before the bench, and build/libef_dpi.a (make
// build/libef_dpi.a) on the command line.
package ef_model_pkg;

    // Interfaces (ef_iface, model/ef_trace.h): the numbers ef_dpi_* take.
    localparam int EF_IF_CMD   = 0;
    localparam int EF_IF_SEG   = 1;
    localparam int EF_IF_ET_WR = 2;
    localparam int EF_IF_ET_RD = 3;
    localparam int EF_IF_PLOT  = 4;
    localparam int EF_IF_SPAN  = 5;
    localparam int EF_IF_PIX   = 6;
    localparam int EF_IF_COUNT = 7;

    // Payload widths P (docs/microarch.md 3); a payload crosses DPI
    // zero-extended to the widest, et_wr's.
    localparam int EF_CMD_BITS   = 100;
    localparam int EF_SEG_BITS   = 97;
    localparam int EF_ET_WR_BITS = 181;
    localparam int EF_ET_RD_BITS = 36;
    localparam int EF_PLOT_BITS  = 36;
    localparam int EF_SPAN_BITS  = 75;
    localparam int EF_PIX_BITS   = 68;
    localparam int EF_PAYLOAD_BITS = 181;
    typedef bit [EF_PAYLOAD_BITS-1:0] ef_payload_t;

    // Command op codes (docs/microarch.md 3.1).
    localparam bit [3:0] EF_OP_FRAME     = 4'd1;
    localparam bit [3:0] EF_OP_SHAPE     = 4'd2;
    localparam bit [3:0] EF_OP_EDGE      = 4'd3;
    localparam bit [3:0] EF_OP_SHAPE_END = 4'd4;
    localparam bit [3:0] EF_OP_FRAME_END = 4'd5;

    // Statuses (ef_mstream_status): >= 0 outcomes, < 0 errors.
    localparam int EF_MS_OK       = 0;
    localparam int EF_MS_EMPTY    = 1;   // nothing queued yet: feed more commands
    localparam int EF_MS_END      = 2;   // the frame has ended: nothing more
    localparam int EF_MS_MISMATCH = 3;   // ef_dpi_expect: differs (ef_dpi_message says how)

    // Rule setting of ef_dpi_create: each SHAPE's own, or 0 non-zero / 1 even-odd for all.
    localparam int EF_MS_RULE_CMD = -1;

    // ------------------------------------------------------------ layouts
    typedef struct packed {
        bit [3:0]  op;
        bit [23:0] a, b, c, d;
    } ef_cmd_t;
    typedef struct packed {
        bit        eos;
        bit [23:0] xa, ya, xb, yb;     // Q16.8, two's complement
    } ef_seg_t;
    typedef struct packed {
        bit        eos;
        bit [13:0] slot;
        bit [18:0] r0, r1;
        bit [24:0] x;                  // signed
        bit [23:0] e;
        bit [29:0] qs;                 // signed
        bit [23:0] rs, dy;
        bit        dir;
    } ef_et_wr_t;
    typedef struct packed {
        bit [13:0] row;
        bit [21:0] eid;
    } ef_et_rd_t;
    typedef struct packed {
        bit        last;
        bit [13:0] row;
        bit [4:0]  s;
        bit [14:0] q;
        bit        dir;
    } ef_plot_t;
    typedef struct packed {
        bit [13:0] y, x;
        bit [14:0] len;
        bit [31:0] mask;
    } ef_span_t;
    typedef struct packed {
        bit [13:0] y, x;
        bit [7:0]  alpha;
        bit [31:0] rgba;
    } ef_pix_t;

    // ------------------------------------------------------------ DPI-C
    // A model.  samples 8/16/32; width_max x height_max: the largest canvas a
    // FRAME may set (the RTL's W_MAX, H_MAX); edges_max: most EDGE commands in
    // a shape (E_MAX); rule: EF_MS_RULE_CMD or 0/1; ifaces: the interfaces
    // whose transactions are kept, bit i = interface i (0: all; a bench keeps
    // what it pops, the rest costs memory).  null and status < 0 on a bad
    // parameter.
    import "DPI-C" function chandle ef_dpi_create(input int samples, input int width_max, input int height_max,
                                                  input int edges_max, input int rule, input int ifaces,
                                                  output int status);
    import "DPI-C" function void ef_dpi_destroy(input chandle h);
    // Feeds one command; EF_MS_OK or an error (< 0; sticky; ef_dpi_message
    // names the command by number).
    import "DPI-C" function int ef_dpi_cmd(input chandle h, input bit [EF_CMD_BITS-1:0] word);
    // The next expected transaction of an interface: EF_MS_OK, EF_MS_EMPTY
    // (feed more commands) or EF_MS_END.  Peek leaves it queued.
    import "DPI-C" function int ef_dpi_pop(input chandle h, input int iface, output longint cycle,
                                           output ef_payload_t payload);
    import "DPI-C" function int ef_dpi_peek(input chandle h, input int iface, output longint cycle,
                                            output ef_payload_t payload);
    import "DPI-C" function int ef_dpi_pending(input chandle h, input int iface);
    // Scoreboard: pops the next expected transaction of iface and compares it
    // with the actual one (the cycle too unless check_cycle is 0): EF_MS_OK,
    // EF_MS_MISMATCH, EF_MS_END (an extra transaction), EF_MS_EMPTY (nothing
    // popped: feed commands, call again).
    import "DPI-C" function int ef_dpi_expect(input chandle h, input int iface, input longint cycle,
                                              input ef_payload_t payload, input int check_cycle);
    // At the end: EF_MS_OK if nothing of iface is left, else EF_MS_MISMATCH
    // ("missing transaction").
    import "DPI-C" function int ef_dpi_expect_done(input chandle h, input int iface);
    import "DPI-C" function string ef_dpi_message(input chandle h);
    import "DPI-C" function string ef_dpi_strerror(input int status);
    import "DPI-C" function string ef_dpi_iface_name(input int iface);
    import "DPI-C" function int ef_dpi_iface_width(input int iface);
    // The frame's length in cycles after FRAME_END, else -1.
    import "DPI-C" function longint ef_dpi_frame_cycles(input chandle h);
    import "DPI-C" function longint ef_dpi_commands(input chandle h);
    // 1 when `ones` (a payload of iface) is exactly field `name` set to all
    // ones: the layout check below.
    import "DPI-C" function int ef_dpi_field_is(input int iface, input string name, input ef_payload_t ones);

    // ------------------------------------------------------------ layout check
    // The number of fields whose position or width differs from the model's
    // table (0 = the structs above are right), each one $display'ed.
    function automatic int ef_check_layout();
        int bad = 0;
        ef_cmd_t c; ef_seg_t g; ef_et_wr_t w; ef_et_rd_t r; ef_plot_t p; ef_span_t s; ef_pix_t x;
`define EF_FIELD(IF, VAR, F) \
        begin VAR = '0; VAR.F = '1; \
            if (ef_dpi_field_is(IF, `"F`", ef_payload_t'(VAR)) != 1) begin \
                $display("ef_model_pkg: %s.%s: position or width differs from the model's table", \
                         ef_dpi_iface_name(IF), `"F`"); \
                bad++; \
            end \
        end
        `EF_FIELD(EF_IF_CMD, c, op) `EF_FIELD(EF_IF_CMD, c, a) `EF_FIELD(EF_IF_CMD, c, b)
        `EF_FIELD(EF_IF_CMD, c, c) `EF_FIELD(EF_IF_CMD, c, d)
        `EF_FIELD(EF_IF_SEG, g, eos) `EF_FIELD(EF_IF_SEG, g, xa) `EF_FIELD(EF_IF_SEG, g, ya)
        `EF_FIELD(EF_IF_SEG, g, xb) `EF_FIELD(EF_IF_SEG, g, yb)
        `EF_FIELD(EF_IF_ET_WR, w, eos) `EF_FIELD(EF_IF_ET_WR, w, slot) `EF_FIELD(EF_IF_ET_WR, w, r0)
        `EF_FIELD(EF_IF_ET_WR, w, r1) `EF_FIELD(EF_IF_ET_WR, w, x) `EF_FIELD(EF_IF_ET_WR, w, e)
        `EF_FIELD(EF_IF_ET_WR, w, qs) `EF_FIELD(EF_IF_ET_WR, w, rs) `EF_FIELD(EF_IF_ET_WR, w, dy)
        `EF_FIELD(EF_IF_ET_WR, w, dir)
        `EF_FIELD(EF_IF_ET_RD, r, row) `EF_FIELD(EF_IF_ET_RD, r, eid)
        `EF_FIELD(EF_IF_PLOT, p, last) `EF_FIELD(EF_IF_PLOT, p, row) `EF_FIELD(EF_IF_PLOT, p, s)
        `EF_FIELD(EF_IF_PLOT, p, q) `EF_FIELD(EF_IF_PLOT, p, dir)
        `EF_FIELD(EF_IF_SPAN, s, y) `EF_FIELD(EF_IF_SPAN, s, x) `EF_FIELD(EF_IF_SPAN, s, len)
        `EF_FIELD(EF_IF_SPAN, s, mask)
        `EF_FIELD(EF_IF_PIX, x, y) `EF_FIELD(EF_IF_PIX, x, x) `EF_FIELD(EF_IF_PIX, x, alpha)
        `EF_FIELD(EF_IF_PIX, x, rgba)
`undef EF_FIELD
        if ($bits(ef_cmd_t) != EF_CMD_BITS || $bits(ef_seg_t) != EF_SEG_BITS || $bits(ef_et_wr_t) != EF_ET_WR_BITS ||
            $bits(ef_et_rd_t) != EF_ET_RD_BITS || $bits(ef_plot_t) != EF_PLOT_BITS ||
            $bits(ef_span_t) != EF_SPAN_BITS || $bits(ef_pix_t) != EF_PIX_BITS) begin
            $display("ef_model_pkg: a struct's width differs from its EF_*_BITS");
            bad++;
        end
        for (int i = 0; i < EF_IF_COUNT; i++)
            if (ef_dpi_iface_width(i) != (i == 0 ? EF_CMD_BITS : i == 1 ? EF_SEG_BITS : i == 2 ? EF_ET_WR_BITS :
                                          i == 3 ? EF_ET_RD_BITS : i == 4 ? EF_PLOT_BITS : i == 5 ? EF_SPAN_BITS :
                                          EF_PIX_BITS)) begin
                $display("ef_model_pkg: %s is %0d bits in the model", ef_dpi_iface_name(i), ef_dpi_iface_width(i));
                bad++;
            end
        return bad;
    endfunction
endpackage
