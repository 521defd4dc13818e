#!/usr/bin/env python3
"""The board's USB device (docs/board-usb.md, docs/board-ulx3s.md "USB"): LUNA's
full-speed device core (luna-usb, PyPI) with the descriptors, endpoints and
vendor requests of docs/board-usb.md, written out as Verilog by Amaranth for
the LiteX SoC (board/soc/soc.py).  The Verilog is a build output, never
committed.

    usb_core.py --out FILE.v [--phy utmi|gateware] [--vid-pid VVVV:PPPP]
                [--descriptors FILE]

--phy gateware: LUNA's gateware full-speed PHY on raw D+/D- pins (the ULX3S's
US2 port), clock domains `usb` (12 MHz) and `usb_io` (48 MHz, phase related).
--phy utmi: the core's UTMI side is the module's ports (the simulation drives
it with whole packets a byte at a time: board/sim/usb_link.cpp); the PHY's
line coding is not simulated.

The module `ef_usb_core`:
  usb domain:  the bulk OUT 0x01 byte stream (out_data/out_valid/out_ready),
               the bulk IN 0x81 byte stream (in_data/in_last/in_valid/in_ready:
               `last` ends the burst with a short packet or a zero-length
               packet, docs/board-usb.md section 4), `connect` (pull-up).
  sys domain:  the request mailbox: mb_we/mb_addr/mb_data write IDENTIFY's 48
               bytes at 0..47 and STATUS's 40 at 64..103; ctl_req, one toggle
               per kind of request that needs the firmware (bit 0 STATUS, bit 1
               RESET, bit 2 a USB bus reset: the connection ended, the firmware
               drops half frames, ef_board_link_lost), pending while it differs
               from the firmware's ctl_ack bit; a kind is asked again only once
               served, so two requests never cancel out.  STATUS's data stage
               and RESET's status stage are NAKed until served.  IDENTIFY and
               the serial string are answered from the mailbox at once.  While
               a RESET or a bus reset waits, every byte of the IN path is
               dropped (docs/board-usb.md 3.3); a bus reset also resets the
               bulk endpoints (their buffers, data toggles DATA0), a RESET
               keeps the toggles.
"""

import argparse
import os

from amaranth import Cat, ClockDomain, Const, Elaboratable, Module, Mux, ResetInserter, Signal
from amaranth.back import verilog
from amaranth.lib.cdc import FFSynchronizer
from luna.gateware.interface.utmi import UTMIInterface
from luna.gateware.stream.generator import StreamSerializer
from luna.gateware.usb.stream import USBInStreamInterface
from luna.gateware.usb.usb2.device import USBDevice
from luna.gateware.usb.usb2.endpoints.stream import USBStreamInEndpoint, USBStreamOutEndpoint
from luna.gateware.usb.usb2.request import USBRequestHandler
from usb_protocol.emitters import DeviceDescriptorCollection
from usb_protocol.types import USBRequestRecipient, USBRequestType

MPS = 64  # full speed: bulk and control packets of 64 bytes
IDENTIFY, RESET, STATUS = 0x01, 0x02, 0x03
IDENTIFY_LEN, STATUS_LEN = 48, 40
MB_STATUS = 64  # the mailbox address of STATUS's first byte
SERIAL_AT = 32  # identify's serial field
SERIAL_INDEX = 3  # iSerialNumber
SERIAL_PLACEHOLDER = "(from identify)"  # never sent: the string comes from the mailbox


def serial_request(setup):
    """GET_DESCRIPTOR(string iSerialNumber, any language): served from the mailbox."""
    return ((setup.type == USBRequestType.STANDARD) & (setup.recipient == USBRequestRecipient.DEVICE) &
            setup.is_in_request & (setup.request == 6) & (setup.value == (3 << 8 | SERIAL_INDEX)))


def descriptors(vid, pid):
    """docs/board-usb.md section 2, at full speed (64-byte packets)."""
    d = DeviceDescriptorCollection()
    with d.DeviceDescriptor() as dev:
        dev.bcdUSB = 2.0
        dev.bMaxPacketSize0 = MPS
        dev.idVendor, dev.idProduct = vid, pid
        dev.bcdDevice = 1.0
        dev.iManufacturer = "edgeflag"
        dev.iProduct = "edgeflag board (ULX3S)"
        dev.iSerialNumber = SERIAL_PLACEHOLDER  # index 3; served from identify's serial (VendorRequests)
        dev.bNumConfigurations = 1
    with d.ConfigurationDescriptor() as c:
        c.bConfigurationValue = 1
        c.bmAttributes = 0x80
        c.bMaxPower = 250  # 500 mA: the board can be powered from US2 alone
        with c.InterfaceDescriptor() as i:
            i.bInterfaceNumber = 0
            i.bAlternateSetting = 0
            i.bInterfaceClass, i.bInterfaceSubclass, i.bInterfaceProtocol = 0xFF, 0, 0
            for addr in (0x01, 0x81):
                with i.EndpointDescriptor() as e:
                    e.bEndpointAddress = addr
                    e.bmAttributes = 2
                    e.wMaxPacketSize = MPS
                    e.bInterval = 0
    return d


class VendorRequests(USBRequestHandler):
    """IDENTIFY, STATUS and RESET (docs/board-usb.md section 3) from the mailbox."""

    def __init__(self):
        super().__init__()
        self.ident = [Signal(8, name=f"ident_{i}") for i in range(IDENTIFY_LEN)]
        self.status = [Signal(8, name=f"status_{i}") for i in range(STATUS_LEN)]
        # one toggle per kind of request that needs the firmware (bit 0 STATUS, 1 RESET, 2 a bus
        # reset), flipped only when the last one of its kind was served, and the firmware's
        # acknowledging toggles (synchronised): kind k is pending while req[k] != ack[k]
        self.req = Signal(3)
        self.ack = Signal(3)
        self.resetting = Signal()  # a RESET or a bus reset waits for the firmware
        self.bus_reset = Signal()  # in: a USB bus reset (plug-in, re-enumeration)

    def elaborate(self, platform):
        m = Module()
        itf = self.interface
        setup = itf.setup
        m.submodules.ser = ser = StreamSerializer(data_length=IDENTIFY_LEN, domain="usb",
                                                  stream_type=USBInStreamInterface, max_length_width=7)
        # the serial number string descriptor, made from identify's serial field (NUL-padded
        # ASCII): equal to identify's by construction, and set by the firmware, not the gateware
        serial = self.ident[SERIAL_AT:SERIAL_AT + 16]
        n = Signal(range(17))
        m.d.comb += n.eq(16)
        for k in reversed(range(16)):
            with m.If(serial[k] == 0):
                m.d.comb += n.eq(k)
        desc = [Cat(n, Const(0, 3)) * 2 + 2, Const(3, 8)]
        for k in range(16):
            desc += [serial[k], Const(0, 8)]
        sel = Signal(2)  # 0 identify, 1 status, 2 the serial string
        for i in range(IDENTIFY_LEN):
            m.d.comb += ser.data[i].eq(Mux(sel == 1, self.status[i] if i < STATUS_LEN else 0,
                                           Mux(sel == 2, desc[i] if i < len(desc) else 0, self.ident[i])))
        full = Signal(7)
        m.d.comb += full.eq(Mux(sel == 1, STATUS_LEN, Mux(sel == 2, n * 2 + 2, IDENTIFY_LEN)))
        m.d.comb += ser.max_length.eq(Mux(setup.length < full, setup.length, full))
        served = [Signal(name=f"served_{k}") for k in range(3)]
        for k in range(3):
            m.d.comb += served[k].eq(self.ack[k] == self.req[k])

        def ask(k):  # a request of kind k: pending (again only when the last one was served)
            return self.req[k].eq(self.req[k] ^ served[k])
        vendor = (setup.type == USBRequestType.VENDOR) & (setup.recipient == USBRequestRecipient.DEVICE)
        serial_desc = serial_request(setup)
        with m.If(vendor | serial_desc):
            m.d.comb += itf.claim.eq(1)
        def dispatch():
            # every SETUP starts over, whatever state the last request was left in
            with m.If(setup.received):
                m.next = "IDLE"
                with m.If(serial_desc & (setup.length != 0)):
                    m.d.usb += sel.eq(2)
                    m.next = "DATA"
                with m.If(vendor):
                    with m.If((setup.request == IDENTIFY) & setup.is_in_request & (setup.length != 0)):
                        m.d.usb += sel.eq(0)
                        m.next = "DATA"
                    with m.Elif((setup.request == STATUS) & setup.is_in_request & (setup.length != 0)):
                        m.d.usb += [sel.eq(1), ask(0)]
                        m.next = "DATA"
                    with m.Elif((setup.request == RESET) & ~setup.is_in_request & (setup.length == 0)):
                        m.d.usb += ask(1)
                        m.next = "RESET"
                    with m.Else():
                        m.next = "UNHANDLED"

        # a bus reset: the firmware drops the half frames and unsent bytes of the connection that
        # ended; until it has, the IN path is emptied
        with m.If(self.bus_reset):
            m.d.usb += ask(2)
        with m.If(~served[2]):
            m.d.comb += self.resetting.eq(1)
        # the data stage: at once, but STATUS's when the firmware has put it in the mailbox
        ready = Signal()
        m.d.comb += ready.eq((sel != 1) | served[0])

        with m.FSM(domain="usb"):
            with m.State("IDLE"):
                m.d.usb += itf.tx_data_pid.eq(1)
                dispatch()
            with m.State("DATA"):
                m.d.comb += ser.stream.attach(itf.tx)
                with m.If(itf.data_requested):
                    with m.If(ready):
                        m.d.comb += ser.start.eq(1)
                    with m.Else():
                        m.d.comb += itf.handshakes_out.nak.eq(1)
                with m.If(itf.status_requested):
                    m.d.comb += itf.handshakes_out.ack.eq(1)
                    m.next = "IDLE"
                dispatch()
            with m.State("RESET"):
                with m.If(~served[1]):
                    m.d.comb += self.resetting.eq(1)
                with m.If(itf.status_requested):
                    with m.If(served[1]):
                        m.d.comb += self.send_zlp()
                    with m.Else():
                        m.d.comb += itf.handshakes_out.nak.eq(1)
                with m.If(itf.handshakes_in.ack & served[1]):
                    m.next = "IDLE"
                dispatch()
            with m.State("UNHANDLED"):
                with m.If(itf.data_requested | itf.status_requested):
                    m.d.comb += itf.handshakes_out.stall.eq(1)
                    m.next = "IDLE"
                dispatch()
        return m


class _Pins:
    """Raw D+/D-/pull-up as the module's ports, in the shape GatewarePHY reads."""

    class _Pad:
        def __init__(self, name, direction):
            if "i" in direction:
                self.i = Signal(name=name + "_i")
            if "o" in direction:
                self.o = Signal(name=name + "_o")
                self.oe = Signal(name=name + "_oe")

    def __init__(self):
        self.d_p = self._Pad("usb_d_p", "io")
        self.d_n = self._Pad("usb_d_n", "io")
        self.pullup = self._Pad("usb_pullup", "o")

    def ports(self):
        return [self.d_p.i, self.d_p.o, self.d_p.oe, self.d_n.i, self.d_n.o, self.d_n.oe, self.pullup.o]


class EFUSBCore(Elaboratable):
    def __init__(self, phy, vid, pid):
        self.phy, self.vid, self.pid = phy, vid, pid
        if phy == "utmi":
            self.utmi = UTMIInterface()
        else:
            self.pins = _Pins()

        def sig(name, width=1):
            return Signal(width, name=name)
        # usb domain
        self.connect = sig("connect")
        self.out_data, self.out_valid, self.out_ready = sig("out_data", 8), sig("out_valid"), sig("out_ready")
        self.in_data, self.in_last = sig("in_data", 8), sig("in_last")
        self.in_valid, self.in_ready = sig("in_valid"), sig("in_ready")
        self.configured = sig("configured")
        # sys domain
        self.mb_we, self.mb_addr, self.mb_data = sig("mb_we"), sig("mb_addr", 7), sig("mb_data", 8)
        self.ctl_req, self.ctl_ack = sig("ctl_req", 3), sig("ctl_ack", 3)
        self.cd_usb, self.cd_sys = ClockDomain("usb"), ClockDomain("sys")
        self.cd_usb_io = ClockDomain("usb_io") if phy != "utmi" else None

    def ports(self):
        p = [self.cd_usb.clk, self.cd_usb.rst, self.cd_sys.clk, self.cd_sys.rst, self.connect, self.out_data, self.out_valid, self.out_ready, self.in_data, self.in_last,
             self.in_valid, self.in_ready, self.configured, self.mb_we, self.mb_addr, self.mb_data,
             self.ctl_req, self.ctl_ack]
        if self.phy == "utmi":
            u = self.utmi
            p += [u.rx_data, u.rx_valid, u.rx_active, u.rx_error, u.tx_data, u.tx_valid, u.tx_ready,
                  u.line_state, u.term_select, u.op_mode, u.xcvr_select]
        else:
            p += self.pins.ports() + [self.cd_usb_io.clk, self.cd_usb_io.rst]
        return p

    def elaborate(self, platform):
        m = Module()
        m.domains += [self.cd_usb, self.cd_sys]
        if self.cd_usb_io is not None:
            m.domains += self.cd_usb_io
        bus = self.utmi if self.phy == "utmi" else self.pins
        m.submodules.dev = dev = USBDevice(bus=bus, handle_clocking=False)
        d = descriptors(self.vid, self.pid)
        assert d.get_index_for_string(SERIAL_PLACEHOLDER) == SERIAL_INDEX
        ctrl = dev.add_standard_control_endpoint(d, skiplist=[serial_request])
        vendor = VendorRequests()
        ctrl.add_request_handler(vendor)
        # a bus reset also resets the bulk endpoints (their buffers, and the data toggles to DATA0,
        # as a host expects after enumerating the board again)
        ep_out = ResetInserter({"usb": dev.reset_detected})(USBStreamOutEndpoint(endpoint_number=1, max_packet_size=MPS))
        ep_in = ResetInserter({"usb": dev.reset_detected})(USBStreamInEndpoint(endpoint_number=1, max_packet_size=MPS))
        dev.add_endpoint(ep_out)
        dev.add_endpoint(ep_in)
        m.d.comb += [
            dev.connect.eq(self.connect),
            dev.full_speed_only.eq(1),
            vendor.bus_reset.eq(dev.reset_detected),
            self.out_data.eq(ep_out.stream.payload),
            self.out_valid.eq(ep_out.stream.valid),
            ep_out.stream.ready.eq(self.out_ready),
            # while a RESET waits for the firmware, the IN path is emptied: the endpoint's
            # buffers and every byte the firmware had queued
            ep_in.discard.eq(vendor.resetting),
            ep_in.stream.payload.eq(self.in_data),
            ep_in.stream.last.eq(self.in_last),
            ep_in.stream.valid.eq(self.in_valid & ~vendor.resetting),
            self.in_ready.eq(ep_in.stream.ready | vendor.resetting),
        ]
        if self.phy == "utmi":
            m.d.comb += self.utmi.session_end.eq(0)
        # the mailbox: written by the firmware (sys), read by the request handler (usb) only while
        # the firmware leaves it alone (identify before connect, status before ctl_ack)
        regs = vendor.ident + [Const(0, 8)] * (MB_STATUS - IDENTIFY_LEN) + vendor.status
        with m.If(self.mb_we):
            with m.Switch(self.mb_addr):
                for a, r in enumerate(regs):
                    if isinstance(r, Signal):
                        with m.Case(a):
                            m.d.sys += r.eq(self.mb_data)
        # three independent toggles each way: one synchroniser per bit is enough
        m.submodules.req_sync = FFSynchronizer(vendor.req, self.ctl_req, o_domain="sys")
        m.submodules.ack_sync = FFSynchronizer(self.ctl_ack, vendor.ack, o_domain="usb")
        m.d.comb += self.configured.eq(ctrl.interface.active_config != 0)
        return m


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--phy", choices=["utmi", "gateware"], default="utmi")
    ap.add_argument("--vid-pid", default="1209:0001")
    ap.add_argument("--descriptors", help="also write the descriptors, hex, one per line (type index bytes)")
    a = ap.parse_args()
    vid, pid = (int(x, 16) for x in a.vid_pid.split(":"))
    core = EFUSBCore(a.phy, vid, pid)
    text = verilog.convert(core, name="ef_usb_core", ports=core.ports(), emit_src=False)
    with open(a.out + ".tmp", "w") as f:
        f.write(text)
    os.replace(a.out + ".tmp", a.out)
    if a.descriptors:
        with open(a.descriptors, "w") as f:
            for t, i, raw in descriptors(vid, pid):
                f.write(f"{t} {i} {bytes(raw).hex()}\n")


if __name__ == "__main__":
    main()
