"""The keys of an open model: ``runtime_parameters``, ``inputs`` and ``forces``, and the
scene refusals that depend on them (work and power need forces; a section may not use a
runtime parameter). Errors are hpgen.errors.ModelError naming file, line and field."""
from __future__ import annotations

import keyword
import re

import numpy as np

from ..errors import ModelError
from .names import check_identifier
from .types import RESERVED_NAMES
from .yamldoc import Doc, describe, is_number

_FACTOR_NAME = re.compile(r"(xi|g|R|x)_[0-9]+")


def _name_list(doc: Doc, key: str, raw, what: str) -> list:
    """A YAML list of distinct identifiers (``runtime_parameters``, ``inputs``)."""
    if not isinstance(raw, list):
        raise doc.error((key,), f"expected a list of {what} names, e.g. [{'c' if key != 'inputs' else 'u0'}], "
                                f"got {describe(raw)}")
    seen = set()
    for i, name in enumerate(raw):
        check_identifier(doc, (key, i), name, f"{what} name")
        if name in seen:
            raise doc.error((key, i), f"{name!r} is listed twice")
        seen.add(name)
    return list(raw)


def _refuse_unforced_work(doc: Doc, scene, forces) -> None:
    """``power`` / ``work`` in the scene's record list need a force that is not identically
    zero (hpgen.model.scene.FORCED_RECORDABLE); with one, they are not expression labels."""
    from .scene import FORCED_RECORDABLE
    forced = any(f.is_zero is not True for f in forces)
    labels = {e.label for e in scene.expressions}
    for i, name in enumerate(scene.record):
        if name not in FORCED_RECORDABLE:
            continue
        if forced and name in labels:
            raise doc.error(("scene", "record", i, name), f"the label {name!r} is a built-in "
                            "record name of a forced model; choose another label")
        if not forced and name not in labels:
            raise doc.error(("scene", "record", i), f"{name!r} is the {name} of the forces, "
                            "and this model has none (add forces: to the model)")


def _runtime_parameters(doc: Doc, raw, stored, exact) -> tuple:
    """((name, shape), ...), the flat symbols, their defaults, and ``exact`` with each runtime
    parameter replaced by its symbol(s) (a sympy scalar or an object array of the shape)."""
    from .symbols import runtime_symbol
    if raw is None:
        return (), (), (), exact
    names = _name_list(doc, "runtime_parameters", raw, "runtime parameter")
    values = dict(stored)
    exact = dict(exact)
    spec, syms, defaults = [], [], []
    for i, name in enumerate(names):
        if name not in values:
            avail = ", ".join(values) or "none"
            raise doc.error(("runtime_parameters", i),
                            f"unknown runtime parameter {name!r}: it must be declared in "
                            f"parameters (its value there is the default; declared: {avail})")
        v = np.asarray(values[name], dtype=float)
        entries = [runtime_symbol(name, idx) for idx in np.ndindex(v.shape)]
        spec.append((name, v.shape))
        syms += entries
        defaults += [float(x) for x in v.ravel()]
        if v.shape:
            arr = np.empty(len(entries), dtype=object)
            arr[:] = entries
            exact[name] = arr.reshape(v.shape)
        else:
            exact[name] = entries[0]
    return tuple(spec), tuple(syms), tuple(defaults), exact


def _inputs(doc: Doc, raw, stored) -> tuple:
    if raw is None:
        return ()
    names = _name_list(doc, "inputs", raw, "input")
    params = dict(stored)
    for i, name in enumerate(names):
        if name in params:
            raise doc.error(("inputs", i), f"input name {name!r} is also a parameter; "
                                           "choose another name")
        if name in RESERVED_NAMES or name in ("pi", "mu") or _FACTOR_NAME.fullmatch(name) \
                or keyword.iskeyword(name):
            raise doc.error(("inputs", i), f"input name {name!r} is reserved (reserved: "
                                           f"{', '.join(RESERVED_NAMES)}, pi, mu, xi_k, g_k, "
                                           "R_k, x_k and Python keywords)")
    return tuple(names)


def _forces(doc: Doc, raw, group, exact, inputs) -> tuple:
    """(sympy expressions, texts): one component of f in g* per algebra coordinate."""
    from .expr import parse_force
    from .symbols import TIME_SYMBOL, input_symbol
    d = group.d
    if not isinstance(raw, list):
        raise doc.error(("forces",), f"expected a list of {d} expressions (one per algebra "
                                     f"coordinate, in the order of xi), got {describe(raw)}")
    if len(raw) != d:
        raise doc.error(("forces",), f"expected {d} expressions (one per algebra coordinate of "
                                     f"{group.name}, in the order of xi), got {len(raw)}")
    extra = {"t": TIME_SYMBOL, **{u: input_symbol(u) for u in inputs}}
    exprs, texts = [], []
    for i, text in enumerate(raw):
        field = f"forces[{i}]"
        if is_number(text):
            text = repr(float(text)) if not isinstance(text, int) else str(text)
        if not isinstance(text, str) or not text.strip():
            raise doc.error(("forces", i), "expected an expression in xi, g, t, parameters and "
                                           f"inputs (or a number), got {describe(text)}")
        try:
            expr, _, _ = parse_force(text, group, exact, extra, field)
        except ModelError as e:
            raise e.located(doc.file, field, doc.line(("forces", i))) from None
        exprs.append(expr)
        texts.append(text)
    return tuple(exprs), tuple(texts)


def _refuse_runtime_in_scene(doc: Doc, scene, runtime_syms) -> None:
    """The scene's section and recorded expressions are frozen: no runtime parameter."""
    rs = set(runtime_syms)
    items = [(("scene", "section"), scene.section)] if scene.section is not None else []
    items += [(("scene", "record"), r) for r in scene.expressions]
    for path, item in items:
        used = sorted(str(s).split(":", 1)[1] for s in item.expr.free_symbols & rs)
        if used:
            raise doc.error(path, f"uses the runtime parameter {used[0].split('[')[0]!r}; the "
                                  "scene's section and recorded expressions may use only fixed "
                                  "parameters")
