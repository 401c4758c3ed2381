"""Work-precision benchmarks (hpgen.bench), printed as Markdown tables.

    python benchmarks/work_precision.py [--quick] [--out DIR] [--cache-dir DIR]

1. Heavy top (examples/heavy_top.yaml), T = 10: the default grid of ``hpgen bench`` (hpgen
   Stormer-Verlet and Gauss 2 in C against SciPy DOP853 / RK45, CasADi cvodes / Gauss
   collocation, RK4 in NumPy and in C), then the issue's target: the time each family needs
   for error TARGET = 1e-6 (log-log interpolation on its Pareto front) and the ratio to
   hpgen's best C scheme there.
2. Free rigid body (examples/free_rigid_body.yaml), its scene's horizon, exact reference.
3. Long runs, T = 1000, both models: hpgen schemes against the C RK4 at equal cost. For each
   hpgen point, RK4's figures at the same wall time are interpolated in log-log along its
   h ladder: max |E - E0| over the samples, the change of the conserved momentum
   (heavy top: e3.(R p), the third component of Integrator.momentum = Ad*_{g^-1} p; free
   body: all of Ad*_{g^-1} p, max over components), and the group defect at T.
Files (CSV, Markdown, PNG per run) go to DIR/<model>-T<T>/ (default benchmarks/out/
work_precision). Every figure printed is measured by this run; nothing is hard-coded.
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
HEAVY_TOP = ROOT / "examples" / "heavy_top.yaml"
FREE_BODY = ROOT / "examples" / "free_rigid_body.yaml"
TARGET = 1e-6
LONG_T = 1000.0
LONG_H0 = 0.1      # long runs: hpgen at h = 0.1, 0.05, 0.025; RK4 (C) at 0.1 * 2^-k, k = 0..9


def log(s):
    print(s, file=sys.stderr, flush=True)


def fmt(x, spec=".2e"):
    return "-" if x is None or not math.isfinite(x) else format(x, spec)


def target_table(res, target=TARGET):
    """Time of each family at error ``target`` and the ratio to hpgen's best scheme there."""
    from hpgen.bench.report import families, time_at_error
    fams = families(res.points)
    times = {f: time_at_error(pts, target) for f, pts in fams.items()}
    hp = {f: t for f, t in times.items() if t is not None and fams[f][0].kind == "hpgen"}
    best = min(hp, key=hp.get) if hp else None
    lines = [f"Error {target:g} at T = {res.T:g}: "
             + (f"hpgen's best C scheme is {best} ({hp[best]:.3e} s)." if best else
                "no hpgen scheme reaches this error within its h grid."),
             "", "| method | time s at error | time / hpgen best |", "|---|---|---|"]
    for f, t in times.items():
        ratio = t / hp[best] if (t is not None and best) else None
        lines.append(f"| {f} | {fmt(t, '.3e') if t else 'no overlap'} | "
                     f"{fmt(ratio, '.3g') + 'x' if ratio else '-'} |")
    return "\n".join(lines)


def work_precision(path, T, out, cache_dir, quick):
    from hpgen.bench import run_bench
    from hpgen.bench.report import comparison_table, md_table
    kw = {}
    if quick:
        kw = dict(h=None, rtol=[1e-4, 1e-7, 1e-10], collocation_h=None, min_time=0.05,
                  peers=["DOP853", "cvodes-bdf", "cvodes-adams", "RK4-C"])
    res = run_bench(path, T=T, out=out / (f"{path.stem}-T{T:g}" if T else path.stem),
                    cache_dir=cache_dir, log=log, **kw)
    print(f"\n## {res.model_name}, T = {res.T:g}\n\nReference: {res.reference}. "
          f"Timing: median, {res.timing_rule}. Files: {', '.join(map(str, res.files))}.\n")
    print(md_table(res.points))
    print("\nhpgen against each peer at equal error (peer time / hpgen time):\n")
    print(comparison_table(res.points))
    print()
    print(target_table(res))
    return res


def _momentum_change(integ, point, component):
    """max_k |m_k - m_0| over the samples, m = Integrator.momentum (Ad*_{g^-1} p)."""
    if point.samples is None:
        return math.nan
    n = integ.n
    Y = point.samples[1]
    if not np.isfinite(Y).all():
        return math.nan
    m = np.array([integ.momentum(y[:n * n].reshape(n, n), y[n * n:]) for y in Y])
    dm = np.abs(m - m[0])
    return float(dm[:, component].max() if component is not None else dm.max())


def _interp_loglog(x, xs, ys):
    ok = [(a, b) for a, b in zip(xs, ys) if a > 0 and b > 0 and math.isfinite(a)
          and math.isfinite(b)]
    if len(ok) < 2:
        return None
    ok.sort()
    lx, ly = np.log([a for a, _ in ok]), np.log([b for _, b in ok])
    if not (lx[0] <= math.log(x) <= lx[-1]):
        return None
    return float(math.exp(np.interp(math.log(x), lx, ly)))


def long_run(path, out, cache_dir, quick, component):
    """T = LONG_T: hpgen schemes against the C RK4 at equal wall time."""
    import hpgen
    from hpgen.bench import run_bench
    from hpgen.bench.schemes import ladder
    hs = ladder(LONG_H0, 1 if quick else 2)
    res = run_bench(path, T=LONG_T, h=hs, rk4_h=ladder(LONG_H0, 5 if quick else 9),
                    peers=["RK4-C"],
                    samples=500 if quick else 2000, min_time=0.05 if quick else 0.2,
                    out=out / f"{path.stem}-T{LONG_T:g}", cache_dir=cache_dir, log=log)
    integ = hpgen.compile(path, cache_dir=cache_dir)
    mom = {id(p): _momentum_change(integ, p, component) for p in res.points}
    rk4 = sorted((p for p in res.points if p.family == "RK4-C" and p.ok), key=lambda p: p.wall_s)
    what = "e3.(R p)" if component is not None else "|Ad*_{g^-1} p| (max component)"
    print(f"\n## {res.model_name}, long run T = {res.T:g}: energy and momentum at equal cost "
          f"with RK4 (C)\n\nmax |E - E0| and the change of {what} over {res.samples} samples "
          "per run (every steps // samples steps, and T); group defect at T. RK4 columns: its "
          "figures interpolated (log-log) at hpgen's wall time along its h ladder "
          f"({', '.join(f'{p.param:.4g}' for p in rk4)}).\n")
    print(f"| method | h | wall s | max energy error | {what} change | group defect | "
          f"RK4-C h at equal time | RK4-C energy error | RK4-C {what} change | "
          "RK4-C group defect |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    ts = [p.wall_s for p in rk4]
    for p in res.points:
        if p.kind != "hpgen":
            continue
        if not p.ok:
            print(f"| {p.family} | {p.param:.4g} | failed: {'; '.join(p.notes)} |||||||")
            continue
        eq = [_interp_loglog(p.wall_s, ts, [q.param for q in rk4]),
              _interp_loglog(p.wall_s, ts, [q.energy_drift for q in rk4]),
              _interp_loglog(p.wall_s, ts, [mom[id(q)] for q in rk4]),
              _interp_loglog(p.wall_s, ts, [q.group_defect for q in rk4])]
        cells = [fmt(v, ".4g") if i == 0 else fmt(v) for i, v in enumerate(eq)]
        if eq[0] is None:
            cells = ["no overlap"] + ["-"] * 3
        print(f"| {p.family} | {p.param:.4g} | {p.wall_s:.3e} | {fmt(p.energy_drift)} | "
              f"{fmt(mom[id(p)])} | {fmt(p.group_defect)} | " + " | ".join(cells) + " |")
    print("\nRK4 (C) ladder itself:\n\n| h | wall s | max energy error | "
          f"{what} change | group defect |\n|---|---|---|---|---|")
    for q in rk4:
        print(f"| {q.param:.4g} | {q.wall_s:.3e} | {fmt(q.energy_drift)} | "
              f"{fmt(mom[id(q)])} | {fmt(q.group_defect)} |")
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller grids, shorter timing")
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "out" / "work_precision"))
    ap.add_argument("--cache-dir", help="hpgen build cache (default ~/.cache/hpgen)")
    a = ap.parse_args(argv)
    out = Path(a.out)
    print("# hpgen work-precision benchmarks")
    work_precision(HEAVY_TOP, 10.0, out, a.cache_dir, a.quick)
    work_precision(FREE_BODY, None, out, a.cache_dir, a.quick)
    long_run(HEAVY_TOP, out, a.cache_dir, a.quick, component=2)
    long_run(FREE_BODY, out, a.cache_dir, a.quick, component=None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
