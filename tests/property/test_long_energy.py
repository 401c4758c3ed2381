"""10^6 steps of the free rigid body at h = 0.1 (T = 10^5; I = (2, 1, 2/3),
Pi0 = (cos 1.1, 0, sin 1.1), the Hairer-Lubich-Wanner set-up): the energy error of every
symplectic (variational) scheme stays bounded with no drift, while classical RK4 at the
same h drifts.

No drift: the envelope max|E - E0| over the last tenth of the run is within 1.5x of the
first tenth's (a linear drift multiplies it by ~10 between the two tenths), and the
slope of a linear fit times T stays below the first tenth's envelope. RK4 must fail the
first criterion by a wide margin (its envelope grows ~linearly: last/first > 5), so the
test can tell the two behaviours apart.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import FREE_BODY

I = np.array([2.0, 1.0, 2.0 / 3.0])
PI0 = np.array([math.cos(1.1), 0.0, math.sin(1.1)])
H, STEPS, EVERY = 0.1, 1_000_000, 100
SCHEMES = [(tab, "cay", "truncated") for tab in
           ("euler-forward", "stormer-verlet", "midpoint", "gauss2", "lobatto3a3")] + \
          [("stormer-verlet", "exp", "truncated"), ("midpoint", "skew", "truncated"),
           ("gauss2", "cay", "exact"), ("gauss2", "exp", "exact")]


def energy(mu):
    return 0.5 * np.sum(mu * mu / I, axis=-1)


def envelopes(err):
    tenth = len(err) // 10
    return np.abs(err[:tenth]).max(), np.abs(err[-tenth:]).max()


def rk4_energy_error(h=H, steps=STEPS, every=EVERY):
    """Classical RK4 on Euler's equations Pi' = Pi x Omega, Omega = Pi / I (plain floats)."""
    i1, i2, i3 = I
    a, b, c = PI0
    e0 = 0.5 * (a * a / i1 + b * b / i2 + c * c / i3)

    def f(a, b, c):
        w1, w2, w3 = a / i1, b / i2, c / i3
        return b * w3 - c * w2, c * w1 - a * w3, a * w2 - b * w1
    out = [0.0]
    for k in range(1, steps + 1):
        k1 = f(a, b, c)
        k2 = f(a + 0.5 * h * k1[0], b + 0.5 * h * k1[1], c + 0.5 * h * k1[2])
        k3 = f(a + 0.5 * h * k2[0], b + 0.5 * h * k2[1], c + 0.5 * h * k2[2])
        k4 = f(a + h * k3[0], b + h * k3[1], c + h * k3[2])
        a += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        b += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        c += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2])
        if k % every == 0:
            out.append(0.5 * (a * a / i1 + b * b / i2 + c * c / i3) - e0)
    return np.array(out)


@pytest.mark.slow
@pytest.mark.parametrize("tableau,tau,rkmk", SCHEMES, ids=["-".join(s) for s in SCHEMES])
def test_symplectic_schemes_energy_bounded_over_1e6_steps(compile_model, tableau, tau, rkmk):
    integ = compile_model(FREE_BODY, tableau=tableau, tau=tau, rkmk=rkmk)
    tr = integ.simulate(g0=np.eye(3), mu0=PI0, h=H, steps=STEPS, every=EVERY)
    err = energy(tr.mu) - energy(tr.mu[0])
    first, last = envelopes(err)
    slope = np.polyfit(tr.t, err, 1)[0]
    print(f"{tableau}/{tau}/{rkmk}: 1e6 steps, max|dE| first tenth {first:.3e}, last tenth "
          f"{last:.3e}, slope*T {slope * tr.t[-1]:.2e}")
    assert last < 1.5 * first
    assert abs(slope) * tr.t[-1] < first


@pytest.mark.slow
def test_rk4_energy_drifts_over_1e6_steps():
    err = rk4_energy_error()
    first, last = envelopes(err)
    print(f"RK4: 1e6 steps, max|dE| first tenth {first:.3e}, last tenth {last:.3e}, "
          f"final {err[-1]:.3e}")
    assert last > 5 * first
