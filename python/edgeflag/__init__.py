"""edgeflag: the bit-exact reference model of the scanline edge-flag rasterizer, from Python.

A thin layer over the C library (libedgeflag.so's public API; the vectors, checker, gen and model
stream code through libefpy.so), loaded with cffi in ABI mode.  docs/python.md is the guide:

    import edgeflag as ef
    scene = ef.Scene.load("tests/data/svg/tiger.svg", fit=(640, 480))
    img = ef.render(scene, samples=8)                 # numpy (480, 640, 4) uint8, premultiplied RGBA
    tr = ef.trace(scene, samples=8)                   # every interface's transactions
    tr["span"][0]                                     # Span(cycle=..., y=..., x=..., len=..., mask=...)

No float enters the model: coordinates are the spec's Q16.8 integers, or exact decimals (str,
decimal.Decimal, fractions.Fraction with a terminating decimal expansion) that the library's own
parser rounds (docs/input.md section 8).  Every model object owns its own C state: several models
live side by side, and nothing here is global but the read-only interface table.
"""

from __future__ import annotations

import decimal
import fractions
import gc
import os
import collections

import numpy as np

from ._ffi import ffi, lib, vec

__all__ = [
    "EdgeflagError", "VectorsError", "Scene", "Model", "Trace", "Vectors", "CheckReport", "Mismatch",
    "ModelStream", "StreamMismatch", "GenCase", "IFACES", "TXN", "Field", "render", "coverage", "trace",
    "read_vectors", "check", "gen_cases", "q8",
]

__version__ = "0.1.0"

RULES = {"nonzero": 0, "evenodd": 1}
RULE_NAMES = {0: "nonzero", 1: "evenodd"}


# ------------------------------------------------------------------ errors
class EdgeflagError(Exception):
    """An error of the library: its status, message and where (file, line, column; 0 if unknown)."""

    def __init__(self, message, status=None, file="", line=0, column=0):
        self.message, self.status, self.file, self.line, self.column = message, status, file, line, column
        where = file
        if file and line:
            where = f"{file}:{line}:{column}"
        super().__init__(f"{where}: {message}" if where else message)


class VectorsError(EdgeflagError):
    """A vector file that cannot be read; `record` and `offset` place binary errors."""

    def __init__(self, message, status=None, file="", line=0, column=0, record=0, offset=0, text=""):
        super().__init__(message, status, file, line, column)
        self.record, self.offset = record, offset
        if text:
            self.args = (text,)


def _status_name(st):
    return ffi.string(lib.ef_strerror(st)).decode()


def _check(st, what=""):
    if st != 0:
        raise EdgeflagError(f"{what}{': ' if what else ''}{_status_name(st)}", status=st)


def _rule(rule):
    if rule is None:
        return -1
    if isinstance(rule, str):
        try:
            return RULES[rule]
        except KeyError:
            raise ValueError(f"rule must be 'nonzero' or 'evenodd', not {rule!r}") from None
    if rule in (0, 1):
        return int(rule)
    raise ValueError(f"rule must be 'nonzero', 'evenodd', 0 or 1, not {rule!r}")


def _samples(n):
    if n not in (8, 16, 32):
        raise ValueError(f"samples must be 8, 16 or 32, not {n!r}")
    return n


# ------------------------------------------------------------ interfaces
Field = collections.namedtuple("Field", "name width signed shift")


def _load_ifaces():
    out = []
    for i in range(7):
        d = lib.ef_iface_get(i)
        fields, shift = [], int(d.width)
        for k in range(d.nfields):
            f = d.field[k]
            shift -= f.width
            fields.append(Field(ffi.string(f.name).decode(), int(f.width), bool(f.is_signed), shift))
        out.append((ffi.string(d.name).decode(), ffi.string(d.__getattribute__("from")).decode(),
                    ffi.string(d.to).decode(), int(d.width), tuple(fields)))
    return out


def _class_name(name):
    return "".join(p.capitalize() for p in name.split("_"))


class _TxnBase(tuple):
    """Base of the transaction types: a named tuple (cycle, then the interface's fields, most
    significant first, with the names and widths of docs/vectors.md); signed fields hold their
    value, the others their bits."""

    __slots__ = ()
    IFACE = -1
    NAME = ""
    FIELDS: tuple = ()
    WIDTH = 0

    def payload(self):
        """The payload as one integer (the fields concatenated, most significant first)."""
        p = 0
        for f, v in zip(self.FIELDS, self[1:]):
            p |= (v & ((1 << f.width) - 1)) << f.shift
        return p

    @classmethod
    def from_payload(cls, cycle, p):
        vals = [cycle]
        for f in cls.FIELDS:
            v = (p >> f.shift) & ((1 << f.width) - 1)
            if f.signed and v >> (f.width - 1):
                v -= 1 << f.width
            vals.append(v)
        return cls(*vals)

    def describe(self):
        """'name=value ...' as edgeflag check prints fields."""
        out = []
        for f, v in zip(self.FIELDS, self[1:]):
            out.append(f"{f.name}={v}" if f.signed or f.width < 32 else f"{f.name}=0x{v:x}")
        return " ".join(out)

    def _c(self):
        t = ffi.new("ef_txn *")
        t.cycle = self[0]
        t.iface = self.IFACE
        p = self.payload()
        for k in range(4):
            t.w[k] = (p >> (64 * k)) & 0xFFFFFFFFFFFFFFFF
        return t


def _codecs(fields):
    """payload() and from_payload() of one interface, written out as straight-line Python (the
    shifts, masks and sign extensions of its fields), for speed: a bench calls them per transfer."""
    pay = " | ".join(f"((self[{k + 1}] & {(1 << f.width) - 1}) << {f.shift})" for k, f in enumerate(fields)) or "0"
    body = []
    for k, f in enumerate(fields):
        body.append(f"    f{k} = (p >> {f.shift}) & {(1 << f.width) - 1}")
        if f.signed:
            body.append(f"    f{k} -= (f{k} & {1 << (f.width - 1)}) << 1")
    names = "".join(f"f{k}, " for k in range(len(fields)))
    src = (f"def payload(self):\n    return {pay}\n"
           f"def from_payload(cls, cycle, p):\n" + "\n".join(body) + f"\n    return _new(cls, (cycle, {names}))\n")
    ns = {"_new": tuple.__new__}
    exec(compile(src, "<edgeflag codecs>", "exec"), ns)
    return ns["payload"], classmethod(ns["from_payload"])


IFACES = []  # interface names in pipeline order: "cmd", "seg", ...
TXN = {}     # name -> transaction type (TXN["plot"] is Plot)
for _i, (_name, _from, _to, _width, _fields) in enumerate(_load_ifaces()):
    _base = collections.namedtuple(_class_name(_name) + "Tuple", ["cycle"] + [f.name for f in _fields])
    _pay, _dec = _codecs(_fields)
    _cls = type(_class_name(_name), (_TxnBase, _base), {
        "__slots__": (), "payload": _pay, "from_payload": _dec, "IFACE": _i, "NAME": _name, "FIELDS": _fields, "WIDTH": _width,
        "FROM": _from, "TO": _to, "__repr__": _base.__repr__, "__doc__":
        f"A `{_name}` transaction ({_from} -> {_to}, {_width} bits): cycle, "
        + ", ".join(f"{f.name}[{f.width}]" for f in _fields)})
    IFACES.append(_name)
    TXN[_name] = _cls
    globals()[_cls.__name__] = _cls
    __all__.append(_cls.__name__)
ALL = (1 << len(IFACES)) - 1


def _iface(i):
    if isinstance(i, str):
        n = lib.ef_iface_find(i.encode())
        if n < 0:
            raise ValueError(f"no interface {i!r} (interfaces: {', '.join(IFACES)})")
        return n
    if isinstance(i, int) and 0 <= i < len(IFACES):
        return i
    raise ValueError(f"no interface {i!r}")


def _mask(ifaces):
    if ifaces is None:
        return ALL
    if isinstance(ifaces, str):
        ifaces = [ifaces]
    m = 0
    for i in ifaces:
        m |= 1 << _iface(i)
    return m


def _txn_from_c(t):
    cls = TXN[IFACES[t.iface]]
    p = t.w[0] | (t.w[1] << 64) | (t.w[2] << 128) | (t.w[3] << 192)
    return cls.from_payload(int(t.cycle), p)


def _decode_records(iface, rec):
    """Decodes an (n, 1 + nw) uint64 array of records into typed transactions: each field is cut
    out of the payload words with NumPy over the whole array, then the tuples are built."""
    cls = TXN[IFACES[iface]]
    n = len(rec)
    if n == 0:
        return []
    cols = [rec[:, 0].tolist()]
    for f in cls.FIELDS:
        k, off = divmod(f.shift, 64)
        v = rec[:, 1 + k] >> np.uint64(off)
        if off + f.width > 64:  # the field crosses into the next payload word
            v = v | (rec[:, 2 + k] << np.uint64(64 - off))
        v = (v & np.uint64((1 << f.width) - 1)).astype(np.int64)
        if f.signed:
            v = v - ((v & (1 << (f.width - 1))) << 1)
        cols.append(v.tolist())
    make = cls._make
    gc_was = gc.isenabled()
    gc.disable()  # a million small tuples: the cyclic collector would rescan them all, again and again
    try:
        return [make(t) for t in zip(*cols)]
    finally:
        if gc_was:
            gc.enable()


# -------------------------------------------------------------- coordinates
_Q8 = fractions.Fraction(1, 256)


def _decimal_text(v):
    """An exact decimal string of a pixel coordinate given as str, Decimal or Fraction."""
    if isinstance(v, bool) or isinstance(v, float):
        raise TypeError(f"coordinate {v!r}: floats are refused (no float enters the model); give Q16.8 "
                        "integers, or exact decimals as str, decimal.Decimal or fractions.Fraction")
    if isinstance(v, str):
        return v
    if isinstance(v, decimal.Decimal):
        if not v.is_finite():
            raise ValueError(f"coordinate {v!r} is not finite")
        return format(v, "f")
    if isinstance(v, fractions.Fraction):
        d = v.denominator
        twos = fives = 0
        while d % 2 == 0:
            d //= 2
            twos += 1
        while d % 5 == 0:
            d //= 5
            fives += 1
        if d != 1:
            raise ValueError(f"coordinate {v} has no exact decimal expansion; give Q16.8 integers instead")
        k = max(twos, fives)
        n = abs(v.numerator) * (10 ** k // v.denominator)
        s = str(n).rjust(k + 1, "0")
        s = s[:len(s) - k] + ("." + s[len(s) - k:] if k else "")
        return ("-" if v < 0 else "") + s
    raise TypeError(f"coordinate {v!r}: expected an int (Q16.8) or an exact decimal (str, Decimal, Fraction)")


def q8(v):
    """Q16.8 of v / 256 as an exact decimal string (the inverse of the parser on exact values)."""
    s = "-" if v < 0 else ""
    a = abs(int(v))
    whole, frac = divmod(a, 256)
    if frac == 0:
        return f"{s}{whole}"
    digits = str(frac * 390625).rjust(8, "0").rstrip("0")  # frac / 256 = frac * 390625 / 10^8
    return f"{s}{whole}.{digits}"


# ----------------------------------------------------------------- scenes
def _load_error(err, st, what):
    msg = ffi.string(err.msg).decode(errors="replace") or _status_name(st)
    f = ffi.string(err.file).decode(errors="replace") or what
    return EdgeflagError(msg, status=st, file=f, line=int(err.line), column=int(err.col))


class Scene:
    """Painted shapes of polygons in device space (Q16.8), owned by this object (an ef_scene)."""

    def __init__(self, width, height):
        if not (1 <= width <= 16384 and 1 <= height <= 16384):
            raise ValueError(f"canvas {width}x{height}: width and height must be 1..16384")
        self._s = ffi.new("ef_scene *")
        lib.ef_scene_create(self._s, int(width), int(height))
        self.name = "scene"
        self.notes = []

    def __del__(self):
        s = getattr(self, "_s", None)
        if s is not None and lib is not None:  # (lib is None at interpreter shutdown)
            lib.ef_scene_destroy(s)
            self._s = None

    @classmethod
    def load(cls, path, fit=None):
        """Reads an SVG or .scene file (by extension); fit=(W, H) fits it into W x H."""
        path = os.fspath(path)

        def loader(opts, err):
            if fit:
                opts.fit_width, opts.fit_height = fit
            return lib.ef_scene_load_file(path.encode(), opts, self_s[0], err)

        self_s = []
        return cls._loaded_from(path, loader, self_s)

    @classmethod
    def _loaded_from(cls, name, loader, holder):
        self = cls.__new__(cls)
        self._s = ffi.new("ef_scene *")
        lib.ef_scene_create(self._s, 1, 1)
        holder.append(self._s)
        self.name = os.path.basename(name)
        self.notes = []
        err = ffi.new("ef_error *")
        opts = ffi.new("ef_load_opts *")
        notes = self.notes

        @ffi.callback("void(void *, const char *, uint32_t, uint32_t, const char *)")
        def on_note(user, file, line, col, msg):
            notes.append(f"{ffi.string(file).decode(errors='replace')}:{line}:{col}: "
                         f"{ffi.string(msg).decode(errors='replace')}")

        opts.note = on_note
        st = loader(opts, err)
        if st != 0:
            raise _load_error(err, st, name)
        return self

    @classmethod
    def from_svg(cls, text, name="input.svg", fit=None):
        data = text.encode() if isinstance(text, str) else bytes(text)
        holder = []

        def loader(opts, err):
            if fit:
                opts.fit_width, opts.fit_height = fit
            return lib.ef_scene_load_svg(name.encode(), data, len(data), opts, holder[0], err)

        return cls._loaded_from(name, loader, holder)

    @classmethod
    def from_text(cls, text, name="input.scene", fit=None):
        """A scene in the `.scene` format (docs/input.md section 8)."""
        data = text.encode() if isinstance(text, str) else bytes(text)
        holder = []

        def loader(opts, err):
            if fit:
                opts.fit_width, opts.fit_height = fit
            return lib.ef_scene_load_text(name.encode(), data, len(data), opts, holder[0], err)

        return cls._loaded_from(name, loader, holder)

    # ----- building
    @property
    def width(self):
        return int(self._s.width)

    @property
    def height(self):
        return int(self._s.height)

    def add_shape(self, contours, rule="nonzero", color=(0, 0, 0, 255)):
        """Appends a shape: `contours` is a list of contours, each a list of (x, y) points, closed
        implicitly.  Integers are Q16.8 (value / 256 px); str, Decimal and Fraction are pixels,
        rounded by the library's parser (floor(256 v + 1/2)); floats are refused."""
        r = _rule(rule)
        if r < 0:
            raise ValueError("a shape needs a rule")
        col = ffi.new("ef_rgba8 *", tuple(int(c) for c in color))
        pts_lists = [self._points(c, k) for k, c in enumerate(contours)]
        _check(lib.ef_scene_begin_shape(self._s, r, col[0]), "add_shape")
        for pts in pts_lists:
            arr = ffi.new("ef_point[]", max(len(pts), 1))
            for j, (x, y) in enumerate(pts):
                arr[j].x, arr[j].y = x, y
            _check(lib.ef_scene_add_contour(self._s, arr, len(pts)), "add_shape")
        return self

    def _points(self, contour, k):
        pts = list(contour)
        if all(isinstance(x, int) and not isinstance(x, bool) and isinstance(y, int) and not isinstance(y, bool)
               for x, y in pts):
            for x, y in pts:
                if not (-(1 << 23) < x < (1 << 23) and -(1 << 23) < y < (1 << 23)):
                    raise EdgeflagError(f"contour {k}: coordinate ({x}, {y}) outside |v| < 2^23 (Q16.8)",
                                        status=-5)
            return pts
        if len(pts) < 3:
            raise ValueError(f"contour {k}: a contour of exact decimals needs at least 3 points")
        nums = []
        for x, y in pts:
            for v in (x, y):
                nums.append(q8(v) if isinstance(v, int) and not isinstance(v, bool) else _decimal_text(v))
        text = f"scene {self.width} {self.height}\nshape nonzero 0 0 0 255\ncontour {' '.join(nums)}\n"
        tmp = Scene.from_text(text, name=f"{self.name}: contour {k}")
        s = tmp._s
        return [(int(s.points[j].x), int(s.points[j].y)) for j in range(s.npoints)]

    @property
    def shapes(self):
        """[(rule name, (r, g, b, a), [contour of (x, y) Q16.8 points, ...]), ...]."""
        s = self._s
        out = []
        for i in range(s.nshapes):
            sh = s.shapes[i]
            cons = []
            for c in range(sh.first_contour, sh.first_contour + sh.ncontours):
                cons.append([(int(s.points[j].x), int(s.points[j].y)) for j in range(s.start[c], s.start[c + 1])])
            out.append((RULE_NAMES[int(sh.rule)], (sh.color.r, sh.color.g, sh.color.b, sh.color.a), cons))
        return out

    def __len__(self):
        return int(self._s.nshapes)

    def commands(self, rule=None):
        """The `cmd` words of this scene as typed Cmd transactions without cycles (cycle 0):
        FRAME, per shape SHAPE, EDGE..., SHAPE_END, then FRAME_END (docs/microarch.md 3.1).
        The stamped stream of the reference schedule is trace(...)["cmd"]."""
        def cmd(cycle, op, a, b, c, d):  # a..d are signed 24-bit fields (docs/microarch.md 3)
            return TXN["cmd"](cycle, op, _s24(a), _s24(b), _s24(c), _s24(d))
        r = _rule(rule)
        out = [cmd(0, 1, self.width, self.height, 0, 0)]
        for rname, (cr, cg, cb, ca), cons in self.shapes:
            out.append(cmd(0, 2, RULES[rname] if r < 0 else r, (cr << 16) | (cg << 8) | cb, ca, 0))
            for c in cons:
                n = len(c)
                if n < 3:
                    continue
                for j in range(n):
                    (xa, ya), (xb, yb) = c[j], c[(j + 1) % n]
                    out.append(cmd(0, 3, xa, ya, xb, yb))
            out.append(cmd(0, 4, 0, 0, 0, 0))
        out.append(cmd(0, 5, 0, 0, 0, 0))
        return out


# ------------------------------------------------------------------ model
class Model:
    """One model (an ef_ctx): a width x height canvas at `samples` samples per pixel."""

    def __init__(self, width, height, samples=8):
        _samples(samples)
        p = ffi.new("ef_ctx **")
        _check(lib.ef_ctx_create(p, int(width), int(height), samples), f"model {width}x{height}")
        self._ctx = ffi.gc(p[0], lib.ef_ctx_destroy)
        self.width, self.height, self.samples = int(width), int(height), samples

    @classmethod
    def for_scene(cls, scene, samples=8):
        return cls(scene.width, scene.height, samples)

    def diag(self):
        d = ffi.new("ef_diag *")
        lib.ef_ctx_diag(self._ctx, d)
        return {"edges_in": d.edges_in, "edges_dropped": d.edges_dropped, "winding_overflows": d.winding_overflows}

    def _image(self):
        img = ffi.new("ef_image *")
        _check(lib.ef_image_create(img, self.width, self.height), "image")
        return ffi.gc(img, lib.ef_image_destroy)

    @staticmethod
    def _array(img):
        h, w, stride = int(img.height), int(img.width), int(img.stride)
        buf = ffi.buffer(img.px, stride * h)
        a = np.frombuffer(buf, dtype=np.uint8).reshape(h, stride)[:, :4 * w].reshape(h, w, 4)
        return a.copy()

    def render(self, scene, rule=None):
        """The scene composited onto transparent black: (H, W, 4) uint8, premultiplied RGBA."""
        img = self._image()
        ffi.memmove(img.px, b"\0" * (img.stride * img.height), img.stride * img.height)
        _check(lib.ef_scene_render(self._ctx, scene._s, _rule(rule), img), "render")
        return self._array(img)

    def coverage(self, scene, shape=0, rule=None):
        """The coverage masks of one shape: (H, W) uint32, bit s = sample s (docs/spec.md 4)."""
        if not 0 <= shape < len(scene):
            raise IndexError(f"shape {shape} of {len(scene)}")
        out = np.zeros((self.height, self.width), dtype=np.uint32)
        poly = lib.ef_scene_polygon(scene._s, shape)
        r = _rule(rule)
        if r < 0:
            r = int(scene._s.shapes[shape].rule)
        spans = []

        @ffi.callback("void(void *, int32_t, int32_t, int32_t, uint32_t)")
        def on_span(user, y, x, n, mask):
            spans.append((y, x, n, mask))

        pp = ffi.new("ef_polygon *", poly)
        _check(lib.ef_rasterize(self._ctx, pp, r, on_span, ffi.NULL), "coverage")
        for y, x, n, mask in spans:
            out[y, x:x + n] = mask
        return out

    def trace(self, scene, rule=None, interfaces=None):
        """Renders the scene with the cycle-level trace on: a Trace of every interface's
        transactions (docs/microarch.md), the frame's cycles and the image."""
        mask = _mask(interfaces)
        c = ffi.gc(vec.efpy_collect_new(mask), vec.efpy_collect_free)
        if c == ffi.NULL:
            raise MemoryError
        img = self._image()
        ffi.memmove(img.px, b"\0" * (img.stride * img.height), img.stride * img.height)
        cycles = ffi.new("uint64_t *")
        sink = ffi.cast("ef_txn_fn", vec.ef_vec_collect_sink)
        try:
            _check(lib.ef_trace_enable(self._ctx, mask, sink, c), "trace")
            _check(lib.ef_trace_frame_begin(self._ctx), "trace")
            _check(lib.ef_scene_render(self._ctx, scene._s, _rule(rule), img), "trace")
            _check(lib.ef_trace_frame_end(self._ctx, cycles), "trace")
        finally:
            lib.ef_trace_enable(self._ctx, 0, ffi.NULL, ffi.NULL)
        why = ffi.new("char[160]")
        st = vec.efpy_collect_error(c, why, 160)
        if st != 0:
            raise EdgeflagError(f"broken trace: {ffi.string(why).decode()}", status=st)
        return Trace(c, mask, int(cycles[0]), self._array(img), scene, self.samples, _rule(rule))


def render(scene, samples=8, rule=None):
    """Module-level shortcut: Model.for_scene(scene, samples).render(scene, rule)."""
    return Model.for_scene(scene, samples).render(scene, rule)


def coverage(scene, shape=0, samples=8, rule=None):
    return Model.for_scene(scene, samples).coverage(scene, shape, rule)


def trace(scene, samples=8, rule=None, interfaces=None):
    return Model.for_scene(scene, samples).trace(scene, rule, interfaces)


# ------------------------------------------------------------- transactions
class _Transactions:
    """Per-interface typed transactions: t["plot"] is a list of Plot; t.array("plot") the raw
    (n, 1 + words) uint64 records (cycle, payload words least significant first)."""

    def __getitem__(self, iface):
        i = _iface(iface)
        if i not in self._cache:
            self._cache[i] = _decode_records(i, self.array(i))
        return self._cache[i]

    def count(self, iface):
        return len(self.array(iface))

    def __iter__(self):
        return (IFACES[i] for i in range(len(IFACES)) if self.mask >> i & 1)

    def counts(self):
        return {n: self.count(n) for n in self}

    def merged(self):
        """Every transaction in cycle order (ties: interface number), as vectors.bin orders them."""
        allt = []
        for n in self:
            allt.extend(self[n])
        allt.sort(key=lambda t: (t.cycle, t.IFACE))
        return allt


class Trace(_Transactions):
    """The trace of one frame: transactions per interface, `cycles`, `image` (the rendered frame)."""

    def __init__(self, collect, mask, cycles, image, scene, samples, rule):
        self._c, self.mask, self.cycles, self.image = collect, mask, cycles, image
        self.scene, self.samples, self.rule = scene, samples, rule
        self._cache = {}
        self._arrays = {}

    def array(self, iface):
        i = _iface(iface)
        if not self.mask >> i & 1:
            raise KeyError(f"interface {IFACES[i]} was not traced")
        if i not in self._arrays:
            n = ffi.new("size_t *")
            nw = ffi.new("unsigned *")
            p = vec.efpy_collect_records(self._c, i, n, nw)
            if n[0] == 0:
                a = np.zeros((0, 1 + nw[0]), dtype=np.uint64)
            else:
                a = np.frombuffer(ffi.buffer(p, 8 * n[0] * (1 + nw[0])), dtype=np.uint64).reshape(n[0], 1 + nw[0])
                a = a.copy()
            self._arrays[i] = a
        return self._arrays[i]

    def _info(self, dump):
        info = ffi.new("ef_vec_info *")
        name = ffi.new("char[]", self.scene.name.encode())
        info.input = name
        info.width, info.height = self.scene.width, self.scene.height
        info.samples = self.samples
        info.rule = self.rule
        info.seed = 0
        info.cycles = self.cycles
        info.mask = self.mask
        info.dump = 1 if dump else 0
        return info, name

    def write(self, directory, formats=("hex", "bin"), dump=False):
        """Writes IFACE.expected.hex (cmd.stim.hex) / vectors.bin (or, dump=True, the dump names
        IFACE.actual.hex and vectors.actual.bin) with the library's writers; returns the paths.
        No manifest: `edgeflag vectors` is the tool for complete vector sets."""
        os.makedirs(directory, exist_ok=True)
        info, keep = self._info(dump)
        paths = []
        for fmt in formats:
            if fmt == "hex":
                for i in range(len(IFACES)):
                    if not self.mask >> i & 1:
                        continue
                    role = "actual" if dump else ("stim" if i == 0 else "expected")
                    paths.append((os.path.join(directory, f"{IFACES[i]}.{role}.hex"), i))
            elif fmt in ("bin", "vcd"):
                paths.append((os.path.join(directory, f"vectors{'.actual' if dump else ''}.{fmt}"), -1))
            else:
                raise ValueError(f"format {fmt!r}: hex, bin or vcd")
            for p, i in paths:
                if not p.endswith("." + fmt):
                    continue
                rc = vec.efpy_write(p.encode(), fmt.encode(), info, self._c, i)
                if rc != 0:
                    raise EdgeflagError(f"cannot write ({os.strerror(rc) if rc > 0 else 'out of memory'})",
                                        status=-6, file=p)
        del keep
        return [p for p, _ in paths]


class Vectors(_Transactions):
    """A vector file read back (hex: one interface; binary: all recorded ones)."""

    def __init__(self, d, path):
        self.path = path
        self.format = "hex" if d.format == 1 else "bin"
        self.mask = int(d.mask)
        self.width, self.height, self.samples = int(d.width), int(d.height), int(d.samples)
        self.rule = {0: "nonzero", 1: "evenodd", 2: "scene"}.get(int(d.rule))
        self.seed = int(d.seed)
        self._cache = {}
        self._arrays = {}
        for i in range(len(IFACES)):
            sq = d.seq[i]
            n, nw = int(sq.n), int(sq.nw) or 1
            a = np.zeros((n, 1 + nw), dtype=np.uint64)
            if n:
                a[:, 0] = np.frombuffer(ffi.buffer(sq.cycle, 8 * n), dtype=np.uint64)
                a[:, 1:] = np.frombuffer(ffi.buffer(sq.pay, 8 * n * nw), dtype=np.uint64).reshape(n, nw)
            self._arrays[i] = a

    def array(self, iface):
        i = _iface(iface)
        if not self.mask >> i & 1:
            raise KeyError(f"{self.path} holds no {IFACES[i]} transactions")
        return self._arrays[i]


def read_vectors(path, interface=None):
    """Reads a hex file (its interface from its header, else its name, else `interface`) or a
    binary stream (.bin); raises VectorsError naming file:line:col or the record."""
    path = os.fspath(path)
    d = ffi.new("ef_vec_dump *")
    err = ffi.new("ef_vec_read_error *")
    hint = _iface(interface) if interface is not None else -1
    if hint < 0:  # as edgeflag check: the interface the file's name starts with
        stem = os.path.basename(path).split(".", 1)[0]
        hint = lib.ef_iface_find(stem.encode())
    st = vec.ef_vec_read_path(path.encode(), ffi.NULL, -1, hint, d, err)
    try:
        if st != 0:
            buf = ffi.new("char[1024]")
            vec.ef_vec_read_error_format(err, buf, 1024)
            raise VectorsError(ffi.string(err.msg).decode(errors="replace"), status=st,
                               file=ffi.string(err.file).decode(errors="replace"), line=int(err.line),
                               column=int(err.col), record=int(err.record), offset=int(err.offset),
                               text=ffi.string(buf).decode(errors="replace"))
        return Vectors(d, path)
    finally:
        vec.ef_vec_dump_destroy(d)


# ------------------------------------------------------------------ checker
Mismatch = collections.namedtuple("Mismatch", "place iface cycle kind text")


class CheckReport:
    """edgeflag check's verdict as objects: status (ef_check_status: 0 pass, 1 fail, 2 input, 3 out of memory), counts,
    mismatches (parsed report lines) and the status lines."""

    def __init__(self, status, res, report, status_text):
        self.status = status
        self.passed = status == 0
        self.mismatch_count = int(res.mismatches)
        self.reported = int(res.reported)
        self.compared = int(res.compared)
        self.transactions = int(res.transactions)
        self.missing = int(res.missing)
        self.lines = [ln for ln in report.splitlines() if ln]
        self.status_lines = [ln for ln in status_text.splitlines() if ln]
        self.mismatches = [self._parse(ln) for ln in self.lines]

    @staticmethod
    def _parse(line):
        # PLACE: IFACE: cycle C[, ...]: WHAT  (PLACE may hold ': ' in "FILE: record N (...)")
        for name in IFACES:
            key = f": {name}: cycle "
            k = line.find(key)
            if k >= 0:
                rest = line[k + len(key):]
                num = ""
                for ch in rest:
                    if not ch.isdigit():
                        break
                    num += ch
                what = rest.split(": ", 1)[1] if ": " in rest else rest
                kind = what.split(":", 1)[0]
                return Mismatch(line[:k], name, int(num) if num else None, kind, line)
        return Mismatch("", None, None, "other", line)

    def __bool__(self):
        return self.passed

    def __repr__(self):
        return (f"CheckReport(status={self.status}, mismatches={self.mismatch_count}, "
                f"transactions={self.transactions}, compared={self.compared})")


def check(expected, actual, cycles=True, errors=20, interfaces=None, allow_missing=None, name=None):
    """Runs the verifier (rtl_vectors/ef_check.h) on two files or directories."""
    o = ffi.new("ef_check_opts *")
    vec.ef_check_opts_defaults(o)
    keep = [ffi.new("char[]", os.fspath(expected).encode()), ffi.new("char[]", os.fspath(actual).encode())]
    o.expected, o.actual = keep[0], keep[1]
    o.errors = errors
    o.cycles = 1 if cycles else 0
    if interfaces is not None:
        o.only = _mask(interfaces)
    if allow_missing is not None:
        o.allow_missing = _mask(allow_missing)
    if name:
        keep.append(ffi.new("char[]", name.encode()))
        o.name = keep[-1]
    res = ffi.new("ef_check_result *")
    rep = ffi.new("char **")
    sta = ffi.new("char **")
    rc = vec.efpy_check(o, res, rep, sta)
    try:
        rtext = ffi.string(rep[0]).decode(errors="replace") if rep[0] != ffi.NULL else ""
        stext = ffi.string(sta[0]).decode(errors="replace") if sta[0] != ffi.NULL else ""
        return CheckReport(rc, res, rtext, stext)
    finally:
        vec.efpy_free(rep[0])
        vec.efpy_free(sta[0])
        vec.ef_check_result_destroy(res)


# ------------------------------------------------------------- model stream
class StreamMismatch(AssertionError):
    """The model stream's scoreboard found a difference: `iface`, `cycle`, the expected and
    actual transactions, and the library's message (every decoded field, differing ones `*`)."""

    def __init__(self, message, iface=None, cycle=None, expected=None, actual=None):
        super().__init__(message)
        self.message, self.iface, self.cycle, self.expected, self.actual = message, iface, cycle, expected, actual


class ModelStream:
    """The model fed one `cmd` word at a time (dv/dpi/ef_model_stream.h, docs/dpi.md):
    each interface's expected transactions come out with the reference schedule's cycle stamps.
    `rule` overrides every SHAPE's rule (None: each command's own)."""

    OK, EMPTY, END, MISMATCH = 0, 1, 2, 3

    def __init__(self, samples=8, width_max=16384, height_max=16384, edges_max=1 << 22, rule=None,
                 interfaces=None):
        p = ffi.new("ef_mstream_params *")
        vec.ef_mstream_params_default(p)
        p.samples = _samples(samples)
        p.width_max, p.height_max, p.edges_max = width_max, height_max, edges_max
        p.rule = _rule(rule)
        p.ifaces = _mask(interfaces)
        m = ffi.new("ef_mstream **")
        st = vec.ef_mstream_create(m, p)
        if st != 0:
            raise EdgeflagError(ffi.string(vec.ef_mstream_strerror(st)).decode(), status=st)
        self._m = ffi.gc(m[0], vec.ef_mstream_destroy)
        self._t = ffi.new("ef_txn *")
        self.samples = samples

    def _msg(self):
        return ffi.string(vec.ef_mstream_message(self._m)).decode(errors="replace")

    def cmd(self, c):
        """Feeds one command: a Cmd transaction or (op, a, b, c, d)."""
        if isinstance(c, tuple) and not isinstance(c, _TxnBase):
            op, a, b, cc, d = c
        else:
            op, a, b, cc, d = c.op, c.a, c.b, c.c, c.d
        st = vec.ef_mstream_cmd_fields(self._m, op, _s24(a), _s24(b), _s24(cc), _s24(d))
        if st < 0:
            raise EdgeflagError(self._msg() or ffi.string(vec.ef_mstream_strerror(st)).decode(), status=st)

    def pop(self, iface):
        """The next expected transaction of iface, None when none is queued yet (feed more
        commands), or StopIteration's sentinel ModelStream.END after the frame's last."""
        st = vec.ef_mstream_pop(self._m, _iface(iface), self._t)
        if st == 0:
            return _txn_from_c(self._t)
        if st == 1:
            return None
        if st == 2:
            return ModelStream.END
        raise EdgeflagError(self._msg() or "pop", status=st)

    def peek(self, iface):
        """pop() without removing the transaction."""
        st = vec.ef_mstream_peek(self._m, _iface(iface), self._t)
        if st == 0:
            return _txn_from_c(self._t)
        if st == 1:
            return None
        if st == 2:
            return ModelStream.END
        raise EdgeflagError(self._msg() or "peek", status=st)

    def pending(self, iface):
        return int(vec.ef_mstream_pending(self._m, _iface(iface)))

    def expect(self, actual, check_cycle=True):
        """Scoreboard step: compares `actual` (a typed transaction) with the next expected one of
        its interface.  Returns True when equal, None when the model has none yet; raises
        StreamMismatch on a difference or an extra transaction."""
        t = self._t
        t.cycle = actual[0]
        t.iface = actual.IFACE
        p = actual.payload()
        t.w[0] = p & 0xFFFFFFFFFFFFFFFF
        if p >> 64:
            t.w[1] = (p >> 64) & 0xFFFFFFFFFFFFFFFF
            t.w[2] = (p >> 128) & 0xFFFFFFFFFFFFFFFF
            t.w[3] = p >> 192
        else:
            t.w[1] = t.w[2] = t.w[3] = 0
        st = vec.ef_mstream_expect(self._m, t, 1 if check_cycle else 0)
        if st == 0:
            return True
        if st == 1:
            return None
        if st in (2, 3):
            raise StreamMismatch(self._msg(), iface=actual.NAME, cycle=actual.cycle, actual=actual)
        raise EdgeflagError(self._msg(), status=st)

    def expect_done(self, iface):
        st = vec.ef_mstream_expect_done(self._m, _iface(iface))
        if st != 0:
            raise StreamMismatch(self._msg(), iface=IFACES[_iface(iface)])

    def commands(self):
        return int(vec.ef_mstream_commands(self._m))

    def frame_cycles(self):
        c = ffi.new("uint64_t *")
        return int(c[0]) if vec.ef_mstream_frame_cycles(self._m, c) else None

    def frame(self):
        img = vec.ef_mstream_frame(self._m)
        return None if img == ffi.NULL else Model._array(img)


ModelStream.END = object()


def _s24(v):
    v = int(v) & 0xFFFFFF
    return v - (1 << 24) if v >> 23 else v


# --------------------------------------------------------------------- gen
GenCase = collections.namedtuple("GenCase", "number name category directed seed scene text")


def gen_cases(level=1, seed=20070101, select=None):
    """The `edgeflag gen` regression cases (docs/gen.md) as Scenes: yields GenCase for every case
    number in `select` (default: all) of the level."""
    cfg = ffi.new("ef_gen_config *")
    _check(vec.ef_gen_config_defaults(cfg, level), "gen")
    cfg.seed = seed
    total = vec.ef_gen_total(cfg)
    for k in (range(total) if select is None else select):
        gc = ffi.new("ef_gen_case *")
        try:
            _check(vec.ef_gen_build(cfg, k, gc), f"gen case {k}")
            txt = ffi.new("ef_gen_text *")
            st = vec.ef_gen_format(cfg, gc, txt)
            text = ffi.string(txt.data).decode() if st == 0 and txt.data != ffi.NULL else None
            vec.ef_gen_text_destroy(txt)
            name = ffi.string(gc.name).decode()
            cat = ffi.string(vec.ef_gen_category_name(gc.category)).decode()
            # a private copy of the case's scene, owned by a Scene
            sc = Scene(int(gc.scene.width), int(gc.scene.height))
            sc.name = f"case_{k:06d}.scene"
            s = gc.scene
            for i in range(s.nshapes):
                sh = s.shapes[i]
                col = ffi.new("ef_rgba8 *", (sh.color.r, sh.color.g, sh.color.b, sh.color.a))
                _check(lib.ef_scene_begin_shape(sc._s, sh.rule, col[0]))
                for c in range(sh.first_contour, sh.first_contour + sh.ncontours):
                    n = s.start[c + 1] - s.start[c]
                    _check(lib.ef_scene_add_contour(sc._s, s.points + s.start[c], n))
            yield GenCase(k, name, cat, bool(gc.directed), int(gc.case_seed), sc, text)
        finally:
            vec.ef_gen_case_destroy(gc)
