"""The derive stage's eliminations solve the same equations as the uneliminated systems.

A tableau whose rows are multiples of b (Stormer-Verlet, midpoint, Euler) with q = 0 and a
g-independent Legendre map is reduced to one common stage velocity X (d unknowns,
derive.action._common_velocity_step). Its solution,
repeated in every stage, must be a root of the s d stage-velocity system the general
truncated path solves, and both must give the same (g_{k+1}, p_{k+1}).
"""
from pathlib import Path

import casadi as ca
import numpy as np
import pytest

from hpgen.derive import action
from hpgen.derive.lagrangian import lagrangian_function
from hpgen.model import load_model
from hpgen.tableaus import get_tableau

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _equations(model, tableau, common_allowed: bool, monkeypatch):
    if not common_allowed:
        monkeypatch.setattr(action, "_rows_proportional_to_b", lambda A, b: False)
    group = model.group
    g = ca.SX.sym("g", group.n, group.n)
    p, h = ca.SX.sym("p", group.d), ca.SX.sym("h", 1)
    eqs = action.step_equations(group, lagrangian_function(model), tableau, "cay",
                                "truncated", False, g, p, h)
    monkeypatch.undo()
    args = [g, p, h]
    F = ca.Function("F", [eqs.z] + args, [eqs.residual, ca.jacobian(eqs.residual, eqs.z)])
    U = ca.Function("U", [eqs.z] + args, [eqs.g1, eqs.p1])
    return eqs.z.numel(), F, U


def _solve(F, z, g, p, h):
    for _ in range(50):
        r, J = (np.array(v) for v in F(z, g, p, h))
        dz = np.linalg.solve(J, r.ravel())
        z = z - dz
        if np.max(np.abs(dz)) <= 1e-15 * (1 + np.max(np.abs(z))):
            break
    return z


@pytest.mark.parametrize("name", ["stormer-verlet", "midpoint", "euler-forward",
                                  "euler-backward"])
@pytest.mark.parametrize("h", [0.01, 0.2])
def test_common_velocity_is_a_root_of_the_stage_system(name, h, monkeypatch):
    model = load_model(EXAMPLES / "heavy_top.yaml")
    tab = get_tableau(name)
    nz1, F1, U1 = _equations(model, tab, True, monkeypatch)
    nz2, F2, U2 = _equations(model, tab, False, monkeypatch)
    d = model.group.d
    assert (nz1, nz2) == (d, tab.stages * d)
    rng = np.random.default_rng(3)
    w = rng.normal(size=3)
    # a rotation from Rodrigues' formula (no casadi.expm needed)
    th = np.linalg.norm(w)
    K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]) / th
    g = np.eye(3) + np.sin(th) * K + (1 - np.cos(th)) * K @ K
    p = np.array([0.7, 4.0, 18.0])
    X = _solve(F1, p / np.array([1.0, 5.0, 6.0]), g, p, h)
    assert np.max(np.abs(np.array(F1(X, g, p, h)[0]))) < 1e-13
    # the common solution solves the s d Legendre conditions (round-off of |p| ~ 20)
    Z = np.tile(X, tab.stages)
    assert np.max(np.abs(np.array(F2(Z, g, p, h)[0]))) < 1e-13 * np.max(np.abs(p))
    # and Newton on the stage system from elsewhere finds it (the root is isolated)
    Z2 = _solve(F2, Z + 1e-3 * rng.normal(size=Z.size), g, p, h)
    assert np.max(np.abs(Z2 - Z)) < 1e-13 * (1 + np.max(np.abs(Z)))
    for a, b in zip(U1(X, g, p, h), U2(Z2, g, p, h)):
        assert np.max(np.abs(np.array(a) - np.array(b))) < 1e-13 * (1 + np.max(np.abs(p)))


def test_g_dependent_legendre_keeps_the_stage_velocities(monkeypatch):
    # turntable: l has xi + w0 R^T e3 in the kinetic term, so dl/dxi depends on R
    model = load_model(EXAMPLES / "turntable.yaml")
    nz, _, _ = _equations(model, get_tableau("stormer-verlet"), True, monkeypatch)
    assert nz == 2 * model.group.d
