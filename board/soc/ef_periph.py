"""ef_raster as a LiteX peripheral (docs/board-ulx3s.md, "The peripheral").

Commands in: the firmware writes a 100-bit cmd word into cmd0..cmd3 and
strobes `push`; an asynchronous FIFO carries it into the `ef` clock domain.
Records out: every transfer of the chosen interfaces (valid && ready at a DUT
clock edge) is captured with its cycle and serialised as 32-bit words into an
asynchronous FIFO that the firmware drains through `rec_data` / `rec_pop`:

    word 0   bits 7:0 interface, 15:8 payload bytes L, 31:16 cycle[15:0]
    word 1   cycle[47:16]
    word 2.. the payload, ceil(L/4) words, least significant first (the
             vectors.bin record's payload bytes, docs/vectors.md section 4)

and marker words (interface byte 0xFF): bits 31:16 a code, 0 for the answer
to a FLUSH command (op 15, never given to the DUT: everything before it is
out), 1 the DUT raised `err`, 2 a command outside a frame.

Cycle exactness: the DUT's clock is the `ef` clock gated (ef_gate_*.v).  It
runs only in cycles in which the reference bench (dv/tb/tb_raster.v,
board/dut_rtl.c) would be in the same state: while a command is owed to the
DUT and none is in the FIFO, and while captured records are being
serialised, the clock stops, so the DUT sees the bench's schedule -- a
command offered in the cycle after the previous one was taken -- whatever
the CPU's and the link's speed.  Cycle 0 is the first cycle after the edge
at which init_done is seen after the reset that each FRAME starts with.

Frame memory: W_MAX x H_MAX words of block RAM on the ef clock (read data one
DUT cycle after fb_re, held), cleared during that reset.  A frame ends at the
DUT clock edge at which FRAME_END is taken: the pipeline is drained there.
ef_raster's DEC takes the command after a SHAPE_END only in the cycle T_free in
which the shape has drained (its eos et_wr passed, AET, SLB+FILL and COV idle:
`shape_done`, docs/microarch.md section 3 "Drain" and section 4 items 1 and 7),
so a FRAME_END that follows a closed shape (or no shape) passes DEC, the only
block it enters, with every other block empty, and is the frame's last
transfer.  The firmware (board/firmware/dut_soc.c) refuses a FRAME_END inside
an open shape, the one stream after which something could still move.  The
DUT's clock stops there; the next FRAME (its reset) and the FLUSH marker wait
for the frame's records to be serialised.
"""

from migen import *
from migen.genlib.cdc import MultiReg

from litex.gen import LiteXModule
from litex.soc.interconnect import stream
from litex.soc.interconnect.csr import CSR, CSRStatus, CSRStorage

# The interfaces of docs/vectors.md in their order (interface i = bit i),
# each with its fields most significant first (model/trace_iface.c): the
# vectors.bin payload is their concatenation, the first field on top.
IFACES = [
    ("cmd", [("op", 4), ("a", 24), ("b", 24), ("c", 24), ("d", 24)]),
    ("seg", [("eos", 1), ("xa", 24), ("ya", 24), ("xb", 24), ("yb", 24)]),
    ("et_wr", [("eos", 1), ("slot", 14), ("r0", 19), ("r1", 19), ("x", 25), ("e", 24), ("qs", 30),
               ("rs", 24), ("dy", 24), ("dir", 1)]),
    ("et_rd", [("row", 14), ("eid", 22)]),
    ("plot", [("last", 1), ("row", 14), ("s", 5), ("q", 15), ("dir", 1)]),
    ("span", [("y", 14), ("x", 14), ("len", 15), ("mask", 32)]),
    ("pix", [("y", 14), ("x", 14), ("alpha", 8), ("rgba", 32)]),
]

OP_FRAME, OP_FRAME_END, OP_FLUSH = 1, 5, 15


def log2(n):
    k = (n - 1).bit_length()
    assert 1 << k == n, "W_MAX and H_MAX must be powers of two here"
    return k


class EFRaster(LiteXModule):
    def __init__(self, ns=8, w_max=64, h_max=64, e_max=255, fifo_depth=512, schedule=0):
        self.ns, self.w_max, self.h_max, self.e_max = ns, w_max, h_max, e_max
        # CSRs (sys domain)
        self.ctrl = CSRStorage(16, description="bit 0: reset; bits 14:8: interfaces to return")
        self.cmd0 = CSRStorage(32)
        self.cmd1 = CSRStorage(32)
        self.cmd2 = CSRStorage(32)
        self.cmd3 = CSRStorage(32)
        self.push = CSR()
        self.status = CSRStatus(8, description="bit 0: cmd FIFO has room; bit 1: a record word is there")
        self.rec_data = CSRStatus(32)
        self.rec_pop = CSR()
        self.ticks = CSRStatus(32, description="DUT clock edges since the last reset (ef domain, sampled)")

        # # #

        cmd_fifo = ClockDomainsRenamer({"write": "sys", "read": "ef"})(stream.AsyncFIFO([("data", 100)], 16))
        rec_fifo = ClockDomainsRenamer({"write": "ef", "read": "sys"})(
            stream.AsyncFIFO([("data", 32)], fifo_depth, buffered=True))
        self.cmd_fifo, self.rec_fifo = cmd_fifo, rec_fifo
        self.comb += [
            cmd_fifo.sink.valid.eq(self.push.re),
            cmd_fifo.sink.data.eq(Cat(self.cmd0.storage, self.cmd1.storage, self.cmd2.storage,
                                      self.cmd3.storage[:4])),
            self.status.status[0].eq(cmd_fifo.sink.ready),
            self.status.status[1].eq(rec_fifo.source.valid),
            self.rec_data.status.eq(rec_fifo.source.data),
            rec_fifo.source.ready.eq(self.rec_pop.re),
        ]

        # ef domain: control from the CSRs
        soft_rst = Signal()
        mask = Signal(7)
        ctrl_rst, ctrl_mask = Signal(), Signal(7)
        self.comb += [ctrl_rst.eq(self.ctrl.storage[0]), ctrl_mask.eq(self.ctrl.storage[8:15])]
        self.specials += [MultiReg(ctrl_rst, soft_rst, "ef"), MultiReg(ctrl_mask, mask, "ef")]

        # the DUT and its clock
        en, tick, gclk = Signal(), Signal(), Signal()
        self.specials += Instance("ef_gate", i_clk=ClockSignal("ef"), i_en=en, o_gclk=gclk, o_tick=tick)
        dut_rst = Signal(reset=1)
        cmd_valid, cmd_ready, init_done, err = Signal(), Signal(), Signal(), Signal()
        head = cmd_fifo.source
        op = head.data[96:100]
        p = {}  # port name -> signal
        ios = dict(i_clk=gclk, i_rst=dut_rst, o_init_done=init_done, i_cmd_valid=cmd_valid,
                   o_cmd_ready=cmd_ready, i_cmd_op=op, i_cmd_a=head.data[72:96], i_cmd_b=head.data[48:72],
                   i_cmd_c=head.data[24:48], i_cmd_d=head.data[0:24], i_pix_ready=1, o_err=err)
        for name, fields in IFACES[1:]:
            for f, w in [("valid", 1), ("ready", 1)] + fields:
                if name == "pix" and f == "ready":
                    continue
                s = Signal(w, name=name + "_" + f)
                p[name + "_" + f] = s
                ios["o_" + name + "_" + f] = s
        for f, w in [("re", 1), ("ry", 14), ("rx", 14), ("we", 1), ("wy", 14), ("wx", 14), ("wdata", 32)]:
            p["fb_" + f] = Signal(w, name="fb_" + f)
            ios["o_fb_" + f] = p["fb_" + f]
        fb_rdata = Signal(32)
        ios["i_fb_rdata"] = fb_rdata
        for f, w in [("cfg_width", 15), ("cfg_height", 15), ("frame_start", 1), ("frame_end", 1)]:
            ios["o_" + f] = Signal(w, name=f)
        self.specials += Instance("ef_raster", p_NS=ns, p_W_MAX=w_max, p_H_MAX=h_max, p_E_MAX=e_max,
                                  p_SCHEDULE=schedule, **ios)
        p["pix_ready"] = Constant(1, 1)

        # the frame memory
        lw, lh = log2(w_max), log2(h_max)
        mem = Memory(32, w_max * h_max)
        rport = mem.get_port(has_re=True, clock_domain="ef")
        wport = mem.get_port(write_capable=True, clock_domain="ef")
        self.specials += mem, rport, wport
        clearing = Signal()
        clr = Signal(lw + lh + 1)
        self.comb += [
            rport.adr.eq(Cat(p["fb_rx"][:lw], p["fb_ry"][:lh])),
            rport.re.eq(tick & p["fb_re"]),
            fb_rdata.eq(rport.dat_r),
            If(clearing,
                wport.adr.eq(clr), wport.dat_w.eq(0), wport.we.eq(tick)
            ).Else(
                wport.adr.eq(Cat(p["fb_wx"][:lw], p["fb_wy"][:lh])), wport.dat_w.eq(p["fb_wdata"]),
                wport.we.eq(tick & p["fb_we"])),
        ]

        # capture: the payload of every interface, the vectors.bin way
        payloads, valids = [], []
        for i, (name, fields) in enumerate(IFACES):
            if name == "cmd":
                src = [head.data[96:100], head.data[72:96], head.data[48:72], head.data[24:48], head.data[0:24]]
                v = cmd_valid & cmd_ready
            else:
                src = [p[name + "_" + f] for f, _ in fields]
                v = p[name + "_valid"] & p[name + "_ready"]
            payloads.append(Cat(*reversed(src)))
            valids.append(v & mask[i])
        held = [Signal(len(x)) for x in payloads]
        held_v = Signal(7)
        t = Signal(48)
        held_t = Signal(48)

        # serialiser state
        ser_busy = Signal()
        idx = Signal(3)
        k = Signal(4)
        mark = Signal()
        mark_code = Signal(16)

        words, lasts = [], []
        for i, (name, fields) in enumerate(IFACES):
            nbytes = (len(payloads[i]) + 7) // 8
            nw = (nbytes + 3) // 4
            ws = [Cat(Constant(i, 8), Constant(nbytes, 8), held_t[:16]), held_t[16:48]]
            ws += [held[i][32 * j:min(32 * (j + 1), len(held[i]))] for j in range(nw)]
            words.append(Array(ws))
            lasts.append(len(ws) - 1)
        word = Signal(32)
        last = Signal(4)
        self.comb += Case(idx, {i: [word.eq(words[i][k]), last.eq(lasts[i])] for i in range(7)})
        cur_v = Signal()
        self.comb += cur_v.eq((held_v >> idx)[0])

        snk = rec_fifo.sink
        self.comb += [
            If(mark,
                snk.valid.eq(1), snk.data.eq(Cat(Constant(0xFF, 8), Constant(0, 8), mark_code))
            ).Elif(ser_busy & cur_v,
                snk.valid.eq(1), snk.data.eq(word)),
        ]

        # the frame sequencer
        IDLE, RST, INIT, RUN = 0, 1, 2, 3
        state = Signal(2)
        fe_taken = Signal()  # FRAME_END was taken: the frame is over (the pipeline is drained)
        n_clear = max(w_max * h_max, 3)
        taken = Signal()
        self.comb += [
            clearing.eq(state == RST),
            cmd_valid.eq((state == RUN) & ~fe_taken),
            taken.eq(tick & cmd_valid & cmd_ready),
            en.eq(~soft_rst & ~ser_busy & ~mark & (
                (state == RST) | (state == INIT) | ((state == RUN) & ~fe_taken & head.valid))),
            head.ready.eq(soft_rst | taken |
                          ((state == IDLE) & ~ser_busy & ~mark & head.valid & (op != OP_FRAME))),
        ]
        ticks = Signal(32)
        self.specials += MultiReg(ticks, self.ticks.status, "sys")
        self.sync.ef += [
            If(tick, ticks.eq(ticks + 1)),
            If(soft_rst,
                state.eq(IDLE), ser_busy.eq(0), mark.eq(0), held_v.eq(0), idx.eq(0), k.eq(0),
                dut_rst.eq(1), ticks.eq(0)
            ).Else(
                # the marker and the serialiser write the record FIFO
                If(mark & snk.ready, mark.eq(0)),
                If(ser_busy & ~mark,
                    If(~cur_v,
                        k.eq(0), idx.eq(idx + 1),
                        If(idx == 6, ser_busy.eq(0), idx.eq(0))
                    ).Elif(snk.ready,
                        If(k == last,
                            k.eq(0), idx.eq(idx + 1),
                            If(idx == 6, ser_busy.eq(0), idx.eq(0))
                        ).Else(k.eq(k + 1)))),
                Case(state, {
                    IDLE: [
                        If(~ser_busy & ~mark & head.valid,
                            If(op == OP_FRAME,
                                state.eq(RST), clr.eq(0), dut_rst.eq(1)
                            ).Elif(op == OP_FLUSH,
                                mark.eq(1), mark_code.eq(0)
                            ).Else(
                                mark.eq(1), mark_code.eq(2)))
                    ],
                    RST: [
                        If(tick,
                            clr.eq(clr + 1),
                            If(clr == n_clear - 1, state.eq(INIT), dut_rst.eq(0)))
                    ],
                    INIT: [
                        If(tick & init_done, state.eq(RUN), t.eq(0), fe_taken.eq(0))
                    ],
                    RUN: [
                        If(tick,
                            t.eq(t + 1),
                            If(taken & (op == OP_FRAME_END), fe_taken.eq(1)),
                            If(Cat(*valids) != 0,
                                held_v.eq(Cat(*valids)), held_t.eq(t), ser_busy.eq(1), idx.eq(0), k.eq(0),
                                *[held[i].eq(payloads[i]) for i in range(7)]),
                            If(err, mark.eq(1), mark_code.eq(1), state.eq(IDLE), dut_rst.eq(1))),
                        # the FRAME_END's cycle captured and serialised: the frame is over
                        If(fe_taken & ~ser_busy, state.eq(IDLE))
                    ],
                })
            )
        ]
