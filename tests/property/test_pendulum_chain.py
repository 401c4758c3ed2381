"""examples/pendulum_chain.yaml (N = 2) against hpgen.bench.multibody's independent reference
(reduced coordinates, DOP853 at rtol 1e-13) and its conventions.

State conversion: the example's frame of link i is its link frame moved along the link's
axis so that every frame is the world frame when the chain hangs straight down: the centre
of mass is X_i = x_i + R_i p_i with p_i = (i + 1/2) b, b = (0, 0, -length) in the link
frame. SE3's xi = (omega, v) is in the body frame: omega is the chain's body angular velocity
and the centre's world velocity is R_i (v + omega x p_i).

- energy: the example's energy (from its Lagrangian) equals hpgen.bench.multibody.chain's
  kinetic + potential energy of the converted state to round-off, at every node.
- order 2 (2.0 +- 0.2) of constrained Stormer-Verlet (truncated RKMK) at T = 0.5.
- the joints (positions and velocities, chain.constraint_residual) at every node to
  round-off (Newton to 1e-14; rows are sums of O(1) products).
- energy bounded without drift over 2e4 steps; the vertical angular momentum (the spatial
  momentum's e3 components summed over the links: l and the joints are invariant under
  rotations about e3 through the pin) kept to round-off (discrete Noether).
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain as ch, hpgen_chain
from hpgen.bench.multibody.reference import solve

MODEL = ROOT / "examples" / "pendulum_chain.yaml"
SPEC = ch.ChainSpec(2)


def _rotvec(w):
    from scipy.spatial.transform import Rotation
    return Rotation.from_rotvec(w).as_matrix()


def _initial() -> ch.ChainState:
    """A generic admissible state: both links tilted and spinning."""
    R = np.array([_rotvec([0.6, -0.3, 0.2]), _rotvec([-0.4, 0.8, 0.5])])
    return ch.from_rotations(SPEC, R, np.array([[1.0, -0.5, 2.0], [-1.5, 0.7, -1.0]]))


def to_hpgen(s: ch.ChainState):
    """(g (8 x 8), xi (12,)) of a chain state (the benchmark's conversion)."""
    return hpgen_chain.to_hpgen(SPEC, s)


def from_hpgen(g, xi) -> ch.ChainState:
    return hpgen_chain.from_hpgen(SPEC, np.asarray(g)[None], np.asarray(xi)[None])[0]


def _distance(a: ch.ChainState, b: ch.ChainState) -> float:
    return max(np.abs(a.R - b.R).max(), np.abs(a.x - b.x).max(),
               np.abs(a.omega - b.omega).max(), np.abs(a.v - b.v).max())


@pytest.fixture(scope="module")
def integ(compile_model):
    return compile_model(MODEL, backend="c")


def test_conversion_round_trip_and_admissible_start():
    s = _initial()
    back = from_hpgen(*to_hpgen(s))
    assert _distance(s, back) < 1e-15
    assert max(ch.constraint_residual(SPEC, s)) < 1e-15


def test_energy_is_the_benchmark_chains(integ):
    g0, xi0 = to_hpgen(_initial())
    tr = integ.simulate(g0=g0, xi0=xi0, h=1e-3, steps=200, every=20)
    E = tr.energy()
    ref = [sum(ch.energy(SPEC, from_hpgen(g, xi))) for g, xi in zip(tr.g, tr.xi())]
    assert np.abs(E - ref).max() < 1e-12 * np.abs(ref).max()


def test_order_two_against_the_reduced_coordinate_reference(integ):
    s0 = _initial()
    T = 0.5
    ref = solve(SPEC, *ch.to_joint(SPEC, s0), [T]).final
    g0, xi0 = to_hpgen(s0)
    errs = []
    for h in (4e-3, 2e-3, 1e-3):
        steps = round(T / h)
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=steps, every=1)
        states = [from_hpgen(g, xi) for g, xi in zip(tr.g, tr.xi())]
        pos, vel = np.max([ch.constraint_residual(SPEC, s) for s in states], axis=0)
        assert pos < 1e-13 and vel < 1e-12, (h, pos, vel)
        errs.append(_distance(states[-1], ref))
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    assert np.all(np.abs(orders - 2.0) <= 0.2), (errs, orders)


def test_energy_bounded_and_vertical_momentum_kept(integ):
    g0, xi0 = to_hpgen(_initial())
    tr = integ.simulate(g0=g0, xi0=xi0, h=1e-3, steps=20_000, every=10)
    E = tr.energy()
    scale = np.abs(E).max()
    band = (E.max() - E.min()) / scale
    half = len(E) // 2
    drift = abs(E[half:].mean() - E[:half].mean()) / scale
    assert band < 1e-4 and drift < 0.1 * band, (band, drift)
    J = tr.momentum()
    Lz = J[:, 2] + J[:, 8]
    assert np.abs(Lz - Lz[0]).max() <= 1e-12 * np.abs(tr.mu).max()
