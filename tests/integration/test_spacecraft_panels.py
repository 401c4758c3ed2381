"""examples/spacecraft_panels.yaml: a hub and two solar panels on [SE3, SE3, SE3] joined by
two hinges (10 constraint rows), constrained Stormer-Verlet, a body torque input on the hub.

- the hinges hold at every node to round-off, positions and velocity form (Newton stops at
  1e-14 relative on rows of O(1) lengths);
- with zero input the craft is invariant under rigid motions: the total linear and angular
  momentum (spatial frame), sum_k R_k P_k and sum_k (R_k pi_k + x_k x R_k P_k), are kept to
  round-off (1e-12 relative over 10^4 steps, as the other momentum tests), and the energy
  stays in a band without drift (symplectic on the constraint manifold);
- with a constant hub torque the linear momentum is still kept (a pure torque), the hinges
  still hold, and the angular momentum changes.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES

MODEL = EXAMPLES / "spacecraft_panels.yaml"
HUB_POINTS = {1: np.array([0.0, 0.6, 0.0]), 2: np.array([0.0, -0.6, 0.0])}
PANEL_POINTS = {1: np.array([0.0, -1.0, 0.0]), 2: np.array([0.0, 1.0, 0.0])}
MASS = np.array([100.0, 10.0, 10.0])
INERTIA = np.array([[17.333333333333332, 13.666666666666666, 20.333333333333332],
                    [3.3336666666666663, 0.8336666666666667, 4.166666666666667],
                    [3.3336666666666663, 0.8336666666666667, 4.166666666666667]])


def _bodies(G, P):
    """Per body k: R (K,3,3), x (K,3), omega (K,3), v (K,3) body-frame velocities."""
    out = []
    for k in range(3):
        R, x = G[:, 4 * k:4 * k + 3, 4 * k:4 * k + 3], G[:, 4 * k:4 * k + 3, 4 * k + 3]
        out.append((R, x, P[:, 6 * k:6 * k + 3] / INERTIA[k], P[:, 6 * k + 3:6 * k + 6] / MASS[k]))
    return out


def _rv(R, v):
    return np.einsum("kij,kj->ki", R, v)


def hinge_residuals(G, P):
    """(max position gap and axis rows, max velocity gap and axis-rate rows) over the nodes."""
    b = _bodies(G, P)
    R0, x0, w0, v0 = b[0]
    pos, vel = 0.0, 0.0
    for k in (1, 2):
        Rk, xk, wk, vk = b[k]
        a, c = HUB_POINTS[k], PANEL_POINTS[k]
        gap = xk + _rv(Rk, np.broadcast_to(c, xk.shape)) - x0 - _rv(R0, np.broadcast_to(a, x0.shape))
        M = np.swapaxes(R0, 1, 2) @ Rk          # relative rotation; the hinge axis is x
        pos = max(pos, np.abs(gap).max(), np.abs(M[:, 1, 0]).max(), np.abs(M[:, 2, 0]).max())
        dgap = _rv(Rk, vk + np.cross(wk, c)) - _rv(R0, v0 + np.cross(w0, a))
        rel = _rv(Rk, wk) - _rv(R0, w0)           # relative angular velocity, world frame
        axis = _rv(R0, np.broadcast_to([1.0, 0.0, 0.0], x0.shape))
        off_axis = rel - np.sum(rel * axis, axis=1)[:, None] * axis
        vel = max(vel, np.abs(dgap).max(), np.abs(off_axis).max())
    return pos, vel


def momenta(G, P):
    """(linear (K,3), angular about the origin (K,3)) total spatial momenta."""
    lin, ang = np.zeros((len(G), 3)), np.zeros((len(G), 3))
    for k in range(3):
        R, x = G[:, 4 * k:4 * k + 3, 4 * k:4 * k + 3], G[:, 4 * k:4 * k + 3, 4 * k + 3]
        RP = _rv(R, P[:, 6 * k + 3:6 * k + 6])
        lin += RP
        ang += _rv(R, P[:, 6 * k:6 * k + 3]) + np.cross(x, RP)
    return lin, ang


@pytest.fixture(scope="module")
def craft(compile_model):
    from hpgen.model import load_model
    model = load_model(MODEL)
    return model, compile_model(MODEL)


def test_free_craft_keeps_hinges_momenta_and_energy(craft):
    model, integ = craft
    sc = model.scene
    tr = integ.simulate(g0=np.array(sc.g0), xi0=np.array(sc.xi0), h=sc.h, steps=10_000,
                        every=10, u=[0.0, 0.0, 0.0])
    pos, vel = hinge_residuals(tr.g, tr.mu)
    lin, ang = momenta(tr.g, tr.mu)
    scale = np.abs(ang[0]).max()
    dlin = np.abs(lin - lin[0]).max() / scale
    dang = np.abs(ang - ang[0]).max() / scale
    err = tr.energy() - tr.energy()[0]
    tenth = len(err) // 10
    first, last = np.abs(err[:tenth]).max(), np.abs(err[-tenth:]).max()
    slope = np.polyfit(tr.t, err, 1)[0]
    print(f"hinges |phi| {pos:.2e}, velocity form {vel:.2e}; momentum drift linear {dlin:.2e}, "
          f"angular {dang:.2e} (|L| {scale:.3f}); energy {tr.energy()[0]:.4f}, band first "
          f"tenth {first:.2e}, last {last:.2e}, slope*T {slope * tr.t[-1]:.2e}")
    assert pos < 1e-14 and vel < 1e-13
    assert dlin < 1e-12 and dang < 1e-12
    # the panels flap through full turns: the craft passes through many configurations
    M = np.swapaxes(tr.g[:, :3, :3], 1, 2) @ tr.g[:, 4:7, 4:7]
    turns = np.ptp(np.unwrap(np.arctan2(M[:, 2, 1], M[:, 1, 1]))) / (2 * np.pi)
    assert turns > 1.0
    assert last < 1.5 * first and abs(slope) * tr.t[-1] < first
    assert first < 1e-4 * abs(tr.energy()[0])


def test_hub_torque_keeps_linear_momentum_and_hinges(craft):
    model, integ = craft
    sc = model.scene
    tau = [0.5, -0.2, 0.3]
    tr = integ.simulate(g0=np.array(sc.g0), xi0=np.array(sc.xi0), h=sc.h, steps=2000,
                        every=10, u=tau)
    pos, vel = hinge_residuals(tr.g, tr.mu)
    lin, ang = momenta(tr.g, tr.mu)
    print(f"torque {tau}: hinges {pos:.2e} / {vel:.2e}, linear momentum drift "
          f"{np.abs(lin - lin[0]).max():.2e}, angular change {np.abs(ang - ang[0]).max():.3f}")
    assert pos < 1e-14 and vel < 1e-13
    assert np.abs(lin - lin[0]).max() < 1e-12 * np.abs(ang).max()
    assert np.abs(ang[-1] - ang[0]).max() > 1.0          # 20 s of a ~0.6 N m torque
