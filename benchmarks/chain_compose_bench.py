"""Energy error at equal cost on the N-link pendulum chain, against N: hpgen's constrained
Stormer-Verlet, its compositions (integrator.compose) and Gauss collocation at several h
against MuJoCo RK4 at several dt (and Pinocchio's RKMK4 where cheap), for each N which runner
has the smaller energy band at equal cost, by what ratio, and the N where hpgen starts to win.

    PYTHONPATH=. python benchmarks/chain_compose_bench.py [--n 10 16 32] [--t T ...]
        [--runs sv@simplified:1e-3,2e-3 suzuki4:1e-2,5e-3 ...]
        [--rk4-dt 5e-4 1e-3 2e-3 4e-3 8e-3 ...] [--pinocchio aba] [--pinocchio-dt 2e-3 4e-3 8e-3]
        [--pinocchio-max-n 16] [--every 10] [--frames centre] [--start random]
        [--newton default] [--error-max-n 16] [--out DIR]

``--runs``: NAME[@NEWTON]:H,H,... with NAME ``sv`` (the model's constrained Stormer-Verlet), a
composition of it (``hpgen list``: yoshida4, suzuki4, yoshida6, kahan-li6), a Gauss tableau
(``gauss2``, ``gauss3``: exact RKMK, which keeps their order), the constrained splitting step
``split2`` (``split2-fasso``; RATTLE around kick / exact free flow / kick, Newton on the
joints' multipliers only, hpgen.derive.family_split) or a composition of it, ``split2+C``
(C a composition name: ``split2+suzuki4``), and NEWTON ``default`` (the
module's: the chord on the chain), ``full`` or ``simplified`` (J kept across steps; without
@NEWTON: ``--newton``'s), e.g. ``sv@simplified:1e-3,2e-3``; default: default_runs(N)
(step sizes falling with N, where Newton converges over T). Model: hpgen_chain's
``--frames`` (``centre`` examples/capsule_chain.yaml, ``pin`` examples/pendulum_chain.yaml).
Start ``--start`` (chain.named_joint_state; ``random``: hanging straight down, joint rates
~ N(0, 1), seed 0). ``--t``: simulated seconds per N (one value for all, or one per N;
default 100 at N <= 16, 20 at N <= 32, 5 above).

What is timed, for each runner (the cost: the calling thread's CPU time per simulated second,
robust to other processes on the machine; the wall time is in the JSON):
- hpgen (hpgen_chain.run): ``Integrator.stream`` with ``every = --every``: the C loop
  stepping and copying out (g, mu) of every ``every``-th node, in chunks of at most 64 MB of
  records, plus the stream's per-chunk Python. Not timed: the record velocity (a Newton solve
  of the Legendre map per recorded node), the energy and the joints' gaps on the recorded
  nodes (``observe`` in the JSON). The line "stream check" compares the streamed run's cost
  with one ``simulate(every=steps)`` call of the same steps (the fast path, no records).
- MuJoCo RK4 (mujoco_peer.run): its C rollout calls (all steps; the rollout copies out every
  state). Not timed: the energy (mj_forward) of every ``every``-th state.
- Pinocchio RKMK4 (pinocchio_peer.run, accelerations by ``--pinocchio``): its Python step
  loop around the C++ calls; ``floor`` the time of its 4 acceleration evaluations per step
  alone (what a C loop around Pinocchio could not go below). Only at N <= --pinocchio-max-n.
Energy band: max_k |E_k - E_0| / (E_0 - V_rest) on the same nodes for every runner: the start
and every ``every``-th step of its own step size (``--every 1``: every node; at N = 10, T = 20
the bands on every 10th step were 1-8% below every node's, but half for suzuki4 at h = 1e-2,
whose every 10th step is 0.1 s apart), and over |E_0|
(potential zero at the pin). hpgen also: Newton iterations per (composed) step, the joints'
largest position / velocity gaps on its records, the error at T = 1 against the reference
(DOP853 at 1e-13 on the reduced equations; N <= --error-max-n). A run whose Newton fails is
reported on one line and left out.

At equal cost (hpgen.bench.multibody.equal_cost, log-log between the peer's rows, no
extrapolation): each hpgen row's band / MuJoCo RK4's band at the row's cost, and its cost /
RK4's cost at the row's band (below 1: hpgen wins); per N the best of them; the crossover N
where the best cost ratio falls through 1. Speed figures are ratios within one run on one
machine. Results: the tables on stdout, OUT/chain_compose.json and the work-precision figure
OUT/chain_equal_cost.png (band against cost, a panel per N). The default runs take about 7 min
of CPU (N = 10 / 16 / 32: about 1.5 / 2.5 / 3.5 min, most of it stepping) plus the compiles;
``--n 64`` (T = 5) adds the record velocity's 0.1 s per record (not in the cost).
"""
from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hpgen.bench.multibody import chain, equal_cost, hpgen_chain, reference  # noqa: E402
from hpgen.runtime.newton import NewtonOptions  # noqa: E402

DEFAULT_N = [10, 16, 32]
RK4 = "MuJoCo RK4"


def default_runs(n):
    """hpgen's runs at N = n when --runs is not given: the chain's fastest modes quicken with
    N, and Newton fails above a step size that falls with N (at N = 32: SV at h = 2e-3,
    suzuki4 at 5e-3, kahan-li6 at 2e-3), so the step sizes fall with N."""
    if n <= 12:
        return ["sv:1e-3,2e-3", "suzuki4:1e-2,5e-3", "yoshida4:5e-3", "kahan-li6:1e-2"]
    if n <= 24:
        return ["sv:1e-3,2e-3", "suzuki4:5e-3,2.5e-3", "kahan-li6:5e-3"]
    return ["sv:5e-4,1e-3", "suzuki4:2e-3"]


def default_rk4_dt(n):
    """MuJoCo RK4's dt at N = n when --rk4-dt is not given: 5e-4 .. 8e-3, from N = 25 one
    smaller (2.5e-4: RK4's band there reaches hpgen's) and not 8e-3 (unstable at N = 32)."""
    return [5e-4, 1e-3, 2e-3, 4e-3, 8e-3] if n <= 24 else [2.5e-4, 5e-4, 1e-3, 2e-3, 4e-3]


def default_t(n):
    """Simulated seconds at N = n when --t is not given."""
    return 100.0 if n <= 16 else 20.0 if n <= 32 else 5.0


NEWTONS = ("default", "full", "simplified")


def parse_run(text):
    """(name, [h, ...], newton) of NAME[@NEWTON]:H,H,... (newton None: --newton's)."""
    from hpgen.schemes import compositions
    head, _, hs = text.partition(":")
    name, _, newton = head.partition("@")
    comps = [c.name for c in compositions()]
    known = ["sv", "gauss2", "gauss3"] + comps
    known += [f"{b}{c}" for b in ("split2", "split2-fasso") for c in [""] + [
        f"+{c}" for c in comps]]
    try:
        steps = [float(h) for h in hs.split(",")]
    except ValueError:
        steps = []
    if (name not in known or not steps or not all(h > 0 for h in steps)
            or newton not in ("",) + NEWTONS):
        raise SystemExit(f"--runs: expected NAME[@NEWTON]:H,H,... with NAME one of "
                         f"{', '.join(known[:3 + len(comps)])}, split2[+C], "
                         f"split2-fasso[+C] (C a composition), NEWTON one of {', '.join(NEWTONS)} and positive "
                         f"step sizes, got {text!r}")
    return name, steps, newton or None


def newton_options(name):
    """NewtonOptions of a NEWTON name (None: the module's default)."""
    return None if name == "default" else NewtonOptions(simplified=name == "simplified")


def compile_options(name):
    if name == "sv":
        return {}
    if name.startswith("gauss"):
        return dict(tableau=name, tau="cay", rkmk="exact")
    if name.startswith("split2"):
        base, _, comp = name.partition("+")
        return dict(tableau=base, **({"compose": comp} if comp else {}))
    return dict(compose=name)


def band(E, spec):
    """max |E - E0| / (E0 - V_rest) over the finite entries of E."""
    E = np.asarray(E)
    E = E[np.isfinite(E)]
    return float(np.abs(E - E[0]).max() / (E[0] - chain.rest_potential(spec)))


def band_abs(E):
    E = np.asarray(E)
    E = E[np.isfinite(E)]
    return float(np.abs(E - E[0]).max() / abs(E[0]))


def hpgen_rows(integ, label, spec, frames, g0, xi0, hs, T, every, ref, newton=None):
    """Rows for ``integ`` at each h of ``hs`` (rounded to divide T): runs to T (cost, band)
    and, with a reference ``ref``, to 1 (error); newton: NewtonOptions or None."""
    from hpgen.errors import ConvergenceError
    rows = []
    for h in hs:
        steps = int(round(T / h))
        try:
            r = hpgen_chain.run(integ, spec, g0, xi0, T / steps, steps, every=every,
                                newton=newton, frames=frames)
        except ConvergenceError as exc:
            print(f"| {label} | {h:g} | Newton failed: {str(exc).split(';')[0]} |", flush=True)
            rows.append(dict(runner=label, h=h, stable=False, failed=str(exc).split(";")[0]))
            continue
        row = dict(runner=label, h=h, steps=steps, cost=r.cpu_seconds / T, wall=r.seconds / T,
                   observe=r.observe_seconds / T, band=band(r.energy, spec),
                   band_abs=band_abs(r.energy), iterations_per_step=r.iterations / steps,
                   guarded=r.guarded, gaps=r.gaps.tolist(), stable=True)
        if ref is not None:
            n1 = int(round(1.0 / h))
            tr = integ.simulate(g0, 1.0 / n1, n1, xi0=xi0, every=n1, newton=newton)
            last = hpgen_chain.from_hpgen(spec, tr.g[-1:], tr.xi()[-1:], frames)[0]
            row["error_T1"] = chain.trajectory_error(last, ref)
        rows.append(row)
        print(_line(row), flush=True)
    return rows


def peer_rows(peer, spec, qpos, qvel, dts, T, every):
    """Rows of ``peer`` (MuJoCo RK4, or Pinocchio RKMK4 ABA / CRBA) at each dt of ``dts``."""
    from hpgen.bench.multibody import mujoco_peer, pinocchio_peer
    rows = []
    for dt in dts:
        steps = int(round(T / dt))
        if peer == RK4:
            run = mujoco_peer.run(spec, qpos, qvel, T / steps, steps, "RK4", sample=every)
            extra = dict(observe=run.observe_seconds / T)
        else:
            run = pinocchio_peer.run(spec, qpos, qvel, T / steps, steps, sample=every,
                                     dynamics=peer.split()[-1].lower())
            extra = dict(floor=run.dynamics_seconds / T)
        rows.append(dict(runner=peer, h=dt, steps=steps, cost=run.cpu_seconds / T,
                         wall=run.seconds / T, band=band(run.energy, spec),
                         band_abs=band_abs(run.energy), stable=bool(run.stable), **extra))
        print(_line(rows[-1]), flush=True)
    return rows


def stream_check(integ, spec, g0, xi0, h, steps, every, newton=None):
    """CPU us per step of one simulate(every=steps) call and of the stream hpgen_chain.run
    times (every ``every``-th node, its chunks; no energies) over the same ``steps``: the
    best of two, alternating."""
    one, streamed = [], []
    chunk = hpgen_chain.chunk_steps(spec, steps, every)
    for _ in range(2):
        start = time.thread_time()
        integ.simulate(g0, h, steps, xi0=xi0, every=steps, newton=newton)
        one.append(time.thread_time() - start)
        start = time.thread_time()
        for _part in integ.stream(g0, h, steps, xi0=xi0, every=every, chunk=chunk,
                                  newton=newton):
            pass
        streamed.append(time.thread_time() - start)
    return dict(h=h, steps=steps, simulate_us=1e6 * min(one) / steps,
                stream_us=1e6 * min(streamed) / steps)


def _line(r):
    if "cost" not in r:
        return f"| {r['runner']} | {r['h']:g} | Newton failed: {r['failed']} |"
    hp = "iterations_per_step" in r
    extra = (f"{r['iterations_per_step']:.1f} | {r['gaps'][0]:.0e} / {r['gaps'][1]:.0e} | "
             + (f"{r['error_T1']:.1e}" if "error_T1" in r else "-")) if hp else "- | - | -"
    cost = f"{1e3 * r['cost']:.1f}" + (f" (floor {1e3 * r['floor']:.1f})" if "floor" in r
                                       else "")
    vs = r.get("vs_rk4") or {}
    eq = " | ".join("-" if vs.get(k) is None else f"{vs[k]:.2g}"
                    for k in ("band_ratio", "cost_ratio"))
    return (f"| {r['runner']} | {r['h']:g} | {cost} | {r['band']:.2e}"
            f"{'' if r['stable'] else ' (unstable)'} | {r['band_abs']:.2e} | {extra} | {eq} |")


HEADER = ("| runner | h | CPU ms per simulated s | band / (E0 - V_rest) | band / abs(E0) | "
          "Newton it/step | joints (pos / vel) | error at T = 1 | band / RK4's at equal cost "
          "| cost / RK4's at equal band |\n|---|---|---|---|---|---|---|---|---|---|")
SUMMARY = ("| N | T | best band ratio at equal cost (hpgen row) | best cost ratio at equal "
           "band (hpgen row) | hpgen wins |\n|---|---|---|---|---|")


def _summary_line(n, T, s):
    def part(key):
        v, row = s[f"{key}_ratio"], s[f"{key}_row"]
        return "-" if v is None else f"{v:.2g} ({row[0]} {row[1]:g})"
    return f"| {n} | {T:g} | {part('band')} | {part('cost')} | {'yes' if s['wins'] else 'no'} |"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=DEFAULT_N)
    ap.add_argument("--t", type=float, nargs="+", default=None,
                    help="simulated seconds per run: one value, or one per N")
    ap.add_argument("--runs", nargs="+", default=None,
                    help="NAME:H,H,... (see above); default: default_runs(N)")
    ap.add_argument("--rk4-dt", type=float, nargs="+", default=None,
                    help="MuJoCo RK4's dt; default: default_rk4_dt(N)")
    ap.add_argument("--pinocchio", choices=["aba", "crba", "none"], default="aba")
    ap.add_argument("--pinocchio-dt", type=float, nargs="+", default=[2e-3, 4e-3, 8e-3])
    ap.add_argument("--pinocchio-max-n", type=int, default=16)
    ap.add_argument("--every", type=int, default=10,
                    help="record (and take the energy of) every this many steps; 1: every node")
    ap.add_argument("--frames", choices=sorted(hpgen_chain.MODELS), default="centre")
    ap.add_argument("--start", default="random", help="chain.named_joint_state's name")
    ap.add_argument("--error-max-n", type=int, default=16,
                    help="the error at T = 1 (a DOP853 reference) up to this N")
    ap.add_argument("--out", type=Path, default=Path("bench-chain-compose"))
    ap.add_argument("--newton", choices=NEWTONS, default="default",
                    help="hpgen's Newton where a run does not name one (default: the module's)")
    args = ap.parse_args(argv)
    given = None if args.runs is None else [parse_run(text) for text in args.runs]
    ts = [default_t(n) for n in args.n] if args.t is None else (
        args.t * len(args.n) if len(args.t) == 1 else args.t)
    if len(ts) != len(args.n) or args.every < 1:
        raise SystemExit("--t: expected one value or one per N; --every: a positive integer")
    import hpgen
    peers = []
    try:
        import mujoco  # noqa: F401
        peers.append(RK4)
    except ImportError:
        print("mujoco is not installed (pip install mujoco): MuJoCo RK4 skipped")
    if args.pinocchio != "none":
        try:
            import pinocchio  # noqa: F401
            peers.append(f"Pinocchio RKMK4 {args.pinocchio.upper()}")
        except ImportError:
            print("pinocchio is not installed (pip install pin): Pinocchio skipped")
    args.out.mkdir(parents=True, exist_ok=True)
    report = {"frames": args.frames, "start": args.start, "newton": args.newton,
              "every": args.every, "N": []}
    model = hpgen_chain.MODELS[args.frames]
    summaries, panels = [], []
    for n, T in zip(args.n, ts):
        spec = chain.ChainSpec(n)
        qpos, qvel = chain.named_joint_state(spec, args.start)
        g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), args.frames)
        ref = (reference.solve(spec, qpos, qvel, [1.0]).final if n <= args.error_max_n
               else None)
        print(f"\nN = {n}, T = {T:g}, {model.name}, start {args.start}, every {args.every}"
              f"\n\n{HEADER}", flush=True)
        rows, check = [], None
        for name, hs, which in given or [parse_run(text) for text in default_runs(n)]:
            integ = hpgen.compile(model, parameters={"N": n}, **compile_options(name))
            which = which or args.newton
            newton = newton_options(which)
            label = ("hpgen SV" if name == "sv" else f"hpgen {name}") + (
                "" if which == "default" else f" ({which})")
            rows += hpgen_rows(integ, label, spec, args.frames, g0, xi0, hs, T, args.every,
                               ref, newton)
            if check is None:
                steps = int(min(round(T / hs[0]), 10_000) // args.every * args.every)
                check = dict(runner=label, **stream_check(integ, spec, g0, xi0, hs[0], steps,
                                                          args.every, newton))
                print(f"stream check, {label} h = {hs[0]:g}, {steps} steps: one simulate call "
                      f"{check['simulate_us']:.1f} us/step, the stream (every {args.every}) "
                      f"{check['stream_us']:.1f} us/step (CPU, best of 2)", flush=True)
        for peer in peers:
            if peer == RK4 or n <= args.pinocchio_max_n:
                dts = ((args.rk4_dt or default_rk4_dt(n)) if peer == RK4
                       else args.pinocchio_dt)
                rows += peer_rows(peer, spec, qpos, qvel, dts, T, args.every)
        rk4 = [r for r in rows if r["runner"] == RK4]
        mine = [r for r in rows if r["runner"].startswith("hpgen") and "cost" in r]
        for r in mine:
            r["vs_rk4"] = equal_cost.compare(r, rk4) if rk4 else None
        s = equal_cost.summary(mine, rk4) if rk4 else None
        print(f"\nN = {n}, T = {T:g}: at equal cost\n\n{HEADER}")
        for r in rows:
            print(_line(r))
        summaries.append((n, T, s))
        panels.append((n, T, [r for r in rows if "cost" in r]))
        report["N"].append(dict(N=n, T=T, rows=rows, stream_check=check, vs_rk4=s))
        (args.out / "chain_compose.json").write_text(json.dumps(report, indent=1))
    figure = args.out / "chain_equal_cost.png"
    equal_cost.plot(panels, figure, f"chain, start {args.start}, energy on every "
                    f"{args.every}th step")
    if any(s is not None for _, _, s in summaries):
        print(f"\nhpgen against MuJoCo RK4 (ratios below 1: hpgen wins)\n\n{SUMMARY}")
        for n, T, s in summaries:
            if s is not None:
                print(_summary_line(n, T, s))
        cross = equal_cost.crossover([n for n, _, _ in summaries],
                                     [None if s is None else s["cost_ratio"]
                                      for _, _, s in summaries])
        report["crossover_N"] = cross
        print("\ncrossover (best cost ratio at equal band falls through 1): "
              + ("not reached" if cross is None else f"N = {cross:.1f}"))
        (args.out / "chain_compose.json").write_text(json.dumps(report, indent=1))
    print(f"work-precision figure -> {figure}")


if __name__ == "__main__":
    main()
