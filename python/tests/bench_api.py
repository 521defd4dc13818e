"""The Python API's cost per transaction (README, "From Python"): the tiger at 640x480, 8 samples.

    PYTHONPATH=python build/venv/bin/python python/tests/bench_api.py [SVG] [WxH]

Prints, each the best of three: the trace collected in C (ef.trace, every interface), the typed
transactions decoded from it (tr[iface] for every interface) and
the scoreboard step (ModelStream: every cmd fed, every other transaction expected, cycle-exact) - in
nanoseconds per transaction."""
import sys
import time

import edgeflag as ef

svg = sys.argv[1] if len(sys.argv) > 1 else "tests/data/svg/tiger.svg"
w, h = (int(v) for v in (sys.argv[2] if len(sys.argv) > 2 else "640x480").split("x"))
scene = ef.Scene.load(svg, fit=(w, h))


def best(fn, k=3):
    t = []
    for _ in range(k):
        t0 = time.perf_counter()
        r = fn()
        t.append(time.perf_counter() - t0)
    return min(t), r


t_trace, tr = best(lambda: ef.trace(scene, samples=8))
n = sum(tr.counts().values())


def decode():
    fresh = ef.trace(scene, samples=8)
    t0 = time.perf_counter()
    m = sum(len(fresh[i]) for i in ef.IFACES)
    return time.perf_counter() - t0, m


dec = min(decode()[0] for _ in range(3))
txns = {i: tr[i] for i in ef.IFACES}


def scoreboard():
    m = ef.ModelStream(samples=8)
    for c in txns["cmd"]:
        m.cmd(c)
    k = 0
    for i in ef.IFACES[1:]:
        for t in txns[i]:
            m.expect(t)
            k += 1
    return k


t_sb, k = best(scoreboard)
print(f"{svg} at {w}x{h}, 8 samples: {n} transactions over {tr.cycles} cycles")
print(f"  ef.trace (collected in C):          {t_trace:.3f} s  {1e9 * t_trace / n:7.0f} ns/transaction")
print(f"  typed transactions (tr[iface]):     {dec:.3f} s  {1e9 * dec / n:7.0f} ns/transaction")
print(f"  ModelStream: cmd fed + expect():    {t_sb:.3f} s  {1e9 * t_sb / n:7.0f} ns/transaction (incl. the model)")
