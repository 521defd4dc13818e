"""pytest entry of the cocotb bench (cocotb.runner): builds ef_raster under Verilator and Icarus and
runs plans of cases through dv/cocotb/test_ef_raster.py.

    EF_COCOTB_SET=slice    (make test-cocotb, in make test): a slice of shared SVGs and gen cases
                           under both simulators, back-pressure, three injected RTL faults, one
                           model-side mismatch and a run with nothing to check
    EF_COCOTB_SET=regress  (make cocotb-regress): every level-1 gen case at NS 8/16/32 under the
                           three rule settings, in Verilator, plus the slice's checks

Every plan's results are checked here again: the expected outcome of every case, the interface
and field of every expected failure, and that a passing case checked transactions on every
observed interface it had.  The merged coverage report goes to build/cocotb/SET/coverage.txt.
"""

import json
import os
import pathlib
import re
import subprocess
import time

import pytest
from cocotb.runner import get_runner

import edgeflag as ef

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("EF_BUILD", ROOT / "build"))
SET = os.environ.get("EF_COCOTB_SET", "slice")
OUT = BUILD / "cocotb" / SET
SVG = ROOT / "tests" / "data" / "svg"
RTL = [ROOT / "rtl" / f for f in ("ef_raster.v", "ef_dec.v", "ef_setup.v", "ef_div.v", "ef_etm.v", "ef_aet.v",
                                  "ef_plot.v", "ef_slb_fill.v", "ef_slb_ram.v", "ef_cov.v")]
HERE = pathlib.Path(__file__).resolve().parent
WM, HM, EM = 256, 256, 16384
OBSERVED = ("seg", "et_wr", "et_rd", "plot", "span", "pix")
_built = {}
# The planted faults are RTL variants (dv/rtl-variant.sh, docs/testing.md "RTL variants"): rtl/
# holds no fault define.
FAULT_RECIPE = {"EF_FAULT_ROOKS": "rooks", "EF_FAULT_TOPCLIP": "topclip", "EF_FAULT_SPAN": "span",
                "EF_FAULT_PAD": "pad"}


def rtl_folder(define):
    """rtl/, or the RTL variant with the planted fault named by define."""
    if not define:
        return ROOT / "rtl"
    d = BUILD / "cocotb" / f"rtl-{FAULT_RECIPE[define]}"
    subprocess.run(["bash", str(ROOT / "dv" / "rtl-variant.sh"), str(d), FAULT_RECIPE[define]], check=True)
    return d


def build(sim, ns, define=None, emax=EM):
    key = (sim, ns, define, emax)
    if key in _built:
        return _built[key]
    d = BUILD / "cocotb" / f"sim-{SET}" / f"{sim}_ns{ns}{'_' + define if define else ''}_e{emax}"
    r = get_runner(sim)
    params = {"NS": ns, "W_MAX": WM, "H_MAX": HM, "E_MAX": emax}
    args = []
    if sim == "verilator":
        args = ["-Wno-fatal", "-O2", "--x-assign", "fast", "--x-initial", "fast"]
    t0 = time.perf_counter()
    src = rtl_folder(define)
    r.build(verilog_sources=[src / f.name for f in RTL], includes=[src], hdl_toplevel="ef_raster",
            parameters=params, build_args=args, build_dir=d, always=False)
    _built[key] = (r, d, params, time.perf_counter() - t0)
    return _built[key]


def run(sim, ns, cases, tag, define=None, emax=EM, expect_ok=True, monkeypatch=None):
    r, d, params, _ = build(sim, ns, define, emax)
    OUT.mkdir(parents=True, exist_ok=True)
    res = OUT / f"{tag}.json"
    plan = OUT / f"{tag}.plan.json"
    plan.write_text(json.dumps({"sim": sim, "params": params, "cases": cases, "results": str(res),
                                "dump_dir": str(OUT / "dumps" / tag)}, indent=1))
    if res.exists():
        res.unlink()
    env = {"EF_COCOTB_PLAN": str(plan), "PYTHONPATH": os.pathsep.join([str(HERE), str(ROOT / "python"),
                                                                        os.environ.get("PYTHONPATH", "")]),
           "EDGEFLAG_LIBDIR": str(BUILD)}
    t0 = time.perf_counter()
    if expect_ok:
        r.test(test_module="test_ef_raster", hdl_toplevel="ef_raster", build_dir=d, test_dir=OUT / tag,
               extra_env=env, parameters=params, results_xml=f"{tag}.xml")
    else:
        # the simulation is expected to report a failing case: check the results here, not in cocotb
        monkeypatch.delenv("PYTEST_CURRENT_TEST", raising=False)
        r.test(test_module="test_ef_raster", hdl_toplevel="ef_raster", build_dir=d, test_dir=OUT / tag,
               extra_env=env, parameters=params, results_xml=f"{tag}.xml")
    wall = time.perf_counter() - t0
    assert res.is_file(), f"{tag}: the bench wrote no results (it did not run)"
    out = json.loads(res.read_text())
    assert len(out["cases"]) == len(cases), f"{tag}: {len(out['cases'])} of {len(cases)} cases ran"
    for c, r_ in zip(cases, out["cases"]):
        if r_["expect"] == "pass":
            assert r_["outcome"] == "pass", f"{tag}: {r_['name']}: {r_.get('message')}"
            for n in OBSERVED:
                assert r_["checked"][n] > 0 or c.get("may_lack", False), \
                    f"{tag}: {r_['name']}: no {n} transaction checked"
        else:
            assert r_["outcome"] == "fail", f"{tag}: {r_['name']}: passed, but the bench must fail"
    summary = {"sim": sim, "ns": ns, "define": define, "wall": wall, "cases": out["cases"]}
    (OUT / f"{tag}.summary.json").write_text(json.dumps(summary, indent=1))
    return out["cases"]


def svg_case(name, size=(24, 18), rule="scene", **kw):
    return {"name": f"svg_{name}_{rule}", "file": str(SVG / f"{name}.svg"), "size": list(size), "rule": rule, **kw}


def gen_case(k, rule="scene", **kw):
    return {"name": f"gen_{k}_{rule}", "gen": k, "rule": rule, "may_lack": True, **kw}


# ------------------------------------------------------------------ the slice
# Small gen cases (a few hundred to a few thousand cycles: Icarus runs the whole pipeline at about a
# thousand cycles a second) and shared SVGs at 24x18 in Verilator.
def directed_text():
    """A scene for cover points the shared SVGs and the small gen cases miss: an edge wholly above
    the canvas (clip.drop_above), a near-horizontal edge with |qs| >= 2^20 (div.qs_big: dY = 1/256 px
    across sample row 0, dX = 256 px), a shape of alpha 0 (shape.alpha0) and one of 4096 EDGE
    commands (shape.edges_4096: a zigzag of 4096 vertices, 1/256 px a step down)."""
    zig = " ".join(f"{1 if i % 2 == 0 else 7} {ef.q8(i // 2)}" for i in range(4096))
    return ("scene 8 8\n"
            "shape nonzero 255 0 0 0\ncontour 1 -3 6 -2 3 -1\n"
            "shape nonzero 0 255 0 255\ncontour -100 0.0625 156 0.06640625 2 5\n"
            f"shape evenodd 0 0 255 200\ncontour {zig}\n")


ICARUS_GEN = {8: [(0, "scene"), (22, "nonzero"), (48, "evenodd"), (52, "scene"), (30, "nonzero")],
              16: [(4, "evenodd"), (14, "scene"), (51, "nonzero"), (74, "scene")],
              32: [(1, "nonzero"), (19, "evenodd"), (55, "scene"), (104, "nonzero")]}


@pytest.mark.skipif(SET != "slice", reason="slice only")
def test_verilator_slice():
    cases = [svg_case("lion", rule="nonzero"), svg_case("stress_pixi_fill_rule_star_nonzero"),
             svg_case("stress_pixi_figure8", rule="evenodd"), svg_case("tiger", rule="evenodd", size=(16, 12)),
             gen_case(36, "scene"), gen_case(38, "scene"), gen_case(44, "nonzero"), gen_case(46, "evenodd"),
             gen_case(47, "scene"), gen_case(52, "nonzero"), gen_case(17, "scene"), gen_case(35, "scene"),
             {"name": "directed_holes", "scene_text": directed_text(), "may_lack": True},
             svg_case("lion", rule="scene", bp_seed=7, size=(12, 9))]
    run("verilator", 8, cases, "verilator_ns8")


@pytest.mark.skipif(SET != "slice", reason="slice only")
@pytest.mark.parametrize("ns", [8, 16, 32])
def test_icarus_slice(ns):
    cases = [gen_case(k, rule) for k, rule in ICARUS_GEN[ns]]
    if ns == 8:
        cases.append(gen_case(2, "scene", bp_seed=11))
    run("icarus", ns, cases, f"icarus_ns{ns}")


def first_difference(dump, stop):
    """The first difference between the bench's dump and the expected vectors by a plain in-order
    comparison of the hex words of each interface (independent of the bench's scoreboard and of
    edgeflag check): (interface, cycle), the cycle being the earlier of the two words that first
    differ, or of the expected word the dump lacks when its cycle is not after `stop` (the bench
    stopped there, so later words were never observed)."""
    best = None
    for n in OBSERVED:
        words = []
        for f in (pathlib.Path(dump) / "expected" / f"{n}.expected.hex", pathlib.Path(dump) / f"{n}.actual.hex"):
            words.append([int(ln, 16) for ln in f.read_text().split("\n") if ln and not ln.startswith("//")])
        exp, act = words
        width = ef.TXN[n].WIDTH
        for k in range(max(len(exp), len(act))):
            e = exp[k] if k < len(exp) else None
            a = act[k] if k < len(act) else None
            if e == a:
                continue
            cyc = min(w >> width for w in (e, a) if w is not None)
            if a is None and cyc > stop:
                break
            if best is None or cyc < best[1]:
                best = (n, cyc)
            break
    return best


FAULTS = [  # define, case, interface, a field the fault changes (as tests/rtl/rtl-test.sh)
    ("EF_FAULT_ROOKS", svg_case("tiger", size=(16, 12)), "plot", "q"),
    ("EF_FAULT_TOPCLIP", {"name": "outside_crossing", "scene_text":
                          "scene 12 10\nshape nonzero 255 0 0 255\ncontour 1 -5 11 3 6 9.5\n"}, "et_wr", "r0"),
    ("EF_FAULT_SPAN", svg_case("tiger", size=(16, 12)), "span", "len"),
    ("EF_FAULT_PAD", svg_case("tiger", rule="nonzero", size=(16, 12)), "span", "mask"),
]


@pytest.mark.skipif(SET == "measure", reason="a measurement")
@pytest.mark.parametrize("define,case,iface,field", FAULTS, ids=[f[0] for f in FAULTS])
def test_rtl_fault_is_caught(define, case, iface, field, monkeypatch):
    c = dict(case, expect="fail", dump=True, name=f"{define}_{case['name']}")
    (r,) = run("icarus", 8, [c], f"fault_{define}", define=define, expect_ok=False, monkeypatch=monkeypatch)
    assert r["iface"] == iface, f"{define}: the bench stopped on {r['iface']}, not {iface}: {r['message']}"
    assert f"{field}=" in r["message"] and re.search(rf"\b{field}=[^ ;]*\*", r["message"]), \
        f"{define}: field {field} not marked: {r['message']}"
    first = first_difference(r["dump"], r["cycle"])
    assert first == (iface, r["cycle"]), f"{define}: the bench stopped on {iface} at cycle {r['cycle']}, the " \
        f"files first differ on {first}"
    chk = ef.check(pathlib.Path(r["dump"]) / "expected", r["dump"], interfaces=OBSERVED)
    assert chk.status == 1 and chk.mismatch_count > 0, chk


@pytest.mark.skipif(SET == "measure", reason="a measurement")
def test_model_side_mismatches_and_nothing_checked(monkeypatch):
    """Three runs that must fail, in one simulation: the model told the wrong rule (the first
    difference is the SHAPE command's rule field `a` on cmd: the model's cmd carries it), the
    wrong sample count (the DUT is built for NS 8: `r0` on et_wr) and an empty frame (nothing to
    check on any observed interface is a failure, not a pass)."""
    text = "scene 24 18\nshape nonzero 0 0 255 255\ncontour 2 2 14 2 14 12\ncontour 8 6 20 6 20 16\n"
    cases = [{"name": "model_wrong_rule", "expect": "fail", "model_rule": "evenodd", "scene_text": text},
             {"name": "model_wrong_samples", "expect": "fail", "model_samples": 16, "scene_text": text},
             {"name": "empty_frame", "expect": "fail", "scene_text": "scene 8 8\n"}]
    r = run("icarus", 8, cases, "model_side", expect_ok=False, monkeypatch=monkeypatch)
    for res, iface, field in zip(r[:2], ("cmd", "et_wr"), ("a", "r0")):
        assert res["iface"] == iface, res["message"]
        assert re.search(rf"\b{field}=[^ ;]*\*", res["message"]) and f"cycle {res['cycle']}" in res["message"], \
            res["message"]
    assert "no transaction was checked" in r[2]["message"], r[2]["message"]


# -------------------------------------------------------------- the long set
@pytest.mark.skipif(SET != "regress", reason="make cocotb-regress")
@pytest.mark.parametrize("ns", [8, 16, 32])
def test_regress_level1(ns):
    """Every level-1 gen case whose canvas fits the bench's 256x256 at this NS, the rule setting
    rotating over scene/nonzero/evenodd with the case number.  EF_COCOTB_MAX_CYCLES=C leaves out the
    cases longer than C cycles (counted and printed), EF_COCOTB_SLICE=K keeps every Kth case."""
    skip = {"canvas-max", "zigzag-4096", "same-cell-4096"}  # over the bench's W_MAX/H_MAX, or slow
    cap = int(os.environ.get("EF_COCOTB_MAX_CYCLES", "0"))
    every = int(os.environ.get("EF_COCOTB_SLICE", "1"))
    rules = ("scene", "nonzero", "evenodd")
    cases, left_out, empty = [], [], []
    for c in ef.gen_cases(level=1):
        if any(c.name.startswith(s) for s in skip) or c.scene.width > WM or c.scene.height > HM:
            continue
        if c.number % every:
            continue
        rule = rules[(c.number + ns // 8) % 3]
        if cap and ef.trace(c.scene, samples=ns, rule=None if rule == "scene" else rule,
                            interfaces=["cmd"]).cycles > cap:
            left_out.append(c.number)
            continue
        if sum(ef.trace(c.scene, samples=ns, interfaces=["seg", "pix"]).counts().values()) == 0:
            empty.append(c.number)  # a frame with nothing to check: the bench would (rightly) fail it
            continue
        cases.append(gen_case(c.number, rule))
    print(f"regress NS {ns}: {len(cases)} cases, {len(left_out)} left out over {cap} cycles: {left_out}, "
          f"{len(empty)} with nothing to check: {empty}")
    (OUT / f"regress_ns{ns}.left_out.json").parent.mkdir(parents=True, exist_ok=True)
    (OUT / f"regress_ns{ns}.left_out.json").write_text(json.dumps({"cap": cap, "cases": left_out, "empty": empty}))
    run("verilator", ns, cases, f"regress_ns{ns}")


@pytest.mark.skipif(SET != "measure", reason="dv/cocotb/measure.sh")
def test_measure():
    size = [int(v) for v in os.environ.get("EF_MEASURE_SIZE", "64x48").split("x")]
    c = {"name": "measure", "file": os.environ.get("EF_MEASURE_SVG", str(SVG / "tiger.svg")), "size": size}
    run("verilator", 8, [c], "measure")


@pytest.mark.skipif(SET == "measure", reason="a measurement")
def test_coverage_model_agrees_with_edgeflag_coverage(tmp_path):
    """One coverage model: the bench's (ef_coverage.py, fed the model's transactions in cycle order,
    as its monitors see them from a DUT that passes) and `edgeflag coverage`'s (cli/cmd_coverage.c,
    issue 27) give the same count for every point of points.tsv on the same vectors."""
    from ef_coverage import CoverageModel
    runs = [(ef.Scene.load(SVG / f"{f}.svg", fit=(24, 18)), n, r) for f, n, r in
            [("lion", 8, None), ("tiger", 16, "evenodd"), ("stress_pixi_fill_rule_star_nonzero", 32, "nonzero"),
             ("antiloop2", 8, None)]]
    runs += [(c.scene, n, None) for c in ef.gen_cases(level=1, select=[0, 17, 22, 35, 36, 44, 47, 52, 74])
             for n in (8, 32)]
    compared = 0
    for k, (scene, n, rule) in enumerate(runs):
        tr = ef.trace(scene, samples=n, rule=rule)
        d = tmp_path / str(k)
        tr.write(d, formats=("hex",))
        cm = CoverageModel(n, EM)
        for t in tr.merged():
            cm(t)
        p = subprocess.run([str(BUILD / "edgeflag"), "coverage", str(d)], capture_output=True, text=True)
        assert p.returncode == 0, p.stderr
        theirs = {}
        for ln in p.stdout.splitlines():
            f = ln.split()
            if len(f) >= 3 and f[1] in cm.hits:
                theirs[f[1]] = int(f[2])
        assert set(theirs) == set(cm.hits), "the two tools list different points"
        diff = {x: (cm.hits[x], theirs[x]) for x in cm.hits if cm.hits[x] != theirs[x]}
        assert not diff, f"run {k} (NS {n}): bench vs edgeflag coverage: {diff}"
        compared += sum(1 for v in theirs.values() if v)
    assert compared > 100


# ------------------------------------------------------------------ the report
@pytest.mark.skipif(SET == "measure", reason="no report for a measurement")
def test_zz_coverage_report():
    from ef_coverage import load_points
    points = load_points()
    total = {p[0]: 0 for p in points}
    runs = sorted(OUT.glob("*.coverage.json"))
    assert runs, "no coverage was recorded"
    for f in runs:
        for k, v in json.loads(f.read_text())["points"].items():
            total[k] += v
    hit = sum(1 for v in total.values() if v)
    lines = [f"edgeflag cocotb coverage ({SET}): {hit} of {len(total)} points hit "
             f"({100.0 * hit / len(total):.1f} %), over {len(runs)} simulation runs"]
    for name, sec, _ in points:
        lines.append(f"  {'HIT ' if total[name] else 'hole'} {total[name]:>9}  {name}  ({sec})")
    speed = {}
    for f in sorted(OUT.glob("*.summary.json")):
        s = json.loads(f.read_text())
        for c in s["cases"]:
            if c.get("cycles"):
                sp = speed.setdefault(s["sim"], [0, 0.0])
                sp[0] += c["cycles"]
                sp[1] += c["wall"]
        lines.append(f"  run {f.stem.replace('.summary', '')}: {s['sim']} NS {s['ns']}, {len(s['cases'])} cases, "
                     f"{s['wall']:.1f} s")
    for sim, (cycles, wall) in sorted(speed.items()):
        lines.append(f"  {sim}: simulated {cycles} cycles in {wall:.1f} s of passing cases "
                     f"({cycles / wall:.0f} cycles/s, the bench's Python included)")
    (OUT / "coverage.txt").write_text("\n".join(lines) + "\n")
    (OUT / "coverage.json").write_text(json.dumps(total, indent=1))
    print("\n".join(lines))
