"""Poincare sections in the C step loop against recording every step and finding the
crossings afterwards (NumPy), same module, same run, same process.

    python benchmarks/sections.py [--steps 1000000]

Underwater vehicle (examples/underwater_vehicle.yaml: SE3, left-invariant, reduced step)
with the section P3 = mu[5] = 0 (upward), tableau stormer-verlet, tau cay, q = 0, h = 0.05,
from the example's initial state. Prints wall time and the bytes of records kept for
``Integrator.sections`` and for ``simulate(every=1)`` + crossing detection, and checks that
the crossings agree (t and mu bitwise: same states, same formulas).
"""
from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=1_000_000)
    a = ap.parse_args()
    import hpgen
    from hpgen.model import load_model
    text = (ROOT / "examples" / "underwater_vehicle.yaml").read_text()
    sc = load_model(ROOT / "examples" / "underwater_vehicle.yaml").scene
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "uv_section.yaml"
        path.write_text(text.rstrip("\n") + "\n  section: mu[5]\n")
        integ = hpgen.compile(path, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                              cache_dir=tmp)
        kw = dict(g0=sc.g0, h=0.05, steps=a.steps, xi0=sc.xi0, mu0=sc.mu0)
        t0 = time.perf_counter()
        cr = integ.sections(**kw)
        t_sec = time.perf_counter() - t0
        t0 = time.perf_counter()
        tr = integ.simulate(every=1, **kw)
        s = tr.mu[:, 5]
        k = np.flatnonzero((s[:-1] < 0.0) & (s[1:] >= 0.0))
        theta = s[k] / (s[k] - s[k + 1])
        t_post = (k + theta) * kw["h"]
        t_full = time.perf_counter() - t0
    assert np.array_equal(cr.step, k) and np.array_equal(cr.t, t_post)
    kept_sec = cr.t.nbytes + cr.g.nbytes + cr.mu.nbytes + cr.step.nbytes
    kept_full = tr.t.nbytes + tr.g.nbytes + tr.mu.nbytes
    print(f"underwater vehicle, {a.steps} steps, {len(cr)} crossings of P3 = 0:")
    print(f"  sections in the C loop:          {t_sec:.3f} s, {kept_sec / 1e6:.3f} MB kept")
    print(f"  simulate(every=1) + NumPy:       {t_full:.3f} s, {kept_full / 1e6:.1f} MB kept")
    print(f"  ratio {t_full / t_sec:.2f}x time, {kept_full / kept_sec:.0f}x memory; crossings "
          "identical (t, step)")


if __name__ == "__main__":
    main()
