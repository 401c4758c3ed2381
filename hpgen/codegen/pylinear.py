"""The Python backend's Newton linear algebra, printed as straight-line Python for one nz
(templates/kernels.py.j2 emits it into kernels.py; hpgen.runtime.newton calls it).

The C runtime (hpgen/runtime/c/hpgen_linalg.c: hpgen_lu_factor_solve, hpgen_lu_apply) keeps
the Newton matrix as J^{-1} (explicit, column-major): an iterate with a fresh J solves J dz = F
(nz <= 3: cofactors; else the LU with partial pivoting, the diagonal of U stored inverted)
and, for simplified Newton, forms J^{-1} from the factors; the other iterates take
dz = J^{-1} F, a matrix-vector product. The functions below print that for one n (entries as
local variables), every operation that of the C loops in the same order, so that the Python
backend computes the same doubles as the C backend. The printed code needs ``_isfinite``
(math.isfinite) and ``_UNIT<n>`` (the rows of the n x n identity) in its namespace
(``unit_rows``). Deterministic: the same n gives the same text.
"""
from __future__ import annotations

from functools import lru_cache

from ..abi import UNROLL_MAX   # largest nz printed as straight-line Python (above: LAPACK)
#: largest nz whose "LU" is the inverse by cofactors in the C runtime (HPGEN_NZ <= 3)
COFACTOR_MAX = 3


def unit_rows(n: int) -> tuple:
    """_UNIT<n>: the rows of the n x n identity, as tuples of floats."""
    return tuple(tuple(1.0 if i == m else 0.0 for i in range(n)) for m in range(n))


def _a(i, j):
    return f"a{i}_{j}"


def _x(i, j):
    return f"x{i}_{j}"


def _names(prefix, n):
    return ", ".join(f"{prefix}{i}" for i in range(n))


def _all(n):
    return [_a(i, j) for j in range(n) for i in range(n)]       # column-major: A[i + j n]


def _cofactor_factor_solve(n: int) -> list[str]:
    """nz <= 3: J^{-1} by cofactors (adjugate / det) and J^{-1} F from the adjugate applied to
    F then scaled; None when det is zero or not finite (then some entry of J is not finite,
    or J is singular)."""
    L = ["def _lin_factor_solve(J, F, keep):"]
    if n == 1:
        L += ["    a, = J",
              "    if not a != 0.0 or not _isfinite(a):",
              "        return None",
              "    r = 1.0 / a",
              "    return [F[0] * r], (r,)"]
    elif n == 2:
        L += ["    a, c, bb, d = J",
              "    b0, b1 = F",
              "    det = a * d - bb * c",
              "    x0 = d * b0 - bb * b1",
              "    x1 = a * b1 - c * b0",
              "    if not det != 0.0 or not _isfinite(det):",
              "        return None",
              "    r = 1.0 / det",
              "    return [x0 * r, x1 * r], (d * r, -c * r, -bb * r, a * r)"]
    else:
        L += ["    j00, j10, j20, j01, j11, j21, j02, j12, j22 = J",
              "    b0, b1, b2 = F",
              "    c00 = j11 * j22 - j12 * j21",
              "    c01 = j12 * j20 - j10 * j22",
              "    c02 = j10 * j21 - j11 * j20",
              "    c10 = j02 * j21 - j01 * j22",
              "    c11 = j00 * j22 - j02 * j20",
              "    c12 = j01 * j20 - j00 * j21",
              "    c20 = j01 * j12 - j02 * j11",
              "    c21 = j02 * j10 - j00 * j12",
              "    c22 = j00 * j11 - j01 * j10",
              "    det = j00 * c00 + j01 * c01 + j02 * c02",
              "    x0 = c00 * b0 + c10 * b1 + c20 * b2",
              "    x1 = c01 * b0 + c11 * b1 + c21 * b2",
              "    x2 = c02 * b0 + c12 * b1 + c22 * b2",
              "    if not det != 0.0 or not _isfinite(det):",
              "        return None",
              "    r = 1.0 / det",
              "    return [x0 * r, x1 * r, x2 * r], (c00 * r, c01 * r, c02 * r, c10 * r, "
              "c11 * r, c12 * r, c20 * r, c21 * r, c22 * r)"]
    return L


def _lu_factor_solve(n: int) -> list[str]:
    """nz > 3: None if J has a non-finite entry; LU with partial pivoting (pivot: the first
    row of largest |a_ik|; whole rows interchanged; r = 1 / u_kk stored on the diagonal and
    the column below scaled by r; column j's update skipped where a_kj = 0); a zero pivot:
    None. Then dz = J^{-1} F (interchanges, L y = P F, u_kk x_k = y_k - sum_j>k u_kj x_j taken
    as (...) * r); with keep also J^{-1} from the factors (hpgen_lu_inverse: the columns of
    P I through the same recurrences, the back substitution column-oriented), None if it has
    a non-finite entry. Returns (dz, J^{-1} column-major or None)."""
    names = _all(n)
    L = ["def _lin_factor_solve(J, F, keep):",
         "    s = sum(J)",
         "    if not s - s == 0.0 and not all(map(_isfinite, J)):",
         "        return None",
         f"    {', '.join(names)}, = J"]
    for k in range(n):
        L += [f"    m = abs({_a(k, k)})", f"    q = {k}"]
        for i in range(k + 1, n):
            L += [f"    t = abs({_a(i, k)})", "    if t > m:", "        m = t",
                  f"        q = {i}"]
        L += ["    if m == 0.0:", "        return None", f"    p{k} = q"]
        for i in range(k + 1, n):
            rk = ", ".join(_a(k, j) for j in range(n))
            ri = ", ".join(_a(i, j) for j in range(n))
            L += [f"    {'if' if i == k + 1 else 'elif'} q == {i}:",
                  f"        {rk}, {ri} = {ri}, {rk}"]
        L += [f"    r = 1.0 / {_a(k, k)}", f"    {_a(k, k)} = r"]
        L += [f"    {_a(i, k)} = {_a(i, k)} * r" for i in range(k + 1, n)]
        for j in range(k + 1, n):
            L.append(f"    if {_a(k, j)} != 0.0:")
            L += [f"        {_a(i, j)} = {_a(i, j)} - {_a(i, k)} * {_a(k, j)}"
                  for i in range(k + 1, n)]
    # the interchanges b_k <-> b_piv[k] (k = 0, 1, ...) composed: P b = [b[perm[i]] for i]
    L.append(f"    perm = list(range({n}))")
    L += [f"    perm[{k}], perm[p{k}] = perm[p{k}], perm[{k}]" for k in range(n)]
    L.append(f"    {_names('b', n)}, = [F[i] for i in perm]")
    for k in range(n):
        L += [f"    b{i} = b{i} - {_a(i, k)} * b{k}" for i in range(k + 1, n)]
    for k in range(n - 1, -1, -1):
        rhs = f"b{k}" + "".join(f" - {_a(k, j)} * b{j}" for j in range(k + 1, n))
        L.append(f"    b{k} = ({rhs}) * {_a(k, k)}" if k + 1 < n else
                 f"    b{k} = {rhs} * {_a(k, k)}")
    L += [f"    dz = [{_names('b', n)}]", "    if not keep:", "        return dz, None"]
    # J^{-1}: column j starts as column j of P I, the unit vector e_m with perm[m] = j
    L.append(f"    inv = [0] * {n}")
    L += ["    for i, q in enumerate(perm):", "        inv[q] = i"]
    for j in range(n):
        L.append(f"    {', '.join(_x(i, j) for i in range(n))}, = _UNIT{n}[inv[{j}]]")
        for k in range(n - 1):
            L.append(f"    if {_x(k, j)} != 0.0:")
            L += [f"        {_x(i, j)} = {_x(i, j)} - {_a(i, k)} * {_x(k, j)}"
                  for i in range(k + 1, n)]
        for k in range(n - 1, -1, -1):
            L.append(f"    {_x(k, j)} = {_x(k, j)} * {_a(k, k)}")
            L += [f"    {_x(i, j)} = {_x(i, j)} - {_a(i, k)} * {_x(k, j)}" for i in range(k)]
    L.append(f"    X = ({', '.join(_x(i, j) for j in range(n) for i in range(n))},)")
    L += ["    s = sum(X)", "    if not s - s == 0.0 and not all(map(_isfinite, X)):",
          "        return None", "    return dz, X"]
    return L


def unpack_inverse(n: int, f: str = "f") -> str:
    """The statement unpacking a kept J^{-1} (column-major, in ``f``) into a<i>_<j>."""
    return f"{', '.join(_all(n))}, = {f}"


def matvec_lines(n: int, c: str = "c") -> list[str]:
    """b = A c (unindented), A = J^{-1} in a<i>_<j> (unpack_inverse), c in c0, c1, ...:
    b_i = A_i0 c_0, then b_i += A_ij c_j for j = 1, 2, ... (hpgen_lu_apply)."""
    return [f"b{i} = " + " + ".join(f"{_a(i, j)} * {c}{j}" for j in range(n))
            for i in range(n)]


def _matvec(n: int) -> list[str]:
    """x = A b, A = J^{-1} column-major in f, b in F (see matvec_lines)."""
    return [f"    {unpack_inverse(n)}", f"    {_names('c', n)}, = F"] + [
        "    " + line for line in matvec_lines(n)]


def finish_lines(n: int) -> list[str]:
    """(unindented) z - dz (z in z0.., dz in b0..) into z0.., and the inf-norms dn of dz and
    zn of the new z; ``return None`` if some entry is not finite (or a sum of entries
    overflows): the caller then takes the general path."""
    return [f"z{i} = z{i} - b{i}" for i in range(n)] + [
        f"s = {' + '.join(f'b{i}' for i in range(n))}",
        f"t = {' + '.join(f'z{i}' for i in range(n))}",
        "if not (s - s == 0.0 and t - t == 0.0):", "    return None"
    ] + max_abs("b", "dn", n) + max_abs("z", "zn", n)


def _finish(n: int) -> list[str]:
    """z - dz and the norms (finish_lines) from z in ``z``: ([z - dz], dn, zn) or None."""
    return [f"    {_names('z', n)}, = z"] + ["    " + line for line in finish_lines(n)] + [
        f"    return [{_names('z', n)}], dn, zn"]


def max_abs(v, m, n):
    """m = max |v_i| over finite v_i, as hpgen_norm_inf (from 0.0 up; a -0.0 entry gives
    t = -0.0, which is not > m); unindented."""
    L = [f"{m} = 0.0"]
    for i in range(n):
        L += [f"t = {v}{i} if {v}{i} >= 0.0 else -{v}{i}", f"if t > {m}:", f"    {m} = t"]
    return L


#: the names the printed source defines, in the order of a module's LINEAR tuple
FUNCTIONS = ("_lin_factor_solve", "_lin_apply", "_lin_update", "_lin_finish")


@lru_cache(maxsize=None)
def linear_solver_source(n: int) -> str:
    """The Python source of FUNCTIONS (factor_solve, apply, update, finish; see
    hpgen.runtime.newton.linear_solver) for nz = n <= UNROLL_MAX (deterministic)."""
    if not 1 <= n <= UNROLL_MAX:
        raise ValueError(f"no straight-line solver for n = {n}")
    L = _cofactor_factor_solve(n) if n <= COFACTOR_MAX else _lu_factor_solve(n)
    L += ["", "", "def _lin_apply(f, F):"] + _matvec(n) + [f"    return [{_names('b', n)}]"]
    # a non-finite F_j makes every entry of f F non-finite (finite * inf is inf or nan): the
    # check of f F in _finish covers F
    L += ["", "", "def _lin_update(f, F, z):"] + _matvec(n) + _finish(n)
    L += ["", "", "def _lin_finish(dz, z):", f"    {_names('b', n)}, = dz"] + _finish(n)
    return "\n".join(L) + "\n"


