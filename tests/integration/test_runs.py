"""Runs: Newton modes (full / simplified, predictor), chunked streaming and batched ensembles
on the heavy top with Gauss 2, Cayley, exact RKMK (9 unknowns after the elimination).

Tolerances: every mode converges each step to round-off (full Newton stops at |dz| <= 1e-14
(1 + |z|), leaving O(tol^2); simplified Newton at an estimated error <= 1e-16 (1 + |z|)), so
the modes differ by a few ulps per step; over 200 steps at h = 0.05 the top amplifies that to
< 1e-12 (measured 2e-13). Chunked and batched runs execute the same C code on the same data in
the same order, so they must be bitwise equal to one call of ``simulate``.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import HEAVY_TOP
from hpgen.errors import DomainError
from hpgen.runtime import NewtonOptions

OPTS = dict(tableau="gauss2", tau="cay", rkmk="exact")
XI0 = np.array([0.2, 1.0, 3.0])
H = 0.05


def _g0():
    v = np.array([0.3, 0.2, 0.0])
    t = np.linalg.norm(v)
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]) / t
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


@pytest.fixture(scope="module")
def tops(tmp_path_factory):
    import hpgen
    path = tmp_path_factory.mktemp("runs") / "top.yaml"
    path.write_text(HEAVY_TOP)
    cache = tmp_path_factory.mktemp("cache")
    return {b: hpgen.compile(path, backend=b, cache_dir=cache, **OPTS) for b in ("c", "python")}


def test_elimination_leaves_theta_and_mu1(tops):
    it = tops["c"]
    assert it.nz == 9
    assert [u[0] for u in it.meta["unknowns"]] == ["Theta1", "Theta2", "mu1"]
    # the Jacobian costs > 4 residuals here, so simplified Newton is the default
    assert it.simplified_default


@pytest.mark.parametrize("backend", ["c", "python"])
def test_newton_modes_agree(tops, backend):
    it = tops[backend]
    steps = 200 if backend == "c" else 30
    runs = {(s, p): it.simulate(_g0(), H, steps, xi0=XI0,
                                newton=NewtonOptions(simplified=s, predictor=p))
            for s in (False, True) for p in (False, True)}
    ref = runs[(False, False)]
    for key, tr in runs.items():
        assert np.abs(tr.g - ref.g).max() < 1e-12, key
        assert np.abs(tr.mu - ref.mu).max() < 1e-12 * np.abs(ref.mu).max(), key
    # simplified Newton reuses J across steps: far fewer Jacobians than steps
    assert runs[(True, True)].jacobians < 0.5 * steps < steps <= runs[(False, True)].jacobians
    # the predictor saves iterations of full Newton
    assert runs[(False, True)].newton_iterations < runs[(False, False)].newton_iterations


def test_simplified_newton_keeps_invariants(tops):
    """e3.(R p) (vertical spatial momentum) and R^T R = I over 1e4 steps with the default
    (simplified Newton, predictor): round-off accumulation only."""
    tr = tops["c"].simulate(_g0(), H, 10_000, xi0=XI0, every=10)
    m = tr.momentum()[:, 2]
    assert np.abs(m - m[0]).max() <= 1e-12 * np.abs(tr.mu).max()
    gtg = np.einsum("kji,kjl->kil", tr.g, tr.g) - np.eye(3)
    assert np.abs(gtg).max() < 1e-13


def test_backends_agree_with_simplified_newton(tops):
    a = tops["c"].simulate(_g0(), H, 40, xi0=XI0, newton=NewtonOptions(simplified=True))
    b = tops["python"].simulate(_g0(), H, 40, xi0=XI0, newton=NewtonOptions(simplified=True))
    assert np.abs(a.g - b.g).max() < 1e-13 and np.abs(a.mu - b.mu).max() < 1e-12


@pytest.mark.parametrize("backend", ["c", "python"])
def test_stream_is_bitwise_simulate(tops, backend):
    it = tops[backend]
    steps = 200 if backend == "c" else 25
    full = it.simulate(_g0(), H, steps, xi0=XI0, every=3)
    parts = list(it.stream(_g0(), H, steps, xi0=XI0, every=3, chunk=7))
    assert len(parts) == -(-steps // 7)
    np.testing.assert_array_equal(np.concatenate([p.g for p in parts]), full.g)
    np.testing.assert_array_equal(np.concatenate([p.mu for p in parts]), full.mu)
    np.testing.assert_allclose(np.concatenate([p.t for p in parts]), full.t, rtol=1e-15)


def test_batch_is_bitwise_one_at_a_time(tops):
    it = tops["c"]
    rng = np.random.default_rng(3)
    xis = XI0 + 0.3 * rng.normal(size=(5, 3))
    batch = it.simulate_batch(_g0(), H, 300, xi0=xis, every=7, threads=2)
    for xi, tr in zip(xis, batch):
        one = it.simulate(_g0(), H, 300, xi0=xi, every=7)
        np.testing.assert_array_equal(tr.g, one.g)
        np.testing.assert_array_equal(tr.mu, one.mu)
        assert not tr.partial and tr.jacobians == one.jacobians


def test_batch_member_failure_is_partial(tops):
    """One member spins too fast for the chart (|h xi| far beyond Cayley's quarter turn): its
    Trajectory is partial with a DomainError; the others are complete."""
    it = tops["c"]
    xis = np.array([XI0, [0.0, 0.0, 200.0], XI0 * 0.5])
    out = it.simulate_batch(_g0(), H, 50, xi0=xis, threads=2)
    assert [tr.partial for tr in out] == [False, True, False]
    assert isinstance(out[1].error, DomainError) and len(out[1]) == out[1].error.step + 1
    np.testing.assert_array_equal(out[2].g, it.simulate(_g0(), H, 50, xi0=XI0 * 0.5).g)
