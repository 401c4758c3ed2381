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


# ---- N from the command line ----------------------------------------------------------------
TINY = """name: springs
group: R1^N
parameters: {N: 2, k: 1.0}
lagrangian: sum(i, 0.5*norm2(v[i])) - 0.5*k*x[0][0]**2 - sum(i, 1, N, 0.5*k*(x[i][0] - x[i-1][0])**2)
scene:
  h: 0.01
  steps: 10
  initial: {g: {position: [0.1]}, xi: [0.0]}
  record: [g, mu, energy]
"""


def _cli(*argv, cwd):
    import os
    import subprocess
    import sys
    from tests.conftest import ROOT
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "hpgen", *argv], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def test_cli_set_n(tmp_path, cache_dir):
    (tmp_path / "springs.yaml").write_text(TINY)
    for n in (2, 3):
        out = tmp_path / f"n{n}.npz"
        p = _cli("run", "springs.yaml", "--set", f"N={n}", "--backend", "python", "--out",
                 str(out), "--no-plot", "--no-progress", "--cache-dir", str(cache_dir),
                 cwd=tmp_path)
        assert p.returncode == 0, p.stderr
        with np.load(out) as data:
            assert data["mu"].shape == (11, n)
    p = _cli("run", "springs.yaml", "--set", "K=3", "--backend", "python", "--cache-dir",
             str(cache_dir), cwd=tmp_path)
    assert p.returncode == 2 and p.stderr.count("\n") == 1
    assert "springs.yaml: parameters.K: cannot set 'K'" in p.stderr
    p = _cli("compile", "springs.yaml", "--set", "N=0", "--backend", "python", "--cache-dir",
             str(cache_dir), cwd=tmp_path)
    assert p.returncode == 2 and "parameters.N:" in p.stderr and "positive integer" in p.stderr


def test_api_parameters_enter_the_module(tmp_path, cache_dir):
    import hpgen
    path = tmp_path / "springs.yaml"
    path.write_text(TINY)
    two = hpgen.build(path, backend="python", cache_dir=cache_dir)
    four = hpgen.build(path, backend="python", cache_dir=cache_dir, parameters={"N": 4})
    assert two.meta["hash"] != four.meta["hash"] and four.meta["d"] == 4
    assert "N: 4" in (four.module_dir / "model.yaml").read_text()
