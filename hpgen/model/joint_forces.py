"""The joint form of a family model's forces: a force between a few neighbouring bodies (a
damper or a torsional spring in a joint) written once for every joint,

    forces:
      for: i
      body: [...]                          # optional: body i's own force (family_forces)
      joint:                               # one mapping or a list of them
        in: [1, N]                         # the joints: i = 1 .. N-1
        bodies: [i - 1, i]                 # the bodies the force acts on (at most MAX_SLOTS)
        force: [[f on body i - 1 (d)], [f on body i (d)]]

Each list in ``force`` is the force on the body at the same place in ``bodies``, in that
body's frame (left-trivialized, in the order of its xi[...]), written in the names of the
listed bodies (``w[i]``, ``R[i - 1]``, ...), i, t, the inputs and the parameters. A pair of
equal and opposite couples (``f`` on one body, ``-Ad*`` of it on the other) is internal: it
leaves the total momentum unchanged.

Conventions: a JointForce holds ``exprs`` (K tuples of d sympy scalars, K = len(bodies), in
the symbols of the K-body product group: ``xi_m`` (m < K d, slot m // d), ``g_a_b`` (a, b <
K n), ``index`` for i, t, the inputs' and runtime parameters' symbols) and ``instances``:
((i, (body in slot 0, ...)), ...) over the range.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass

import sympy as sp

from ..errors import ModelError
from .yamldoc import Doc, describe, is_number

KEYS = ("in", "bodies", "force")


@dataclass(frozen=True)
class JointForce:
    exprs: tuple                   # K tuples of d sympy scalars (module docstring)
    index: object                  # sympy Symbol of the loop variable
    instances: tuple               # ((i, (body, ...)), ...)


def _slot_symbol(sym, bodies, xi_syms, g_syms, nb: int, db: int):
    """The product group's symbol of a K-slot symbol (xi_m, g_a_b) for the slots' bodies."""
    name = str(sym)
    if name.startswith("xi_"):
        m = int(name[3:])
        return xi_syms[bodies[m // db] * db + m % db]
    if name.startswith("g_"):
        a, b = map(int, name[2:].split("_"))
        off = bodies[a // nb] * nb
        return g_syms[off + a % nb][off + b % nb]
    return None


def parse_joint_forces(doc: Doc, raw, var: str, family, params: dict, extra: dict) -> tuple:
    """The JointForce of each mapping of ``forces.joint`` (one mapping or a list)."""
    entries, listed = (raw, True) if isinstance(raw, list) else ([raw], False)
    return tuple(_joint_force(doc, ("forces", "joint", k) if listed else ("forces", "joint"),
                              e, var, family, params, extra) for k, e in enumerate(entries))


def _joint_force(doc: Doc, path, entry, var: str, family, params: dict, extra: dict):
    from ..groups import group_from_spec
    from .bodyterms import MAX_SLOTS, _Local, _NotLocal
    from .family_forces import scalar_force
    from .joints import _integer
    from .families import FamilyGroup
    from .syntax import parse_checked
    if not isinstance(entry, dict) or set(map(str, entry)) != set(KEYS):
        raise doc.error(path, "expected a mapping {in: [start, stop], bodies: [A, B], force: "
                              f"[[d expressions], [d expressions]]}}, got {describe(entry)}")
    rng, bodies, force = entry["in"], entry["bodies"], entry["force"]
    if not isinstance(rng, list) or len(rng) != 2:
        raise doc.error(path + ("in",), "expected [start, stop] (the joints i = start .. "
                                        f"stop-1), got {describe(rng)}")
    group = FamilyGroup(family)
    start, stop = (_integer(doc, path + ("in",), b, group, params) for b in rng)
    if not isinstance(bodies, list) or not 1 <= len(bodies) <= MAX_SLOTS \
            or not all(type(b) is int or (isinstance(b, str) and b.strip()) for b in bodies):
        raise doc.error(path + ("bodies",), f"expected a list of 1 to {MAX_SLOTS} body indices "
                                            f"(integers or expressions of {var}), got "
                                            f"{describe(bodies)}")
    K = len(bodies)
    body = group_from_spec(family.body)
    if not isinstance(force, list) or len(force) != K or not all(
            isinstance(f, list) and len(f) == body.d for f in force):
        raise doc.error(path + ("force",), f"expected {K} lists of {body.d} expressions (the "
                                           "force on each listed body, in its frame), got "
                                           f"{describe(force)}")
    ev = _Local(family.body, K, params, var, ("xi",), extra=extra)
    for s, b in enumerate(bodies):
        try:
            node = parse_checked(str(b)).body
        except ModelError as e:
            raise doc.error(path + ("bodies", s), e.message) from None
        ev.slots[ast.dump(node)] = (s, node)
    if len(ev.slots) != K:
        raise doc.error(path + ("bodies",), "the bodies must be distinct expressions")
    exprs = []
    for s, fs in enumerate(force):
        row = []
        for c, text in enumerate(fs):
            where = path + ("force", s, c)
            if is_number(text):
                text = repr(float(text)) if not isinstance(text, int) else str(text)
            if not isinstance(text, str) or not text.strip():
                raise doc.error(where, "expected an expression in the listed bodies' names, t, "
                                       f"parameters and inputs (or a number), got {describe(text)}")
            try:
                value = ev.walk(parse_checked(text).body)
            except _NotLocal:
                value = None
            except ModelError as e:
                raise doc.error(where, e.message) from None
            if value is None or len(ev.slots) != K:
                raise doc.error(where, "a joint force may use only the names of the bodies "
                                       f"listed in bodies ({', '.join(map(str, bodies))}), "
                                       "indexed as written there")
            row.append(scalar_force(doc, where, value))
        exprs.append(tuple(row))
    instances = []
    for i in range(start, stop):
        try:
            at = ev.bodies_at(i)
        except ModelError as e:
            raise doc.error(path + ("bodies",), f"({var} = {i}): {e.message}") from None
        bad = [b for b in at if not 0 <= b < family.count]
        if bad or len(set(at)) != K:
            what = (f"body index {bad[0]} out of range (0..{family.count - 1})" if bad
                    else "the bodies coincide")
            raise doc.error(path + ("bodies",), f"({var} = {i}): {what}")
        instances.append((i, at))
    return JointForce(tuple(exprs), ev.index, tuple(instances))


def expand_joint_forces(joint_forces, out: list, xi_syms, g_syms, nb: int, db: int) -> None:
    """Add every instance of ``joint_forces`` to the product's force ``out`` (N d sympy
    scalars, body k's at k d .. (k + 1) d - 1), in place."""
    for jf in joint_forces:
        syms = {s for row in jf.exprs for e in row for s in e.free_symbols}
        for i, bodies in jf.instances:
            sub = {s: _slot_symbol(s, bodies, xi_syms, g_syms, nb, db) for s in syms}
            sub = {s: v for s, v in sub.items() if v is not None}
            sub[jf.index] = sp.Integer(i)
            for slot, row in enumerate(jf.exprs):
                for c, e in enumerate(row):
                    k = bodies[slot] * db + c
                    out[k] = out[k] + e.xreplace(sub)
