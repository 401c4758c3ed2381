"""The Newton linear algebra of the N-link pendulum chain (examples/pendulum_chain.yaml):
the dense LU against the sparse one (compile option jacobian="dense" / "sparse": the LU with
a static pivot order, the QR where a pivot fails; hpgen.codegen.sparse), C backend,
one process, for N = 2, 3, 4 (and more with --n, compiles permitting).

    PYTHONPATH=. python benchmarks/chain_linear_algebra.py [--n 2 3 4] [--steps 2000]
                                                          [--repeats 5] [--json out.json]

For every N and storage, the scene's start (the chain swung as one rigid body) and h, and
both Newton variants (full: J at every iterate; simplified: J^{-1} or the QR kept across
iterations and steps):
- us/step: the best of ``repeats`` runs of ``steps`` steps (simulate, every = steps), the
  dense and the sparse module's runs interleaved;
- it/step, J/step: Newton iterations and Jacobian evaluations (factorizations) per step;
- kernels us/step: it/step residual evaluations' worth of kernel time, J/step of them the
  residual_jacobian kernel instead of the residual, each kernel timed alone through the
  module's exported C symbol (ctypes, preallocated buffers) minus the call overhead of the
  trivial margin kernel;
  the rest of the step (linear algebra, predictor, update) is us/step minus that. The
  exported residual_jacobian of a sparse module writes J dense (its contract), so its time
  is an upper bound of what the step's own sparse call costs;
- the factorization's flops: dense 2/3 nz^3 (LU) and, for simplified Newton, 4/3 nz^3 more for
  J^{-1}; sparse those of the static LU (hpgen.codegen.static_lu.flops).
The ratio sparse/dense of each N is measured in the same process (the same machine load).
"""
from __future__ import annotations

import argparse
import ctypes
import json
import time
from pathlib import Path

import numpy as np

import hpgen
from hpgen.api import read_model_text
from hpgen.model import load_model_text
from hpgen.model.overrides import apply_overrides
from hpgen.runtime.newton import NewtonOptions

MODEL = str(Path(__file__).resolve().parent.parent / "examples" / "pendulum_chain.yaml")


def scene(n: int):
    text = apply_overrides(read_model_text(MODEL), {"N": n}, file=MODEL)
    return load_model_text(text, filename=MODEL).scene


def kernel_time(integ, name, args, reps=2000) -> float:
    """Seconds per call of the exported C kernel hpgen_kernel_<name> through ctypes on
    preallocated buffers (best of 3)."""
    lib = integ.engine.backend.lib
    fn = getattr(lib, f"hpgen_kernel_{name}")
    fn.restype = ctypes.c_int
    ins = [np.ascontiguousarray(a, dtype=np.float64) for a in args]
    outs = [np.zeros(int(np.prod(s))) for _, s in integ.meta["kernels"][name]["outputs"]]
    ptrs = [a.ctypes.data_as(ctypes.c_void_p) for a in ins + outs]
    best = np.inf
    for _ in range(3):
        t = time.perf_counter()
        for _ in range(reps):
            fn(*ptrs)
        best = min(best, (time.perf_counter() - t) / reps)
    return best


def lu_flops(integ) -> int:
    """Flops of one factorization by the sparse module's static LU (its compile-time analysis,
    hpgen.codegen.static_lu; the QR takes over only where a static pivot fails)."""
    from hpgen.codegen.static_lu import flops, static_lu  # the compile side: benchmark only
    jac = integ.meta["jacobian"]
    return flops(static_lu(integ.meta["nz"], jac["colind"], jac["row"]))


def prepare(n: int, storage: str) -> dict:
    """Compile (timed), the kernel times and the factorization's flops of one storage."""
    sc = scene(n)
    t = time.perf_counter()
    integ = hpgen.compile(MODEL, parameters={"N": n}, jacobian=storage)
    compile_s = time.perf_counter() - t
    nz = integ.meta["nz"]
    tr = integ.simulate(sc.g0, sc.h, 1, xi0=sc.xi0)
    gf, pk = np.asarray(tr.g[-1]).ravel(order="F"), np.asarray(tr.mu[-1])
    zk = np.zeros(nz)
    args = (zk, gf, pk, np.array([sc.h]))
    over = kernel_time(integ, "margin", (zk, np.array([sc.h])))
    return {"integ": integ, "scene": sc, "N": n, "storage": storage, "nz": nz,
            "compile_s": round(compile_s, 1),
            "residual_us": (kernel_time(integ, "residual", args) - over) * 1e6,
            "residual_jacobian_us": (kernel_time(integ, "residual_jacobian", args, reps=300)
                                     - over) * 1e6,
            "flops": (2 * nz ** 3 // 3) if storage == "dense" else lu_flops(integ)}


def measure(pair: list, steps: int, repeats: int) -> None:
    """us/step (best of ``repeats``, the storages' runs interleaved so that both see the same
    load), iterations and Jacobians per step and the split, into each entry of ``pair``."""
    for variant, simplified in (("full", False), ("simplified", True)):
        opts = NewtonOptions(simplified=simplified)
        best, runs = [np.inf] * len(pair), [None] * len(pair)
        for _ in range(repeats):
            for i, r in enumerate(pair):
                sc = r["scene"]
                t = time.perf_counter()
                runs[i] = r["integ"].simulate(sc.g0, sc.h, steps, xi0=sc.xi0, every=steps,
                                              newton=opts)
                best[i] = min(best[i], time.perf_counter() - t)
        for r, b, run in zip(pair, best, runs):
            it, jac = run.newton_iterations / steps, run.jacobians / steps
            step_us = b / steps * 1e6
            kern_us = jac * r["residual_jacobian_us"] + (it - jac) * r["residual_us"]
            r[variant] = {"us_step": step_us, "it_step": it, "J_step": jac,
                          "kernels_us": kern_us, "rest_us": step_us - kern_us,
                          "g_end": np.asarray(run.g[-1]).tolist()}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[2, 3, 4])
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--json", type=str, default=None)
    a = ap.parse_args()
    rows = []
    print("| N | nz | storage | flops/factor | full us/step | it/step | kernels us | rest us "
          "| simplified us/step | it/step | J/step | kernels us | rest us | compile s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in a.n:
        pair = [prepare(n, s) for s in ("dense", "sparse")]
        measure(pair, a.steps, a.repeats)
        for r in pair:
            f, s = r["full"], r["simplified"]
            print(f"| {n} | {r['nz']} | {r['storage']} | {r['flops']} | {f['us_step']:.1f} | "
                  f"{f['it_step']:.2f} | {f['kernels_us']:.1f} | {f['rest_us']:.1f} | "
                  f"{s['us_step']:.1f} | {s['it_step']:.2f} | {s['J_step']:.2f} | "
                  f"{s['kernels_us']:.1f} | {s['rest_us']:.1f} | {r['compile_s']} |", flush=True)
        dev = max(np.abs(np.array(pair[0][v]["g_end"]) - np.array(pair[1][v]["g_end"])).max()
                  for v in ("full", "simplified"))
        print(f"|   | sparse/dense: full {pair[1]['full']['us_step'] / pair[0]['full']['us_step']:.2f},"
              f" simplified {pair[1]['simplified']['us_step'] / pair[0]['simplified']['us_step']:.2f};"
              f" max |g_dense - g_sparse| at the end {dev:.1e} |", flush=True)
        rows += [{k: v for k, v in r.items() if k not in ("integ", "scene")} for r in pair]
    if a.json:
        Path(a.json).write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
