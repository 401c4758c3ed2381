"""A family model's Lagrangian sums and joint row blocks, each evaluated once for a generic
body (or joint) with its index as a symbol, so that the compiler can derive them once.

Conventions:
- A BodyTerm is ``sign * term`` of one top-level ``sum(i, start, stop, term)`` of the
  Lagrangian (hpgen.model.families.FamilySum) evaluated on ONE body of the family's group:
  its free symbols are that body's ``xi_k`` (k < d of the body group), ``g_a_b`` (a, b < n of
  the body group) and ``index`` (the sum variable, a real symbol standing for the body's
  number i). Body i's term in the expanded Lagrangian is ``expr`` with the symbols of body i
  and index = i. A term is local when every body-indexed name in it (xi g R x w v) is indexed
  by the sum variable itself; a parameter indexed by it is a scalar (shared) or a runtime
  parameter with one entry per body (``m[i]``, ``J[i]`` with ``m``, ``J`` in
  ``runtime_parameters``), body data: body i's entry is the symbol ``body:m`` (``body:J[0]``
  ... for a vector entry) in ``expr``. A fixed per-body list makes the model expanded.
- ``LocalTerms.data`` lists the body data: ((symbol, (body 0's value, ..., body N-1's)), ...)
  sorted by the symbol's name, each value a runtime parameter's symbol (hpgen.model.symbols.
  runtime_symbol); the compiler passes body i's values next to its index.
- A JointTerm is one constraint row block (hpgen.model.constraints.ConstraintSpec) evaluated
  on K local bodies ("slots", K <= MAX_SLOTS, one per distinct body-index expression in the
  text, in order of first use): ``rows`` in the symbols ``g_a_b`` of the K-body product group
  (slot s is factor s) and ``index`` (the loop variable of a ``for:`` entry, or None).
  ``bodies`` are the family's bodies that fill the slots for this row block, ``value`` the
  loop variable's value (0 without one). Row blocks with the same ``text`` share their rows
  (the compiler derives one function per text).
- A JointPotential is a sum whose term involves K <= MAX_SLOTS bodies (slots in order of
  first use, as a JointTerm's) through their configurations only (no xi, w, v of any body, no
  t, no body data): ``expr`` is ``sign * term`` (its part of l: -V for a potential energy V)
  in the K-slot product's ``g_a_b`` and ``index``; ``instances`` ((i, (body in slot 0, ...)),
  ...) over the sum's range. The compiler derives it once and enters it as the conservative
  joint force f_s = d/deta l_j(.., g_s (I + eta^), ..) at eta = 0 (hpgen.derive.
  family_potentials).
- ``local_terms`` returns None when some part is not local (a term coupling two bodies'
  velocities, a per-body parameter list, a non-sum Lagrangian term): the model is then
  compiled expanded.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass

import sympy as sp

from ..errors import ModelError
import numpy as np

from .bodies import BodyIndexed, body_parameter
from .evaluator import _Evaluator
from .families import BodyFamily, FamilyGroup
from .syntax import fail, parse_checked

#: the most bodies one joint row block may involve for it to be derived once
MAX_SLOTS = 4


@dataclass(frozen=True)
class BodyTerm:
    expr: object                   # sympy scalar (module docstring)
    index: object                  # sympy Symbol of the sum variable
    start: int
    stop: int


@dataclass(frozen=True)
class JointTerm:
    text: str
    rows: tuple                    # sympy scalars in the K-slot product's g_a_b and index
    index: object                  # sympy Symbol of the loop variable, or None
    bodies: tuple                  # the family's bodies in slot order
    value: int                     # the loop variable's value for this row block


@dataclass(frozen=True)
class JointPotential:
    expr: object                   # sympy scalar in the K-slot g_a_b and index
    index: object                  # sympy Symbol of the sum variable
    instances: tuple               # ((i, (body, ...)), ...)


@dataclass(frozen=True)
class LocalTerms:
    bodies: tuple                  # BodyTerm per Lagrangian sum, file order
    joints: tuple                  # JointTerm per ConstraintSpec, file order
    slots: int                     # the largest K over the joints (1 without joints)
    #: the per-body force (hpgen.model.family_forces.BodyForce) of a ``forces: {for, body}``
    force: object = None
    #: the body data (module docstring): ((symbol, per-body values), ...), sorted by name
    data: tuple = ()
    #: the JointPotential of each sum coupling a few bodies' configurations, file order
    potentials: tuple = ()


class _NotLocal(Exception):
    pass


class _Local(_Evaluator):
    """The whitelist evaluator on a K-body family, with the index ``var`` symbolic and every
    body index expression mapped to a slot (its first use)."""

    def __init__(self, body: str, slots: int, params: dict, var, variables, forbidden=None,
                 extra=None, count: int | None = None):
        group = FamilyGroup(BodyFamily(body=body, count=slots))
        super().__init__(group, params, variables=variables, forbidden=forbidden, extra=extra)
        self.var = var
        self.index = sp.Symbol(var, real=True) if var else None
        self.slots: dict = {}      # ast.dump(index node) -> (slot, node)
        #: the family's N when runtime per-body lists may be body data (else None)
        self.count = count
        self.data: dict = {}       # body data symbol -> per-body values

    def lookup(self, node):
        if self.var is not None and node.id == self.var and node.id not in self.bound:
            return self.index
        return super().lookup(node)

    def _uses(self, node, names) -> bool:
        return any(isinstance(n, ast.Name) and n.id in names for n in ast.walk(node))

    def subscript(self, node):
        base, sl = node.value, node.slice
        idx = sl.elts if isinstance(sl, ast.Tuple) else [sl]
        if isinstance(base, ast.Name) and isinstance(self.names.get(base.id), BodyIndexed):
            if len(idx) != 1 or self._uses(idx[0], self.bound):
                raise _NotLocal            # an index over a nested sum's variable
            key = ast.dump(idx[0])
            if key not in self.slots:
                if len(self.slots) >= len(self.names[base.id].values):
                    raise _NotLocal
                self.slots[key] = (len(self.slots), idx[0])
            return self.names[base.id].values[self.slots[key][0]]
        if isinstance(base, ast.Name) and base.id in self.params and self.var is not None \
                and any(self._uses(n, (self.var,)) for n in idx):
            value = self.lookup(base)
            if hasattr(value, "shape"):    # one entry per body
                return self._body_data(node, base.id, value, idx)
            if len(idx) != 1:
                raise _NotLocal            # refused by the full evaluator
            return value
        return super().subscript(node)

    def _body_data(self, node, name: str, value, idx):
        """``p[i]`` (``p[i, k]``, ...) of a runtime per-body list: body i's entry as body data
        symbols (module docstring); any other per-body list is not local."""
        runtime = all(isinstance(e, sp.Symbol) and e.name.startswith("param:")
                      for e in value.flat)
        if self.count is None or not runtime or not (
                isinstance(idx[0], ast.Name) and idx[0].id == self.var) \
                or any(self._uses(n, (self.var,)) for n in idx[1:]):
            raise _NotLocal
        body_parameter(node, name, value, (0,), self.count)   # one entry per body
        rest = tuple(self.index_value(n) for n in idx[1:])
        shape = value.shape[1:]
        if len(rest) > len(shape) or not all(0 <= r < s for r, s in zip(rest, shape)):
            raise fail(node, f"index {[self.var, *rest]} out of range for the parameter {name} "
                             f"(shape {' x '.join(map(str, value.shape))})")
        syms = np.empty(shape, dtype=object)
        for e in np.ndindex(shape):
            s = sp.Symbol("body:" + name + "".join(f"[{a}]" for a in e), real=True)
            syms[e] = s
            self.data[s] = tuple(value[(k,) + e] for k in range(self.count))
        out = syms[rest] if rest else syms
        return out[()] if isinstance(out, np.ndarray) and not out.shape else out

    def bodies_at(self, value: int) -> tuple:
        """The family's bodies of the slots when the index has ``value``."""
        self.bound = {self.var: value} if self.var else {}
        try:
            return tuple(self.index_value(n) for _, n in sorted(self.slots.values(),
                                                                   key=lambda s: s[0]))
        finally:
            self.bound = {}


def _body_term(family: BodyFamily, fsum, params: dict, data: dict, work=None) -> BodyTerm:
    """The BodyTerm of the sum ``fsum`` (body data into ``data``; the evaluator's work
    appended to the list ``work`` when given)."""
    from .symbols import TIME_SYMBOL
    ev = _Local(family.body, 1, params, fsum.variable, ("xi",), extra={"t": TIME_SYMBOL},
                count=family.count)
    value = ev.walk(parse_checked(fsum.term).body)
    if hasattr(value, "shape") or not all(isinstance(node, ast.Name) and node.id == fsum.variable
                                          for _, node in ev.slots.values()):
        raise _NotLocal
    data.update(ev.data)
    if work is not None:
        work.append(ev.work)
    return BodyTerm(fsum.sign * value, ev.index, fsum.start, fsum.stop)


def _potential(family: BodyFamily, fsum, params: dict, work=None) -> JointPotential:
    """The JointPotential of the sum ``fsum`` (module docstring), else _NotLocal (the
    evaluator's work appended to the list ``work`` when given)."""
    ev = _Local(family.body, MAX_SLOTS, params, fsum.variable, ("xi",), count=family.count)
    value = ev.walk(parse_checked(fsum.term).body)
    if hasattr(value, "shape") or ev.data or not ev.slots:
        raise _NotLocal
    value = value if isinstance(value, sp.Basic) else sp.Float(float(value))
    if any(str(s).startswith("xi_") for s in value.free_symbols):
        raise _NotLocal
    if work is not None:
        work.append(ev.work)
    K = len(ev.slots)
    expr = fsum.sign * value
    instances = []
    for i in range(fsum.start, fsum.stop):
        bodies = ev.bodies_at(i)
        if len(set(bodies)) != K or not all(0 <= b < family.count for b in bodies):
            raise _NotLocal
        instances.append((i, bodies))
    return JointPotential(expr, ev.index, tuple(instances))


def sorted_data(data: dict) -> tuple:
    """LocalTerms.data of {body data symbol: per-body values}."""
    return tuple(sorted(data.items(), key=lambda kv: kv[0].name))


def _joint_terms(family: BodyFamily, constraints, params: dict) -> tuple:
    from .expr import _XI_NAME
    forbidden = (_XI_NAME, "xi in a constraint")
    cache: dict = {}
    out = []
    for c in constraints:
        bound = dict(getattr(c, "bound", ()))
        if len(bound) > 1:
            raise _NotLocal
        var = next(iter(bound), None)
        key = (c.text, var)
        if key not in cache:
            ev = _Local(family.body, MAX_SLOTS, params, var, (), forbidden)
            value = ev.walk(parse_checked(c.text).body)
            rows = tuple(value.tolist()) if hasattr(value, "shape") else (value,)
            if len(rows) != len(c.rows) or not ev.slots:
                raise _NotLocal
            cache[key] = (ev, rows)
        ev, rows = cache[key]
        value = bound.get(var, 0)
        bodies = ev.bodies_at(value)
        if len(set(bodies)) != len(bodies) or not all(0 <= b < family.count for b in bodies):
            raise _NotLocal
        out.append(JointTerm(c.text, rows, ev.index, bodies, value))
    return tuple(out)


def local_terms(family: BodyFamily | None, constraints, params: dict) -> LocalTerms | None:
    """The family's LocalTerms (module docstring), None when the model is not local or not a
    family. ``params``: the parameters as the Lagrangian's evaluator takes them."""
    if family is None or family.rest is not None or not family.sums:
        return None
    data: dict = {}
    bodies, potentials = [], []
    try:
        for s in family.sums:
            try:
                bodies.append(_body_term(family, s, params, data))
            except _NotLocal:
                potentials.append(_potential(family, s, params))
        joints = _joint_terms(family, constraints, params)
    except (_NotLocal, ModelError):
        return None
    if not bodies:
        return None
    slots = [len(j.bodies) for j in joints] + [len(p.instances[0][1]) for p in potentials
                                               if p.instances]
    return LocalTerms(tuple(bodies), joints, max(slots, default=1), data=sorted_data(data),
                      potentials=tuple(potentials))
