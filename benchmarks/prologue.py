"""simulate's fixed Python cost (the prologue), fast path against the generic path, in one
process.

    python benchmarks/prologue.py [--quick]

Heavy top (examples/heavy_top.yaml), C backend, gauss2/cay/exact and gauss3/cay/exact.
"new" is ``Integrator.simulate`` (the fast path, hpgen.runtime.prologue), "old" is
``hpgen.runtime.states.simulate``, the generic path (the run engine's loop). Per case: steps = 0
(the fixed cost per call) and the T = 10 run of 130 steps (every = steps, as the
work-precision timing), from xi0 and from mu0; "same" repeats one start (a repeated call),
"new" takes a different start at every call (a sweep of initial conditions near the scene's:
the mu0 velocity is not kept). Old, new and the peer alternate in blocks of N calls; each
figure is the min over the repeats of the mean per call. The peer is the C stepping alone
(``hpgen_advance`` of 130 steps from the scene's start on a prepared run), so what the fast
path adds is also given in C steps. Last, an open module (spacecraft_slew: forces, runtime
parameters), steps = 0, old against new.
"""
from __future__ import annotations

import argparse
import ctypes
import time
from pathlib import Path

import numpy as np

from hpgen.runtime.engine import RunArgs
from hpgen.runtime.states import simulate as generic_simulate

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "heavy_top.yaml"
T, STEPS = 10.0, 130


def rotation(w):
    t = np.linalg.norm(w)
    K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]) / t
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


def interleaved(fns, calls, repeats):
    """{name: min over repeats of the mean seconds per call}, the functions alternating."""
    best = {name: float("inf") for name in fns}
    for _ in range(repeats):
        for name, f in fns.items():
            t0 = time.perf_counter()
            for k in range(calls):
                f(k)
            best[name] = min(best[name], (time.perf_counter() - t0) / calls)
    return best


def c_steps(integ, g0, xi0, h, steps):
    """f(k): hpgen_advance of ``steps`` steps on a run started once (the peer)."""
    b = integ.engine.backend
    tr = integ.simulate(g0, h, 0, xi0=xi0)
    z0 = b.call("guess", np.asarray(xi0, dtype=float), tr.g[0].ravel(order="F"), tr.mu[0],
                np.array([h]))[0]
    gf, mu0 = tr.g[0].ravel(order="F"), tr.mu[0]
    run = b.start(gf, mu0, z0)
    from hpgen.runtime.cstructs import _Options, _Status
    opts = _Options.of(integ.engine.options(None))
    g_rec, p_rec, st = np.zeros((1, 9)), np.zeros((1, 3)), _Status()

    def f(k):
        b._init_run(run, gf, mu0, z0)
        b._lib.hpgen_advance(run, h, steps, steps, ctypes.byref(opts), g_rec.ctypes.data,
                             p_rec.ctypes.data, ctypes.byref(st))
    return f


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    ap.add_argument("--cache-dir", default=None)
    args = ap.parse_args()
    import hpgen
    calls, repeats = (200, 5) if args.quick else (1000, 15)
    g0 = rotation(np.array([0.3, 0.2, 0.0]))
    xi0 = [0.2, 1.0, 3.0]
    rng = np.random.default_rng(0)
    # new starts near the scene's (a sweep of initial conditions; similar stepping costs)
    starts = [(rotation(np.array([0.3, 0.2, 0.0]) + 0.05 * rng.normal(size=3)),
               np.array(xi0) + 0.05 * rng.normal(size=3)) for _ in range(64)]
    h = T / STEPS
    print(f"heavy top, C backend; us per call (min over {repeats} x {calls} calls, old and "
          "new interleaved)")
    print("| scheme | start | steps | starts | old us | new us | old/new | C stepping us "
          "| new beyond C stepping, in C steps |")
    print("|---|---|---|---|---|---|---|---|---|")
    for tab in ("gauss2", "gauss3"):
        integ = hpgen.build(MODEL, tableau=tab, tau="cay", rkmk="exact", backend="c",
                            cache_dir=args.cache_dir).load()
        mus = [integ.legendre(g, x) for g, x in starts]
        mu_same = integ.legendre(g0, xi0)
        c_run = c_steps(integ, g0, xi0, h, STEPS)
        for which in ("xi0", "mu0"):
            for steps in (0, STEPS):
                every = max(steps, 1)
                for label in ("same", "new"):
                    if label == "same":
                        kw = [{which: xi0 if which == "xi0" else mu_same, "g0": g0}]
                    else:
                        kw = [{which: (x if which == "xi0" else m), "g0": g}
                              for (g, x), m in zip(starts, mus)]
                    n = len(kw)

                    def new(k, kw=kw, n=n, steps=steps, every=every):
                        integ.simulate(h=h, steps=steps, every=every, **kw[k % n])

                    def old(k, kw=kw, n=n, steps=steps, every=every):
                        a = kw[k % n]
                        generic_simulate(integ.engine, RunArgs(a["g0"], h, steps, a.get("xi0"),
                                                               a.get("mu0"), every))
                    r = interleaved({"c": c_run, "old": old, "new": new}, calls, repeats)
                    peer = r["c"]
                    per_step = peer / STEPS
                    # beyond the C stepping, in C steps (not for new starts of 130 steps:
                    # their stepping differs from the peer's start)
                    fixed = "-" if steps and label == "new" else \
                        f"{(r['new'] - (peer if steps else 0.0)) / per_step:.1f}"
                    print(f"| {tab}/cay/exact | {which} | {steps} | {label} | "
                          f"{r['old'] * 1e6:.1f} | {r['new'] * 1e6:.1f} | "
                          f"{r['old'] / r['new']:.2f} | {peer * 1e6:.1f} | {fixed} |")
    # an open module (forces, runtime parameters): spacecraft_slew's scene, steps = 0
    integ = hpgen.build(ROOT / "examples" / "spacecraft_slew.yaml", backend="c",
                        cache_dir=args.cache_dir).load()
    g0, xi0 = np.eye(3), [0.1, -0.2, 0.3]
    for params in (None, {"kp": 2.0}):
        r = interleaved({
            "old": lambda k, p=params: generic_simulate(
                integ.engine, RunArgs(g0, 0.05, 0, xi0, None, 1, None, None, p, 0.0)),
            "new": lambda k, p=params: integ.simulate(g0, 0.05, 0, xi0=xi0, params=p)},
            calls, repeats)
        print(f"spacecraft_slew (open), steps = 0, params={params}: old {r['old'] * 1e6:.1f} "
              f"us, new {r['new'] * 1e6:.1f} us, old/new {r['old'] / r['new']:.2f}")


if __name__ == "__main__":
    main()
