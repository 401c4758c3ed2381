"""Ensembles with and without the lane-wise kernels (hpgen.codegen.lanes): ns per body-step.

    python benchmarks/ensemble_lanes.py [--quick] [--bodies 256 1024] [--heavy-top] [--native]
                                        [--simplified] [--composed] [--chain2] [--cpu]

The free rigid body (examples/free_rigid_body.yaml, its default scheme: Stormer-Verlet,
Cayley, reduced step, 3 unknowns, full Newton) as ``simulate_batch`` of B bodies on 1 and 2
threads, lanes on and off, interleaved in one process; the stepping cost is the marginal
one beyond the per-body setup (the same call with 0 steps), minimum over repeats on both
sides. With --heavy-top also the heavy top's Gauss 2 ensemble (9 unknowns, 3883 step
instructions: no lane code is emitted, so both columns run the scalar kernels; printed as
the control). --native
builds with -march=native (opt-in; the default is the portable -O3 build). --simplified: the
free body with simplified Newton (each lane keeps its own J^{-1}); --composed: its step
composed (suzuki4, 5 substeps); --chain2: two bodies coupled by a spring (6 unknowns: the
kernels lane-wise, the LU lane by lane), full and simplified Newton. --cpu: process CPU time (all
threads summed) instead of wall time, for a loaded machine.
"""
from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


#: the clock of ``seconds`` (--cpu: time.process_time)
CLOCK = [time.perf_counter]


def seconds(integ, g0, h, steps, threads, lanes, init, newton=None):
    """Time of one simulate_batch of `steps` steps (recorded once, at the end)."""
    t0 = CLOCK[0]()
    integ.simulate_batch(g0, h, steps, every=max(steps, 1), threads=threads, lanes=lanes,
                         newton=newton, **init)
    return CLOCK[0]() - t0


def run(integ, label, g0, h, init_of, bodies, steps, repeats, newton=None):
    """Per B: the interleaved repeats (lanes on / off, 1 / 2 threads, `steps` and 0 steps
    alternate); ns per body-step = (min time of `steps` steps - min time of 0 steps) /
    (B steps): the stepping beyond the per-body setup, the same statistic on both sides."""
    print(f"\n{label} (lanes: {integ.engine.backend.lanes or 'none'} bodies per call)")
    print("| bodies | threads | lanes on ns/body-step | lanes off | on / off |")
    print("|---|---|---|---|---|")
    for B in bodies:
        init = init_of(B)
        best = {}
        for _ in range(repeats):
            for threads in (1, 2):
                for lanes in (True, False):
                    for n in (steps, 0):
                        key = (threads, lanes, n)
                        best[key] = min(best.get(key, np.inf),
                                        seconds(integ, g0, h, n, threads, lanes, init,
                                                newton))
        for threads in (1, 2):
            on, off = ((best[(threads, lanes, steps)] - best[(threads, lanes, 0)])
                       / (B * steps) for lanes in (True, False))
            print(f"| {B} | {threads} | {on * 1e9:.1f} | {off * 1e9:.1f} | {on / off:.2f} |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--bodies", type=int, nargs="+", default=[256, 1024])
    ap.add_argument("--heavy-top", action="store_true")
    ap.add_argument("--native", action="store_true")
    ap.add_argument("--simplified", action="store_true")
    ap.add_argument("--composed", action="store_true")
    ap.add_argument("--chain2", action="store_true")
    ap.add_argument("--cpu", action="store_true")
    a = ap.parse_args()
    if a.cpu:
        CLOCK[0] = time.process_time
    cflags = ("-march=native",) if a.native else None
    import hpgen
    from hpgen.runtime import NewtonOptions
    cache = tempfile.mkdtemp(prefix="hpgen-lanes-")
    steps, repeats = (2000, 3) if a.quick else (10000, 5)
    rng = np.random.default_rng(0)

    def momenta(B):
        mus = rng.normal(size=(B, 3))
        return {"mu0": mus / np.linalg.norm(mus, axis=1)[:, None]}

    body = hpgen.compile(ROOT / "examples" / "free_rigid_body.yaml", cache_dir=cache,
                         cflags=cflags)
    run(body, "free rigid body, reduced Cayley step, h = 0.1" + " (-march=native)" * a.native,
        np.eye(3), 0.1, momenta,
        a.bodies, steps, repeats)
    if a.simplified:
        run(body, "free rigid body, simplified Newton, h = 0.1", np.eye(3), 0.1, momenta,
            a.bodies, steps, repeats, NewtonOptions(simplified=True))
    if a.composed:
        comp = hpgen.compile(ROOT / "examples" / "free_rigid_body.yaml", compose="suzuki4",
                             cache_dir=cache, cflags=cflags)
        run(comp, "free rigid body, composed suzuki4 (5 substeps), h = 0.1", np.eye(3), 0.1,
            momenta, a.bodies, max(steps // 5, 200), repeats)
    if a.chain2:
        from hpgen.model import load_model
        path = ROOT / "examples" / "double_body_chain.yaml"
        sc = load_model(str(path)).scene
        chain = hpgen.compile(path, cache_dir=cache, cflags=cflags)
        for simplified in (False, True):
            run(chain, f"double body chain (6 unknowns), h = {sc.h}, simplified Newton: "
                f"{simplified}", sc.g0, sc.h,
                lambda B: {"xi0": np.asarray(sc.xi0) * (1 + 0.01 * rng.normal(size=(B, 6)))},
                a.bodies[:1], max(steps // 5, 200), repeats, NewtonOptions(simplified=simplified))
    if a.heavy_top:
        from scipy.spatial.transform import Rotation
        top = hpgen.compile(ROOT / "examples" / "heavy_top.yaml", tableau="gauss2", tau="cay",
                            rkmk="exact", cache_dir=cache, cflags=cflags)
        assert not top.engine.backend.lanes

        def velocities(B):
            return {"xi0": np.array([0.2, 1.0, 3.0]) + 0.01 * rng.normal(size=(B, 3))}

        run(top, "heavy top, Gauss 2 cay exact, h = 0.05", Rotation.from_rotvec(
            [0.3, 0.2, 0.0]).as_matrix(), 0.05, velocities, a.bodies[:1],
            max(steps // 5, 200), repeats)


if __name__ == "__main__":
    main()
