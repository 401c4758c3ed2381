"""The linear algebra of the Python Newton loop (hpgen.runtime.newton), as in the C runtime's
hpgen/runtime/c/hpgen_linalg.c (hpgen_lu_factor_solve, hpgen_lu_apply), and its inf-norm and
finiteness tests (hpgen_norm_inf).

The C runtime keeps the Newton matrix as J^{-1} (explicit, column-major): an iterate with a
fresh J solves J dz = F (nz <= 3: cofactors; else the LU with partial pivoting, the diagonal
of U stored inverted) and, for simplified Newton, forms J^{-1} from the factors; the other
iterates take dz = J^{-1} F, a matrix-vector product. For nz <= UNROLL_MAX the generated
module prints these as straight-line Python for one n (hpgen.codegen.pylinear: entries as
local variables, every operation that of the C loops in the same order); above it
numpy/LAPACK does them (``linear_solver`` without ``printed``), which agrees with C to
round-off.
"""
from __future__ import annotations

import math

import numpy as np

_isfinite = math.isfinite


def norm_inf(x) -> float:
    """max |x_i| of a sequence of floats, NaN if some x_i is NaN (hpgen_norm_inf); 0 if empty."""
    if len(x) == 0:
        return 0.0
    m = max(map(abs, x))
    s = sum(x)
    if s - s == 0.0:        # the sum is finite, so every x_i is (a NaN or inf would not be)
        return m
    m = 0.0                 # some x_i non-finite (or the sum overflowed): C's loop
    for v in x:
        a = abs(v)
        if a != a:
            return a
        if a > m:
            m = a
    return m


def all_finite(x) -> bool:
    """Whether every x_i is finite (the sum first: one pass in the common case)."""
    s = sum(x)
    return s - s == 0.0 or all(map(_isfinite, x))


class LinearSolver:
    """The linear algebra of Newton for n x n systems (linear_solver)."""
    __slots__ = ("n", "factor_solve", "apply", "update", "finish")

    def __init__(self, n, factor_solve, apply, update=None, finish=None):
        self.n, self.factor_solve, self.apply = n, factor_solve, apply
        self.update, self.finish = update, finish


def _numpy_solver(n: int) -> LinearSolver:
    """Above UNROLL_MAX: LAPACK through numpy (agrees with the C runtime to round-off)."""
    def factor_solve(J, F, keep):
        if not all_finite(J):
            return None
        A = np.array(J, dtype=np.float64).reshape(n, n, order="F")
        with np.errstate(all="ignore"):
            try:
                if not keep:
                    return np.linalg.solve(A, np.array(F, dtype=np.float64)).tolist(), None
                X = np.linalg.inv(A)
            except np.linalg.LinAlgError:
                return None
            if not np.isfinite(X).all():
                return None
            return (X @ np.array(F, dtype=np.float64)).tolist(), X

    def apply(X, F):
        with np.errstate(all="ignore"):
            return (X @ np.array(F, dtype=np.float64)).tolist()
    return LinearSolver(n, factor_solve, apply)


def linear_solver(n: int, printed=None) -> LinearSolver:
    """The Newton linear algebra for n x n systems, as in the C runtime (hpgen_linalg.c):
    factor_solve(J flat column-major, F, keep) -> (J^{-1} F as a list, J^{-1} if keep else
    None), or None when J has a non-finite entry or is singular; apply(f, F) -> f F (f a
    kept J^{-1}); update(f, F, z) -> (z - f F, |f F|, |z - f F|) and finish(dz, z) -> (z - dz,
    |dz|, |z - dz|) (inf-norms), each None when some entry is not finite (or a sum of
    entries overflows), where the caller takes the general path.

    printed: the generated module's LINEAR = (factor_solve, apply, update, finish), printed
    by hpgen.codegen.pylinear for nz <= UNROLL_MAX (bitwise the C runtime's operations);
    without it numpy/LAPACK (agrees with C to round-off), update and finish None."""
    if printed is None:
        return _numpy_solver(n)
    return LinearSolver(n, *printed)


def fresh_solve(kern, z, g, p, hv, keep):
    """F and a fresh J at z (one evaluation when the module has residual_jacobian), then
    J^{-1} F with factor_solve(J, F, keep): (F, result); result is None when F is not finite
    (then nothing was factored) or the factorization failed."""
    if kern.residual_jacobian is not None:
        F, J = kern.residual_jacobian(z, g, p, hv)
    else:
        F = kern.residual(z, g, p, hv)[0]
        J = kern.jacobian(z, g, p, hv)[0]
    if not all_finite(F):
        return F, None
    return F, kern.linear.factor_solve(J, F, keep)

