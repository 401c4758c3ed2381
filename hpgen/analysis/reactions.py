"""The multipliers (joint reactions) of a constrained model's steps, from recorded states.

A model with ``constraints:`` has the blocks ``lambda`` and ``nu`` among the step's unknowns
z (docs/numerics.md sec. 14): the impulses h lambda_k (at the start of step k,
fixed by phi(g_(k+1)) = 0) and h nu_(k+1) (at its end, fixed by the hidden constraint). The
runtime does not keep z, so ``reactions`` solves the step again from each recorded state (full
Newton from the guess kernel, tol 1e-14 relative, or until the correction stalls at round-off
below STALL_TOL) and reads the two blocks.

Convention: the constraint force in g* (body frame, the sign of the forces f) is
-Phi(g)^T lambda, Phi(g) eta = d/de phi(g exp(e eta)) at 0; for a joint written
phi = (point on body b) - (point on body a), lambda is minus the spatial force the joint
exerts on body b. The continuous multiplier at t_k is approximated to O(h^2) by
lambda_k + nu_k (the node's two impulses over h), and to O(h) by 2 lambda_k.
Closed models only (the step vector is [h]).
"""
from __future__ import annotations

import numpy as np

from ..errors import ConvergenceError

#: a Newton correction that stops decreasing below STALL_TOL (1 + |z|) is round-off
STALL_TOL = 1e-11


def _block(integ, label):
    for name, a, b in integ.meta["unknowns"]:
        if name == label:
            return a, b
    raise ValueError(f"the module {integ.meta.get('module')!r} has no {label!r} unknowns "
                     "(a model without constraints:)")


def step_unknowns(integ, g, p, h, tol=1e-14, maxit=50, k=0):
    """z of the step of size h from (g, p) (n x n, d), by full Newton from the guess kernel;
    k: the step's index in the error message."""
    gf = np.asarray(g, dtype=float).ravel(order="F")
    p = np.asarray(p, dtype=float)
    hv = np.array([h], dtype=float)
    z = np.asarray(integ.kernel("guess", integ.velocity(g, p), gf, p, hv)[0], dtype=float)
    nz, last = z.size, np.inf
    for _ in range(maxit):
        F, J = integ.kernel("residual_jacobian", z, gf, p, hv)
        dz = np.linalg.solve(np.asarray(J, dtype=float).reshape(nz, nz, order="F"),
                             np.asarray(F, dtype=float).ravel())
        z = z - dz
        dn, scale = np.abs(dz).max(), 1.0 + np.abs(z).max()
        # converged, or stalled at round-off (no longer decreasing, within STALL_TOL)
        if dn <= tol * scale or (dn >= last and dn <= STALL_TOL * scale):
            return z
        last = dn
    raise ConvergenceError("Newton did not converge re-solving the step", step=k,
                           time=k * h, residual=float(np.abs(np.asarray(F)).max()),
                           iterations=maxit)


def reactions(integ, g, p, h):
    """(lam, nu): arrays (K, m) with lambda_k and nu_(k+1) of the step of size h from each of
    the K states (g[k], p[k]) (e.g. a trajectory's ``g`` and ``mu`` recorded with every=1)."""
    la, lb = _block(integ, "lambda")
    na, nb = _block(integ, "nu")
    lam, nu = [], []
    for k, (gk, pk) in enumerate(zip(g, p)):
        z = step_unknowns(integ, gk, pk, h, k=k)
        lam.append(z[la:lb] / h)
        nu.append(z[na:nb] / h)
    return np.array(lam), np.array(nu)
