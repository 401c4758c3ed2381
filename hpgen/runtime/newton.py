"""Newton iteration and the step loop in Python, identical in logic to kernels.c.j2.

z <- z - J^{-1} F, inf-norms, theta = ||dz_k|| / ||dz_{k-1}||.
- Full Newton (J at every iterate) converges when ||dz|| <= tol (1 + ||z||), which leaves an
  error of order tol^2 (a rate-based early stop left errors ~ tol per step, which added up
  to 3e-11 in the free body's momentum map over 1e4 steps: not offered).
- Simplified Newton keeps J^{-1} across iterations and steps, refreshes it when theta exceeds
  THETA_MAX (if J is already fresh from this step, the rest of the step is full Newton), and
  converges when the linear-rate bound theta/(1 - theta) ||dz|| (or ||dz|| itself) is
  <= SIMPLIFIED_TOL tol (1 + ||z||): the round-off level full Newton's stop leaves.
- Both stop when ||dz|| stopped decreasing while ||dz|| <= 1e-11 (1 + ||z||) (round-off floor).
Non-finite F, J or z, or an exactly singular J, give code NONFINITE. A first step whose start
has margin(z, h) <= 0 is DOMAIN at once (h too large for the chart). After convergence
margin(z, h) > 0 else DOMAIN; a failed Newton whose last iterate lies outside tau's domain
(finite margin <= 0) is reported as DOMAIN too. Steps after the first start from the previous
solution z_k, or from the linear predictor 2 z_k - z_{k-1} (options.predictor).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

OK, NO_CONVERGENCE, NONFINITE, DOMAIN = 0, 1, 2, 3
ROUNDOFF_FLOOR = 1e-11
THETA_MAX = 0.05
SIMPLIFIED_TOL = 0.01
DEFAULT_TOL = 1e-14
DEFAULT_MAXIT = 50


@dataclass(frozen=True)
class NewtonOptions:
    """Runtime Newton settings (the C backend's ``hpgen_options``)."""
    tol: float = DEFAULT_TOL
    maxit: int = DEFAULT_MAXIT
    simplified: bool = True      # reuse J (its inverse / LU) across iterations and steps
    predictor: bool = True       # start step k+1 from 2 z_k - z_{k-1}


class NewtonMemory:
    """The Jacobian kept by simplified Newton (None: evaluate at the next iterate)."""
    __slots__ = ("jinv",)

    def __init__(self):
        self.jinv = None


def norm_inf(x) -> float:
    return float(np.max(np.abs(x))) if x.size else 0.0


def newton(fun, z, tol=DEFAULT_TOL, maxit=DEFAULT_MAXIT):
    """Full Newton for F(z) = 0 from z; ``fun(z) -> (F (m,), J (m, m))``.

    Returns (code, z, iterations, last residual inf-norm). ``fun`` may raise; it is not
    caught here (the callers use that for the singular-Legendre check).
    """
    last = {}

    def residual(zz):
        # full Newton asks for J at the iterate whose F it just took: evaluate fun once
        last["F"], last["J"] = fun(zz)
        return last["F"]

    code, z, it, r, _ = solve(residual, lambda zz: last["J"], z,
                              NewtonOptions(tol, maxit, simplified=False), NewtonMemory())
    return code, z, it, r


def solve(residual, jacobian, z, opts: NewtonOptions, memory: NewtonMemory):
    """Newton (full or simplified, see the module docstring) from z.

    Returns (code, z, iterations, last residual inf-norm, Jacobian evaluations).
    """
    z = np.array(z, dtype=np.float64)
    dprev, rnorm, jacs = math.inf, math.nan, 0
    full, fresh = not opts.simplified, False
    for it in range(1, opts.maxit + 1):
        F = residual(z)
        rnorm = norm_inf(F)
        if not math.isfinite(rnorm):
            return NONFINITE, z, it, rnorm, jacs
        if full or memory.jinv is None:
            memory.jinv = None
            jacs += 1
            J = jacobian(z)
            if not np.isfinite(J).all():
                return NONFINITE, z, it, rnorm, jacs
            try:
                memory.jinv = np.linalg.inv(J)
            except np.linalg.LinAlgError:
                return NONFINITE, z, it, rnorm, jacs
            fresh = True
        dz = memory.jinv @ F
        z = z - dz
        dn, zn = norm_inf(dz), norm_inf(z)
        if not (math.isfinite(dn) and math.isfinite(zn)):
            return NONFINITE, z, it, rnorm, jacs
        if it > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + zn):
            return OK, z, it, rnorm, jacs
        if full:
            # quadratic convergence: the error left after dn <= tol is about C tol^2
            if dn <= opts.tol * (1.0 + zn):
                return OK, z, it, rnorm, jacs
        else:
            # linear convergence: the error left is about theta/(1 - theta) dn
            th = dn / dprev
            if dn <= SIMPLIFIED_TOL * opts.tol * (1.0 + zn):
                return OK, z, it, rnorm, jacs
            if it > 1 and th < 1.0 and th / (1.0 - th) * dn <= SIMPLIFIED_TOL * opts.tol * (1.0 + zn):
                return OK, z, it, rnorm, jacs
        if not full and it > 1 and dn > THETA_MAX * dprev:
            if fresh:
                full = True          # a fresh J contracts poorly: full Newton
            else:
                memory.jinv = None   # a stale J: refresh it at the next iterate
        dprev = dn
    return NO_CONVERGENCE, z, opts.maxit, rnorm, jacs


def step_core(call, nz, g, p, hv, z, opts: NewtonOptions, memory: NewtonMemory,
              check_start=True):
    """One step with kernels ``call(name, *args) -> [outputs]`` (flat column-major args).

    Returns (code, g1 flat, p1, z, iterations, residual norm, Jacobian evaluations); g1/p1
    are None on failure.
    """
    def residual(zz):
        return call("residual", zz, g, p, hv)[0]

    def jacobian(zz):
        return call("jacobian", zz, g, p, hv)[0].reshape(nz, nz, order="F")

    with np.errstate(all="ignore"):
        # a start outside the chart (h too large): no Newton. Later starts are built from
        # earlier solutions, whose margins (same h) were checked after they converged.
        if check_start and call("margin", z, hv)[0][0] <= 0.0:
            return DOMAIN, None, None, z, 0, math.nan, 0
        code, z, it, r, jacs = solve(residual, jacobian, z, opts, memory)
        m = call("margin", z, hv)[0][0]
        if code != OK:
            memory.jinv = None
            # a failure at an iterate outside tau's domain is reported as a domain error
            return (DOMAIN if m <= 0.0 else code), None, None, z, it, r, jacs
        if not m > 0.0:
            return DOMAIN, None, None, z, it, r, jacs
        g1, p1 = call("update", z, g, p, hv)
        if not (np.isfinite(g1).all() and np.isfinite(p1).all()):
            return NONFINITE, None, None, z, it, r, jacs
    return OK, g1, p1, z, it, r, jacs


class Run:
    """A run in progress (the C backend's ``hpgen_run``): state (g_k, p_k) flat, the last
    solution z, the one before (predictor), the Newton memory and the steps done k."""

    def __init__(self, g0, p0, z0):
        self.g = np.array(g0, dtype=np.float64)
        self.p = np.array(p0, dtype=np.float64)
        self.z = np.array(z0, dtype=np.float64)
        self.zprev = None
        self.memory = NewtonMemory()
        self.k = 0


def new_status() -> dict:
    return {"code": OK, "step": 0, "iterations": 0, "total_iterations": 0, "residual": 0.0,
            "jacobians": 0}


def advance(call, nz, run: Run, h, steps, every, opts: NewtonOptions):
    """Advance ``run`` by ``steps`` steps like ``hpgen_advance`` in C.

    Returns (steps done, records [(g flat, p)] of the global steps k % every == 0 reached,
    status dict with code, step, iterations, total_iterations, residual, jacobians).
    """
    hv = np.array([h], dtype=np.float64)
    st, recs = new_status(), []
    full = NewtonOptions(opts.tol, opts.maxit, False, opts.predictor)
    for n in range(steps):
        zs = run.z if not (opts.predictor and run.zprev is not None) else 2.0 * run.z - run.zprev
        # the first step starts from the crude guess kernel: full Newton
        code, g1, p1, zs, it, r, jacs = step_core(call, nz, run.g, run.p, hv, zs,
                                                  full if run.k == 0 else opts, run.memory,
                                                  run.k == 0)
        st["iterations"], st["residual"] = it, r
        st["total_iterations"] += it
        st["jacobians"] += jacs
        if code != OK:
            st["code"], st["step"] = code, run.k
            return n, recs, st
        run.zprev, run.z = run.z, zs
        run.g, run.p = g1, p1
        run.k += 1
        if run.k % every == 0:
            recs.append((g1, p1))
    st["step"] = run.k
    return steps, recs, st
