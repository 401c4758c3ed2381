"""The first step of a run with simplified Newton against full Newton, in one process: Newton
iterations, Jacobian evaluations and time of the first step on shipped scenes (their own g0,
initial velocity or momentum and h; simplified Newton asked for).

    PYTHONPATH=. python benchmarks/first_step.py [--quick]

A run's first step starts from the guess kernel. With ``simplified=True`` it takes
simplified Newton (one fresh J kept for the iterates, the later steps' stop test; full
Newton from the same start where that fails); with ``simplified=False`` it is full Newton,
which was every run's first step before. The time is per body of the C backend's batch
call (CBackend.simulate_batch: B runs from the scene's state and the first step's start,
made once) with 1 step, less the same call with 0 steps, 1 thread, the scalar loop (least of
the repeats, in process CPU time: the machine may be loaded): the first step's margin check,
Newton, margin and update. Closed models only.
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
#: (label, example, compile options)
SCENES = [("heavy top, Gauss 3 cay exact", "heavy_top.yaml",
           {"tableau": "gauss3", "tau": "cay", "rkmk": "exact"}),
          ("heavy top, default scheme", "heavy_top.yaml", {}),
          ("free body, Gauss 2 exp exact", "free_rigid_body.yaml",
           {"tableau": "gauss2", "tau": "exp", "rkmk": "exact"}),
          ("chain, default scheme", "chain.yaml", {}),
          ("pendulum chain, default scheme", "pendulum_chain.yaml", {})]


def _least(f, reps):
    best = np.inf
    for _ in range(reps):
        t0 = time.process_time()
        f()
        best = min(best, time.process_time() - t0)
    return best


def main():
    import hpgen
    from hpgen.model import load_model
    from hpgen.runtime import NewtonOptions
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    reps, B = (5, 64) if args.quick else (25, 512)
    print("| scene | first step | iterations | Jacobians | us | full / simplified time |")
    print("|---|---|---|---|---|---|")
    for label, name, opts in SCENES:
        path = ROOT / "examples" / name
        scene = load_model(str(path)).scene
        integ = hpgen.compile(path, **opts)
        x0 = {"xi0": scene.xi0} if scene.xi0 is not None else {"mu0": scene.mu0}
        g0 = np.asarray(scene.g0, dtype=np.float64)
        mu = (integ.legendre(g0, scene.xi0) if scene.xi0 is not None
              else np.asarray(scene.mu0, dtype=np.float64))
        xi = integ.velocity(g0, mu)
        gf = g0.ravel(order="F")
        eng, cb = integ.engine, integ.engine.backend
        row = {}
        for simplified in (False, True):
            newton = NewtonOptions(simplified=simplified)

            opts = eng.options(newton)
            z0 = eng.first_step.closed_start(gf, mu, xi, scene.h, opts)

            def batch(n, opts=opts, z0=z0):
                return cb.simulate_batch([gf] * B, [mu] * B, scene.h, [z0] * B, n, 1, opts, 1,
                                         None, None, lanes=False)
            tr = integ.simulate(scene.g0, scene.h, 1, newton=newton, **x0)
            t = (_least(lambda: batch(1), reps) - _least(lambda: batch(0), reps)) / B
            row[simplified] = (tr.newton_iterations, tr.jacobians, t * 1e6, tr.error)
        for simplified in (False, True):
            it, jac, us, err = row[simplified]
            ratio = f"{row[False][2] / row[True][2]:.2f}" if simplified else ""
            note = "" if err is None else f" ({err})"
            print(f"| {label} | {'simplified' if simplified else 'full'}{note} | {it} | {jac} "
                  f"| {us:.1f} | {ratio} |")


if __name__ == "__main__":
    main()
