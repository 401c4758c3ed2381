"""Cost of Integrator.linearize on composed steps (integrator.compose).

    PYTHONPATH=. python benchmarks/linearize_composed.py [--steps 1000] [--repeat 3]

Two composed models, C backend, one simulate of ``steps`` steps (every=1) and then
``linearize`` of the whole trajectory (best of ``repeat``):
- a heavy top with three body torques u (SO3, stormer-verlet / cay / truncated, compose suzuki4,
  h = 0.05, u_k = 0.1 sin(k h) e): (A, B) = linearize(traj, u=U);
- the pendulum chain N = 4 (examples/pendulum_chain.yaml, SE3^4 with ball joints,
  constrained SV, compose suzuki4, h = 0.01, the chain benchmark's start): A.
Peer in the same run: simulate of the same steps (one pass of the composed step). Prints
microseconds per step, linearize / simulate, and the Newton iterations per substep that
linearize spent (hpgen.runtime.linearize.along_with_status) against the run's. Read the ratios,
not the digits (2 shared cores).
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import hpgen  # noqa: E402
from hpgen.bench.multibody import chain, hpgen_chain  # noqa: E402

TOP = """\
name: driven_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0}
inputs: [u0, u1, u2]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2,2]
forces: ["u0", "u1", "u2"]
"""


def best(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--cache-dir", default=None)
    a = ap.parse_args(argv)
    K, rep = a.steps, a.repeat

    top_path = Path(a.cache_dir or "/tmp") / "driven_top.yaml"
    top_path.parent.mkdir(parents=True, exist_ok=True)
    top_path.write_text(TOP)
    top = hpgen.compile(top_path, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                        compose="suzuki4", cache_dir=a.cache_dir)
    h = 0.05
    U = 0.1 * np.sin(h * np.arange(K))[:, None] * np.array([1.0, -0.5, 0.3])
    g0, xi0 = np.eye(3), np.array([0.2, 1.0, 3.0])
    t_sim, traj = best(lambda: top.simulate(g0, h, K, xi0=xi0, u=U), rep)
    t_lin, (A, B) = best(lambda: top.linearize(traj, u=U), rep)
    st = _status(top, traj, u=U)
    stages = len(top.composition.gammas)
    print(f"composed heavy top with torques (suzuki4 x SV cay/truncated, nz = {top.nz}), {K} steps, "
          f"best of {rep}")
    print(f"  linearize (A {A.shape}, B {B.shape})  {1e6 * t_lin / K:9.1f} us/step   "
          f"simulate {1e6 * t_sim / K:8.1f} us/step   ratio {t_lin / t_sim:6.1f}"
          f"{_its(K, stages, traj, st)}")

    spec = chain.ChainSpec(4)
    ch = hpgen.compile(hpgen_chain.MODEL, parameters={"N": 4}, compose="suzuki4",
                       cache_dir=a.cache_dir)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
    h = 0.01
    t_sim, traj = best(lambda: ch.simulate(g0, h, K, xi0=xi0), rep)
    t_lin, A = best(lambda: ch.linearize(traj), rep)
    st = _status(ch, traj)
    print(f"composed pendulum chain N = 4 (suzuki4 x constrained SV, nz = {ch.nz}), {K} "
          f"steps, best of {rep}")
    print(f"  linearize (A {A.shape})        {1e6 * t_lin / K:9.1f} us/step   "
          f"simulate {1e6 * t_sim / K:8.1f} us/step   ratio {t_lin / t_sim:6.1f}"
          f"{_its(K, stages, traj, st)}")


def _status(integ, traj, **kw):
    """The status of linearize (None before hpgen.runtime.linearize reported it)."""
    from hpgen.runtime import linearize as lz
    if not hasattr(lz, "along_with_status"):
        return None
    return lz.along_with_status(integ.engine, traj, **kw)[1]


def _its(K, stages, traj, st):
    """Newton iterations per substep of linearize (when the runtime reports them) and of the
    run."""
    run = float(np.sum(traj.newton_iterations)) / (K * stages)
    if st is None:
        return f"   run {run:.2f} it/substep"
    return (f"   linearize {st['total_iterations'] / (K * stages):.2f} it/substep, run "
            f"{run:.2f}, deviation from the records {st['deviation']:.1e}")


if __name__ == "__main__":
    main()
