"""Energy error at equal cost on the N-link pendulum chain: hpgen's constrained Stormer-Verlet,
its compositions (integrator.compose) and Gauss collocation at several h against MuJoCo RK4
at several dt, one table of cost per simulated second against energy band.

    PYTHONPATH=. python benchmarks/chain_compose_bench.py [--n 10] [--t 100]
        [--runs sv:1e-3,2e-3 suzuki4:1e-2,5e-3 kahan-li6:2e-2,1e-2 gauss2:1e-2]
        [--rk4-dt 5e-4 1e-3 2e-3 4e-3 8e-3 1.6e-2 3.2e-2] [--frames centre] [--start random]
        [--newton default] [--out DIR]

``--runs``: NAME:H,H,... with NAME ``sv`` (the model's constrained Stormer-Verlet), a
composition of it (``hpgen list``: yoshida4, suzuki4, yoshida6, kahan-li6) or a Gauss tableau
(``gauss2``, ``gauss3``: exact RKMK, which keeps their order). Model: hpgen_chain's
``--frames`` (``centre`` examples/capsule_chain.yaml, ``pin`` examples/pendulum_chain.yaml:
the same discretization, the trajectories agree to round-off). Start ``--start``
(chain.named_joint_state; ``random``: hanging straight down, joint rates ~ N(0, 1), seed 0).

Per N every runner integrates to T = ``--t``:
- cost: wall ms of stepping per simulated second (hpgen: its stream's C loop; MuJoCo: its
  rollout calls); Newton iterations per (composed) step for hpgen;
- energy band max_k |E_k - E_0| / (E_0 - V_rest) over the nodes (every 10th for MuJoCo), and
  the same divided by |E_0| (potential zero at the pin);
- hpgen: the joints' largest position / velocity gaps and the error at T = 1 against the
  reference (DOP853 at 1e-13 on the reduced equations), a check of the order;
- a run whose Newton fails (h too large for the motion) is reported on one line and left out;
- at equal cost: MuJoCo RK4's band interpolated (log-log, between its dt) at the hpgen row's
  cost, and the ratio hpgen band / RK4 band (below 1: hpgen has the smaller error); and
  RK4's cost at the hpgen row's band, and the ratio of costs (below 1: hpgen is cheaper).
MuJoCo (the peers extra) is skipped when it is not installed. Speed figures are ratios within
one run on one machine. Results: the table on stdout and OUT/chain_compose.json.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from chain_bench import band, hpgen_run  # noqa: E402
from hpgen.bench.multibody import chain, hpgen_chain, reference  # noqa: E402
from hpgen.runtime.newton import NewtonOptions  # noqa: E402

DEFAULT_RUNS = ["sv:1e-3,2e-3", "suzuki4:1e-2,5e-3", "kahan-li6:2e-2,1e-2", "gauss2:1e-2"]


def parse_run(text):
    """(name, [h, ...]) of NAME:H,H,..."""
    from hpgen.schemes import compositions
    name, _, hs = text.partition(":")
    known = ["sv", "gauss2", "gauss3"] + [c.name for c in compositions()]
    try:
        steps = [float(h) for h in hs.split(",")]
    except ValueError:
        steps = []
    if name not in known or not steps or not all(h > 0 for h in steps):
        raise SystemExit(f"--runs: expected NAME:H,H,... with NAME one of {', '.join(known)} "
                         f"and positive step sizes, got {text!r}")
    return name, steps


def compile_options(name):
    if name == "sv":
        return {}
    if name.startswith("gauss"):
        return dict(tableau=name, tau="cay", rkmk="exact")
    return dict(compose=name)


def hpgen_rows(integ, label, spec, frames, g0, xi0, hs, T, ref, newton=None):
    """Rows for ``integ`` at each h of ``hs``: runs to T (cost, band) and to 1 (error);
    newton: NewtonOptions or None (the module's default)."""
    from hpgen.errors import ConvergenceError
    rows = []
    for h in hs:
        steps = int(round(T / h))
        try:
            r = hpgen_run(integ, spec, g0, xi0, T / steps, steps, newton=newton, frames=frames)
        except ConvergenceError as exc:
            print(f"| {label} | {h:g} | Newton failed: {str(exc).split(';')[0]} |", flush=True)
            continue
        n1 = int(round(1.0 / h))
        tr = integ.simulate(g0, 1.0 / n1, n1, xi0=xi0, every=n1, newton=newton)
        last = hpgen_chain.from_hpgen(spec, tr.g[-1:], tr.xi()[-1:], frames)[0]
        rows.append(dict(runner=label, h=h, cost=r.seconds / T, band=band(r.energy, spec),
                         band_abs=_band_abs(r.energy), error_T1=chain.trajectory_error(last, ref),
                         iterations_per_step=r.iterations / steps, gaps=r.gaps.tolist(),
                         stable=True))
        print(_line(rows[-1]), flush=True)
    return rows


def mujoco_rows(spec, qpos, qvel, dts, T):
    from hpgen.bench.multibody import mujoco_peer
    rows = []
    for dt in dts:
        steps = int(round(T / dt))
        run = mujoco_peer.run(spec, qpos, qvel, T / steps, steps, "RK4", sample=10)
        rows.append(dict(runner="MuJoCo RK4", h=dt, cost=run.seconds / T,
                         band=band(run.energy, spec), band_abs=_band_abs(run.energy),
                         stable=bool(run.stable)))
        print(_line(rows[-1]), flush=True)
    return rows


def _band_abs(E):
    E = np.asarray(E)
    E = E[np.isfinite(E)]
    return float(np.abs(E - E[0]).max() / abs(E[0]))


def rk4_band_at(cost, rk4):
    """MuJoCo RK4's band at ``cost`` (log-log interpolation between its stable rows), or None
    outside their range."""
    pts = sorted((r["cost"], r["band"]) for r in rk4 if r["stable"] and r["band"] > 0)
    if len(pts) < 2 or not pts[0][0] <= cost <= pts[-1][0]:
        return None
    c, b = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return float(np.exp(np.interp(np.log(cost), c, b)))


def rk4_cost_at(band_value, rk4):
    """MuJoCo RK4's cost per simulated second at an energy band (log-log interpolation between
    its stable rows), or None outside their range."""
    pts = sorted((r["band"], r["cost"]) for r in rk4 if r["stable"] and r["band"] > 0)
    if len(pts) < 2 or not pts[0][0] <= band_value <= pts[-1][0]:
        return None
    b, c = np.log([p[0] for p in pts]), np.log([p[1] for p in pts])
    return float(np.exp(np.interp(np.log(band_value), b, c)))


def _line(r):
    hp = "error_T1" in r
    extra = (f"{r['error_T1']:.2e} | {r['iterations_per_step']:.1f} | "
             f"{r['gaps'][0]:.0e} / {r['gaps'][1]:.0e}" if hp else "- | - | -")
    eq = r.get("rk4_band_at_cost")
    eq = "-" if eq is None else f"{eq:.1e} ({r['band'] / eq:.2g})"
    eqc = r.get("rk4_cost_at_band")
    eq += " | " + ("-" if eqc is None else f"{1e3 * eqc:.1f} ({r['cost'] / eqc:.2g})")
    return (f"| {r['runner']} | {r['h']:g} | {1e3 * r['cost']:.1f} | {r['band']:.2e}"
            f"{'' if r['stable'] else ' (unstable)'} | {r['band_abs']:.2e} | {extra} | {eq} |")


HEADER = ("| runner | h | ms per simulated s | band / (E0 - V_rest) | band / abs(E0) | "
          "error at T = 1 | Newton it/step | joints (pos / vel) | RK4 band at equal cost "
          "(hpgen / RK4) | RK4 ms per s at equal band (hpgen / RK4) |\n"
          "|---|---|---|---|---|---|---|---|---|---|")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[10])
    ap.add_argument("--t", type=float, default=100.0, help="simulated seconds per run")
    ap.add_argument("--runs", nargs="+", default=DEFAULT_RUNS, help="NAME:H,H,... (see above)")
    ap.add_argument("--rk4-dt", type=float, nargs="+",
                    default=[5e-4, 1e-3, 2e-3, 4e-3, 8e-3, 1.6e-2, 3.2e-2])
    ap.add_argument("--frames", choices=sorted(hpgen_chain.MODELS), default="centre")
    ap.add_argument("--start", default="random", help="chain.named_joint_state's name")
    ap.add_argument("--out", type=Path, default=Path("bench-chain-compose"))
    ap.add_argument("--newton", choices=["default", "full", "simplified"], default="default",
                    help="hpgen's Newton (default: the module's, full Newton for a sparse J)")
    args = ap.parse_args(argv)
    runs = [parse_run(text) for text in args.runs]
    import hpgen
    try:
        import mujoco  # noqa: F401
        have_mujoco = True
    except ImportError:
        have_mujoco = False
        print("mujoco is not installed (pip install mujoco): MuJoCo RK4 skipped")
    args.out.mkdir(parents=True, exist_ok=True)
    newton = None if args.newton == "default" else NewtonOptions(
        simplified=args.newton == "simplified")
    report = {"T": args.t, "frames": args.frames, "start": args.start, "newton": args.newton,
              "N": []}
    model = hpgen_chain.MODELS[args.frames]
    for n in args.n:
        spec = chain.ChainSpec(n)
        qpos, qvel = chain.named_joint_state(spec, args.start)
        g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), args.frames)
        ref = reference.solve(spec, qpos, qvel, [1.0]).final
        print(f"\nN = {n}, T = {args.t:g}, {model.name}, start {args.start}\n\n{HEADER}",
              flush=True)
        rows = []
        for name, hs in runs:
            integ = hpgen.compile(model, parameters={"N": n}, **compile_options(name))
            label = "hpgen SV" if name == "sv" else f"hpgen {name}"
            rows += hpgen_rows(integ, label, spec, args.frames, g0, xi0, hs, args.t, ref,
                               newton)
        rk4 = mujoco_rows(spec, qpos, qvel, args.rk4_dt, args.t) if have_mujoco else []
        print(f"\nN = {n}: at equal cost\n\n{HEADER}")
        for r in rows:
            r["rk4_band_at_cost"] = rk4_band_at(r["cost"], rk4)
            r["rk4_cost_at_band"] = rk4_cost_at(r["band"], rk4)
            print(_line(r))
        for r in rk4:
            print(_line(r))
        report["N"].append(dict(N=n, rows=rows + rk4))
        (args.out / "chain_compose.json").write_text(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()
