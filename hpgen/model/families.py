"""Families of bodies: a group ``G^N`` of N identical bodies and the sums over them.

Conventions:
- ``group: G^N`` (G one of SO2, SO3, SE2, SE3, R<k>; N a positive integer literal or the
  name of an integer parameter) is the direct product of N copies of G, body i being factor
  i (0-based). It is compiled as the product group ``[G, G, ...]`` (a FamilyGroup, i.e. a
  ProductGroup that remembers its BodyFamily), so every later stage treats it as a product.
- Indexing rule (hpgen.model.evaluator): in a family model the group names ``xi g R x w v``
  are indexed by body first: ``xi[i]`` is body i's algebra vector, ``xi[i][k]`` its
  component k, ``R[i]`` its rotation, ``R[i][a, b]`` an entry. The product aliases ``xi_k``,
  ``g_k``, ``R_k``, ``x_k`` stay defined (equal to ``xi[k]`` ...). The flat concatenated xi of
  a product is not available in a family model.
- ``sum(i, term)`` sums over i = 0..N-1, ``sum(i, start, stop, term)`` over start..stop-1
  (Python's range): a sum is kept in the parsed model as a FamilySum (its variable, its range
  as written and evaluated, and its per-body term as text), so that a later stage can derive
  the term once and map it over the range; today the sums are expanded into the product
  group's Lagrangian.
- Parameter overrides (``--set N=8``, ``parameters={"N": 8}``) are applied to the file's text
  by hpgen.model.overrides, so a changed N is a different model text and a different hash.
"""
from __future__ import annotations

import ast
import re
from dataclasses import dataclass

from ..errors import ModelError
from ..groups.catalog import ProductGroup, group_from_spec

#: the largest body count accepted before any group is built (the dense pipeline's matrix
#: size limit in hpgen.model.loader refuses much smaller families)
MAX_BODIES = 4096
_FAMILY = re.compile(r"\s*([A-Za-z][A-Za-z0-9]*)\s*\^\s*([A-Za-z_][A-Za-z0-9_]*|[0-9]+)\s*")


@dataclass(frozen=True)
class FamilySum:
    """One top-level ``sum`` of the Lagrangian: ``sign`` (+1 or -1) times ``term`` (its text,
    in the sum variable ``variable``) summed over ``range(start, stop)``; ``start_text`` /
    ``stop_text`` as written (e.g. "1" and "N"), ``start``/``stop`` their values for this
    model's N."""
    variable: str
    start: int
    stop: int
    start_text: str
    stop_text: str
    term: str
    sign: int = 1


@dataclass(frozen=True)
class BodyFamily:
    """N identical bodies on the group ``body`` (a group name); ``count`` = N; ``count_name``
    the parameter that sets it (None for a literal); ``sums`` the Lagrangian's top-level
    FamilySum terms (filled by ``with_sums``), ``rest`` its remaining text or None."""
    body: str
    count: int
    count_name: str | None = None
    sums: tuple = ()
    rest: str | None = None
    #: the sums and joints evaluated once for a generic body (hpgen.model.bodyterms.LocalTerms),
    #: None when some term couples bodies' velocities (the model is then compiled expanded)
    local: object = None


class FamilyGroup(ProductGroup):
    """The product of ``family.count`` copies of ``family.body``: a ProductGroup that also
    carries its BodyFamily (``family``), read by the expression evaluator."""

    def __init__(self, family: BodyFamily):
        super().__init__([group_from_spec(family.body) for _ in range(family.count)])
        self.family = family

    def momentum_map(self, g, p):
        """Ad*_{g^{-1}} p body by body (the product's Ad is block-diagonal; building it from
        the product's d basis vectors would cost O(N^2)). For SX, one body's map is built
        once as a function and its expression replayed on every body's (g, p)."""
        import casadi as ca
        gs, ps = self._split_g(g), self._split_v(p)
        if not isinstance(g, ca.SX):
            return ca.vertcat(*[f.momentum_map(gk, pk) for f, gk, pk in
                                zip(self.parts, gs, ps)])
        body = self.parts[0]
        G, P = ca.SX.sym("g", body.n, body.n), ca.SX.sym("p", body.d)
        one = ca.Function("body_momentum_map", [G, P], [body.momentum_map(G, P)])
        return ca.vertcat(*[one(gk, pk) for gk, pk in zip(gs, ps)])


def family_of(group) -> BodyFamily | None:
    """The BodyFamily of a FamilyGroup, None for any other group."""
    return group.family if isinstance(group, FamilyGroup) else None


def is_family_spec(spec) -> bool:
    return isinstance(spec, str) and "^" in spec


def parse_family_spec(spec: str, parameters: dict) -> BodyFamily:
    """The BodyFamily of ``G^N``; ``parameters`` maps names to values as written in the file.
    Raises ModelError(field="group") naming what was expected."""
    m = _FAMILY.fullmatch(spec)
    if not m:
        raise ModelError(f"malformed family {spec!r}: expected G^N with G a group name (SO2, "
                         "SO3, SE2, SE3, R<k>) and N a positive integer or an integer "
                         "parameter, e.g. SE3^N", field="group")
    body, count_text = m.group(1), m.group(2)
    group_from_spec(body)                                  # an unknown body group: its message
    name = None
    if count_text[0].isdigit():
        count = int(count_text)
    else:
        name = count_text
        if name not in parameters:
            raise ModelError(f"the body count {name!r} of {spec!r} is not a parameter; declare "
                             f"it, e.g. parameters: {{{name}: 4}}", field="group")
        count = parameters[name]
    if type(count) is not int or count < 1:
        what = f"the parameter {name}" if name else "the body count"
        raise ModelError(f"{what} of {spec!r} must be a positive integer (the number of "
                         f"bodies), got {count!r}", field=f"parameters.{name}" if name else "group")
    if count > MAX_BODIES:
        raise ModelError(f"too many bodies: {count} (limit {MAX_BODIES})",
                         field=f"parameters.{name}" if name else "group")
    return BodyFamily(body=group_from_spec(body).name, count=count, count_name=name)


def _segment(text: str, node) -> str:
    return ast.get_source_segment(text, node) or ast.unparse(node)


def with_sums(family: BodyFamily, text: str, tree, parameters: dict) -> BodyFamily:
    """``family`` with the top-level sums of the checked Lagrangian ``tree`` (the text
    ``text``) as FamilySum terms and the remaining terms' text as ``rest``. The evaluator has
    checked the sums already (variables, ranges), so their bounds evaluate here."""
    terms, stack = [], [(tree.body, True)]
    while stack:
        node, sign = stack.pop()
        if isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub)):
            stack.append((node.left, sign))
            stack.append((node.right, sign == isinstance(node.op, ast.Add)))
        else:
            terms.append((node, sign))
    sums, rest = [], []
    for node, sign in reversed(terms):
        if _is_sum(node):
            sums.append(_family_sum(family, text, node, parameters, 1 if sign else -1))
        else:
            rest.append(("+ " if sign else "- ") + _segment(text, node))
    tail = " ".join(rest).removeprefix("+ ") if rest else None
    return BodyFamily(family.body, family.count, family.count_name, tuple(sums), tail)


def _is_sum(node) -> bool:
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
        and node.func.id == "sum"


def _family_sum(family: BodyFamily, text: str, node, parameters: dict, sign: int) -> FamilySum:
    args = node.args
    var = args[0].id
    if len(args) == 2:
        start_t, stop_t = "0", family.count_name or str(family.count)
        start, stop = 0, family.count
    else:
        start_t, stop_t = _segment(text, args[1]), _segment(text, args[2])
        start, stop = (_bound(a, parameters) for a in args[1:3])
    return FamilySum(var, start, stop, start_t, stop_t, _segment(text, args[-1]), sign)


def _bound(node, parameters: dict) -> int:
    """A top-level sum's bound: integer literals, integer parameters and + - * of them
    (checked by the evaluator before)."""
    if isinstance(node, ast.Constant):
        return int(node.value)
    if isinstance(node, ast.Name):
        return int(parameters[node.id])
    if isinstance(node, ast.UnaryOp):
        v = _bound(node.operand, parameters)
        return -v if isinstance(node.op, ast.USub) else v
    a, b = _bound(node.left, parameters), _bound(node.right, parameters)
    return a + b if isinstance(node.op, ast.Add) else a - b if isinstance(node.op, ast.Sub) \
        else a * b


def group_of_spec(spec, parameters: dict):
    """The group of a model file's ``group`` field: a FamilyGroup for ``G^N``, else
    hpgen.groups.group_from_spec. ``parameters``: the file's values as written."""
    if is_family_spec(spec):
        return FamilyGroup(parse_family_spec(spec, parameters))
    if isinstance(spec, list) and any(is_family_spec(s) for s in spec):
        raise ModelError("a family G^N is the whole group (e.g. group: SE3^N); it cannot be "
                         "a factor of a list", field="group")
    return group_from_spec(spec)


def repeat_initial(group, initial: dict) -> dict:
    """A scene's ``initial`` mapping with one body's entry repeated for every body of a
    family: ``g`` one body's spec (``{rotvec: ...}``, ``{angle: ...}``, ``{position: ...}`` or
    its matrix), ``xi``/``mu`` one body's d numbers. Other entries (and other groups) are
    returned unchanged; the scene parser validates the result."""
    family = family_of(group)
    if family is None or not isinstance(initial, dict):
        return initial
    out = dict(initial)
    body = group_from_spec(family.body)
    g = initial.get("g")
    if isinstance(g, dict) or (isinstance(g, list) and len(g) == body.n and family.count > 1
                               and all(isinstance(r, list) and r and not isinstance(r[0], list)
                                       for r in g)):
        out["g"] = [g] * family.count
    for key in ("xi", "mu"):
        v = initial.get(key)
        if isinstance(v, list) and len(v) == body.d and family.count > 1 \
                and not any(isinstance(e, (list, dict)) for e in v):
            out[key] = v * family.count
    return out
