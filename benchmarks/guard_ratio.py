"""The guard on an accepted step (hpgen_runs.c, hpgen_guard_ratio; docs/numerics.md sec. 8):
the largest guard ratio |(z - G) - d_0| / (max(|d_0 - d_1|, |d_0 - 2 d_1 + d_2|) + GUARD_FLOOR
(1 + |z|)) over the steps
of runs, and the steps the guard solved again, from a measurement build (-DHPGEN_GUARD_LOG=1,
bitwise the same states as the default build); the threshold abi.GUARD_RATIO is set with a
wide margin above the normal runs' largest ratio.

Runs: the capsule chain (examples/capsule_chain.yaml, link frames at the centres, random
start chain.initial_joint_state) with constrained SV, suzuki4, kahan-li6 and Gauss 2, and
the heavy top's scene (SV, Gauss 3) and the driven pendulum's (Gauss 2, 30000 steps: the
fingerprint's stroboscopic run). The kahan-li6 run at h = 1e-2 (N = 10, T = 100) is the
one that took a wrong root at t = 97.58 without the guard; ``--ratio 1e300`` builds with the
guard off (-DHPGEN_GUARD_RATIO=1e300) to see it. Per run: the ratio, the re-solves, the
energy band max |E - E0| / |E0| over the recorded nodes and the joints' largest gaps.

    PYTHONPATH=. python benchmarks/guard_ratio.py [--only kahan-li6] [--ratio 1e300]
"""
from __future__ import annotations

import argparse
import ctypes
import time
from pathlib import Path

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.model import load_model

ROOT = Path(__file__).resolve().parent.parent
#: (label, N, compile options, h, T)
CHAIN_RUNS = [
    ("sv", 10, {}, 1e-3, 20.0), ("sv", 10, {}, 2e-3, 20.0),
    ("suzuki4", 10, {"compose": "suzuki4"}, 5e-3, 20.0),
    ("gauss2", 10, {"tableau": "gauss2", "tau": "cay", "rkmk": "exact"}, 1e-2, 50.0),
    ("sv", 32, {}, 1e-3, 10.0), ("sv", 32, {}, 2e-3, 10.0),
    ("kahan-li6", 10, {"compose": "kahan-li6"}, 1e-2, 100.0),
]
#: (label, example, compile options, steps) at the scene's start and h
SCENE_RUNS = [
    ("heavy_top sv", "heavy_top.yaml",
     {"tableau": "stormer-verlet", "tau": "cay", "rkmk": "exact"}, 100_000),
    ("heavy_top gauss3", "heavy_top.yaml",
     {"tableau": "gauss3", "tau": "cay", "rkmk": "exact"}, 100_000),
    ("driven_pendulum", "driven_pendulum.yaml", {}, 30_000),
]


def guard_log(integ):
    """(largest ratio, re-solves) of the module's library since the last call."""
    lib = ctypes.CDLL(str(integ.engine.backend.library))
    lib.hpgen_guard_log.restype = ctypes.c_double
    n = ctypes.c_longlong()
    q = lib.hpgen_guard_log(ctypes.byref(n))
    return q, n.value


def chain_run(label, n, opts, h, T, cflags):
    integ = hpgen.compile(str(ROOT / "examples" / "capsule_chain.yaml"), parameters={"N": n},
                          cflags=cflags, **opts)
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), "centre")
    t = time.perf_counter()
    try:
        r = hpgen_chain.run(integ, spec, g0, xi0, h, int(round(T / h)), every=10,
                            frames="centre")
        E = r.energy
        out = (f"band {np.abs(E - E[0]).max() / abs(E[0]):.2e}  joints "
               f"{r.gaps[0]:.1e} / {r.gaps[1]:.1e}  {r.iterations / r.steps:.2f} it/step, "
               f"the result's guarded {r.guarded}")
    except hpgen.HpgenError as e:
        out = f"failed: {str(e).splitlines()[0][:90]}"
    q, m = guard_log(integ)
    print(f"{label:10s} N={n:2d} h={h:g} T={T:g}: max ratio {q:6.3g}, re-solved {m}; {out} "
          f"({time.perf_counter() - t:.0f} s)", flush=True)


def scene_run(label, example, opts, steps, cflags):
    path = str(ROOT / "examples" / example)
    scene = load_model(path).scene
    integ = hpgen.compile(path, cflags=cflags, **opts)
    x0 = {"xi0": scene.xi0} if scene.xi0 is not None else {"mu0": scene.mu0}
    tr = integ.simulate(scene.g0, scene.h, steps, every=100, **x0)
    q, m = guard_log(integ)
    E = tr.energy() if callable(tr.energy) else tr.energy
    print(f"{label:16s} h={scene.h:.3g} {steps} steps: max ratio {q:6.3g}, re-solved {m}; "
          f"band {np.abs(E - E[0]).max() / abs(E[0]):.2e}", flush=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", help="the runs whose label is this")
    ap.add_argument("--ratio", type=float, help="build with this HPGEN_GUARD_RATIO")
    a = ap.parse_args(argv)
    cflags = ["-DHPGEN_GUARD_LOG=1"] + ([f"-DHPGEN_GUARD_RATIO={a.ratio!r}"] if a.ratio else [])
    for label, n, opts, h, T in CHAIN_RUNS:
        if a.only in (None, label):
            chain_run(label, n, opts, h, T, cflags)
    for label, example, opts, steps in SCENE_RUNS:
        if a.only in (None, label):
            scene_run(label, example, opts, steps, cflags)


if __name__ == "__main__":
    main()
