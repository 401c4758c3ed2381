"""Open modules (forces, control inputs, runtime parameters, t; issue 16) through the public
API: u, params and t0 in simulate / stream / step / simulate_batch on both backends, their
checks, C against Python, record / sections and their batches."""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.errors import ArgumentError
from hpgen.runtime import NewtonOptions

from test_derive_forces import FREE_BODY, HEAVY_TOP, TAU_S, VEHICLE

FULL = NewtonOptions(simplified=False)
SCENE = """\
scene:
  h: 0.05
  steps: 60
  initial: {g: identity, xi: [0.2, 1.0, 3.0]}
  record: [g, mu, energy, {height: "R[2, 2]"}]
  every: 10
"""


@pytest.fixture(scope="module")
def modules(tmp_path_factory):
    root = tmp_path_factory.mktemp("forces")
    out = {}
    for name, text in (("body", FREE_BODY), ("top", HEAVY_TOP), ("vehicle", VEHICLE),
                       ("scene", HEAVY_TOP + SCENE),
                       ("section", HEAVY_TOP + SCENE + "  section: mu[0]\n")):
        path = root / f"{name}.yaml"
        path.write_text(text)
        out[name] = hpgen.compile(path, tableau="gauss2", tau="cay", rkmk="exact",
                                  backend="python", cache_dir=root / "cache")
        out[name + "_c"] = hpgen.compile(path, tableau="gauss2", tau="cay", rkmk="exact",
                                         cache_dir=root / "cache")
    out["root"] = root
    return out


@pytest.mark.parametrize("backend", ["python", "c"])
def test_spatial_torque_identity(modules, backend):
    """R_k p_k = R_0 p_0 + k h tau_s over 10^4 steps to 1e-12 relative (full Newton: the
    default simplified Newton's stop, ~1e-16 (1 + |z|) per step with a stale Jacobian, adds
    up to 2e-12 over 10^4 steps, measured)."""
    body = modules["body" if backend == "python" else "body_c"]
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
    assert isinstance(e.value, ArgumentError) and "\n" not in str(e.value)
    for part in parts:
        assert part in str(e.value)


@pytest.mark.parametrize("u, parts", [
    (None, ["u is required", "thrust"]),
    ([1.0, 2.0], ["u", "shape (1,)"]),
    (np.ones((9, 1)), ["u", "(10, 1)"]),
    ([np.nan], ["u", "input thrust is not finite", "u[0] = nan"]),
    (np.r_[np.ones(7), np.inf, np.ones(2)].reshape(10, 1),
     ["u", "step 7, input thrust is not finite", "u[7, 0] = inf"]),
    (["1.0"], ["u", "real numbers", "strings"]),
    ([True], ["u", "real numbers", "booleans"]),
    ([None], ["u", "real numbers", "None"]),
    ([[1.0]] * 9 + [["x"]], ["u", "real numbers", "strings"]),
])
def test_bad_inputs_u(modules, u, parts):
    with pytest.raises(ArgumentError) as e:
        modules["vehicle"].simulate(np.eye(4), 0.05, 10, mu0=[0.3, 1.0, 0.2, 1.0, 0.0, 0.5],
                                    u=u)
    for part in parts:
        assert part in str(e.value)


@pytest.mark.parametrize("kw, parts", [
    (dict(params={"Mg": "1.3"}), ["params['Mg']", "real numbers", "strings"]),
    (dict(params={"Mg": True}), ["params['Mg']", "real numbers", "booleans"]),
    (dict(params={"Mg": None}), ["params['Mg']", "real numbers", "None"]),
    (dict(params={"Mg": object()}), ["params['Mg']", "real numbers", "object"]),
])
def test_non_numeric_params_are_refused(modules, kw, parts):
    """Strings, booleans, None and objects are not numbers (numpy would convert "1.3" and
    True silently); numpy numbers and Python ints stay accepted."""
    top = modules["top"]
    with pytest.raises(ArgumentError) as e:
        top.simulate(np.eye(3), 0.05, 10, xi0=[0.2, 1.0, 3.0], **kw)
    assert e.value.field.startswith("params") and "\n" not in str(e.value)
    for part in parts:
        assert part in str(e.value)
    a = top.simulate(np.eye(3), 0.05, 10, xi0=[0.2, 1.0, 3.0], params={"Mg": np.float32(2)})
    b = top.simulate(np.eye(3), 0.05, 10, xi0=[0.2, 1.0, 3.0], params={"Mg": 2})
    assert np.array_equal(a.mu, b.mu)


def test_step_asks_for_one_row_of_u(modules):
    """step() takes the input of one step: its messages ask for shape (m,) only."""
    veh = modules["vehicle"]
    mu0 = [0.3, 1.0, 0.2, 1.0, 0.0, 0.5]
    with pytest.raises(ArgumentError) as e:
        veh.step(np.eye(4), mu0, 0.05)
    assert "shape (1,)" in str(e.value) and "steps" not in str(e.value)
    with pytest.raises(ArgumentError) as e:
        veh.step(np.eye(4), mu0, 0.05, u=np.ones((3, 1)))
    assert "shape (1,)" in str(e.value) and "steps" not in str(e.value)
    with pytest.raises(ArgumentError, match="input thrust is not finite"):
        veh.step(np.eye(4), mu0, 0.05, u=[np.nan])


@pytest.mark.parametrize("backend", ["python", "c"])
def test_per_step_u_with_zero_steps(modules, backend):
    """steps = 0 records the start, whose input a per-step u (0, m) does not hold: one line
    (was an IndexError); a constant u works."""
    vehicle = modules["vehicle" if backend == "python" else "vehicle_c"]
    mu0 = [0.3, 1.0, 0.2, 1.0, 0.0, 0.5]
    with pytest.raises(ArgumentError, match="steps >= 1") as e:
        vehicle.simulate(np.eye(4), 0.05, 0, mu0=mu0, u=np.zeros((0, 1)))
    assert e.value.field == "u" and "\n" not in str(e.value)
    assert len(vehicle.simulate(np.eye(4), 0.05, 0, mu0=mu0, u=[0.5]).t) == 1


def test_closed_modules_refuse_u_and_params(tmp_path):
    path = tmp_path / "closed.yaml"
    path.write_text(FREE_BODY.split("forces:")[0])
    integ = hpgen.compile(path, backend="python", cache_dir=tmp_path / "cache")
    with pytest.raises(ArgumentError, match="no control inputs"):
        integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3], u=[1.0])
    with pytest.raises(ArgumentError, match="no runtime parameters"):
        integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3], params={"I": 1.0})
    a = integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3], t0=2.0)
    b = integ.simulate(np.eye(3), 0.05, 3, xi0=[0.1, 0.2, 0.3])
    assert np.array_equal(a.mu, b.mu) and np.array_equal(a.t, b.t + 2.0)


def test_c_and_python_agree(modules):
    """Forced, time-dependent, runtime-parameter runs: bitwise for nz <= abi.UNROLL_MAX (the
    same kernels and the same linear algebra), to round-off above (numpy's LAPACK)."""
    kw = dict(xi0=[0.2, 1.0, 3.0], params={"Mg": 1.3}, t0=0.3)
    a = modules["top"].simulate(np.eye(3), 0.05, 300, **kw)
    b = modules["top_c"].simulate(np.eye(3), 0.05, 300, **kw)
    assert modules["top_c"].nz <= 12
    assert np.array_equal(a.mu, b.mu) and np.array_equal(a.g, b.g)
    U = np.linspace(0.0, 1.0, 300).reshape(300, 1)
    kw = dict(mu0=[0.3, 1.0, 0.2, 1.0, 0.0, 0.5], u=U, t0=0.1)
    a = modules["vehicle"].simulate(np.eye(4), 0.05, 300, **kw)
    b = modules["vehicle_c"].simulate(np.eye(4), 0.05, 300, **kw)
    assert np.abs(a.mu - b.mu).max() <= 1e-12 * np.abs(a.mu).max()
    assert np.abs(a.g - b.g).max() <= 1e-12 * np.abs(a.g).max()
    # step solves with full Newton from the guess; a run's first step takes the run's Newton
    # (simplified here): the two roots agree to the Newton tolerance (1e-14 (1 + |z|))
    g1, p1 = modules["vehicle_c"].step(np.eye(4), kw["mu0"], 0.05, u=U[0], t=0.1)
    assert np.abs(p1 - b.mu[1]).max() <= 1e-13 * (1.0 + np.abs(p1).max())


def test_parameter_sweep_in_one_batch(modules):
    """64 values of a runtime parameter in one simulate_batch of one compiled module; each run
    bitwise the one-at-a-time simulate."""
    top = modules["top_c"]
    Mg = np.linspace(0.5, 2.0, 64)
    W0 = np.tile([0.2, 1.0, 3.0], (64, 1))
    runs = top.simulate_batch(np.eye(3), 0.05, 200, xi0=W0, params={"Mg": Mg}, t0=0.3,
                              threads=2)
    assert len(runs) == 64
    for b in (0, 17, 63):
        one = top.simulate(np.eye(3), 0.05, 200, xi0=W0[b], params={"Mg": Mg[b]}, t0=0.3)
        assert np.array_equal(runs[b].mu, one.mu) and np.array_equal(runs[b].g, one.g)
        assert np.array_equal(runs[b].t, one.t)
    assert np.abs(runs[0].mu[-1] - runs[63].mu[-1]).max() > 1e-2
    with pytest.raises(ArgumentError, match="params"):
        top.simulate_batch(np.eye(3), 0.05, 10, xi0=W0, params={"Mg": Mg[:5]})


@pytest.mark.parametrize("backend", ["python", "c"])
def test_record_of_an_open_module(modules, backend):
    """record / stream_record: the compiled row (g, mu, energy at the record's time and
    params) of the same states as simulate, bitwise; C and Python rows bitwise."""
    top = modules["scene" if backend == "python" else "scene_c"]
    kw = dict(xi0=[0.2, 1.0, 3.0], params={"Mg": 1.3}, t0=0.3)
    rec = top.record(np.eye(3), 0.05, 60, every=10, **kw)
    sim = top.simulate(np.eye(3), 0.05, 60, every=10, **kw)
    assert np.array_equal(rec["mu"], sim.mu) and np.array_equal(rec.t, sim.t)
    assert np.abs(rec["energy"] - sim.energy()).max() <= 1e-13 * np.abs(sim.energy()).max()
    parts = list(top.stream_record(np.eye(3), 0.05, 60, every=10, chunk=25, **kw))
    assert np.array_equal(np.concatenate([p["mu"] for p in parts]), rec["mu"])
    assert np.array_equal(rec["height"], sim.g[:, 2, 2])
    other = modules["scene_c" if backend == "python" else "scene"]
    assert np.array_equal(other.record(np.eye(3), 0.05, 60, every=10, **kw)["energy"],
                          rec["energy"])


def test_sections_of_an_open_module(modules):
    """Upward crossings of s = mu[0] with params and t0: at the steps where simulate's p_k
    changes sign, times t0 + (k + theta) h; C and Python bitwise."""
    kw = dict(xi0=[0.2, 1.0, 3.0], params={"Mg": 1.3}, t0=0.3)
    cs = modules["section_c"].sections(np.eye(3), 0.05, 400, **kw)
    cp = modules["section"].sections(np.eye(3), 0.05, 400, **kw)
    assert np.array_equal(cs.t, cp.t) and np.array_equal(cs.mu, cp.mu)
    sim = modules["section_c"].simulate(np.eye(3), 0.05, 400, **kw)
    s = sim.mu[:, 0]
    ks = np.nonzero((s[:-1] < 0) & (s[1:] >= 0))[0]
    assert len(ks) >= 3 and np.array_equal(cs.step, ks)
    theta = s[ks] / (s[ks] - s[ks + 1])
    assert np.allclose(cs.t, 0.3 + (ks + theta) * 0.05, rtol=0, atol=1e-12)


def test_record_and_sections_batch_of_an_open_module(modules):
    """record_batch / sections_batch over a params sweep with t0: each run bitwise the
    one-at-a-time record / sections (rows, times, crossings)."""
    Mg = np.array([0.8, 1.3, 1.7])
    W0 = np.tile([0.2, 1.0, 3.0], (3, 1))
    recs = modules["scene_c"].record_batch(np.eye(3), 0.05, 60, xi0=W0, every=10,
                                           params={"Mg": Mg}, t0=0.3, threads=2)
    secs = modules["section_c"].sections_batch(np.eye(3), 0.05, 400, xi0=W0,
                                               params={"Mg": Mg}, t0=0.3, threads=2)
    for b in range(3):
        kw = dict(xi0=W0[b], params={"Mg": Mg[b]}, t0=0.3)
        one = modules["scene_c"].record(np.eye(3), 0.05, 60, every=10, **kw)
        assert recs[b].names == one.names and np.array_equal(recs[b].t, one.t)
        assert all(np.array_equal(recs[b][k], one[k]) for k in one.names)
        cs = modules["section_c"].sections(np.eye(3), 0.05, 400, **kw)
        assert len(cs.t) >= 3 and np.array_equal(secs[b].t, cs.t)
        assert np.array_equal(secs[b].mu, cs.mu) and np.array_equal(secs[b].g, cs.g)
    assert np.abs(recs[0]["mu"][-1] - recs[2]["mu"][-1]).max() > 1e-3


def test_cli_on_an_open_model(modules, tmp_path):
    """hpgen run records an open model's scene (default params, t0 = 0); hpgen bench runs it
    against its peers (the forced equations); hpgen check reports the
    energy-work balance (tests/property/test_check_forced.py)."""
    import subprocess
    import sys
    path = modules["root"] / "scene.yaml"
    env_cache = str(modules["root"] / "cache")
    run = subprocess.run([sys.executable, "-m", "hpgen", "run", str(path), "--out",
                          str(tmp_path / "o.npz"), "--cache-dir", env_cache, "--tableau",
                          "gauss2", "--tau", "cay", "--rkmk", "exact"],
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    out = np.load(tmp_path / "o.npz")
    sim = modules["scene_c"].simulate(np.eye(3), 0.05, 60, xi0=[0.2, 1.0, 3.0], every=10)
    assert np.array_equal(out["mu"], sim.mu)
    for cmd in (["bench", "--T", "0.5", "--peers", "DOP853"],):
        res = subprocess.run([sys.executable, "-m", "hpgen", cmd[0], str(path), *cmd[1:],
                              "--cache-dir", env_cache], capture_output=True, text=True,
                             timeout=600, cwd=tmp_path)   # bench writes bench-<name>/ here
        assert res.returncode == 0, res.stderr          # bench integrates the forced model
        assert (tmp_path / "bench-forced_top" / "work_precision.csv").is_file()
        assert "DOP853" in res.stdout and "Traceback" not in res.stderr
