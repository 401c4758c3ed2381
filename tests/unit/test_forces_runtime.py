"""Open modules (forces, control inputs, runtime parameters, t; issue 16) through the public
API on the Python backend: u, params and t0 in simulate / stream / step, their checks, and
the refusals of what does not run them yet (the C backend, record, sections, batches)."""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.errors import ModelError
from hpgen.runtime import NewtonOptions

from test_derive_forces import FREE_BODY, HEAVY_TOP, TAU_S, VEHICLE

FULL = NewtonOptions(simplified=False)


@pytest.fixture(scope="module")
def modules(tmp_path_factory):
    root = tmp_path_factory.mktemp("forces")
    out = {}
    for name, text in (("body", FREE_BODY), ("top", HEAVY_TOP), ("vehicle", VEHICLE)):
        path = root / f"{name}.yaml"
        path.write_text(text)
        out[name] = hpgen.compile(path, tableau="gauss2", tau="cay", rkmk="exact",
                                  backend="python", cache_dir=root / "cache")
    out["root"] = root
    return out


def test_spatial_torque_identity_python_backend(modules):
    """R_k p_k = R_0 p_0 + k h tau_s over 10^4 steps to 1e-12 relative (full Newton: the
    default simplified Newton's stop, ~1e-16 (1 + |z|) per step with a stale Jacobian, adds
    up to 2e-12 over 10^4 steps, measured)."""
    body = modules["body"]
    tr = body.simulate(np.eye(3), 0.01, 10_000, xi0=[0.3, 0.2, -0.5], every=1000,
                       newton=FULL)
    m = np.einsum("kij,kj->ki", tr.g, tr.mu)
    expected = m[0] + tr.t[:, None] * TAU_S
    assert np.abs(m - expected).max() <= 1e-12 * np.abs(expected).max()
    assert np.abs(tr.momentum() - m).max() <= 1e-12 * np.abs(m).max()   # Ad* vs R p


def test_runtime_parameters_and_time(modules, tmp_path):
    """params overrides without recompiling equal a module whose file has that default,
    bitwise; t0 shifts the time of a time-dependent force (and the record times)."""
    top = modules["top"]
    kw = dict(xi0=[0.2, 1.0, 3.0], t0=0.3)
    a = top.simulate(np.eye(3), 0.05, 100, params={"Mg": 1.3}, **kw)
    path = tmp_path / "top13.yaml"
    path.write_text(HEAVY_TOP.replace("Mg: 1.0", "Mg: 1.3"))
    other = hpgen.compile(path, tableau="gauss2", tau="cay", rkmk="exact", backend="python",
                          cache_dir=tmp_path / "cache")
    b = other.simulate(np.eye(3), 0.05, 100, **kw)
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
    assert a.t[0] == 0.3 and a.t[-1] == pytest.approx(5.3, abs=1e-12)
    c = top.simulate(np.eye(3), 0.05, 100, xi0=[0.2, 1.0, 3.0], params={"Mg": 1.3})
    assert np.abs(c.mu[-1] - a.mu[-1]).max() > 1e-3        # the force depends on t
    d = top.simulate(np.eye(3), 0.05, 100, xi0=[0.2, 1.0, 3.0])
    assert np.abs(d.mu[-1] - c.mu[-1]).max() > 1e-3        # and the step on Mg


def test_stream_and_step_match_simulate(modules):
    veh = modules["vehicle"]
    U = np.linspace(0.2, 1.0, 60).reshape(60, 1)
    kw = dict(mu0=[0.3, 1.0, 0.2, 1.0, 0.0, 0.5], u=U, t0=1.0)
    full = veh.simulate(np.eye(4), 0.05, 60, every=5, **kw)
    parts = list(veh.stream(np.eye(4), 0.05, 60, every=5, chunk=17, **kw))
    assert np.array_equal(np.concatenate([p.mu for p in parts]), full.mu)
    assert np.array_equal(np.concatenate([p.t for p in parts]), full.t)
    g, p = veh.step(np.eye(4), kw["mu0"], 0.05, u=U[0], t=1.0)
    one = veh.simulate(np.eye(4), 0.05, 1, mu0=kw["mu0"], u=U[:1], t0=1.0)
    assert np.allclose(p, one.mu[1], rtol=0, atol=1e-13)
    # a constant u equals the same row repeated, bitwise
    c1 = veh.simulate(np.eye(4), 0.05, 20, mu0=kw["mu0"], u=[0.7])
    c2 = veh.simulate(np.eye(4), 0.05, 20, mu0=kw["mu0"], u=np.full((20, 1), 0.7))
    assert np.array_equal(c1.mu, c2.mu) and np.array_equal(c1.g, c2.g)


@pytest.mark.parametrize("kw, parts", [
    (dict(params={"Mx": 1.0}), ["params", "unknown runtime parameter 'Mx'", "Mg"]),
    (dict(params={"Mg": float("nan")}), ["params['Mg']", "non-finite"]),
    (dict(params={"Mg": [1.0, 2.0]}), ["params['Mg']", "expected a number"]),
    (dict(params=[1.0]), ["params", "expected a dict"]),
    (dict(u=[1.0]), ["u", "no control inputs"]),
    (dict(t0=float("inf")), ["t0", "finite"]),
])
def test_bad_arguments_fail_before_any_step(modules, kw, parts):
    with pytest.raises(ValueError) as e:
        modules["top"].simulate(np.eye(3), 0.05, 10, xi0=[0.2, 1.0, 3.0], **kw)
    assert isinstance(e.value, ModelError) and "\n" not in str(e.value)
    for part in parts:
        assert part in str(e.value)


@pytest.mark.parametrize("u, parts", [
    (None, ["u is required", "thrust"]),
    ([1.0, 2.0], ["u", "shape (1,)"]),
    (np.ones((9, 1)), ["u", "(10, 1)"]),
    ([np.nan], ["u", "non-finite"]),
])
def test_bad_inputs_u(modules, u, parts):
    with pytest.raises(ModelError) as e:
        modules["vehicle"].simulate(np.eye(4), 0.05, 10, mu0=[0.3, 1.0, 0.2, 1.0, 0.0, 0.5],
                                    u=u)
    for part in parts:
        assert part in str(e.value)


def test_closed_modules_refuse_u_and_params(tmp_path):
    path = tmp_path / "closed.yaml"
    path.write_text(FREE_BODY.split("forces:")[0])
    integ = hpgen.compile(path, backend="python", cache_dir=tmp_path / "cache")
    with pytest.raises(ModelError, match="no control inputs"):
        integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3], u=[1.0])
    with pytest.raises(ModelError, match="no runtime parameters"):
        integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3], params={"I": 1.0})
    a = integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3], t0=2.0)
    b = integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3])
    assert np.array_equal(a.mu, b.mu) and np.array_equal(a.t, b.t + 2.0)


def test_what_does_not_run_open_modules_yet(modules):
    top = modules["top"]
    with pytest.raises(ModelError, match="backend='python'"):
        hpgen.compile(modules["root"] / "top.yaml", cache_dir=modules["root"] / "cache")
    with pytest.raises(ModelError, match="does not run models with forces"):
        top.record(np.eye(3), 0.05, 3, xi0=[0.2, 1.0, 3.0])
