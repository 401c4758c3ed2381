"""The constrained splitting step (``tableau: split2`` on examples/capsule_chain.yaml, N = 3;
hpgen.derive.family_split: RATTLE around kick / exact symmetric-top flow / kick, Newton on the
joints' multipliers only) against the chain's reference (DOP853 at 1e-13 on reduced
coordinates) and its own invariants (the hand-written scheme: tests/regression/
test_rattle_split.py).

- the module's unknowns are the multipliers alone (blocks lambda, nu; 2 x 3 rows per joint),
  and it is not an explicit module (Newton runs);
- the joints (positions and velocities, chain.constraint_residual) at every node to
  round-off (Newton to 1e-14 on rows that are sums of O(1) products), with both backends;
- order 2 (2.0 +- 0.2) of the error at T = 0.5, and order 4 (4.0 +- 0.4) of its suzuki4
  composition (integrator.compose), against the reference; order 2 and joints at round-off
  on an asymmetric chain (moments J set by --set-style parameters: DLM rotations for split2,
  Fasso's symmetric top + remainder for split2-fasso);
- the energy error stays bounded (no drift): the band over the second half of a run is not
  above the first half's by more than 50% (a symplectic scheme's band saturates).
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain as ch, hpgen_chain
from hpgen.bench.multibody.reference import solve

MODEL = ROOT / "examples" / "capsule_chain.yaml"
SPEC = ch.ChainSpec(3)


def _initial() -> ch.ChainState:
    qpos, qvel = ch.initial_joint_state(SPEC, seed=4, angle=0.5, rate=1.5)
    return ch.from_joint(SPEC, qpos, qvel)


@pytest.fixture(scope="module", params=["c", "python"])
def integ(request, compile_model):
    return compile_model(MODEL, parameters={"N": 3}, tableau="split2", backend=request.param)


def test_unknowns_are_the_multipliers(integ):
    assert integ.meta["unknowns"] == [["lambda", 0, 9], ["nu", 9, 18]]
    assert integ.meta.get("explicit") is not True


def test_joints_at_round_off(integ):
    g0, xi0 = hpgen_chain.to_hpgen(SPEC, _initial(), "centre")
    tr = integ.simulate(g0=g0, xi0=xi0, h=1e-2, steps=200, every=1)
    states = hpgen_chain.from_hpgen(SPEC, tr.g, tr.xi(), "centre")
    pos, vel = np.max([ch.constraint_residual(SPEC, s) for s in states], axis=0)
    assert pos < 1e-13 and vel < 1e-13, (pos, vel)


def _orders(integ, hs, T=0.5, spec=SPEC):
    qpos, qvel = ch.initial_joint_state(spec, seed=4, angle=0.5, rate=1.5)
    s0 = ch.from_joint(spec, qpos, qvel)
    ref = solve(spec, qpos, qvel, [T]).final
    g0, xi0 = hpgen_chain.to_hpgen(spec, s0, "centre")
    errs = []
    for h in hs:
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=round(T / h), every=1)
        states = hpgen_chain.from_hpgen(spec, tr.g, tr.xi(), "centre")
        pos, vel = np.max([ch.constraint_residual(spec, s) for s in states], axis=0)
        assert pos < 1e-13 and vel < 1e-13, (h, pos, vel)
        errs.append(ch.trajectory_error(states[-1], ref))
    return errs, np.log2(np.array(errs[:-1]) / np.array(errs[1:]))


def test_order_two(integ):
    errs, orders = _orders(integ, (4e-3, 2e-3, 1e-3))
    print("split2 errors", errs, "orders", orders)
    assert np.all(np.abs(orders - 2.0) <= 0.2), (errs, orders)


def test_order_four_composed(compile_model):
    integ = compile_model(MODEL, parameters={"N": 3}, tableau="split2", compose="suzuki4")
    errs, orders = _orders(integ, (2e-2, 1e-2, 5e-3))
    print("split2 + suzuki4 errors", errs, "orders", orders)
    assert np.all(np.abs(orders - 4.0) <= 0.4), (errs, orders)


@pytest.mark.parametrize("tableau", ["split2", "split2-fasso"])
def test_order_two_asymmetric_links(compile_model, tableau):
    J = (0.03, 0.02, 0.005)
    integ = compile_model(MODEL, parameters={"N": 3, "J": list(J)}, tableau=tableau)
    errs, orders = _orders(integ, (4e-3, 2e-3, 1e-3), spec=ch.ChainSpec(3, moments=J))
    print(f"{tableau}, moments {J}: errors", errs, "orders", orders)
    assert np.all(np.abs(orders - 2.0) <= 0.2), (errs, orders)


def test_energy_band_bounded(integ):
    g0, xi0 = hpgen_chain.to_hpgen(SPEC, _initial(), "centre")
    E = integ.simulate(g0=g0, xi0=xi0, h=1e-2, steps=4000, every=10).energy()
    dE = np.abs(E - E[0])
    half = len(E) // 2
    print(f"split2 energy band: first half {dE[:half].max():.2e}, second {dE[half:].max():.2e}")
    assert dE[half:].max() <= 1.5 * dE[:half].max()
