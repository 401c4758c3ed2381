"""Python backend: time per step with and without the fused Newton iterates (kernels.py
ITERATE and ITERATE_FULL, hpgen.codegen.pyiterate), interleaved in one process.

    python benchmarks/archive/python_step.py [--quick]

Heavy top (examples/heavy_top.yaml, h = 0.05), default Newton mode. For each configuration
one Python-backend module is loaded twice: as shipped ("fused") and with ITERATE and
ITERATE_FULL unset ("unfused": the kernels and LINEAR's functions called per iterate, the
path before them). Short runs alternate between the two (order reversed every repeat),
minimum over 41 repeats, the same statistic on both sides; the
C backend's time per step is printed beside as the peer. Both Python variants compute
bitwise the same run (tests/unit/test_pyiterate.py).
"""
from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "examples" / "heavy_top.yaml"
#: (tableau, tau, rkmk, steps per timed run): short runs, many repeats (a shared machine's
#: quiet moments decide the minimum)
CONFIGS = [("gauss2", "cay", "exact", 100), ("gauss2", "exp", "exact", 100),
           ("stormer-verlet", "cay", "truncated", 1000), ("lobatto3a3", "exp", "exact", 40)]


def best_per_step(integ, steps, g0):
    t0 = time.perf_counter()
    integ.simulate(g0=g0, xi0=[0.2, 1.0, 3.0], h=0.05, steps=steps, every=steps)
    return (time.perf_counter() - t0) / steps


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    import hpgen
    from scipy.spatial.transform import Rotation
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    cache = tempfile.mkdtemp(prefix="hpgen-pystep-")
    repeats = 7 if a.quick else 41
    print("| tableau | tau | rkmk | unknowns | Python fused us/step | unfused us/step | ratio "
          "| C us/step |")
    print("|---|---|---|---|---|---|---|---|")
    for tab, tau, rk, steps in CONFIGS:
        opts = dict(tableau=tab, tau=tau, rkmk=rk, cache_dir=cache)
        fused = hpgen.compile(MODEL, backend="python", **opts)
        unfused = hpgen.compile(MODEL, backend="python", **opts)
        unfused.engine.backend._newton.iterate = unfused.engine.backend._newton.iterate_full = None
        c = hpgen.compile(MODEL, backend="c", **opts)
        best = {"fused": float("inf"), "unfused": float("inf"), "c": float("inf")}
        runs = [("fused", fused, steps), ("unfused", unfused, steps), ("c", c, 100 * steps)]
        for r in range(repeats):
            for name, integ, n in (runs if r % 2 else runs[::-1]):     # alternating order
                best[name] = min(best[name], best_per_step(integ, n, g0))
        print(f"| {tab} | {tau} | {rk} | {fused.nz} | {best['fused'] * 1e6:.1f} "
              f"| {best['unfused'] * 1e6:.1f} | {best['fused'] / best['unfused']:.3f} "
              f"| {best['c'] * 1e6:.2f} |")


if __name__ == "__main__":
    main()
