"""Energy error at equal cost on the N-link pendulum chain: hpgen's constrained Stormer-Verlet
and its compositions (integrator.compose: order 4 and 6) at several h against MuJoCo RK4 at
several dt, and the long run of the best composition.

    PYTHONPATH=. python benchmarks/chain_compose_bench.py [--n 8 10] [--t 10]
        [--sv-h 1e-3 5e-4] [--c4-h 1e-2 5e-3 2.5e-3] [--c6-h 2e-2 1e-2 5e-3]
        [--rk4-dt 1e-3 2e-3 4e-3 8e-3] [--long-steps 100000] [--long-h 1e-3] [--out DIR]

Per N (the chain of hpgen.bench.multibody.chain, start as benchmarks/chain_bench.py: hanging
straight down, joint rates ~ N(0, 1), seed 0), every runner integrates to T = ``--t``:
- cost: wall seconds of stepping per simulated second (hpgen: its stream's C loop; MuJoCo:
  its rollout calls), and Newton iterations per step for hpgen;
- energy band max_k |E_k - E_0| / (E_0 - V_rest) over the nodes (every 10th for MuJoCo);
- the error at T = 1 against the reference (DOP853 at 1e-13 on the reduced equations) for the
  hpgen runs, as a check of the order.
Then ``--long-steps`` steps of ``--long-h`` with the order-4 composition chosen by
``--long`` (the issue's figure: 1e5 steps of dt = 1e-3 on the 10-link chain): energy band and
joint gaps. MuJoCo (``pip install mujoco``, the peers extra) is skipped when it is not
installed. Speed figures are ratios within one run on one machine; read them against each
other. Results: a table on stdout and OUT/chain_compose.json.
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
sys.path.insert(0, str(ROOT / "benchmarks"))

from chain_bench import band, hpgen_run  # noqa: E402
from hpgen.bench.multibody import chain, hpgen_chain, reference  # noqa: E402
from hpgen.runtime.newton import NewtonOptions  # noqa: E402


def hpgen_rows(integ, label, spec, g0, xi0, hs, T, ref, newton=None):
    """Rows for ``integ`` at each h of ``hs``: runs to T (cost, band) and to 1 (error);
    newton: NewtonOptions or None (the module's default)."""
    rows = []
    for h in hs:
        steps = int(round(T / h))
        sec, E, gaps, _ = hpgen_run(integ, spec, g0, xi0, h, steps, newton=newton)
        its = integ.simulate(g0, h, min(steps, 200), xi0=xi0, every=200,
                              newton=newton).newton_iterations
        n1 = int(round(1.0 / h))
        tr = integ.simulate(g0, 1.0 / n1, n1, xi0=xi0, every=n1, newton=newton)
        last = hpgen_chain.from_hpgen(spec, tr.g[-1:], tr.xi()[-1:])[0]
        rows.append(dict(runner=label, h=h, cost=sec / T, band=band(E, spec),
                         error_T1=chain.trajectory_error(last, ref),
                         iterations_per_step=float(np.sum(its)) / min(steps, 200),
                         gaps=gaps.tolist(), stable=True))
        _show(rows[-1])
    return rows


def mujoco_rows(spec, qpos, qvel, dts, T):
    from hpgen.bench.multibody import mujoco_peer
    rows = []
    for dt in dts:
        steps = int(round(T / dt))
        run = mujoco_peer.run(spec, qpos, qvel, dt, steps, "RK4", sample=10)
        rows.append(dict(runner="MuJoCo RK4", h=dt, cost=run.seconds / T,
                         band=band(run.energy, spec), stable=bool(run.stable)))
        _show(rows[-1])
    return rows


def _show(r):
    extra = "" if "error_T1" not in r else (f" | {r['error_T1']:.2e} | "
                                            f"{r['iterations_per_step']:.1f}")
    print(f"| {r['runner']} | {r['h']:g} | {1e3 * r['cost']:.1f} | {r['band']:.2e}"
          f"{'' if r['stable'] else ' (unstable)'}{extra} |", flush=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 10])
    ap.add_argument("--t", type=float, default=10.0, help="simulated seconds per run")
    ap.add_argument("--sv-h", type=float, nargs="+", default=[1e-3, 5e-4])
    ap.add_argument("--c4-h", type=float, nargs="+", default=[1e-2, 5e-3, 2.5e-3])
    ap.add_argument("--c6-h", type=float, nargs="+", default=[2e-2, 1e-2, 5e-3])
    ap.add_argument("--c4", default="suzuki4", help="the order-4 composition")
    ap.add_argument("--c6", default="kahan-li6", help="the order-6 composition")
    ap.add_argument("--rk4-dt", type=float, nargs="+", default=[1e-3, 2e-3, 4e-3, 8e-3])
    ap.add_argument("--long-steps", type=int, default=100_000)
    ap.add_argument("--long-h", type=float, default=1e-3)
    ap.add_argument("--long", default="suzuki4", help="the composition of the long run")
    ap.add_argument("--out", type=Path, default=Path("bench-chain-compose"))
    ap.add_argument("--newton", choices=["default", "full", "simplified"], default="default",
                    help="hpgen's Newton (default: the module's, full Newton for a sparse J)")
    args = ap.parse_args(argv)
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
    report = {"T": args.t, "N": [], "newton": args.newton}
    for n in args.n:
        spec = chain.ChainSpec(n)
        plain = hpgen.compile(hpgen_chain.MODEL, parameters={"N": n})
        c4 = hpgen.compile(hpgen_chain.MODEL, parameters={"N": n}, compose=args.c4)
        c6 = hpgen.compile(hpgen_chain.MODEL, parameters={"N": n}, compose=args.c6)
        qpos, qvel = chain.initial_joint_state(spec)
        g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
        ref = reference.solve(spec, qpos, qvel, [1.0]).final
        print(f"\nN = {n}, T = {args.t:g}\n\n| runner | h | ms of wall per simulated s | "
              "energy band / (E0 - V_rest) | error at T = 1 | Newton iterations / step |\n"
              "|---|---|---|---|---|---|", flush=True)
        rows = hpgen_rows(plain, "hpgen SV", spec, g0, xi0, args.sv_h, args.t, ref, newton)
        rows += hpgen_rows(c4, f"hpgen SV o {args.c4}", spec, g0, xi0, args.c4_h, args.t, ref, newton)
        rows += hpgen_rows(c6, f"hpgen SV o {args.c6}", spec, g0, xi0, args.c6_h, args.t, ref, newton)
        if have_mujoco:
            rows += mujoco_rows(spec, qpos, qvel, args.rk4_dt, args.t)
        entry = dict(N=n, rows=rows)
        if n == max(args.n) and args.long_steps > 0:
            lc = c4 if args.long == args.c4 else hpgen.compile(
                hpgen_chain.MODEL, parameters={"N": n}, compose=args.long)
            start = time.perf_counter()
            sec, E, gaps, _ = hpgen_run(lc, spec, g0, xi0, args.long_h, args.long_steps,
                                        newton=newton)
            entry["long"] = dict(runner=f"hpgen SV o {args.long}", h=args.long_h,
                                 steps=args.long_steps, band=band(E, spec), gaps=gaps.tolist(),
                                 us_per_step=1e6 * sec / args.long_steps,
                                 wall=time.perf_counter() - start)
            print(f"\nlong run N = {n}: {args.long_steps} steps of h = {args.long_h:g} with "
                  f"{args.long}: energy band {entry['long']['band']:.2e}, joints (position / "
                  f"velocity) {gaps[0]:.1e} / {gaps[1]:.1e}, "
                  f"{entry['long']['us_per_step']:.0f} us/step", flush=True)
        report["N"].append(entry)
        (args.out / "chain_compose.json").write_text(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()
