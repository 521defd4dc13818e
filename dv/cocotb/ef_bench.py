"""A cocotb testbench of ef_raster (rtl/ef_raster.v) with the Python model as its scoreboard.

The pieces, each usable alone in a bench of your own (docs/python.md, "the model in your bench"):

  Iface        one valid/ready interface of the DUT: its signal handles and the typed transaction
               type (edgeflag.TXN) whose fields name the signals (`plot_q` is Plot.q).
  CmdDriver    drives `cmd` words from their cycle stamps on, each held until the DUT takes it.
  PixReady     drives `pix_ready`: always 1, or seeded random back-pressure (ready 3 cycles in 4).
  FrameMemory  the frame memory behind COV's read and write ports (docs/microarch.md 3.6).
  Monitor      samples one interface every cycle and hands each transfer, stamped with the cycle,
               to its listeners (the scoreboard, the coverage model, a dump).
  Scoreboard   edgeflag.ModelStream fed with every command the DUT accepted; each observed
               transfer is compared with the model's next expected one of that interface
               (cycle-exact, or in order only under back-pressure); it stops at the first
               mismatch with the interface, cycle and every decoded field, and it also fails when
               an expected transfer's cycle passes without it (cycle-exact mode).

One clock loop runs everything (one FallingEdge and one ReadOnly per cycle): inputs for cycle c are
written at c's falling edge, and the values of cycle c are read in its ReadOnly phase, so every
monitor sees exactly what the DUT's registers take at the rising edge that ends cycle c.
"""

import random

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge, ReadOnly, RisingEdge

import edgeflag as ef

OBSERVED = ("seg", "et_wr", "et_rd", "plot", "span", "pix")


class BenchFailure(AssertionError):
    """The bench stopped: `iface`, `cycle` and the model's message with every decoded field."""

    def __init__(self, message, iface=None, cycle=None):
        super().__init__(message)
        self.iface, self.cycle, self.message = iface, cycle, message


class Iface:
    """The signals of interface `name` on the DUT: NAME_valid, NAME_ready and NAME_FIELD."""

    def __init__(self, dut, name):
        self.name = name
        self.txn = ef.TXN[name]
        self.valid = getattr(dut, f"{name}_valid")
        self.ready = getattr(dut, f"{name}_ready")
        # the simulator's handles, read as integers without a BinaryValue (a 1-bit x reads as 0
        # here; the fields of a transfer are read with x/z detection below)
        self.valid_raw = self.valid._handle.get_signal_val_long
        self.ready_raw = self.ready._handle.get_signal_val_long
        self.fields = [getattr(dut, f"{name}_{f.name}") for f in self.txn.FIELDS]
        self.masks = [(1 << f.width) - 1 for f in self.txn.FIELDS]
        self.signed = [f.width if f.signed else 0 for f in self.txn.FIELDS]

    def read(self, cycle):
        vals = [cycle]
        for h, sw in zip(self.fields, self.signed):
            v = h.value
            if not v.is_resolvable:
                raise BenchFailure(f"{self.name}: cycle {cycle}: the DUT drives x/z on {h._name} while valid",
                                   self.name, cycle)
            v = v.integer
            if sw and v >> (sw - 1):
                v -= 1 << sw
            vals.append(v)
        return self.txn(*vals)


class Monitor:
    """Observes one interface; listeners get (txn) for every transfer (valid & ready)."""

    def __init__(self, iface):
        self.iface = iface
        self.listeners = []
        self.count = 0

    def sample(self, cycle):
        i = self.iface
        if i.valid_raw() and i.ready_raw():
            t = i.read(cycle)
            self.count += 1
            for fn in self.listeners:
                fn(t)
            return t
        return None


class CmdDriver:
    """Presents each Cmd transaction from its cycle stamp on, held until cmd_ready."""

    def __init__(self, dut, commands):
        self.dut = dut
        self.cmds = list(commands)
        self.k = 0
        self.h = [dut.cmd_op, dut.cmd_a, dut.cmd_b, dut.cmd_c, dut.cmd_d]
        self.presenting = False

    def drive(self, cycle):
        if self.k < len(self.cmds) and self.cmds[self.k].cycle <= cycle:
            c = self.cmds[self.k]
            if not self.presenting or self.cur is not c:
                self.dut.cmd_valid.value = 1
                for h, v, w in zip(self.h, c[1:], (4, 24, 24, 24, 24)):
                    h.value = v & ((1 << w) - 1)
                self.cur = c
            self.presenting = True
        elif self.presenting:
            self.dut.cmd_valid.value = 0
            self.presenting = False

    def accepted(self):
        self.k += 1

    @property
    def done(self):
        return self.k >= len(self.cmds)


class PixReady:
    """pix_ready: 1 always (seed None), else ready 3 cycles in 4 at random from `seed`."""

    def __init__(self, dut, seed=None):
        self.dut, self.seed = dut, seed
        self.rng = random.Random(seed) if seed is not None else None
        self.stalls = 0
        self.last = None

    def drive(self, cycle):
        v = 1 if self.rng is None else int(self.rng.random() < 0.75)
        if v != self.last:
            self.dut.pix_ready.value = v
            self.last = v
        return v


class FrameMemory:
    """COV's frame memory: a read port with one cycle of latency and a write port."""

    def __init__(self, dut):
        self.dut = dut
        self.mem = {}
        self.rdata = None
        self.re, self.ry, self.rx, self.we, self.wy, self.wx, self.wdata = (
            getattr(dut, n)._handle.get_signal_val_long for n in ("fb_re", "fb_ry", "fb_rx", "fb_we", "fb_wy",
                                                                   "fb_wx", "fb_wdata"))

    def clear(self):
        self.mem.clear()

    def sample(self, cycle):
        out = None
        if self.re():
            out = self.mem.get((self.ry(), self.rx()), 0)
        if self.we():
            self.mem[(self.wy(), self.wx())] = self.wdata()
        self.rdata = out

    def drive(self):
        if self.rdata is not None:
            self.dut.fb_rdata.value = self.rdata


class Scoreboard:
    """The Python model (edgeflag.ModelStream) as the scoreboard of every observed interface."""

    def __init__(self, samples, width_max, height_max, edges_max, rule=None, check_cycles=True, log=None):
        self.model = ef.ModelStream(samples=samples, width_max=width_max, height_max=height_max,
                                    edges_max=edges_max, rule=rule)
        self.check_cycles = check_cycles
        self.pending = {n: [] for n in ("cmd",) + OBSERVED}
        self.checked = {n: 0 for n in ("cmd",) + OBSERVED}
        self.log = log
        self.due = None    # (cycle, iface) of the earliest expected transfer not yet made, cached:
        self.dirty = True  # recomputed only after a match or a command, not every cycle

    def command(self, t):
        """A command the DUT accepted: the model gets the same word, then waiting transfers drain."""
        try:
            self.model.cmd(t)
        except ef.EdgeflagError as e:
            raise BenchFailure(f"cmd: cycle {t.cycle}: the model refuses the command the DUT took: {e}", "cmd",
                               t.cycle) from None
        self.observe(t)
        self.drain()

    def observe(self, t):
        self.pending[t.NAME].append(t)
        self.dirty = True
        self._match(t.NAME)

    def _match(self, name):
        q = self.pending[name]
        while q:
            try:
                r = self.model.expect(q[0], check_cycle=self.check_cycles)
            except ef.StreamMismatch as e:
                raise BenchFailure(e.message, name, q[0].cycle) from None
            if r is None:
                return
            q.pop(0)
            self.checked[name] += 1
            self.dirty = True

    def drain(self):
        self.dirty = True
        for n in self.pending:
            self._match(n)

    def late(self, cycle):
        """Cycle-exact mode: an expected transfer whose cycle is over and that the DUT did not make."""
        if not self.check_cycles:
            return
        if self.dirty:
            self.dirty = False
            self.due = None
            for n in OBSERVED:
                if self.pending[n]:
                    continue
                t = self.model.peek(n)
                if t is not None and t is not ef.ModelStream.END and (self.due is None or t.cycle < self.due[0]):
                    self.due = (t.cycle, n, t)
        if self.due is not None and self.due[0] < cycle:
            c, n, t = self.due
            raise BenchFailure(f"{n}: cycle {c}: missing transaction: expected {t.describe()}; the DUT "
                               f"made none by cycle {cycle}", n, c)

    def finish(self):
        self.drain()
        for n in self.pending:
            if self.pending[n]:
                t = self.pending[n][0]
                raise BenchFailure(f"{n}: cycle {t.cycle}: extra transaction: actual {t.describe()}; the model "
                                   "has none", n, t.cycle)
        for n in ("cmd",) + OBSERVED:
            try:
                self.model.expect_done(n)
            except ef.StreamMismatch as e:
                raise BenchFailure(e.message, n) from None
        total = sum(self.checked.values())
        if sum(self.checked[n] for n in OBSERVED) == 0:
            raise BenchFailure("no transaction was checked on any observed interface (only the commands): "
                               "a test that compares nothing fails")
        return total


class RasterBench:
    """The whole bench for one run: reset, one frame's commands, every interface checked."""

    def __init__(self, dut, samples, width_max, height_max, edges_max):
        self.dut = dut
        self.samples, self.wmax, self.hmax, self.emax = samples, width_max, height_max, edges_max
        self.ifaces = {n: Iface(dut, n) for n in OBSERVED}
        self.monitors = {n: Monitor(self.ifaces[n]) for n in OBSERVED}
        self.cmd_iface = Iface(dut, "cmd")
        self.cmd_monitor = Monitor(self.cmd_iface)
        self.fb = FrameMemory(dut)
        self.clock = None
        self.cycles = 0

    async def reset(self):
        d = self.dut
        if self.clock is None:
            self.clock = cocotb.start_soon(Clock(d.clk, 2, units="step").start())
        else:
            await FallingEdge(d.clk)  # leave the read-only phase the last run ended in
        d.rst.value = 1
        d.cmd_valid.value = 0
        d.pix_ready.value = 1
        d.fb_rdata.value = 0
        for h in (d.cmd_op, d.cmd_a, d.cmd_b, d.cmd_c, d.cmd_d):
            h.value = 0
        for _ in range(3):
            await RisingEdge(d.clk)
        await FallingEdge(d.clk)
        d.rst.value = 0
        self.fb.clear()
        while True:
            await FallingEdge(d.clk)
            await ReadOnly()
            if d.init_done.value.integer:
                break

    async def run(self, commands, model_rule=None, bp_seed=None, listeners=(), limit=None, model_samples=None):
        """Drives `commands` (Cmd transactions with the reference schedule's stamps) and checks
        every interface against a fresh model.  Returns (cycles, checked counts)."""
        d = self.dut
        sb = Scoreboard(model_samples or self.samples, self.wmax, self.hmax, self.emax, rule=model_rule,
                        check_cycles=bp_seed is None)
        for n, m in self.monitors.items():
            m.listeners = [sb.observe, *[fn for fn in listeners if fn is not None]]
        self.cmd_monitor.listeners = [sb.command] + [fn for fn in listeners if fn is not None]
        drv = CmdDriver(d, commands)
        ready = PixReady(d, bp_seed)
        last = commands[-1].cycle if commands else 0
        limit = limit or 2 * last + 20000
        mons = list(self.monitors.values())
        cycle = 0
        quiet = None
        err = d.err._handle.get_signal_val_long
        # cycle 0 is the cycle after the one where init_done was seen (as tests/rtl/tb_raster.v)
        while True:
            await FallingEdge(d.clk)
            drv.drive(cycle)
            ready.drive(cycle)
            self.fb.drive()
            await ReadOnly()
            if self.cmd_monitor.sample(cycle) is not None:
                drv.accepted()
            for m in mons:
                m.sample(cycle)
            self.fb.sample(cycle)
            sb.late(cycle)
            if err():
                raise BenchFailure(f"cycle {cycle}: the DUT raised err (a FRAME over W_MAX x H_MAX or a shape over "
                                   "E_MAX edges)", None, cycle)
            cycle += 1
            # the end: every command taken, the frame's end fed to the model, every expected
            # transfer matched (pending 0), then 64 quiet cycles in which an extra one would show
            if drv.done and sb.model.frame_cycles() is not None and all(sb.model.pending(n) == 0 for n in OBSERVED):
                if quiet is None:
                    quiet = cycle
                if cycle - quiet >= 64:
                    break
            else:
                quiet = None
            if cycle > limit:
                raise BenchFailure(f"cycle {cycle}: the run did not end (limit {limit} cycles; "
                                   f"{len(commands) - drv.k} commands not taken)", None, cycle)
        total = sb.finish()
        self.cycles += cycle
        return cycle, dict(sb.checked), total
