"""Observed order of convergence against an independent DOP853 reference (rtol 1e-12).

Error = max(|g_N - g(T)|, |p_N - mu(T)|) with p_N the node momentum (math.md sec. 2).
The observed order is log2(e(h) / e(h/2)) on the two finest step sizes; it must be within
0.25 of the theoretical order: the leading error term dominates there (checked: the
observed orders of the two successive pairs agree to about 0.1), and a wrong order is off
by at least 1. Variational Euler has a large second-order error term on this fast top:
its observed order is 1.2-2.7 (or even negative, where the first- and second-order terms
cancel) for h in [0.001, 0.004] and settles to 1 +- 0.1 only for h <= 5e-4, measured for
both maps and both Euler tableaus, so it is tested there.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import HEAVY_TOP, SE3_BODY
from reference import SE3Problem, SO3Problem, reference, rotvec

TOP = SO3Problem([1.0, 5.0, 6.0], Mg=1.0)
TOP_G0, TOP_W0 = rotvec([0.3, 0.2, 0.0]), np.array([0.2, 1.0, 3.0])
BODY = SE3Problem([2.0, 1.0, 2.0 / 3.0], [1.0, 1.5, 3.0], Mg=0.5, k=0.3)
BODY_G0 = np.eye(4)
BODY_G0[:3, :3], BODY_G0[:3, 3] = rotvec([0.1, -0.2, 0.3]), [0.2, 0.0, -0.1]
BODY_W0 = np.array([0.3, 0.5, 0.4, 0.5, 0.2, -0.3])

COARSE = (0.1, 0.05, 0.025)
FINE = (0.0005, 0.00025, 0.000125)

CASES = [  # (problem, tableau, tau, rkmk, expected order, step sizes)
    *[("top", "euler-forward", tau, "truncated", 1, FINE) for tau in ("exp", "cay")],
    *[("top", "euler-backward", tau, "truncated", 1, FINE) for tau in ("exp", "cay")],
    *[("top", "stormer-verlet", tau, rk, 2, COARSE) for tau in ("exp", "cay")
      for rk in ("truncated", "exact")],
    *[("top", tab, tau, "truncated", 2, COARSE) for tab in ("midpoint", "gauss2", "lobatto3a3")
      for tau in ("exp", "cay")],
    *[("top", tab, tau, "exact", 4, COARSE) for tab in ("gauss2", "lobatto3a3")
      for tau in ("exp", "cay")],
    ("se3", "stormer-verlet", "cay", "truncated", 2, COARSE),
    ("se3", "gauss2", "cay", "truncated", 2, COARSE),
    ("se3", "gauss2", "cay", "exact", 4, COARSE),
    ("se3", "lobatto3a3", "cay", "exact", 4, COARSE),
    ("se3", "gauss2", "exp", "exact", 4, COARSE),
]

_REF = {}


def _problem(name):
    if name == "top":
        return HEAVY_TOP, TOP, TOP_G0, TOP.I * TOP_W0
    return SE3_BODY, BODY, BODY_G0, BODY.I * BODY_W0


def observed_orders(integ, problem, g0, mu0, hs, T=1.0):
    if (id(problem), T) not in _REF:
        _REF[(id(problem), T)] = reference(problem, g0, mu0, [T])
    gT, muT = (a[0] for a in _REF[(id(problem), T)])
    errs = []
    for h in hs:
        steps = int(round(T / h))
        tr = integ.simulate(g0=g0, mu0=mu0, h=h, steps=steps, every=steps)
        errs.append(max(np.abs(tr.g[-1] - gT).max(), np.abs(tr.mu[-1] - muT).max()))
    errs = np.array(errs)
    return errs, np.log2(errs[:-1] / errs[1:])


@pytest.mark.parametrize("prob,tableau,tau,rkmk,order,hs", CASES,
                         ids=[f"{c[0]}-{c[1]}-{c[2]}-{c[3]}" for c in CASES])
def test_observed_order(compile_model, prob, tableau, tau, rkmk, order, hs):
    text, problem, g0, mu0 = _problem(prob)
    integ = compile_model(text, tableau=tableau, tau=tau, rkmk=rkmk, backend="c")
    errs, orders = observed_orders(integ, problem, g0, mu0, hs)
    print(f"{prob} {tableau} {tau} {rkmk}: errors {errs} observed orders {orders}")
    assert abs(orders[-1] - order) < 0.25, (errs, orders)
