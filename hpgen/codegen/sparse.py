"""The sparse Newton matrix of a module whose J outputs stay sparse (hpgen.derive.sparse_jacobian):
its pattern and the symbolic analysis of its factorizations, computed once at compile time.

The runtime factors J's nonzeros by an LU with a static pivot order (hpgen.codegen.static_lu)
and, for a J on which a static pivot fails at run time (or a pattern with no static order),
by CasADi's sparse Householder QR: ``casadi_qr`` and ``casadi_qr_solve`` of CasADi's C
runtime, the code its Linsol "qr" generates, J P_c = Q R with a fill-reducing column order
P_c (approximate minimum degree on J^T J) and Q kept as Householder vectors V. The analyses
(static_lu; ``casadi.Sparsity.qr_sparse``) fix every pattern and permutation, so the runtime
only computes numbers on static arrays (kernels.c) with sizes known at compile time.

Why these two: J is not symmetric (so no LDL^T, neither CasADi's ``ldl`` nor QDLDL) and its
multiplier blocks have zero diagonals (RATTLE's constraint rows). The static LU pivots on them
only after the bodies they join are eliminated and needs a fraction of the QR's flops;
Householder QR needs no pivoting at all, is backward stable and keeps its factors O(nz) for
chains and trees under the minimum-degree order: the safety net. A singular J shows as a
negligible diagonal of R.

Conventions: CasADi's compressed sparsity [nrow, ncol, colind (ncol + 1), row (nnz)], J's
nonzeros in column-major (CCS) order, which is the order in which CasADi's code writes the
kernels' J output (the public kernels still return J dense, column-major).
"""
from __future__ import annotations

import casadi

from .contract import CodegenError, dense_positions
from .lu_code import factor_code, fill_positions
from .static_lu import static_lu

#: the CasADi Function whose generated code brings casadi_qr and casadi_qr_solve into
#: kernels.c (it is not called; the runtime calls those two on the arrays below)
AUX_FUNCTION = "newton_sparse_qr"


def jacobian_sparsity(step):
    """The Sparsity (nz x nz) of J when the module's Newton matrix is sparse, else None.

    The J outputs of the jacobian and residual_jacobian kernels (they must agree) say it: the
    nz x nz matrix (its structural nonzeros, column-major) is a sparse J by the derive stage's
    choice (hpgen.derive.sparse_jacobian, a forced one included); the nz*nz column is dense,
    unless its structural nonzeros are few enough for the derive stage's rule (a derivation
    that keeps its outputs' structure, e.g. a family's, leaves the choice to this rule)."""
    from ..derive import sparse_jacobian
    nz = step.nz
    sps = [step.kernel("jacobian").function.sparsity_out(0),
           step.kernel("residual_jacobian").function.sparsity_out(1)]
    if sps[0] != sps[1]:
        raise CodegenError("the jacobian and residual_jacobian kernels disagree on J's "
                           "storage or sparsity")
    sp = sps[0]
    if nz > 1 and sp.size1() == sp.size2() == nz:
        return sp
    if sp.is_dense():
        return None
    pos = dense_positions(sp)
    mat = casadi.Sparsity.triplet(nz, nz, [q % nz for q in pos], [q // nz for q in pos])
    return mat if sparse_jacobian(mat, None) else None


def sparse_context(step) -> dict | None:
    """kernels.c.j2's ``sparse`` entry (None for a dense J): sizes and static arrays of the
    QR's symbolic analysis. nnz_j, nnz_v, nnz_r: nonzeros of J, V, R; nrow_v: rows of V (nz,
    or more when J is structurally singular); sp_j, sp_v, sp_r: compressed sparsities;
    prinv: the inverse row permutation; pc: the column order; lu: the static LU's analysis
    (hpgen.codegen.static_lu.StaticLU's fields and nnz; code: the numeric factorization's
    generated C, hpgen.codegen.lu_code, or None; fill: the fill's positions; pinv: the
    inverse of perm) or None."""
    sp = jacobian_sparsity(step)
    if sp is None:
        return None
    spv, spr, prinv, pc = sp.qr_sparse(True)
    lu = static_lu(sp.size1(), [int(i) for i in sp.colind()], [int(i) for i in sp.row()])
    return {"nnz_j": sp.nnz(), "nnz_v": spv.nnz(), "nnz_r": spr.nnz(), "nrow_v": spv.size1(),
            "sp_j": list(sp.compress()), "sp_v": list(spv.compress()),
            "sp_r": list(spr.compress()), "prinv": [int(i) for i in prinv],
            "pc": [int(i) for i in pc],
            "lu": None if lu is None else {
                "nnz": lu.nnz, "perm": list(lu.perm), "colptr": list(lu.colptr),
                "row": list(lu.row), "diag": list(lu.diag), "jmap": list(lu.jmap),
                "code": factor_code(lu), "fill": fill_positions(lu),
                "pinv": _inverse(lu.perm)}}


def _inverse(perm) -> list[int]:
    inv = [0] * len(perm)
    for t, c in enumerate(perm):
        inv[c] = t
    return inv


def aux_function(sp):
    """x = J \\ b by CasADi's Linsol "qr" on J's sparsity (for its generated code)."""
    A = casadi.MX.sym("J", sp)
    b = casadi.MX.sym("b", sp.size1())
    return casadi.Function(AUX_FUNCTION, [A, b], [casadi.solve(A, b, "qr")])


def meta_entry(step) -> dict:
    """meta.json's "jacobian" entry: {"storage": "dense"} or {"storage": "sparse", "colind",
    "row"} (J's CCS pattern, the order of the J nonzeros the runtime's Newton works on)."""
    sp = jacobian_sparsity(step)
    if sp is None:
        return {"storage": "dense"}
    return {"storage": "sparse", "colind": [int(i) for i in sp.colind()],
            "row": [int(i) for i in sp.row()]}
