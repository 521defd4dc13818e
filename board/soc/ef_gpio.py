"""The GPIO bus of docs/board-gpio.md as a LiteX peripheral: the board's side of the bus in gateware.

The host owns the bus clock.  All twelve host lines are synchronised into sys with two flip-flops
(MultiReg); the rising edge of the synchronised `clk` is the bus edge, at which the synchronised
`d`, `valid`, `take` and `ctl` are sampled (they were stable S host steps before it and stay H
after, so they are stable in the synchronisers too).  At each edge (section 9 of the document):

- `ctl` changed: CONTROL when `take`, or `valid` with `ctl` = 0; the reply is dropped; with `ctl`
  and `valid` a request starts.
- control view: `take` consumes a reply byte (UNDERRUN past its end); `valid` starts a request.
- stream view: `take` pops the output FIFO (UNDERRUN when `avail` was low); `valid` pushes `d` into
  the input FIFO (OVERRUN when `ready` was low: the byte is dropped).

`ready`, `avail`, `q`, `done` and `err` are registers, updated every sys cycle from the FIFOs' flags:
a flag falls only at an edge (the push that filled the last place, the pop of the last byte), so
the pins fall only in response to an edge, as section 4.2 requires.

The firmware (board/firmware/link_gpio.c) moves the stream: `rx` / `rx_pop` drain the input FIFO
into the engine, `tx` fills the output FIFO.  A request (IDENTIFY 1, STATUS 2, BUS_STATUS 4) is
shown in `status` with a tag; the firmware writes `reply_begin`, the reply's bytes into `reply`,
then the tag into `reply_end`: the reply is shown (`avail` in the control view) only if no other
request, and no leaving of the control view, came in between (the tag still matches), so a reply
never mixes two requests.  RESET (3) clears the FIFOs, the error cause and the counters at its edge
and holds `ready` and `avail` low (and drops the firmware's `tx` writes) until the firmware has
reset the engine and written `reset_ack`, so no byte of the old run crosses the reset either way.
`engine` tells the gateware the engine's state (bit 0 done, bit 1 failed: `done`, and `err` with
cause ENGINE).  An unknown request code latches CONTROL here; the firmware never sees it.
"""

from migen import *
from migen.genlib.cdc import MultiReg

from litex.gen import LiteXModule
from litex.soc.interconnect import stream
from litex.soc.interconnect.csr import CSR, CSRStatus

REQ_IDENTIFY, REQ_STATUS, REQ_RESET, REQ_BUS_STATUS = 1, 2, 3, 4
ERR_OVERRUN, ERR_UNDERRUN, ERR_CONTROL = 1, 2, 3

# The bus's pins: what the host drives (inputs here) and what the board drives.
HOST_SIGNALS = [("d", 8), ("clk", 1), ("valid", 1), ("take", 1), ("ctl", 1)]
BOARD_SIGNALS = [("q", 8), ("ready", 1), ("avail", 1), ("done", 1), ("err", 1)]


class EFGpioBus(LiteXModule):
    def __init__(self, pads, rx_depth=256, tx_depth=256, reply_depth=64):
        # CSRs (sys domain)
        self.rx = CSRStatus(9, description="bit 8: a host byte is there; bits 7:0 the byte")
        self.rx_pop = CSR()  # write: consumes the byte `rx` shows
        self.tx = CSR(8)  # write: a byte for the host (dropped if `status` bit 1 is 0)
        self.status = CSRStatus(20, description="bit 0: rx byte there; bit 1: tx FIFO has room; bit 2: a request "
                                                "waits for its reply; bit 3: a reset waits for reset_ack; "
                                                "bits 15:8: the request code; bits 19:16: its tag")
        self.reply_begin = CSR()  # write: empties the reply buffer
        self.reply = CSR(8)  # write: appends a reply byte
        self.reply_end = CSR(4)  # write the request's tag: the reply is complete
        self.reset_ack = CSR()  # write: the engine has reset; the stream resumes
        self.engine = CSR(2)  # write: bit 0 the engine's run is done, bit 1 the engine failed
        # (ignored while a reset waits for reset_ack; cleared by RESET)
        self.cause = CSRStatus(8, description="the latched bus error cause (0: none)")
        self.rx_count = CSRStatus(32, description="stream bytes accepted from the host since reset")
        self.tx_count = CSRStatus(32, description="stream bytes taken by the host since reset")

        # # #

        # the host's lines, two flip-flops each
        s = {}
        for name, w in HOST_SIGNALS:
            s[name] = Signal(w, name="gb_" + name)
            self.specials += MultiReg(getattr(pads, name), s[name])
        clk_prev = Signal()
        edge = Signal()
        self.sync += clk_prev.eq(s["clk"])
        self.comb += edge.eq(s["clk"] & ~clk_prev)

        rx_fifo = ResetInserter()(stream.SyncFIFO([("data", 8)], rx_depth, buffered=True))
        tx_fifo = ResetInserter()(stream.SyncFIFO([("data", 8)], tx_depth, buffered=True))
        rp_fifo = ResetInserter()(stream.SyncFIFO([("data", 8)], reply_depth, buffered=True))
        self.submodules += rx_fifo, tx_fifo, rp_fifo

        ctl_mode = Signal()    # ctl as sampled at the last edge
        cause = Signal(8)
        rst_pending = Signal()
        req_pending = Signal()
        req_code = Signal(8)
        tag = Signal(4)
        reply_shown = Signal()  # the reply is complete: avail in the control view
        engine_done, engine_failed = Signal(), Signal()
        rx_count, tx_count = Signal(32), Signal(32)

        # what the pins show now (registered below)
        ready_now, avail_now, q_now = Signal(), Signal(), Signal(8)
        self.comb += [
            If(ctl_mode,
                ready_now.eq(1),
                avail_now.eq(reply_shown & rp_fifo.source.valid),
                q_now.eq(rp_fifo.source.data)
            ).Else(
                ready_now.eq(rx_fifo.sink.ready & ~rst_pending),
                avail_now.eq(tx_fifo.source.valid & ~rst_pending),
                q_now.eq(tx_fifo.source.data)),
        ]
        for name, sig in [("q", q_now), ("ready", ready_now), ("avail", avail_now),
                          ("done", engine_done), ("err", (cause != 0) | engine_failed)]:
            self.sync += getattr(pads, name).eq(sig)

        d, valid, take, ctl = s["d"], s["valid"], s["take"], s["ctl"]
        ctl_change = Signal()
        self.comb += ctl_change.eq(edge & (ctl != ctl_mode))
        start_req = Signal()   # a request code is sampled at this edge
        drop_reply = Signal()
        edge_drop = Signal()   # an edge that drops the reply and any request waiting for one
        stream_edge = Signal()
        self.comb += [
            start_req.eq(edge & ctl & valid),
            edge_drop.eq(ctl_change | start_req),
            drop_reply.eq(edge_drop | self.reply_begin.re),
            stream_edge.eq(edge & ~ctl & ~ctl_change),
        ]
        is_reset = Signal()
        self.comb += is_reset.eq(start_req & (d == REQ_RESET))

        # the FIFOs: host bytes in, board bytes out, the reply
        self.comb += [
            rx_fifo.reset.eq(is_reset | self.reset_ack.re),
            tx_fifo.reset.eq(is_reset | self.reset_ack.re),
            rp_fifo.reset.eq(drop_reply),
            rx_fifo.sink.valid.eq(stream_edge & valid & ready_now),
            rx_fifo.sink.data.eq(d),
            rx_fifo.source.ready.eq(self.rx_pop.re),
            tx_fifo.sink.valid.eq(self.tx.re & ~rst_pending),
            tx_fifo.sink.data.eq(self.tx.r),
            tx_fifo.source.ready.eq(stream_edge & take & avail_now),
            rp_fifo.sink.valid.eq(self.reply.re),
            rp_fifo.sink.data.eq(self.reply.r),
            rp_fifo.source.ready.eq(edge & ctl & ~ctl_change & take & avail_now),
        ]

        # the bus's state at each edge
        first = Signal(8)   # the cause to latch at this edge (0: none)
        self.comb += [
            If(ctl_change,
                If(take | (valid & ~ctl), first.eq(ERR_CONTROL))
            ).Elif(edge & ctl,
                If(take & ~avail_now, first.eq(ERR_UNDERRUN))
            ).Elif(edge,
                If(take & ~avail_now, first.eq(ERR_UNDERRUN)
                ).Elif(valid & ~ready_now, first.eq(ERR_OVERRUN))),
            If(start_req & (d != REQ_IDENTIFY) & (d != REQ_STATUS) & (d != REQ_RESET) & (d != REQ_BUS_STATUS),
                first.eq(ERR_CONTROL)),
        ]
        self.sync += [
            If(edge, ctl_mode.eq(ctl)),
            If(edge_drop, reply_shown.eq(0), req_pending.eq(0), tag.eq(tag + 1)),
            If(start_req & ((d == REQ_IDENTIFY) | (d == REQ_STATUS) | (d == REQ_BUS_STATUS)),
                req_pending.eq(1), req_code.eq(d)),
            If(is_reset,
                rst_pending.eq(1), rx_count.eq(0), tx_count.eq(0), cause.eq(0),
                engine_done.eq(0), engine_failed.eq(0)
            ).Else(
                If(self.engine.re & ~rst_pending, engine_done.eq(self.engine.r[0]), engine_failed.eq(self.engine.r[1])),
                If((cause == 0) & (first != 0), cause.eq(first)),
                If(rx_fifo.sink.valid & rx_fifo.sink.ready, rx_count.eq(rx_count + 1)),
                If(tx_fifo.source.ready & tx_fifo.source.valid, tx_count.eq(tx_count + 1))),
            If(self.reset_ack.re & ~is_reset, rst_pending.eq(0)),
            If(self.reply_end.re & ~edge_drop & req_pending & (self.reply_end.r == tag),
                reply_shown.eq(1), req_pending.eq(0)),
        ]
        self.comb += [
            self.rx.status.eq(Cat(rx_fifo.source.data, rx_fifo.source.valid)),
            self.status.status.eq(Cat(rx_fifo.source.valid, tx_fifo.sink.ready & ~rst_pending, req_pending,
                                      rst_pending, Constant(0, 4), req_code, tag)),
            self.cause.status.eq(cause),
            self.rx_count.status.eq(rx_count),
            self.tx_count.status.eq(tx_count),
        ]
