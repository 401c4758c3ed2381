"""Full Newton of a module whose Newton matrix is sparse (many bodies): the C runtime's
hpgen_newton_sparse (hpgen_newton_sparse.c), the same iteration and stop tests; the linear algebra
is hpgen.runtime.sparse's, which agrees with C's to round-off.

CHORD (hpgen_runtime.h HPGEN_SPARSE_CHORD): J and its factors at the step's first iterate; the
next iterates one residual and one solve each while they contract; a kept J whose rate
theta = |dz| / |dz_prev| exceeds THETA_MAX (and that is no round-off stall) is evaluated again
at the next iterate. Nothing is kept across steps. Stops (inf-norms): |dz| stopped decreasing
while <= ROUNDOFF_FLOOR (1 + |z|); after a fresh J |dz| <= tol (1 + |z|) and
hpgen.runtime.newton.sparse_converged (quadratic rate); after a kept J chord_converged (the
chord's rate bound; RATE_STOP = False: sparse_converged asked of SIMPLIFIED_TOL tol, simplified
Newton's bound); the round-off stall (``stalled``). A pass that wanders (``wanders``) fails.
"""
from __future__ import annotations

from ..abi import (KEEP_J_FLOOR, NO_CONVERGENCE, NONFINITE, OK, ROUNDOFF_FLOOR, SIMPLIFIED_TOL,
                   STALL_MAX, THETA_FLOOR, THETA_MAX)
from .newton_linalg import all_finite, fresh_solve, norm_inf

_INF, _NAN = float("inf"), float("nan")

#: the C runtime's HPGEN_SPARSE_CHORD default: J once a step (refreshed on a poor rate)
CHORD = True
#: the C runtime's HPGEN_CHORD_RATE_STOP default: a kept J stops on chord_converged
RATE_STOP = True


def sparse_converged(it: int, dn: float, dprev: float, zn: float, tol: float,
                     fresh_j: bool) -> bool:
    """The extra stop of a module whose Newton matrix is sparse (many bodies), hpgen_newton.c's
    hpgen_sparse_converged: the error left, estimated from theta = |dz| / |dz_prev|, is
    <= tol (1 + |z|): after an iterate with a fresh J theta^2 |dz| (quadratic convergence),
    with theta |dz| <= ROUNDOFF_FLOOR (1 + |z|); with a kept J te/(1 - te) |dz|,
    te = max(theta, THETA_FLOOR), with |dz| <= ROUNDOFF_FLOOR (1 + |z|).
    The round-off in dz of a many-body step is itself about tol (1 + |z|) and grows with the
    number of bodies: the dense modules' tests end there only when |dz| stagnates."""
    if it < 2:
        return False
    th = dn / dprev
    if not th < 1.0:
        return False
    if fresh_j:
        return th * dn <= ROUNDOFF_FLOOR * (1.0 + zn) and th * th * dn <= tol * (1.0 + zn)
    if not dn <= ROUNDOFF_FLOOR * (1.0 + zn):
        return False
    te = th if th > THETA_FLOOR else THETA_FLOOR
    return te / (1.0 - te) * dn <= tol * (1.0 + zn)


def at_floor(dn: float, zn: float) -> bool:
    """hpgen_newton.c's hpgen_at_floor: from a step's third iterate on, a sparse module's
    simplified Newton keeps its J once |dz| <= KEEP_J_FLOOR (1 + |z|) (a rate above
    THETA_MAX there neither refreshes J nor switches to full Newton; the iterates go on to a
    stop test): a many-body step's corrections at that level are noise of ratio O(1), which
    a fresh J cannot contract. The rate of the first two corrections, taken while the
    start's error dominates, still decides on a refresh."""
    return dn <= KEEP_J_FLOOR * (1.0 + zn)


def chord_converged(it: int, dn: float, dprev: float, zn: float, tol: float) -> bool:
    """hpgen_newton_sparse.c's hpgen_chord_converged: from the second iterate on, the chord's rate
    theta = |dz| / |dz_prev| < 1 bounds the error left by theta / (1 - theta) |dz|; stop when
    that is <= tol (1 + |z|) with |dz| <= ROUNDOFF_FLOOR (1 + |z|). The chord's J was evaluated
    at the step's own start, so its rate is uniform over the directions (no slow mode behind
    the fast ones, as with a J kept across steps)."""
    if it < 2:
        return False
    th = dn / dprev
    return (th < 1.0 and dn <= ROUNDOFF_FLOOR * (1.0 + zn)
            and th / (1.0 - th) * dn <= tol * (1.0 + zn))


def stalled(it: int, dn: float, dprev: float, zn: float, fresh: bool,
            contracted: bool) -> bool:
    """hpgen_newton_sparse.c's hpgen_stalled: dz_k is the round-off noise of the step's solution when
    theta_k = |dz_k| / |dz_{k-1}| > THETA_MAX and |dz_k| <= STALL_MAX (1 + |z_k|) with a J that
    contracts (fresh: evaluated at z_{k-1}; or one under which the step's iterates contracted,
    theta <= THETA_MAX once). The noise level is the data's (where the corrections stop
    contracting; it grows with cond(J)); STALL_MAX only bounds it."""
    return (it > 1 and (fresh or contracted) and dn > THETA_MAX * dprev
            and dn <= STALL_MAX * (1.0 + zn))


def wanders(dn: float, d1: float, zn: float) -> bool:
    """hpgen_newton_sparse.c's hpgen_wanders: a correction larger than the pass's first one, above
    the noise (> STALL_MAX (1 + |z|)), leaves the start's Newton basin; where such iterates
    end is a root of F that need not be the step's. The pass fails and the next route (J at
    every iterate from the same start, then the run's plain warm start) takes the step."""
    return dn > d1 and dn > STALL_MAX * (1.0 + zn)


def solve_sparse(kern, z, g, p, hv, tol: float, maxit: int, chord: bool = CHORD):
    """Full Newton from z (a list of floats) on kern.residual(z, g, p, hv) = 0 with kern.linear
    a sparse solver (hpgen.runtime.sparse): the chord pass (solve_pass), and if it fails a
    second pass with J at every iterate from the same z (hpgen_newton_sparse.c's
    hpgen_newton_sparse). Returns (code, z (list), iterations of both passes, last residual
    inf-norm, Jacobian evaluations of both), as hpgen.runtime.newton.solve."""
    out = solve_pass(kern, z, g, p, hv, tol, maxit, chord)
    if not chord or out[0] == OK or out[2] <= 1:     # a first iterate is the same in both
        return out
    again = solve_pass(kern, z, g, p, hv, tol, maxit, False)
    return again[0], again[1], out[2] + again[2], again[3], out[4] + again[4]


def solve_pass(kern, z, g, p, hv, tol: float, maxit: int, chord: bool):
    """One pass of hpgen_newton_sparse.c's hpgen_newton_sparse_pass (chord: J once a step, refreshed
    on a poor rate; else J at every iterate): (code, z, iterations, residual, J evaluations)."""
    residual, apply = kern.residual, kern.linear.apply
    dprev, d1, jacs, F, kept = _INF, _INF, 0, None, None
    need_j, fresh, contracted = True, False, False
    for it in range(1, maxit + 1):
        if need_j:
            jacs += 1
            F, res = fresh_solve(kern, z, g, p, hv, chord)
            if res is None:
                return NONFINITE, z, it, norm_inf(F), jacs
            dz, kept = res
            need_j, fresh = not chord, True
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
        if it == 1:
            d1 = dn
        elif wanders(dn, d1, zn):
            return NO_CONVERGENCE, z, it, norm_inf(F), jacs
        if it > 1 and dprev <= dn <= ROUNDOFF_FLOOR * (1.0 + zn):
            return OK, z, it, norm_inf(F), jacs
        if fresh and dn <= tol * (1.0 + zn):
            return OK, z, it, norm_inf(F), jacs
        if (sparse_converged(it, dn, dprev, zn, tol, True) if fresh
                else chord_converged(it, dn, dprev, zn, tol) if RATE_STOP
                else sparse_converged(it, dn, dprev, zn, SIMPLIFIED_TOL * tol, False)):
            return OK, z, it, norm_inf(F), jacs
        if stalled(it, dn, dprev, zn, fresh, contracted):
            return OK, z, it, norm_inf(F), jacs
        if it > 1 and dn <= THETA_MAX * dprev:
            contracted = True
        elif it > 1 and not fresh:
            need_j = True
        dprev = dn
    return NO_CONVERGENCE, z, maxit, (_NAN if F is None else norm_inf(F)), jacs
