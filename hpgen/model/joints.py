"""Entries of ``constraints:`` that are mappings: constraint families and joint shorthands.

An entry of the ``constraints:`` list is either an expression (hpgen.model.constraints) or a
mapping with exactly one of the keys

    row:  "text"                 an expression, as a plain entry
    ball: [A, B], at: [a, b]     a ball joint: point a of body A (in A's frame) coincides with
                                 point b of body B; the row block is x_B + R_B b - x_A - R_A a
    hinge: [A, B], at: [a, b], axis: z
                                 a ball joint whose relative rotation M = R_A^T R_B turns about
                                 the body axis (x, y or z) that A's and B's frames share: the
                                 ball's rows and the alignment rows M[j, k] (j != k, k the axis)
    fixed: [A, B], at: [a, b]    a ball joint and no relative rotation: the rows
                                 M[2, 1] - M[1, 2], M[0, 2] - M[2, 0], M[1, 0] - M[0, 1]
    pin:  A, at: a (, to: p)     point a of body A is pinned at the world point p (default the
                                 origin); the row block is x_A + R_A a - p

and optionally ``for: i, in: [start, stop]`` (a new name i; integer bounds as in
``sum(i, start, stop, term)``: literals, integer parameters and + - * of them, the range
start..stop-1), which repeats the entry for every i of the range: one row block per i, with i
an integer in the texts. Body indices A, B are integers or integer expressions of i and the
integer parameters; the points a, b, p are vector expressions (parameter names, ``i*c``, ...).
The shorthands expand to the text of the row block written out (``x[B] + R[B] @ (b) -
x[A] - R[A] @ (a)`` in a family model ``G^N``, ``x_B`` ... in a product, ``x``, ``R`` on a single
group), parsed by the same whitelist parser as every expression: nothing is evaluated as
Python. Errors name ``constraints[k]`` and, in a family, the value of i.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import ModelError
from .yamldoc import describe, is_number

KINDS = ("row", "ball", "hinge", "fixed", "pin")
KEYS = KINDS + ("at", "to", "axis", "for", "in")
AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class RowBlock:
    """One expanded row block: ``text`` the expression, ``bound`` {loop variable: value}
    ({} outside a family), ``label`` how messages name it (``constraints[k]`` or
    ``constraints[k] (i = 3)``)."""
    text: str
    bound: dict
    label: str
    generated: bool = False         #: text written by a shorthand (its columns mean nothing)


def expand_entry(doc, k: int, entry, group, params: dict) -> list:
    """The RowBlocks of the mapping entry ``constraints[k]`` (module docstring)."""
    path, field = ("constraints", k), f"constraints[{k}]"
    unknown = sorted(set(map(str, entry)) - set(KEYS))
    if unknown:
        raise doc.error(path, f"unknown key {unknown[0]!r}; expected one of {', '.join(KEYS)}")
    kinds = [c for c in KINDS if c in entry]
    if len(kinds) != 1:
        raise doc.error(path, "expected exactly one of row: (an expression), ball: [A, B] "
                        "with at: [a, b], or pin: A with at: a")
    kind = kinds[0]
    if ("for" in entry) != ("in" in entry):
        raise doc.error(path, "for: and in: go together: for: i, in: [start, stop]")
    variable, indices = None, [None]
    if "for" in entry:
        variable = entry["for"]
        if not isinstance(variable, str) or not variable.isidentifier() \
                or variable in params or variable in ("x", "R", "g", "xi", "mu", "w", "v", "t", "pi"):
            raise doc.error(path + ("for",), "expected a new name for the loop variable (not a "
                            f"parameter or a name of the model), e.g. i; got {describe(variable)}")
        rng = entry["in"]
        if not isinstance(rng, list) or len(rng) != 2:
            raise doc.error(path + ("in",), "expected [start, stop] (the range start..stop-1, "
                            f"as in sum(i, start, stop, term)), got {describe(rng)}")
        start, stop = (_integer(doc, path + ("in",), b, group, params) for b in rng)
        if stop - start > 10_000:
            raise doc.error(path + ("in",), f"{stop - start} joints (limit 10000)")
        indices = list(range(start, stop))
    texts = [(_text(doc, path, "ball" if kind in ("hinge", "fixed") else kind, entry, group),
              "")]
    if kind in ("hinge", "fixed"):
        texts += _alignment(doc, path, kind, entry, group)
    elif "axis" in entry:
        raise doc.error(path + ("axis",), "axis: belongs to hinge:")
    out = []
    for i in indices:
        bound = {} if variable is None else {variable: i}
        for text, part in texts:
            out.append(RowBlock(text, bound, field + (f" ({variable} = {i})" if bound else "")
                                + part, kind != "row"))
    return out


def _alignment(doc, path, kind: str, entry: dict, group) -> list:
    """The rotation rows of a hinge (about a shared body axis) or a fixed joint."""
    A, B = (str(b) for b in entry[kind])
    M = f"(transpose({_alias(group, 'R', A)}) @ {_alias(group, 'R', B)})"
    if kind == "fixed":
        if "axis" in entry:
            raise doc.error(path + ("axis",), "axis: belongs to hinge:, not fixed:")
        return [(f"{M}[2, 1] - {M}[1, 2]", " rotation"), (f"{M}[0, 2] - {M}[2, 0]", " rotation"),
                (f"{M}[1, 0] - {M}[0, 1]", " rotation")]
    axis = entry.get("axis")
    if axis not in AXES:
        raise doc.error(path + ("axis",), "expected the hinge's axis, shared by both bodies' "
                        f"frames: x, y or z; got {describe(axis)}")
    k = AXES[axis]
    return [(f"{M}[{j}, {k}]", f" axis row {n}") for n, j in enumerate(j for j in range(3)
                                                                   if j != k)]


def _integer(doc, path, value, group, params) -> int:
    """A range bound: an int, or an integer expression of the integer parameters."""
    if type(value) is int:
        return value
    if not isinstance(value, str):
        raise doc.error(path, f"expected an integer or an integer expression of the integer "
                        f"parameters (e.g. N or N - 1), got {describe(value)}")
    from .evaluator import _Evaluator
    from .syntax import parse_checked
    try:
        return _Evaluator(group, params, variables=()).index_value(parse_checked(value).body)
    except ModelError as e:
        raise doc.error(path, f"the bound {value!r}: {e.message}") from None


def _part(doc, path, value, what: str) -> str:
    if type(value) is int or (isinstance(value, str) and value.strip()):
        return str(value)
    raise doc.error(path, f"expected {what}, got {describe(value)}")


def _alias(group, name: str, body: str) -> str:
    """The text of body ``body``'s ``name`` (x or R) on ``group``."""
    from .families import family_of
    if family_of(group) is not None:
        return f"{name}[({body})]"
    if len(group.factors) > 1:
        if not body.isdigit():
            raise ModelError(f"a body index of a product group is an integer literal, got "
                             f"{body!r} (indexed bodies need a family, group: G^N)")
        return f"{name}_{body}"
    if body != "0":
        raise ModelError(f"a single group has one body, 0; got {body!r}")
    return name


def _text(doc, path, kind: str, entry: dict, group) -> str:
    if kind == "row":
        text = entry["row"]
        if is_number(text) or not isinstance(text, str) or not text.strip():
            raise doc.error(path + ("row",), "expected an expression in g (R, x, ...) and "
                            f"parameters that vanishes, got {describe(text)}")
        for key in ("at", "to"):
            if key in entry:
                raise doc.error(path + (key,), f"{key}: belongs to ball: and pin:, not row:")
        return text
    if "at" not in entry:
        raise doc.error(path, f"{kind}: needs at: (the joint point in the body frame"
                        + (" of each body, [a, b])" if kind == "ball" else ")"))
    at = entry["at"]
    try:
        if kind == "ball":
            if "to" in entry:
                raise doc.error(path + ("to",), "to: belongs to pin:, not ball:")
            key = next(c for c in ("ball", "hinge", "fixed") if c in entry)
            bodies = entry[key]
            if not isinstance(bodies, list) or len(bodies) != 2:
                raise doc.error(path + (key,), "expected the two bodies [A, B], got "
                                f"{describe(bodies)}")
            if not isinstance(at, list) or len(at) != 2:
                raise doc.error(path + ("at",), "expected the joint point in each body's "
                                f"frame, [a, b], got {describe(at)}")
            A, B = (_part(doc, path + (key,), b, "a body index") for b in bodies)
            a, b = (_part(doc, path + ("at",), p, "a vector expression, e.g. a parameter name")
                    for p in at)
            return (f"{_alias(group, 'x', B)} + {_alias(group, 'R', B)} @ ({b}) - "
                    f"{_alias(group, 'x', A)} - {_alias(group, 'R', A)} @ ({a})")
        A = _part(doc, path + ("pin",), entry["pin"], "a body index")
        a = _part(doc, path + ("at",), at, "a vector expression, e.g. a parameter name")
        to = f" - ({_part(doc, path + ('to',), entry['to'], 'a vector expression')})" \
            if "to" in entry else ""
        return f"{_alias(group, 'x', A)} + {_alias(group, 'R', A)} @ ({a}){to}"
    except ModelError as e:
        if e.file:
            raise
        raise doc.error(path + (kind,), e.message) from None
