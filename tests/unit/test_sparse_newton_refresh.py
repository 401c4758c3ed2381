"""A sparse module's simplified Newton (J kept across steps; hpgen.runtime.newton.solve, the C
runtime's hpgen_newton with HPGEN_SIMPLIFIED_REFRESH): a step that converged with a J kept
from earlier steps alone in more than KEPT_J_ITERATES iterates drops that J (the next step
evaluates J at its first iterate), and a J evaluated in the step stops on the chord's rate
bound (newton_sparse.chord_converged) instead of the floored bound of a J kept across steps.

The synthetic problem is test_sparse_newton_rate_stop's F(z) = A z + c z^2 - b (A tridiagonal,
diagonally dominant) with its root to the last bit; a J kept "from an earlier step" is the
factorization of J(root) scaled by 1 + eps, whose rate is about eps.
"""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.abi import OK
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime import newton
from hpgen.runtime.newton import KEPT_J_ITERATES, NewtonMemory, NewtonOptions, solve
from hpgen.runtime.newton_sparse import solve_pass

from conftest import EXAMPLES
from test_sparse_newton_rate_stop import NZ, TOL, quadratic_problem

SIMPLIFIED = NewtonOptions(simplified=True)


def kept_factors(kern, root, eps):
    """The factors of (1 + eps) J(root), as a J kept from an earlier step."""
    J = (1.0 + eps) * np.asarray(kern.jacobian(root.tolist(), [], [], [1e-3])[0])
    return kern.linear.factor_solve(J.tolist(), [0.0] * NZ, True)[1]


def start(root, offset):
    return (root + offset * np.cos(np.arange(NZ))).tolist()


@pytest.mark.parametrize("refresh", [True, False])
def test_a_slow_kept_j_is_dropped_after_the_step(refresh, monkeypatch):
    """A kept J with rate 1e-2 from 1e-6 off: the step converges (error within tol (1 + |z|))
    on the kept J alone in more than KEPT_J_ITERATES iterates; the J is dropped, unless
    SIMPLIFIED_REFRESH is off."""
    monkeypatch.setattr(newton, "SIMPLIFIED_REFRESH", refresh)
    kern, root = quadratic_problem()
    memory = NewtonMemory()
    memory.lu = lu = kept_factors(kern, root, 1e-2)
    code, z, it, _, jacs = solve(kern, start(root, 1e-6), [], [], [1e-3], SIMPLIFIED, memory)
    assert code == OK and jacs == 0 and it > KEPT_J_ITERATES
    assert np.abs(np.asarray(z) - root).max() <= TOL * (1.0 + np.abs(root).max())
    assert (memory.lu is None) if refresh else (memory.lu is lu)


def test_a_fast_kept_j_is_kept():
    """A kept J with rate 1e-8 from 1e-6 off: converged within KEPT_J_ITERATES iterates, the
    same factors kept for the next step."""
    kern, root = quadratic_problem()
    memory = NewtonMemory()
    memory.lu = lu = kept_factors(kern, root, 1e-8)
    code, z, it, _, jacs = solve(kern, start(root, 1e-6), [], [], [1e-3], SIMPLIFIED, memory)
    assert code == OK and jacs == 0 and it <= KEPT_J_ITERATES
    assert memory.lu is lu
    assert np.abs(np.asarray(z) - root).max() <= TOL * (1.0 + np.abs(root).max())


@pytest.mark.parametrize("offset", [1e-4, 1e-5, 1e-6])
def test_a_j_of_the_step_stops_as_the_chord(offset, monkeypatch):
    """No kept J (the run's first step, or one after a drop): J at the step's first iterate,
    and the iterates stop where the chord (newton_sparse.solve_pass) stops, with the error
    within tol (1 + |z|); without SIMPLIFIED_REFRESH they take no fewer (one more where the
    second correction is at the noise but not below the floored bound)."""
    kern, root = quadratic_problem()
    z0 = start(root, offset)
    code, z, it, _, jacs = solve(kern, z0, [], [], [1e-3], SIMPLIFIED, NewtonMemory())
    chord = solve_pass(kern, z0, [], [], [1e-3], TOL, 30, True)
    assert code == OK and jacs == 1 and it == chord[2]
    assert np.abs(np.asarray(z) - root).max() <= TOL * (1.0 + np.abs(root).max())
    monkeypatch.setattr(newton, "SIMPLIFIED_REFRESH", False)
    _, _, it_old, _, _ = solve(kern, z0, [], [], [1e-3], SIMPLIFIED, NewtonMemory())
    assert it_old >= it


@pytest.fixture(scope="module")
def chain_runs(cache_dir):
    """Simplified Newton on the capsule chain (N = 4, random joint velocities, 300 steps of
    2e-3): C, C built with -DHPGEN_SIMPLIFIED_REFRESH=0, Python."""
    n, steps = 4, 300
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), "centre")
    runs = {}
    for key, backend, flags in (("c", "c", None), ("old", "c", ["-DHPGEN_SIMPLIFIED_REFRESH=0"]),
                                ("python", "python", None)):
        integ = hpgen.compile(EXAMPLES / "capsule_chain.yaml", parameters={"N": n},
                              cache_dir=cache_dir, cflags=flags, backend=backend)
        runs[key] = integ.simulate(g0, 2e-3, steps, xi0=xi0, every=10, newton=SIMPLIFIED)
        assert runs[key].error is None
    return spec, steps, runs


def test_the_chain_in_c_and_python(chain_runs):
    """Fewer iterates than without the rule, more J (but well under one a step); Python's
    Newton the same as C's up to round-off in the stop decisions (the iterations and J
    within 5 %); the states agree to the round-off of 300 steps and the joints stay closed."""
    spec, steps, runs = chain_runs
    c, old, py = runs["c"], runs["old"], runs["python"]
    assert c.newton_iterations < old.newton_iterations
    assert old.jacobians <= c.jacobians < 0.7 * steps
    assert abs(py.newton_iterations - c.newton_iterations) <= 0.05 * c.newton_iterations
    assert abs(py.jacobians - c.jacobians) <= 0.05 * c.jacobians + 1
    mu = old.mu
    for r in (c, py):
        assert np.abs(r.mu - mu).max() <= steps * 1e-13 * (1.0 + np.abs(mu).max())
    gap = max(chain.constraint_residual(spec, s)[0]
              for s in hpgen_chain.from_hpgen(spec, c.g, c.xi(), "centre"))
    assert gap <= 1e-12
