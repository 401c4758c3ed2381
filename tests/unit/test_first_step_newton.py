"""A run's first step takes the run's Newton: with simplified Newton one fresh J for the
iterates of the first step (hpgen_run_step, hpgen.runtime.loop._run_step), the later steps'
stop test, and full Newton from the same start where simplified Newton fails there. C and
Python bitwise equal; the fallback gives the full-Newton first step with both tries'
counters."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hpgen.model import load_model
from hpgen.runtime import NewtonOptions

ROOT = Path(__file__).resolve().parents[2]
HEAVY_TOP = ROOT / "examples" / "heavy_top.yaml"
GAUSS3 = {"tableau": "gauss3", "tau": "cay", "rkmk": "exact"}


@pytest.fixture(scope="module")
def scene():
    return load_model(str(HEAVY_TOP)).scene


@pytest.fixture(scope="module", params=["c", "python"])
def top(request, compile_model):
    return compile_model(HEAVY_TOP, backend=request.param, **GAUSS3)


def _run(integ, scene, steps, **newton):
    return integ.simulate(scene.g0, scene.h, steps, xi0=scene.xi0,
                          newton=NewtonOptions(**newton))


def test_first_step_simplified_one_jacobian(top, scene):
    """Simplified: one J for the whole first step (more, cheaper iterations); full: a J at
    every iterate. Both reach the same step to the Newton tolerance."""
    simp, full = _run(top, scene, 1, simplified=True), _run(top, scene, 1, simplified=False)
    assert simp.error is None and full.error is None
    assert simp.jacobians == 1 < simp.newton_iterations
    assert full.jacobians == full.newton_iterations > 1
    np.testing.assert_allclose(simp.mu[-1], full.mu[-1], rtol=0, atol=1e-13)
    np.testing.assert_allclose(simp.g[-1], full.g[-1], rtol=0, atol=1e-13)


def test_first_step_keeps_its_jacobian(top, scene):
    """The first step's J is the second step's Newton matrix: two steps, one J (the
    contraction stays below the refresh threshold at the heavy top's h)."""
    two = _run(top, scene, 2, simplified=True)
    assert two.error is None and two.jacobians == 1


def test_fallback_to_full_newton(top, scene):
    """maxit = 4: simplified Newton does not converge in 4 iterations at the first step, full
    Newton does; the run's first step is then the full-Newton one bitwise, its counters both
    tries' (4 + 4 iterations, 1 + 4 Jacobians)."""
    simp = _run(top, scene, 1, simplified=True, maxit=4)
    full = _run(top, scene, 1, simplified=False, maxit=4)
    assert simp.error is None and full.error is None
    assert np.array_equal(simp.mu, full.mu) and np.array_equal(simp.g, full.g)
    assert (simp.newton_iterations, simp.jacobians) == (4 + full.newton_iterations,
                                                        1 + full.jacobians)


def test_c_and_python_bitwise(compile_model, scene):
    """A simplified run from its first step on, and a first step by the fallback: both
    backends give the same bits and counters."""
    c, py = (compile_model(HEAVY_TOP, backend=b, **GAUSS3) for b in ("c", "python"))
    for newton, steps in (({"simplified": True}, 20), ({"simplified": True, "maxit": 4}, 1)):
        a, b = _run(c, scene, steps, **newton), _run(py, scene, steps, **newton)
        assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
        assert (a.newton_iterations, a.jacobians) == (b.newton_iterations, b.jacobians)
