"""The scene's record row in Python, like hpgen/runtime/c/hpgen_advance.c's hpgen_velocity
and hpgen_record_row (same order of operations): the velocity xi of the state (g, p) by
Newton on the Legendre map from xi = 0, then the record kernel at (g, p, xi). The Python
backend's record rows (hpgen.runtime.backends: hpgen.runtime.loop.advance_record's
``row_of`` and Backend.record). Vectors are lists of Python floats.
"""
from __future__ import annotations

from ..abi import OK, RECORD, ROUNDOFF_FLOOR, VELOCITY_MAXIT, VELOCITY_TOL
from .newton import _INF, _NAN, all_finite, norm_inf
from .newton_sparse import stalled


def velocity(velocity_step, g, p, quadratic, stall=False) -> tuple:
    """(code, xi) with legendre(g, xi) = p, like ``hpgen_velocity`` in C: Newton steps
    velocity_step(g, p, xi) -> [xi1] from xi = 0; one step when ``quadratic``, else until
    |dxi| <= VELOCITY_TOL (1 + |xi|) or the round-off floor (``stall``, a sparse module's: or
    the round-off stall, newton_sparse.stalled), at most VELOCITY_MAXIT steps; RECORD on
    failure."""
    xi, dprev = [0.0] * len(p), _INF
    for it in range(1, VELOCITY_MAXIT + 1):
        x1 = velocity_step(g, p, xi)[0]
        if not all_finite(x1):
            return RECORD, x1
        dn = 0.0
        for a, b in zip(x1, xi):
            dx = abs(a - b)
            if dx > dn:
                dn = dx
        xi = x1
        if quadratic:
            return OK, xi
        xn = norm_inf(xi)
        if dn <= VELOCITY_TOL * (1.0 + xn):
            return OK, xi
        if it > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + xn):
            return OK, xi
        if stall and stalled(it, dn, dprev, xn, True, False):
            return OK, xi
        dprev = dn
    return RECORD, xi


def record_row(record, velocity_step, width, g, p, uses_xi, quadratic, stall=False) -> tuple:
    """(code, row) like ``hpgen_record_row`` in C (raw kernels record and velocity_step; a
    velocity that does not converge gives a row of ``width`` NaNs; stall: see velocity)."""
    if uses_xi:
        code, xi = velocity(velocity_step, g, p, quadratic, stall)
        if code != OK:
            return RECORD, [_NAN] * width
    else:
        xi = [0.0] * len(p)
    row = record(g, p, xi)[0]
    return (OK if all_finite(row) else RECORD), row
