"""The stop tests of a sparse Newton matrix's full Newton (hpgen.runtime.newton_sparse, the C
runtime's hpgen_newton_sparse): the round-off stall follows the noise of the problem, not a
fixed floor, and a chord iteration within the step (one J a step) converges on the pendulum
chain at 32 and 64 links (its pin frames put the noise of dz at 2e-11 .. 5e-11 (1 + |z|),
above the fixed ROUNDOFF_FLOOR, where the chord without the stall test stalled).

The synthetic problem: F(z) = A z - b + noise, A tridiagonal (diagonally dominant, so the
exact solution is A^{-1} b and J = A), the noise uniform in [-s, s] per entry and call: the
attainable accuracy is |A^{-1}| s, and Newton's corrections after the first are noise of that
size with ratios of order one. A stop test that ends there leaves an error of that size; one
with a fixed floor below it never ends.
"""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.abi import NO_CONVERGENCE, OK, ROUNDOFF_FLOOR, STALL_MAX, THETA_MAX
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime.newton import Kernels, NewtonMemory, NewtonOptions, solve
from hpgen.runtime.newton_sparse import solve_pass, solve_sparse, stalled

from conftest import EXAMPLES

NZ = 24


def noisy_linear(rel: float, seed: int = 1):
    """(Kernels of F(z) = A z - b + noise with A's sparse pattern, exact solution, the noise's
    bound s = rel (1 + |z*|))."""
    rng = np.random.default_rng(seed)
    A = (np.diag(4.0 + rng.random(NZ)) + np.diag(rng.random(NZ - 1), 1)
         + np.diag(rng.random(NZ - 1), -1))
    b = 10.0 * rng.standard_normal(NZ)
    scale = rel * (1.0 + np.abs(np.linalg.solve(A, b)).max())
    rows, colind = [], [0]
    for j in range(NZ):
        rows += [i for i in range(NZ) if A[i, j] != 0.0]
        colind.append(len(rows))
    Jflat = A.ravel(order="F").tolist()

    def residual(z, g, p, hv):
        return [(A @ np.asarray(z) - b + scale * rng.uniform(-1, 1, NZ)).tolist()]

    def residual_jacobian(z, g, p, hv):
        return residual(z, g, p, hv)[0], Jflat
    kern = Kernels(NZ, residual, lambda *a: [Jflat], residual_jacobian,
                   pattern=(colind, rows))
    return kern, np.linalg.solve(A, b), scale


@pytest.mark.parametrize("chord", [True, False])
@pytest.mark.parametrize("rel", [1e-14, 1e-12, 1e-11, 1e-10, 3e-10])
def test_the_stall_follows_the_noise(rel, chord):
    """Noise rel (1 + |z*|) in F, rel from 1e-14 to 3e-10: converged within a few iterates,
    the error left at the noise's level (|A^{-1}|_inf <= 1/3 times the noise bound, times 10:
    the last correction's size is random)."""
    kern, exact, scale = noisy_linear(rel)
    z0 = (exact + 1e-3).tolist()
    code, z, it, _, jacs = solve_sparse(kern, z0, [], [], [1e-3], 1e-14, 50, chord=chord)
    assert code == OK and it <= 6
    assert jacs == (1 if chord else it)
    err = np.abs(np.asarray(z) - exact).max()
    assert err <= 10 * scale / 3.0


def test_a_fixed_floor_does_not_end_above_it():
    """The same problem with noise 3e-10 (1 + |z*|) under simplified Newton's stops (the fixed
    ROUNDOFF_FLOOR and tol, no stall test) never ends: the case the stall test is for."""
    assert 3e-10 > ROUNDOFF_FLOOR * 10
    kern, exact, _ = noisy_linear(3e-10)
    code, *_ = solve(kern, (exact + 1e-3).tolist(), [], [], [1e-3],
                     NewtonOptions(simplified=True, maxit=30), NewtonMemory())
    assert code == NO_CONVERGENCE


def test_noise_above_the_cap_is_no_convergence():
    """Noise 10 STALL_MAX (1 + |z*|) in F: the chord pass does not take it for round-off
    (NO_CONVERGENCE, not a result with an error of that size); the second pass (J at every
    iterate) stops only where its correction is below the cap."""
    kern, exact, _ = noisy_linear(10 * STALL_MAX)
    z0 = (exact + 1e-3).tolist()
    code, *_ = solve_pass(kern, z0, [], [], [1e-3], 1e-14, 30, True)
    assert code == NO_CONVERGENCE
    code, z, it, _, jacs = solve_sparse(kern, z0, [], [], [1e-3], 1e-14, 30)
    assert jacs > 1 and it > 30                    # both passes ran
    if code == OK:
        assert np.abs(np.asarray(z) - exact).max() <= 10 * STALL_MAX * (1 + np.abs(exact).max())


def test_a_failed_chord_pass_is_repeated_with_j_at_every_iterate():
    """The chord pass's J at the start is poor (a fifth of the true one, as at a bad predictor
    start): its first correction leaves F's domain (|z| > 1e3: F not finite) and the pass fails
    at its second iterate; the second pass from the same start, with J at every iterate (the
    true one), converges. Iterations and J evaluations of both passes are counted."""
    kern0, exact, _ = noisy_linear(0.0)
    A = np.asarray(kern0.jacobian(None, None, None, None)[0]).reshape(NZ, NZ, order="F")
    calls = []

    def residual(z, g, p, hv):
        z = np.asarray(z)
        F = A @ z - A @ exact
        return [(F if np.abs(z).max() <= 1e3 else F * np.nan).tolist()]

    def residual_jacobian(z, g, p, hv):
        calls.append(1)
        J = A / 5.0 if len(calls) == 1 else A
        return residual(z, g, p, hv)[0], J.ravel(order="F").tolist()
    rows, colind = [], [0]
    for j in range(NZ):
        rows += np.flatnonzero(A[:, j]).tolist()
        colind.append(len(rows))
    kern = Kernels(NZ, residual, None, residual_jacobian, pattern=(colind, rows))
    z0 = (exact + 300.0).tolist()
    code, *_ = solve_pass(kern, z0, [], [], [1e-3], 1e-14, 30, True)
    assert code != OK
    calls.clear()
    code, z, it, _, jacs = solve_sparse(kern, z0, [], [], [1e-3], 1e-14, 30)
    assert code == OK and np.abs(np.asarray(z) - exact).max() <= 1e-10 * np.abs(exact).max()
    assert jacs == len(calls) >= 2 and it >= 3


def test_a_stall_above_the_cap_or_without_contraction_is_not_noise():
    s = 1.0 + 2.0                                  # 1 + |z| with |z| = 2
    assert stalled(2, 0.5 * STALL_MAX * s, 0.5 * STALL_MAX * s, 2.0, True, False)
    assert not stalled(2, 2 * STALL_MAX * s, 2 * STALL_MAX * s, 2.0, True, True)
    assert not stalled(3, 1e-12, 1e-12, 2.0, False, False)   # a kept J that never contracted
    assert stalled(3, 1e-12, 1e-12, 2.0, False, True)
    assert not stalled(3, THETA_MAX * 1e-12, 1e-12, 2.0, True, True)   # still contracting
    assert not stalled(1, 1e-12, float("inf"), 2.0, True, True)


def chain_starts(n):
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
    return {"example": (np.eye(4 * n), np.tile([3.0, 1.0, 0.5, 0, 0, 0], n)),
            "slow": (np.eye(4 * n), np.tile([0.3, 0.1, 0.05, 0, 0, 0], n)),
            "random": (g0, xi0)}


def run_starts(n, steps, cache_dir):
    integ = hpgen.compile(EXAMPLES / "pendulum_chain.yaml", parameters={"N": n},
                          cache_dir=cache_dir)
    for name, (g0, xi0) in chain_starts(n).items():
        run = integ.simulate(g0, 1e-3, steps, xi0=xi0, every=steps // 10)
        assert run.error is None, (name, run.error)
        # one J a step (the chord); the predictor's start takes 3-5 iterates to the noise
        assert run.jacobians == steps, name
        assert run.newton_iterations <= 5 * steps, name


def test_chord_on_the_chain_at_32_links(cache_dir):
    """The three starts (the example's scene, a slow one, random joint velocities)."""
    run_starts(32, 300, cache_dir)


@pytest.mark.slow
@pytest.mark.parametrize("n", [32, 64])
def test_chord_on_the_chain_over_2000_steps(n, cache_dir):
    run_starts(n, 2000, cache_dir)


@pytest.mark.slow
def test_python_backend_the_same_iteration_at_32_links(cache_dir):
    """The Python backend (SuperLU) takes the same chord and stops: one J a step, the same
    states to the noise over 20 steps of the example's scene (the noise of a step's solution
    is about 2e-11 (1 + |z|) at 32 links; 1e-10 (1 + |mu|) a step allows 5 times that)."""
    runs = {}
    for backend in ("c", "python"):
        integ = hpgen.compile(EXAMPLES / "pendulum_chain.yaml", parameters={"N": 32},
                              backend=backend, cache_dir=cache_dir)
        runs[backend] = integ.simulate(np.eye(128), 1e-3, 20,
                                       xi0=np.tile([3.0, 1.0, 0.5, 0, 0, 0], 32))
    assert runs["python"].error is None and runs["python"].jacobians == 20
    mu = runs["c"].mu
    assert np.abs(runs["python"].mu - mu).max() <= 20 * 1e-10 * (1 + np.abs(mu).max())


def test_velocity_from_momentum_at_32_links(cache_dir):
    """Integrator.step from (g, mu) inverts the Legendre map by full Newton (dense,
    hpgen.runtime.newton.newton): at 32 links its corrections' noise is above the fixed
    floor, and the stall stop ends it (at d724a98 the state after 150 steps of the example's
    scene raised ConvergenceError after 50 iterations)."""
    integ = hpgen.compile(EXAMPLES / "pendulum_chain.yaml", parameters={"N": 32},
                          cache_dir=cache_dir)
    run = integ.simulate(np.eye(128), 1e-3, 200, xi0=np.tile([3.0, 1.0, 0.5, 0, 0, 0], 32),
                         every=50)
    for g, mu in zip(run.g, run.mu):
        g1, mu1 = integ.step(g, mu, 1e-3)
        assert np.isfinite(mu1).all()


def test_a_sparse_modules_record_velocity_stops_at_the_noise():
    """The record's velocity (Newton on the Legendre map from xi = 0, hpgen_velocity) of an
    ill-conditioned family lands at the solution plus noise above the fixed floor (here
    alternating +-1e-9): the fixed tests never end (a NaN record: the pendulum chain at 48
    links did this at step 0); with the stall (sparse modules) it stops at the noise."""
    from hpgen.abi import RECORD, ROUNDOFF_FLOOR, VELOCITY_TOL
    from hpgen.runtime.record_row import velocity
    exact = np.linspace(-10.0, 10.0, 12)
    assert 2e-9 > max(ROUNDOFF_FLOOR, VELOCITY_TOL) * 11.0
    calls = []

    def step(g, p, xi):
        calls.append(1)
        return [(exact + (-1) ** len(calls) * 1e-9).tolist()]
    code, _ = velocity(step, None, exact.tolist(), False)
    assert code == RECORD
    calls.clear()
    code, xi = velocity(step, None, exact.tolist(), False, stall=True)
    assert code == OK and len(calls) == 3 and np.abs(np.asarray(xi) - exact).max() <= 1.01e-9
