"""A closed kinematic loop: the planar four-bar linkage of examples/four_bar.yaml on
SE2^3 (4 hinges, 8 rows, one degree of freedom), constrained Stormer-Verlet.

- every hinge closes to round-off at every node (1e-14: Newton's 1e-14 relative stop on
  O(1) rows), and so does its velocity form (the hidden constraint);
- energy bounded without drift over 10^5 steps (symplectic on the constraint manifold);
  the crank turns fully (the linkage passes all its configurations).
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT

MODEL = ROOT / "examples" / "four_bar.yaml"
L = (1.0, 2.5, 2.0)
GROUND = np.array([2.5, 0.0])


def _rot(t):
    return np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])


def _link(A, B):
    """SE2 element of a link from its end A (body (-L/2, 0)) to its end B (body (L/2, 0))."""
    g = np.eye(3)
    g[:2, :2] = _rot(np.arctan2(*(B - A)[::-1]))
    g[:2, 2] = (A + B) / 2
    return g


def initial(theta=0.7, omega=6.0):
    """(g0, xi0): crank at angle theta turning at omega, the loop closed (upper branch), the
    other links' velocities from the null space of the constraint Jacobian."""
    from hpgen.model import load_model
    from hpgen.model.constraints import constraint_values
    B = L[0] * np.array([np.cos(theta), np.sin(theta)])
    dv = GROUND - B
    dist = np.linalg.norm(dv)
    a = (L[1] ** 2 - L[2] ** 2 + dist ** 2) / (2 * dist)
    C = B + a * dv / dist + np.sqrt(L[1] ** 2 - a ** 2) * np.array([-dv[1], dv[0]]) / dist
    g0 = np.zeros((9, 9))
    for k, (P, Q) in enumerate(((np.zeros(2), B), (B, C), (GROUND, C))):
        g0[3 * k:3 * k + 3, 3 * k:3 * k + 3] = _link(P, Q)
    model = load_model(MODEL)
    phi, Phi, _ = constraint_values(model.constraints, model.g_symbols, model.group, g0)
    assert np.abs(phi).max() < 1e-14
    # Phi xi = 0 with xi[0] = omega: 8 equations in the other 8 entries
    xi_rest = np.linalg.solve(Phi[:, 1:], -omega * Phi[:, 0])
    return model, g0, np.concatenate([[omega], xi_rest])


def residuals(G, P, model):
    """(max |phi|, max |Phi xi|) over the nodes, xi = M^-1 p (l quadratic, diagonal)."""
    m, Iz = dict(model.parameters)["m"], dict(model.parameters)["I"]
    M = np.array([[Iz[k], m[k], m[k]] for k in range(3)]).ravel()
    xi = P / M
    ends = dict(a0=(-0.5, 0), b0=(0.5, 0), a1=(-1.25, 0), b1=(1.25, 0), a2=(-1, 0), b2=(1, 0))

    def point(k, e):          # position and velocity of body point e of link k
        R, x = G[:, 3 * k:3 * k + 2, 3 * k:3 * k + 2], G[:, 3 * k:3 * k + 2, 3 * k + 2]
        w, v = xi[:, 3 * k], xi[:, 3 * k + 1:3 * k + 3]
        e = np.array(ends[e], dtype=float)
        body_v = v + w[:, None] * np.array([-e[1], e[0]])
        return x + R @ e, np.einsum("kij,kj->ki", R, body_v)

    pairs = [(point(0, "a0"), (0.0, 0.0)), (point(1, "a1"), point(0, "b0")),
             (point(2, "a2"), (GROUND, 0.0)), (point(2, "b2"), point(1, "b1"))]
    phi = max(np.abs(p[0] - q[0]).max() for p, q in pairs)
    hidden = max(np.abs(p[1] - q[1]).max() for p, q in pairs)
    return phi, hidden


def test_four_bar_closes_at_round_off(compile_model):
    model, g0, xi0 = initial()
    integ = compile_model(MODEL)
    tr = integ.simulate(g0=g0, xi0=xi0, h=0.002, steps=10_000, every=1)
    phi, hidden = residuals(tr.g, tr.mu, model)
    crank = np.unwrap(np.arctan2(tr.g[:, 1, 0], tr.g[:, 0, 0]))
    print(f"four-bar: |phi| {phi:.2e}, |Phi xi| {hidden:.2e}, crank turns "
          f"{(crank[-1] - crank[0]) / (2 * np.pi):.1f}")
    assert abs(crank[-1] - crank[0]) > 4 * np.pi        # full turns: every configuration
    assert phi < 1e-14
    assert hidden < 1e-13


@pytest.mark.slow
def test_four_bar_energy_bounded_without_drift(compile_model):
    model, g0, xi0 = initial()
    integ = compile_model(MODEL)
    tr = integ.simulate(g0=g0, xi0=xi0, h=0.005, steps=100_000, every=10)
    err = tr.energy() - tr.energy()[0]
    tenth = len(err) // 10
    first, last = np.abs(err[:tenth]).max(), np.abs(err[-tenth:]).max()
    slope = np.polyfit(tr.t, err, 1)[0]
    phi, hidden = residuals(tr.g, tr.mu, model)
    print(f"four-bar energy {tr.energy()[0]:.4f}: max error first tenth {first:.3e}, last "
          f"tenth {last:.3e}, slope*T {slope * tr.t[-1]:.3e}; |phi| {phi:.2e}, "
          f"|Phi xi| {hidden:.2e}")
    assert last < 1.5 * first
    assert abs(slope) * tr.t[-1] < first
    assert phi < 1e-13 and hidden < 1e-12
