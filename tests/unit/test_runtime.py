"""hpgen.runtime on the toy free rigid body module (tests/unit/_toy_step.py)."""
from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hpgen
from hpgen.abi import META_FORMAT
from hpgen.runtime import newton
from hpgen.errors import ArgumentError, BuildError, ConvergenceError, DomainError, ModelError
from hpgen.runtime import build_library, load

from _toy_step import emitted, integrator, module_dir, write_module

G0 = np.eye(3)
XI0 = np.array([0.3, 1.0, -0.4])
REPO = Path(hpgen.__file__).resolve().parents[1]


def _rotation(v):
    """exp of hat(v) (Rodrigues): a point on SO(3)."""
    t = np.linalg.norm(v)
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]) / t
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


def _fresh_copy(tmp_path, variant="plain") -> Path:
    return write_module(emitted(variant)[1], tmp_path)


def test_backends_agree_over_1000_steps():
    g0 = _rotation(np.array([0.3, 0.2, 0.0]))
    a = integrator("c").simulate(g0, 0.1, 1000, xi0=XI0)
    b = integrator("python").simulate(g0, 0.1, 1000, xi0=XI0)
    assert a.g.shape == (1001, 3, 3) and a.mu.shape == (1001, 3) and not a.partial
    np.testing.assert_allclose(a.g, b.g, rtol=0, atol=1e-12)
    np.testing.assert_allclose(a.mu, b.mu, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(a.t, b.t)
    assert a.newton_iterations > 1000


def test_conservation_over_10000_steps_c():
    tr = integrator("c").simulate(G0, 0.1, 10_000, xi0=XI0)
    m = tr.momentum()
    assert np.max(np.abs(m - m[0])) <= 1e-13 * np.linalg.norm(m[0])
    gtg = np.einsum("kji,kjl->kil", tr.g, tr.g) - np.eye(3)
    assert np.max(np.abs(gtg)) < 1e-13
    assert np.max(tr.defect()) < 1e-13


def test_records_every_and_first_step():
    it = integrator("c")
    full = it.simulate(G0, 0.05, 10, xi0=XI0)
    sub = it.simulate(G0, 0.05, 10, xi0=XI0, every=3)
    np.testing.assert_array_equal(sub.g, full.g[[0, 3, 6, 9]])
    np.testing.assert_array_equal(sub.mu, full.mu[[0, 3, 6, 9]])
    np.testing.assert_allclose(sub.t, [0, 0.15, 0.3, 0.45], rtol=0, atol=1e-15)
    assert len(it.simulate(G0, 0.05, 9, xi0=XI0, every=3)) == 4
    assert len(it.simulate(G0, 0.05, 0, xi0=XI0)) == 1
    for backend in ("c", "python"):
        g1, p1 = integrator(backend).step(full.g[0], full.mu[0], 0.05)
        np.testing.assert_allclose(g1, full.g[1], rtol=0, atol=1e-15)
        np.testing.assert_allclose(p1, full.mu[1], rtol=0, atol=1e-15)


def test_c_backend_is_thread_safe():
    from concurrent.futures import ThreadPoolExecutor
    it = integrator("c")
    xis = [XI0 * s for s in (0.5, 1.0, 1.5, 2.0)]
    with ThreadPoolExecutor(4) as pool:
        par = list(pool.map(lambda xi: it.simulate(G0, 0.05, 3000, xi0=xi), xis))
    for xi, tr in zip(xis, par):
        np.testing.assert_array_equal(tr.g, it.simulate(G0, 0.05, 3000, xi0=xi).g)


def test_legendre_velocity_energy():
    for backend in ("c", "python"):
        it = integrator(backend)
        g = _rotation(np.array([0.1, -0.7, 0.4]))
        mu = it.legendre(g, XI0)
        np.testing.assert_allclose(mu, [0.6, 1.0, -0.4 * 2 / 3], rtol=1e-15)
        np.testing.assert_allclose(it.velocity(g, mu), XI0, rtol=1e-15)
        assert abs(it.energy(g, mu) - 0.5 * XI0 @ mu) < 1e-15
        np.testing.assert_allclose(it.momentum(g, mu), g @ mu, rtol=1e-14)
        tr = it.simulate(g, 0.1, 3, mu0=mu)
        np.testing.assert_allclose(tr.xi()[0], XI0, rtol=1e-15)
        assert tr.energy().shape == (4,)


def test_newton_failure_raises_with_partial():
    for backend in ("c", "python"):
        with pytest.raises(ConvergenceError) as info:
            integrator(backend).simulate(G0, 0.1, 100, xi0=XI0,
                                         newton=newton.NewtonOptions(maxit=1))
        err = info.value
        assert type(err) is ConvergenceError and err.step == 0 and err.iterations == 1
        assert err.partial.partial and len(err.partial) == 1 and err.partial.error is err
        assert "did not converge" in str(err)


def test_non_finite_values_give_code_2_in_both_backends():
    for backend in ("c", "python"):
        it = integrator(backend)
        opts = newton.NewtonOptions(1e-14, 50)
        code, g1, *_ = it.engine.backend.step(G0.ravel(), XI0, np.array([0.1]), np.full(3, 1e200), opts)
        assert code == 2 and g1 is None
        with pytest.raises(ConvergenceError, match="non-finite"):
            it.step(G0, XI0, 0.1, z=np.full(3, 1e200))


def test_domain_error_mid_run_with_partial():
    results = []
    for backend in ("c", "python"):
        it = integrator(backend, "domain")
        with pytest.raises(DomainError) as info:
            it.simulate(G0, 0.1, 1000, xi0=XI0, every=3)
        err = info.value
        assert err.step > 3 and err.time == pytest.approx(err.step * 0.1)
        part = err.partial
        assert part.partial and len(part) == err.step // 3 + 1
        full = it.simulate(G0, 0.1, err.step, xi0=XI0, every=3)
        np.testing.assert_array_equal(part.g, full.g)
        results.append(err.step)
        with pytest.raises(DomainError):
            it.step(part.g[-1], part.mu[-1], 10.0)
    assert results[0] == results[1]


@pytest.mark.parametrize("kw, field", [
    ({"h": 0.0}, "h"), ({"h": float("nan")}, "h"), ({"steps": -1}, "steps"),
    ({"steps": 2.5}, "steps"), ({"every": 0}, "every"), ({"xi0": [1.0, 2.0]}, "xi0"),
    ({"xi0": [1.0, np.inf, 0.0]}, "xi0"), ({"xi0": None, "mu0": [1, 2]}, "mu0"),
    ({"mu0": [1.0, 0.0, 0.0]}, "xi0"), ({"g0": np.eye(2)}, "g0"),
    ({"g0": np.full((3, 3), np.nan)}, "g0"), ({"g0": 2 * np.eye(3)}, "initial g"),
    ({"newton": newton.NewtonOptions(maxit=0)}, "newton.maxit"),
    ({"newton": newton.NewtonOptions(tol=-1.0)}, "newton.tol"),
    ({"newton": newton.NewtonOptions(tol=float("nan"))}, "newton.tol"),
    ({"newton": {"tol": 1e-3}}, "newton")])
def test_simulate_validates_inputs(kw, field):
    """API arguments are refused as ArgumentError (a ValueError, not a ModelError: model
    files keep ModelError), one line naming the argument."""
    args = {"g0": G0, "h": 0.1, "steps": 5, "xi0": XI0, **kw}
    with pytest.raises(ArgumentError) as info:
        integrator("python").simulate(**args)
    assert info.value.field == field and isinstance(info.value, ValueError)
    assert not isinstance(info.value, ModelError) and "\n" not in str(info.value)


def test_singular_legendre_is_a_model_error():
    it = integrator("python", "singular")
    with pytest.raises(ModelError) as info:
        it.velocity(G0, [1.0, 0.0, 0.0])
    assert info.value.field == "scene.initial" and "singular" in str(info.value)


def test_trajectory_save_is_atomic_npz(tmp_path):
    tr = integrator("c").simulate(G0, 0.1, 20, xi0=XI0, every=5)
    out = tr.save(tmp_path / "run")
    assert out == tmp_path / "run.npz" and sorted(os.listdir(tmp_path)) == ["run.npz"]
    with np.load(out) as z:
        np.testing.assert_array_equal(z["g"], tr.g)
        np.testing.assert_array_equal(z["mu"], tr.mu)
        assert int(z["every"]) == 5 and not bool(z["partial"]) and str(z["module"]) == \
            "toy_plain"


def test_missing_compiler_is_a_build_error(tmp_path, monkeypatch):
    d = _fresh_copy(tmp_path)
    with pytest.raises(BuildError, match="/nonexistent/cc") as info:
        build_library(d, cc="/nonexistent/cc")
    assert "backend='python'" in str(info.value)
    monkeypatch.setenv("CC", "/nonexistent/cc")
    with pytest.raises(BuildError, match="/nonexistent/cc"):
        load(d, backend="c")
    assert load(d, backend="python").step(G0, XI0, 0.1)[0].shape == (3, 3)
    assert not list(d.glob("*.so"))


def test_compiler_failure_reports_stderr(tmp_path):
    d = _fresh_copy(tmp_path)
    (d / "kernels.c").write_text("this is not C\n")
    with pytest.raises(BuildError) as info:
        build_library(d)
    assert "kernels.c" in str(info.value) and info.value.stderr
    assert not [p for p in os.listdir(d) if p.endswith(".so")]


def test_concurrent_builds_both_succeed(tmp_path):
    d = _fresh_copy(tmp_path)
    code = "import sys; from hpgen.runtime import build_library; print(build_library(sys.argv[1]))"
    env = dict(os.environ, PYTHONPATH=str(REPO))
    procs = [subprocess.Popen([sys.executable, "-c", code, str(d)], stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, env=env) for _ in range(2)]
    outs = [p.communicate(timeout=120) for p in procs]
    assert all(p.returncode == 0 for p in procs), outs
    assert outs[0][0] == outs[1][0]
    (lib,) = d.glob("*.so")              # one library, named by its build key, with its record
    assert re.fullmatch(r"_kernels_[0-9a-f]{16}\.so", lib.name) and outs[0][0].strip() == str(lib)
    assert (d / (lib.name + ".json")).is_file()
    assert not list(d.glob(".tmp*"))


FRESH = r"""
import os, sys
sys.modules['casadi'] = sys.modules['sympy'] = sys.modules['jinja2'] = None
sys.path[:0] = [sys.argv[1], sys.argv[2]]
import numpy as np
import toy_plain as m
d = m.__path__[0]
assert not [p for p in os.listdir(d) if p.endswith('.so')], 'built at import'
xi0 = np.array([0.3, 1.0, -0.4])
ic, ip = m.integrator('c'), m.integrator('python')
assert ic.backend == 'c' and ip.backend == 'python' and m.integrator() is ic
mu0 = ic.legendre(np.eye(3), xi0)
g1, p1 = m.step(np.eye(3), mu0, 0.1)
g2, p2 = ip.step(np.eye(3), mu0, 0.1)
assert np.abs(g1 - g2).max() < 1e-14 and np.abs(p1 - p2).max() < 1e-14
tr = m.simulate(g0=np.eye(3), h=0.1, steps=50, xi0=xi0)
assert len(tr) == 51
A = ic.linearize(tr)   # issue 12: the step's derivatives, runtime path only
assert A.shape == (50, 6, 6) and np.abs(A - ip.linearize(tr)).max() < 1e-12
bad = [k for k in sys.modules if k.split('.')[0] in ('casadi', 'sympy', 'jinja2')
       and sys.modules[k] is not None]
assert not bad, bad
assert not any(k.startswith(('hpgen.codegen', 'hpgen.derive', 'hpgen.model')) for k in sys.modules)
print('OK')
"""


def test_generated_package_runs_without_compile_time_stack(tmp_path):
    write_module(emitted()[1], tmp_path / "pkgs")
    proc = subprocess.run([sys.executable, "-c", FRESH, str(REPO), str(tmp_path / "pkgs")],
                          capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, PYTHONPATH=""))
    assert proc.returncode == 0 and proc.stdout.strip() == "OK", proc.stderr


def test_load_rejects_bad_meta_and_backend(tmp_path):
    d = _fresh_copy(tmp_path)
    with pytest.raises(ModelError, match="backend"):
        load(d, backend="fortran")
    meta = (d / "meta.json").read_text()
    assert f'"format": {META_FORMAT},' in meta
    (d / "meta.json").write_text(meta.replace(f'"format": {META_FORMAT},', '"format": 1,'))
    with pytest.raises(ModelError, match=r"format: .*format 1, .*recompile"):
        load(d)
    (d / "meta.json").write_text(meta.replace('"0123456789abcdef', '"../../0123456789abcdef'))
    with pytest.raises(ModelError, match="hash"):
        load(d)


def test_runtime_imports_no_compile_time_stack():
    import hpgen.runtime as rt
    src = "".join(p.read_text() for p in Path(rt.__file__).parent.glob("*.py"))
    for banned in ("casadi", "sympy", "jinja2", "hpgen.codegen", ".codegen", ".derive",
                   ".model"):
        assert f"import {banned}" not in src and f"from {banned}" not in src
    assert module_dir().is_dir()


STEPPING = ("step", "velocity", "simulate", "stream", "simulate_batch", "sections",
            "sections_batch", "record", "stream_record", "record_batch")


def test_newton_settings_are_one_keyword_object():
    import inspect
    from hpgen.runtime import Integrator, NewtonOptions
    for name in STEPPING:
        params = inspect.signature(getattr(Integrator, name)).parameters
        assert params["newton"].kind is inspect.Parameter.KEYWORD_ONLY, name
        assert params["newton"].default is None, name
        assert not {"tol", "maxit", "simplified", "predictor"} & set(params), name
    it = integrator("python")
    # an old or misspelt keyword: Python's one-line TypeError naming it
    with pytest.raises(TypeError, match="unexpected keyword argument 'tol'"):
        it.simulate(G0, 0.1, 5, xi0=XI0, tol=1e-3)
    with pytest.raises(TypeError, match="unexpected keyword argument 'tolerance'"):
        NewtonOptions(tolerance=1e-3)
    # None is the defaults; step resolves simplified=None to full Newton, runs to the module's
    assert it.engine.options(None) == NewtonOptions(1e-14, 50, it.simplified_default, True)
    assert it.engine.options(NewtonOptions(maxit=7), full=True) == NewtonOptions(1e-14, 7, False, True)
