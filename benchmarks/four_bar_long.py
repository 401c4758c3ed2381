"""examples/four_bar.yaml (constrained Stormer-Verlet, C backend) over a long run: the hinges
at every node, the energy band and its drift, the time per step.

    PYTHONPATH=. python benchmarks/four_bar_long.py [--steps 1000000] [--h 0.002]
                                                   [--chunk 100000] [--cache-dir DIR]

Start: the example's scene (crank at 0.7 rad turning at 6 rad/s, closed by initial.project).
Every node is checked (the run is streamed in chunks): the largest gap of the four hinges
(positions) and of their velocity form (xi = M^-1 p, l quadratic), and the energy of every
node. Band: max_k |E_k - E_0| / |E_0|; drift: the slope of a linear fit of E_k - E_0 times
the duration T, and the band of the first and of the last tenth of the run (equal bands and
a drift below them: no secular growth). Time per step: the wall time of the stream's chunks
(the C loop and the chunk's arrays; the checks above excluded) / steps.
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

import hpgen
from hpgen.model import load_model

MODEL = Path(__file__).resolve().parents[1] / "examples" / "four_bar.yaml"
ENDS = {"a0": (-0.5, 0.0), "b0": (0.5, 0.0), "a1": (-1.25, 0.0), "b1": (1.25, 0.0),
        "a2": (-1.0, 0.0), "b2": (1.0, 0.0)}
GROUND = np.array([2.5, 0.0])


def hinge_gaps(G, P, mass):
    """(max position gap, max velocity gap) of the four hinges over the nodes (G, P)."""
    xi = P / mass

    def point(k, e):
        R, x = G[:, 3 * k:3 * k + 2, 3 * k:3 * k + 2], G[:, 3 * k:3 * k + 2, 3 * k + 2]
        w, v = xi[:, 3 * k], xi[:, 3 * k + 1:3 * k + 3]
        e = np.array(ENDS[e])
        return x + R @ e, np.einsum("kij,kj->ki", R, v + w[:, None] * np.array([-e[1], e[0]]))

    zero = (0.0, 0.0)
    pairs = [(point(0, "a0"), (0.0, zero)), (point(1, "a1"), point(0, "b0")),
             (point(2, "a2"), (GROUND, zero)), (point(2, "b2"), point(1, "b1"))]
    pos = max(np.abs(p[0] - np.asarray(q[0])).max() for p, q in pairs)
    vel = max(np.abs(p[1] - np.asarray(q[1])).max() for p, q in pairs)
    return float(pos), float(vel)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=1_000_000)
    ap.add_argument("--h", type=float, default=0.002)
    ap.add_argument("--chunk", type=int, default=100_000)
    ap.add_argument("--cache-dir", default=None)
    args = ap.parse_args(argv)
    model = load_model(MODEL)
    sc = model.scene
    params = dict(model.parameters)
    mass = np.array([[params["I"][k], params["m"][k], params["m"][k]] for k in range(3)]).ravel()
    start = time.perf_counter()
    integ = hpgen.compile(MODEL, cache_dir=args.cache_dir)
    compile_s = time.perf_counter() - start
    pos = vel = wall = 0.0
    energies, times = [], []
    stream = integ.stream(np.array(sc.g0), args.h, args.steps, xi0=np.array(sc.xi0),
                          chunk=args.chunk)
    while True:
        start = time.perf_counter()
        part = next(stream, None)
        wall += time.perf_counter() - start
        if part is None:
            break
        p, v = hinge_gaps(part.g, part.mu, mass)
        pos, vel = max(pos, p), max(vel, v)
        energies.append(part.energy())
        times.append(part.t)
    E, t = np.concatenate(energies), np.concatenate(times)
    err = E - E[0]
    tenth = len(err) // 10
    slope = np.polyfit(t, err, 1)[0]
    print(f"four-bar, {args.steps} steps of h = {args.h} (T = {args.steps * args.h:g}), "
          f"C backend; compile {compile_s:.1f} s")
    print(f"  hinges at every node: position gap <= {pos:.2e}, velocity gap <= {vel:.2e}")
    print(f"  energy E0 = {E[0]:.6g}: band max|E - E0|/|E0| = {np.abs(err).max() / abs(E[0]):.3e}"
          f"; first tenth {np.abs(err[:tenth]).max() / abs(E[0]):.3e}, last tenth "
          f"{np.abs(err[-tenth:]).max() / abs(E[0]):.3e}; drift slope*T / |E0| = "
          f"{slope * t[-1] / abs(E[0]):.2e}")
    print(f"  {wall:.1f} s, {wall / args.steps * 1e6:.2f} us/step")


if __name__ == "__main__":
    main()
