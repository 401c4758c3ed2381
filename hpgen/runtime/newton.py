"""Newton iteration and the step loop in Python, identical in logic to kernels.c.j2.

z <- z - J^{-1} F (numpy.linalg.solve: LAPACK LU with partial pivoting); converged when
||dz|| <= tol (1 + ||z||), or when ||dz|| stopped decreasing (||dz_k|| >= ||dz_{k-1}||) while
||dz_k|| <= 1e-11 (1 + ||z||) (round-off floor); inf-norms. Non-finite F, J or z, or an
exactly singular J, give code NONFINITE. A start with margin(z, h) <= 0 is DOMAIN at once (h
too large for the chart). After convergence margin(z, h) > 0 else DOMAIN; a
failed Newton whose last iterate lies outside tau's domain (finite margin <= 0, e.g. the
skew projector's sqrt(1 - |h xi|^2) turning NaN) is reported as DOMAIN too.
"""
from __future__ import annotations

import math

import numpy as np

OK, NO_CONVERGENCE, NONFINITE, DOMAIN = 0, 1, 2, 3
ROUNDOFF_FLOOR = 1e-11
DEFAULT_TOL = 1e-14
DEFAULT_MAXIT = 50


def norm_inf(x) -> float:
    return float(np.max(np.abs(x))) if x.size else 0.0


def newton(fun, z, tol=DEFAULT_TOL, maxit=DEFAULT_MAXIT):
    """Solve F(z) = 0 from z; ``fun(z) -> (F (m,), J (m, m))``.

    Returns (code, z, iterations, last residual inf-norm). ``fun`` may raise; it is not
    caught here (the callers use that for the singular-Legendre check).
    """
    z = np.array(z, dtype=np.float64)
    dprev, rnorm = math.inf, math.nan
    for it in range(1, maxit + 1):
        F, J = fun(z)
        rnorm = norm_inf(F)
        if not math.isfinite(rnorm) or not np.isfinite(J).all():
            return NONFINITE, z, it, rnorm
        try:
            dz = np.linalg.solve(J, F)
        except np.linalg.LinAlgError:
            return NONFINITE, z, it, rnorm
        z = z - dz
        dn, zn = norm_inf(dz), norm_inf(z)
        if not (math.isfinite(dn) and math.isfinite(zn)):
            return NONFINITE, z, it, rnorm
        if dn <= tol * (1.0 + zn):
            return OK, z, it, rnorm
        if it > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + zn):
            return OK, z, it, rnorm
        dprev = dn
    return NO_CONVERGENCE, z, maxit, rnorm


def step_core(call, nz, g, p, hv, z, tol, maxit, check_start=True):
    """One step with kernels ``call(name, *args) -> [outputs]`` (flat column-major args).

    Returns (code, g1 flat, p1, z, iterations, residual norm); g1/p1 are None on failure.
    """
    def fun(zz):
        F = call("residual", zz, g, p, hv)[0]
        J = call("jacobian", zz, g, p, hv)[0].reshape(nz, nz, order="F")
        return F, J

    with np.errstate(all="ignore"):
        # a start outside the chart (h too large): no Newton. A warm start is the previous
        # solution, whose margin (same h) was checked after it converged.
        if check_start and call("margin", z, hv)[0][0] <= 0.0:
            return DOMAIN, None, None, z, 0, math.nan
        code, z, it, r = newton(fun, z, tol, maxit)
        m = call("margin", z, hv)[0][0]
        if code != OK:
            # a failure at an iterate outside tau's domain is reported as a domain error
            return (DOMAIN if m <= 0.0 else code), None, None, z, it, r
        if not m > 0.0:
            return DOMAIN, None, None, z, it, r
        g1, p1 = call("update", z, g, p, hv)
        if not (np.isfinite(g1).all() and np.isfinite(p1).all()):
            return NONFINITE, None, None, z, it, r
    return OK, g1, p1, z, it, r


def simulate(call, nz, d, nn, g0, p0, h, z0, steps, every, tol, maxit):
    """All steps, warm-started, like ``hpgen_simulate`` in C.

    Returns (steps done, g_rec (K, nn) flat column-major rows, p_rec (K, d), status dict with
    code, step, iterations, total_iterations, residual); K = steps // every + 1.
    """
    K = steps // every + 1
    g_rec, p_rec = np.zeros((K, nn)), np.zeros((K, d))
    g, p = np.array(g0, dtype=np.float64), np.array(p0, dtype=np.float64)
    g_rec[0], p_rec[0] = g, p
    hv = np.array([h], dtype=np.float64)
    z = np.array(z0, dtype=np.float64)
    st = {"code": OK, "step": 0, "iterations": 0, "total_iterations": 0, "residual": 0.0}
    for k in range(steps):
        code, g1, p1, z, it, r = step_core(call, nz, g, p, hv, z, tol, maxit, k == 0)
        st["iterations"], st["residual"] = it, r
        st["total_iterations"] += it
        if code != OK:
            st["code"], st["step"] = code, k
            return k, g_rec, p_rec, st
        g, p = g1, p1
        if (k + 1) % every == 0:
            g_rec[(k + 1) // every], p_rec[(k + 1) // every] = g, p
    st["step"] = steps
    return steps, g_rec, p_rec, st
