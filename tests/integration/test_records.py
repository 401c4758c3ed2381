"""Scene records compiled into the step loop (kernel record, C hpgen_advance_record, the
Python mirror, Integrator.record / stream_record): the row holds exactly what ``record:``
asks for, user expressions included; the states are bitwise those of ``simulate``; with a
left-invariant l and no g requested, g is never formed; bad values stop the run with a
RecordError naming the entry."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.errors import RecordError

SV = dict(tableau="stormer-verlet", tau="cay", rkmk="truncated")


def _with_record(example, record):
    text = (EXAMPLES / example).read_text()
    lines = [ln for ln in text.splitlines() if not ln.strip().startswith("record:")]
    out = "\n".join(lines).replace("  every:", f"  record: {record}\n  every:")
    assert f"record: {record}" in out
    return out + "\n"


TOP = _with_record("heavy_top.yaml", '[energy, {height: "R[2,2]"}, '
                                     '{spin: "xi[2] - mu[0]/I[0]"}, momentum, g, mu]')
BODY = _with_record("free_rigid_body.yaml", '[mu, {spin: "xi[2]"}, energy]')
QUARTIC = """
name: quartic_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) + 0.05*xi[0]**4 - R[2,2]
scene:
  h: 0.05
  steps: 300
  initial: {g: {rotvec: [0.3, 0.2, 0.0]}, xi: [0.2, 1.0, 3.0]}
  record: [xi, energy, {p0: "mu[0]"}]
"""


def _run(integ, scene_src, steps, every, model):
    from hpgen.model import load_model_text
    sc = load_model_text(scene_src).scene
    kw = dict(g0=sc.g0, h=sc.h, steps=steps, xi0=sc.xi0, mu0=sc.mu0, every=every)
    return integ.record(**kw), integ.simulate(**kw), kw


@pytest.mark.parametrize("backend", ["c", "python"])
def test_heavy_top_rows_are_the_scene_list(compile_model, backend):
    integ = compile_model(TOP, backend=backend, **SV)
    assert integ.record_names == ("energy", "height", "spin", "momentum", "g", "mu")
    assert integ.meta["step_uses_g"] and integ.meta["record_uses_g"]
    rec, tr, _ = _run(integ, TOP, 300, 7, "top")
    assert len(rec) == len(tr) == 300 // 7 + 1 and np.array_equal(rec.t, tr.t)
    assert np.array_equal(rec["g"], tr.g) and np.array_equal(rec["mu"], tr.mu)   # bitwise
    xi = tr.xi()
    # the same formulas evaluated by NumPy on simulate's states: round-off (|mu| ~ 20)
    assert np.array_equal(rec["height"], tr.g[:, 2, 2])
    assert np.allclose(rec["spin"], xi[:, 2] - tr.mu[:, 0] / 1.0, rtol=0, atol=1e-14)
    assert np.allclose(rec["energy"], tr.energy(), rtol=1e-15, atol=0)
    assert np.allclose(rec["momentum"], tr.momentum(), rtol=0, atol=1e-14)


def test_c_and_python_rows_are_bitwise_equal(compile_model):
    rows = []
    for backend in ("c", "python"):
        integ = compile_model(TOP, backend=backend, **SV)
        rec, _, _ = _run(integ, TOP, 120, 5, "top")
        rows.append(rec)
    for name in rows[0].names:
        assert np.array_equal(rows[0][name], rows[1][name]), name


@pytest.mark.parametrize("backend", ["c", "python"])
def test_left_invariant_scene_without_g_never_forms_g(compile_model, backend):
    integ = compile_model(BODY, backend=backend, **SV)
    assert not integ.meta["step_uses_g"] and not integ.meta["record_uses_g"]
    assert integ.engine.backend.skip_g
    rec, tr, kw = _run(integ, BODY, 400, 3, "body")
    assert np.array_equal(rec["mu"], tr.mu)          # the momenta do not need g: bitwise
    assert np.allclose(rec["spin"], tr.xi()[:, 2], rtol=0, atol=1e-15)
    assert np.allclose(rec["energy"], tr.energy(), rtol=1e-15, atol=0)
    # the run's g was never advanced: the backend refuses to continue it with g
    b = integ.engine.backend
    gf = np.asarray(kw["g0"], dtype=float).ravel(order="F")
    run = b.start(gf, tr.mu[0], np.zeros(integ.nz) + 0.1)
    b.advance_record(run, kw["h"], 2, 1, integ.engine.options(None))
    with pytest.raises(ValueError, match="advance"):
        b.advance(run, kw["h"], 1, 1, integ.engine.options(None))


@pytest.mark.parametrize("chunk", [1, 7, 100])
def test_stream_record_chunks_equal_one_call(compile_model, chunk):
    integ = compile_model(TOP, backend="c", **SV)
    rec, _, kw = _run(integ, TOP, 101, 4, "top")
    parts = list(integ.stream_record(**kw, chunk=chunk))
    assert np.array_equal(np.concatenate([p.t for p in parts]), rec.t)
    for name in rec.names:
        assert np.array_equal(np.concatenate([p[name] for p in parts]), rec[name]), name


@pytest.mark.parametrize("backend", ["c", "python"])
def test_velocity_newton_for_a_quartic_lagrangian(compile_model, backend):
    integ = compile_model(QUARTIC, backend=backend, **SV)
    assert integ.meta["legendre_quadratic"] is False
    rec, tr, _ = _run(integ, QUARTIC, 300, 10, "quartic")
    # xi solves legendre(g, xi) = mu to round-off (|mu| ~ 20, a few ulp)
    for g, xi, mu in zip(tr.g, rec["xi"], tr.mu):
        assert np.abs(integ.legendre(g, xi) - mu).max() <= 1e-13
    assert np.allclose(rec["xi"], tr.xi(), rtol=0, atol=1e-13)
    assert np.allclose(rec["energy"], tr.energy(), rtol=1e-14, atol=0)
    assert np.array_equal(rec["p0"], tr.mu[:, 0])


@pytest.mark.parametrize("backend", ["c", "python"])
def test_a_non_finite_record_stops_the_run_and_names_the_entry(compile_model, backend):
    # log(mu[0] - 0.3): the free body's mu[0] starts at 0.45 and later falls below 0.3
    src = _with_record("free_rigid_body.yaml", '[mu, {lg: "log(mu[0] - 0.3)"}]')
    integ = compile_model(src, backend=backend, **SV)
    from hpgen.model import load_model_text
    sc = load_model_text(src).scene
    kw = dict(g0=sc.g0, h=sc.h, steps=1000, mu0=sc.mu0, every=2)
    tr = integ.simulate(**kw)
    first_bad = int(np.argmax(tr.mu[:, 0] - 0.3 < 0))
    assert first_bad > 0, "the test needs mu[0] to fall below 0.3"
    with pytest.raises(RecordError) as info:
        integ.record(**kw)
    err = info.value
    assert err.names == ("lg",) and "lg" in str(err)
    assert err.step == first_bad * 2
    part = err.partial
    assert part.partial and len(part) == first_bad + 1
    assert np.isfinite(part["lg"][:-1]).all() and not np.isfinite(part["lg"][-1])
    assert np.array_equal(part["mu"], tr.mu[:first_bad + 1])


def test_record_batch_is_bitwise_the_single_runs(compile_model):
    integ = compile_model(BODY, backend="c", **SV)
    rng = np.random.default_rng(3)
    mus = rng.normal(size=(7, 3))
    runs = integ.record_batch(np.eye(3), 0.1, 150, mu0=mus, every=4, threads=2)
    for mu0, rec in zip(mus, runs):
        one = integ.record(np.eye(3), 0.1, 150, mu0=mu0, every=4)
        assert not rec.partial and np.array_equal(rec.t, one.t)
        for name in one.names:
            assert np.array_equal(rec[name], one[name]), name


def test_a_row_without_xi_compiles_with_strict_warnings(compile_model, tmp_path):
    # no entry needs xi: the velocity Newton is left out of the C (no unused function)
    import subprocess
    src = _with_record("free_rigid_body.yaml", '[g, mu, defect, {c: "R[0,0] + mu[1]"}]')
    integ = compile_model(src, backend="c", **SV)
    assert not integ.meta["record_uses_xi"] and integ.meta["record_uses_g"]
    kernels_c = integ.engine.backend.library.parent / "kernels.c"
    from hpgen.runtime.build import include_flags
    proc = subprocess.run(["cc", "-std=c99", "-O1", "-Wall", "-Werror", "-fPIC", "-shared",
                           *include_flags(), "-o", str(tmp_path / "k.so"), str(kernels_c),
                           "-lm"],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[:2000]
    rec, tr, _ = _run(integ, src, 50, 5, "body")
    assert np.array_equal(rec["c"], tr.g[:, 0, 0] + tr.mu[:, 1])
    assert np.array_equal(rec["g"], tr.g)
