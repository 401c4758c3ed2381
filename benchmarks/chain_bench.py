"""The N-link pendulum chain (examples/capsule_chain.yaml, ``--frames pin``
examples/pendulum_chain.yaml: SE3^N, ball joints as holonomic constraints, constrained
Stormer-Verlet) against MuJoCo (RK4, Euler, implicitfast through
mujoco.rollout) and Pinocchio (RKMK4, accelerations by CRBA + Cholesky; ABA on request) in
one run, for N in a list, with a work-precision figure per N.

    PYTHONPATH=. python benchmarks/chain_bench.py [--n 2 4 8 16 32 64] [--budget 120]
        [--steps 100000] [--dt 1e-3] [--wp-h 4e-3 2e-3 1e-3 5e-4 2.5e-4] [--out bench-chain]
        [--peers ...] [--frames centre] [--quick]

Per N (the chain of hpgen.bench.multibody.chain; start: hanging straight down, joint rates
qvel ~ N(0, 1), seed 0):
- cold compile: hpgen.compile in a subprocess with a fresh build cache, wall time. A compile
  that exceeds ``--budget`` seconds is stopped, and that N and every larger N are skipped (the
  table says so): compile time grows with N, so the run ends there instead of waiting.
- the long run, ``--steps`` steps of ``--dt`` for hpgen and every peer: time per step (hpgen
  the stream's calls, its C loop recording every 10th node (hpgen_chain.run); MuJoCo its
  rollout calls; Pinocchio its Python step loop), energy band
  max_k |E_k - E_0| / (E_0 - V_rest) (V_rest: the chain at rest; chain_peers.py's
  normalisation) over the start and every 10th node for every runner, and for hpgen the
  joints' largest position and velocity gaps over those nodes (chain.constraint_residual).
- the work-precision figure ``OUT/chain_wp_N<N>.png`` (and the rows in OUT/chain_bench.json):
  for hpgen at each h of ``--wp-h`` and each peer at the same dt, runs to T = 1: the error at
  T = 1 against the reference (hpgen.bench.multibody.reference: DOP853 at 1e-13 on the
  reduced equations) and the energy band over [0, 1], each against the run's wall time.
  An unstable peer run (MuJoCo reset, non-finite state) is left out of the figure and marked
  in the table.
Speed figures are ratios within one run on one machine; read them against each other.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hpgen.bench.multibody import chain, hpgen_chain, mujoco_peer, pinocchio_peer  # noqa: E402
from hpgen.bench.multibody import reference  # noqa: E402

PEERS = ("MuJoCo RK4", "MuJoCo Euler", "MuJoCo implicitfast", "Pinocchio RKMK4 CRBA",
         "Pinocchio RKMK4 ABA")
#: ABA loses accuracy on long chains of these links (pinocchio_peer): CRBA by default
DEFAULT_PEERS = PEERS[:4]
COMPILE = ("import sys, time, hpgen; n, cache = int(sys.argv[1]), sys.argv[2]; "
           "t = time.perf_counter(); hpgen.compile(sys.argv[3], parameters={'N': n}, "
           "cache_dir=cache); print(time.perf_counter() - t)")


def cold_compile(n, cache, budget, model=hpgen_chain.CENTRE_MODEL):
    """Seconds of a cold hpgen.compile of the chain with N = n into ``cache``, or None when it
    exceeded ``budget`` (the subprocess is stopped)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    try:
        out = subprocess.run([sys.executable, "-c", COMPILE, str(n), str(cache),
                              str(model)], capture_output=True, text=True,
                             timeout=budget, cwd=ROOT, env=env)
    except subprocess.TimeoutExpired:
        return None
    if out.returncode != 0:
        raise SystemExit(f"compile of N = {n} failed: {out.stderr.strip().splitlines()[-1]}")
    return float(out.stdout.strip().splitlines()[-1])


def band(E, spec):
    E = np.asarray(E)
    E = E[np.isfinite(E)]
    return float(np.abs(E - E[0]).max() / (E[0] - chain.rest_potential(spec)))


def hpgen_run(integ, spec, g0, xi0, h, steps, every=10, newton=None, frames="pin"):
    """hpgen_chain.run: ``steps`` steps of h, every ``every``-th node recorded and streamed
    (the stream's calls timed; the energy and the joints' gaps on the records)."""
    return hpgen_chain.run(integ, spec, g0, xi0, h, steps, every=every, newton=newton,
                           frames=frames)


def peer_run(peer, spec, qpos, qvel, dt, steps):
    if peer.startswith("MuJoCo"):
        return mujoco_peer.run(spec, qpos, qvel, dt, steps, peer.split()[1], sample=10)
    return pinocchio_peer.run(spec, qpos, qvel, dt, steps, sample=10,
                              dynamics=peer.split()[2].lower())


def peer_final(spec, run):
    return chain.from_joint(spec, run.qpos, run.qvel)


def work_precision(integ, spec, peers, qpos, qvel, g0, xi0, hs, ref, frames="centre"):
    """Rows (runner, h, seconds, error at T = 1, energy band on [0, 1], stable)."""
    rows = []
    for h in hs:
        steps = int(round(1.0 / h))
        h = 1.0 / steps
        r = hpgen_run(integ, spec, g0, xi0, h, steps, frames=frames)
        rows.append(("hpgen SV", h, r.seconds, chain.trajectory_error(r.last, ref),
                     band(r.energy, spec), True))
        for peer in peers:
            run = peer_run(peer, spec, qpos, qvel, h, steps)
            err = chain.trajectory_error(peer_final(spec, run), ref) if run.stable else np.nan
            rows.append((peer, h, run.seconds, err, band(run.energy, spec), bool(run.stable)))
    return rows


def plot(n, rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for runner in dict.fromkeys(r[0] for r in rows):
        pts = sorted((r for r in rows if r[0] == runner and r[5]), key=lambda r: r[2])
        if not pts:
            continue
        sec = [r[2] for r in pts]
        style = dict(marker="o" if runner.startswith("hpgen") else "s", label=runner)
        axes[0].loglog(sec, [r[3] for r in pts], **style)
        axes[1].loglog(sec, [max(r[4], 1e-17) for r in pts], **style)
    axes[0].set(xlabel="wall time to T = 1 (s)", ylabel="error at T = 1 (max over links, m)",
                title=f"N = {n}: trajectory error")
    axes[1].set(xlabel="wall time to T = 1 (s)", ylabel="energy band / (E0 - V_rest)",
                title=f"N = {n}: energy error")
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[2, 4, 8, 16, 32, 64])
    ap.add_argument("--budget", type=float, default=120.0,
                    help="seconds a cold compile may take before that N (and larger) is skipped")
    ap.add_argument("--steps", type=int, default=100_000)
    ap.add_argument("--dt", type=float, default=1e-3)
    ap.add_argument("--wp-h", type=float, nargs="+", default=[4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4])
    ap.add_argument("--peers", nargs="*", default=list(DEFAULT_PEERS), choices=PEERS)
    ap.add_argument("--out", type=Path, default=Path("bench-chain"))
    ap.add_argument("--frames", choices=sorted(hpgen_chain.MODELS), default="centre",
                    help="hpgen's model file: frames at the link centres or at the pin")
    ap.add_argument("--quick", action="store_true",
                    help="a smoke run: 2000 long steps, two work-precision step sizes")
    args = ap.parse_args(argv)
    if args.quick:
        args.steps, args.wp_h = 2000, [4e-3, 2e-3]
    import hpgen
    from hpgen.model import load_model
    args.out.mkdir(parents=True, exist_ok=True)
    path = hpgen_chain.MODELS[args.frames]
    model = load_model(path)
    table, report = [], {"dt": args.dt, "steps": args.steps, "budget": args.budget, "N": []}
    for n in sorted(args.n):
        spec = chain.ChainSpec(n)
        with tempfile.TemporaryDirectory(prefix="hpgen-cold-") as cache:
            compile_s = cold_compile(n, cache, args.budget, path)
            if compile_s is None:
                skipped = [m for m in sorted(args.n) if m >= n]
                print(f"N = {n}: the cold compile exceeded the budget of {args.budget:g} s; "
                      f"skipped N = {', '.join(map(str, skipped))}", flush=True)
                report["skipped"] = skipped
                break
            integ = hpgen.compile(path, parameters={"N": n}, cache_dir=cache)
        hpgen_chain.check_parameters(spec, model, args.frames)
        qpos, qvel = chain.initial_joint_state(spec)
        g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), args.frames)
        r = hpgen_run(integ, spec, g0, xi0, args.dt, args.steps, frames=args.frames)
        rows = [dict(runner="hpgen SV", us_per_step=1e6 * r.seconds / args.steps,
                     band=band(r.energy, spec), gaps=r.gaps.tolist(), stable=True,
                     compile_s=compile_s)]
        for peer in args.peers:
            run = peer_run(peer, spec, qpos, qvel, args.dt, args.steps)
            rows.append(dict(runner=peer, us_per_step=1e6 * run.seconds / args.steps,
                             band=band(run.energy, spec), stable=bool(run.stable)))
        ref = reference.solve(spec, qpos, qvel, [1.0]).final
        wp = work_precision(integ, spec, args.peers, qpos, qvel, g0, xi0, args.wp_h, ref,
                            args.frames)
        figure = args.out / f"chain_wp_N{n}.png"
        plot(n, wp, figure)
        report["N"].append(dict(N=n, long=rows, work_precision=[
            dict(runner=r[0], h=r[1], seconds=r[2], error_T1=r[3], band=r[4], stable=r[5])
            for r in wp], figure=str(figure)))
        for r in rows:
            extra = (f"compile {r['compile_s']:.1f} s; joints {r['gaps'][0]:.1e} / "
                     f"{r['gaps'][1]:.1e}" if "gaps" in r else "")
            table.append(f"| {n} | {r['runner']} | {r['us_per_step']:.2f} | {r['band']:.2e}"
                         f"{'' if r['stable'] else ' (unstable)'} | {extra} |")
        print("\n".join(table[-len(rows):]), flush=True)
        print(f"  work-precision -> {figure}", flush=True)
    (args.out / "chain_bench.json").write_text(json.dumps(report, indent=1))
    print(f"\n{args.steps} steps of dt = {args.dt:g}\n")
    print("| N | runner | us/step | energy band / (E0 - V_rest) | hpgen: cold compile; joints "
          "(position / velocity) |")
    print("|---|---|---|---|---|")
    print("\n".join(table))


if __name__ == "__main__":
    main()
