"""The Python package against the C library's own tools: every comparison is with bytes the CLI
wrote or with the C structures' sizes, never with numbers written here."""
import decimal
import fractions
import pathlib
import re

import numpy as np
import pytest

import edgeflag as ef
from edgeflag._ffi import ffi, vec


def read_pam(path):
    data = pathlib.Path(path).read_bytes()
    head, _, body = data.partition(b"ENDHDR\n")
    f = dict(ln.split(b" ", 1) for ln in head.splitlines()[1:] if b" " in ln)
    w, h, d = int(f[b"WIDTH"]), int(f[b"HEIGHT"]), int(f[b"DEPTH"])
    return np.frombuffer(body, dtype=np.uint8).reshape(h, w, d)


def test_layout_matches_the_c_compiler():
    names = re.findall(r"typedef struct (\w+) \{", ef._ffi.CDEF + ef._ffi.CDEF_VEC)
    assert len(names) >= 20
    for n in names:
        c = vec.efpy_sizeof(n.encode())
        assert c != 0, f"efpy_sizeof does not know {n}"
        assert ffi.sizeof(n) == c, f"{n}: cffi {ffi.sizeof(n)} bytes, C {c}"


def test_interfaces_are_the_vectors_table(cli, tmp_path):
    # the hex headers' `word` lines name every field and width: the types must say the same
    cli("vectors", pathlib.Path(ef.__file__).parents[2] / "tests/data/svg/lion.svg", "-o", tmp_path,
        "--size", "32x24", "--formats", "hex")
    assert ef.IFACES == ["cmd", "seg", "et_wr", "et_rd", "plot", "span", "pix"]
    for name in ef.IFACES:
        role = "stim" if name == "cmd" else "expected"
        text = (tmp_path / f"{name}.{role}.hex").read_text()
        word = re.search(r"^// word (\d+) bits: (.*)$", text, re.M)
        cls = ef.TXN[name]
        assert int(word.group(1)) == 48 + cls.WIDTH
        parts = word.group(2).split()[1:]  # after cycle[..]
        names = [re.match(r"(\w+)\[", p).group(1) for p in parts]
        assert names == [f.name for f in cls.FIELDS]
        assert cls._fields == ("cycle", *names)


@pytest.mark.parametrize("name,samples,rule", [("tiger", 8, None), ("lion", 16, "evenodd"),
                                               ("stress_pixi_figure8", 32, "nonzero")])
def test_render_equals_cli_bytes(cli, svg, tmp_path, name, samples, rule):
    out = tmp_path / "f.pam"
    args = ["render", svg / f"{name}.svg", "-o", out, "--samples", samples, "--size", "160x120"]
    if rule:
        args += ["--rule", rule]
    cli(*args)
    want = read_pam(out)
    got = ef.render(ef.Scene.load(svg / f"{name}.svg", fit=(160, 120)), samples=samples, rule=rule)
    assert got.dtype == np.uint8 and got.shape == want.shape
    assert got.tobytes() == want.tobytes()


def test_trace_files_equal_cli_vectors(cli, svg, tmp_path):
    cli("vectors", svg / "lion.svg", "-o", tmp_path / "cli", "--size", "48x36", "--samples", "16",
        "--formats", "hex,bin,vcd")
    tr = ef.trace(ef.Scene.load(svg / "lion.svg", fit=(48, 36)), samples=16)
    paths = tr.write(tmp_path / "py", formats=("hex", "bin", "vcd"))
    assert len(paths) == 9
    for p in paths:
        p = pathlib.Path(p)
        assert p.read_bytes() == (tmp_path / "cli" / p.name).read_bytes(), p.name
    # read back: the same typed transactions, from the hex files and from the binary stream
    b = ef.read_vectors(tmp_path / "cli" / "vectors.bin")
    assert (b.width, b.height, b.samples) == (48, 36, 16)
    for name in ef.IFACES:
        assert b[name] == tr[name], name
        role = "stim" if name == "cmd" else "expected"
        assert ef.read_vectors(tmp_path / "cli" / f"{name}.{role}.hex")[name] == tr[name]
    assert sum(tr.counts().values()) > 1000


def test_check_report_as_objects(svg, tmp_path):
    tr = ef.trace(ef.Scene.load(svg / "tiger.svg", fit=(40, 30)), samples=8)
    tr.write(tmp_path / "exp", formats=("hex",))
    tr.write(tmp_path / "act", formats=("hex",), dump=True)
    ok = ef.check(tmp_path / "exp", tmp_path / "act", allow_missing=None)
    assert ok.passed and ok.status == 0 and ok.mismatch_count == 0
    assert ok.transactions == sum(n for k, n in tr.counts().items() if k != "cmd")
    # one pix word changed: one mismatch on pix at that word's cycle, the rgba field marked
    pix = tmp_path / "act" / "pix.actual.hex"
    lines = pix.read_text().splitlines()
    k = next(i for i, ln in enumerate(lines) if not ln.startswith("//")) + 5
    word = int(lines[k], 16) ^ 1
    lines[k] = format(word, "0%dx" % len(lines[k]))
    pix.write_text("\n".join(lines) + "\n")
    bad = ef.check(tmp_path / "exp", tmp_path / "act")
    assert not bad and bad.status == 1 and bad.mismatch_count == 1
    m = bad.mismatches[0]
    assert m.iface == "pix" and m.cycle == word >> ef.Pix.WIDTH and m.kind == "fields differ"
    assert "rgba=" in m.text and "*" in m.text


def test_errors_carry_file_line_column(tmp_path):
    p = tmp_path / "bad.svg"
    p.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">\n'
                 '  <path d="M 0 0 L 5 Q"/>\n</svg>\n')
    with pytest.raises(ef.EdgeflagError) as e:
        ef.Scene.load(p)
    assert e.value.file.endswith("bad.svg") and e.value.line == 2 and e.value.column > 0 and e.value.message
    with pytest.raises(ef.EdgeflagError) as e:
        ef.Scene.from_text("scene 10 10\nshape nonzero 0 0 0 255\ncontour 0 0 1 x 2 2\n", name="t.scene")
    assert (e.value.file, e.value.line) == ("t.scene", 3) and e.value.column > 1
    h = tmp_path / "pix.actual.hex"
    h.write_text("// a dump\n00000000000000000000000000x\n")
    with pytest.raises(ef.VectorsError) as e:
        ef.read_vectors(h)
    assert e.value.line == 2 and e.value.column > 0 and "unknown" in e.value.message


def test_no_float_enters_the_model():
    s = ef.Scene(8, 8)
    with pytest.raises(TypeError):
        s.add_shape([[(0.5, 0), (4, 0), (4, 4)]])
    with pytest.raises(ValueError):
        s.add_shape([[(fractions.Fraction(1, 3), 0), ("4", 0), ("4", "4")]])
    # exact decimals go through the library's parser: the same points as the .scene reader's
    s.add_shape([[(decimal.Decimal("0.5"), "0"), (fractions.Fraction(33, 8), 0), ("4.001953125", "-1.5")]])
    t = ef.Scene.from_text("scene 8 8\nshape nonzero 0 0 0 255\ncontour 0.5 0 4.125 0 4.001953125 -1.5\n")
    assert s.shapes == t.shapes
    # integers are Q16.8 as they are
    u = ef.Scene(8, 8).add_shape([[(128, 0), (1056, 0), (1025, -384)]])
    assert u.shapes == t.shapes


def test_coverage_masks_and_several_models(svg):
    sc = ef.Scene(20, 10).add_shape([[("1.25", "0.5"), ("18.5", "2"), ("7", "9.75")]], color=(255, 255, 255, 255))
    models = {n: ef.Model(20, 10, n) for n in (8, 16, 32)}
    # interleaved use of three models: each equals a fresh one alone
    imgs = {n: models[n].render(sc) for n in models}
    masks = {n: models[n].coverage(sc) for n in models}
    for n in (8, 16, 32):
        assert (imgs[n] == ef.Model(20, 10, n).render(sc)).all()
        pop = np.vectorize(lambda m: bin(int(m)).count("1"))(masks[n])
        alpha = (255 * pop + n // 2) // n  # docs/spec.md 7
        assert (alpha == imgs[n][..., 3]).all() and alpha.max() == 255


def test_model_stream_matches_trace(svg):
    # two overlapping squares wound the same way: winding 2 where they overlap
    sc = ef.Scene(24, 18).add_shape([[("2", "2"), ("14", "2"), ("14", "12")], [("8", "6"), ("20", "6"), ("20", "16")]])
    tr = ef.trace(sc, samples=8)
    wrong = "nonzero" if sc.shapes[0][0] == "evenodd" else "evenodd"
    for rule_ok in (True, False):
        m = ef.ModelStream(samples=8, rule=None if rule_ok else wrong)
        for c in tr["cmd"]:
            m.cmd(c)
        try:
            for name in ef.IFACES[1:]:
                for t in tr[name]:
                    assert m.expect(t) is True
                m.expect_done(name)
            assert rule_ok
        except ef.StreamMismatch as e:
            assert not rule_ok and e.iface in ("span", "pix") and "cycle" in e.message
    assert (m.frame() is not None)


def test_commands_equal_trace_cmd(svg):
    sc = ef.Scene.load(svg / "lion.svg", fit=(30, 30))
    tr = ef.trace(sc)
    assert [t[1:] for t in sc.commands()] == [t[1:] for t in tr["cmd"]]


def test_gen_cases_equal_cli(cli, tmp_path):
    cli("gen", "-o", tmp_path)
    n = 0
    for case in ef.gen_cases(level=1, select=[0, 7, 100, 250]):
        assert case.text == (tmp_path / f"case_{case.number:06d}.scene").read_text()
        assert (ef.render(case.scene) == ef.render(ef.Scene.load(tmp_path / case.scene.name))).all()
        n += 1
    assert n == 4
