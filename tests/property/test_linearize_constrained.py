"""Integrator.linearize of a composed constrained step (hpgen.runtime.linearize): the double
spherical pendulum (constrained SV, suzuki4, nz = 24). C and Python agree (1e-11 relative:
nz > UNROLL_MAX, so the two runs' solutions differ by the Newton tolerance 1e-14, which
moves A by |dA/dz| 1e-14, and the solves by round-off times cond(J)), each backend
reproduces its own records bit for bit, and A is symplectic on the tangent space of the constraint manifold
{phi = 0, Phi xi = 0} (as tests/property/test_constraints.py for the plain step; relative
defect 1e-13, round-off)."""
from __future__ import annotations

import numpy as np

from hpgen.runtime import linearize as lz


def _rel(X, Y):
    return np.abs(X - Y).max() / np.abs(Y).max()


def test_composed_constrained_linearize(compile_model):
    """Double spherical pendulum (constrained SV, suzuki4): backends agree, records
    reproduced, A symplectic on the tangent space of the constraint manifold."""
    from scipy.linalg import null_space
    from hpgen.analysis.symplectic import ad_matrices, omega_matrix
    from hpgen.model import load_model
    from test_constraints import MODEL, _initial, _manifold_jacobian
    _, _, g0, xi0 = _initial()
    A, trs = {}, {}
    for b in ("c", "python"):
        integ = compile_model(MODEL, backend=b, compose="suzuki4")
        trs[b] = traj = integ.simulate(g0, 0.01, 6, xi0=xi0)
        A[b], st = lz.along_with_status(integ.engine, traj)
        assert st["deviation"] == 0.0, b
    assert np.abs(trs["c"].g - trs["python"].g).max() < 1e-13
    assert _rel(A["python"], A["c"]) < 1e-11
    model, tr = load_model(MODEL), trs["c"]
    ad = ad_matrices(model.group)
    for k in (0, 5):
        T = null_space(_manifold_jacobian(model, tr.g[k], tr.mu[k]))
        Ak, om1 = A["c"][k], omega_matrix(ad, tr.mu[k + 1])
        E = Ak.T @ om1 @ Ak - omega_matrix(ad, tr.mu[k])
        scale = np.linalg.norm(Ak, 2) ** 2 * np.linalg.norm(om1, 2)
        assert np.abs(T.T @ E @ T).max() / scale < 1e-13, k
