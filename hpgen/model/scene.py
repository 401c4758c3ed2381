"""The ``scene:`` section: step size, number of steps, initial state, what to record.

Conventions:
- ``h`` != 0 finite (h < 0 runs backwards in time); ``steps`` an integer >= 0, or ``duration``
  > 0 with steps = round(duration/|h|) integral within 1e-9 relative (exactly one of the two).
- ``initial.g``: ``identity`` | an n x n matrix | ``{rotvec: [3]}`` or ``{quat: [w, x, y, z]}``
  (a unit quaternion, scalar first; hpgen.groups.elements) (SO3, SE3) or ``{angle: a}``
  (SO2, SE2), optionally with ``position: [k]`` (SE2, SE3; R<k> takes ``{position: [k]}``).
  For a product: ``identity``, the full block-diagonal matrix, or a list with one such entry per
  factor. Rotations come from Rodrigues' formula. The result must be on the group: every
  rotation block has |R^T R - I|max and |det R - 1| <= 1e-10; the affine bottom row, the identity
  block of R<k> and the off-diagonal blocks of a product are exact.
- Exactly one of ``initial.xi`` / ``initial.mu`` (d finite numbers).
- ``initial.project``: true or false (default); true asks the loader to move the initial state
  onto the model's constraints (hpgen.model.projection) instead of refusing it.
- ``record``: a list of distinct entries (default g, mu): names from RECORDABLE, or one-key
  mappings ``{label: "expression"}`` recording a scalar expression in xi, mu and g
  (hpgen.model.expr.parse_record) under ``label`` ([A-Za-z][A-Za-z0-9_]{0,63}; not a RECORDABLE
  name, not ``t``, not a Python keyword). Scene.record lists names and labels in file order,
  Scene.expressions the RecordExpr of the labels. ``every``: integer >= 1.
- ``u``: the control inputs of a model with ``inputs:`` (a constant, expressions of t or a
  table; hpgen.model.controls), a ControlSpec in Scene.u; refused for a model without inputs.
- ``section``: optional Poincare section s(g, mu), an expression text parsed like the Lagrangian
  with ``mu`` instead of ``xi`` (hpgen.model.expr.parse_section) into a SectionSpec.
"""
from __future__ import annotations

import keyword
import math
import re

import numpy as np

from ..errors import ModelError
from ..groups.elements import (compose, quat_norm_error, rotation_from_angle, rotation_from_quat,
                               rotation_from_rotvec)
from .families import repeat_initial
from .types import RecordExpr, Scene, SectionSpec

SCENE_KEYS = ("h", "steps", "duration", "initial", "record", "every", "section", "u")
INITIAL_KEYS = ("g", "xi", "mu", "project")
RECORDABLE = ("g", "mu", "xi", "energy", "momentum", "defect")
#: record names of a forced model only (the loader refuses them without forces, and refuses
#: them as expression labels with forces): the power <f, xi> at the record and the work done
#: by the forces since the start
FORCED_RECORDABLE = ("power", "work")
ON_GROUP_TOL = 1e-10
MAX_STEPS = 2**31 - 1
LABEL = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}")
RESERVED_LABELS = ("t",)


def _int(doc, path, v, low, what):
    if type(v) is not int:
        raise doc.error(path, f"expected {what}, got {_describe(doc, v)}")
    if v < low or v > MAX_STEPS:
        raise doc.error(path, f"expected {what}, got {v}")
    return v


def _describe(doc, v):
    from .yamldoc import describe
    return describe(v)


def _rotation(doc, path, fgroup, spec):
    """The rotation block (k x k) from {rotvec: [...]} or {angle: a}."""
    k = fgroup.rotation_block[1] - fgroup.rotation_block[0]
    if k == 2:
        if "rotvec" in spec:
            raise doc.error(path + ("rotvec",), f"{fgroup.name} takes angle: a, not rotvec")
        if "angle" not in spec:
            return np.eye(2)
        return rotation_from_angle(doc.number(path + ("angle",), spec["angle"]))
    if "angle" in spec:
        raise doc.error(path + ("angle",), f"{fgroup.name} takes rotvec: [3 numbers], not angle")
    if "quat" in spec:
        if "rotvec" in spec:
            raise doc.error(path + ("quat",), "give either rotvec or quat, not both")
        q = doc.vector(path + ("quat",), spec["quat"], 4)
        if quat_norm_error(q):
            raise doc.error(path + ("quat",), quat_norm_error(q))
        return rotation_from_quat(q)
    if "rotvec" not in spec:
        return np.eye(3)
    return rotation_from_rotvec(doc.vector(path + ("rotvec",), spec["rotvec"], 3))


def _from_mapping(doc, path, fgroup, spec):
    rot = fgroup.rotation_block is not None
    tr = fgroup.translation_block is not None
    allowed = ((("rotvec", "quat") if fgroup.rotation_block[1] - fgroup.rotation_block[0] == 3
                else ("angle",)) if rot else ()) + (("position",) if tr else ())
    if not allowed:
        raise doc.error(path, f"for {fgroup.name} expected identity or a matrix")
    doc.mapping(path, spec, allowed)
    R = _rotation(doc, path, fgroup, spec) if rot else None
    x = None
    if tr and spec.get("position") is not None:
        a, b = fgroup.translation_block
        x = doc.vector(path + ("position",), spec["position"], b - a)
    return compose(fgroup.n, fgroup.rotation_block, fgroup.translation_block, R, x)


def _factor_matrix(doc, path, fgroup, spec):
    """g0 of one (non-product) group from identity / matrix / mapping."""
    if spec == "identity":
        return np.eye(fgroup.n)
    if isinstance(spec, dict):
        return _from_mapping(doc, path, fgroup, spec)
    if isinstance(spec, list):
        return np.array(doc.matrix(path, spec, (fgroup.n, fgroup.n)), dtype=float)
    raise doc.error(path, f"expected identity, a {fgroup.n} x {fgroup.n} matrix or a mapping "
                          f"(rotvec/angle/position) for {fgroup.name}, got {_describe(doc, spec)}")


def _is_full_matrix(spec):
    return isinstance(spec, list) and spec and all(
        isinstance(r, list) and all(not isinstance(x, (list, dict, str)) for x in r) for r in spec)


def _check_on_group(doc, path, fgroup, G, what):
    n = fgroup.n
    if fgroup.translation_block is not None:
        bottom = np.zeros(n)
        bottom[-1] = 1.0
        dev = float(np.max(np.abs(G[-1] - bottom)))
        if dev != 0.0:
            raise doc.error(path, f"{what} is not on {fgroup.name}: the bottom row must be "
                                  f"exactly {bottom.astype(int).tolist()} (deviation {dev:.3g}, "
                                  "tolerance 0)")
    if fgroup.rotation_block is not None:
        a, b = fgroup.rotation_block
        R = G[a:b, a:b]
        with np.errstate(all="ignore"):
            dev = max(float(np.max(np.abs(R.T @ R - np.eye(b - a)))),
                      abs(float(np.linalg.det(R)) - 1.0))
        if not dev <= ON_GROUP_TOL:
            raise doc.error(path, f"{what} is not on {fgroup.name}: the rotation block has "
                                  f"max(|R^T R - I|, |det R - 1|) = {dev:.3g} "
                                  f"(tolerance {ON_GROUP_TOL:g})")
    else:  # R<k>: [[I, x], [0, 1]]
        k = n - 1
        dev = float(np.max(np.abs(G[:k, :k] - np.eye(k)))) if k else 0.0
        if dev != 0.0:
            raise doc.error(path, f"{what} is not on {fgroup.name}: the top-left {k} x {k} "
                                  f"block must be exactly the identity (deviation {dev:.3g}, "
                                  "tolerance 0)")


def initial_g(doc, path, group, spec):
    """g0 as an n x n float array on ``group`` (FactorLayout-aware for products)."""
    from ..groups import group_from_spec
    factors = group.factors
    path = tuple(path)
    if len(factors) == 1:
        if spec is None:
            spec = "identity"
        G = _factor_matrix(doc, path, group, spec)
        if not np.all(np.isfinite(G)):
            raise doc.error(path, "the initial g is not finite")
        _check_on_group(doc, path, group, G, "the initial g")
        return G
    n = group.n
    if spec is None or spec == "identity":
        return np.eye(n)
    fgroups = [group_from_spec(f.name) for f in factors]
    G = np.zeros((n, n))
    if _is_full_matrix(spec):
        G[:] = doc.matrix(path, spec, (n, n))
        mask = np.ones((n, n), dtype=bool)
        for f in factors:
            mask[f.row:f.row + f.n, f.row:f.row + f.n] = False
        dev = float(np.max(np.abs(G[mask]))) if mask.any() else 0.0
        if dev != 0.0:
            raise doc.error(path, f"the initial g is not block diagonal for {group.name}: "
                                  f"off-diagonal entries up to {dev:.3g} (tolerance 0)")
    elif isinstance(spec, list) and len(spec) == len(factors):
        for k, (f, fg) in enumerate(zip(factors, fgroups)):
            G[f.row:f.row + f.n, f.row:f.row + f.n] = _factor_matrix(doc, path + (k,), fg, spec[k])
    else:
        raise doc.error(path, f"for the product {group.name} expected identity, the full "
                              f"{n} x {n} block-diagonal matrix, or a list of {len(factors)} "
                              "entries (one per factor)")
    if not np.all(np.isfinite(G)):
        raise doc.error(path, "the initial g is not finite")
    for k, (f, fg) in enumerate(zip(factors, fgroups)):
        sub = path + (k,) if not _is_full_matrix(spec) else path
        _check_on_group(doc, sub, fg, G[f.row:f.row + f.n, f.row:f.row + f.n],
                        f"factor {k} of the initial g")
    return G


def _steps(doc, raw, h):
    has_steps, has_dur = raw.get("steps") is not None, raw.get("duration") is not None
    if has_steps and has_dur:
        raise doc.error(("scene", "duration"), "give either steps or duration, not both")
    if has_steps:
        return _int(doc, ("scene", "steps"), raw["steps"], 0,
                    f"an integer number of steps from 0 to {MAX_STEPS}")
    if not has_dur:
        raise doc.error(("scene",), "missing steps: expected steps: N (integer >= 0) or "
                                    "duration: T (> 0)")
    path = ("scene", "duration")
    T = doc.number(path, raw["duration"], "a duration > 0")
    if T <= 0:
        raise doc.error(path, f"expected a duration > 0, got {T!r}")
    ratio = T / abs(h)
    if not math.isfinite(ratio) or ratio > MAX_STEPS + 0.5:
        raise doc.error(path, f"duration / h = {ratio:.6g} steps is too many (limit {MAX_STEPS})")
    steps = round(ratio)
    if abs(ratio - steps) > 1e-9 * ratio or steps < 1:
        raise doc.error(path, f"duration / h = {ratio:.12g} is not an integer number of steps "
                              "(within 1e-9 relative); adjust duration or h")
    return int(steps)


def _section(doc, text, group, parameters) -> SectionSpec:
    from .expr import SECTION_FIELD, parse_section
    path = ("scene", "section")
    if type(text) in (int, float):
        raise doc.error(path, f"the section is the constant {text!r} and would never cross zero; "
                              "expected an expression in mu and/or g, e.g. mu[0]")
    if not isinstance(text, str) or not text.strip():
        raise doc.error(path, "expected an expression s(g, mu) in mu and/or g (and parameters), "
                              f"e.g. mu[0] or R[2, 2] - 0.5, got {_describe(doc, text)}")
    try:
        expr, mu_syms, g_syms = parse_section(text, group, parameters)
    except ModelError as e:
        line = doc.line(path)
        if line and getattr(doc, "section_style", None) == "|" and getattr(e, "expr_line", None):
            line += e.expr_line
        raise e.located(doc.file, SECTION_FIELD, line) from None
    return SectionSpec(text=text, expr=expr, mu_symbols=mu_syms, g_symbols=g_syms)


def _record_label(doc, path, label, seen):
    if not isinstance(label, str) or not LABEL.fullmatch(label):
        raise doc.error(path, f"the label {str(label)[:70]!r} is not a valid name: expected a letter "
                              "followed by at most 63 letters, digits or _")
    if label in RECORDABLE:
        raise doc.error(path, f"the label {label!r} is a built-in record name; list it as the "
                              f"plain name {label} or choose another label")
    if label in RESERVED_LABELS:
        raise doc.error(path, f"the label {label!r} is reserved (the sample times); choose "
                              "another label")
    if keyword.iskeyword(label):
        raise doc.error(path, f"the label {label!r} is a Python keyword; choose another label")
    if label in seen:
        raise doc.error(path, f"{label!r} is listed twice")


def _record_expr(doc, path, label, text, group, parameters) -> RecordExpr:
    from .expr import parse_record
    from .yamldoc import fmt_path
    if type(text) in (int, float):
        raise doc.error(path, f"the recorded expression is the constant {text!r}; expected an "
                              "expression in xi, mu and/or g as a string, e.g. xi[0] or R[2, 2]")
    if not isinstance(text, str) or not text.strip():
        raise doc.error(path, "expected an expression in xi, mu and/or g (and parameters), e.g. "
                              f"xi[0], mu[0] or R[2, 2], got {_describe(doc, text)}")
    field = fmt_path(path)
    try:
        expr, xi_syms, mu_syms, g_syms = parse_record(text, group, parameters, field)
    except ModelError as e:
        raise e.located(doc.file, field, doc.line(path)) from None
    return RecordExpr(label=label, text=text, expr=expr, xi_symbols=xi_syms, mu_symbols=mu_syms,
                      g_symbols=g_syms)


def _record(doc, rec, group, parameters):
    """(record names and labels, RecordExpr tuple) from the ``record`` list, in file order."""
    rpath = ("scene", "record")
    if not isinstance(rec, list) or not rec:
        raise doc.error(rpath, f"expected a non-empty list of names from {', '.join(RECORDABLE)} "
                               f"or {{label: expression}} mappings, got {_describe(doc, rec)}")
    names, exprs, seen = [], [], set()
    for i, r in enumerate(rec):
        if isinstance(r, dict):
            if len(r) != 1:
                raise doc.error(rpath + (i,), "expected a mapping with exactly one key, "
                                              f"{{label: expression}}, got {len(r)} keys"
                                              + (f" ({', '.join(list(r)[:5])})" if r else ""))
            (label, text), = r.items()
            _record_label(doc, rpath + (i, label), label, seen)
            exprs.append(_record_expr(doc, rpath + (i, label), label, text, group, parameters))
            r = label
        elif not isinstance(r, str) or r not in RECORDABLE + FORCED_RECORDABLE:
            raise doc.error(rpath + (i,), f"expected one of {', '.join(RECORDABLE)} or a mapping "
                                          f"{{label: expression}}, got {_describe(doc, r)}")
        elif r in seen:
            raise doc.error(rpath + (i,), f"{r!r} is listed twice")
        seen.add(r)
        names.append(r)
    return tuple(names), tuple(exprs)


def parse_scene(doc, raw, group, parameters=None, inputs=()) -> Scene:
    """Validate the scene mapping ``raw`` for ``group``; doc is the loader's located document.
    ``parameters``: the exact parameter values ({name: int | float | lists}) for the section
    and the recorded expressions; ``inputs``: the model's control input names (scene.u)."""
    raw = doc.mapping(("scene",), raw, SCENE_KEYS)
    if raw.get("h") is None:
        raise doc.error(("scene", "h"), "missing h: expected a step size h != 0")
    h = doc.number(("scene", "h"), raw["h"], "a step size h != 0")
    if h == 0:
        raise doc.error(("scene", "h"), "expected a step size h != 0 (h < 0 runs backwards "
                                        "in time), got 0.0")
    steps = _steps(doc, raw, h)
    ipath = ("scene", "initial")
    init = doc.mapping(ipath, raw.get("initial"), INITIAL_KEYS)
    init = repeat_initial(group, init)          # G^N: one body's g, xi or mu for every body
    G = initial_g(doc, ipath + ("g",), group, init.get("g"))
    has_xi, has_mu = init.get("xi") is not None, init.get("mu") is not None
    if has_xi == has_mu:
        raise doc.error(ipath, f"expected exactly one of xi or mu (a list of {group.d} numbers), "
                               f"got {'both' if has_xi else 'neither'}")
    key = "xi" if has_xi else "mu"
    vec = doc.vector(ipath + (key,), init[key], group.d)
    project = init.get("project", False)
    if type(project) is not bool:
        raise doc.error(ipath + ("project",), f"expected true or false, got "
                        f"{_describe(doc, project)}")
    record, expressions = ("g", "mu"), ()
    if raw.get("record") is not None:
        record, expressions = _record(doc, raw["record"], group, parameters or {})
    every = 1
    if raw.get("every") is not None:
        every = _int(doc, ("scene", "every"), raw["every"], 1, "an integer >= 1")
    section, every_t = None, None
    if isinstance(raw.get("section"), dict):
        every_t = _every_t(doc, raw["section"], h)
    elif raw.get("section") is not None:
        section = _section(doc, raw["section"], group, parameters or {})
    u = _controls(doc, raw, group, parameters or {}, inputs)
    return Scene(h=h, steps=steps, g0=tuple(tuple(float(x) for x in row) for row in G),
                 xi0=vec if has_xi else None, mu0=vec if has_mu else None,
                 record=record, every=every, section=section, expressions=expressions,
                 section_every_t=every_t, u=u, project=project)


def _controls(doc, raw, group, parameters, inputs):
    """scene.u (hpgen.model.controls): None when absent."""
    from pathlib import Path

    from .controls import parse_controls
    if raw.get("u") is None:
        return None
    path = ("scene", "u")
    if not inputs:
        raise doc.error(path, "this model has no control inputs (inputs:), so its scene takes "
                              "no u")
    base = None if doc.file in (None, "<string>") else Path(doc.file).parent
    return parse_controls(raw["u"], inputs, parameters, group, file=doc.file, field="scene.u",
                          base=base, line=doc.line(path))


def _every_t(doc, raw, h) -> float:
    """``section: {every_t: T}``, a section in t (stroboscopic): T > 0, a whole number of
    steps of the scene's h (within 1e-9 relative, as for ``duration``)."""
    path = ("scene", "section")
    raw = doc.mapping(path, raw, ("every_t",))
    if raw.get("every_t") is None:
        raise doc.error(path, "expected {every_t: T} (a section in t, every T > 0) or an "
                              "expression s(g, mu)")
    T = doc.number(path + ("every_t",), raw["every_t"], "a period T > 0")
    ratio = T / h
    if not math.isfinite(ratio) or T <= 0 or round(ratio) < 1 or \
            abs(ratio - round(ratio)) > 1e-9 * ratio:
        raise doc.error(path + ("every_t",), f"every_t / h = {ratio:.12g} is not a whole "
                                              "number >= 1 of steps (within 1e-9 relative); "
                                              "adjust every_t or h")
    return float(T)
