"""hpgen.ocp.rest_to_rest: the worked optimal control example (issue 12 item 3,
examples/spacecraft_rest_to_rest.py).

- Principal-axis slew: the discrete optimum converges to the closed-form continuous optimum
  (theta = theta_f (3 s^2 - 2 s^3), torque I3 theta'') at order 2 (Stormer-Verlet's order;
  the zero-order-hold inputs cap any tableau at 2), in the torque at the step midpoints, the
  angle at the nodes and the cost: observed orders over h = 0.2 .. 0.025 within 0.1 of 2
  (measured 1.97-2.01); the off-axis torques vanish (<= 1e-9: IPOPT's tolerance 1e-12 times
  the problem's conditioning). gauss2 converges at its order 4 to the exact optimum among
  held inputs (the same discrete-time problem without the scheme's error).
- Three-axis slew: the planned inputs re-simulated by ``simulate`` (full Newton, tolerance
  1e-14) reproduce the planned states to 1e-9 (the plan satisfies the step to IPOPT's
  1e-12, amplified by at most the 40 steps' growth), torques on all three axes.
- Bad input: a model without inputs, a wrong g0, steps: one-line ArgumentError.
"""
from __future__ import annotations

import importlib.util

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.errors import ArgumentError

_spec = importlib.util.spec_from_file_location("spacecraft_rest_to_rest",
                                               EXAMPLES / "spacecraft_rest_to_rest.py")
ex = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ex)


@pytest.fixture(scope="module")
def integ(compile_model):
    return compile_model(ex.MODEL, tableau="stormer-verlet", tau="cay", rkmk="exact")


def _orders(integ, steps):
    """Observed orders (rows: consecutive halvings of h) of the five errors of
    ex.principal_axis_errors."""
    errs = np.array([r[2:7] for r in ex.convergence_table(integ, steps=steps)])
    return np.log2(errs[:-1] / errs[1:])


def test_principal_axis_slew_converges_at_order_two(integ):
    """Stormer-Verlet: all errors at order 2 (against the continuous optimum over
    h = 0.2 .. 0.025, measured 1.97-2.01)."""
    orders = _orders(integ, (10, 20, 40, 80))
    assert np.all(np.abs(orders[:, :3] - 2.0) <= 0.1), orders
    plan = ex.principal_axis_errors(integ, 20)[0]
    assert np.abs(plan.u[:, :2]).max() <= 1e-9
    assert plan.status == "Solve_Succeeded"


def test_gauss2_slew_converges_at_the_schemes_order(compile_model):
    """gauss2 (order 4): against the continuous optimum order 2 (the held inputs' cap),
    against the exact held-input optimum order 4 (h = 0.1 .. 0.025: measured 1.97-2.01 and
    3.89-4.11)."""
    integ = compile_model(ex.MODEL, tableau="gauss2", tau="cay", rkmk="exact")
    orders = _orders(integ, (20, 40, 80))
    assert np.all(np.abs(orders[:, :3] - 2.0) <= 0.1), orders
    assert np.all(np.abs(orders[:, 3:] - 4.0) <= 0.2), orders


def test_three_axis_plan_resimulates(integ):
    plan, traj = ex.three_axis(integ)
    assert np.abs(traj.g - plan.g).max() <= 1e-9
    assert np.abs(traj.mu - plan.mu).max() <= 1e-9
    assert np.abs(plan.mu[[0, -1]]).max() <= 1e-12            # at rest at both ends
    assert np.abs(plan.g[-1] - ex.rotation([1.0, -2.0, 2.0], 2.0)).max() <= 1e-12
    assert np.all(np.abs(plan.u).max(axis=0) > 0.1)           # all three axes actuated


def test_rest_to_rest_bad_input(integ, compile_model):
    from hpgen.ocp import rest_to_rest
    closed = compile_model(ex.MODEL.replace("inputs: [u0, u1, u2]\n", "")
                           .replace("forces: [u0, u1, u2]\n", ""), backend="python")
    cases = ((closed, np.eye(3), 2, "integ"), (integ, np.eye(2), 10, "g0"),
             (integ, np.eye(3), 1, "steps"))
    for model, g0, steps, field in cases:
        with pytest.raises(ArgumentError) as e:
            rest_to_rest(model, g0, np.eye(3), 1.0, steps)
        assert e.value.field == field and "\n" not in str(e.value)


def test_rest_to_rest_says_when_ipopt_cannot_start(integ, monkeypatch):
    """CasADi 3.6.0's wheels load IPOPT only beside a system libgfortran: a solver that does
    not start is a one-line HpgenError that says so, not CasADi's RuntimeError from stats."""
    import casadi as ca

    from hpgen.errors import HpgenError
    from hpgen.ocp import rest_to_rest
    solver = ca.Opti.solver
    monkeypatch.setattr(ca.Opti, "solver",
                        lambda self, name, *a: solver(self, "no_such_nlp_plugin", *a))
    with pytest.raises(HpgenError, match="CasADi could not start IPOPT") as e:
        rest_to_rest(integ, np.eye(3), np.eye(3), 1.0, 10)
    assert "\n" not in str(e.value) and not isinstance(e.value, ArgumentError)
