"""The splitting schemes' speed targets, measured in one run, one process (portable -O3).

    PYTHONPATH=. python benchmarks/splitting_targets.py [--quick]

1. Heavy top, T = 10 (``hpgen bench`` points: the generated splittings, SciPy DOP853, RK4
   emitted as C, the hand-written DLM splittings of hpgen.bench.rigid): at errors 1e-4 ..
   1e-10, each family's time read off its Pareto front (log-log interpolation, as the bench's
   equal-error comparison), then the best generated splitting against DOP853, RK4-C and the
   best hand-written splitting (ratio = their time / hpgen's time, > 1: hpgen faster).
   ``--part free-equal``: the same table for the free rigid body (examples/free_rigid_body.yaml,
   T = 10, error against the exact flow of hpgen.analysis.exact; peers RK4-C and the
   hand-written DLM splittings 2/4/6, one C call a run).
2. Free rigid body (examples/free_rigid_body.yaml), T = 10, against the exact solution: the
   error of the generated Stormer-Verlet (cay, truncated) at h = 0.01, and for every
   splitting scheme the step h reaching that error (log-log interpolation over a ladder of
   h), its time per step and the simulated time per second as Stormer-Verlet steps of 0.01
   ("SV-equivalent steps/s" = (T / 0.01) / wall time at that h).
3. Free-body ensembles (simulate_batch): ns per body-step, lanes or not, 1 and 2 threads.
4. Heavy top, T = 10 .. 1000: RK4-C's time / the best generated splitting's at equal
   final-state error (DOP853 reference at 1e-13) and the break-even T per error.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SPLITS = ("split2", "split4-yoshida", "split4-suzuki", "split4-mclachlan", "split4-blanes-moan",
          "split6-yoshida", "split6-kahan-li", "split6-blanes-moan", "split8-mclachlan",
          "split8-kahan-li", "split2-fasso", "split4-suzuki-fasso", "split4-blanes-moan-fasso",
          "split6-kahan-li-fasso", "split6-blanes-moan-fasso", "split8-kahan-li-fasso")
#: the generated schemes of the long runs: the best DLM tables and the best Fasso variants
LONG_SPLITS = ("split6-kahan-li", "split8-kahan-li", "split4-blanes-moan-fasso",
               "split6-blanes-moan-fasso", "split8-kahan-li-fasso")
HAND = ("splitting-2", "splitting-4", "splitting-6")
#: the ensembles' stepping alone is timed over this many times the steps of T = 10
LONG = 20


def heavy_top(quick, splits=SPLITS, cache_dir=None):
    hs = [0.4, 0.3, 0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625, 0.003125]
    return equal_error(ROOT / "examples" / "heavy_top.yaml", "Heavy top", quick, splits, hs,
                       ("DOP853", "RK4-C", *HAND), "dop853", cache_dir)


def free_body_equal_error(quick, splits=SPLITS, cache_dir=None):
    """The free body (examples/free_rigid_body.yaml), T = 10, against the exact flow: h from
    10 (one step) down to 10 * 2^-14, so that every family's front spans 1e-4 .. 1e-10 where
    its order allows (the order-2 schemes stop short of 1e-10)."""
    hs = [10.0 * 2.0 ** -k for k in range(12 if quick else 15)]
    return equal_error(ROOT / "examples" / "free_rigid_body.yaml", "Free rigid body", quick,
                       splits, hs, ("RK4-C", *HAND), "exact", cache_dir)


def equal_error(path, title, quick, splits, hs, peers, reference, cache_dir=None):
    """``hpgen bench`` points over T = 10 (the generated splittings and ``peers``), each
    family's time at errors 1e-4 .. 1e-10 read off its Pareto front; prints the table of
    peer time / the best generated splitting's time and returns
    {error: (best generated time, its scheme, best hand-written time, its family)}."""
    from hpgen.bench import run_bench
    from hpgen.bench.report import time_at_error
    load = os.getloadavg()[0]
    res = run_bench(path, T=10, schemes=[(s, "cay", "exact") for s in splits], h=hs,
                    rtol=[1e-4, 1e-6, 1e-8, 1e-10, 1e-12], peers=list(peers),
                    reference=reference, write=False, min_time=0.05 if quick else 0.2,
                    cache_dir=cache_dir, log=lambda s: None)
    gen = [p for p in res.points if p.kind == "hpgen"]
    hand = [p for p in res.points if p.family in HAND]
    others = [name for name in peers if name not in HAND]
    fam = {name: [p for p in res.points if p.family == name] for name in others}
    print(f"\n## {title}, T = 10 (reference: {res.reference}): time at equal error (ratio = "
          f"peer time / best generated splitting's time; load average {load:.1f} before, "
          f"{os.getloadavg()[0]:.1f} after)\n")
    print("| error | best generated (s) | " + " | ".join(f"{n} / gen" for n in others)
          + " | best hand splitting / gen | gen / hand |")
    print("|---|---|" + "---|" * len(others) + "---|---|")
    out = {}
    for e in (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10):
        tg, best = _best(gen, e, time_at_error, which=True)
        th, hbest = _best(hand, e, time_at_error, which=True)
        out[e] = (tg, best, th, hbest)
        cells = [f"{e:g}", _f(tg) + f" ({best})"]
        for name in others:
            t = time_at_error(fam[name], e)
            cells.append("-" if t is None or tg is None else f"{t / tg:.3g}x")
        cells.append("-" if th is None or tg is None else f"{th / tg:.3g}x ({hbest})")
        cells.append("-" if th is None or tg is None else f"{tg / th:.3g}")
        print("| " + " | ".join(cells) + " |")
    for name in sorted({b for _, b, _, _ in out.values() if b}):
        pro = next((n for p in gen if p.family == name for n in p.notes
                    if n.startswith("simulate prologue")), None)
        if pro:
            print(f"\n{name}: {pro}")
    return out


def long_runs(quick):
    """Heavy top over T = 10 .. 1000: the final-state error against a DOP853 reference at
    rtol = atol = 1e-13 (hpgen bench's), the time at equal error of the best generated
    splitting (LONG_SPLITS) and of RK4-C; their ratio per T and the
    break-even T (log-log interpolation between the T where the ratio crosses 1) per error."""
    from hpgen.bench import run_bench
    from hpgen.bench.report import time_at_error
    Ts = (10, 100, 1000) if quick else (10, 30, 100, 300, 1000)
    errors = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8)
    ratio = {}
    for T in Ts:
        res = run_bench(ROOT / "examples" / "heavy_top.yaml", T=T, schemes=[
            (s, "cay", "exact") for s in LONG_SPLITS],
            h=[0.4 * 2.0 ** -k for k in range(8 if T <= 100 else 7)],
            rk4_h=[0.05 * 2.0 ** -k for k in range(6 if T <= 100 else 5)],
            peers=["RK4-C"], reference="dop853", write=False, min_time=0.02,
            min_repeats=1 if quick else 2, log=lambda s: None)
        gen = [p for p in res.points if p.kind == "hpgen"]
        rk4 = [p for p in res.points if p.family == "RK4-C"]
        for e in errors:
            tg, tr = _best(gen, e, time_at_error), time_at_error(rk4, e)
            ratio[T, e] = None if tg is None or tr is None else tr / tg
    print("\n## Heavy top, T = 10 .. 1000: RK4-C time / best generated splitting's time at "
          "equal final-state error (> 1: hpgen cheaper)\n")
    print("| error | " + " | ".join(f"T = {T}" for T in Ts) + " | break-even T |")
    print("|---|" + "---|" * (len(Ts) + 1))
    for e in errors:
        cells = ["-" if ratio[T, e] is None else f"{ratio[T, e]:.3g}x" for T in Ts]
        print(f"| {e:g} | " + " | ".join(cells) + f" | {_break_even(Ts, [ratio[T, e] for T in Ts])} |")


def _break_even(Ts, ratios) -> str:
    """The T where the ratio first reaches 1 (log-log interpolation), '<= T0' when it is
    >= 1 from the first T on, '> T_last' when it never is."""
    pts = [(T, r) for T, r in zip(Ts, ratios) if r is not None]
    if not pts:
        return "-"
    if pts[0][1] >= 1.0:
        return f"<= {pts[0][0]}"
    for (T0, r0), (T1, r1) in zip(pts, pts[1:]):
        if r0 < 1.0 <= r1:
            s = -math.log(r0) / (math.log(r1) - math.log(r0))
            return f"{math.exp(math.log(T0) + s * (math.log(T1) - math.log(T0))):.3g}"
    return f"> {pts[-1][0]}"


def _best(points, e, time_at_error, which=False):
    """The least time at error e over the families of ``points`` (with ``which``: and the
    family reaching it)."""
    out, name = None, None
    for f in sorted({p.family for p in points}):
        t = time_at_error([p for p in points if p.family == f], e)
        if t is not None and (out is None or t < out):
            out, name = t, f
    return (out, name) if which else out


def _f(x):
    return "-" if x is None else f"{x:.3g}"


def free_body(quick, splits=SPLITS):
    import hpgen
    from hpgen.analysis.exact import free_rigid_body_attitude
    path = ROOT / "examples" / "free_rigid_body.yaml"
    inertia = np.array([2.0, 1.0, 0.6666666666666666])
    pi0 = np.array([0.4535961214255773, 0.0, 0.8912073600614354])
    T = 10.0
    RT, piT = (a[-1] for a in free_rigid_body_attitude(inertia, pi0, np.eye(3), [0.0, T]))

    def run(integ, h, steps):
        return integ.simulate(np.eye(3), h, steps, mu0=pi0, every=steps)

    def error_time(integ, h):
        steps = max(1, round(T / h))
        tr = run(integ, T / steps, steps)
        err = max(np.abs(tr.g[-1] - RT).max(), np.abs(tr.mu[-1] - piT).max())
        reps = []
        for _ in range(3 if quick else 7):
            t0 = time.perf_counter()
            run(integ, T / steps, steps)
            reps.append(time.perf_counter() - t0)
        return err, min(reps), steps

    h_at = {}
    sv = hpgen.compile(path, tableau="stormer-verlet", tau="cay", rkmk="truncated")
    e_sv, t_sv, n_sv = error_time(sv, 0.01)
    print(f"\n## Free rigid body, T = 10: Stormer-Verlet (cay, truncated) at h = 0.01: error "
          f"{e_sv:.3g}, {n_sv / t_sv / 1e6:.3g} M steps/s\n")
    print("| scheme | h at SV's error | error | steps/s (M) | ns/step | SV-equivalent "
          "steps/s (M) | time / SV's |")
    print("|---|---|---|---|---|---|---|")
    for name in splits:
        integ = hpgen.compile(path, tableau=name)
        ladder = [2.0 ** -k for k in range(-1, 9)]
        pts = [(h, *error_time(integ, h)) for h in ladder]
        h_eq = _h_at(pts, e_sv)
        if h_eq is None:
            print(f"| {name} | - | - | - | - | - | - |")
            continue
        e, t, steps = error_time(integ, h_eq)
        print(f"| {name} | {T / steps:.4g} | {e:.3g} | {steps / t / 1e6:.3g} | "
              f"{t / steps * 1e9:.0f} | {n_sv / t / 1e6:.3g} | {t / t_sv:.3g} |")
        h_at[name] = T / steps
    return h_at, e_sv


def ensembles(quick, h_at, e_sv):
    """Free-body ensembles (simulate_batch, B bodies around the benchmark's state, records
    only at the end): ns per body-step and per Stormer-Verlet-equivalent body-step (T / 0.01
    steps a body) of split2 and split4-suzuki at the h reaching SV's error, on 1 and 2
    threads, with and without lanes: the whole call, and the stepping alone (a call of LONG
    times the steps less the same call with 0 steps, the per-member start and Trajectory,
    over LONG times the body-steps; also in process CPU time, all threads summed: the
    wall time on free cores is about that over the threads), the whole call's CPU time, and
    the call of 0 steps per body (the per-member start and Trajectory alone; wall and CPU)."""
    import hpgen
    path = ROOT / "examples" / "free_rigid_body.yaml"
    T, B = 10.0, 512 if quick else 2048
    rng = np.random.default_rng(1)
    pi0 = np.array([0.4535961214255773, 0.0, 0.8912073600614354])
    mu0 = pi0 * (1.0 + 0.01 * rng.standard_normal((B, 3)))
    print(f"\n## Free-body ensembles, B = {B}, T = 10, at SV(h = 0.01)'s error {e_sv:.3g} "
          f"(load average {os.getloadavg()[0]:.1f})\n")
    print("| scheme | h | lanes | threads | ns / body-step | ns / SV-eq. body-step | "
          "stepping alone: ns / body-step | ns / SV-eq. body-step | its CPU ns / SV-eq. "
          "body-step | whole call: CPU ns / SV-eq. body-step | 0 steps: us / body (CPU) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for name in ("split2", "split4-suzuki"):
        if name not in h_at:
            continue
        integ = hpgen.compile(path, tableau=name)
        steps = round(T / h_at[name])
        h = T / steps
        for lanes in (True, False):
            for threads in (1, 2):
                reps = 3 if quick else 5
                (t, c), (t_0, c_0), (t_l, c_l) = (
                    _batch_time(integ, h, n, mu0, threads, lanes, reps)
                    for n in (steps, 0, LONG * steps))
                ts, cs = (t_l - t_0) / LONG, (c_l - c_0) / LONG
                print(f"| {name} | {h:.4g} | {'yes' if lanes else 'no'} | {threads} | "
                      f"{t / (B * steps) * 1e9:.1f} | {t / (B * T / 0.01) * 1e9:.2f} | "
                      f"{ts / (B * steps) * 1e9:.1f} | {ts / (B * T / 0.01) * 1e9:.2f} | "
                      f"{cs / (B * T / 0.01) * 1e9:.2f} | {c / (B * T / 0.01) * 1e9:.2f} | "
                      f"{t_0 / B * 1e6:.2f} ({c_0 / B * 1e6:.2f}) |")
    print(f"\nload average after the ensembles: {os.getloadavg()[0]:.1f}")


def _batch_time(integ, h, steps, mu0, threads, lanes, reps):
    """(the least wall time, the least process CPU time) of ``reps`` simulate_batch
    calls."""
    wall = cpu = math.inf
    for _ in range(reps):
        t0, c0 = time.perf_counter(), time.process_time()
        integ.simulate_batch(np.eye(3), h, steps, mu0=mu0, every=max(steps, 1),
                             threads=threads, lanes=lanes)
        wall = min(wall, time.perf_counter() - t0)
        cpu = min(cpu, time.process_time() - c0)
    return wall, cpu


def _h_at(pts, e):
    """h with error e by log-log interpolation over (h, error, ...) points, or None."""
    pts = sorted((h, err) for h, err, *_ in pts if err > 0 and math.isfinite(err))
    for (h0, e0), (h1, e1) in zip(pts, pts[1:]):
        if min(e0, e1) <= e <= max(e0, e1) and e0 != e1:
            s = (math.log(e) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(h0) + s * (math.log(h1) - math.log(h0)))
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--splits", help="comma-separated generated schemes of the heavy top "
                    "T = 10 and free body parts (default: SPLITS)")
    ap.add_argument("--part", choices=("all", "heavy", "free-equal", "free", "free-ensembles",
                                       "long"),
                    default="all", help="one part only: heavy top T = 10, free body at equal "
                    "error against the hand-written splittings, free body at SV's error "
                    "(without or with its ensembles), heavy top T = 10 .. 1000")
    ap.add_argument("--cache-dir", help="hpgen's module cache (default: ~/.cache/hpgen)")
    args = ap.parse_args(argv)
    splits = tuple(args.splits.split(",")) if args.splits else SPLITS
    if args.part in ("all", "heavy"):
        heavy_top(args.quick, splits, args.cache_dir)
    if args.part in ("all", "free-equal"):
        free_body_equal_error(args.quick, splits, args.cache_dir)
    if args.part in ("all", "free", "free-ensembles"):
        h_at, e_sv = free_body(args.quick, splits)
        if args.part != "free":
            ensembles(args.quick, h_at, e_sv)
    if args.part in ("all", "long"):
        long_runs(args.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
