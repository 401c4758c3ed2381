"""Conservation laws of the generated (variational, symplectic) schemes, C backend.

- Spatial momentum Ad*_{g^-1} p of a left-invariant l, and the vertical component
  e3.(R p) of the heavy top's, constant to 1e-12 relative over 10^4 steps: the scheme
  conserves them exactly (discrete Noether), so only Newton's tolerance (1e-14 relative)
  and round-off accumulated over 10^4 steps (~sqrt(10^4) * 1e-16 * growth) remain.
- R^T R = I to 1e-13 over 10^4 steps: each step multiplies by tau(.), orthogonal to
  round-off, so the defect grows like a random walk of 1e-16 steps.
- Energy of the heavy top over 10^5 steps at h = 0.05: bounded, no drift (symplectic).
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import FREE_BODY, HEAVY_TOP
from reference import rotvec

E3 = np.array([0.0, 0.0, 1.0])


@pytest.mark.parametrize("tableau,tau,rkmk", [("stormer-verlet", "cay", "truncated"),
                                              ("gauss2", "exp", "exact"),
                                              ("midpoint", "exp", "truncated")])
def test_free_body_spatial_momentum_and_group(compile_model, tableau, tau, rkmk):
    integ = compile_model(FREE_BODY, tableau=tableau, tau=tau, rkmk=rkmk)
    mu0 = np.array([np.cos(1.1), 0.0, np.sin(1.1)])
    tr = integ.simulate(g0=np.eye(3), mu0=mu0, h=0.1, steps=10_000, every=10)
    m = tr.momentum()
    rel = np.abs(m - m[0]).max() / np.linalg.norm(m[0])
    defect = max(np.abs(g.T @ g - np.eye(3)).max() for g in tr.g)
    print(f"free body {tableau} {tau} {rkmk}: momentum drift {rel:.2e}, |R^T R - I| {defect:.2e}")
    assert rel < 1e-12
    assert defect < 1e-13


@pytest.mark.parametrize("tableau,tau,rkmk", [("stormer-verlet", "cay", "truncated"),
                                              ("gauss2", "exp", "exact")])
def test_heavy_top_vertical_momentum_and_group(compile_model, tableau, tau, rkmk):
    integ = compile_model(HEAVY_TOP, tableau=tableau, tau=tau, rkmk=rkmk)
    tr = integ.simulate(g0=rotvec([0.3, 0.2, 0.0]), xi0=[0.2, 1.0, 3.0], h=0.05, steps=10_000,
                        every=10)
    vert = np.einsum("i,kij,kj->k", E3, tr.g, tr.mu)
    rel = np.abs(vert - vert[0]).max() / np.linalg.norm(tr.mu[0])
    defect = max(np.abs(g.T @ g - np.eye(3)).max() for g in tr.g)
    print(f"heavy top {tableau} {tau} {rkmk}: e3.(R p) drift {rel:.2e}, |R^T R - I| {defect:.2e}")
    assert rel < 1e-12
    assert defect < 1e-13


@pytest.mark.slow
def test_heavy_top_energy_bounded_without_drift(compile_model):
    """10^5 steps at h = 0.05 (T = 5000). No drift: the energy error's envelope over the
    last tenth is within 1.5x of the first tenth's (a drifting method grows linearly, by
    10x over this span), and a linear fit's slope times T is below the oscillation size."""
    integ = compile_model(HEAVY_TOP, tableau="gauss2", tau="exp", rkmk="exact")
    tr = integ.simulate(g0=rotvec([0.3, 0.2, 0.0]), xi0=[0.2, 1.0, 3.0], h=0.05,
                        steps=100_000, every=10)
    err = tr.energy() - tr.energy()[0]
    tenth = len(err) // 10
    first, last = np.abs(err[:tenth]).max(), np.abs(err[-tenth:]).max()
    slope = np.polyfit(tr.t, err, 1)[0]
    print(f"heavy top energy: max error first tenth {first:.3e}, last tenth {last:.3e}, "
          f"slope {slope:.3e} per unit time, slope*T {slope * tr.t[-1]:.3e}")
    assert last < 1.5 * first
    assert abs(slope) * tr.t[-1] < first
