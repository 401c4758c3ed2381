"""How the step of the N-link pendulum chain (examples/pendulum_chain.yaml: SV / cay /
truncated, C backend, sparse J) grows with N, for four Newton variants run interleaved in
one process: the default (a chord iteration within the step: J once a step, again only on a
poor rate; stops on its rate's error bound), the chord that confirms its stop with one more
correction (-DHPGEN_CHORD_RATE_STOP=0, the stop before the rate bound), J at every iterate
(-DHPGEN_SPARSE_CHORD=0) and simplified Newton (J kept across steps,
NewtonOptions(simplified=True)).

    PYTHONPATH=. python benchmarks/chain_step_scaling.py [--n 8 16 32 64] [--steps 2000]
                                                         [--rounds 3]

Every N starts from the chain's joint-space initial state (hpgen.bench.multibody.chain:
joint velocities N(0, 1), seed fixed) with h = 1e-3; us/step is the best over ``rounds``
rounds of ``steps`` steps (simulate, one recorded row) on the process's CPU clock, the
variants alternating within each round; it/step and J/step are Newton iterations and
Jacobian evaluations per step; "residual us" is the residual kernel alone. The last columns
are the variants' times over the default's, and the default's over its time at the first N
(the issue's "time(64) / time(8)"). The machine's load moves the figures: read the ratios.
"""
from __future__ import annotations

import argparse
import ctypes
import time

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime.newton import NewtonOptions

VARIANTS = {"chord": (None, None), "confirm": (["-DHPGEN_CHORD_RATE_STOP=0"], None),
            "every": (["-DHPGEN_SPARSE_CHORD=0"], None),
            "simplified": (None, NewtonOptions(simplified=True))}


def kernel_us(integ, name, args, reps=300) -> float:
    """us per call of the exported C kernel hpgen_kernel_<name> (ctypes, best of 3)."""
    fn = getattr(integ.engine.backend.lib, f"hpgen_kernel_{name}")
    ins = [np.ascontiguousarray(a, dtype=np.float64) for a in args]
    outs = [np.zeros(int(np.prod(s))) for _, s in integ.meta["kernels"][name]["outputs"]]
    ptrs = [a.ctypes.data_as(ctypes.c_void_p) for a in ins + outs]
    best = np.inf
    for _ in range(3):
        t = time.process_time()
        for _ in range(reps):
            fn(*ptrs)
        best = min(best, (time.process_time() - t) / reps)
    return best * 1e6


def measure(n: int, steps: int, rounds: int) -> dict:
    integs = {k: hpgen.compile(hpgen_chain.MODEL, parameters={"N": n}, cflags=f)
              for k, (f, _) in VARIANTS.items()}
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
    best = {k: np.inf for k in VARIANTS}
    runs = {}
    for _ in range(rounds):
        for k, (_, newton) in VARIANTS.items():
            t = time.process_time()
            runs[k] = integs[k].simulate(g0, 1e-3, steps, xi0=xi0, every=steps, newton=newton)
            best[k] = min(best[k], time.process_time() - t)
    tr, integ = runs["chord"], integs["chord"]
    if any(r.error is not None for r in runs.values()):
        raise SystemExit(f"N = {n}: " + "; ".join(f"{k}: {r.error}" for k, r in runs.items()))
    gap = max(chain.constraint_residual(spec, s)[0]
              for s in hpgen_chain.from_hpgen(spec, tr.g, tr.xi()))
    nz = integ.meta["nz"]
    args = (np.zeros(nz), np.asarray(tr.g[-1]).ravel(order="F"), np.asarray(tr.mu[-1]),
            np.array([1e-3]))
    out = {"N": n, "nz": nz, "residual_us": kernel_us(integ, "residual", args), "gap": gap}
    for k, r in runs.items():
        out[k] = (best[k] / steps * 1e6, r.newton_iterations / steps, r.jacobians / steps)
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args()
    print(f"hpgen from {hpgen.__file__}")
    cols = " | ".join(f"{k} us | it/step | J/step" for k in VARIANTS)
    print(f"| N | nz | {cols} | residual us | joint gap | confirm / chord | every / chord | "
          "simplified / chord | chord / first |")
    print("|---|---|" + "---|" * (3 * len(VARIANTS) + 6))
    first = None
    for n in a.n:
        r = measure(n, a.steps, a.rounds)
        first = first or r
        cells = " | ".join(f"{r[k][0]:.1f} | {r[k][1]:.2f} | {r[k][2]:.2f}" for k in VARIANTS)
        print(f"| {n} | {r['nz']} | {cells} | {r['residual_us']:.1f} | {r['gap']:.1e} | "
              f"{r['confirm'][0] / r['chord'][0]:.2f} | {r['every'][0] / r['chord'][0]:.2f} | {r['simplified'][0] / r['chord'][0]:.2f} | "
              f"{r['chord'][0] / first['chord'][0]:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
