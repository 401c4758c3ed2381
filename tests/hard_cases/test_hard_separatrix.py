"""Hard case 1: the free rigid body (I = (2, 1, 2/3)) started next to its unstable middle
axis, 10^5 steps.

Which side of the separatrix a state lies on is decided by one number. With J2 = 1 the
identity D := M^2 - 2 E J2 = (Pi1^2 - Pi3^2) / 2 holds for every Pi (M^2 = |Pi|^2,
2E = Pi.I^{-1}Pi), so
  D > 0  <=>  |Pi1| > |Pi3|: the body tumbles about the major axis 1 and Pi1 never changes
              sign (|Pi1| >= sqrt(2 D));
  D < 0  <=>  it tumbles about the minor axis 3 and Pi3 never changes sign.
The exact solution keeps D. The schemes keep M^2 to round-off (the spatial momentum R p is
conserved and R is orthogonal), so along the numerical trajectory
      D_k - D_0 = -2 (E_k - E_0)        exactly, up to round-off:
the numerical state stays on the exact solution's side as long as the energy error stays
below |D_0| / 2. A drifting energy would cross the separatrix sooner or later; a symplectic
scheme's bounded energy error must not.

Initial states: Pi0 = (delta, sqrt(1 - delta^2), 0) (D0 = +delta^2/2, Pi1 keeps its sign)
and Pi0 = (0, sqrt(1 - delta^2), delta) (D0 = -delta^2/2, Pi3 keeps its sign), delta = 0.08:
0.08 rad from the unstable axis, D0 = +-3.2e-3 (1 - k^2 = 0.0127): close to the homoclinic
loop. The orbit comes back to 0.08 rad from the unstable axis each time the oscillating
component crosses zero, every ~14 time units: ~700 times in 10^5 steps of h = 0.1.

Pass criteria (per scheme and side):
- the sign of the exact solution's conserved component (checked on the Jacobi-elliptic
  solution over t in [0, 100]) never changes along the numerical trajectory (every step
  recorded), while the other component changes sign repeatedly (the run really goes
  around the loop, past the unstable axis);
- margin: max |E_k - E_0| < |D0| / 4 (so D_k keeps its sign with a factor 2 to spare);
- energy without drift: the error's envelope over the last tenth is within 1.5x of the
  first tenth's (each tenth spans ~35 loop periods, so both envelopes are reached; a
  linear drift would make the last one ~10x the first), and a linear fit's slope times T
  is below the first tenth's envelope.
"""
from __future__ import annotations

import time

import numpy as np
import pytest

from conftest import FREE_BODY
from hardcase_util import FREE_INERTIA, envelope_drift

DELTA = 0.08
SIDES = {"D>0 (Pi1 fixed)": (np.array([DELTA, np.sqrt(1 - DELTA**2), 0.0]), 0),
         "D<0 (Pi3 fixed)": (np.array([0.0, np.sqrt(1 - DELTA**2), DELTA]), 2)}
SCHEMES = [("stormer-verlet", "cay", "truncated", 0.1),
           ("gauss2", "cay", "exact", 0.1)]
STEPS = 100_000


def _sign_changes(x):
    s = np.sign(x)
    s = s[s != 0]
    return int(np.count_nonzero(s[1:] != s[:-1]))


def _exact_side(pi0, fixed):
    """Sign pattern of the exact solution over t in [0, 100] (several loop periods)."""
    try:
        from hpgen.analysis.exact import free_rigid_body_momentum
        Pi = free_rigid_body_momentum(FREE_INERTIA, pi0, np.linspace(0.0, 100.0, 2001))
    except ImportError:                       # the DOP853 fallback
        from hardcase_util import free_body_reference
        Pi = free_body_reference(pi0, np.linspace(0.0, 100.0, 2001))[1]
    other = 2 - fixed
    return (np.sign(Pi[:, fixed]), _sign_changes(Pi[:, other]))


@pytest.mark.parametrize("side", list(SIDES))
@pytest.mark.parametrize("tableau,tau,rkmk,h", SCHEMES,
                         ids=[f"{a}-{b}-{c}-h{h}" for a, b, c, h in SCHEMES])
def test_separatrix_side_and_energy(compile_model, tableau, tau, rkmk, h, side):
    """10^5 steps next to the separatrix: the conserved component's sign never changes
    (as for the exact solution), the energy error stays below |D0| / 4 and does not drift
    (criteria and their justification: module docstring)."""
    pi0, fixed = SIDES[side]
    other = 2 - fixed
    signs, exact_flips = _exact_side(pi0, fixed)
    # the exact solution: conserved component of one sign, the other one oscillating
    assert np.all(signs == 1.0) and exact_flips >= 4

    integ = compile_model(FREE_BODY, tableau=tableau, tau=tau, rkmk=rkmk)
    t0 = time.perf_counter()
    tr = integ.simulate(g0=np.eye(3), mu0=pi0, h=h, steps=STEPS, every=1)
    wall = time.perf_counter() - t0
    Pi = tr.mu
    E = 0.5 * np.sum(Pi**2 / FREE_INERTIA, axis=1)       # l = 1/2 xi.I xi: xi = p / I
    for k in range(0, STEPS + 1, 10_000):                 # hpgen's own energy agrees
        assert abs(integ.energy(tr.g[k], Pi[k]) - E[k]) <= 1e-13 * E[k]
    dE = E - E[0]
    D = 0.5 * (Pi[:, 0] ** 2 - Pi[:, 2] ** 2)
    first, last, slope = envelope_drift(tr.t, dE)
    flips_fixed, flips_other = _sign_changes(Pi[:, fixed]), _sign_changes(Pi[:, other])
    M2 = np.sum(Pi**2, axis=1)
    print(f"\n[separatrix] {tableau}/{tau}/{rkmk} h={h} {side}: D0={D[0]:+.3e}, "
          f"{STEPS} steps in {wall:.2f} s; max|dE| first tenth {first:.3e}, last tenth "
          f"{last:.3e}, slope*T {slope * tr.t[-1]:+.2e}; min D_k/D0 {np.min(D / D[0]):.4f}; "
          f"|M^2 - M0^2| max {np.abs(M2 - M2[0]).max():.1e}; sign changes: Pi{fixed + 1} "
          f"{flips_fixed} (exact: 0), Pi{other + 1} {flips_other} (exact: {exact_flips} "
          f"by t = 100); min |Pi{fixed + 1}| {np.abs(Pi[:, fixed]).min():.4f}")
    assert flips_fixed == 0 and np.all(np.sign(Pi[:, fixed]) == 1.0)
    assert flips_other >= 100
    assert np.max(np.abs(dE)) < abs(D[0]) / 4
    assert np.all(D / D[0] > 0.5)
    assert last <= 1.5 * first
    assert abs(slope) * tr.t[-1] < first
