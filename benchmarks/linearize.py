"""Cost of Integrator.linearize on the heavy top.

    python benchmarks/linearize.py [--steps 10000] [--repeat 5]

examples/heavy_top.yaml (SO3, gauss2, exp, exact: nz = 9, d = 3) from its scene's initial
state and h. One simulate of ``steps`` steps (every=1), then ``linearize`` of the whole
trajectory, C backend (best of ``repeat``), against two peers timed in the same run:
- simulate of the same steps (C): what one pass of the step costs;
- central differences of ``step`` (2 x 2d perturbed solves per step, warm-started, C
  Newton through Integrator.step), on the first steps only (``--fd-steps``).
The Python backend's linearize is timed on ``--py-steps`` steps. Prints microseconds per step
and the ratios; no figure is asserted here.
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
from hpgen.model import load_model  # noqa: E402

MODEL = ROOT / "examples" / "heavy_top.yaml"


def best(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def fd_linearize(integ, traj, steps):
    """Central differences of step (the peer linearize replaces), eps = 1e-5: per step one
    Newton start (guess kernel at the record's velocity), then 2 x 2d warm-started steps."""
    d, hv = integ.d, np.array([traj.h])
    K = [np.array([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]]) for e in np.eye(3)]
    for k in range(steps):
        g, p = traj.g[k], traj.mu[k]
        z = integ.kernel("guess", integ.velocity(g, p), g.ravel(order="F"), p, hv)[0]
        for i in range(2 * d):
            for s in (1e-5, -1e-5):
                if i < d:   # g exp(s e_i^) by Rodrigues (|s| small)
                    gp, pp = g @ (np.eye(3) + np.sin(s) * K[i] + (1 - np.cos(s)) * K[i] @ K[i]), p
                else:
                    gp, pp = g, p + s * np.eye(d)[i - d]
                integ.step(gp, pp, traj.h, z=z)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=10_000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--fd-steps", type=int, default=200)
    ap.add_argument("--py-steps", type=int, default=500)
    a = ap.parse_args(argv)
    sc = load_model(MODEL).scene
    ic = hpgen.compile(MODEL, backend="c")
    ip = hpgen.compile(MODEL, backend="python")
    g0, K = np.array(sc.g0), a.steps
    t_sim, traj = best(lambda: ic.simulate(g0, sc.h, K, xi0=sc.xi0, mu0=sc.mu0), a.repeat)
    t_lin, A = best(lambda: ic.linearize(traj), a.repeat)
    short = ic.simulate(g0, sc.h, a.py_steps, xi0=sc.xi0, mu0=sc.mu0)
    t_py, _ = best(lambda: ip.linearize(short), 1)
    t_fd, _ = best(lambda: fd_linearize(ic, traj, a.fd_steps), 1)
    us = lambda t, n: 1e6 * t / n  # noqa: E731
    print(f"heavy top gauss2 exp exact (nz = {ic.nz}), h = {sc.h}, {K} steps, best of "
          f"{a.repeat}")
    print(f"  linearize, C            {us(t_lin, K):8.2f} us/step   A {A.shape}")
    print(f"  simulate, C (peer)      {us(t_sim, K):8.2f} us/step   linearize / simulate = "
          f"{t_lin / t_sim:.2f}")
    print(f"  central differences, C  {us(t_fd, a.fd_steps):8.2f} us/step   ({a.fd_steps} "
          f"steps; / linearize = {us(t_fd, a.fd_steps) / us(t_lin, K):.0f})")
    print(f"  linearize, Python       {us(t_py, a.py_steps):8.2f} us/step   ({a.py_steps} "
          f"steps; / C = {us(t_py, a.py_steps) / us(t_lin, K):.0f})")


if __name__ == "__main__":
    main()
