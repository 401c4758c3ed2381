"""Hard case 6: the chaotic underwater vehicle (examples/underwater_vehicle.yaml: Kirchhoff's
equations on SE3, I = (2, 1, 2/3), M = (1, 1.5, 3), (Pi0; P0) = (0.3, 1, 0.2; 1, 0, 0.5),
largest Lyapunov exponent ~0.117, docs/numerics.md sec. 11) at h = 0.05 up to T = 5000 (10^5 steps),
gauss2/cay/exact (order 4, variational) against a plain RK4 on the reduced Kirchhoff
equations written here:
    Pi' = Pi x Omega + P x v,  P' = P x Omega,  Omega = Pi / I,  v = P / M.
Trajectories of a chaotic system cannot be compared after t ~ 100 (errors grow like
e^{0.117 t}); the discriminator is the drift of the invariants.

Pass criteria:
- energy: hpgen's error is bounded (last tenth within 1.5x of the first tenth) and its
  largest value over the last tenth is at least 10x smaller than RK4's |H(T) - H(0)|;
  RK4's error is a secular drift (|dH(T)| > 1.5 |dH(T/2)|; docs/numerics.md sec. 11: -1.3e-4
  by T = 10^4);
- Casimirs |P|^2 and Pi.P conserved by hpgen to 1e-11 relative: the scheme conserves the
  spatial momentum Ad*_{g_k^-1} p_k (discrete Noether), so p_{k+1} = Ad*_{g_k^-1 g_k+1} p_k
  stays on the coadjoint orbit of p_0, where the Casimirs are constant (round-off only);
  RK4 violates them by ~1e-4 / ~4e-5;
- spatial momenta R P (to 1e-11 relative to |P|) and R Pi + x x R P (to 1e-11 relative to
  |Pi| + max|x| |P|: x grows linearly, the vehicle travels ~10^3 lengths, so absolute
  round-off scales with |x|) conserved by hpgen (discrete Noether).
"""
from __future__ import annotations

import time

import numpy as np
import pytest

from conftest import EXAMPLES

I = (2.0, 1.0, 0.6666666666666666)
M = (1.0, 1.5, 3.0)
MU0 = np.array([0.3, 1.0, 0.2, 1.0, 0.0, 0.5])
H, T, EVERY = 0.05, 5000.0, 50
STEPS = int(round(T / H))


def hamiltonian(y):
    y = np.asarray(y)
    return 0.5 * (np.sum(y[..., :3] ** 2 / np.array(I), axis=-1)
                  + np.sum(y[..., 3:] ** 2 / np.array(M), axis=-1))


def casimirs(y):
    y = np.asarray(y)
    return np.sum(y[..., 3:] ** 2, axis=-1), np.sum(y[..., :3] * y[..., 3:], axis=-1)


def rk4_kirchhoff(y0, h, steps, every):
    """Classical RK4 on (Pi, P) in scalar Python floats (the arithmetic of a NumPy RK4, ~10x
    faster than NumPy for 6 components)."""
    I0, I1, I2 = I
    M0, M1, M2 = M

    def f(a0, a1, a2, b0, b1, b2):
        w0, w1, w2 = a0 / I0, a1 / I1, a2 / I2
        v0, v1, v2 = b0 / M0, b1 / M1, b2 / M2
        return (a1 * w2 - a2 * w1 + b1 * v2 - b2 * v1,
                a2 * w0 - a0 * w2 + b2 * v0 - b0 * v2,
                a0 * w1 - a1 * w0 + b0 * v1 - b1 * v0,
                b1 * w2 - b2 * w1, b2 * w0 - b0 * w2, b0 * w1 - b1 * w0)
    y = [float(v) for v in y0]
    out = [tuple(y)]
    h2, h6 = h / 2, h / 6
    for k in range(steps):
        k1 = f(*y)
        k2 = f(*[a + h2 * b for a, b in zip(y, k1)])
        k3 = f(*[a + h2 * b for a, b in zip(y, k2)])
        k4 = f(*[a + h * b for a, b in zip(y, k3)])
        y = [a + h6 * (b1 + 2 * b2 + 2 * b3 + b4) for a, b1, b2, b3, b4 in zip(y, k1, k2, k3, k4)]
        if (k + 1) % every == 0:
            out.append(tuple(y))
    return np.array(out)


@pytest.mark.slow
def test_underwater_vehicle_invariants_vs_rk4(compile_model):
    """T = 5000: hpgen's energy error bounded and >= 10x below RK4's drift; Casimirs and
    spatial momenta to 1e-11 relative (module docstring)."""
    t0 = time.perf_counter()
    Y = rk4_kirchhoff(MU0, H, STEPS, EVERY)
    t_rk4 = time.perf_counter() - t0
    dH_rk4 = hamiltonian(Y) - hamiltonian(MU0)
    c1, c2 = casimirs(Y)
    rk4_c1, rk4_c2 = np.abs(c1 / c1[0] - 1).max(), np.abs(c2 / c2[0] - 1).max()
    half = len(Y) // 2

    integ = compile_model(EXAMPLES / "underwater_vehicle.yaml", tableau="gauss2", tau="cay",
                          rkmk="exact")
    t0 = time.perf_counter()
    tr = integ.simulate(g0=np.eye(4), mu0=MU0, h=H, steps=STEPS, every=EVERY)
    t_hp = time.perf_counter() - t0
    E = tr.energy()
    assert np.allclose(E, hamiltonian(tr.mu), rtol=1e-13, atol=0)
    dE = E - E[0]
    tenth = len(dE) // 10
    first, last = np.abs(dE[:tenth]).max(), np.abs(dE[-tenth:]).max()
    d1, d2 = casimirs(tr.mu)
    hp_c1, hp_c2 = np.abs(d1 / d1[0] - 1).max(), np.abs(d2 / d2[0] - 1).max()
    m = tr.momentum()                                  # (R Pi + x x R P, R P)
    xmax = np.abs(tr.g[:, :3, 3]).max()
    lin = np.abs(m[:, 3:] - m[0, 3:]).max() / np.linalg.norm(MU0[3:])
    ang = np.abs(m[:, :3] - m[0, :3]).max() / (np.linalg.norm(MU0[:3])
                                              + np.sqrt(3) * xmax * np.linalg.norm(MU0[3:]))
    print(f"\n[underwater] T = {T:g}, h = {H} ({STEPS} steps)\n"
          f"  RK4 (scalar Python floats, {t_rk4:.1f} s): H(T) - H0 = {dH_rk4[-1]:+.3e} "
          f"(at T/2: {dH_rk4[half]:+.3e}); Casimirs |P|^2 {rk4_c1:.1e}, Pi.P {rk4_c2:.1e} rel\n"
          f"  hpgen gauss2/cay/exact ({t_hp:.1f} s): max |H - H0| first tenth {first:.2e}, "
          f"last tenth {last:.2e} (ratio RK4/hpgen {abs(dH_rk4[-1]) / last:.0f}); Casimirs "
          f"|P|^2 {hp_c1:.1e}, Pi.P {hp_c2:.1e} rel; spatial momenta: R P {lin:.1e}, "
          f"R Pi + x x R P {ang:.1e} (max |x| {xmax:.0f})")
    assert abs(dH_rk4[-1]) > 1.5 * abs(dH_rk4[half])
    assert last <= 1.5 * first
    assert 10 * last <= abs(dH_rk4[-1])
    assert hp_c1 < 1e-11 and hp_c2 < 1e-11
    assert lin < 1e-11 and ang < 1e-11
