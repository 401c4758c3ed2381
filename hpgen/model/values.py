"""Values of the whitelist evaluator (hpgen.model.evaluator): sympy scalars, or numpy object
arrays of sympy scalars (1-D vectors, 2-D matrices); shapes, their wording in messages, and
fresh arrays of real symbols."""
from __future__ import annotations

import functools

import numpy as np
import sympy as sp


def _shape(v):
    return v.shape if isinstance(v, np.ndarray) else ()


def _shape_text(shape) -> str:
    return {0: "scalar", 1: "vector of length {}", 2: "{} x {} matrix"}[len(shape)].format(*shape)


def _to_array(values: list, shape) -> np.ndarray:
    out = np.empty(len(values), dtype=object)
    out[:] = values
    return out.reshape(shape)


def _as_sympy(v):
    """A parameter value (int, float, list, list of lists) as a sympy scalar / object array;
    a runtime parameter's symbol (sympy scalar or object array of them) is returned as is."""
    if isinstance(v, (np.ndarray, sp.Basic)):
        return v
    if isinstance(v, list):
        items = [_as_sympy(x) for x in v]
        if items and isinstance(items[0], np.ndarray):
            return _to_array([e for row in items for e in row], (len(items), len(items[0])))
        return _to_array(items, (len(items),))
    return sp.Integer(v) if type(v) is int else sp.Float(v)


def _real_symbols(names: list[str]) -> tuple:
    """sp.Symbol(name, real=True) for each name. Symbols of the same assumptions share their
    assumption tables (sympy caches them), so past the first symbol each is that symbol with
    another name, made without sympy's per-symbol canonicalisation (a family's g has
    16 N^2 entries); equal and of equal hash to sp.Symbol(name, real=True), else (another
    sympy) every symbol is made by sp.Symbol."""
    first = sp.Symbol(names[0], real=True)
    out = [first]
    for name in names[1:]:
        s = sp.Expr.__new__(sp.Symbol)
        s.name = name
        s._assumptions = first._assumptions
        s._assumptions_orig = first._assumptions_orig
        s._assumptions0 = first._assumptions0
        out.append(s)
    if len(out) > 1:
        probe = sp.Symbol(names[-1], real=True)
        if not (out[-1] == probe and hash(out[-1]) == hash(probe)
                and out[-1].assumptions0 == probe.assumptions0):
            return tuple(sp.Symbol(name, real=True) for name in names)
    return tuple(out)


@functools.lru_cache(maxsize=16)
def _symbol_list(prefix: str, rows: int, cols: int | None) -> tuple:
    if cols is None:
        return _real_symbols([f"{prefix}_{k}" for k in range(rows)])
    return _real_symbols([f"{prefix}_{i}_{j}" for i in range(rows) for j in range(cols)])


@functools.lru_cache(maxsize=16)
def _symbols(prefix: str, rows: int, cols: int | None = None) -> np.ndarray:
    """The read-only object array of the real symbols ``<prefix>_k`` (rows,) or
    ``<prefix>_i_j`` (rows x cols), created once per size (a family's g has n*n of them)."""
    out = _to_array(list(_symbol_list(prefix, rows, cols)),
                    (rows,) if cols is None else (rows, cols))
    out.flags.writeable = False
    return out


@functools.lru_cache(maxsize=16)
def symbol_rows(prefix: str, rows: int, cols: int) -> tuple:
    """The symbols of _symbols(prefix, rows, cols) as a tuple of row tuples (Model.g_symbols),
    built once per size."""
    flat = _symbol_list(prefix, rows, cols)
    return tuple(flat[i * cols:(i + 1) * cols] for i in range(rows))
