"""The speed targets of docs/performance.md, all measured in one run, one process.

    python benchmarks/targets.py [--quick]

Prints one Markdown table (target, measured, peer, ratio) and the raw figures behind it.
Every figure is a ratio against a peer timed in the same process, interleaved where the
two sides are cheap (same statistic on both sides), on the portable -O3 build:

1. Lie Stormer-Verlet (heavy top, cay, truncated): generated / hand-written C
   (benchmarks/hand_sv), medians of interleaved repeats, h = 0.01 and 0.05.
2. Heavy top, T = 10, at error 1e-6 (log-log interpolation on each Pareto front, as
   ``hpgen bench``): the best hpgen scheme (gauss3 or gauss2, cay, exact) against SciPy
   DOP853 and RK4 emitted as C, all methods once per round in shuffled order
   (benchmarks/heavy_top_target.py), the minimum and the median of the rounds.
3. Free rigid body ensemble (``simulate_batch`` of 256 bodies, h = 0.1): ns per body-step
   on 2 threads (the marginal cost beyond the per-body setup), against one scalar run.
4. Python backend, heavy top Gauss 2 cay exact, h = 0.05: us per step of a 1000-step run
   from the scene's start (against the C backend's step in the same run), min and median.
5. ``simulate``'s fixed cost (steps = 0, heavy top gauss3/cay/exact, xi0 start), repeated
   calls of one Integrator: us per call, against one step of the same scheme.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
sys.path.insert(0, str(ROOT / "benchmarks" / "hand_sv"))

HEAVY_TOP = ROOT / "examples" / "heavy_top.yaml"
FREE_BODY = ROOT / "examples" / "free_rigid_body.yaml"
XI0 = [0.2, 1.0, 3.0]


def g0_top():
    from scipy.spatial.transform import Rotation
    return Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()


def interleaved(runs: dict, repeats: int, stat=statistics.median) -> dict:
    """{name: stat of wall seconds} over interleaved repeats (one warm-up each); stat=None:
    {name: [seconds]}."""
    for fn in runs.values():
        fn()
    times = {k: [] for k in runs}
    for _ in range(repeats):
        for k, fn in runs.items():
            t0 = time.perf_counter()
            fn()
            times[k].append(time.perf_counter() - t0)
    return times if stat is None else {k: stat(v) for k, v in times.items()}


def sv_ratio(cache, quick):
    import hand_sv
    import hpgen
    from hpgen.runtime.build import DEFAULT_CFLAGS
    from sv_vs_hand import initial_state
    hand = hand_sv.HandSV(hand_sv.build(cache, list(DEFAULT_CFLAGS)))
    integ = hpgen.compile(HEAVY_TOP, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                          backend="c", cache_dir=cache)
    R0, p0 = initial_state()
    steps = 200_000 if quick else 1_000_000
    out = {}
    for h in (0.01, 0.05):
        t = interleaved({"hand": lambda: hand.simulate(R0, p0, h, steps, steps),
                         "generated": lambda: integ.simulate(g0=R0, mu0=p0, h=h, steps=steps,
                                                             every=steps)},
                        3 if quick else 5)
        out[h] = (t["generated"] / steps * 1e9, t["hand"] / steps * 1e9)
    return out


def heavy_top_T10(cache, quick):
    """{statistic: (best hpgen family, its ms, DOP853 ms, RK4-C ms)} at error 1e-6, from
    benchmarks/heavy_top_target.py's interleaved rounds (min and median)."""
    import heavy_top_target as ht
    from hpgen.bench.crk4 import CRK4
    from hpgen.bench.problem import Problem
    pb = Problem(HEAVY_TOP, 10.0)
    methods = ht._methods(pb, [("gauss3", "cay", "exact"), ("gauss2", "cay", "exact")],
                          [0.125, 0.1, 0.0833333, 0.0714286, 0.0625, 0.05],
                          [1e-6, 1e-7, 1e-8, 1e-9, 1e-10], [0.02, 0.01, 0.005, 0.0025], cache)
    y_ref, _ = pb.reference("auto", CRK4(pb, cache).rhs)
    res = ht.measure(pb, y_ref, methods, 5 if quick else 31)
    return {name: ht.best_at(methods, res, stat)
            for name, stat in (("min", min), ("median", statistics.median))}


def ensemble(cache, quick):
    import hpgen
    integ = hpgen.compile(FREE_BODY, cache_dir=cache)
    B, steps = 256, (2_000 if quick else 20_000)
    rng = np.random.default_rng(0)
    mus = rng.normal(size=(B, 3))
    mus /= np.linalg.norm(mus, axis=1)[:, None]
    mu0 = mus[0]
    one_steps = 100 * steps

    def batch(n, threads):
        return lambda: integ.simulate_batch(np.eye(3), 0.1, n, mu0=mus, every=max(n, 1),
                                            threads=threads)
    t = interleaved({"setup": batch(0, 2), "2 threads": batch(steps, 2),
                     "1 thread": batch(steps, 1),
                     "scalar": lambda: integ.simulate(g0=np.eye(3), mu0=mu0, h=0.1,
                                                      steps=one_steps, every=one_steps)},
                    3, stat=min)
    per = {k: (t[k] - t["setup"]) / (B * steps) * 1e9 for k in ("1 thread", "2 threads")}
    return per, t["scalar"] / one_steps * 1e9


def python_step(cache, quick):
    """{statistic: (Python us/step, C us/step)}: runs of 1000 (Python) and 100,000 (C) steps
    from the scene's start, interleaved, min and median of the repeats."""
    import hpgen
    kw = dict(tableau="gauss2", tau="cay", rkmk="exact", cache_dir=cache)
    py = hpgen.compile(HEAVY_TOP, backend="python", **kw)
    c = hpgen.compile(HEAVY_TOP, backend="c", **kw)
    g0 = g0_top()
    n_py, n_c = (200, 20_000) if quick else (1000, 100_000)
    t = interleaved({"python": lambda: py.simulate(g0=g0, xi0=XI0, h=0.05, steps=n_py,
                                                    every=n_py),
                     "c": lambda: c.simulate(g0=g0, xi0=XI0, h=0.05, steps=n_c, every=n_c)},
                    3 if quick else 11, stat=None)
    return {name: (stat(t["python"]) / n_py * 1e6, stat(t["c"]) / n_c * 1e6)
            for name, stat in (("min", min), ("median", statistics.median))}


def prologue(cache, quick):
    import hpgen
    integ = hpgen.compile(HEAVY_TOP, tableau="gauss3", tau="cay", rkmk="exact", backend="c",
                          cache_dir=cache)
    g0, n = g0_top(), 20_000

    def calls(k):
        def run():
            for _ in range(k):
                integ.simulate(g0=g0, xi0=XI0, h=0.1, steps=0)
        return run
    k = 200 if quick else 2000
    t = interleaved({"prologue": calls(k),
                     "steps": lambda: integ.simulate(g0=g0, xi0=XI0, h=0.1, steps=n, every=n)},
                    5, stat=min)
    return t["prologue"] / k * 1e6, t["steps"] / n * 1e6


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer steps and repeats")
    a = ap.parse_args()
    cache = tempfile.mkdtemp(prefix="hpgen-targets-")
    rows = []
    sv = sv_ratio(cache, a.quick)
    for h, (g, hd) in sv.items():
        rows.append(("generated SV within 1.2x of hand C", f"h = {h}: {g:.0f} ns/step",
                     f"hand {hd:.0f} ns/step", f"{g / hd:.2f}x"))
    def ms(t):
        return "no overlap" if t is None else f"{t * 1e3:.3f} ms"
    for stat, (best, t_hp, t_dop, t_rk4) in heavy_top_T10(cache, a.quick).items():
        rows.append((f"heavy top T = 10 at 1e-6: >= 30x DOP853 ({stat})",
                     f"{best}: {ms(t_hp)}", f"DOP853 {ms(t_dop)}",
                     "-" if None in (t_dop, t_hp) else f"{t_dop / t_hp:.1f}x faster"))
        rows.append((f"heavy top T = 10 at 1e-6: within 5x RK4-C ({stat})",
                     f"{best}: {ms(t_hp)}", f"RK4-C {ms(t_rk4)}",
                     "-" if None in (t_rk4, t_hp) else f"{t_hp / t_rk4:.2f}x slower"))
    per, scalar = ensemble(cache, a.quick)
    rows.append(("free-body ensemble <= 40 ns/body-step, 2 threads",
                 f"{per['2 threads']:.0f} ns (1 thread {per['1 thread']:.0f})",
                 f"one scalar run {scalar:.0f} ns/step", f"{scalar / per['2 threads']:.2f}x"))
    for stat, (tp, tc) in python_step(cache, a.quick).items():
        rows.append((f"Python backend < 50 us per Gauss 2 step ({stat})", f"{tp:.1f} us/step",
                     f"C backend {tc:.2f} us/step", f"{tp / tc:.0f}x C"))
    tpro, tstep = prologue(cache, a.quick)
    rows.append(("simulate prologue off the critical path", f"{tpro:.1f} us/call (steps = 0)",
                 f"gauss3 step {tstep:.2f} us", f"{tpro / tstep:.1f} steps"))
    print("| target | measured | peer (same run) | ratio |")
    print("|---|---|---|---|")
    for r in rows:
        print("| " + " | ".join(r) + " |")


if __name__ == "__main__":
    main()
