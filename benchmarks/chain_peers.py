"""The N-link 3-D pendulum chain (hpgen.bench.multibody) run by its peers, MuJoCo (RK4,
Euler, implicitfast through its C rollout) and Pinocchio (RKMK4 in a Python step loop, the
accelerations by ABA or by the mass matrix and Cholesky),
against the independent DOP853 reference, for N = 2, 4, 8, 16, 32, 64, in one process.

    pip install -c constraints.txt -e '.[peers]'
    PYTHONPATH=. python benchmarks/chain_peers.py [--n 2 4 8 16 32 64] [--steps 100000] [--budget 30]
                                     [--dt 1e-3] [--json chain_peers.json]

Start: the chain hanging straight down, joint angular velocities qvel ~ N(0, 1) (seed 0;
chain.initial_joint_state). For every N and peer:
- time per step: MuJoCo the wall time of its rollout calls alone; Pinocchio the Python step
  loop (4 acceleration evaluations, 4 exponential maps and NumPy arithmetic per step) and, in
  brackets, the CPU time of its 4 acceleration evaluations (what a C loop around Pinocchio could
  not go below);
- energy band over ``steps`` steps of dt: max_k |E_k - E_0| / (E_0 - V_rest), sampled every 10
  steps, E the total energy and V_rest the potential energy of the chain hanging at rest, so
  the band is relative to the energy above the chain's minimum and does not depend on where
  the potential's zero is; the column ``/|E0|`` divides by |E_0| instead (potential zero at the
  pin: the normalisation of MuJoCo figures quoted elsewhere);
- steps: the same for every peer of one N (chaotic trajectories: bands over different
  horizons do not compare), ``--steps`` unless 300-step probes predict more than ``--budget``
  seconds for the slowest peer, then budget / (its time per step) rounded down to thousands
  (at least 1000); the table says how many;
- error at T = 1: max over links of |x_i - x_i_ref| (m) and of the rotation matrices' entries,
  from a separate run of round(1 / dt) steps, against DOP853 at rtol = atol = 1e-13.
A run that blows up (MuJoCo resets the simulation, or a state becomes non-finite) is marked
"unstable"; its band then is the band up to the blow-up.
"""
from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

from hpgen.bench.multibody import chain, mujoco_peer, pinocchio_peer, reference

PEERS = ("MuJoCo RK4", "MuJoCo Euler", "MuJoCo implicitfast", "Pinocchio RKMK4 ABA",
         "Pinocchio RKMK4 CRBA")
SAMPLE = 10


def run_peer(peer, spec, qpos, qvel, dt, steps):
    if peer.startswith("MuJoCo"):
        return mujoco_peer.run(spec, qpos, qvel, dt, steps, peer.split()[1], sample=SAMPLE)
    return pinocchio_peer.run(spec, qpos, qvel, dt, steps, sample=SAMPLE,
                              dynamics=peer.split()[2].lower())


def steps_for(peers, spec, qpos, qvel, dt, max_steps, budget):
    """The common step count of one N (see the module docstring)."""
    cost = max(run_peer(peer, spec, qpos, qvel, dt, 300).seconds / 300 for peer in peers)
    if cost * max_steps <= budget:
        return max_steps
    return max(1000, int(budget / cost) // 1000 * 1000)


def measure(peer, spec, qpos, qvel, dt, steps, final_ref):
    long = run_peer(peer, spec, qpos, qvel, dt, steps)
    e0 = long.energy[0]
    finite = long.energy[np.isfinite(long.energy)]
    dev = np.abs(finite - e0).max()
    short = run_peer(peer, spec, qpos, qvel, dt, round(1.0 / dt))
    error = (chain.trajectory_error(chain.from_joint(spec, short.qpos, short.qvel), final_ref)
             if short.stable else float("nan"))
    row = {"N": spec.n, "peer": peer, "steps": long.steps, "us_per_step":
           1e6 * long.seconds / long.steps, "band": dev / (e0 - chain.rest_potential(spec)),
           "band_abs_E0": dev / abs(e0), "error_T1": error, "stable": long.stable}
    if hasattr(long, "dynamics_seconds"):
        row["dynamics_us_per_step"] = 1e6 * long.dynamics_seconds / long.steps
    return row


def fmt(row):
    step = f"{row['us_per_step']:.1f}"
    if "dynamics_us_per_step" in row:
        step += f" ({row['dynamics_us_per_step']:.1f})"
    note = "" if row["stable"] else "unstable"
    return (f"| {row['N']} | {row['peer']} | {row['steps']} | {step} | {row['band']:.2e} | "
            f"{row['band_abs_E0']:.2e} | {row['error_T1']:.2e} | {note} |")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, nargs="+", default=[2, 4, 8, 16, 32, 64])
    parser.add_argument("--steps", type=int, default=100_000)
    parser.add_argument("--budget", type=float, default=100.0,
                        help="seconds of the slowest peer's long run before the step count "
                             "of that N is reduced")
    parser.add_argument("--dt", type=float, default=1e-3)
    parser.add_argument("--peers", nargs="+", default=list(PEERS), choices=PEERS)
    parser.add_argument("--json", type=Path, help="write the rows as JSON here")
    args = parser.parse_args(argv)
    rows, refs = [], []
    print("| N | peer | steps | us/step | energy band / (E0 - V_rest) | band / abs(E0) | "
          "error at T = 1 | |")
    print("|---|---|---|---|---|---|---|---|")
    for n in args.n:
        spec = chain.ChainSpec(n)
        qpos, qvel = chain.initial_joint_state(spec)
        start = time.perf_counter()
        ref = reference.solve(spec, qpos, qvel, [1.0])
        refs.append({"N": n, "seconds": time.perf_counter() - start, "nfev": ref.nfev,
                     "quat_drift": ref.quat_drift})
        steps = steps_for(args.peers, spec, qpos, qvel, args.dt, args.steps, args.budget)
        for peer in args.peers:
            rows.append(measure(peer, spec, qpos, qvel, args.dt, steps, ref.final))
            print(fmt(rows[-1]), flush=True)
    print()
    for r in refs:
        print(f"reference N = {r['N']}: DOP853 {r['seconds']:.1f} s, {r['nfev']} evaluations, "
              f"quaternion norm drift {r['quat_drift']:.1e}")
    if args.json:
        args.json.write_text(json.dumps({"dt": args.dt, "rows": rows, "reference": refs},
                                        indent=1))


if __name__ == "__main__":
    main()
