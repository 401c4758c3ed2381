"""How the step of the N-link pendulum chain (examples/pendulum_chain.yaml: SV / cay /
truncated, C backend, sparse J, default Newton) grows with N: us/step, Newton iterations and
Jacobian evaluations per step, and the time of the residual kernel alone.

    PYTHONPATH=. python benchmarks/chain_step_scaling.py [--n 8 16 32 64] [--steps 2000]
                                                         [--newton default|full|simplified]

Every N starts from the chain's joint-space initial state (hpgen.bench.multibody.chain:
joint velocities N(0, 1), seed fixed) with h = 1e-3; us/step is the best of three runs of
``steps`` steps (simulate, one recorded row), compile time included once in "compile s"
(a cached module compiles in well under a second). The last column is us/step over that of
the first N, the issue's "time(64) / time(8)". The machine's load moves the figures: run the
variants to compare in one session, interleaved.
"""
from __future__ import annotations

import argparse
import ctypes
import time

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime.newton import NewtonOptions


def kernel_us(integ, name, args, reps=300) -> float:
    """us per call of the exported C kernel hpgen_kernel_<name> (ctypes, best of 3)."""
    fn = getattr(integ.engine.backend.lib, f"hpgen_kernel_{name}")
    ins = [np.ascontiguousarray(a, dtype=np.float64) for a in args]
    outs = [np.zeros(int(np.prod(s))) for _, s in integ.meta["kernels"][name]["outputs"]]
    ptrs = [a.ctypes.data_as(ctypes.c_void_p) for a in ins + outs]
    best = np.inf
    for _ in range(3):
        t = time.perf_counter()
        for _ in range(reps):
            fn(*ptrs)
        best = min(best, (time.perf_counter() - t) / reps)
    return best * 1e6


def measure(n: int, steps: int, newton) -> dict:
    t = time.perf_counter()
    integ = hpgen.compile(hpgen_chain.MODEL, parameters={"N": n})
    compile_s = time.perf_counter() - t
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
    best, tr = np.inf, None
    for _ in range(3):
        t = time.perf_counter()
        tr = integ.simulate(g0, 1e-3, steps, xi0=xi0, every=steps, newton=newton)
        best = min(best, time.perf_counter() - t)
    gap = max(chain.constraint_residual(spec, s)[0]
              for s in hpgen_chain.from_hpgen(spec, tr.g, tr.xi()))
    nz = integ.meta["nz"]
    args = (np.zeros(nz), np.asarray(tr.g[-1]).ravel(order="F"), np.asarray(tr.mu[-1]),
            np.array([1e-3]))
    return {"N": n, "nz": nz, "compile_s": compile_s, "us": best / steps * 1e6,
            "it": tr.newton_iterations / steps, "jac": tr.jacobians / steps,
            "residual_us": kernel_us(integ, "residual", args), "gap": gap}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--newton", choices=["default", "full", "simplified"], default="default")
    a = ap.parse_args()
    newton = None if a.newton == "default" else NewtonOptions(simplified=a.newton == "simplified")
    print(f"hpgen from {hpgen.__file__}; Newton: {a.newton}")
    print("| N | nz | compile s | us/step | it/step | J/step | residual us | joint gap | "
          "us/step / first |")
    print("|---|---|---|---|---|---|---|---|---|")
    first = None
    for n in a.n:
        r = measure(n, a.steps, newton)
        first = first or r
        print(f"| {n} | {r['nz']} | {r['compile_s']:.1f} | {r['us']:.1f} | {r['it']:.2f} | "
              f"{r['jac']:.2f} | {r['residual_us']:.1f} | {r['gap']:.1e} | "
              f"{r['us'] / first['us']:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
