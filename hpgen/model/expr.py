"""The Lagrangian, the scene's Poincare section and recorded expressions: text -> sympy.

Security: the text goes through ``ast.parse(..., mode="eval")`` only (hpgen.model.syntax); the
tree is checked against a whitelist and evaluated by the walker in hpgen.model.evaluator into
sympy objects. Nothing here evaluates strings.

Allowed: int/float literals; names; ``+ - * / ** @``; unary ``- +``; indexing ``v[i]`` /
``M[i, j]`` with non-negative integer literals or integer expressions (``+ - *``) of sum
variables and integer parameters; calls ``sin cos tan exp log sqrt`` (one argument,
elementwise), ``dot(u, v)`` and ``u @ v`` (numpy dot: vector.vector, matrix.vector,
vector.matrix, matrix.matrix), ``cross(a, b)``, ``transpose(M)``, ``norm2(v)`` and the sums
``sum(i, term)`` (over the bodies of a family) / ``sum(i, start, stop, term)`` (over
range(start, stop)); families of bodies (group ``G^N``) and their body-indexed names are
described in hpgen.model.families and hpgen.model.bodies. Values are sympy scalars or numpy object arrays (1-D vectors, 2-D matrices) of
sympy scalars; ``+ - * /`` are elementwise with scalar broadcasting, ``**`` needs a scalar
exponent. Literal ints stay exact (``1/2`` is Rational(1, 2)); parameters are numbers
(int -> Integer, float -> Float with the exact binary value), never symbols.

Names: ``xi`` (length d, symbols xi_k), ``g`` (n x n, symbols g_i_j), ``pi``, the parameters, and
for a single group ``R`` (rotation block: SO2, SO3, SE2, SE3) and ``x`` (translation: SE2, SE3,
R<n>). For a product group (more than one factor): ``xi_k``, ``g_k`` and, where factor k has
them, ``R_k``, ``x_k`` (0-based); ``xi``/``g`` are then the concatenated vector and the
block-diagonal matrix, and plain ``R``/``x`` are undefined.

Limits: text <= 200,000 characters, <= 50,000 syntax nodes, nesting depth <= 200 (left-nested
chains of + - and of * / count as one level, so a sum of 10^4 terms is fine), <= 50,000
elementwise operations, final expression tree <= 10^6 nodes. Every constant must be a finite
real number within double range; the result must be a scalar that depends on xi.

The section s(g, mu) (``parse_section``) is parsed the same way with ``mu`` (the node momentum,
length d, symbols mu_k; ``mu_k`` slices for products) in place of ``xi``; ``xi``/``xi_k`` are
refused, and the result must be a scalar that depends on mu or on an entry of g that varies on
the group (rotation / translation blocks). Its g symbols are equal (==, same hash) to the
Lagrangian's: same names, same ``real=True`` assumption. Errors have field "scene.section".

A recorded expression (``parse_record``, an entry ``{label: "text"}`` of ``scene.record``) may
use both ``xi`` and ``mu`` (and g); it must be a scalar depending on xi, mu or a varying entry of
g. Its xi / mu / g symbols are equal to the Lagrangian's / the section's. Errors carry the field
the caller passes (the scene uses "scene.record[i].label").

A holonomic constraint (``parse_constraint``, an entry of the model's ``constraints:`` list)
is a scalar or a vector in g (and its aliases) and the fixed parameters, one row per entry;
xi and t are refused, every row must depend on a varying entry of g. Errors carry the field
the caller passes ("constraints[i]").
"""
from __future__ import annotations

import math
import re

import numpy as np
import sympy as sp

from ..errors import ModelError
from .evaluator import _NONFINITE, _Evaluator, _shape_text
from .syntax import MAX_DEPTH, parse_checked
from .values import symbol_rows

MAX_TREE = 1_000_000
SECTION_FIELD = "scene.section"
RECORD_FIELD = "scene.record"
_XI_NAME = re.compile(r"xi(_[0-9]+)?")
_MU_NAME = re.compile(r"mu(_[0-9]+)?")


def _final_checks(expr, required, field="lagrangian", what="the Lagrangian") -> bool:
    """Tree size, non-finite/complex constants; iterative over the DAG. True when ``expr``
    contains one of the symbols ``required`` (the caller reports the missing dependence)."""
    size, const, seen, stack = {}, {}, set(), [(expr, False)]
    xiset = set(required)
    depends = False
    while stack:
        e, done = stack.pop()
        if done:
            size[id(e)] = min(1 + sum(size[id(a)] for a in e.args), MAX_TREE + 1)
            const[id(e)] = not e.is_Symbol and all(const[id(a)] for a in e.args)
            if size[id(e)] > MAX_TREE:
                raise ModelError(f"expression too large: more than {MAX_TREE} nodes after "
                                 f"evaluation (limit {MAX_TREE})", field=field)
            if e in _NONFINITE or e is sp.S.NaN:
                raise ModelError(f"{what} is not finite: it contains {e} (a division by "
                                 "zero or log(0)?)", field=field)
            if e is sp.I:
                raise ModelError(f"{what} is complex (contains the imaginary unit)",
                                 field=field)
            if const[id(e)] and (e.args or e.is_Number):
                try:
                    val = complex(e if e.is_Number else e.evalf(30))
                except (TypeError, ValueError, OverflowError):
                    val = complex(math.nan)
                if not (math.isfinite(val.real) and abs(val.imag) <= 1e-12 * max(1, abs(val.real))):
                    raise ModelError(f"the constant {str(e)[:60]} is not a finite real number "
                                     "within double range", field=field)
            if e in xiset:
                depends = True
            continue
        if id(e) in seen:
            continue
        seen.add(id(e))
        stack.append((e, True))
        stack.extend((a, False) for a in e.args if id(a) not in seen)
    return depends


def parse_lagrangian(text: str, group, parameters: dict, extra=None, refused=None):
    """(expr, xi_symbols, g_symbols) for the Lagrangian text on ``group`` (n, d, factors).

    ``parameters`` maps names to validated values (int, float, lists of them) or, for a
    runtime parameter, to its sympy symbol(s). ``extra``: further names ({"t": time symbol});
    ``refused``: {name: message} (the control inputs). Raises ModelError(field="lagrangian")
    without file/line (the loader adds them).
    """
    tree = parse_checked(text)
    ev = _Evaluator(group, parameters, extra=extra, refused=refused)
    try:
        result = ev.walk(tree.body)
    except RecursionError:
        raise ModelError(f"expression too large: nested too deeply (limit {MAX_DEPTH})",
                         field="lagrangian") from None
    if isinstance(result, np.ndarray):
        raise ModelError(f"the Lagrangian must be a scalar, got shape {result.shape} "
                         f"(a {_shape_text(result.shape)})", field="lagrangian")
    xi_syms = tuple(ev.vars["xi"].tolist())
    g_syms = symbol_rows("g", *ev.g.shape)
    try:
        depends = _final_checks(result, xi_syms)
    except RecursionError:
        raise ModelError("expression too large: nested too deeply", field="lagrangian") from None
    if not depends:
        raise ModelError(f"the Lagrangian does not depend on xi (it is {str(result)[:60]}); it "
                         "must contain the velocity xi, e.g. 0.5*xi[0]**2", field="lagrangian")
    return result, xi_syms, g_syms


def _relabel(e: ModelError, field: str) -> ModelError:
    """The shared parser's errors carry field "lagrangian"; relabel them with ``field``."""
    if e.field not in (None, "lagrangian"):
        return e
    out = ModelError(e.message, file=e.file, field=field, line=e.line)
    out.expr_line = getattr(e, "expr_line", None)
    return out


def _as_section_error(e: ModelError) -> ModelError:
    return _relabel(e, SECTION_FIELD)


def _refuse_mu_parameters(parameters: dict, field: str, user: str) -> None:
    mu_like = sorted(p for p in parameters if _MU_NAME.fullmatch(p))
    if mu_like:
        raise ModelError(f"the parameter {mu_like[0]!r} has the name of the momentum mu that "
                         f"{user} uses; rename the parameter", field=field)


def _parse_scalar(text: str, group, parameters: dict, variables, forbidden, field: str,
                  what: str, extra=None, refused=None):
    """(result, evaluator, depends): ``text`` walked with ``variables``; a scalar, checked by
    _final_checks; ``depends`` is True when it contains a variable or a varying entry of g.
    Every ModelError has ``field`` (no file/line; ``expr_line`` kept)."""
    try:
        tree = parse_checked(text)
        ev = _Evaluator(group, parameters, variables=variables, forbidden=forbidden,
                        extra=extra, refused=refused)
        try:
            result = ev.walk(tree.body)
        except RecursionError:
            raise ModelError(f"expression too large: nested too deeply (limit {MAX_DEPTH})",
                             field=field) from None
        if isinstance(result, np.ndarray):
            raise ModelError(f"{what} must be a scalar, got shape {result.shape} "
                             f"(a {_shape_text(result.shape)})", field=field)
        wanted = set(ev.varying_g)
        for v in variables:
            wanted.update(ev.vars[v].flat)
        try:
            depends = _final_checks(result, wanted, field, what)
        except RecursionError:
            raise ModelError("expression too large: nested too deeply", field=field) from None
    except ModelError as e:
        raise _relabel(e, field) from None
    return result, ev, depends


def parse_force(text: str, group, parameters: dict, extra: dict, field: str):
    """(expr, xi_symbols, g_symbols) for one component of the generalized force f in g*.

    Same grammar, functions and limits as the Lagrangian, with ``xi`` (symbols equal to
    Model.xi_symbols), ``g`` and its aliases, the parameters (runtime ones as symbols) and the
    names in ``extra`` (the time ``t`` and the control inputs). The result must be a finite
    scalar; it may be constant (a constant torque). Raises ModelError(field=field) without
    file/line (the loader adds them).
    """
    result, ev, _ = _parse_scalar(text, group, parameters, ("xi",), None, field,
                                  "a force component", extra=extra)
    return (result, tuple(ev.vars["xi"].tolist()),
            symbol_rows("g", *ev.g.shape))


def parse_section(text: str, group, parameters: dict):
    """(expr, mu_symbols, g_symbols) for the scene's Poincare section s(g, mu) on ``group``.

    Same grammar, functions and limits as the Lagrangian (parse_lagrangian) with ``mu`` (length
    d, symbols mu_k real) in place of ``xi``. mu_symbols is a d-tuple; g_symbols an n-tuple of
    n-tuples equal to the Lagrangian's (Model.g_symbols). The result must be a scalar depending
    on mu or on an entry of g that varies on the group. Raises ModelError(field="scene.section")
    without file/line (the scene parser adds them; ``expr_line`` as for the Lagrangian).
    """
    _refuse_mu_parameters(parameters, SECTION_FIELD, "the section")
    forbidden = (_XI_NAME, "the section may use mu (the node momentum) and g, not xi; "
                           "write it in terms of mu, e.g. mu[0]")
    result, ev, depends = _parse_scalar(text, group, parameters, ("mu",), forbidden,
                                        SECTION_FIELD, "the section")
    if not depends:
        raise ModelError(f"the section is constant on the group (it is {str(result)[:60]}; no "
                         "mu and no varying entry of g) and would never cross zero; expected an "
                         "expression in mu and/or g, e.g. mu[0] or R[2, 2] - 0.5",
                         field=SECTION_FIELD)
    mu_syms = tuple(ev.vars["mu"].tolist())
    g_syms = symbol_rows("g", *ev.g.shape)
    return result, mu_syms, g_syms


def parse_record(text: str, group, parameters: dict, field: str = RECORD_FIELD):
    """(expr, xi_symbols, mu_symbols, g_symbols) for a recorded expression on ``group``.

    Same grammar, functions and limits as the Lagrangian, with both ``xi`` (symbols xi_k, equal
    to Model.xi_symbols) and ``mu`` (symbols mu_k, equal to SectionSpec.mu_symbols) defined;
    g_symbols equal to Model.g_symbols. The result must be a scalar depending on xi, mu or an
    entry of g that varies on the group. Parameters named mu / mu_k are refused. Raises
    ModelError(field=field) without file/line (the scene parser adds them).
    """
    _refuse_mu_parameters(parameters, field, "a recorded expression")
    result, ev, depends = _parse_scalar(text, group, parameters, ("xi", "mu"), None, field,
                                        "a recorded expression")
    if not depends:
        raise ModelError(f"the recorded expression is constant (it is {str(result)[:60]}; no xi, "
                         "no mu and no varying entry of g); expected a scalar expression in xi, "
                         "mu and/or g, e.g. xi[0], mu[0] or R[2, 2]", field=field)
    xi_syms = tuple(ev.vars["xi"].tolist())
    mu_syms = tuple(ev.vars["mu"].tolist())
    g_syms = symbol_rows("g", *ev.g.shape)
    return result, xi_syms, mu_syms, g_syms


def parse_constraint(text: str, group, parameters: dict, field: str, refused=None,
                     bound=None):
    """(rows, g_symbols) for one holonomic constraint phi(g) = 0: a scalar or a vector
    expression in g and its aliases (R, x; R_k, x_k, g_k of products) and the parameters,
    the same grammar, functions and limits as the Lagrangian. ``rows``: a tuple of sympy
    scalars (one per entry), each depending on a varying entry of g; xi and t are refused,
    and so are the names in ``refused`` ({name: message}: the runtime parameters). Raises
    ModelError(field=field) without file/line (the loader adds them). ``bound``: {name: int},
    the loop variables of a constraint family (hpgen.model.joints), integers in the text."""
    forbidden = (_XI_NAME, "a constraint may use g (R, x, ...) and fixed parameters, not the "
                           "velocity xi: holonomic constraints are functions of the "
                           "configuration")
    try:
        tree = parse_checked(text)
        ev = _Evaluator(group, parameters, variables=(), forbidden=forbidden,
                        refused=refused)
        ev.bound.update(bound or {})
        try:
            result = ev.walk(tree.body)
        except RecursionError:
            raise ModelError(f"expression too large: nested too deeply (limit {MAX_DEPTH})",
                             field=field) from None
        if isinstance(result, np.ndarray) and result.ndim != 1:
            raise ModelError(f"a constraint must be a scalar or a vector, got shape "
                             f"{result.shape} (a {_shape_text(result.shape)})", field=field)
        rows = tuple(result.tolist()) if isinstance(result, np.ndarray) else (result,)
        for r, row in enumerate(rows):
            what = "the constraint" + (f" (row {r})" if len(rows) > 1 else "")
            if not _final_checks(row, set(ev.varying_g), field, what):
                raise ModelError(f"{what} is constant on the group (it is {str(row)[:60]}); "
                                 "expected an expression in R, x or g that vanishes on the "
                                 "admissible configurations, e.g. x - dot(R, c)", field=field)
    except ModelError as e:
        raise _relabel(e, field) from None
    return rows, symbol_rows("g", *ev.g.shape)
