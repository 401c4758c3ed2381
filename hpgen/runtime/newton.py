"""Newton iteration and one step in Python, identical in logic to the C runtime's
hpgen/runtime/c/hpgen_newton.c (the run loop over steps is hpgen.runtime.loop).

z <- z - J^{-1} F, inf-norms, theta = ||dz_k|| / ||dz_{k-1}||.
- Full Newton (J at every iterate) converges when ||dz|| <= tol (1 + ||z||), which leaves an
  error of order tol^2 (a rate-based early stop left errors ~ tol per step, which added up
  to 3e-11 in the free body's momentum map over 1e4 steps: not offered).
- Simplified Newton keeps J^{-1} across iterations and steps, refreshes it when theta exceeds
  THETA_MAX (if J is already fresh from this step, the rest of the step is full Newton), and
  converges when the linear-rate bound te/(1 - te) ||dz|| (te = max(theta, THETA_FLOOR)),
  or ||dz|| itself, is <= SIMPLIFIED_TOL tol (1 + ||z||): the round-off level full Newton's
  stop leaves.
- Both stop when ||dz|| stopped decreasing while ||dz|| <= ROUNDOFF_FLOOR (1 + ||z||) (round-off
  floor). The constants and status codes are hpgen.abi's, as are the C runtime's.
- A module whose Newton matrix is sparse (many bodies) also stops when the error left,
  estimated from the rate (quadratic after a fresh J, linear else), is <= tol (1 + ||z||)
  (sparse_converged); its full Newton is a chord iteration within the step (J once a step)
  that also stops at the round-off stall, whose level follows the problem
  (hpgen.runtime.newton_sparse).
- An iterate that needs J takes F and J from one ``residual_jacobian`` evaluation when the
  module has that kernel (else ``residual`` then ``jacobian``), the others ``residual`` only.
Non-finite F, J or z, or an exactly singular J, give code NONFINITE. A first step whose start
has margin(z, h) <= 0 is DOMAIN at once (h too large for the chart). After convergence
margin(z, h) > 0 else DOMAIN; a failed Newton is NO_CONVERGENCE or NONFINITE wherever its
iterates went (a divergence is not a domain violation). Steps after the first start from the
previous solution z_k, or with options.predictor from the predictor of hpgen.runtime.loop
(the guess kernel at the state plus the extrapolated offsets of the last solutions from it); a
predicted start that fails (Newton diverged, or converged outside the chart) is retried from
z_k before the failure is reported (hpgen.runtime.loop).

The loop runs on lists of Python floats with the generated module's raw kernels
(``kernels.py`` RAW: lists in, lists out): no numpy array is made per iteration. The linear
algebra is that of hpgen_linalg.c operation for operation (``linear_solver``, in
hpgen.runtime.newton_linalg): an iterate with a fresh J solves J dz = F (nz <= 3 by
cofactors, else by the LU with partial pivoting) and, for simplified Newton, forms J^{-1},
which the other iterates apply as a matrix-vector product. For nz <= UNROLL_MAX these are printed once per nz as straight-line Python, so that
with the same kernels (the backends' kernels are bitwise equal) the Python backend computes
the same doubles as the C backend; above UNROLL_MAX numpy/LAPACK does the linear algebra,
which agrees with C to round-off; a module whose Newton matrix is sparse (meta.json
"jacobian") solves with SuperLU on J's structural nonzeros (hpgen.runtime.sparse), which
agrees with C's sparse QR to round-off. The iterates with a kept J^{-1} run, when the module has
it, in its printed ITERATE (hpgen.codegen.pyiterate: the residual's body, J^{-1} F, z - dz and
this loop's tests fused into one function, the same operations), which hands back at a
refresh of J or to the way below at a math error or a non-finite value; full Newton's
iterates likewise in ITERATE_FULL.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

# status codes and Newton constants: the generated-module contract (hpgen_runtime.h defines
# the same values)
from ..abi import (DEFAULT_MAXIT, DEFAULT_TOL, DOMAIN, NO_CONVERGENCE, NONFINITE,
                   OK, REFRESH, ROUNDOFF_FLOOR, SIMPLIFIED_TOL, STALL_MAX, THETA_FLOOR,
                   THETA_MAX)
# the linear algebra (re-exported: hpgen.runtime.loop, .sparse and the tests import it here)
from .newton_linalg import (LinearSolver, _isfinite, all_finite, fresh_solve,  # noqa: F401
                            linear_solver, norm_inf)
# a sparse module's stop tests (re-exported: the tests import them here)
from .newton_sparse import at_floor, chord_converged, solve_sparse, sparse_converged  # noqa: F401

_INF, _NAN = math.inf, math.nan


@dataclass(frozen=True)
class NewtonOptions:
    """Runtime Newton settings, the one argument ``newton=`` of the Integrator's stepping
    methods (the C backend's ``hpgen_options``, abi.OPTIONS_FIELDS).

    tol: converged when |dz| <= tol (1 + |z|) (inf-norms); maxit: iterations per step >= 1;
    simplified: reuse J^{-1} across iterations and steps (None: the Integrator decides, see
    hpgen.runtime.integrator; the loops here read None as False); predictor: start step k+1
    from the extrapolated last solutions (else from z_k)."""
    tol: float = DEFAULT_TOL
    maxit: int = DEFAULT_MAXIT
    simplified: bool | None = None
    predictor: bool = True


class NewtonMemory:
    """J^{-1} kept by simplified Newton (None: evaluate J at the next iterate), as
    ``linear_solver(nz).factor_solve`` returned it."""
    __slots__ = ("lu",)

    def __init__(self):
        self.lu = None


# ---- Newton --------------------------------------------------------------------------------

class Kernels:
    """The kernels the Newton loop calls, on lists of Python floats (``kernels.py`` RAW):
    name(*args) -> list of output lists. residual_jacobian may be None (then residual and
    jacobian are called in turn); update and margin are needed by step_lists only, guess and
    velocity_step by the run loop's predictor (hpgen.runtime.loop). Holds the linear solver
    for nz (linear_solver) and, optionally, the module's ITERATE (the simplified iterates
    with a kept J^{-1}, residual and linear algebra fused: solve's arithmetic, printed by
    hpgen.codegen.pyiterate; it needs the printed linear solver)."""
    __slots__ = ("residual", "jacobian", "residual_jacobian", "update", "margin", "linear",
                 "nz", "update_p", "iterate", "iterate_full", "guess", "velocity_step",
                 "sparse", "explicit")

    def __init__(self, nz, residual, jacobian, residual_jacobian=None, update=None,
                 margin=None, linear=None, update_p=None, iterate=None, iterate_full=None,
                 guess=None, velocity_step=None, pattern=None):
        self.nz = nz
        self.residual, self.jacobian = residual, jacobian
        self.residual_jacobian = residual_jacobian
        self.update, self.margin, self.update_p = update, margin, update_p
        self.guess, self.velocity_step = guess, velocity_step
        self.sparse = pattern is not None
        self.explicit = False         # an explicit step (meta "explicit"): no Newton in runs
        if pattern is not None:       # a sparse Newton matrix: no printed dense solver
            from .sparse import sparse_solver
            linear = None
            self.linear = sparse_solver(nz, *pattern)
        else:
            self.linear = linear_solver(nz, linear)
        self.iterate = iterate if linear is not None else None
        self.iterate_full = iterate_full if linear is not None else None

    @classmethod
    def from_raw(cls, nz, raw: dict, linear=None, iterate=None, iterate_full=None,
                 jacobian=None) -> "Kernels":
        """linear: the module's LINEAR (printed solver functions) or None; iterate,
        iterate_full: its ITERATE and ITERATE_FULL or None; jacobian: meta.json's "jacobian"
        entry (a sparse one: Newton factors J sparse, hpgen.runtime.sparse)."""
        pattern = None
        if jacobian is not None and jacobian.get("storage") == "sparse":
            pattern = (jacobian["colind"], jacobian["row"])
        return cls(nz, raw["residual"], raw["jacobian"], raw.get("residual_jacobian"),
                   raw.get("update"), raw.get("margin"), linear, raw.get("update_p"),
                   iterate, iterate_full, raw.get("guess"), raw.get("velocity_step"),
                   pattern)


#: hpgen_newton_sparse.c's HPGEN_SIMPLIFIED_REFRESH and HPGEN_KEPT_J_ITERATES: a sparse module's
#: simplified Newton stops a J evaluated in the step on the chord's rate bound, and drops a J
#: kept from earlier steps after a step that took more than KEPT_J_ITERATES iterates with it
SIMPLIFIED_REFRESH, KEPT_J_ITERATES = True, 3


def solve(kern: Kernels, z, g, p, hv, opts: NewtonOptions, memory: NewtonMemory):
    """Newton (full or simplified, see the module docstring) from z (a list of floats) on
    kern.residual(z, g, p, hv) = 0: the C runtime's hpgen_newton.

    Returns (code, z (list), iterations, last residual inf-norm, Jacobian evaluations).
    A sparse module's simplified Newton whose step converged with a J kept from earlier steps
    alone in more than KEPT_J_ITERATES iterates drops that J (memory.lu = None: the next step
    evaluates J at its first iterate; SIMPLIFIED_REFRESH).
    """
    out = _iterates(kern, z, g, p, hv, opts, memory)
    if (SIMPLIFIED_REFRESH and kern.sparse and opts.simplified and out[0] == OK
            and out[4] == 0 and out[2] > KEPT_J_ITERATES):
        memory.lu = None
    return out


def _iterates(kern: Kernels, z, g, p, hv, opts: NewtonOptions, memory: NewtonMemory):
    """solve's iteration (hpgen_newton.c's hpgen_newton_iterates)."""
    residual = kern.residual
    lin, iterate = kern.linear, kern.iterate
    apply, update, finish = lin.apply, lin.update, lin.finish
    tol, keep, maxit = opts.tol, opts.simplified, opts.maxit
    stol, sparse = SIMPLIFIED_TOL * tol, kern.sparse
    dprev, jacs, F = _INF, 0, None
    full, fresh = not opts.simplified, False
    rate_stop = sparse and SIMPLIFIED_REFRESH
    if full and sparse:
        # a chord iteration within the step with the round-off stall (newton_sparse)
        memory.lu = None
        return solve_sparse(kern, z, g, p, hv, tol, maxit)
    if full and kern.iterate_full is not None:
        # full Newton's iterates in one call (same arithmetic as below; J is not kept)
        out = kern.iterate_full(z, g, p, hv, 1, maxit, dprev, tol)
        if out is not None:
            memory.lu = None
            return out[0], out[1], out[2], out[4], out[2]
    it = 0
    while it < maxit:
        it += 1
        if iterate is not None and not full and memory.lu is not None:
            # the iterates with the kept J^{-1} in one call (same arithmetic as below)
            out = iterate(memory.lu, z, g, p, hv, it, maxit, dprev, stol)
            if out is not None:
                code, z, it, dn, rnorm = out
                if code != REFRESH:
                    return code, z, it, rnorm, jacs
                if fresh:
                    full = True
                else:
                    memory.lu = None
                if it >= maxit:
                    return NO_CONVERGENCE, z, maxit, rnorm, jacs
                dprev = dn
                continue
            # a math error or a non-finite value on the way: from this iterate on, the way
            # below (the same values up to there; it then handles the event as C does)
            iterate = None
        now = False                      # J evaluated at this iterate
        if full or memory.lu is None:
            # F and a fresh J (one evaluation when the module has residual_jacobian)
            memory.lu = None
            jacs += 1
            F, res = fresh_solve(kern, z, g, p, hv, keep)
            if res is None:
                return NONFINITE, z, it, norm_inf(F), jacs
            dz = res[0]
            if keep:                     # J^{-1} kept only for simplified Newton
                memory.lu = res[1]
            fresh = now = True
            new = finish(dz, z) if finish is not None else None
        else:
            F = residual(z, g, p, hv)[0]
            new = update(memory.lu, F, z) if update is not None else None
            dz = None
        # the residual's norm is only reported: it is taken when returning (the same value)
        if new is not None:
            z, dn, zn = new
        else:
            # some entry not finite (or a sum overflowed): step by step as in C
            rnorm = norm_inf(F)
            if not rnorm < _INF:
                return NONFINITE, z, it, rnorm, jacs
            if dz is None:
                dz = apply(memory.lu, F)
            z = [a - b for a, b in zip(z, dz)]
            dn, zn = norm_inf(dz), norm_inf(z)
            if not (dn < _INF and zn < _INF):
                return NONFINITE, z, it, rnorm, jacs
        # (a sparse module's kept J whose second correction is no smaller than its first:
        # the rate test below refreshes it, hpgen_kept_j_diverges)
        if (it > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + zn)
                and not (sparse and keep and it == 2 and not fresh)):
            return OK, z, it, norm_inf(F), jacs
        if sparse and sparse_converged(it, dn, dprev, zn, tol, full):
            return OK, z, it, norm_inf(F), jacs
        if (rate_stop and not full and fresh and not now
                and chord_converged(it, dn, dprev, zn, tol)):
            return OK, z, it, norm_inf(F), jacs
        if full:
            # quadratic convergence: the error left after dn <= tol is about C tol^2
            if dn <= tol * (1.0 + zn):
                return OK, z, it, norm_inf(F), jacs
        else:
            # linear convergence: the error left is about theta/(1 - theta) dn
            th = dn / dprev
            te = th if th > THETA_FLOOR else THETA_FLOOR
            if dn <= stol * (1.0 + zn):
                return OK, z, it, norm_inf(F), jacs
            if it > 1 and te < 1.0 and te / (1.0 - te) * dn <= stol * (1.0 + zn):
                return OK, z, it, norm_inf(F), jacs
        if (not full and it > 1 and dn > THETA_MAX * dprev
                and not (sparse and it > 2 and at_floor(dn, zn))):
            if fresh:
                full = True          # a fresh J contracts poorly: full Newton
            else:
                memory.lu = None     # a stale J: refresh it at the next iterate
        dprev = dn
    return NO_CONVERGENCE, z, maxit, (_NAN if F is None else norm_inf(F)), jacs


def newton(fun, z, tol=DEFAULT_TOL, maxit=DEFAULT_MAXIT):
    """Full Newton for F(z) = 0 from z; ``fun(z (m,) array) -> (F (m,), J (m, m))`` arrays.

    The logic of ``solve`` with full Newton and numpy's solve for the update (J dz = F), on
    arrays from ``fun`` without per-iterate conversions: converged when |dz| <= tol (1 + |z|)
    or at the round-off floor, or at a round-off stall above that floor (the rate above
    THETA_MAX at |dz| <= STALL_MAX (1 + |z|): an ill-conditioned J's noise, e.g. the Legendre
    map of the pendulum chain at 32 links; hpgen.runtime.newton_sparse.stalled); NONFINITE
    on a non-finite F, J or z or a singular J.
    Returns (code, z (m,) array, iterations, residual inf-norm of the last iterate, NaN
    before the first). ``fun`` may raise; it is not caught here (the callers use that for
    the singular-Legendre check).
    """
    zl = np.asarray(z, dtype=np.float64).tolist()
    dprev, F, code, it = _INF, None, NO_CONVERGENCE, maxit
    with np.errstate(all="ignore"):
        for k in range(1, maxit + 1):
            Fa, J = fun(np.array(zl, dtype=np.float64))
            F, it, code = np.asarray(Fa, dtype=np.float64).tolist(), k, NONFINITE
            if not (all_finite(F) and np.isfinite(J).all()):
                break
            try:
                dz = np.linalg.solve(J, Fa).tolist()
            except np.linalg.LinAlgError:
                break
            zl = [a - b for a, b in zip(zl, dz)]
            dn, zn = norm_inf(dz), norm_inf(zl)
            if not (dn < _INF and zn < _INF):
                break
            if (k > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + zn)) or \
                    dn <= tol * (1.0 + zn) or (k > 1 and dn > THETA_MAX * dprev and
                                               ROUNDOFF_FLOOR * (1.0 + zn) < dn
                                               <= STALL_MAX * (1.0 + zn)):
                code = OK
                break
            code, dprev = NO_CONVERGENCE, dn
    return code, np.array(zl, dtype=np.float64), it, (_NAN if F is None else norm_inf(F))


def step_lists(kern: Kernels, g, p, hv, z, opts: NewtonOptions, memory: NewtonMemory,
               check_start=True, with_g=True):
    """One step on lists of floats (the C runtime's hpgen_step_core): margin at the start
    (check_start), Newton from z, margin at the solution, update (with_g False: update_p,
    and g1 is g).

    Returns (code, g1, p1, z, iterations, residual norm, Jacobian evaluations); g1/p1 are
    lists, None on failure.
    """
    margin = kern.margin
    # a start outside the chart (h too large): no Newton. Later starts are built from earlier
    # solutions, whose margins (same h) were checked after they converged.
    if check_start and margin(z, hv)[0][0] <= 0.0:
        return DOMAIN, None, None, z, 0, _NAN, 0
    code, z, it, r, jacs = solve(kern, z, g, p, hv, opts, memory)
    # a Newton failure is reported as such (wherever its last iterate went): DOMAIN is a
    # converged solution outside tau's domain only
    if code != OK:
        memory.lu = None
        return code, None, None, z, it, r, jacs
    if not margin(z, hv)[0][0] > 0.0:
        memory.lu = None
        return DOMAIN, None, None, z, it, r, jacs
    if not with_g:
        p1 = kern.update_p(z, g, p, hv)[0]
        if not all_finite(p1):
            return NONFINITE, None, None, z, it, r, jacs
        return OK, g, p1, z, it, r, jacs
    g1, p1 = kern.update(z, g, p, hv)
    if not (all_finite(g1) and all_finite(p1)):
        return NONFINITE, None, None, z, it, r, jacs
    return OK, g1, p1, z, it, r, jacs


def _floats(x) -> list:
    return np.asarray(x, dtype=np.float64).ravel().tolist()


def kernels_from_call(call, nz: int) -> Kernels:
    """Kernels from ``call(name, *args) -> [outputs]`` (any array-likes, e.g.
    Integrator.kernel of either backend)."""
    def raw(name):
        return lambda *args: [_floats(o) for o in call(name, *args)]
    return Kernels(nz, raw("residual"), raw("jacobian"), None, raw("update"), raw("margin"))


def step_core(call, nz, g, p, hv, z, opts: NewtonOptions, memory: NewtonMemory,
              check_start=True):
    """One step with kernels ``call(name, *args) -> [outputs]`` (flat column-major args).

    Returns (code, g1 flat, p1, z, iterations, residual norm, Jacobian evaluations) as numpy
    arrays; g1/p1 are None on failure.
    """
    return _arrays(step_lists(kernels_from_call(call, nz), _floats(g), _floats(p),
                              _floats(hv), _floats(z), opts, memory, check_start))


def _arrays(res):
    code, g1, p1, z, it, r, jacs = res
    if g1 is not None:
        g1, p1 = np.array(g1, dtype=np.float64), np.array(p1, dtype=np.float64)
    return code, g1, p1, np.array(z, dtype=np.float64), it, r, jacs
