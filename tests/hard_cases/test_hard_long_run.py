"""Hard case 4: 10^7 steps of the free rigid body in C (stormer-verlet/cay/truncated, the
reduced Cayley step, h = 0.1, T = 10^6; HLW set-up Pi0 = (cos 1.1, 0, sin 1.1)), recording
every 10^4 steps (1001 samples).

The run happens in a fresh child process (cache hit: no compile stack imported) so that its
peak RSS (resource.getrusage ru_maxrss) is not masked by an earlier, higher peak of the test
session: the child warms up (one short simulate: library load, first-call allocations),
reads ru_maxrss, runs the 10^7 steps, reads it again.

Pass criteria:
- memory flat: max RSS growth during the 10^7-step run below 4 MiB. The records need
  1001 x 12 doubles = 96 kB; any per-step allocation would need >= 10^7 x 8 B = 80 MB (a
  single double per step). Sensitivity check in the same child: 2 x 10^6 steps recorded every
  step (the records alone are 192 MB) must raise the peak by more than 50 MiB -- the
  measure does see allocations of that kind (ru_maxrss only grows past the child's earlier
  peak, which the imports and warm-up set: 10^6 steps, 96 MB of records written straight
  into the result arrays, raised it by 49.9 MiB, too close to the bar);
- energy error bounded, no drift: every sample's |E_k - E_0| is within 1.01x of the
  energy-error envelope of a dense run (first 10^4 steps, every step; the orbit is periodic
  in Pi, period ~ 10, so 10^3 time units reach the envelope), and a linear fit's slope
  times T is below a quarter of that envelope (the fit over 1001 samples of an oscillation
  at scattered phases has a noise of ~0.1 envelope). (Round-off random walk over 10^7 steps is
  ~ sqrt(10^7) 1e-16 ~ 3e-13, negligible against the envelope ~ 3e-4.);
- spatial momentum R p constant to 1e-10 relative and |R^T R - I| < 1e-10 after 10^7
  steps (random walks of ~1e-16 per step: ~3e-13 expected);
- the run takes < 30 s (0.3 us per step expected, i.e. ~3 s).
"""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from conftest import FREE_BODY
from hardcase_util import FREE_INERTIA, envelope_drift

STEPS, EVERY, H = 10_000_000, 10_000, 0.1
PI0 = [float(np.cos(1.1)), 0.0, float(np.sin(1.1))]
OPTS = dict(tableau="stormer-verlet", tau="cay", rkmk="truncated")

CHILD = r"""
import json, resource, sys, time
import numpy as np
import hpgen
path, cache, steps, every, h, pi0 = sys.argv[1], sys.argv[2], int(sys.argv[3]), \
    int(sys.argv[4]), float(sys.argv[5]), json.loads(sys.argv[6])
integ = hpgen.compile(path, cache_dir=cache, tableau="stormer-verlet", tau="cay",
                      rkmk="truncated", backend="c")
integ.simulate(g0=np.eye(3), mu0=pi0, h=h, steps=20_000, every=10_000)   # warm-up
kb = lambda: resource.getrusage(resource.RUSAGE_SELF).ru_maxrss          # KiB on Linux
r0 = kb()
t0 = time.perf_counter()
tr = integ.simulate(g0=np.eye(3), mu0=pi0, h=h, steps=steps, every=every)
wall = time.perf_counter() - t0
r1 = kb()
m = tr.momentum()
out = {"maxrss_before_kib": r0, "maxrss_after_kib": r1, "wall_s": wall,
       "records": len(tr), "mu": tr.mu.tolist(), "t": tr.t.tolist(),
       "momentum_drift": float(np.abs(m - m[0]).max() / np.linalg.norm(m[0])),
       "defect": float(max(np.abs(g.T @ g - np.eye(3)).max() for g in tr.g)),
       "compile_stack_imported": any(k in sys.modules for k in ("casadi", "sympy"))}
del tr
r2 = kb()
integ.simulate(g0=np.eye(3), mu0=pi0, h=h, steps=2_000_000, every=1)    # sensitivity check
out["control_growth_kib"] = kb() - r2
print(json.dumps(out))
"""


@pytest.mark.slow
def test_ten_million_steps_flat_memory_bounded_energy(compile_model, model_file, cache_dir):
    """10^7 steps in a child process: max RSS growth < 4 MiB (control: > 50 MiB for 2 x 10^6
    recorded steps), energy within 1.01x of the dense envelope, no drift, < 30 s."""
    integ = compile_model(FREE_BODY, **OPTS)            # builds the cache entry and library
    dense = integ.simulate(g0=np.eye(3), mu0=PI0, h=H, steps=10_000, every=1)
    E_dense = 0.5 * np.sum(dense.mu**2 / FREE_INERTIA, axis=1)
    envelope = float(np.abs(E_dense - E_dense[0]).max())

    proc = subprocess.run([sys.executable, "-c", CHILD, str(model_file(FREE_BODY)),
                           str(cache_dir), str(STEPS), str(EVERY), str(H), json.dumps(PI0)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr[-3000:]
    res = json.loads(proc.stdout.strip().splitlines()[-1])
    mu, t = np.array(res["mu"]), np.array(res["t"])
    E = 0.5 * np.sum(mu**2 / FREE_INERTIA, axis=1)
    err = E - E[0]
    first, last, slope = envelope_drift(t, err)
    growth = res["maxrss_after_kib"] - res["maxrss_before_kib"]
    print(f"\n[long run] {STEPS} steps h={H} in {res['wall_s']:.2f} s "
          f"({res['wall_s'] / STEPS * 1e6:.3f} us/step), {res['records']} records; max RSS "
          f"{res['maxrss_before_kib']} -> {res['maxrss_after_kib']} KiB (growth {growth} KiB; "
          f"control: 2 x 10^6 steps recorded every step grew it by "
          f"{res['control_growth_kib'] / 1024:.1f} MiB); energy error: dense envelope "
          f"{envelope:.6e}, samples max {np.abs(err).max():.6e}, first tenth {first:.4e}, "
          f"last tenth {last:.4e}, slope*T {slope * t[-1]:+.2e}; spatial momentum drift "
          f"{res['momentum_drift']:.1e}, |R^T R - I| {res['defect']:.1e}")
    assert res["records"] == STEPS // EVERY + 1 and np.isfinite(mu).all()
    assert not res["compile_stack_imported"]
    assert growth < 4 * 1024
    assert res["control_growth_kib"] > 50 * 1024
    assert np.abs(err).max() <= 1.01 * envelope
    assert abs(slope) * t[-1] < 0.25 * envelope
    assert res["momentum_drift"] < 1e-10 and res["defect"] < 1e-10
    assert res["wall_s"] < 30.0
