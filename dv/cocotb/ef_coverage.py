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

import edgeflag as ef

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


def _ceil_div(a, b):
    return -((-a) // b)


class CoverageModel:
    """Samples the points of points.tsv from the monitors' transactions.  The definitions are the
    TSV's; where one needs a value no interface carries (an edge's unclipped sample rows, the
    plotter's q before the clamp, a lane's value, the filler's accumulator, a sample's true winding
    number) it is computed here from the interfaces' fields as docs/spec.md 5-7 define it."""

    def __init__(self, samples, edges_max):
        self.points = load_points()
        self.names = [p[0] for p in self.points]
        self.samplers = {}
        for name in self.names:
            self.samplers[name] = CoverPoint(name, xf=lambda hit: hit, bins=[True])(lambda hit: None)
        self.hits = {n: 0 for n in self.names}
        self.unknown = set()
        self.n = samples
        self.h_step = 256 // samples
        self.c = self.h_step // 2
        pat = ef._ffi.lib.ef_pattern(samples)
        self.off = [256 - self.h_step * pat[s] - self.c for s in range(samples)]
        self.emax = edges_max
        self.w = self.h = 0
        self.options = 0
        self.rule = 0
        self.shapes = 0
        self.written = set()
        self.in_shape = False
        self.cells = {}
        self.row_plots = {}

    def hit(self, name, n=1):
        s = self.samplers.get(name)
        if s is None:
            self.unknown.add(name)  # a name the code uses that the TSV does not define: an error at export
            return
        for _ in range(n):
            s(True)
        self.hits[name] += n

    def _begin_shape(self):
        self.in_shape = True
        self.edges = 0
        self.records = 0
        self.spans = 0
        self.span_rows = set()
        self.rd_rows = {}
        self.rd_first = None

    def _end_shape(self):
        if not self.in_shape:
            return
        self.in_shape = False
        if self.edges == 0:
            self.hit("shape.empty")
        elif self.records == 0:
            self.hit("shape.no_records")
        if self.records and self.spans == 0:
            self.hit("shape.degenerate")
        if self.spans and len(self.span_rows) == 1:
            self.hit("shape.one_row")

    # ---------------------------------------------------------------- listener
    def __call__(self, t):
        getattr(self, "on_" + t.NAME)(t)

    def on_cmd(self, t):
        op = t.op
        if op == 1:  # FRAME
            self.w, self.h = t.a & 0xFFFFFF, t.b & 0xFFFFFF
            self.options = t.c & 0xFFFFFF
            self.shapes = 0
            self.written = set()
            if self.w == 1 or self.h == 1:
                self.hit("canvas.one_px")
        elif op == 2:  # SHAPE
            self._end_shape()
            self._begin_shape()
            self.shapes += 1
            self.rule = t.a & 1
            filt = "tent" if self.options & 1 else "box"
            sub = {0: "none", 1: "rgb", 2: "bgr"}.get(self.options >> 1 & 3)
            if sub:
                self.hit(f"mode.{'evenodd' if self.rule else 'nonzero'}.ns{self.n}.{filt}.{sub}")
            alpha = t.c & 0xFF
            if alpha == 0:
                self.hit("shape.alpha0")
            elif alpha < 255:
                self.hit("shape.alpha_partial")
        elif op == 3:
            self.edges += 1
        elif op == 4:  # SHAPE_END: the shape's transfers may still be in flight; judged at the next SHAPE
            if self.edges >= 4096:
                self.hit("shape.edges_4096")
        elif op == 5:  # FRAME_END
            self._end_shape()
            if self.shapes == 0:
                self.hit("frame.empty")
            if self.shapes >= 100:
                self.hit("frame.many_shapes")

    def on_seg(self, t):
        if t.eos:
            return
        if t.ya == t.yb:
            self.hit("setup.horizontal")
            return
        y0, y1 = min(t.ya, t.yb), max(t.ya, t.yb)
        r0 = _ceil_div(y0 - self.c, self.h_step)
        r1 = _ceil_div(y1 - self.c, self.h_step) - 1
        last = self.n * self.h - 1
        if r0 > r1:
            self.hit("setup.between_rows")
            return
        if r1 < 0:
            self.hit("clip.drop_above")
        elif r0 > last:
            self.hit("clip.drop_below")
        else:  # kept: it has an et_wr
            if r0 < 0:
                self.hit("clip.top")
            if r1 > last:
                self.hit("clip.bottom")

    def on_et_wr(self, t):
        if t.eos:
            return
        self.records += 1
        self.hit("setup.dir_up" if t.dir else "setup.dir_down")
        if t.r0 == 0 and t.r1 == self.n * self.h - 1:
            self.hit("edge.longest")
        if t.qs == 0:
            self.hit("div.qs_zero")
        elif t.qs == -1:
            self.hit("div.qs_minus1")
        if abs(t.qs) >= 1 << 20:
            self.hit("div.qs_big")
        if t.rs == 0 and t.qs != 0:
            self.hit("div.rs_zero")
        if t.e == 0:
            self.hit("div.e_zero")
        if t.e == t.dy - 1:
            self.hit("div.e_max")
        if t.dy == 1:
            self.hit("div.dy_one")
        if t.dy >= 1 << 20:
            self.hit("div.dy_big")
        if t.x < 0:
            self.hit("div.x_neg")
        if abs(t.x) >= 1 << 22:
            self.hit("div.x_big")
        # the DDA of spec 5/6.1 over the record's sample rows: q before the clamp, counted per
        # sample row (as edgeflag coverage counts)
        x, e, left, right = t.x, t.e, 0, 0
        for r in range(t.r0, t.r1 + 1):
            q = (x + self.off[r % self.n]) >> 8
            if q < 0:
                left += 1
            elif q > self.w:
                right += 1
            x += t.qs
            e += t.rs
            if e >= t.dy:
                e -= t.dy
                x += 1
        if left:
            self.hit("clamp.left", left)
        if right:
            self.hit("clamp.right", right)

    def on_et_rd(self, t):
        # counted as edgeflag coverage counts them: a row when its second edge joins, and every
        # edge that joins in a row after the shape's first et_rd row
        k = self.rd_rows.get(t.row, 0) + 1
        self.rd_rows[t.row] = k
        if k == 2:
            self.hit("et.slot_multi")
        if self.rd_first is None:
            self.rd_first = t.row
        elif t.row > self.rd_first:
            self.hit("et.join_late")

    def on_plot(self, t):
        if t.q == 0:
            self.hit("plot.cell0")
        elif t.q == self.w:
            self.hit("plot.sink")
        key = (t.q, t.s)
        self.row_plots.setdefault(t.s, []).append((t.q, t.dir))
        if self.rule == 0:
            v = self.cells.get(key, 0)
            if t.dir == 0:
                if v == 127:
                    self.hit("wind.plot_wrap_up")
                if v == 63:
                    self.hit("wind.plot_ovf_up")
                self.cells[key] = (v + 1) & 127
            else:
                if v == 0:
                    self.hit("wind.plot_wrap_down")
                else:
                    self.hit("wind.plot_pad_carry_down")
                if v == 64:
                    self.hit("wind.plot_ovf_down")
                self.cells[key] = (v + 127) & 127
        if t.last:
            self._fill_row()
            self.cells = {}
            self.row_plots = {}

    def _fill_row(self):
        """The filler's pass over the row (spec 6.2, 6.3, 7.2), sampled as edgeflag coverage samples
        it: at every cell the row's plots touched (the sink W included), for every sample row s, the
        lane accumulator (pad carry, signed overflow) and the true winding number (non-zero) or the
        crossing count (even-odd) accumulated up to that cell."""
        net = {}
        for s, plots in self.row_plots.items():
            for q, d in plots:
                k = (q, s)
                net[k] = net.get(k, 0) + ((-1 if d else 1) if self.rule == 0 else 1)
        touched = sorted({q for plots in self.row_plots.values() for q, _ in plots})
        n = self.n
        acct = [0] * n
        if self.rule == 0:
            accr = [0] * n
            cells = self.cells
            for q in touched:
                for s in range(n):
                    raw = cells.get((q, s), 0)
                    if accr[s] + raw >= 128:
                        self.hit("wind.acc_pad_carry")
                    if not -64 <= _s7(accr[s]) + _s7(raw) <= 63:
                        self.hit("wind.acc_ovf")
                    accr[s] = (accr[s] + raw) & 127
                    acct[s] += net.get((q, s), 0)
                    a = abs(acct[s])
                    if a == 63:
                        self.hit("wind.true_63")
                    elif a == 64:
                        self.hit("wind.true_64")
                    if a and a % 128 == 0:
                        self.hit("wind.true_mod128")
        else:
            for q in touched:
                for s in range(n):
                    acct[s] += net.get((q, s), 0)
                    if acct[s] >= 3 and acct[s] % 2:
                        self.hit("eo.odd_gt1")

    def on_span(self, t):
        self.spans += 1
        self.span_rows.add(t.y)
        if t.x == 0:
            self.hit("span.x0")
            if t.len == self.w:
                self.hit("span.full_row")
        if t.x + t.len == self.w:
            self.hit("span.right")
        if t.len == 1:
            self.hit("span.len1")
        full = (1 << self.n) - 1
        if t.mask == full:
            self.hit("span.solid")
        elif t.mask:
            self.hit("span.partial")

    def on_pix(self, t):
        if t.alpha == 255:
            self.hit("pix.alpha_full")
        elif t.alpha:
            self.hit("pix.alpha_partial")
        k = (t.x, t.y)
        if k in self.written:
            self.hit("pix.overdraw")
        self.written.add(k)

    # ------------------------------------------------------------------ report
    def export(self, path):
        if self.unknown:
            raise ValueError(f"cover points used but not in {POINTS_TSV}: {sorted(self.unknown)}")
        path = pathlib.Path(path)
        path.write_text(json.dumps({"points": self.hits}, indent=1, sort_keys=True))
        coverage_db.export_to_xml(filename=str(path.with_suffix(".xml")))
