"""Heavy top, T = 10, error 1e-6: hpgen's best scheme against
SciPy DOP853 and RK4 emitted as C, timed interleaved in one process.

    python benchmarks/heavy_top_target.py [--rounds 15] [--schemes gauss3/cay/exact,...]
                                          [--h 0.1,0.0769,0.0625,0.05] [--T 10]

Each method's runs (hpgen ``Integrator.simulate(h, steps, every=steps)`` on the C backend,
simulate's prologue included, as hpgen bench times it; SciPy ``solve_ivp(DOP853)`` with
atol = 1e-3 rtol on the C vector field; the C RK4 of hpgen.bench.crk4) are called once per
round, all methods in every round, in a shuffled order (interleaved: the machine's load hits
every method alike). Per method: its error at T (hpgen.bench.problem.Problem.error against the
bench's reference) and the minimum and the median of its round times. The time at error
TARGET is the log-log interpolation on each family's Pareto front (hpgen.bench.report
.time_at_error), once with the minima and once with the medians: the ratios printed are the
same statistic on both sides. Also printed: Newton iterations and Jacobians per step of each
hpgen point, and simulate's prologue (steps = 0) alone.
"""
from __future__ import annotations

import argparse
import random
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HEAVY_TOP = ROOT / "examples" / "heavy_top.yaml"
TARGET = 1e-6


def _log(s):
    print(s, file=sys.stderr, flush=True)


def _methods(pb, schemes, hs, rtols, rk4_hs, cache_dir):
    """[(family, param, fn() -> y_T, info)] and the crk4 object."""
    import hpgen
    from hpgen.bench.crk4 import CRK4
    from hpgen.bench.peers import ATOL_FACTOR, steps_for
    from scipy.integrate import solve_ivp
    crk4 = CRK4(pb, cache_dir)
    kw0 = {"g0": pb.g0}
    kw0.update({"xi0": pb.xi0} if pb.xi0 is not None else {"mu0": pb.mu0})
    out = []
    for tab, tau, rkmk in schemes:
        integ = hpgen.build(pb.path, tableau=tab, tau=tau, rkmk=rkmk, backend="c",
                            cache_dir=cache_dir).load()
        for h in hs:
            steps, hu = steps_for(pb.T, h)

            def run(integ=integ, hu=hu, steps=steps):
                tr = integ.simulate(h=hu, steps=steps, every=steps, **kw0)
                return pb.pack(tr.g[-1], tr.mu[-1]), tr
            tr = run()[1]
            info = (f"it/step {tr.newton_iterations / steps:.3f}, J/step "
                    f"{tr.jacobians / steps:.3f}" if hasattr(tr, "jacobians") else
                    f"it/step {tr.newton_iterations / steps:.3f}")
            out.append((f"hpgen {tab}/{tau}/{rkmk}", hu, lambda r=run: r()[0], info))
        out.append((f"prologue {tab}/{tau}/{rkmk}", 0.0,
                    lambda integ=integ: integ.simulate(h=hs[0], steps=0, **kw0), ""))
    for rtol in rtols:
        def dop(rtol=rtol):
            sol = solve_ivp(crk4.rhs, (0.0, pb.T), pb.y0, method="DOP853", rtol=rtol,
                            atol=rtol * ATOL_FACTOR)
            return sol.y[:, -1]
        out.append(("DOP853", rtol, dop, ""))
    for h in rk4_hs:
        steps, hu = steps_for(pb.T, h)
        out.append(("RK4-C", hu, lambda hu=hu, steps=steps: crk4.run(pb.y0, hu, steps)[1], ""))
    return out


def measure(pb, y_ref, methods, rounds, seed=0):
    """{index: (error, [times])}: every method once per round, order shuffled per round."""
    import gc
    import numpy as np
    times = {i: [] for i in range(len(methods))}
    errs = {}
    for i, (_, _, fn, _) in enumerate(methods):
        y = fn()
        errs[i] = (pb.error(np.asarray(y, dtype=float), y_ref)
                   if methods[i][0].split()[0] != "prologue" else float("nan"))
    rng = random.Random(seed)
    order = list(range(len(methods)))
    gc.disable()
    try:
        for _ in range(rounds):
            rng.shuffle(order)
            for i in order:
                fn = methods[i][2]
                t0 = time.perf_counter()
                fn()
                times[i].append(time.perf_counter() - t0)
    finally:
        gc.enable()
    return {i: (errs[i], times[i]) for i in times}


def times_at(methods, res, stat, target=TARGET):
    """{family: time at error ``target`` or None}: the log-log interpolation on each family's
    Pareto front of its points' ``stat`` (min, median) of the round times."""
    import numpy as np
    from hpgen.bench.measure import Point
    from hpgen.bench.report import time_at_error
    fams = {}
    for i, (fam, _, _, _) in enumerate(methods):
        if not fam.startswith("prologue"):
            fams.setdefault(fam, []).append(i)
    at = {}
    for fam, idx in fams.items():
        pts = []
        for i in idx:
            p = Point(fam, fam, "x", "p", methods[i][1], error=res[i][0],
                      wall_s=stat(res[i][1]))
            p.y_end = np.zeros(1)
            pts.append(p)
        at[fam] = time_at_error(pts, target)
    return at


def best_at(methods, res, stat, target=TARGET):
    """(best hpgen family or None, its time, DOP853's, RK4-C's) at error ``target``."""
    at = times_at(methods, res, stat, target)
    cand = {f: t for f, t in at.items() if f.startswith("hpgen") and t is not None}
    best = min(cand, key=cand.get) if cand else None
    return best, (cand[best] if best else None), at.get("DOP853"), at.get("RK4-C")


def table(methods, res, target=TARGET):
    """Markdown lines: per-method figures, then the ratios at ``target`` (min and median)."""
    lines = ["| method | h / rtol | error at T | min ms | median ms | Newton |",
             "|---|---|---|---|---|---|"]
    for i, (fam, par, _, info) in enumerate(methods):
        e, ts = res[i]
        lines.append(f"| {fam} | {par:.4g} | {e:.2e} | {min(ts) * 1e3:.4f} | "
                     f"{statistics.median(ts) * 1e3:.4f} | {info} |")
    lines += ["", f"Time at error {target:g} (log-log on each Pareto front), ms, and ratios "
              "(same statistic on both sides):", "",
              "| statistic | hpgen best | DOP853 | RK4-C | DOP853 / hpgen | hpgen / RK4-C |",
              "|---|---|---|---|---|---|"]
    for stat_name, stat in (("min", min), ("median", statistics.median)):
        best, t, d, r = best_at(methods, res, stat, target)
        if best is None:
            lines.append(f"| {stat_name} | no hpgen scheme reaches {target:g} |||||")
            continue
        lines.append(f"| {stat_name} | {best} {t * 1e3:.4f} | "
                     f"{'-' if d is None else f'{d * 1e3:.4f}'} | "
                     f"{'-' if r is None else f'{r * 1e3:.4f}'} | "
                     f"{'-' if d is None else f'{d / t:.1f}x'} | "
                     f"{'-' if r is None else f'{t / r:.2f}x'} |")
    return lines


def main(argv=None):
    from hpgen.bench.problem import Problem
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--T", type=float, default=10.0)
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--schemes", default="gauss3/cay/exact")
    ap.add_argument("--h", default="0.125,0.1,0.0833333,0.0714286,0.0625")
    ap.add_argument("--rtol", default="1e-6,1e-7,1e-8,1e-9,1e-10")
    ap.add_argument("--rk4-h", default="0.02,0.01,0.005,0.0025")
    ap.add_argument("--cache-dir")
    a = ap.parse_args(argv)
    schemes = [tuple(s.split("/")) for s in a.schemes.split(",")]
    fl = lambda s: [float(x) for x in s.split(",")]  # noqa: E731
    pb = Problem(HEAVY_TOP, a.T)
    methods = _methods(pb, schemes, fl(a.h), fl(a.rtol), fl(a.rk4_h), a.cache_dir)
    from hpgen.bench.crk4 import CRK4
    y_ref, ref_text = pb.reference("auto", CRK4(pb, a.cache_dir).rhs)
    _log(f"reference: {ref_text}; {len(methods)} methods x {a.rounds} rounds")
    res = measure(pb, y_ref, methods, a.rounds)
    print(f"# heavy top, T = {a.T:g}, error {TARGET:g}: interleaved, {a.rounds} rounds\n")
    print("\n".join(table(methods, res)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
