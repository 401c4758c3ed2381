"""examples/pendulum_chain.yaml with N = 64 (nz = 768, 2d = 768): every C entry point whose
scratch grows like nz or 2d times nz runs in a process of its own (a stack overflow is a
failed test, not a crashed session) and returns finite results.

- the step: 20 steps of h = 1e-3, the joints' positions kept to round-off at every node;
- the linearization (hpgen_linearize, its step partials 3 x 2d x nz doubles): A of two steps
  has the shape (2, 2d, 2d) and is finite.
"""
from __future__ import annotations

import subprocess
import sys

import pytest

from conftest import ROOT

pytestmark = pytest.mark.slow

CHILD = r"""
import sys
import numpy as np
import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
n = 64
integ = hpgen.compile(sys.argv[1], parameters={"N": n})
spec = chain.ChainSpec(n)
qpos, qvel = chain.initial_joint_state(spec)
g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
tr = integ.simulate(g0, 1e-3, 20, xi0=xi0)
states = hpgen_chain.from_hpgen(spec, tr.g, tr.xi())
gap = max(chain.constraint_residual(spec, s)[0] for s in states)
A = integ.linearize(integ.simulate(g0, 1e-3, 2, xi0=xi0))
print(A.shape[0], A.shape[1], int(np.isfinite(A).all()), gap)
"""


def test_sixty_four_links_step_and_linearize():
    model = str(ROOT / "examples" / "pendulum_chain.yaml")
    out = subprocess.run([sys.executable, "-c", CHILD, model], capture_output=True, text=True,
                         cwd=ROOT, timeout=1200)
    assert out.returncode == 0, out.stderr[-2000:]
    k, rows, finite, gap = out.stdout.split()[-4:]
    assert (int(k), int(rows), int(finite)) == (2, 768, 1)
    assert float(gap) < 1e-12
