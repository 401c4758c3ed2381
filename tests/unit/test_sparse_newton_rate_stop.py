"""The chord's rate stop (hpgen.runtime.newton_sparse.chord_converged, the C runtime's
hpgen_chord_converged): from the second iterate on, the error left in z_k is bounded by
theta_k / (1 - theta_k) |dz_k|, theta_k = |dz_k| / |dz_{k-1}|, and the chord stops there
instead of computing one more correction to see it at the noise.

The synthetic problem: F(z) = A z + c z^2 (entrywise) - b, A tridiagonal and diagonally
dominant, no noise; its root by dense Newton in long double steps to the last bit is the
reference. The chord from a start 1e-4 .. 1e-6 away: z_1 (a Newton step) has an error of
about C |dz_1|^2, dz_2 is that error, and theta_2 |dz_2| tells that z_2 is converged.
"""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.abi import ROUNDOFF_FLOOR
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime import newton_sparse
from hpgen.runtime.newton import Kernels
from hpgen.runtime.newton_sparse import chord_converged, solve_pass

from conftest import EXAMPLES

NZ = 24
TOL = 1e-14


def quadratic_problem(seed: int = 3):
    """(Kernels of F(z) = A z + c z^2 - b with its sparse J, the root)."""
    rng = np.random.default_rng(seed)
    A = (np.diag(4.0 + rng.random(NZ)) + np.diag(rng.random(NZ - 1), 1)
         + np.diag(rng.random(NZ - 1), -1))
    c = 0.3 * rng.random(NZ)
    b = 3.0 * rng.standard_normal(NZ)
    rows, colind = [], [0]
    for j in range(NZ):
        rows += [i for i in range(NZ) if A[i, j] != 0.0]
        colind.append(len(rows))

    def residual(z, g, p, hv):
        z = np.asarray(z)
        return [(A @ z + c * z * z - b).tolist()]

    def jac(z):
        return (A + np.diag(2.0 * c * np.asarray(z))).ravel(order="F").tolist()

    def residual_jacobian(z, g, p, hv):
        return residual(z, g, p, hv)[0], jac(z)
    root = np.linalg.solve(A, b)
    for _ in range(60):
        step = np.linalg.solve(A + np.diag(2.0 * c * root), A @ root + c * root * root - b)
        root = root - step
        if np.abs(step).max() == 0.0:
            break
    kern = Kernels(NZ, residual, lambda z, *a: [jac(z)], residual_jacobian,
                   pattern=(colind, rows))
    return kern, root


def test_the_bound_and_its_guards():
    s = 1.0 + 2.0                                          # 1 + |z| with |z| = 2
    assert not chord_converged(1, 1e-20, float("inf"), 2.0, TOL)   # no rate yet
    assert chord_converged(2, 1e-13, 1e-9, 2.0, TOL)       # theta 1e-4: 1e-17 left
    assert not chord_converged(2, 1e-13, 1e-13, 2.0, TOL)  # no contraction
    assert not chord_converged(2, 1e-13, 2e-13, 2.0, TOL)  # theta 0.5: 1e-13 left > tol s
    assert chord_converged(2, 1e-14, 2e-14, 2.0, TOL)      # theta 0.5: 1e-14 left <= tol s
    big = 2.0 * ROUNDOFF_FLOOR * s                         # above the floor: not trusted
    assert not chord_converged(2, big, big / 1e-9, 2.0, TOL)


@pytest.mark.parametrize("offset, iterates", [(1e-3, 3), (1e-4, 3), (1e-5, 2), (1e-6, 2)])
def test_the_chord_stops_on_its_rate(offset, iterates, monkeypatch):
    """From a start 1e-3 .. 1e-6 off the root: the chord stops at the first iterate whose
    correction is below ROUNDOFF_FLOOR (1 + |z|) (the second from 1e-5 on, |dz_2| ~ C
    offset^2) with the error left within tol (1 + |z|) (the bound theta |dz| holds), one J;
    the old stop (RATE_STOP False: a kept J's bound with THETA_FLOOR and SIMPLIFIED_TOL)
    needs one iterate more for the same accuracy."""
    kern, root = quadratic_problem()
    z0 = (root + offset * np.cos(np.arange(NZ))).tolist()
    code, z, it, _, jacs = solve_pass(kern, z0, [], [], [1e-3], TOL, 30, True)
    err = np.abs(np.asarray(z) - root).max()
    assert code == 0 and jacs == 1 and it == iterates
    assert err <= TOL * (1.0 + np.abs(root).max())
    monkeypatch.setattr(newton_sparse, "RATE_STOP", False)
    code, z_old, it_old, _, _ = solve_pass(kern, z0, [], [], [1e-3], TOL, 30, True)
    assert code == 0 and it_old == it + 1


def test_a_slow_chord_is_not_stopped_early():
    """A start 0.3 off the root (theta_2 of order 0.1): the rate bound holds only once the
    correction is tiny, and the error left is still within tol (1 + |z|)."""
    kern, root = quadratic_problem()
    z0 = (root + 0.3 * np.cos(np.arange(NZ))).tolist()
    code, z, it, _, _ = solve_pass(kern, z0, [], [], [1e-3], TOL, 50, True)
    assert code == 0 and it >= 4
    assert np.abs(np.asarray(z) - root).max() <= TOL * (1.0 + np.abs(root).max())


def test_the_c_chord_on_the_chain(cache_dir):
    """The capsule chain (N = 4, random joint velocities, 300 steps of 1e-3, C): one J a
    step and about two iterates (the stop at the second), against three and more with
    -DHPGEN_CHORD_RATE_STOP=0; both runs' states agree to the round-off of 300 steps, and the
    joints stay closed."""
    n, steps = 4, 300
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), "centre")
    runs = {}
    for key, flags in (("rate", None), ("old", ["-DHPGEN_CHORD_RATE_STOP=0"])):
        integ = hpgen.compile(EXAMPLES / "capsule_chain.yaml", parameters={"N": n},
                              cache_dir=cache_dir, cflags=flags)
        runs[key] = integ.simulate(g0, 1e-3, steps, xi0=xi0, every=10)
        assert runs[key].error is None and runs[key].jacobians == steps
    assert runs["rate"].newton_iterations <= 2.2 * steps
    assert runs["old"].newton_iterations >= 2.8 * steps
    mu = runs["old"].mu
    assert np.abs(runs["rate"].mu - mu).max() <= steps * 1e-13 * (1.0 + np.abs(mu).max())
    gap = max(chain.constraint_residual(spec, s)[0]
              for s in hpgen_chain.from_hpgen(spec, runs["rate"].g, runs["rate"].xi(), "centre"))
    assert gap <= 1e-12
