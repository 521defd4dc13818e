"""The cocotb test of ef_raster: runs the cases of a plan (JSON, $EF_COCOTB_PLAN, written by
dv/cocotb/test_runner.py), each after a reset, with the Python model as the scoreboard, and writes
what happened to $EF_COCOTB_PLAN's `results` file: per case the outcome, the cycles simulated, the
transactions checked per interface and, for a failure, its interface, cycle and message.

A case that is expected to fail (an injected RTL fault, a wrong rule given to the model) passes only
when the bench stopped with a mismatch; the runner then checks the interface and the field.
"""

import json
import os
import pathlib
import time

import cocotb

import edgeflag as ef
from ef_bench import OBSERVED, BenchFailure, RasterBench
from ef_coverage import CoverageModel


class Dump:
    """Every observed transfer, to write as IFACE.actual.hex for `edgeflag check`."""

    def __init__(self):
        self.txns = {n: [] for n in OBSERVED}

    def __call__(self, t):
        if t.NAME in self.txns:
            self.txns[t.NAME].append(t)

    def write(self, directory):
        os.makedirs(directory, exist_ok=True)
        for n, ts in self.txns.items():
            cls = ef.TXN[n]
            digits = (48 + cls.WIDTH + 3) // 4
            with open(os.path.join(directory, f"{n}.actual.hex"), "w") as f:
                f.write(f"// edgeflag vectors format 1: interface {n}, role actual: dv/cocotb\n")
                for t in ts:
                    f.write(format((t.cycle << cls.WIDTH) | t.payload(), f"0{digits}x") + "\n")


def case_scene(case):
    if "gen" in case:
        (c,) = ef.gen_cases(level=1, select=[case["gen"]])
        return c.scene
    if "scene_text" in case:
        return ef.Scene.from_text(case["scene_text"], name=case["name"] + ".scene")
    return ef.Scene.load(case["file"], fit=tuple(case["size"]) if case.get("size") else None)


@cocotb.test()
async def run_plan(dut):
    plan = json.loads(pathlib.Path(os.environ["EF_COCOTB_PLAN"]).read_text())
    p = plan["params"]
    bench = RasterBench(dut, p["NS"], p["W_MAX"], p["H_MAX"], p["E_MAX"])
    cov = CoverageModel(p["NS"], p["E_MAX"])
    results = []
    out = pathlib.Path(plan["results"])
    unexpected = None
    try:
        for case in plan["cases"]:
            scene = case_scene(case)
            rule = None if case.get("rule", "scene") == "scene" else case["rule"]
            tr = ef.trace(scene, samples=p["NS"], rule=rule, interfaces=["cmd"])
            cmds = tr["cmd"]
            dump = Dump() if case.get("dump") else None
            await bench.reset()
            t0 = time.perf_counter()
            r = {"name": case["name"], "expect": case.get("expect", "pass"), "frame_cycles": tr.cycles}
            try:
                cycles, checked, total = await bench.run(cmds, model_rule=case.get("model_rule"),
                                                         bp_seed=case.get("bp_seed"), listeners=(cov, dump),
                                                         model_samples=case.get("model_samples"))
                r.update(outcome="pass", cycles=cycles, checked=checked, total=total)
            except BenchFailure as e:
                r.update(outcome="fail", iface=e.iface, cycle=e.cycle, message=e.message, cycles=None)
                dut._log.info("%s: bench stopped: %s", case["name"], e.message)
            r["wall"] = time.perf_counter() - t0
            if dump is not None:
                d = pathlib.Path(plan["dump_dir"]) / case["name"]
                dump.write(d)
                tr_all = ef.trace(scene, samples=p["NS"], rule=rule)
                tr_all.write(d / "expected", formats=("hex",))
                r["dump"] = str(d)
            results.append(r)
            ok = (r["outcome"] == "pass") == (r["expect"] == "pass")
            dut._log.info("%s: %s (%s), %s cycles, %.2f s", case["name"], r["outcome"], "as expected" if ok else
                          "NOT AS EXPECTED", r.get("cycles"), r["wall"])
            if not ok:
                unexpected = r
                break

    finally:
        out.write_text(json.dumps({"sim": plan.get("sim"), "cases": results}, indent=1))
        cov.export(out.with_name(out.stem + ".coverage.json"))
    if unexpected is not None:
        raise AssertionError(f"{unexpected['name']}: {unexpected.get('message', 'passed, but a failure was expected')}")
