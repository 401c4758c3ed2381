"""Full Newton of a module whose Newton matrix is sparse (many bodies), as a chord iteration
within the step: the C runtime's hpgen_newton_chord (hpgen_newton.c), the same iteration and
tests (the linear algebra is hpgen.runtime.sparse's, which agrees with C's to round-off).

J is evaluated and factored at the step's first iterate; the next iterates solve with those
factors (one residual and one solve each) while they contract, and a kept J whose rate
theta = |dz| / |dz_prev| exceeds THETA_MAX is refreshed at the next iterate, unless |dz| is
at the round-off noise (at_floor) from the third iterate on. Nothing is kept across steps.
Stops: after a fresh J full Newton's (|dz| <= tol (1 + |z|), sparse_converged with a fresh
J); after a kept J sparse_converged's linear-rate bound asked of SIMPLIFIED_TOL tol, as
simplified Newton's (the error full Newton's stop leaves); either, |dz| stopped decreasing at
the round-off floor (ROUNDOFF_FLOOR (1 + |z|)). Inf-norms throughout.
"""
from __future__ import annotations

from ..abi import NO_CONVERGENCE, NONFINITE, OK, ROUNDOFF_FLOOR, SIMPLIFIED_TOL, THETA_MAX
from .newton_linalg import all_finite, norm_inf

_INF, _NAN = float("inf"), float("nan")


def solve_chord(kern, z, g, p, hv, tol: float, maxit: int):
    """The chord iteration from z (a list of floats) on kern.residual(z, g, p, hv) = 0 with
    kern.linear a sparse solver (hpgen.runtime.sparse). Returns (code, z (list), iterations,
    last residual inf-norm, Jacobian evaluations), as hpgen.runtime.newton.solve."""
    from .newton import at_floor, sparse_converged
    residual, both, jacobian = kern.residual, kern.residual_jacobian, kern.jacobian
    factor_solve, apply = kern.linear.factor_solve, kern.linear.apply
    dprev, jacs, F, kept, need_j = _INF, 0, None, None, True
    for it in range(1, maxit + 1):
        if need_j:
            jacs += 1
            if both is not None:
                F, J = both(z, g, p, hv)
            else:
                F = residual(z, g, p, hv)[0]
                J = jacobian(z, g, p, hv)[0]
            if not all_finite(F):
                return NONFINITE, z, it, norm_inf(F), jacs
            res = factor_solve(J, F, True)
            if res is None:
                return NONFINITE, z, it, norm_inf(F), jacs
            dz, kept = res
            need_j, fresh = False, True
        else:
            F = residual(z, g, p, hv)[0]
            if not all_finite(F):
                return NONFINITE, z, it, norm_inf(F), jacs
            dz = apply(kept, F)
            fresh = False
        z = [a - b for a, b in zip(z, dz)]
        dn, zn = norm_inf(dz), norm_inf(z)
        if not (dn < _INF and zn < _INF):
            return NONFINITE, z, it, norm_inf(F), jacs
        if it > 1 and dprev <= dn <= ROUNDOFF_FLOOR * (1.0 + zn):
            return OK, z, it, norm_inf(F), jacs
        if fresh and dn <= tol * (1.0 + zn):
            return OK, z, it, norm_inf(F), jacs
        if sparse_converged(it, dn, dprev, zn, tol if fresh else SIMPLIFIED_TOL * tol, fresh):
            return OK, z, it, norm_inf(F), jacs
        if not fresh and dn > THETA_MAX * dprev and not (it > 2 and at_floor(dn, zn)):
            need_j = True
        dprev = dn
    return NO_CONVERGENCE, z, maxit, (_NAN if F is None else norm_inf(F)), jacs
