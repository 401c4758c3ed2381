"""Regression: the constrained ``split2`` step of examples/capsule_chain.yaml (N = 3,
hpgen.derive.family_split) against the hand-written RATTLE with the exact symmetric-top flow
(tests/handwritten/rattle_split.py, NumPy only), both backends.

- local: one hand-written step from hpgen's node k against hpgen's node k + 1 (the maps
  themselves), every k of a 50-step run at h = 1e-2;
- global: 50 hand-written steps from hpgen's start against hpgen's nodes.
Both sides solve their multipliers to round-off (hpgen: Newton to 1e-14 relative; the
hand-written chord to 1e-15 on the joints' gaps) and evaluate the same flows with
differently ordered formulas: measured local 9e-15, global 2e-14 on entries of size <= 3.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from handwritten.rattle_split import Chain
from hpgen.bench.multibody import chain as ch, hpgen_chain

MODEL = ROOT / "examples" / "capsule_chain.yaml"
SPEC = ch.ChainSpec(3)
#: round-off of O(1) entries after a step (local) and after a 50-step run (global)
LOCAL_TOL, GLOBAL_TOL = 1e-13, 1e-12


@pytest.fixture(scope="module", params=["c", "python"])
def integ(request, compile_model):
    return compile_model(MODEL, parameters={"N": 3}, tableau="split2", backend=request.param)


def _hand(g, mu):
    """(x world, P world, R, pi) of an hpgen node (frames at the centres)."""
    n = SPEC.n
    place = np.array([[0.0, 0.0, -(i + 0.5) * SPEC.length] for i in range(n)])
    R = np.array([g[4 * i:4 * i + 3, 4 * i:4 * i + 3] for i in range(n)])
    x = np.array([g[4 * i:4 * i + 3, 4 * i + 3] for i in range(n)]) + place
    m = mu.reshape(n, 6)
    return x, np.einsum("nij,nj->ni", R, m[:, 3:]), R, m[:, :3]


def _gap(a, b) -> float:
    return max(float(np.abs(u - v).max()) for u, v in zip(a, b))


def test_split2_is_the_hand_written_rattle(integ):
    qpos, qvel = ch.initial_joint_state(SPEC, seed=4, angle=0.5, rate=1.5)
    g0, xi0 = hpgen_chain.to_hpgen(SPEC, ch.from_joint(SPEC, qpos, qvel), "centre")
    h, steps = 1e-2, 50
    tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=steps, every=1)
    hw = Chain(SPEC.n, SPEC.mass, SPEC.inertia, SPEC.a, SPEC.g)
    s = _hand(tr.g[0], tr.mu[0])
    local = glob = 0.0
    for k in range(steps):
        s = hw.step(*s, h)
        node = _hand(tr.g[k + 1], tr.mu[k + 1])
        glob = max(glob, _gap(s, node))
        local = max(local, _gap(hw.step(*_hand(tr.g[k], tr.mu[k]), h), node))
    print(f"split2 vs hand-written RATTLE: local {local:.1e}, global {glob:.1e}")
    assert local < LOCAL_TOL and glob < GLOBAL_TOL
