"""A sparse module's full Newton as a chord iteration within the step (hpgen_newton_chord in
hpgen/runtime/c/hpgen_newton.c, hpgen.runtime.newton_chord) against J at every iterate (the
same module built with -DHPGEN_SPARSE_CHORD=0) on the pendulum chain.

Tolerances: both stop at Newton's round-off level (full Newton: |dz| <= 1e-14 (1 + |z|);
the chord's kept J: an error estimate 100 times below that), so two runs differ by a few
1e-14 per step, at most 500 * 1e-13 = 5e-11 over 500 steps (test_sparse_newton's bound). A
chord that stopped early (error tol (1 + |z|) per step) or a wrong kept factorization gives
far larger differences.
"""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.runtime.newton import NewtonOptions

from conftest import EXAMPLES
from test_sparse_newton import chain_scene, max_deviation

CHAIN = EXAMPLES / "pendulum_chain.yaml"
STEPS = 500
TOL = STEPS * 1e-13
FULL = NewtonOptions(simplified=False)


@pytest.fixture(scope="module")
def built(cache_dir):
    made = {}

    def get(backend="c", cflags=None):
        key = (backend, cflags)
        if key not in made:
            made[key] = hpgen.compile(CHAIN, parameters={"N": 2}, jacobian="sparse",
                                      backend=backend, cache_dir=cache_dir, cflags=cflags)
        return made[key]
    return get


@pytest.mark.parametrize("backend", ["c", "python"])
def test_chord_agrees_with_newton_at_one_jacobian_a_step(built, backend):
    sc = chain_scene(2)
    ref = built("c", ("-DHPGEN_SPARSE_CHORD=0",)).simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0,
                                                           newton=FULL)
    run = built(backend).simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, newton=FULL)
    assert ref.error is None and run.error is None and len(run.t) == STEPS + 1
    assert max_deviation(run.g, ref.g) <= TOL and max_deviation(run.mu, ref.mu) <= TOL
    # J at every iterate takes two (J, LU) a step; the chord one, its later iterates a
    # residual and a solve each
    assert ref.jacobians == ref.newton_iterations >= 2 * STEPS
    assert run.jacobians <= 1.05 * STEPS
    assert run.jacobians < run.newton_iterations


def test_chord_step_is_deterministic(built):
    sc = chain_scene(2)
    a = built().simulate(sc.g0, sc.h, 50, xi0=sc.xi0, newton=FULL)
    b = built().simulate(sc.g0, sc.h, 50, xi0=sc.xi0, newton=FULL)
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)


def test_chord_refreshes_a_poorly_contracting_j(built):
    """From starts far off (no predictor, steps of 50 h): in some steps J at the start
    contracts poorly and the chord refreshes it (more J than steps), yet the run reaches the
    same solutions as J at every iterate, with fewer J."""
    sc = chain_scene(2)
    opts = NewtonOptions(simplified=False, predictor=False)
    h = 50 * sc.h
    ref = built("c", ("-DHPGEN_SPARSE_CHORD=0",)).simulate(sc.g0, h, 20, xi0=sc.xi0,
                                                           newton=opts)
    run = built().simulate(sc.g0, h, 20, xi0=sc.xi0, newton=opts)
    assert ref.error is None and run.error is None
    assert max_deviation(run.g, ref.g) <= 20 * 1e-13
    assert 20 < run.jacobians < ref.jacobians
