"""How the step of the N-link pendulum chain (examples/pendulum_chain.yaml: SV / cay /
truncated, C backend, sparse J) grows with N, for Newton variants run interleaved in one
process: ``chord``, the default (a chord iteration within the step: J once a step, again only
on a poor rate; stops on its rate's error bound); ``confirm``, the chord that confirms its
stop with one more correction (-DHPGEN_CHORD_RATE_STOP=0, the stop before the rate bound);
``every``, J at every iterate (-DHPGEN_SPARSE_CHORD=0); ``simplified``, simplified Newton (J
kept across steps, NewtonOptions(simplified=True)); ``simplified-k2`` / ``-k4`` with a kept J
dropped after a step of more than 2 / 4 iterates (-DHPGEN_KEPT_J_ITERATES, default 3);
``simplified-old`` without the refresh rules (-DHPGEN_SIMPLIFIED_REFRESH=0,
docs/numerics.md sec. 8).

    PYTHONPATH=. python benchmarks/chain_step_scaling.py [--n 8 16 32 64] [--steps 2000]
        [--rounds 3] [--frames pin] [--h 1e-3 ...] [--scheme sv] [--variants chord simplified]

``--frames centre``: examples/capsule_chain.yaml (link frames at the centres); ``--h``: one
table per step size; ``--scheme``: ``sv`` or a composition (suzuki4, yoshida4, ...), whose
it/step and J/step count a composed step's substeps; ``--variants``: which to run (default
the first four; the first is the ratios' base).

Every N starts from the chain's joint-space initial state (hpgen.bench.multibody.chain:
joint velocities N(0, 1), seed fixed) with h = 1e-3 (``--h``); us/step is the best over ``rounds``
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
from hpgen.errors import ConvergenceError
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime.newton import NewtonOptions

VARIANTS = {"chord": (None, None), "confirm": (["-DHPGEN_CHORD_RATE_STOP=0"], None),
            "every": (["-DHPGEN_SPARSE_CHORD=0"], None),
            "simplified": (None, NewtonOptions(simplified=True)),
            "simplified-k2": (["-DHPGEN_KEPT_J_ITERATES=2"], NewtonOptions(simplified=True)),
            "simplified-k4": (["-DHPGEN_KEPT_J_ITERATES=4"], NewtonOptions(simplified=True)),
            "simplified-old": (["-DHPGEN_SIMPLIFIED_REFRESH=0"],
                               NewtonOptions(simplified=True))}


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


def measure(n: int, steps: int, rounds: int, frames: str = "pin", h: float = 1e-3,
            scheme: str = "sv", variants=tuple(VARIANTS)) -> dict:
    extra = {} if scheme == "sv" else {"compose": scheme}
    integs = {k: hpgen.compile(hpgen_chain.MODELS[frames], parameters={"N": n},
                               cflags=VARIANTS[k][0], **extra) for k in variants}
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), frames)
    best = {k: np.inf for k in variants}
    runs = {}
    failed = {}
    for _ in range(rounds):
        for k in variants:
            if k in failed:
                continue
            t = time.process_time()
            try:
                runs[k] = integs[k].simulate(g0, h, steps, xi0=xi0, every=steps,
                                             newton=VARIANTS[k][1])
            except ConvergenceError as exc:
                failed[k] = str(exc).split(";")[0]
                continue
            best[k] = min(best[k], time.process_time() - t)
    integ = integs[variants[0]]
    out = {"N": n, "nz": integ.meta["nz"], "failed": failed}
    for k in variants:
        r = runs.get(k)
        out[k] = ((np.nan,) * 3 if k in failed else
                  (best[k] / steps * 1e6, r.newton_iterations / steps, r.jacobians / steps))
    tr = runs.get(variants[0])
    if failed:
        return out
    gap = max(chain.constraint_residual(spec, s)[0]
              for s in hpgen_chain.from_hpgen(spec, tr.g, tr.xi(), frames))
    args = (np.zeros(out["nz"]), np.asarray(tr.g[-1]).ravel(order="F"),
            np.asarray(tr.mu[-1]), np.array([h]))
    out.update(residual_us=kernel_us(integ, "residual", args), gap=gap)
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--frames", choices=sorted(hpgen_chain.MODELS), default="pin")
    ap.add_argument("--h", type=float, nargs="+", default=[1e-3])
    ap.add_argument("--scheme", default="sv", help="sv or a composition (hpgen list)")
    ap.add_argument("--variants", nargs="+", choices=list(VARIANTS),
                    default=["chord", "confirm", "every", "simplified"])
    a = ap.parse_args()
    variants = tuple(a.variants)
    print(f"hpgen from {hpgen.__file__}; {a.frames} frames, {a.scheme}")
    base = variants[0]
    cols = " | ".join(f"{k} us | it/step | J/step" for k in variants)
    ratios = " | ".join(f"{k} / {base}" for k in variants[1:])
    for h in a.h:
        print(f"\nh = {h:g}\n\n| N | nz | {cols} | residual us | joint gap | {ratios} | "
              f"{base} / first |")
        print("|---|---|" + "---|" * (3 * len(variants) + len(variants) + 2))
        first = None
        for n in a.n:
            r = measure(n, a.steps, a.rounds, a.frames, h, a.scheme, variants)
            cells = " | ".join(f"{r[k][0]:.1f} | {r[k][1]:.2f} | {r[k][2]:.2f}"
                               for k in variants)
            if r["failed"]:
                print(f"| {n} | {r['nz']} | {cells} | failed: "
                      + "; ".join(f"{k}: {e}" for k, e in r["failed"].items()) + " |",
                      flush=True)
                continue
            first = first or r
            rat = " | ".join(f"{r[k][0] / r[base][0]:.2f}" for k in variants[1:])
            print(f"| {n} | {r['nz']} | {cells} | {r['residual_us']:.1f} | {r['gap']:.1e} | "
                  f"{rat} | {r[base][0] / first[base][0]:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
