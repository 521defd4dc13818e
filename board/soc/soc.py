#!/usr/bin/env python3
"""The edgeflag board's system-on-chip (docs/board-ulx3s.md).

A VexRiscv (lite: rv32im with small caches) runs the firmware (board/firmware: the board engine
board/ef_board.c) from the integrated ROM; ef_raster is the peripheral of
ef_periph.py on its own clock `ef`; the UART is LiteX's, at 3 Mbaud; the GPIO bus slave of
ef_gpio.py on the header (docs/board-gpio.md; --no-gpio leaves it out); the USB
device of ef_usb.py (LUNA, usb_core.py) on its clocks `usb` (12 MHz) and, on
a ULX3S, `usb_io` (48 MHz), unless --no-usb.

    soc.py --target ulx3s-25f|ulx3s-85f|sim --out DIR [--ns 8|16] [--rom FIRMWARE.bin]
           [--headers-only] [--sys-clk HZ] [--ef-clk HZ] [--no-usb] [--usb-vid-pid V:P]

--headers-only writes the software headers (DIR/software/include/generated:
csr.h, soc.h, mem.h) and stops: the firmware is built against them, then a
second call with --rom puts it in the ROM and writes the gateware (the
Verilog for sim, the bitstream for a ULX3S: yosys, nextpnr-ecp5 and ecppack
on PATH, build/fpga-bin's shims of the yowasp tools).
"""

import argparse
import os
import subprocess
import sys

from migen import *

from litex.build.generic_platform import Pins, Subsignal
from litex.soc.cores.clock import ECP5PLL
from litex.soc.integration.builder import Builder
from litex.soc.integration.common import get_mem_data
from litex.soc.integration.soc_core import SoCCore

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ef_periph import EFRaster  # noqa: E402
from ef_gpio import BOARD_SIGNALS, HOST_SIGNALS, EFGpioBus  # noqa: E402
from ef_usb import UTMI_PORTS, EFUSB  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))

BAUD = 3_000_000

# The canvas the board's frame memory holds (block RAM: W_MAX * H_MAX words).
W_MAX, H_MAX = 64, 64
# Edges per shape (ef_raster's AET ring and ETM's edge memory, block RAM): the tiger at 64x64 has
# shapes of 939 edges.
E_MAX = 1023


class _CRGULX3S(Module):
    """25 MHz in; sys (CPU, UART: a multiple of 3 MHz, so the UART's phase
    accumulator divides exactly) and ef (ef_raster, below its Fmax) out of
    one PLL."""

    def __init__(self, platform, sys_clk, ef_clk):
        self.clock_domains.cd_sys = ClockDomain()
        self.clock_domains.cd_ef = ClockDomain()
        clk25 = platform.request("clk25")
        rst = platform.request("rst")
        self.submodules.pll = pll = ECP5PLL()
        self.comb += pll.reset.eq(rst)
        pll.register_clkin(clk25, 25e6)
        pll.create_clkout(self.cd_sys, sys_clk, margin=0)
        pll.create_clkout(self.cd_ef, ef_clk, margin=0)
        # the USB device's clocks (US2): 12 MHz, and 48 MHz for LUNA's gateware PHY, phase related,
        # from a second PLL (the first has no output left)
        self.clock_domains.cd_usb = ClockDomain()
        self.clock_domains.cd_usb_io = ClockDomain()
        self.submodules.usb_pll = usb_pll = ECP5PLL()
        self.comb += usb_pll.reset.eq(rst)
        usb_pll.register_clkin(clk25, 25e6)
        # 48 MHz is not reachable exactly from 25 MHz within the PLL's PFD and VCO ranges: the
        # nearest is 47.917 MHz (VCO 575 MHz / 12), -0.17 %, inside full speed's +-0.25 %
        usb_pll.create_clkout(self.cd_usb_io, 48e6, margin=2e-3)
        usb_pll.create_clkout(self.cd_usb, 12e6, margin=2e-3)
        # keep the ESP32 from resetting the FPGA (as litex_boards' target does)
        self.comb += platform.request("wifi_gpio0").eq(1)


# The GPIO bus (docs/board-gpio.md, "The ULX3S"): the host's 12 lines on J1 (GP0-GP5, GN0-GN5), the
# board's 12 on J2 (GP18-GP23, GN18-GN23); LVCMOS33 both ways.  Header lines shared with the ESP32
# (GP11-GP13) and the ADC (GP14-GP17) are left alone.
GPIO_PINS = {
    "d": "gp0 gn0 gp1 gn1 gp2 gn2 gp3 gn3", "clk": "gp4", "valid": "gn4", "take": "gp5", "ctl": "gn5",
    "q": "gp18 gn18 gp19 gn19 gp20 gn20 gp21 gn21", "ready": "gp22", "avail": "gn22", "done": "gp23",
    "err": "gn23",
}
# the ECP5 balls of the ULX3S v2/v3 header lines used (the board's constraint file, ulx3s_v20.lpf)
ULX3S_BALLS = {
    "gp0": "B11", "gn0": "C11", "gp1": "A10", "gn1": "A11", "gp2": "A9", "gn2": "B10", "gp3": "B9",
    "gn3": "C10", "gp4": "A7", "gn4": "A8", "gp5": "C8", "gn5": "B8",
    "gp18": "H18", "gn18": "H17", "gp19": "F17", "gn19": "G18", "gp20": "D18", "gn20": "E17", "gp21": "C18",
    "gn21": "D17", "gp22": "B15", "gn22": "C15", "gp23": "B17", "gn23": "C17",
}


def _gpio_ulx3s_io():
    from litex.build.generic_platform import IOStandard, Misc
    subs = []
    for name, _ in HOST_SIGNALS + BOARD_SIGNALS:
        balls = " ".join(ULX3S_BALLS[p] for p in GPIO_PINS[name].split())
        # the host's lines pulled down (an unwired header is an idle bus), the board's driven
        extra = [Misc("PULLMODE=DOWN")] if name in dict(HOST_SIGNALS) else [Misc("DRIVE=4")]
        subs.append(Subsignal(name, Pins(balls), IOStandard("LVCMOS33"), *extra))
    return [("ef_gpio", 0, *subs)]


_sim_io = [
    ("ef_gpio", 0, *[Subsignal(n, Pins(w)) for n, w in HOST_SIGNALS + BOARD_SIGNALS]),
    ("sys_clk", 0, Pins(1)),
    ("ef_clk", 0, Pins(1)),
    ("sys_rst", 0, Pins(1)),
    ("serial", 0,
        Subsignal("source_valid", Pins(1)),
        Subsignal("source_ready", Pins(1)),
        Subsignal("source_data", Pins(8)),
        Subsignal("sink_valid", Pins(1)),
        Subsignal("sink_ready", Pins(1)),
        Subsignal("sink_data", Pins(8))),
    # the USB device's clock (12 MHz) and its core's UTMI side (board/sim/usb_link.cpp drives it)
    ("usb_clk", 0, Pins(1)),
    ("utmi", 0, *[Subsignal(n, Pins(w)) for n, w, _ in UTMI_PORTS]),
]


class _CRGSim(Module):
    def __init__(self, platform):
        self.clock_domains.cd_sys = ClockDomain()
        self.clock_domains.cd_ef = ClockDomain()
        self.clock_domains.cd_usb = ClockDomain()
        rst = platform.request("sys_rst")
        self.comb += [
            self.cd_sys.clk.eq(platform.request("sys_clk")), self.cd_sys.rst.eq(rst),
            self.cd_ef.clk.eq(platform.request("ef_clk")), self.cd_ef.rst.eq(rst),
            self.cd_usb.clk.eq(platform.request("usb_clk")), self.cd_usb.rst.eq(rst),
        ]


class EdgeflagSoC(SoCCore):
    def __init__(self, target, ns, rom_init, sys_clk, ef_clk, main_ram, cpu_variant="lite", e_max=E_MAX,
                 gpio=True, usb_core=None, schedule=0):
        if target == "sim":
            from litex.build.sim import SimPlatform
            platform = SimPlatform("SIM", _sim_io)
            crg = _CRGSim(platform)
            uart = "sim"
        else:
            from litex_boards.platforms import radiona_ulx3s
            device = {"ulx3s-25f": "LFE5U-25F", "ulx3s-85f": "LFE5U-85F"}[target]
            platform = radiona_ulx3s.Platform(device=device, revision="2.0", toolchain="trellis")
            crg = _CRGULX3S(platform, sys_clk, ef_clk)
            uart = "serial"
        for v in ["ef_aet", "ef_cov", "ef_dec", "ef_div", "ef_etm", "ef_plot", "ef_raster", "ef_setup",
                  "ef_slb_fill", "ef_slb_ram"] + (["ef_spanq"] if schedule else []):
            platform.add_source(os.path.join(ROOT, "rtl", v + ".v"))
        # rtl/'s modules include ef_ifaces.vh and ef_ns.vh (docs/vectors.md section 8)
        platform.add_verilog_include_path(os.path.join(ROOT, "rtl"))
        platform.add_source(os.path.join(HERE, "ef_gate_sim.v" if target == "sim" else "ef_gate_ecp5.v"))
        SoCCore.__init__(self, platform, sys_clk,
                         ident="edgeflag board", ident_version=False,
                         cpu_type="vexriscv", cpu_variant=cpu_variant,
                         integrated_rom_size=0x4000, integrated_rom_init=rom_init,
                         integrated_sram_size=0x2000,
                         integrated_main_ram_size=main_ram,
                         uart_name=uart, uart_baudrate=BAUD, uart_fifo_depth=64,
                         with_timer=True, with_ctrl=False)
        self.submodules.crg = crg
        if gpio:
            # the GPIO bus slave (board/soc/ef_gpio.py); the firmware's link_gpio.c drives it
            if target != "sim":
                platform.add_extension(_gpio_ulx3s_io())
            self.gpiobus = EFGpioBus(platform.request("ef_gpio"))
        self.ef = EFRaster(ns=ns, w_max=W_MAX, h_max=H_MAX, e_max=e_max, schedule=schedule)
        if usb_core:
            # the USB device of docs/board-usb.md (board/soc/ef_usb.py), its core's Verilog written
            # by board/soc/usb_core.py (LUNA, Amaranth) at build time
            platform.add_source(usb_core)
            if target == "sim":
                self.usb = EFUSB(utmi=platform.request("utmi"))
            else:
                self.usb = EFUSB(pads=platform.request("usb"))
        for name, value in [("EF_NS", ns), ("EF_W_MAX", W_MAX), ("EF_H_MAX", H_MAX), ("EF_E_MAX", e_max),
                            ("EF_SCHEDULE", schedule), ("EF_SYS_CLK", int(sys_clk)), ("EF_EF_CLK", int(ef_clk)), ("EF_BAUD", BAUD)]:
            self.add_constant(name, value)
        if target != "sim" and not main_ram:
            # the heap (the engine's receive buffer and its results) in the 32 MB SDRAM
            from litedram.modules import MT48LC16M16
            from litedram.phy import GENSDRPHY
            from litex.build.io import DDROutput
            self.crg.clock_domains.cd_sys_ps = ClockDomain()
            self.crg.pll.create_clkout(self.crg.cd_sys_ps, sys_clk, phase=90, margin=0)
            self.specials += DDROutput(1, 0, platform.request("sdram_clock"), ClockSignal("sys_ps"))
            self.sdrphy = GENSDRPHY(platform.request("sdram"), sys_clk)
            self.add_sdram("sdram", phy=self.sdrphy, module=MT48LC16M16(sys_clk, "1:1"),
                           size=0x2000000, l2_cache_size=2048)
        if target != "sim":
            self.platform.add_period_constraint(crg.cd_ef.clk, 1e9 / ef_clk)
            self.platform.add_period_constraint(crg.cd_sys.clk, 1e9 / sys_clk)
            if usb_core:
                self.platform.add_period_constraint(crg.cd_usb.clk, 1e9 / 12e6)
                self.platform.add_period_constraint(crg.cd_usb_io.clk, 1e9 / 48e6)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--target", required=True, choices=["ulx3s-25f", "ulx3s-85f", "sim"])
    ap.add_argument("--out", required=True)
    ap.add_argument("--ns", type=int, default=8, choices=[8, 16, 32])
    ap.add_argument("--rom", help="firmware image for the ROM")
    ap.add_argument("--headers-only", action="store_true")
    ap.add_argument("--sys-clk", type=float, default=None,
                    help="sys clock (a multiple of 3 MHz): default 30 MHz on a ULX3S (the 60 MHz placement "
                         "reached 44.68 MHz, docs/board-ulx3s.md), 60 MHz in the simulation (its USB clock is a "
                         "fifth of it; --sys-clk 30e6 and board_sim --sys-clk 30e6 simulate the board's clocks)")
    ap.add_argument("--ef-clk", type=float, default=15e6)
    ap.add_argument("--main-ram", type=lambda s: int(s, 0), default=None,
                    help="block RAM main RAM bytes (sim default 4 MiB; the board: 0, the heap in SRAM)")
    ap.add_argument("--cpu-variant", default="lite", choices=["minimal", "lite"],
                    help="VexRiscv variant: lite (rv32im, 2 KiB instruction and data caches: the default) or minimal (rv32i)")
    ap.add_argument("--e-max", type=int, default=E_MAX, help="ef_raster's E_MAX (edges per shape)")
    ap.add_argument("--seed", type=int, default=1, help="nextpnr's placement seed")
    ap.add_argument("--no-gpio", action="store_true", help="leave the GPIO bus slave out (docs/board-gpio.md)")
    ap.add_argument("--no-usb", action="store_true",
                    help="without the USB device (docs/board-ulx3s.md: utilisation with and without it)")
    ap.add_argument("--schedule", default="reference", choices=["reference", "overlap"],
                    help="ef_raster's SCHEDULE: reference (0) or overlap (1, the fast configuration of "
                         "docs/microarch.md section 6; the host then needs vectors made with --schedule overlap)")
    ap.add_argument("--usb-vid-pid", default="1209:0001", help="the USB device's VID:PID (docs/board-usb.md)")
    a = ap.parse_args()
    if a.sys_clk is None:
        a.sys_clk = 60e6 if a.target == "sim" else 30e6
    if a.sys_clk % 3e6:
        sys.exit("soc.py: --sys-clk must be a multiple of 3 MHz (the UART's 3 Mbaud divides it exactly)")
    rom = get_mem_data(a.rom, endianness="little") if a.rom else []
    main_ram = a.main_ram if a.main_ram is not None else (0x400000 if a.target == "sim" else 0)
    usb_core = None
    if not a.no_usb:
        # LUNA's device as Verilog (a build output): Amaranth runs Yosys, the packaged one of
        # tools/install-fpga.sh (build/fpga-bin)
        usb_core = os.path.abspath(os.path.join(a.out, "gateware", "ef_usb_core.v"))
        os.makedirs(os.path.dirname(usb_core), exist_ok=True)
    if usb_core and not a.headers_only:  # the headers need only its CSRs
        env = dict(os.environ, PATH=os.path.join(ROOT, "build", "fpga-bin") + os.pathsep + os.environ["PATH"])
        subprocess.run([sys.executable, os.path.join(HERE, "usb_core.py"), "--out", usb_core,
                        "--phy", "utmi" if a.target == "sim" else "gateware", "--vid-pid", a.usb_vid_pid],
                       check=True, env=env)
    soc = EdgeflagSoC(a.target, a.ns, rom, a.sys_clk, a.ef_clk, main_ram, a.cpu_variant, a.e_max,
                      gpio=not a.no_gpio, usb_core=usb_core, schedule=int(a.schedule == "overlap"))
    if a.target == "sim":
        # Only the Verilog and the memory images: board/sim has its own Verilator harness, so
        # LiteX's simulator (its C modules, its tap/ethernet data package) is not used.
        import litex.build.sim.verilator as lsv
        lsv._generate_sim_variables = lambda *args, **kwargs: None
        lsv._build_sim = lambda *args, **kwargs: None
    builder = Builder(soc, output_dir=a.out, compile_software=False,
                      compile_gateware=not (a.headers_only or a.target == "sim"))
    if a.headers_only:
        builder.build(run=False, **({"build": False} if a.target == "sim" else {}))
        return
    kw = {}
    if a.target != "sim":
        kw = dict(seed=a.seed, timingstrict=True)
        builder.build(**kw)
    else:
        builder.build(run=False, build_name="sim")
        # the Verilog the harness compiles, in order (the CPU's, the RTL's, the SoC's)
        with open(os.path.join(a.out, "gateware", "sources.txt"), "w") as f:
            top = os.path.abspath(os.path.join(a.out, "gateware", "sim.v"))  # the harness names it last
            for src in soc.platform.sources:
                if os.path.abspath(src[0]) != top:
                    f.write(os.path.abspath(src[0]) + "\n")


if __name__ == "__main__":
    main()
