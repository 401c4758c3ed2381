"""The splitting schemes as compositions of first-order half-steps phi, phi*
(hpgen.splitting.coefficients, hpgen.splitting.flows.schedule).

- Catalog: every scheme's halves are a palindrome (the scheme is symmetric) summing to 1 to
  round-off; a symmetric composition of S has the halves (gamma_1/2, gamma_1/2, ...).
- The schedule: S(t) = phi(t/2) phi*(t/2) merges to K X1 X2 X3(t) X2 X1 K per stage (the
  heavy top's split6-kahan-li: 45 rotations, 10 kicks a step); between two kicks each factor's
  rotations are grouped (two bodies: 5 rotations per body per stage), so no rotation is
  split in two.
- Measured orders of the phi/phi* compositions (McLachlan 4, Blanes-Moan 4 and 6) against the
  exact free rigid body (measured slopes 3.98-4.00, 5.96-6.00) and on the heavy top (kicks
  between the rotations) against split8-kahan-li at h = 0.01: the slope between two step
  sizes in the asymptotic range is the catalog order within 0.15.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.analysis.exact import free_rigid_body_attitude
from hpgen.splitting import SPLITTING_NAMES, get_splitting

HEAVY_TOP, FREE_BODY = EXAMPLES / "heavy_top.yaml", EXAMPLES / "free_rigid_body.yaml"
TWO_BODIES = EXAMPLES / "double_body_chain.yaml"
NEW = ("split4-mclachlan", "split4-blanes-moan", "split6-blanes-moan")


@pytest.mark.parametrize("name", SPLITTING_NAMES)
def test_halves_are_a_consistent_palindrome(name):
    s = get_splitting(name)
    c = s.halves
    assert c == c[::-1] and len(c) == 2 * s.stages
    assert abs(math.fsum(c) - 1.0) <= 4 * 2.0 ** -52 * max(map(abs, c)) * len(c)
    if s.gammas:
        assert c == tuple(x / 2 for x in s.gammas for _ in range(2))
    assert s.order in (2, 4, 6, 8)


def _ops(path, name):
    from hpgen.derive.lagrangian import lagrangian_function
    from hpgen.model import load_model
    from hpgen.splitting.flows import schedule
    from hpgen.splitting.structure import recognise
    model = load_model(path)
    lag = lagrangian_function(model)
    return schedule(recognise(model, lag), get_splitting(name), True)


def test_schedule_of_a_symmetric_composition():
    ops = _ops(HEAVY_TOP, "split6-kahan-li")
    assert sum(o[0] == "rot" for o in ops) == 45 and sum(o[0] == "kick" for o in ops) == 10
    s = get_splitting("split6-kahan-li")
    g = s.gammas[0]
    assert ops[:7] == [("kick", -1, 0, g / 2), ("rot", 0, 0, g / 2), ("rot", 0, 1, g / 2),
                       ("rot", 0, 2, g), ("rot", 0, 1, g / 2), ("rot", 0, 0, g / 2),
                       ("kick", -1, 0, g / 2 + s.gammas[1] / 2)]
    # two bodies: between two kicks each body's five rotations, the middle one merged
    ops = _ops(TWO_BODIES, "split2")
    assert [o[:3] for o in ops] == [("kick", -1, 0)] + [
        ("rot", k, a) for k in (0, 1) for a in (0, 1, 2, 1, 0)] + [("kick", -1, 0)]
    # McLachlan's method starts with phi*: rotations first, the kicks inside
    ops = _ops(HEAVY_TOP, "split4-mclachlan")
    assert ops[0][0] == "rot" and ops[-1][0] == "rot"
    assert sum(o[0] == "kick" for o in ops) == 5


@pytest.mark.parametrize("name,tol", [(n, 0.1) for n in NEW] + [
    ("split2-fasso", 0.15), ("split4-blanes-moan-fasso", 0.15), ("split6-blanes-moan-fasso", 0.15)])
def test_measured_order_against_the_exact_free_body(compile_model, name, tol):
    integ = compile_model(FREE_BODY, tableau=name)
    inertia = np.array([2.0, 1.0, 0.6666666666666666])
    pi0 = np.array([math.cos(1.1), 0.0, math.sin(1.1)])
    T = 10.0
    RT, piT = (a[-1] for a in free_rigid_body_attitude(inertia, pi0, np.eye(3), [0.0, T]))
    errs = []
    for h in (0.25, 0.125):
        N = round(T / h)
        tr = integ.simulate(np.eye(3), h, N, mu0=pi0, every=N)
        errs.append(max(np.abs(tr.g[-1] - RT).max(), np.abs(tr.mu[-1] - piT).max()))
    slope = math.log2(errs[0] / errs[1])
    assert abs(slope - get_splitting(name).order) <= tol, (name, errs, slope)


@pytest.mark.parametrize("name", NEW)
def test_measured_order_on_the_heavy_top(compile_model, name):
    from hpgen.groups.elements import rotation_from_rotvec
    g0, xi0, T = rotation_from_rotvec([0.3, 0.2, 0.0]), np.array([0.2, 1.0, 3.0]), 2.0
    ref = compile_model(HEAVY_TOP, tableau="split8-kahan-li").simulate(
        g0, 0.01, round(T / 0.01), xi0=xi0, every=round(T / 0.01))
    integ = compile_model(HEAVY_TOP, tableau=name)
    errs = []
    for h in (0.05, 0.025):
        N = round(T / h)
        tr = integ.simulate(g0, h, N, xi0=xi0, every=N)
        errs.append(max(np.abs(tr.g[-1] - ref.g[-1]).max(), np.abs(tr.mu[-1] - ref.mu[-1]).max()))
    slope = math.log2(errs[0] / errs[1])
    assert abs(slope - get_splitting(name).order) <= 0.15, (name, errs, slope)
