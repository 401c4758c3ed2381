"""The Python backend's Newton linear algebra for a module whose Newton matrix is sparse
(meta.json "jacobian": {"storage": "sparse", "colind", "row"}, hpgen.codegen.sparse).

The C runtime factors J's structural nonzeros with CasADi's sparse Householder QR on a
pattern analysed at compile time; here SuperLU (scipy.sparse.linalg.splu, COLAMD column
order, threshold partial pivoting) factors the same sparse matrix. Both solve J dz = F
directly, so a step agrees with the C backend's to round-off (not bitwise). The same
singularity test as in C: a diagonal of the triangular factor that is not finite or is at
most nz DBL_EPSILON times the largest makes factor_solve return None (Newton's NONFINITE).

The kept factors are a tuple of J's nonzeros (what a run's checkpoint saves,
hpgen.runtime.loop.Run.to_arrays) carrying the SuperLU object; a plain tuple restored from a
checkpoint is factored where it is applied (the same numbers, the same factors).
"""
from __future__ import annotations

import sys

import numpy as np

from .newton import LinearSolver

_EPS = sys.float_info.epsilon


class SparseFactors(tuple):
    """J's nonzeros (column-major CCS order) with their SuperLU factors in ``lu``."""
    lu = None


def sparse_solver(n: int, colind, row) -> LinearSolver:
    """The LinearSolver (hpgen.runtime.newton.linear_solver's interface: factor_solve, apply)
    of n x n systems with J's CCS pattern (colind, row); factor_solve takes J dense
    column-major (the kernels' output) and gathers its nonzeros."""
    from scipy.sparse import csc_matrix
    from scipy.sparse.linalg import splu
    indptr = np.asarray(colind, dtype=np.int64)
    indices = np.asarray(row, dtype=np.int64)
    cols = np.repeat(np.arange(n, dtype=np.int64), np.diff(indptr))
    positions = indices + n * cols

    def factor(values):
        A = csc_matrix((np.asarray(values, dtype=np.float64), indices, indptr), shape=(n, n))
        try:
            lu = splu(A, permc_spec="COLAMD")
        except RuntimeError:          # an exactly zero pivot
            return None
        d = np.abs(lu.U.diagonal())
        with np.errstate(all="ignore"):
            if not (np.isfinite(d).all() and d.min() > n * _EPS * d.max()):
                return None
        return lu

    def factor_solve(J, F, keep):
        values = np.asarray(J, dtype=np.float64)[positions]
        if not np.isfinite(values).all():
            return None
        lu = factor(values)
        if lu is None:
            return None
        with np.errstate(all="ignore"):
            dz = lu.solve(np.asarray(F, dtype=np.float64)).tolist()
        if not keep:
            return dz, None
        kept = SparseFactors(values.tolist())
        kept.lu = lu
        return dz, kept

    def apply(f, F):
        lu = getattr(f, "lu", None)
        if lu is None:                # restored from a checkpoint: factor the saved J again
            lu = factor(f)
            if lu is None:
                return [float("nan")] * n
            if isinstance(f, SparseFactors):
                f.lu = lu
        with np.errstate(all="ignore"):
            return lu.solve(np.asarray(F, dtype=np.float64)).tolist()
    return LinearSolver(n, factor_solve, apply)
