"""Per-step wall time of generated integrators, C and Python backends, and compile times.

    python benchmarks/step_times.py [--quick]

Heavy top (examples/heavy_top.yaml) for several (tableau, tau, rkmk), each with its default
Newton mode (simplified when the Jacobian costs > 4 residuals) and with full Newton; the free
rigid body's reduced Cayley step one run at a time and as a batched ensemble over threads;
medians of repeats, all in one process. Compile time is measured cold (empty cache, including
the C build) and cached (a second compile of the same input), each in a fresh subprocess as
a user runs it.
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

from hpgen.runtime import NewtonOptions

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "heavy_top.yaml"
CONFIGS = [("stormer-verlet", "cay", "truncated"), ("gauss2", "cay", "exact"),
           ("gauss2", "exp", "exact"), ("lobatto3a3", "exp", "exact")]


def per_step(integ, steps, repeats, **kw):
    from scipy.spatial.transform import Rotation
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        tr = integ.simulate(g0=g0, xi0=[0.2, 1.0, 3.0], h=0.05, steps=steps, every=steps, **kw)
        times.append((time.perf_counter() - t0) / steps)
    return statistics.median(times), tr.newton_iterations / steps, tr.jacobians / steps


def free_body(cache, quick):
    """Reduced Euler-Poincare Cayley step (examples/free_rigid_body.yaml), h = 0.1."""
    import hpgen
    integ = hpgen.compile(ROOT / "examples" / "free_rigid_body.yaml", cache_dir=cache)
    mu0 = [0.4535961214255773, 0.0, 0.8912073600614354]
    steps = 200_000 if quick else 2_000_000
    times = []
    for _ in range(3 if quick else 5):
        t0 = time.perf_counter()
        integ.simulate(g0=np.eye(3), mu0=mu0, h=0.1, steps=steps, every=steps)
        times.append(time.perf_counter() - t0)
    one = statistics.median(times) / steps
    B, bsteps = 256, (2_000 if quick else 20_000)
    rng = np.random.default_rng(0)
    mus = rng.normal(size=(B, 3))
    mus /= np.linalg.norm(mus, axis=1)[:, None]
    def per_body_step(run_batch):
        """(seconds per body-step on 1 and 2 threads, setup seconds): the per-body setup
        (Legendre inversion and Newton start in Python, result objects) is timed with 0
        steps; the stepping rate is the marginal cost beyond it (medians of 3)."""
        def seconds(nsteps, threads):
            times = []
            for _ in range(3):
                t0 = time.perf_counter()
                run_batch(np.eye(3), 0.1, nsteps, mu0=mus, every=max(nsteps, 1),
                          threads=threads)
                times.append(time.perf_counter() - t0)
            return statistics.median(times)
        setup = seconds(0, 1)
        return {t: (seconds(bsteps, t) - setup) / (B * bsteps) for t in (1, 2)}, setup

    res, setup = per_body_step(integ.simulate_batch)
    print(f"\nfree rigid body, reduced Cayley step (h = 0.1, {integ.nz} unknowns): "
          f"{one * 1e9:.0f} ns/step = {1 / one / 1e6:.2f} M steps/s; batched ensemble of {B} "
          f"bodies: {res[1] * 1e9:.0f} ns/body-step on 1 thread, {res[2] * 1e9:.0f} on 2 "
          f"(stepping, beyond a setup of {setup / B * 1e6:.0f} us/body)")
    # the same ensemble keeping only mu (scene record [mu]): the group is never formed
    text = (ROOT / "examples" / "free_rigid_body.yaml").read_text()
    path = Path(cache) / "free_body_mu.yaml"
    path.write_text("\n".join("  record: [mu]" if ln.strip().startswith("record:") else ln
                              for ln in text.splitlines()) + "\n")
    reduced = hpgen.compile(path, cache_dir=cache)
    assert reduced.engine.backend.skip_g

    # one body, interleaved, min of repeats: simulate (forms g_k) against record [mu]
    best = {"simulate": np.inf, "record": np.inf}
    for _ in range(3 if quick else 7):
        for name, run in (("simulate", reduced.simulate), ("record", reduced.record)):
            t0 = time.perf_counter()
            run(np.eye(3), 0.1, steps, mu0=mu0, every=steps)
            best[name] = min(best[name], time.perf_counter() - t0)

    res, _ = per_body_step(reduced.record_batch)
    print(f"  scene record [mu] (g never formed, update_p): {best['record'] / steps * 1e9:.0f} "
          f"ns/step against {best['simulate'] / steps * 1e9:.0f} forming g (same module, "
          f"interleaved, min of repeats); record_batch: {res[1] * 1e9:.0f} ns/body-step on 1 "
          f"thread, {res[2] * 1e9:.0f} on 2")


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
    print("| tableau | tau | rkmk | unknowns | Newton | C us/step | it/step | J/step "
          "| C full Newton us/step | it/step | Python us/step |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for tab, tau, rk in CONFIGS:
        opts = dict(tableau=tab, tau=tau, rkmk=rk, cache_dir=cache)
        c = hpgen.compile(MODEL, backend="c", **opts)
        py = hpgen.compile(MODEL, backend="python", **opts)
        n = 2000 if a.quick else 20000
        tc, it, jac = per_step(c, n, 3 if a.quick else 7)
        tf, itf, _ = per_step(c, n, 3 if a.quick else 7,
                              newton=NewtonOptions(simplified=False))
        tp, _, _ = per_step(py, 200 if a.quick else 1000, 3)
        mode = "simplified" if c.simplified_default else "full"
        print(f"| {tab} | {tau} | {rk} | {c.nz} | {mode} | {tc * 1e6:.2f} | {it:.2f} | {jac:.2f} "
              f"| {tf * 1e6:.2f} | {itf:.2f} | {tp * 1e6:.0f} |")
    free_body(cache, a.quick)
    cold = tempfile.mkdtemp(prefix="hpgen-bench-cold-")
    args = ["--tableau", "gauss2", "--tau", "exp", "--rkmk", "exact"]
    t_cold = compile_seconds(cold, args)
    t_hot = compile_seconds(cold, args)
    print(f"\nhpgen compile heavy_top (gauss2, exp, exact, C): cold {t_cold:.2f} s, cached {t_hot:.2f} s "
          "(wall, fresh process each, including interpreter start)")


if __name__ == "__main__":
    main()
