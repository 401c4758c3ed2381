"""The canonical symplectic form of T*G (hpgen.analysis.symplectic) and the Jacobians it is
applied to.

- R^n (ad = 0): Omega is dq ^ dp, [[0, I], [-I, 0]]; the exact flow of a linear oscillator
  preserves it, its degree-4 Taylor polynomial (RK4) does not.
- SO3: the bracket block is C(p) = -hat(p) (C_ij = p.(e_i x e_j)).
- Exact flows (independent, hand-coded variational equations of Euler's free rigid body; the
  generic ones of hpgen.analysis.rkmk for the heavy top and SE3): defect at round-off with
  BRACKET_SIGN = +1 and O(1) with the opposite sign, which fixes the sign.
- The Jacobian of a generated step by implicit differentiation and that of RKMK-RK4 by AD
  agree with central differences of the steps (the check itself never uses differences).
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.linalg import expm, logm

from conftest import EXAMPLES, HEAVY_TOP, SE3_BODY
from hpgen.analysis.rkmk import RKMK4, ContinuousEquations, hat_basis
from hpgen.analysis.symplectic import (BRACKET_SIGN, GeneratedMap, ad_matrices, omega_matrix,
                                       symplectic_defect)
from hpgen.derive import derive
from hpgen.groups.catalog import group_from_spec
from hpgen.model import load_model
from hpgen.tableaus import get_tableau

from reference import hat3, rotvec

INERTIA = np.array([2.0, 1.0, 2.0 / 3.0])
PI0 = np.array([0.4535961214255773, 0.0, 0.8912073600614354])


def _defect(ad, Phi, p0, p1, sign=BRACKET_SIGN):
    return symplectic_defect(Phi, omega_matrix(ad, p0, sign), omega_matrix(ad, p1, sign))


def test_flat_form_is_canonical():
    ad = ad_matrices(group_from_spec("R3"))
    assert np.abs(ad).max() == 0.0
    J = np.block([[np.zeros((3, 3)), np.eye(3)], [-np.eye(3), np.zeros((3, 3))]])
    p = np.array([0.3, -1.2, 2.0])
    assert np.array_equal(omega_matrix(ad, p), J)
    # q'' = -K q: the exact flow expm(t A) is symplectic, RK4's Taylor polynomial is not
    K = np.array([[2.0, 0.5, 0.0], [0.5, 1.0, 0.2], [0.0, 0.2, 3.0]])
    A = np.block([[np.zeros((3, 3)), np.eye(3)], [-K, np.zeros((3, 3))]])
    h = 0.1
    exact = expm(h * A)
    rk4 = sum(np.linalg.matrix_power(h * A, k) / np.prod(np.arange(1, k + 1)) for k in range(5))
    assert _defect(ad, exact, p, p)[0] < 1e-15
    assert _defect(ad, rk4, p, p)[0] > 1e-7


def test_so3_bracket_block_and_antisymmetry():
    p = np.array([0.7, -0.4, 1.3])
    Om = omega_matrix(ad_matrices(group_from_spec("SO3")), p)
    assert np.allclose(Om[:3, :3], -hat3(p), atol=1e-15, rtol=0)
    for spec in ("SO3", "SE3", "SE2"):
        g = group_from_spec(spec)
        Om = omega_matrix(ad_matrices(g), np.linspace(-1.0, 1.5, g.d))
        assert np.array_equal(Om, -Om.T)


def _free_body_flow(T):
    """Exact flow (g(T), Pi(T)) and its left-trivialized Jacobian, hand-coded in numpy."""
    def f(t, y):
        R, Pi, dR, dPi = y[:9].reshape(3, 3), y[9:12], y[12:66].reshape(6, 3, 3), \
            y[66:].reshape(6, 3)
        W, dW = Pi / INERTIA, dPi / INERTIA
        ddR = [dR[k] @ hat3(W) + R @ hat3(dW[k]) for k in range(6)]
        ddPi = [np.cross(dPi[k], W) + np.cross(Pi, dW[k]) for k in range(6)]
        return np.concatenate([(R @ hat3(W)).ravel(), np.cross(Pi, W),
                               np.ravel(ddR), np.ravel(ddPi)])
    R0 = rotvec([0.3, -0.2, 0.1])
    dR0 = [R0 @ hat3(e) for e in np.eye(3)] + [np.zeros((3, 3))] * 3
    dPi0 = [np.zeros(3)] * 3 + list(np.eye(3))
    y0 = np.concatenate([R0.ravel(), PI0, np.ravel(dR0), np.ravel(dPi0)])
    y = solve_ivp(f, (0, T), y0, method="DOP853", rtol=1e-13, atol=1e-13).y[:, -1]
    R1, Pi1 = y[:9].reshape(3, 3), y[9:12]
    dR1, dPi1 = y[12:66].reshape(6, 3, 3), y[66:].reshape(6, 3)
    eta = np.array([[(R1.T @ dR1[k])[i] for i in ((2, 1), (0, 2), (1, 0))] for k in range(6)])
    return R0, R1, Pi1, np.vstack([eta.T, dPi1.T])


def test_exact_rigid_body_flow_preserves_the_form():
    ad = ad_matrices(group_from_spec("SO3"))
    R0, R1, Pi1, Phi = _free_body_flow(0.8)
    good = _defect(ad, Phi, PI0, Pi1)[0]
    wrong = _defect(ad, Phi, PI0, Pi1, sign=-BRACKET_SIGN)[0]
    print(f"exact free body flow: defect {good:.2e} (sign +), {wrong:.2e} (sign -)")
    assert good < 1e-12 and wrong > 1e-2
    # the generic variational equations of hpgen.analysis.rkmk give the same Jacobian
    eq = ContinuousEquations(load_model(EXAMPLES / "free_rigid_body.yaml"))
    g1, mu1, Phi2 = eq.flow_jacobian(R0, PI0, 0.8)
    assert np.abs(Phi2 - Phi).max() < 1e-10 and np.abs(g1 - R1).max() < 1e-12


@pytest.mark.parametrize("text,g0,mu0", [
    (HEAVY_TOP, rotvec([0.3, 0.2, 0.0]), np.array([0.2, 5.0, 18.0])),
    (SE3_BODY, np.block([[rotvec([0.1, -0.2, 0.3]), np.array([[0.2], [0.0], [-0.1]])],
                         [np.zeros((1, 3)), np.ones((1, 1))]]),
     np.array([0.6, 0.5, 0.27, 0.5, 0.3, -0.9])),
], ids=["heavy-top", "se3-body"])
def test_exact_flow_with_potential_preserves_the_form(model_file, text, g0, mu0):
    model = load_model(model_file(text))
    eq, ad = ContinuousEquations(model), ad_matrices(model.group)
    g1, mu1, Phi = eq.flow_jacobian(g0, mu0, 0.5)
    good = _defect(ad, Phi, mu0, mu1)[1]
    wrong = _defect(ad, Phi, mu0, mu1, sign=-BRACKET_SIGN)[1]
    print(f"exact flow: relative defect {good:.2e} (sign +), {wrong:.2e} (sign -)")
    assert good < 1e-12 and wrong > 1e-4


def _fd_jacobian(step, group, g, p, h, eps=1e-6):
    """Central differences of step(g, p, h) in the chart (g exp(delta^), p + dp)."""
    B, d = hat_basis(group), group.d
    g1 = step(g, p, h)[0]
    cols = []
    for k in range(2 * d):
        out = []
        for s in (1.0, -1.0):
            dl = np.zeros(2 * d)
            dl[k] = s * eps
            out.append(step(g @ expm(np.tensordot(dl[:d], B, 1)), p + dl[d:], h))
        (ga, pa), (gb, pb) = out
        E = np.real(logm(np.linalg.solve(g1, ga)) - logm(np.linalg.solve(g1, gb)))
        eta = np.linalg.lstsq(np.stack([b.ravel() for b in B], 1), E.ravel(), rcond=None)[0]
        cols.append(np.concatenate([eta, pa - pb]) / (2 * eps))
    return np.array(cols).T


@pytest.mark.parametrize("text,tableau,tau,rkmk", [
    (HEAVY_TOP, "stormer-verlet", "cay", "truncated"),
    (SE3_BODY, "midpoint", "cay", "exact"),
], ids=["top-sv-cay", "se3-midpoint-cay-exact"])
def test_implicit_jacobian_matches_differences(compile_model, model_file, text, tableau, tau,
                                               rkmk):
    model = load_model(model_file(text))
    integ = compile_model(text, tableau=tableau, tau=tau, rkmk=rkmk, backend="c")
    gm = GeneratedMap(integ, derive(model, get_tableau(tableau), tau, rkmk), model.group)
    g0 = np.eye(model.group.n)
    g0[:3, :3] = rotvec([0.3, 0.2, -0.1])
    p0 = np.linspace(0.5, 2.0, model.group.d)
    h = 0.1
    Phi, g1, p1 = gm.map_jacobian(g0, p0, h)
    g1s, p1s = integ.step(g0, p0, h)
    assert np.abs(g1 - g1s).max() < 1e-13 and np.abs(p1 - p1s).max() < 1e-13
    assert gm.last["kernel_mismatch"] < 1e-13
    FD = _fd_jacobian(integ.step, model.group, g0, p0, h)
    assert np.abs(FD - Phi).max() < 1e-7 * max(1.0, np.abs(Phi).max())


def test_rkmk_jacobian_matches_differences(model_file):
    model = load_model(model_file(HEAVY_TOP))
    rk = RKMK4(model)
    g0, p0, h = rotvec([0.3, 0.2, 0.0]), np.array([0.2, 5.0, 18.0]), 0.05
    Phi, g1, p1 = rk.map_jacobian(g0, p0, h)
    FD = _fd_jacobian(rk.step, model.group, g0, p0, h)
    assert np.abs(FD - Phi).max() < 1e-7 * max(1.0, np.abs(Phi).max())


def test_rkmk4_refuses_chart_arguments_outside_exp_domain():
    # exp's half-angle series are accurate for |omega| <= pi only: a step whose chart
    # argument h Theta reaches past it raises DomainError instead of a silently wrong g
    from hpgen.errors import DomainError
    from hpgen.model import load_model
    model = load_model(EXAMPLES / "heavy_top.yaml")
    rk = RKMK4(model)
    g0, mu0 = np.array(model.scene.g0), np.array([0.2, 5.0, 18.0])   # |xi| ~ 3
    g, mu = rk.simulate(g0, mu0, 0.05, 4)
    assert np.isfinite(g).all() and len(g) == 5
    with pytest.raises(DomainError) as info:
        rk.simulate(g0, mu0, 1.5, 3)
    assert info.value.step == 0 and "exp's domain" in str(info.value)
