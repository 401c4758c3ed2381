"""Poincare sections compiled into the step loop (scene ``section:``, Integrator.sections,
C hpgen_advance_sections and its Python mirror).

A crossing is s_k < 0 <= s_{k+1} for s = section(g, mu); it is recorded with
theta = s_k / (s_k - s_{k+1}), t = (k + theta) h, mu linearly interpolated, and g on the
step's chart curve g_k tau(theta h xi_{k+1}). The tests recompute every crossing from a full
``simulate`` (every = 1) with the same formulas: t and mu bitwise, g to round-off; and check
that both backends, chunked calls and max_crossings give the same records.
"""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.errors import ModelError

FREE_BODY = """
name: free_body_section
group: SO3
parameters:
  I: [2.0, 1.0, 0.6666666666666666]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)
scene:
  h: 0.1
  steps: 1000
  initial: {g: identity, mu: [0.4535961214255773, 0.0, 0.8912073600614354]}
  section: mu[1]
"""
# the heavy top with a section in g: the body axis e3 crossing the height 0.9 upwards
HEAVY_TOP = """
name: heavy_top_section
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, chi: [0.0, 0.0, 1.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*(R[2,0]*chi[0] + R[2,1]*chi[1] + R[2,2]*chi[2])
scene:
  h: 0.05
  steps: 2000
  initial: {g: {rotvec: [0.3, 0.2, 0.0]}, xi: [0.2, 1.0, 3.0]}
  section: R[2,2] - 0.97
"""
OPTS = {"free": dict(tableau="stormer-verlet", tau="cay", rkmk="truncated"),
        "top": dict(tableau="gauss2", tau="cay", rkmk="exact")}


def _scene(name):
    if name == "free":
        return FREE_BODY, dict(g0=np.eye(3), mu0=[0.4535961214255773, 0.0, 0.8912073600614354],
                               h=0.1, steps=1000), (lambda g, mu: mu[:, 1])
    from scipy.spatial.transform import Rotation
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    return HEAVY_TOP, dict(g0=g0, xi0=[0.2, 1.0, 3.0], h=0.05, steps=2000), \
        (lambda g, mu: g[:, 2, 2] - 0.97)


@pytest.fixture(scope="module", params=["free", "top"])
def case(request, compile_model):
    text, kw, s = _scene(request.param)
    integ = {b: compile_model(text, backend=b, **OPTS[request.param]) for b in ("c", "python")}
    return integ, kw, s


def test_crossings_match_the_full_trajectory(case):
    integ, kw, s_of = case
    cr = integ["c"].sections(**kw)
    tr = integ["c"].simulate(every=1, **kw)
    s = s_of(tr.g, tr.mu)
    k = np.flatnonzero((s[:-1] < 0.0) & (s[1:] >= 0.0))
    assert len(k) >= 3 and cr.steps == kw["steps"] and not cr.partial
    np.testing.assert_array_equal(cr.step, k)
    theta = s[k] / (s[k] - s[k + 1])
    np.testing.assert_array_equal(cr.t, (k + theta) * kw["h"])
    np.testing.assert_array_equal(cr.mu, (1.0 - theta)[:, None] * tr.mu[k] + theta[:, None]
                                  * tr.mu[k + 1])
    # g on the chart curve: between g_k and g_{k+1}, on the group
    for j, kk in enumerate(k):
        a, b = np.abs(cr.g[j] - tr.g[kk]).max(), np.abs(tr.g[kk + 1] - tr.g[kk]).max()
        assert a <= b * (1 + 1e-12)
        # on the group as the nodes are (their defect is round-off accumulated over the
        # run, about 1e-14 after 2000 steps), plus the few roundings of g_k tau(.)
        node = max(np.abs(tr.g[i].T @ tr.g[i] - np.eye(3)).max() for i in (kk, kk + 1))
        assert np.abs(cr.g[j].T @ cr.g[j] - np.eye(3)).max() <= node + 8 * np.finfo(float).eps
    # s at the recorded (g, mu) is zero up to linear interpolation's error, at most
    # h^2 max|s''| / 8 on the step: bounded here by the neighbouring second differences
    s_at = s_of(cr.g, cr.mu)
    k = k[k >= 1]
    d2 = np.abs(s[k + 1] - 2 * s[k] + s[k - 1]) + np.abs(s[k + 2] - 2 * s[k + 1] + s[k])
    assert np.all(np.abs(s_at[-len(k):]) <= d2 + 1e-14)


def test_python_backend_is_bitwise_the_c_loop(case):
    integ, kw, _ = case
    a, b = integ["c"].sections(**kw), integ["python"].sections(**kw)
    for f in ("t", "g", "mu", "step"):
        np.testing.assert_array_equal(getattr(a, f), getattr(b, f))


def test_chunked_calls_and_max_crossings(case):
    integ, kw, _ = case
    whole = integ["c"].sections(**kw)
    one_by_one = integ["c"].sections(chunk=1, **kw)
    for f in ("t", "g", "mu", "step"):
        np.testing.assert_array_equal(getattr(whole, f), getattr(one_by_one, f))
    first = integ["c"].sections(max_crossings=2, **kw)
    assert len(first) == 2 and first.steps == whole.step[1] + 1
    np.testing.assert_array_equal(first.t, whole.t[:2])


def test_model_without_section_is_a_model_error(compile_model):
    integ = compile_model(FREE_BODY.replace("  section: mu[1]\n", ""),
                          **OPTS["free"])
    with pytest.raises(ModelError, match="section"):
        integ.sections(g0=np.eye(3), mu0=[0.5, 0.0, 0.8], h=0.1, steps=10)


def test_cli_run_saves_the_crossings(model_file, compile_model, tmp_path, cache_dir):
    import subprocess
    import sys
    path = model_file(FREE_BODY)
    out = subprocess.run([sys.executable, "-m", "hpgen", "run", str(path), "--out",
                          str(tmp_path / "sec.npz"), "--cache-dir", str(cache_dir),
                          "--tableau", "stormer-verlet", "--tau", "cay", "--rkmk", "truncated"],
                         capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    assert "crossings of the section 'mu[1]'" in out.stdout
    data = np.load(tmp_path / "sec.npz")
    _, kw, _ = _scene("free")
    ref = compile_model(FREE_BODY, **OPTS["free"]).sections(**kw)
    for f in ("t", "g", "mu", "step"):
        np.testing.assert_array_equal(data[f], getattr(ref, f))
    assert not data["partial"]


def test_batch_is_bitwise_the_single_runs(compile_model):
    integ = compile_model(FREE_BODY, **OPTS["free"])
    rng = np.random.default_rng(7)
    mus = rng.normal(size=(6, 3))
    mus[3] = [0.0, 0.0, 1e3]        # spins far beyond the Cayley chart at h = 0.1: fails
    out = integ.sections_batch(np.eye(3), 0.1, 400, mu0=mus, threads=2)
    assert [c.partial for c in out] == [False, False, False, True, False, False]
    assert out[3].error is not None and len(out[3]) == 0
    for b in (0, 1, 2, 4, 5):
        one = integ.sections(g0=np.eye(3), mu0=mus[b], h=0.1, steps=400)
        for f in ("t", "g", "mu", "step"):
            np.testing.assert_array_equal(getattr(out[b], f), getattr(one, f))
