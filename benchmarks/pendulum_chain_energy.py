"""Energy band of examples/pendulum_chain.yaml (constrained Stormer-Verlet, cay, truncated
RKMK, C backend) against MuJoCo RK4 on the same chain (hpgen.bench.multibody), in one process.

    PYTHONPATH=. python benchmarks/pendulum_chain_energy.py [--n 2 4] [--steps 100000]
                                                          [--h 1e-3]

Start: the benchmark's (chain.initial_joint_state: hanging straight down, qvel ~ N(0, 1),
seed 0), converted to the example's SE3^N state (its frames sit at the pin when the chain
hangs straight: centre x_i + R_i (i + 1/2) b, b = (0, 0, -length); xi = (omega, v) in the
body frame). hpgen runs ``steps`` steps of h (simulated time T = steps h); MuJoCo RK4 runs
the same T (1) at dt = h and (2) at equal cost per simulated second: dt = h c_mj / c_hpgen
with c the measured time per step (MuJoCo's from a 2000-step probe of its C rollout, hpgen's
from its own run). Band: max_k |E_k - E_0| / (E_0 - V_rest), V_rest the potential energy of
the chain at rest (chain_peers.py's normalisation). Also: the joints' largest position and
velocity gaps over hpgen's recorded nodes (chain.constraint_residual), and hpgen.compile's
wall time (cold unless the build cache already holds the module: use a fresh --cache-dir
for cold figures).
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, mujoco_peer

MODEL = Path(__file__).resolve().parents[1] / "examples" / "pendulum_chain.yaml"


def to_hpgen(spec, s):
    """(g (4N x 4N), xi (6N,)) of a chain.ChainState in the example's frames."""
    n, b = spec.n, np.array([0.0, 0.0, -spec.length])
    g, xi = np.eye(4 * n), np.zeros(6 * n)
    for i in range(n):
        p = (i + 0.5) * b
        g[4 * i:4 * i + 3, 4 * i:4 * i + 3] = s.R[i]
        g[4 * i:4 * i + 3, 4 * i + 3] = s.x[i] - s.R[i] @ p
        xi[6 * i:6 * i + 3] = s.omega[i]
        xi[6 * i + 3:6 * i + 6] = s.R[i].T @ s.v[i] - np.cross(s.omega[i], p)
    return g, xi


def from_hpgen(spec, g, xi):
    n, b = spec.n, np.array([0.0, 0.0, -spec.length])
    R = np.array([g[4 * i:4 * i + 3, 4 * i:4 * i + 3] for i in range(n)])
    w = np.array([xi[6 * i:6 * i + 3] for i in range(n)])
    x = np.array([g[4 * i:4 * i + 3, 4 * i + 3] + R[i] @ ((i + 0.5) * b) for i in range(n)])
    v = np.array([R[i] @ (xi[6 * i + 3:6 * i + 6] + np.cross(w[i], (i + 0.5) * b))
                  for i in range(n)])
    return chain.ChainState(R, x, w, v)


def band(E, spec):
    return np.abs(E - E[0]).max() / (E[0] - chain.rest_potential(spec))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[2, 4])
    ap.add_argument("--steps", type=int, default=100_000)
    ap.add_argument("--h", type=float, default=1e-3)
    ap.add_argument("--cache-dir", default=None, help="hpgen's build cache (default its own)")
    args = ap.parse_args(argv)
    print("| N | runner | dt | steps | us/step | us per simulated ms | energy band | joints |")
    print("|---|---|---|---|---|---|---|---|")
    for n in args.n:
        spec = chain.ChainSpec(n)
        qpos, qvel = chain.initial_joint_state(spec)
        g0, xi0 = to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
        start = time.perf_counter()
        integ = hpgen.compile(MODEL, parameters={"N": n}, cache_dir=args.cache_dir)
        compile_s = time.perf_counter() - start
        start = time.perf_counter()
        tr = integ.simulate(g0=g0, xi0=xi0, h=args.h, steps=args.steps, every=10)
        c_hp = (time.perf_counter() - start) / args.steps
        E = np.array([sum(chain.energy(spec, from_hpgen(spec, g, xi)))
                      for g, xi in zip(tr.g, tr.xi())])
        gaps = np.max([chain.constraint_residual(spec, from_hpgen(spec, g, xi))
                       for g, xi in zip(tr.g, tr.xi())], axis=0)
        T = args.steps * args.h
        print(f"| {n} | hpgen SV (compile {compile_s:.1f} s) | {args.h:g} | {args.steps} | "
              f"{1e6 * c_hp:.2f} | {1e3 * c_hp / args.h:.1f} | {band(E, spec):.2e} | "
              f"{gaps[0]:.2e} / {gaps[1]:.2e} |")
        probe = mujoco_peer.run(spec, qpos, qvel, args.h, 2000, "RK4")
        c_mj = probe.seconds / 2000
        for label, dt in (("equal dt", args.h), ("equal cost", args.h * c_mj / c_hp)):
            steps = int(round(T / dt))
            dt = T / steps
            run = mujoco_peer.run(spec, qpos, qvel, dt, steps, "RK4",
                                  sample=max(10, steps // 10_000))
            c = run.seconds / steps
            print(f"| {n} | MuJoCo RK4 ({label}) | {dt:.3g} | {steps} | {1e6 * c:.2f} | "
                  f"{1e3 * c / dt:.1f} | {band(run.energy, spec):.2e}"
                  f"{'' if run.stable else ' (unstable)'} | - |")


if __name__ == "__main__":
    main()
