"""Scene records compiled into the C step loop (Integrator.record) against simulate + the
observables afterwards (Trajectory.energy / momentum / xi: one C call over the records), same
module, same run, same process.

    python benchmarks/records.py [--steps 1000000] [--repeats 5]

1. Free rigid body (examples/free_rigid_body.yaml: left-invariant, Stormer-Verlet, Cayley,
   q = 0, h = 0.1), record [mu, energy, {spin: xi[2]}], every step: no entry needs g, so the
   loop never forms g (kernel update_p) and keeps 5 doubles per record. Against:
   simulate(every=1) (g and mu per record) + energy() + xi().
2. Heavy top (Stormer-Verlet, Cayley, q = 0, h = 0.05), record [energy, momentum,
   {height: R[2,2]}] every step (the step needs g: g is formed, not kept).
Prints the min-of-repeats wall time per step and the bytes kept, and checks that the values
agree (mu bitwise: same states; the rest to round-off).
"""
from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def _model(tmp, example, record):
    text = (ROOT / "examples" / example).read_text()
    lines = [ln for ln in text.splitlines() if not ln.strip().startswith("record:")]
    text = "\n".join(lines).replace("  every:", f"  record: {record}\n  every:") + "\n"
    path = Path(tmp) / example.replace(".yaml", "_rec.yaml")
    path.write_text(text)
    return path


def _best(fn, repeats):
    best, out = np.inf, None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def _case(label, integ, sc, steps, repeats, observe):
    kw = dict(g0=sc.g0, h=sc.h, steps=steps, xi0=sc.xi0, mu0=sc.mu0, every=1)
    t_rec, rec = _best(lambda: integ.record(**kw), repeats)

    def full():
        tr = integ.simulate(**kw)
        return tr, {name: getattr(tr, name)() for name in observe}
    t_full, (tr, obs) = _best(full, repeats)
    kept_rec = rec.t.nbytes + sum(a.nbytes for a in rec.arrays.values())
    kept_full = tr.t.nbytes + tr.g.nbytes + tr.mu.nbytes + sum(a.nbytes for a in obs.values())
    print(f"{label}, {steps} steps, every step recorded "
          f"(skip g: {integ.engine.backend.skip_g}; row {rec.names}):")
    other = f"simulate + {'/'.join(observe)}:"
    print(f"  {'record in the C loop:':30s} {t_rec / steps * 1e9:7.1f} ns/step, "
          f"{kept_rec / 1e6:7.1f} MB kept")
    print(f"  {other:30s} {t_full / steps * 1e9:7.1f} ns/step, {kept_full / 1e6:7.1f} MB kept")
    print(f"  ratio {t_full / t_rec:.2f}x time, {kept_full / kept_rec:.1f}x memory")
    return rec, tr, obs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--steps", type=int, default=1_000_000)
    ap.add_argument("--repeats", type=int, default=5)
    a = ap.parse_args()
    import hpgen
    from hpgen.model import load_model
    sv = dict(tableau="stormer-verlet", tau="cay", rkmk="truncated")
    with tempfile.TemporaryDirectory() as tmp:
        path = _model(tmp, "free_rigid_body.yaml", '[mu, energy, {spin: "xi[2]"}]')
        integ = hpgen.compile(path, cache_dir=tmp, **sv)
        rec, tr, obs = _case("free rigid body", integ, load_model(path).scene, a.steps,
                             a.repeats, ("energy", "xi"))
        assert np.array_equal(rec["mu"], tr.mu)
        assert np.allclose(rec["energy"], obs["energy"], rtol=1e-15, atol=0)
        assert np.allclose(rec["spin"], obs["xi"][:, 2], rtol=0, atol=1e-15)
        path = _model(tmp, "heavy_top.yaml", '[energy, momentum, {height: "R[2,2]"}]')
        integ = hpgen.compile(path, cache_dir=tmp, **sv)
        rec, tr, obs = _case("heavy top", integ, load_model(path).scene, a.steps, a.repeats,
                             ("energy", "momentum"))
        assert np.array_equal(rec["height"], tr.g[:, 2, 2])
        assert np.allclose(rec["energy"], obs["energy"], rtol=1e-15, atol=0)
        assert np.allclose(rec["momentum"], obs["momentum"], rtol=0, atol=1e-14)
    print("values agree (mu / height bitwise, energy, xi, momentum to round-off)")


if __name__ == "__main__":
    main()
