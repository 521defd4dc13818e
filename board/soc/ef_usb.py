"""The USB device as a LiteX peripheral (docs/board-ulx3s.md, "USB"): the Verilog module
ef_usb_core that board/soc/usb_core.py writes (LUNA's device core), its byte streams carried
across clock domains by asynchronous FIFOs, and the CSRs the firmware uses
(board/firmware/link_usb.c):

    ctrl      bit 0: connect (the D+ pull-up: the board appears on the bus)
    status    bit 0: a bulk OUT byte is there (out_data); bit 1: the IN FIFO has room;
              bits 4:2: the request toggles (ctl_req: STATUS, RESET, a bus reset);
              bit 5: the host set configuration 1
    out_data  the bulk OUT byte at the FIFO's head; writing out_pop takes it
    in_data   write: bits 7:0 a bulk IN byte, bit 8: the burst ends here (short packet or ZLP)
    mb        write: bits 14:8 a mailbox address, 7:0 the byte (IDENTIFY at 0, STATUS at 64)
    ctl_ack   the firmware's toggles: bit k equal to ctl_req's once that request is served

The core runs in the `usb` clock domain (12 MHz; on a ULX3S also `usb_io`, 48 MHz, for LUNA's
gateware PHY on the US2 pins); in the simulation its UTMI side is `utmi`, a set of pads the
Verilated harness drives (board/sim/usb_link.cpp).
"""

from migen import *
from migen.genlib.cdc import MultiReg

from litex.gen import LiteXModule
from litex.soc.interconnect import stream
from litex.soc.interconnect.csr import CSR, CSRStatus, CSRStorage

UTMI_PORTS = [("rx_data", 8, "i"), ("rx_valid", 1, "i"), ("rx_active", 1, "i"), ("rx_error", 1, "i"),
              ("tx_data", 8, "o"), ("tx_valid", 1, "o"), ("tx_ready", 1, "i"), ("line_state", 2, "i"),
              ("term_select", 1, "o"), ("op_mode", 2, "o"), ("xcvr_select", 2, "o")]


class EFUSB(LiteXModule):
    def __init__(self, utmi=None, pads=None, fifo_depth=128):
        self.ctrl = CSRStorage(1, description="bit 0: connect")
        self.status = CSRStatus(6)
        self.out_data = CSRStatus(8)
        self.out_pop = CSR()
        self.in_data = CSR(9)
        self.mb = CSR(15)
        self.ctl_ack = CSRStorage(3)

        # # #

        out_fifo = ClockDomainsRenamer({"write": "usb", "read": "sys"})(stream.AsyncFIFO([("data", 8)], fifo_depth))
        in_fifo = ClockDomainsRenamer({"write": "sys", "read": "usb"})(
            stream.AsyncFIFO([("data", 9)], fifo_depth))  # bit 8: the burst's last byte
        self.out_fifo, self.in_fifo = out_fifo, in_fifo
        connect = Signal()
        self.specials += MultiReg(self.ctrl.storage[0], connect, "usb")
        ctl_req, configured_u, configured = Signal(3), Signal(), Signal()
        self.specials += MultiReg(configured_u, configured, "sys")
        ios = dict(
            i_usb_clk=ClockSignal("usb"), i_usb_rst=ResetSignal("usb"),
            i_sys_clk=ClockSignal("sys"), i_sys_rst=ResetSignal("sys"),
            i_connect=connect, o_configured=configured_u,
            o_out_data=out_fifo.sink.data, o_out_valid=out_fifo.sink.valid, i_out_ready=out_fifo.sink.ready,
            i_in_data=in_fifo.source.data[0:8], i_in_last=in_fifo.source.data[8], i_in_valid=in_fifo.source.valid,
            o_in_ready=in_fifo.source.ready,
            i_mb_we=self.mb.re, i_mb_addr=self.mb.r[8:15], i_mb_data=self.mb.r[0:8],
            o_ctl_req=ctl_req, i_ctl_ack=self.ctl_ack.storage,
        )
        if utmi is not None:
            for name, _, d in UTMI_PORTS:
                ios[("i_" if d == "i" else "o_") + name] = getattr(utmi, name)
        else:
            ios["i_usb_io_clk"] = ClockSignal("usb_io")
            ios["i_usb_io_rst"] = ResetSignal("usb_io")
            dp, dn = TSTriple(), TSTriple()
            self.specials += dp.get_tristate(pads.d_p), dn.get_tristate(pads.d_n)
            pullup = Signal()
            ios.update(i_usb_d_p_i=dp.i, o_usb_d_p_o=dp.o, o_usb_d_p_oe=dp.oe,
                       i_usb_d_n_i=dn.i, o_usb_d_n_o=dn.o, o_usb_d_n_oe=dn.oe, o_usb_pullup_o=pullup)
            # US2's pull-ups: B12 on D+ (a full-speed device), C12 on D- (left off)
            self.comb += pads.pullup.eq(Cat(pullup, 0))
        self.specials += Instance("ef_usb_core", **ios)
        self.comb += [
            self.status.status.eq(Cat(out_fifo.source.valid, in_fifo.sink.ready, ctl_req, configured)),
            self.out_data.status.eq(out_fifo.source.data),
            out_fifo.source.ready.eq(self.out_pop.re),
            in_fifo.sink.valid.eq(self.in_data.re),
            in_fifo.sink.data.eq(self.in_data.r),
        ]
