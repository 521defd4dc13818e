"""Functional coverage of the cocotb bench, by cocotb-coverage, over the points of
dv/coverage/points.tsv (the one list of names and definitions every edgeflag bench shares).

CoverageModel listens to the bench's monitors (the same typed transactions the scoreboard gets) and
samples a point when a transaction, a pixel row or a shape satisfies the point's definition.  Each
point is a cocotb_coverage CoverPoint with the single bin True; `export(path)` writes the hit counts
of every point of the TSV (0 for those not hit) as JSON for the runner's merged report, and
cocotb-coverage's own XML beside it.
"""

import json
import pathlib

from cocotb_coverage.coverage import CoverPoint, coverage_db

POINTS_TSV = pathlib.Path(__file__).resolve().parents[1] / "coverage" / "points.tsv"


def load_points(path=POINTS_TSV):
    """[(name, section, definition)] of the TSV, in file order."""
    out = []
    header = True
    for line in pathlib.Path(path).read_text().splitlines():
        if not line or line.startswith("#"):
            continue
        cols = line.split("\t")
        if header:
            if cols[:3] != ["name", "section", "definition"]:
                raise ValueError(f"{path}: the header must be name, section, definition")
            header = False
            continue
        if len(cols) != 3:
            raise ValueError(f"{path}: {line!r}: three tab-separated columns expected")
        out.append(tuple(cols))
    return out


def _s7(v):
    return v - 128 if v >= 64 else v


class CoverageModel:
    def __init__(self, samples, edges_max):
        self.points = load_points()
        self.names = [p[0] for p in self.points]
        self.samplers = {}
        for name in self.names:
            self.samplers[name] = CoverPoint(name, xf=lambda hit: hit, bins=[True])(lambda hit: None)
        self.hits = {n: 0 for n in self.names}
        self.unknown = set()
        self.n = samples
        self.emax = edges_max
        self.w = self.h = 0
        self.rule = 0
        self.shape_no = 0
        self._new_shape()
        self.cells = {}
        self.row_net = {}
        self.written = {}

    def hit(self, name):
        s = self.samplers.get(name)
        if s is None:
            self.unknown.add(name)  # a name the code uses that the TSV does not define
            return
        s(True)
        self.hits[name] += 1

    def _new_shape(self):
        self.edges = 0
        self.records = 0
        self.span_rows = set()
        self.in_shape = False

    def _end_shape(self):
        if not self.in_shape:
            return
        if self.records == 0:
            self.hit("spec5.shape.empty")
        if len(self.span_rows) == 1:
            self.hit("spec5.shape.one_row")
        self._new_shape()

    # ---------------------------------------------------------------- listener
    def __call__(self, t):
        getattr(self, "on_" + t.NAME)(t)

    def on_cmd(self, t):
        if t.op == 1:  # FRAME
            self.w, self.h = t.a & 0xFFFFFF, t.b & 0xFFFFFF
            self.written = {}
            self.shape_no = 0
        elif t.op == 2:  # SHAPE
            self._end_shape()
            self.in_shape = True
            self.shape_no += 1
            self.rule = t.a & 1
            self.hit(f"spec4.rule_samples.{'evenodd' if self.rule else 'nonzero'}.n{self.n}")
        elif t.op == 3:
            self.edges += 1
        elif t.op == 4:
            if self.edges == self.emax:
                self.hit("uarch1.emax.full")
        elif t.op == 5:
            self._end_shape()

    def on_seg(self, t):
        if t.eos:
            return
        lo, hi = min(t.ya, t.yb), max(t.ya, t.yb)
        if t.ya == t.yb:
            self.hit("spec5.drop.horizontal")
            return
        bottom = 256 * self.h
        if hi <= 0 or lo >= bottom:
            self.hit("spec5.drop.outside")
        if lo < 0 < hi:
            self.hit("spec5.clip.top")
        if lo < bottom < hi:
            self.hit("spec5.clip.bottom")

    def on_et_wr(self, t):
        if t.eos:
            return
        self.records += 1
        if t.r0 == 0 and t.r1 == self.n * self.h - 1:
            self.hit("spec5.edge.full_height")
        if t.dy >= 1 << 23:
            self.hit("spec5.edge.dy_max")
        if t.x < -255:
            self.hit("spec6.1.clamp.left")

    def on_et_rd(self, t):
        pass

    def on_plot(self, t):
        if t.q == self.w:
            self.hit("spec6.1.clamp.right")
        if self.rule == 0:
            key = (t.q, t.s)
            v = self.cells.get(key, 0)
            if t.dir == 0:
                if v == 127:
                    self.hit("spec6.3.pad.carry_up")
                if v == 63:
                    self.hit("spec6.4.overflow.plot")
                self.cells[key] = (v + 1) & 127
            else:
                if v >= 1:
                    self.hit("spec6.3.pad.carry_down")
                if v == 64:
                    self.hit("spec6.4.overflow.plot")
                self.cells[key] = (v + 127) & 127
            net = self.row_net.setdefault(t.s, {})
            net[t.q] = net.get(t.q, 0) + (1 if t.dir == 0 else -1)
        if t.last:
            if self.rule == 0:
                self._windings()
            self.cells = {}
            self.row_net = {}

    def _windings(self):
        for net in self.row_net.values():
            run = 0
            for q in sorted(net):
                if q >= self.w:
                    break
                run += net[q]
                if run == 63:
                    self.hit("spec6.4.winding.pos63")
                elif run == 64:
                    self.hit("spec6.4.winding.pos64")
                elif run == -64:
                    self.hit("spec6.4.winding.neg64")
                elif run == -65:
                    self.hit("spec6.4.winding.neg65")
                if run and run % 128 == 0:
                    self.hit("spec6.4.winding.wrap128")

    def on_span(self, t):
        self.span_rows.add(t.y)
        if t.x == 0:
            self.hit("spec7.span.x0")
            if t.len == self.w:
                self.hit("spec7.span.full_row")
        if t.x + t.len == self.w:
            self.hit("spec7.span.xlast")
        if t.mask == (1 << self.n) - 1:
            self.hit("spec7.span.solid")
        if t.mask and t.mask & (t.mask - 1) == 0:
            self.hit("spec7.span.single_sample")

    def on_pix(self, t):
        k = (t.x, t.y)
        prev = self.written.get(k)
        if prev is not None and prev < self.shape_no:
            self.hit("spec8.pix.blend_over")
        self.written[k] = self.shape_no

    # ------------------------------------------------------------------ report
    def export(self, path):
        if self.unknown:
            raise ValueError(f"cover points used but not in {POINTS_TSV}: {sorted(self.unknown)}")
        path = pathlib.Path(path)
        path.write_text(json.dumps({"points": self.hits}, indent=1, sort_keys=True))
        coverage_db.export_to_xml(filename=str(path.with_suffix(".xml")))
