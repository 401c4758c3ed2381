"""A chain written as a family (SO3^N, sums over bodies) gives the same Lagrangian and bitwise
the same step as the same chain written out by hand on the product group (xi_k, R_k)."""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.model import load_model_text
from tests.conftest import EXAMPLES

# examples/double_body_chain.yaml as a family: per-body inertia, weight, centre of mass and
# spring points, the spring between consecutive bodies
FAMILY = """
name: chain_family
group: SO3^N
parameters:
  N: {n}
  I: {I}
  mg: {mg}
  c: {c}
  a: {a}
  d: 1.3
  k: 4.0
  e3: [0, 0, 1]
lagrangian: >-
  sum(i, 0.5*dot(I[i]*w[i], w[i]) - mg[i]*(R[i] @ c[i])[2])
  - sum(i, 1, N, 0.5*k*norm2(R[i-1] @ a[i-1] - R[i] @ a[i] + d*e3))
integrator: {{tableau: stormer-verlet, tau: cay, rkmk: truncated}}
"""

# the three-body chain written out by hand, in the style of examples/double_body_chain.yaml
HAND3 = """
name: chain_hand
group: [SO3, SO3, SO3]
parameters: {I0: [0.9, 1.0, 0.2], I1: [0.6, 0.5, 0.15], I2: [0.5, 0.4, 0.1], m0g: 2.0,
             m1g: 1.5, m2g: 1.0, c0: [0.05, 0.0, -0.5], c1: [0.0, 0.04, -0.4],
             c2: [0.0, 0.0, -0.3], a0: [0.1, 0.05, -1.0], a1: [0.0, 0.1, 0.3],
             a2: [0.02, 0.0, 0.2], d: 1.3, k: 4.0}
lagrangian: >-
  0.5*(I0[0]*xi_0[0]**2 + I0[1]*xi_0[1]**2 + I0[2]*xi_0[2]**2)
  - m0g*(R_0[2,0]*c0[0] + R_0[2,1]*c0[1] + R_0[2,2]*c0[2])
  + 0.5*(I1[0]*xi_1[0]**2 + I1[1]*xi_1[1]**2 + I1[2]*xi_1[2]**2)
  - m1g*(R_1[2,0]*c1[0] + R_1[2,1]*c1[1] + R_1[2,2]*c1[2])
  + 0.5*(I2[0]*xi_2[0]**2 + I2[1]*xi_2[1]**2 + I2[2]*xi_2[2]**2)
  - m2g*(R_2[2,0]*c2[0] + R_2[2,1]*c2[1] + R_2[2,2]*c2[2])
  - 0.5*k*((R_0[0,0]*a0[0] + R_0[0,1]*a0[1] + R_0[0,2]*a0[2] - R_1[0,0]*a1[0] - R_1[0,1]*a1[1] - R_1[0,2]*a1[2])**2
  + (R_0[1,0]*a0[0] + R_0[1,1]*a0[1] + R_0[1,2]*a0[2] - R_1[1,0]*a1[0] - R_1[1,1]*a1[1] - R_1[1,2]*a1[2])**2
  + (R_0[2,0]*a0[0] + R_0[2,1]*a0[1] + R_0[2,2]*a0[2] - R_1[2,0]*a1[0] - R_1[2,1]*a1[1] - R_1[2,2]*a1[2] + d)**2)
  - 0.5*k*((R_1[0,0]*a1[0] + R_1[0,1]*a1[1] + R_1[0,2]*a1[2] - R_2[0,0]*a2[0] - R_2[0,1]*a2[1] - R_2[0,2]*a2[2])**2
  + (R_1[1,0]*a1[0] + R_1[1,1]*a1[1] + R_1[1,2]*a1[2] - R_2[1,0]*a2[0] - R_2[1,1]*a2[1] - R_2[1,2]*a2[2])**2
  + (R_1[2,0]*a1[0] + R_1[2,1]*a1[1] + R_1[2,2]*a1[2] - R_2[2,0]*a2[0] - R_2[2,1]*a2[1] - R_2[2,2]*a2[2] + d)**2)
integrator: {tableau: stormer-verlet, tau: cay, rkmk: truncated}
"""

BODIES = {"I": [[0.9, 1.0, 0.2], [0.6, 0.5, 0.15], [0.5, 0.4, 0.1]], "mg": [2.0, 1.5, 1.0],
          "c": [[0.05, 0.0, -0.5], [0.0, 0.04, -0.4], [0.0, 0.0, -0.3]],
          "a": [[0.1, 0.05, -1.0], [0.0, 0.1, 0.3], [0.02, 0.0, 0.2]]}


def family_text(n: int) -> str:
    return FAMILY.format(n=n, **{k: v[:n] for k, v in BODIES.items()})


def hand_text(n: int):
    return (EXAMPLES / "double_body_chain.yaml").read_text() if n == 2 else HAND3


def _rotation(rotvec):
    from scipy.spatial.transform import Rotation
    return Rotation.from_rotvec(rotvec).as_matrix()


@pytest.mark.parametrize("n", [2, 3])
def test_family_lagrangian_is_the_hand_written_one(n):
    fam = load_model_text(family_text(n), "family.yaml")
    hand = load_model_text(hand_text(n), "hand.yaml")
    assert fam.xi_symbols == hand.xi_symbols and fam.g_symbols == hand.g_symbols
    assert fam.lagrangian == hand.lagrangian            # the same sympy tree


@pytest.mark.parametrize("n", [2, 3])
def test_family_step_is_the_hand_written_step(n, compile_model):
    fam = compile_model(family_text(n), backend="python")
    hand = compile_model(hand_text(n), backend="python")
    rng = np.random.default_rng(7)
    g0 = np.zeros((3 * n, 3 * n))
    for k in range(n):
        g0[3 * k:3 * k + 3, 3 * k:3 * k + 3] = _rotation(rng.normal(size=3) * 0.5)
    xi0 = rng.normal(size=3 * n)
    a = fam.simulate(g0=g0, xi0=xi0, h=0.01, steps=50)
    b = hand.simulate(g0=g0, xi0=xi0, h=0.01, steps=50)
    # sympy keeps sums in a canonical order: the family's Lagrangian is the hand-written one
    # term for term, so the derived kernels and the states are bitwise the same
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
