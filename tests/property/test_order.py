"""Observed order of convergence against an independent DOP853 reference (rtol 2.5e-14).

Error = max(|g_N - g(T)|, |p_N - mu(T)|) with p_N the node momentum (docs/numerics.md sec. 4).
The observed order is log2(e(h) / e(h/2)) on the two finest step sizes; it must be within
0.25 of the scheme's order: the leading error term dominates there (measured: the finest
pair is within 0.07 of the order for every case, and moves towards it from the previous
pair), and a wrong order is off by at least 1.

The matrix comes from the registry (hpgen.schemes): every catalog tableau x every RKMK
constraint x every chart map the heavy top's group (SO3) supports, each against the order
the tableau carries, capped by the RKMK constraint (truncated: 2). A new tableau, chart or
constraint is tested by registering it. Step sizes by the scheme's order p:
- p = 1 (variational Euler): a large second-order error term on this fast top makes the
  observed order 1.2-2.7 (or even negative, where the first- and second-order terms
  cancel) for h in [0.001, 0.004]; it settles to 1 +- 0.1 for h <= 5e-4 with exp and cay,
  and only for h <= 1.25e-4 with skew (measured: 0.86-1.05 on the pair 1.25e-4 / 6.25e-5,
  0.93-1.01 on 6.25e-5 / 3.125e-5), so every order-1 scheme is tested there (32000 steps,
  a few hundredths of a second in C);
- p <= 4: h = 0.1, 0.05, 0.025 (errors 1e-2 .. 1e-7);
- p = 6: the errors fall by 64 per halving, so h = 0.05, 0.025, 0.0125 keeps the finest
  error at 1e-12, where the leading term dominates (skew: 5.69 on 0.05 / 0.025, 5.94 on
  0.025 / 0.0125) and the reference's own error, 1.5e-14 (measured against rtol 1e-13 and
  1e-12 solutions, it scales linearly with rtol), moves the observed order by < 0.03.
A scheme of another order needs its step sizes chosen here (the module refuses to guess).
The SE3 body (a non-reduced step: the potential depends on R and x) is tested on a fixed
list: its 6th-order kernels take 25-140 s to compile.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import HEAVY_TOP, SE3_BODY
from hpgen import schemes
from reference import SE3Problem, SO3Problem, reference, rotvec

TOP = SO3Problem([1.0, 5.0, 6.0], Mg=1.0)
TOP_G0, TOP_W0 = rotvec([0.3, 0.2, 0.0]), np.array([0.2, 1.0, 3.0])
BODY = SE3Problem([2.0, 1.0, 2.0 / 3.0], [1.0, 1.5, 3.0], Mg=0.5, k=0.3)
BODY_G0 = np.eye(4)
BODY_G0[:3, :3], BODY_G0[:3, 3] = rotvec([0.1, -0.2, 0.3]), [0.2, 0.0, -0.1]
BODY_W0 = np.array([0.3, 0.5, 0.4, 0.5, 0.2, -0.3])
REFERENCE_RTOL = 2.5e-14      # just above SciPy's floor for DOP853 (2.2e-14)

COARSE = (0.1, 0.05, 0.025)
STEP_SIZES = {1: (1.25e-4, 6.25e-5, 3.125e-5), 2: COARSE, 4: COARSE,
              6: (0.05, 0.025, 0.0125)}


def _step_sizes(order):
    if order not in STEP_SIZES:
        raise ValueError(f"no step sizes chosen for a scheme of order {order}: add them to "
                         "STEP_SIZES in tests/property/test_order.py (see the module doc)")
    return STEP_SIZES[order]


def _registry_cases():
    """(problem, tableau, tau, rkmk, order, step sizes) for every registered combination
    on the heavy top."""
    for tab in schemes.tableaus():
        for rk in schemes.RKMK.entries:
            for tau in schemes.charts_on("SO3"):
                order = rk.order(tab.order)
                yield ("top", tab.name, tau, rk.name, order, _step_sizes(order))


CASES = [  # (problem, tableau, tau, rkmk, expected order, step sizes)
    *_registry_cases(),
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
        _REF[(id(problem), T)] = reference(problem, g0, mu0, [T], rtol=REFERENCE_RTOL)
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
