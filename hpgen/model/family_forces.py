"""The per-body form of ``forces:`` in a family model (group G^N): written once for body i,

    forces: {for: i, body: [f_0, ..., f_(d-1)]}

with d the body group's dimension; f_k is body i's force component k (left-trivialized,
body frame, in the order of xi[i]) in body i's names (xi[i], g[i], R[i], x[i], w[i], v[i]),
the index i as a number, t, the control inputs and the parameters (runtime ones as
symbols; a runtime per-body list ``c[i]`` as body data, hpgen.model.bodyterms). Body i's components are the force's entries i d .. (i + 1) d - 1, so the file does
not grow with N.

Conventions: a BodyForce holds ``exprs`` (d sympy scalars in the symbols of ONE body of the
family, as hpgen.model.bodyterms.BodyTerm: ``xi_k``, ``g_a_b``, ``index``, plus t, the inputs'
and the runtime parameters' symbols) and ``index`` (the symbol standing for i); the expanded
forces (Model.forces) are ``exprs`` with body i's symbols and index = i.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass

import sympy as sp

from ..errors import ModelError
from .names import check_identifier
from .yamldoc import Doc, describe, is_number

_BODY_NAMES = ("xi", "g", "R", "x", "w", "v", "mu", "t", "pi")


@dataclass(frozen=True)
class BodyForce:
    exprs: tuple                   # d sympy scalars of one body (module docstring)
    index: object                  # sympy Symbol of the loop variable
    #: the body data its entries use (hpgen.model.bodyterms.LocalTerms.data's form)
    data: tuple = ()
    #: the forces between bodies (hpgen.model.joint_forces.JointForce), written per joint
    joints: tuple = ()


def _local_symbol(sym, xi_syms, g_syms, k: int, nb: int, db: int):
    """Body k's product symbol for a one-body symbol (xi_a, g_a_b), else None."""
    name = str(sym)
    if name.startswith("xi_"):
        return xi_syms[k * db + int(name[3:])]
    if name.startswith("g_"):
        a, b = map(int, name[2:].split("_"))
        return g_syms[k * nb + a][k * nb + b]
    return None


def scalar_force(doc: Doc, where: str, value):
    """A force component from the whitelist walker's value (a SymPy expression, or a Python
    number for a constant force) as a SymPy expression; an array is refused at ``where``."""
    if hasattr(value, "shape"):
        raise doc.error(where, f"expected a scalar, got shape {value.shape}")
    return (value if isinstance(value, sp.Basic) else
            sp.Integer(value) if isinstance(value, int) else sp.Float(value))


def parse_family_forces(doc: Doc, raw: dict, group, params: dict, inputs, xi_syms, g_syms):
    """(expanded force exprs, their texts, BodyForce) of a ``forces: {for, body}`` mapping."""
    from .bodyterms import _Local, _NotLocal, sorted_data
    from .symbols import TIME_SYMBOL, input_symbol
    from .syntax import parse_checked
    from .families import family_of
    family = family_of(group)
    if family is None:
        raise doc.error(("forces",), "the per-body form {for: i, body: [...]} needs a family "
                                     "group (G^N); give a list of one expression per algebra "
                                     "coordinate")
    if "for" not in raw or not set(raw) - {"for"} or set(raw) - {"for", "body", "joint"}:
        raise doc.error(("forces",), "expected the keys for (the body index's name), body "
                                     "(one expression per coordinate) and/or joint (forces "
                                     f"between bodies), got {sorted(map(str, raw))}")
    var = raw["for"]
    check_identifier(doc, ("forces", "for"), var, "body index name")
    if var in params or var in inputs or var in _BODY_NAMES:
        raise doc.error(("forces", "for"), f"the body index {var!r} shadows a parameter, an "
                                           "input or a group name; choose a new name")
    from ..groups import group_from_spec
    body = group_from_spec(family.body)
    nb, db, N = body.n, body.d, family.count
    entries = raw.get("body", [0] * db)
    if not isinstance(entries, list) or len(entries) != db:
        raise doc.error(("forces", "body"), f"expected a list of {db} expressions (body i's "
                                            f"force, one per coordinate of {family.body}), got "
                                            f"{describe(entries)}")
    extra = {"t": TIME_SYMBOL, **{u: input_symbol(u) for u in inputs}}
    joints = ()
    if "joint" in raw:
        from .joint_forces import parse_joint_forces
        joints = parse_joint_forces(doc, raw["joint"], var, family, params, extra)
    exprs, index, data = [], None, {}
    for j, text in enumerate(entries):
        path = ("forces", "body", j)
        if is_number(text):
            text = repr(float(text)) if not isinstance(text, int) else str(text)
        if not isinstance(text, str) or not text.strip():
            raise doc.error(path, "expected an expression in body i's names, t, parameters "
                                  f"and inputs (or a number), got {describe(text)}")
        ev = _Local(family.body, 1, params, var, ("xi",), extra=extra, count=N)
        try:
            value = ev.walk(parse_checked(text).body)
        except _NotLocal:
            value = None
        except ModelError as e:
            raise doc.error(path, e.message) from None
        if value is None or not all(isinstance(n, ast.Name) and n.id == var
                                    for _, n in ev.slots.values()):
            raise doc.error(path, f"body {var}'s force may use only body {var}'s names "
                                  f"({var} itself as the index: xi[{var}], R[{var}], ...) and "
                                  "shared parameters")
        exprs.append(scalar_force(doc, path, value))
        index = ev.index
        data.update(ev.data)
    out = []
    for k in range(N):
        for e in exprs:
            sub = {s: _local_symbol(s, xi_syms, g_syms, k, nb, db) for s in e.free_symbols}
            sub = {s: v for s, v in sub.items() if v is not None}
            sub[index] = sp.Integer(k)
            sub.update({s: vals[k] for s, vals in data.items()})
            out.append(e.xreplace(sub))
    if joints:
        from .joint_forces import expand_joint_forces
        expand_joint_forces(joints, out, xi_syms, g_syms, nb, db)
    texts = tuple(f"{t} ({var} = {k})" for k in range(N) for t in map(str, entries))
    return tuple(out), texts, BodyForce(tuple(exprs), index, sorted_data(data), joints)
