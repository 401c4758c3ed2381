"""Cold compile time and step time of examples/rod.yaml against N (C backend, the model's
Stormer-Verlet): the rod's bending and twisting energy is a joint potential derived once per
joint (hpgen.derive.family_potentials), so both should grow slowly (compile) and linearly
(step) with N.

    PYTHONPATH=. python benchmarks/rod_scaling.py --n 8 16 32 64 [--steps 2000 --rounds 2]

Compile: wall s, cold (a new cache directory); step: CPU us per step, best of the rounds.
Start: the scene's straight rod tilted by 0.6 rad about x, segments end to end, each
twisting at 4 rad/s about its axis (consistent with the joints), h = 5e-4.
"""
from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

ROD = Path(__file__).resolve().parent.parent / "examples" / "rod.yaml"


def start(n: int):
    from scipy.spatial.transform import Rotation
    R, c = Rotation.from_rotvec([0.6, 0.0, 0.0]).as_matrix(), np.array([0.0, 0.0, -0.05])
    g = np.zeros((4 * n, 4 * n))
    for i in range(n):
        g[4 * i:4 * i + 3, 4 * i:4 * i + 3] = R
        g[4 * i:4 * i + 3, 4 * i + 3] = (2 * i + 1) * (R @ c)
        g[4 * i + 3, 4 * i + 3] = 1.0
    return g, np.tile([0.0, 0.0, 4.0, 0.0, 0.0, 0.0], n)


def main() -> None:
    import hpgen
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--rounds", type=int, default=2)
    a = ap.parse_args()
    print("N  compile_s  us_per_step  it_per_step  us_per_step_per_segment")
    for n in a.n:
        with tempfile.TemporaryDirectory() as cache:
            t0 = time.perf_counter()
            integ = hpgen.compile(ROD, backend="c", cache_dir=cache, parameters={"N": n})
            tc = time.perf_counter() - t0
            g, xi = start(n)
            best, its = np.inf, float("nan")
            for _ in range(a.rounds):     # CPU time of this process (the loop is serial)
                t0 = time.process_time()
                traj = integ.simulate(g, 5e-4, a.steps, xi0=xi, every=a.steps)
                best = min(best, time.process_time() - t0)
                its = traj.newton_iterations / a.steps
            us = 1e6 * best / a.steps
            print(f"{n:<3d} {tc:9.1f}  {us:11.1f}  {its:11.2f}  {us / n:8.2f}", flush=True)


if __name__ == "__main__":
    main()
