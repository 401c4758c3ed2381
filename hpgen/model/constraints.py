"""The ``constraints:`` key: holonomic constraints phi(g) = 0 of the configuration.

The key holds a list; entry i is one expression (scalar or vector) in g and its aliases
(R, x; g_k, R_k, x_k of a product group) and the fixed parameters, parsed by the whitelist
parser (hpgen.model.expr.parse_constraint); each entry of a vector is one row of phi. The
velocity xi, the time t, control inputs and runtime parameters are refused. An entry may also
be a mapping (a row block repeated over joints ``for: i, in: [start, stop]``, the ball and pin
shorthands: hpgen.model.joints), expanded to one ConstraintSpec per row block. Errors name the
field ``constraints[i]`` (and the loop variable's value).

Redundant rows are refused: Phi(g) of deficient row rank at a fixed generic g (then it is
deficient everywhere). The scene's initial state must be admissible: |phi_r(g0)| <=
INITIAL_TOL (the residual is reported), the body-frame constraint Jacobian Phi(g0) (m x d,
Phi(g) eta = d/de phi(g exp(e eta)) at 0) must have full row rank m (a redundant row is
named), and when the scene gives xi0 the hidden constraint |Phi(g0) xi0| <= INITIAL_TOL
(1 + |xi0|) must hold. A scene given by mu0 is checked on the constraint only. A scene with
``initial.project: true`` is first moved onto the constraints (hpgen.model.projection), and
refused only when that fails.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass

import numpy as np

from ..errors import ModelError
from .yamldoc import describe, is_number

#: absolute tolerance on phi(g0) and on the hidden constraint Phi(g0) xi0 of the scene
INITIAL_TOL = 1e-9
#: a row of Phi(g0) whose distance to the span of the previous rows is below this fraction
#: of the largest row norm is redundant
RANK_TOL = 1e-9
#: a Legendre map whose smallest singular value is below this fraction of its largest is
#: singular (derive.checks' limit on the condition number, 1e12)
LEGENDRE_TOL = 1e-12
#: a symmetric matrix of at most this many rows gets one dense eigenvalue solve
DENSE_EIGEN_SIZE = 200


@dataclass(frozen=True)
class ConstraintSpec:
    """One entry of ``constraints:``: ``text`` as written, ``rows`` its sympy scalars (one per
    vector entry) in Model.g_symbols, parameters substituted as for the Lagrangian."""
    text: str
    rows: tuple
    label: str = ""                 #: how messages name it; "" -> constraints[i]
    #: ((loop variable, value),) of a row block repeated by ``for:`` (hpgen.model.joints)
    bound: tuple = ()


def parse_constraints(doc, raw, group, exact: dict, runtime_names, g_symbols,
                      lagrangian=None) -> tuple:
    """(ConstraintSpec, ...) from the ``constraints:`` list; ``exact`` the fixed parameters
    (ints exact), ``runtime_names`` the runtime parameters' names (refused); g_symbols:
    Model.g_symbols. Redundant rows (Phi of deficient rank at a generic g) are refused, and
    with ``lagrangian`` = (l, xi_symbols, {runtime symbol: default}) a singular Legendre map
    (check_legendre)."""
    from .expr import parse_constraint
    from .joints import RowBlock, expand_entry
    if not isinstance(raw, list) or not raw:
        raise doc.error(("constraints",), "expected a non-empty list of expressions in g "
                        f"(R, x, ...) that vanish, e.g. [x - dot(R, c)], got {describe(raw)}")
    refused = {n: f"the runtime parameter {n!r} may not appear in a constraint (constraints "
                  "take fixed parameters only)" for n in runtime_names}
    params = {k: v for k, v in exact.items() if k not in refused}
    out = []
    for i, entry in enumerate(raw):
        field = f"constraints[{i}]"
        if isinstance(entry, dict):
            blocks = expand_entry(doc, i, entry, group, params)
        elif is_number(entry) or not isinstance(entry, str) or not entry.strip():
            raise doc.error(("constraints", i), "expected an expression in g (R, x, ...) and "
                            "parameters that vanishes, or a mapping (row:, ball:, pin:, "
                            f"optionally for: / in:), got {describe(entry)}")
        else:
            blocks = [RowBlock(entry, {}, field)]
        for b in blocks:
            try:
                rows, _ = parse_constraint(b.text, group, params, field, refused, b.bound)
            except ModelError as e:
                message = re.sub(r" \((line \d+, )?column \d+\)", "", e.message) \
                    if b.generated else e.message
                if b.bound:
                    message = f"{b.label.removeprefix(field).strip()}: {message}"
                e = ModelError(message, field=e.field)
                raise e.located(doc.file, field, doc.line(("constraints", i))) from None
            out.append(ConstraintSpec(b.text, rows, b.label, tuple(b.bound.items())))
    if sum(len(c.rows) for c in out) >= group.d:
        raise doc.error(("constraints",), f"{sum(len(c.rows) for c in out)} constraint rows "
                        f"leave no freedom on {group.name} (d = {group.d}); expected fewer than d")
    generic = _generic_point(group)
    _check_rank(doc, out, g_symbols, group, generic, "at a generic g")
    if lagrangian is not None:
        check_legendre(doc, out, g_symbols, group, generic, lagrangian)
    return tuple(out)


def check_legendre(doc, constraints, g_symbols, group, g, lagrangian) -> None:
    """The constrained step inverts H = d2l/dxi2 (its node velocity is H^-1 (p - Phi^T nu)
    on Phi xi = 0): refuse, at g and xi = 0 (t = 0, runtime parameters at their defaults),
    a constrained Legendre map [[H, Phi^T], [Phi, 0]] that is singular (l flat along a
    velocity the constraints leave free: naming it), and a singular H whose flat direction
    the constraints remove (a massless constrained direction, not supported)."""
    _, Phi, _ = constraint_values(constraints, g_symbols, group, g)
    H = _legendre_map(lagrangian, g_symbols, group, g)
    if not np.all(np.isfinite(H)):
        return                      # the Legendre check of the derived step reports it
    m, d = Phi.shape
    scale = max(np.abs(H).max(), 1e-300)
    kkt = np.block([[H / scale, Phi.T], [Phi, np.zeros((m, m))]])
    s = _singular_values(kkt)
    if s[-1] <= LEGENDRE_TOL * s[0]:
        v = np.linalg.svd(kkt)[2][-1][:d]
        raise doc.error(("lagrangian",), "the constrained Legendre map is singular at a "
                        "generic g: l has no second derivative along the velocity "
                        f"{_direction(v)}, which the constraints leave free; the Lagrangian "
                        "must be nondegenerate in xi on the constraints")
    sh = _singular_values(H / scale)
    if sh[-1] <= LEGENDRE_TOL * sh[0]:
        v = np.linalg.svd(H)[2][-1]
        raise doc.error(("lagrangian",), "d2l/dxi2 is singular at a generic g (l is flat "
                        f"along the velocity {_direction(v)}); the constraints fix that "
                        "velocity, but the constrained step needs d2l/dxi2 invertible: give "
                        "that direction an inertia")


def _singular_values(a):
    """The singular values of the symmetric matrix ``a``, decreasing: its eigenvalues'
    magnitudes (symmetrized first, so round-off asymmetry does not matter), computed per
    connected block of its nonzero pattern and, for a block that is banded after a
    reverse Cuthill-McKee ordering (a family's body-local terms and joints), by the banded
    solver; a permutation leaves the eigenvalues unchanged. Up to DENSE_EIGEN_SIZE rows,
    one dense eigvalsh."""
    a = (a + a.T) / 2
    if len(a) <= DENSE_EIGEN_SIZE:
        return np.sort(np.abs(np.linalg.eigvalsh(a)))[::-1]
    from scipy.linalg import eig_banded
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components, reverse_cuthill_mckee
    count, block_of = connected_components(csr_matrix(a != 0), directed=False)
    values = []
    for b in range(count):
        idx = np.flatnonzero(block_of == b)
        block = a[np.ix_(idx, idx)]
        order = reverse_cuthill_mckee(csr_matrix(block != 0), symmetric_mode=True)
        block = block[np.ix_(order, order)]
        rows, cols = np.nonzero(block)
        width = int(np.abs(rows - cols).max()) if rows.size else 0
        if 4 * width < len(idx):
            bands = np.zeros((width + 1, len(idx)))      # lower band storage
            for k in range(width + 1):
                bands[k, :len(idx) - k] = np.diagonal(block, -k)
            values.append(eig_banded(bands, lower=True, eigvals_only=True))
        else:
            values.append(np.linalg.eigvalsh(block))
    return np.sort(np.abs(np.concatenate(values)))[::-1]


def _legendre_map(lagrangian, g_symbols, group, g):
    """H = d2l/dxi2 (d x d) at numeric g and xi = 0, t = 0, runtime parameters at their
    defaults; lagrangian: (l, xi_symbols, {runtime symbol: default}). Only the entries of g
    that l uses become CasADi symbols."""
    import casadi as ca

    from ..derive.lagrangian import to_casadi
    from .symbols import TIME_SYMBOL
    lag, xi_symbols, runtime = lagrangian
    from .family_load import BodyLagrangian, body_terms_hessian
    if isinstance(lag, BodyLagrangian):       # a family loaded body by body
        return body_terms_hessian(lag, group, g, runtime)
    expr = lag.xreplace({TIME_SYMBOL: 0, **runtime})
    where = {s: (i, j) for i, row in enumerate(g_symbols) for j, s in enumerate(row)}
    used = sorted(where[s] for s in expr.free_symbols if s in where)
    v, X = ca.SX.sym("v", len(used)), ca.SX.sym("xi", group.d)
    mapping = {**{g_symbols[i][j]: v[k] for k, (i, j) in enumerate(used)},
               **{s: X[k] for k, s in enumerate(xi_symbols)}}
    H = ca.hessian(to_casadi(expr, mapping), X)[0]
    fun = ca.Function("legendre_map", [v, X], [H])
    values = [float(g[i][j]) for i, j in used]
    return np.array(fun(values, np.zeros(group.d)), dtype=float)


def _direction(v) -> str:
    """A unit vector of the algebra as text: its largest entries, ``xi[k]``."""
    ks = [k for k in np.argsort(-np.abs(v)) if abs(v[k]) > 1e-8 * np.abs(v).max()][:4]
    return " ".join(f"{'+' if v[k] > 0 else '-'} {abs(v[k]):.3g} xi[{k}]"
                    for k in sorted(ks)).lstrip("+ ")


def _generic_point(group):
    """A fixed pseudo-random element tau(x) of the group (x of norm about 0.5 per entry):
    the rank of Phi there is its generic (maximal) rank, so a rank drop there is a drop
    everywhere (the rows are redundant as written, not only at special configurations)."""
    import casadi as ca
    x = np.random.default_rng(12345).uniform(-0.5, 0.5, group.d)
    kind, parts = group.tau_kinds[0], getattr(group, "parts", None)
    if not parts:
        return np.array(ca.evalf(ca.SX(group.tau(kind, ca.SX(x)))), dtype=float)
    # a product: tau block by block, one numeric function per distinct factor
    g, funs, row, off = np.zeros((group.n, group.n)), {}, 0, 0
    for f in parts:
        if f.name not in funs:
            X = ca.SX.sym("x", f.d)
            funs[f.name] = ca.Function("tau", [X], [f.tau(kind, X)])
        g[row:row + f.n, row:row + f.n] = np.array(funs[f.name](x[off:off + f.d]))
        row, off = row + f.n, off + f.d
    return g


def _check_rank(doc, constraints, g_symbols, group, g, where: str) -> None:
    _, Phi, labels = constraint_values(constraints, g_symbols, group, g)
    scale = max(np.abs(Phi).max(), 1e-300)
    basis = np.zeros(Phi.shape)      # orthonormal rows spanning Phi[:r]
    for r in range(len(Phi)):
        rest = Phi[r] - basis[:r].T @ (basis[:r] @ Phi[r])
        if np.linalg.norm(rest) <= RANK_TOL * scale:
            raise doc.error(("constraints",), f"{labels[r]} is redundant {where}: its Jacobian "
                            "row is a combination of the previous rows' (singular constraint "
                            "Jacobian); remove it or the rows it repeats")
        basis[r] = rest / np.linalg.norm(rest)


def _numeric_hats(group) -> list:
    """((layout, [hat(e_a) as numpy n_f x n_f arrays of the factor, a = 0..d_f-1]), ...) per
    factor of the group (one entry for a single group)."""
    import casadi as ca
    from ..groups import group_from_spec
    out, cache = [], {}
    factors = group.factors
    for lay in factors:
        if lay.name not in cache:
            fg = group_from_spec(lay.name) if len(factors) > 1 else group
            eye = np.eye(lay.d)
            cache[lay.name] = [np.array(ca.evalf(ca.SX(fg.hat(ca.SX(eye[:, a])))), dtype=float)
                               for a in range(lay.d)]
        out.append((lay, cache[lay.name]))
    return out


def constraint_values(constraints, g_symbols, group, g0):
    """(phi(g0) (m,), Phi(g0) (m x d), labels) for numeric g0 (n x n); labels[r] names row r
    (``constraints[i]`` or ``constraints[i] row j``). The rows and their gradient in the
    entries of g they use are evaluated by one CasADi function (_row_function); Phi follows
    from d/de g0 exp(e E_a) at 0 = g0 E_a."""
    fun, used, labels = _row_function(tuple(constraints), tuple(map(tuple, g_symbols)))
    g0 = np.asarray(g0, dtype=float)
    where = np.array(used, dtype=int).reshape(len(used), 2)
    phi, grad = fun(g0[where[:, 0], where[:, 1]])
    phi = np.array(phi, dtype=float).reshape(len(labels))
    grad = np.array(grad, dtype=float).reshape(len(labels), len(used))
    Phi = np.zeros((len(labels), group.d))
    for lay, Es in _numeric_hats(group):
        # the used entries (i, j) in the factor's columns: dphi/de_a = sum grad * (g0 E_a)[i, j]
        ks = np.flatnonzero((where[:, 1] >= lay.row) & (where[:, 1] < lay.row + lay.n))
        if not len(ks):
            continue
        cols = g0[:, lay.row:lay.row + lay.n]
        D = np.stack([(cols @ E)[where[ks, 0], where[ks, 1] - lay.row] for E in Es], axis=1)
        Phi[:, lay.off:lay.off + lay.d] = grad[:, ks] @ D
    return phi, Phi, labels


@functools.lru_cache(maxsize=8)
def _row_function(constraints: tuple, g_symbols: tuple):
    """(casadi.Function v -> (phi, dphi/dv), ((i, j) of v's entries in g, ...), labels) for
    the rows of ``constraints``: v the entries of g the rows use, in row-major order."""
    import casadi as ca

    from ..derive.lagrangian import to_casadi
    where = {s: (i, j) for i, row in enumerate(g_symbols) for j, s in enumerate(row)}
    rows, labels = [], []
    for i, c in enumerate(constraints):
        for j, row in enumerate(c.rows):
            labels.append((c.label or f"constraints[{i}]")
                          + (f" row {j}" if len(c.rows) > 1 else ""))
            rows.append(row)
    used = sorted({where[s] for r in rows for s in r.free_symbols})
    v = ca.SX.sym("v", len(used))
    symbol = {g_symbols[i][j]: v[k] for k, (i, j) in enumerate(used)}
    phi = ca.vertcat(*[to_casadi(r, symbol) for r in rows])
    fun = ca.Function("constraint_rows", [v], [phi, ca.jacobian(phi, v)])
    return fun, tuple(used), tuple(labels)


def check_initial(doc, constraints, g_symbols, group, scene, lagrangian=None):
    """The scene with its admissible initial state: refused when not admissible (the module
    docstring), or first moved onto the constraints when the scene asks (``initial.project``,
    hpgen.model.projection; the returned Scene then carries ``projection``). lagrangian:
    (l, xi_symbols, {runtime symbol: default}) for the projection's metric."""
    if scene is None:
        return scene
    if scene.project:
        if not constraints:
            raise doc.error(("scene", "initial", "project"), "this model has no constraints: "
                            "there is nothing to project the initial state onto (remove "
                            "project or add constraints:)")
        scene = _projected(doc, constraints, g_symbols, group, scene, lagrangian)
    if not constraints:
        return scene
    phi, Phi, labels = constraint_values(constraints, g_symbols, group, scene.g0)
    path = ("scene", "initial", "g")
    for r, v in enumerate(phi):
        if not abs(v) <= INITIAL_TOL:
            raise doc.error(path, f"the initial g violates {labels[r]}: residual {v:.3e} "
                            f"(expected |phi(g0)| <= {INITIAL_TOL:g}, or initial.project: true "
                            "to move it onto the constraints)")
    _check_rank(doc, constraints, g_symbols, group, scene.g0, "at the initial g")
    if scene.xi0 is not None:
        xi0 = np.asarray(scene.xi0, dtype=float)
        hidden = Phi @ xi0
        tol = INITIAL_TOL * (1 + np.abs(xi0).max())
        for r, v in enumerate(hidden):
            if not abs(v) <= tol:
                raise doc.error(("scene", "initial", "xi"), f"the initial xi violates the "
                                f"velocity form of {labels[r]}: Phi(g0) xi0 = {v:.3e} "
                                f"(expected |Phi(g0) xi0| <= {tol:.1e}, or initial.project: "
                                "true to project it)")
    return scene


def _projected(doc, constraints, g_symbols, group, scene, lagrangian):
    """The scene with (g0, xi0) projected (hpgen.model.projection)."""
    import dataclasses

    from .projection import project
    from .symbols import TIME_SYMBOL
    path = ("scene", "initial", "project")
    _check_rank(doc, constraints, g_symbols, group, scene.g0, "at the initial g")
    lag, xi_symbols, runtime = lagrangian
    fixed = {TIME_SYMBOL: 0, **runtime}
    try:
        g, xi, note = project(constraints, g_symbols, group, lag, xi_symbols, fixed,
                              scene.g0, scene.xi0)
    except np.linalg.LinAlgError:
        raise doc.error(path, "cannot project: d2l/dxi2 or Phi H^-1 Phi^T is singular at the "
                        "initial state (the constrained Legendre map is not invertible)") \
            from None
    if not note.residual_after <= INITIAL_TOL:
        raise doc.error(path, f"cannot project the initial g onto the constraints: the "
                        f"residual went from {note.residual_before:.3e} to "
                        f"{note.residual_after:.3e} (expected <= {INITIAL_TOL:g}); start "
                        "closer to them")
    if not np.all(np.isfinite(g)):
        raise doc.error(path, "cannot project: the projected g is not finite")
    return dataclasses.replace(
        scene, g0=tuple(tuple(float(v) for v in row) for row in g),
        xi0=None if xi is None else tuple(float(v) for v in xi), projection=note)
