"""The grid file of ``hpgen sweep``: YAML data naming the members, never evaluated.

    xi0: [[0.2, 1.0, 3.0], [0.3, 1.0, 3.0]]   # or mu0: one vector of length d per member
    g0: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]     # optional: one matrix, or one per member
    h: 0.05                                    # optional: one step, or one per member (!= 0)
    steps: 1000                                # optional (default: the scene's)
    every: 10                                  # optional (default: the scene's)
    record: [energy, momentum]                 # optional (default: the scene's record list)
    chunk_size: 16                             # optional: members per chunk / Dask task
    params: {c: [0.1, 0.2]}                    # optional: runtime parameters per member
    u: [[2.5, 2.4], [2.4, 2.5]]                # optional: constant inputs, shared or per member
                                               # (a single number in params: shared by all)

Read with hpgen.model.yamldoc (composed node by node: no PyYAML constructor runs, tags are
refused); every error is one line naming the file, the field and its line.
"""
from __future__ import annotations

from ..model.yamldoc import compose_document, describe, is_number

KEYS = ("xi0", "mu0", "g0", "h", "steps", "every", "record", "chunk_size", "params", "u")


def read_grid(path, n: int, d: int) -> dict:
    """The sweep arguments of the grid file ``path`` for a group of n x n matrices and
    algebra dimension d: a dict with some of KEYS (xi0 or mu0 always). ModelError."""
    from ..api import read_model_text
    from ..errors import ModelError
    text = read_model_text(path)
    if not text.strip():
        raise ModelError("the grid file is empty; expected a mapping with xi0 or mu0",
                         file=str(path))
    doc = compose_document(text, str(path))
    data = doc.mapping((), doc.data, KEYS)
    if ("xi0" in data) == ("mu0" in data):
        raise doc.error(("xi0",) if "xi0" in data else (),
                        "give exactly one of xi0 (velocities) and mu0 (momenta): a list "
                        f"of vectors of length {d}, one per member")
    kind = "xi0" if "xi0" in data else "mu0"
    out = {kind: _vectors(doc, kind, data[kind], d)}
    B = len(out[kind])
    if "g0" in data:
        out["g0"] = _g0(doc, data["g0"], n, B)
    if "h" in data:
        v = data["h"]
        out["h"] = _nonzero(doc, ("h",), v) if not isinstance(v, list) else \
            [_nonzero(doc, ("h", i), x) for i, x in enumerate(_per_member(doc, "h", v, B))]
    for key in ("steps", "every", "chunk_size"):
        if key in data:
            out[key] = _integer(doc, key, data[key], 0 if key == "steps" else 1)
    if "record" in data:
        v = data["record"]
        if not isinstance(v, list) or not v or not all(isinstance(r, str) for r in v):
            raise doc.error(("record",), f"expected a non-empty list of record names, got "
                                         f"{describe(v)}")
        out["record"] = list(v)
    if "params" in data:
        p = data["params"]
        if not isinstance(p, dict) or not p:
            raise doc.error(("params",), f"expected a mapping of runtime parameter names to "
                                         f"one value per member, got {describe(p)}")
        out["params"] = {k: _param(doc, k, v, B) for k, v in p.items()}
    if "u" in data:               # shapes against the model's inputs: hpgen.ensemble.members
        v = data["u"]
        rows = v if isinstance(v, list) and v and isinstance(v[0], list) else [v]
        if not all(isinstance(r, list) and r and all(is_number(x) for x in r) for r in rows):
            raise doc.error(("u",), "expected the constant inputs: a list of m numbers "
                                    f"(shared) or one such list per member, got {describe(v)}")
        out["u"] = v
    return out


def _vectors(doc, key, v, d):
    if not isinstance(v, list) or not v:
        raise doc.error((key,), f"expected a non-empty list of vectors of length {d} (one per "
                                f"member), got {describe(v)}")
    return [doc.vector((key, i), x, d) for i, x in enumerate(v)]


def _g0(doc, v, n, B):
    if isinstance(v, list) and v and isinstance(v[0], list) and v[0] \
            and isinstance(v[0][0], list):
        return [doc.matrix(("g0", i), x, (n, n)) for i, x in
                enumerate(_per_member(doc, "g0", v, B))]
    return doc.matrix(("g0",), v, (n, n))


def _per_member(doc, key, v, B):
    if len(v) != B:
        raise doc.error(tuple(key.split(".")), f"expected one value per member ({B}), got "
                                               f"{len(v)}")
    return v


def _param(doc, name, v, B):
    """A runtime parameter's values: one per member (numbers, or lists of numbers for a
    vector parameter), or one number shared by all B members."""
    if is_number(v):
        return [doc.number(("params", name), v)] * B
    if not isinstance(v, list):
        raise doc.error(("params", name), f"expected a number (shared by all members) or a "
                                          f"list of {B} values (one per member), got "
                                          f"{describe(v)}")
    for i, x in enumerate(_per_member(doc, f"params.{name}", v, B)):
        if isinstance(x, list):
            doc.vector(("params", name, i), x)
        else:
            doc.number(("params", name, i), x)
    return v


def _nonzero(doc, path, v):
    x = doc.number(path, v, "a step h != 0")
    if x == 0:
        raise doc.error(path, "expected a step h != 0 (h < 0 runs backwards in time), got 0")
    return x


def _integer(doc, key, v, low):
    if not (is_number(v) and type(v) is int) or v < low:
        raise doc.error((key,), f"expected an integer >= {low}, got {describe(v)}")
    return v
