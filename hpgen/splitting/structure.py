"""Recognition of the structure that makes a step explicit, from the derived Lagrangian.

A model admits the splitting schemes when its Lagrangian is

    l(g, xi) = 1/2 xi . M xi - V(g)

with M constant (free of g, xi and the runtime parameters), symmetric positive definite and
block diagonal over the factors of the group, each factor one of

- SO3: any SPD 3 x 3 block, diagonalised at compile time: M = Q diag(D) Q^T, the columns
  of Q the principal axes (body frame), the largest moment last; a diagonal block keeps
  the coordinate axes (permuted); two
  equal moments (a symmetric body) are noted (its free flow is exact in closed form);
- SE3: xi = (omega, v), M = diag(M_rot, M_tr) (rotation and translation decoupled), M_rot
  as for SO3, M_tr any SPD block;
- SO2: M = (I,);
- R<n>: any SPD block;

and V a function of g (and of the runtime parameters and t) alone; forces may depend on
(g, t, u, params) but not on xi (they join -dV in the kicks, hpgen.splitting.flows). No
constraints (a constrained family model's bodies are recognised one by one,
recognise_lagrangian, hpgen.derive.family_split). ``recognise`` returns
the frozen description the flows are built from, or raises ModelError naming what breaks
the structure (a Lagrangian term where one can be named).
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..errors import ModelError

FIELD = "integrator.tableau"
#: the group families whose free flow the splitting knows exactly (or by DLM rotations)
FAMILIES = ("SO3", "SE3", "SO2", "R")


@dataclass(frozen=True)
class FactorKinetics:
    """The kinetic energy of one group factor: ``family`` (SO3, SE3, SO2, R), its place
    (``row``, ``n``: block of g; ``off``, ``d``: slice of xi and p), ``axes`` the principal
    axes (columns of a 3 x 3 rotation, as nested tuples) and ``moments`` D (rotation part;
    empty for R), ``translation_inverse`` M_tr^{-1} (SE3, R; nested tuples, else ())."""
    family: str
    row: int
    n: int
    off: int
    d: int
    axes: tuple = ()
    moments: tuple = ()
    translation_inverse: tuple = ()
    #: the axis index of the distinct moment of a symmetric body (two moments equal, or
    #: three: then any), whose free flow is exact in closed form; None otherwise
    symmetric_axis: int | None = None
    #: Fasso's kinetic splitting of an asymmetric body, (a, b, s) axis indices: T = T_sym +
    #: T_r, T_sym = |pi|^2 / (2 D_s) + (1/D_a - 1/D_s) pi_a^2 / 2 (a symmetric top, exact),
    #: T_r = (1/D_b - 1/D_s) pi_b^2 / 2 (one rotation about b); {b, s} the pair of moments
    #: with the smallest |1/D_b - 1/D_s|; () for a symmetric body or without three moments
    fasso: tuple = ()


@dataclass(frozen=True)
class SplitStructure:
    """l = 1/2 xi.M xi - V(g): the factors' kinetic energies (in group-factor order)."""
    factors: tuple


def _refuse(msg: str) -> ModelError:
    return ModelError(f"the splitting schemes need l = 1/2 xi.M xi - V(g) with constant "
                      f"block-diagonal M: {msg}", field=FIELD)


def _family(name: str) -> str:
    if name in ("SO3", "SE3", "SO2"):
        return name
    if name.startswith("R") and name[1:].isdigit():
        return "R"
    raise _refuse(f"group {name} has no explicit free flow here (supported: SO3, SE3, SO2, "
                  "R<n> and products of them)")


def _term_breaking(model, expr=None, xs=None) -> str:
    """The first additive term of the model's Lagrangian (or of the sympy ``expr`` in the
    symbols ``xs``) that is neither free of xi nor a constant quadratic form in xi, as text
    ('' when none can be singled out)."""
    import sympy as sp
    xs = tuple(model.xi_symbols) if xs is None else tuple(xs)
    for term in sp.Add.make_args(model.lagrangian if expr is None else expr):
        if not term.free_symbols & set(xs):
            continue
        at0 = {x: 0 for x in xs}
        ok = term.subs(at0) == 0 and all(sp.diff(term, x).subs(at0) == 0 for x in xs) \
            and all(not sp.diff(term, x, y).free_symbols for x in xs for y in xs)
        if not ok:
            text = str(term)
            return text if len(text) <= 60 else text[:57] + "..."
    return ""


def _principal(block: np.ndarray):
    """(axes Q as nested tuples, moments D) of an SPD 3 x 3 block, ordered so that the
    largest moment comes last: the DLM free flow X1(t/2) X2(t/2) X3(t) X2(t/2) X1(t/2) then
    rotates about the axis of largest moment in the middle (heavy top I = (1, 5, 6): 15-70x
    smaller errors than the other two choices at orders 2, 6, 8). A diagonal block keeps the
    coordinate axes (a signed permutation with det +1), any other is diagonalised by numpy's
    eigh (ascending moments, det Q = +1)."""
    if not np.any(block - np.diag(np.diag(block))):
        D = np.diag(block)
        last = int(np.argmax(D))
        order = [i for i in range(3) if i != last] + [last]
        Q = np.eye(3)[:, order]
        D = D[order]
    else:
        D, Q = np.linalg.eigh(block)
    if np.linalg.det(Q) < 0:
        Q[:, 0] = -Q[:, 0]
    return tuple(tuple(float(v) for v in r) for r in Q), tuple(float(v) for v in D)


def recognise(model, lag, params=None) -> SplitStructure:
    """The SplitStructure of ``model`` with l given as ``lag(g, xi)`` (SX in, SX out; the
    runtime parameters and t, if any, bound to the SX symbols ``params``), or ModelError."""
    if model.constraints:
        raise _refuse("the model has constraints and is not derived body by body (split2 "
                      "takes constraints on a family model with local sums and joints; else "
                      "use a VPRK tableau)")
    texts = getattr(model, "forces_text", ())
    for k, e in enumerate(model.forces if model.forced else ()):
        if any(str(s).startswith("xi_") for s in e.free_symbols):
            text = texts[k] if k < len(texts) else str(e)
            text = text if len(text) <= 40 else text[:37] + "..."
            raise _refuse(f"forces[{k}] ({text}) depends on the velocity; the kicks take "
                          "forces of (g, t, u, params) only (use a VPRK tableau)")
    return recognise_lagrangian(model.group, lag, params, lambda: _term_breaking(model))


def recognise_lagrangian(group, lag, params=None, breaking=None,
                         where: str = "") -> SplitStructure:
    """The SplitStructure of l = ``lag(g, xi)`` on ``group`` alone (no model-level checks:
    a family's body Lagrangian, hpgen.derive.family_split), or ModelError; ``params``: SX
    symbols l may depend on (runtime parameters, a body index) but M may not; ``breaking()``
    -> the text of the term that breaks the structure ('' if none); ``where``: a prefix of
    the message naming what was recognised (a body class)."""
    n, d = group.n, group.d
    g, xi = ca.SX.sym("g", n, n), ca.SX.sym("xi", d)
    L = lag(g, xi)
    H = ca.hessian(L, xi)[0]
    moving = [ca.vec(g), xi] + ([params] if params is not None and params.numel() else [])
    term = (lambda: breaking() if breaking is not None else "")  # noqa: E731
    if ca.depends_on(H, ca.vertcat(*moving)):
        t = term()
        raise _refuse(where + "d2l/dxi2 is not constant" + (f" (term {t})" if t else ""))
    lin = ca.substitute(ca.gradient(L, xi), xi, ca.SX.zeros(d))
    if not _vanishes(lin, [ca.vec(g)] + moving[2:], None, n):
        t = term()
        raise _refuse(where + "l has a term linear in xi" + (f" ({t})" if t else ""))
    M = np.array(ca.evalf(H), dtype=float)
    factors = []
    for lay in group.factors:
        fam = _family(lay.name)
        sl = slice(lay.off, lay.off + lay.d)
        rest = M[sl, :].copy()
        rest[:, sl] = 0.0
        if np.any(rest):
            raise _refuse(where + f"the inertia couples factor {lay.name} (xi[{lay.off}:"
                          f"{lay.off + lay.d}]) with another factor")
        B = M[sl, sl]
        if np.any(B != B.T) or np.linalg.eigvalsh(B).min() <= 0.0:
            raise _refuse(where + f"the inertia of factor {lay.name} is not symmetric "
                          "positive definite")
        axes, moments, tinv = (), (), ()
        if fam in ("SO3", "SE3"):
            if fam == "SE3" and np.any(B[:3, 3:]):
                raise _refuse(where + "the SE3 inertia couples rotation and translation (block "
                              "xi[0:3] x xi[3:6] not zero)")
            axes, moments = _principal(B[:3, :3])
        if fam == "SO2":
            moments = (float(B[0, 0]),)
        if fam in ("SE3", "R"):
            T = B[3:, 3:] if fam == "SE3" else B
            tinv = tuple(tuple(float(v) for v in r) for r in np.linalg.inv(T))
        sym = None
        if len(moments) == 3:
            for c in range(3):
                a, b = [i for i in range(3) if i != c]
                if moments[a] == moments[b]:
                    sym = c
                    break
        fasso = _fasso_axes(moments) if len(moments) == 3 and sym is None else ()
        factors.append(FactorKinetics(fam, lay.row, lay.n, lay.off, lay.d, axes, moments,
                                      tinv, sym, fasso))
    return SplitStructure(tuple(factors))


def _fasso_axes(moments) -> tuple:
    """(a, b, s) of Fasso's splitting (FactorKinetics.fasso) for three distinct moments:
    the pair {b, s} with the smallest |1/D_b - 1/D_s| (ties: the first in axis order), s the
    one of smaller moment (on the heavy top, I = (1, 5, 6), 3x smaller errors with
    split6-blanes-moan than s the larger); a the third axis."""
    inv = [1.0 / m for m in moments]
    pairs = [(0, 1), (0, 2), (1, 2)]
    i, j = min(pairs, key=lambda q: abs(inv[q[0]] - inv[q[1]]))
    s, b = (i, j) if moments[i] < moments[j] else (j, i)
    return (3 - i - j, b, s)


def _vanishes(expr, inputs, model, n) -> bool:
    """Whether the SX ``expr`` of g (and parameters) is zero: structurally, else at a few
    random group-like points (it is an analytic function of g)."""
    if not ca.depends_on(expr, ca.vertcat(*inputs)):
        return not np.any(np.array(ca.evalf(expr), dtype=float))
    f = ca.Function("lin", inputs, [expr])
    rng = np.random.default_rng(0)
    for _ in range(3):
        args = [rng.normal(size=(int(v.numel()), 1)) for v in inputs]
        if np.abs(np.array(f(*args), dtype=float)).max() > 1e-13:
            return False
    return True
