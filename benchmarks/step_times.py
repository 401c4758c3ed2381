"""Per-step wall time of generated integrators, C and Python backends, and compile times.

    python benchmarks/step_times.py [--quick]

Heavy top (examples/heavy_top.yaml) for several (tableau, tau, rkmk); medians of repeats,
all in one process. Compile time is measured cold (empty cache, including the C build) and
cached (a second compile of the same input), each in a fresh subprocess as a user runs it.
"""
from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "heavy_top.yaml"
CONFIGS = [("stormer-verlet", "cay", "truncated"), ("gauss2", "cay", "exact"),
           ("gauss2", "exp", "exact"), ("lobatto3a3", "exp", "exact")]


def per_step(integ, steps, repeats):
    from scipy.spatial.transform import Rotation
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        tr = integ.simulate(g0=g0, xi0=[0.2, 1.0, 3.0], h=0.05, steps=steps, every=steps)
        times.append((time.perf_counter() - t0) / steps)
    return statistics.median(times), tr.newton_iterations / steps


def compile_seconds(cache: str, args: list[str]) -> float:
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "hpgen", "compile", str(MODEL), "-o", cache + "/out",
                    "--cache-dir", cache, *args], check=True, capture_output=True)
    return time.perf_counter() - t0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    a = ap.parse_args()
    import hpgen
    cache = tempfile.mkdtemp(prefix="hpgen-bench-")
    print("| tableau | tau | rkmk | unknowns | C us/step | Python us/step | Python / C | Newton it/step |")
    print("|---|---|---|---|---|---|---|---|")
    for tab, tau, rk in CONFIGS:
        opts = dict(tableau=tab, tau=tau, rkmk=rk, cache_dir=cache)
        c = hpgen.compile(MODEL, backend="c", **opts)
        py = hpgen.compile(MODEL, backend="python", **opts)
        tc, it = per_step(c, 2000 if a.quick else 20000, 3 if a.quick else 7)
        tp, _ = per_step(py, 10 if a.quick else 50, 3)
        print(f"| {tab} | {tau} | {rk} | {c.nz} | {tc * 1e6:.2f} | {tp * 1e6:.0f} | {tp / tc:.0f} | {it:.2f} |")
    cold = tempfile.mkdtemp(prefix="hpgen-bench-cold-")
    args = ["--tableau", "gauss2", "--tau", "exp", "--rkmk", "exact"]
    t_cold = compile_seconds(cold, args)
    t_hot = compile_seconds(cold, args)
    print(f"\nhpgen compile heavy_top (gauss2, exp, exact, C): cold {t_cold:.2f} s, cached {t_hot:.2f} s "
          "(wall, fresh process each, including interpreter start)")


if __name__ == "__main__":
    main()
