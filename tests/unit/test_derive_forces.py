"""The forced step at the derive level (issue 16, math.md sec. 9): the discrete
Lagrange-d'Alembert principle in hpgen.derive, stepped here by a plain Newton loop on the
derived CasADi kernels (no code generation involved).

- the spatial-torque identity: a free rigid body under a constant spatial torque tau_s
  (forces = R^T tau_s) has R_k p_k = R_0 p_0 + k h tau_s exactly (discrete forced Noether);
  the only error is round-off and Newton's tolerance (1e-15 relative per step), so after
  10^4 steps 1e-12 relative holds with margin;
- zero forces: the closed model's kernels, bitwise (the derivation is the same);
- orders 2 / 4 / 6 (Stormer-Verlet truncated, Gauss 2 exact, Gauss 3 exact) against DOP853 on
  the continuous forced equations (hpgen.analysis.rkmk.ContinuousEquations with f), on SO3
  (heavy top with friction and a periodic torque in t, the weight a runtime parameter) and
  on SE3 (underwater vehicle with drag and a constant thrust input).
"""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.analysis.rkmk import ContinuousEquations
from hpgen.derive import derive
from hpgen.model import load_model_text
from hpgen.tableaus import get_tableau

FREE_BODY = """\
name: body
group: SO3
parameters: {I: [2.0, 1.0, 0.6666666666666666], ts: [0.003, -0.002, 0.005]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)
forces: ["dot(ts, R)[0]", "dot(ts, R)[1]", "dot(ts, R)[2]"]
"""
TAU_S = np.array([0.003, -0.002, 0.005])

HEAVY_TOP = """\
name: forced_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, c: 0.1, a: 0.4}
runtime_parameters: [Mg]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2, 2]
forces: ["-c*xi[0] + a*cos(2*t)", "-c*xi[1]", "-c*xi[2] + a*R[2, 0]*sin(t)"]
"""

VEHICLE = """\
name: vehicle
group: SE3
parameters: {I: [2.0, 1.0, 0.6666666666666666], M: [1.0, 1.5, 3.0], k: 0.2, q: 0.3}
inputs: [thrust]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) + \
  0.5*(M[0]*xi[3]**2 + M[1]*xi[4]**2 + M[2]*xi[5]**2)
forces: ["-k*xi[0]", "-k*xi[1]", "-k*xi[2]", "thrust - k*xi[3] - q*xi[3]*sqrt(xi[3]**2 + 1)",
         "-k*xi[4]", "-k*xi[5]"]
"""

SCHEMES = (("stormer-verlet", "truncated", 2), ("gauss2", "exact", 4), ("gauss3", "exact", 6))


class Stepper:
    """(g_k, p_k, t_k) -> (g_{k+1}, p_{k+1}, t_k + h) with the derived kernels and Newton."""

    def __init__(self, step, u=(), params=()):
        self.K = {k.name: k.function for k in step.kernels}
        self.open = step.open_spec is not None
        self.extra = (np.asarray(u, float), np.asarray(params, float))
        self.n, self.nz = step.n, step.nz

    def hv(self, h, t):
        """the step vector: [h] closed, [h, t_k, u, params] open (hpgen.abi)"""
        return np.concatenate([[h, t], *self.extra]) if self.open else np.array([h])

    def momentum(self, g, xi, t=0.0):
        a = (self.hv(0.0, t),) if self.open else ()
        return np.array(self.K["legendre"](g.ravel("F"), xi, *a)).ravel()

    def step(self, g, p, h, t):
        gf, K = g.ravel("F"), self.K
        hv = self.hv(h, t)
        a = (hv,) if self.open else ()
        H = np.array(K["hessian"](gf, np.zeros_like(p), *a)).reshape(len(p), len(p))
        z = np.array(K["guess"](np.linalg.solve(H, p), gf, p, hv)).ravel()
        for _ in range(40):
            F, J = K["residual_jacobian"](z, gf, p, hv)
            dz = np.linalg.solve(np.array(J).reshape(self.nz, self.nz, order="F"),
                                 np.array(F).ravel())
            z = z - dz
            if np.abs(dz).max() <= 1e-15 * (1.0 + np.abs(z).max()):
                break
        else:
            raise AssertionError("Newton did not converge")
        g1, p1 = K["update"](z, gf, p, hv)
        return np.array(g1).reshape(self.n, self.n, order="F"), np.array(p1).ravel()

    def run(self, g, p, h, steps, t0=0.0):
        for k in range(steps):
            g, p = self.step(g, p, h, t0 + k * h)
        return g, p


def _derive(text, tableau, rkmk, tau="cay"):
    model = load_model_text(text)
    return model, derive(model, get_tableau(tableau), tau, rkmk)


@pytest.mark.parametrize("tableau, rkmk, steps", [("gauss2", "exact", 10_000),
                                                  ("stormer-verlet", "truncated", 2000),
                                                  ("gauss3", "exact", 2000)])
def test_spatial_torque_identity(tableau, rkmk, steps):
    model, step = _derive(FREE_BODY, tableau, rkmk)
    assert model.forced and not step.reduced
    st = Stepper(step)
    g0, h = np.eye(3), 0.01
    p0 = st.momentum(g0, np.array([0.3, 0.2, -0.5]))
    g, p = st.run(g0, p0, h, steps)
    expected = g0 @ p0 + steps * h * TAU_S
    assert np.abs(g @ p - expected).max() <= 1e-12 * np.abs(expected).max()
    # not trivially: the body tumbles and the torque changed the momentum by O(|p0|)
    assert np.abs(g - np.eye(3)).max() > 0.5
    assert np.linalg.norm(steps * h * TAU_S) > 0.15 * np.linalg.norm(p0)


@pytest.mark.parametrize("tableau, rkmk", [("gauss2", "exact"), ("stormer-verlet", "truncated"),
                                           ("lobatto3a3", "exact")])
def test_zero_forces_derive_the_closed_step(tableau, rkmk):
    plain = FREE_BODY.split("forces:")[0].replace("lagrangian: ", "lagrangian: 0.1*R[2, 2] + ")
    _, closed = _derive(plain, tableau, rkmk)
    model, zero = _derive(plain + "forces: [0, 0.0, '0*xi[0]']\n", tableau, rkmk)
    assert len(model.forces) == 3 and not model.open_system
    assert zero.open_spec is None and zero.unknowns == closed.unknowns
    for a, b in zip(closed.kernels, zero.kernels):
        assert a.function.serialize() == b.function.serialize(), a.name


def test_forced_with_zero_coefficient_matches_closed_step():
    """An open model whose force vanishes for the given parameters: same trajectory as the
    closed model to round-off (the emitted step differs: it takes t, u, params)."""
    forced = HEAVY_TOP.replace("c: 0.1, a: 0.4", "c: 0.1, a: 0.4, s: 0.0").replace(
        "runtime_parameters: [Mg]", "runtime_parameters: [Mg, s]").replace(
        'forces: ["-c*xi[0] + a*cos(2*t)", "-c*xi[1]", "-c*xi[2] + a*R[2, 0]*sin(t)"]',
        'forces: ["s*(-c*xi[0] + a*cos(2*t))", "-s*c*xi[1]", "s*a*R[2, 0]*sin(t)"]')
    closed = HEAVY_TOP.split("runtime_parameters")[0] + \
        "lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2, 2]\n"
    _, s_open = _derive(forced, "gauss2", "exact")
    _, s_closed = _derive(closed, "gauss2", "exact")
    a, b = Stepper(s_open, params=(1.0, 0.0)), Stepper(s_closed)
    g0, xi0 = np.eye(3), np.array([0.2, 1.0, 3.0])
    ga, pa = a.run(g0, a.momentum(g0, xi0), 0.05, 200)
    gb, pb = b.run(g0, b.momentum(g0, xi0), 0.05, 200)
    assert np.abs(ga - gb).max() < 1e-12 and np.abs(pa - pb).max() < 1e-11


def _observed_orders(text, tableau, rkmk, g0, xi0, T, hs, u=(), params=None):
    model, step = _derive(text, tableau, rkmk)
    params = model.runtime_defaults if params is None else params
    st = Stepper(step, u, params)
    eq = ContinuousEquations(model, u=u, params=params)
    t0 = 0.3                                     # a time-dependent force: start off zero
    p0 = st.momentum(g0, xi0, t0)
    g_ref, p_ref = eq.reference(g0, p0, [T], rtol=1e-13, t0=t0)
    errs = []
    for h in hs:
        g, p = st.run(g0, p0, h, int(round(T / h)), t0)
        errs.append(max(np.abs(g - g_ref[-1]).max(), np.abs(p - p_ref[-1]).max()))
    errs = np.array(errs)
    return np.log2(errs[:-1] / errs[1:]), errs


@pytest.mark.parametrize("tableau, rkmk, order", SCHEMES)
def test_forced_orders_heavy_top_so3(tableau, rkmk, order):
    hs = (0.2, 0.1, 0.05) if order < 6 else (0.1, 0.05, 0.025)   # asymptotic range
    orders, errs = _observed_orders(HEAVY_TOP, tableau, rkmk, np.eye(3),
                                    np.array([0.2, 1.0, 3.0]), 2.0, hs, params=(1.3,))
    assert errs[-1] > 1e-13                       # above the reference's accuracy
    assert abs(orders[-1] - order) < 0.3, (orders, errs)


@pytest.mark.parametrize("tableau, rkmk, order", SCHEMES)
def test_forced_orders_vehicle_se3(tableau, rkmk, order):
    hs = (0.2, 0.1, 0.05) if order < 6 else (0.4, 0.2, 0.1)
    orders, errs = _observed_orders(VEHICLE, tableau, rkmk, np.eye(4),
                                    np.array([0.3, 1.0, 0.2, 1.0, 0.0, 0.5]), 2.0, hs,
                                    u=(0.7,))
    assert errs[-1] > 1e-13
    assert abs(orders[-1] - order) < 0.3, (orders, errs)
