"""examples/capsule_chain.yaml (frames at the link centres; N = 3) against
hpgen.bench.multibody's independent reference (reduced coordinates, DOP853 at rtol 1e-13) and
against examples/pendulum_chain.yaml (the same chain, frames at the pin).

The two files' states are related by a constant translation on each side of g (pin frames:
g_pin = g_world (I, -p_i); centre frames: g_centre = (I, -c_i) g_world, g_world the link frame
at its centre in the world), and the Cayley step is equivariant under both (cay(Ad_k X) =
k cay(X) k^-1 for a matrix group), so constrained Stormer-Verlet gives the same trajectory in
both files up to round-off: the frame's origin changes the conditioning of the step's
linear algebra (the 6 x 6 body inertia), not its discretization.

- the same nodes as the pin-frame file (max over the states' entries), to 1e-12 over 250
  steps (round-off of O(1) entries, amplified by a short chaotic run);
- the file's energy (its Lagrangian's, potential zero at the pin) equals the chain's
  kinetic + potential energy of the converted state to round-off at every node;
- order 2 (2.0 +- 0.2) of the error at T = 0.5 against the reference, and the joints
  (positions and velocities, chain.constraint_residual) at every node to round-off (Newton to
  1e-14; rows are sums of O(1) products);
- the scene (a straight chain, velocity projected onto the joints) holds for any N.
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
    """A generic admissible state: every link tilted and spinning."""
    qpos, qvel = ch.initial_joint_state(SPEC, seed=4, angle=0.5, rate=1.5)
    return ch.from_joint(SPEC, qpos, qvel)


def _states(tr, frames="centre"):
    return hpgen_chain.from_hpgen(SPEC, tr.g, tr.xi(), frames)


def _distance(a: ch.ChainState, b: ch.ChainState) -> float:
    return max(np.abs(a.R - b.R).max(), np.abs(a.x - b.x).max(),
               np.abs(a.omega - b.omega).max(), np.abs(a.v - b.v).max())


@pytest.fixture(scope="module")
def integ(compile_model):
    return compile_model(MODEL, parameters={"N": 3})


def test_same_nodes_as_the_pin_frame_file(integ, compile_model):
    pin = compile_model(hpgen_chain.MODEL, parameters={"N": 3})
    s0 = _initial()
    runs = {}
    for frames, it in (("centre", integ), ("pin", pin)):
        g0, xi0 = hpgen_chain.to_hpgen(SPEC, s0, frames)
        runs[frames] = _states(it.simulate(g0=g0, xi0=xi0, h=2e-3, steps=250, every=5), frames)
    gap = max(_distance(a, b) for a, b in zip(runs["centre"], runs["pin"]))
    moved = _distance(runs["centre"][0], runs["centre"][-1])
    print(f"centre vs pin frames: {gap:.1e} (the state moved by {moved:.2f})")
    assert moved > 0.5 and gap < 1e-12


def test_energy_is_the_benchmark_chains(integ):
    g0, xi0 = hpgen_chain.to_hpgen(SPEC, _initial(), "centre")
    tr = integ.simulate(g0=g0, xi0=xi0, h=1e-3, steps=200, every=20)
    ref = [sum(ch.energy(SPEC, s)) for s in _states(tr)]
    assert np.abs(tr.energy() - ref).max() < 1e-13 * np.abs(ref).max()


def test_order_two_and_joints_at_round_off(integ):
    s0 = _initial()
    T = 0.5
    ref = solve(SPEC, *ch.to_joint(SPEC, s0), [T]).final
    g0, xi0 = hpgen_chain.to_hpgen(SPEC, s0, "centre")
    errs = []
    for h in (4e-3, 2e-3, 1e-3):
        steps = round(T / h)
        states = _states(integ.simulate(g0=g0, xi0=xi0, h=h, steps=steps, every=1))
        pos, vel = np.max([ch.constraint_residual(SPEC, s) for s in states], axis=0)
        assert pos < 1e-13 and vel < 1e-13, (h, pos, vel)
        errs.append(ch.trajectory_error(states[-1], ref))
    orders = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    print("capsule_chain N = 3 errors", errs, "orders", orders)
    assert np.all(np.abs(orders - 2.0) <= 0.2), (errs, orders)


@pytest.mark.parametrize("n", [2, 10, 32])
def test_the_scene_holds_for_any_n(n):
    from hpgen.model import load_model_text
    from hpgen.model.constraints import constraint_values
    from hpgen.model.overrides import apply_overrides
    model = load_model_text(apply_overrides(MODEL.read_text(), {"N": n}), str(MODEL))
    sc = model.scene
    phi, Phi, _ = constraint_values(model.constraints, model.g_symbols, model.group,
                                    np.array(sc.g0))
    assert np.abs(phi).max() == 0.0 and np.abs(Phi @ np.asarray(sc.xi0)).max() < 1e-12
    assert sc.projection.moved_xi > 1.0          # the links' common spin was projected
