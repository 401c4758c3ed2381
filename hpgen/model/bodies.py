"""The body-indexed names of a family model and the vector functions of the expression language.

Used by hpgen.model.evaluator. Values are sympy scalars or numpy object arrays of them (the
evaluator's convention). In a model on ``G^N`` (hpgen.model.families) the names below are
BodyIndexed: their first index is a body (0..N-1) and gives body i's value:

    xi[i]  body i's algebra vector (length d of G)     mu[i]  its momentum (sections, records)
    g[i]   its group element (n x n)                    R[i]   its rotation (SO2 SO3 SE2 SE3)
    x[i]   its position (SE2 SE3 R<k>)                  w[i]   its angular velocity: SO3, SE3
           xi[i][0:3]; SO2, SE2 the scalar xi[i][0]     v[i]   its body-frame linear velocity:
           SE2 xi[i][1:3], SE3 xi[i][3:6], R<k> xi[i]

Functions: ``cross(a, b)`` (two 3-vectors), ``transpose(M)`` (a matrix), ``norm2(v)`` (the
squared Euclidean norm of a vector, the squared Frobenius norm of a matrix); ``a @ b`` is
``dot(a, b)``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from .syntax import fail


@dataclass(frozen=True)
class BodyIndexed:
    """A name of a family model indexed by body: ``values[i]`` is body i's value."""
    name: str
    values: tuple
    what: str                      # e.g. "algebra vector", for messages


def body_names(layouts, groups, variables: dict, g) -> dict:
    """{name: BodyIndexed} for a family: ``layouts`` the product's FactorLayouts, ``groups``
    the factor groups, ``variables`` {"xi": array, "mu": array, ...} (flat, length d), ``g``
    the n x n array."""
    out = {}
    for v, arr in variables.items():
        out[v] = BodyIndexed(v, tuple(arr[L.off:L.off + L.d] for L in layouts),
                             "algebra vector" if v == "xi" else "momentum")
    blocks = [g[L.row:L.row + L.n, L.row:L.row + L.n] for L in layouts]
    out["g"] = BodyIndexed("g", tuple(blocks), "group element")
    G = groups[0]
    if G.rotation_block:
        a, b = G.rotation_block
        out["R"] = BodyIndexed("R", tuple(B[a:b, a:b] for B in blocks), "rotation")
    if G.translation_block:
        a, b = G.translation_block
        out["x"] = BodyIndexed("x", tuple(B[a:b, L.n - 1] for B, L in zip(blocks, layouts)),
                               "position")
    if "xi" in variables:
        xis = out["xi"].values
        if G.rotation_block:                       # angular first: SO2/SE2 omega, SO3/SE3 w
            planar = G.rotation_block[1] - G.rotation_block[0] == 2
            out["w"] = BodyIndexed("w", tuple(s[0] if planar else s[0:3] for s in xis),
                                   "angular velocity")
        if G.translation_block:                    # the last k entries (all of R<k>'s)
            k = G.translation_block[1] - G.translation_block[0]
            out["v"] = BodyIndexed("v", tuple(s[s.shape[0] - k:] for s in xis),
                                   "linear velocity")
    return out


def cross(a, b):
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                     a[0] * b[1] - a[1] * b[0]], dtype=object)


def transpose(m):
    return np.ascontiguousarray(m.T)


def norm2(v):
    return sp.Add(*[e * e for e in v.flat])


def select_body(node, val: BodyIndexed, idx):
    """``val[i]``: body i's value; ``idx`` the evaluated index tuple."""
    n = len(val.values)
    if len(idx) != 1:
        raise fail(node, f"{val.name} takes one body index in a family model: {val.name}[i] "
                         f"is body i's {val.what}; index its entries after it, e.g. "
                         f"{val.name}[i][0]")
    if not 0 <= idx[0] < n:
        raise fail(node, f"body index {idx[0]} out of range for {val.name}: the family has "
                         f"N = {n} bodies (0..{n - 1})")
    return val.values[idx[0]]


def body_parameter(node, name: str, val, idx, n: int):
    """``p[i]`` with a sum variable in the index, for a family of ``n`` bodies: a scalar is
    shared by every body; a list must have one entry per body (along its first axis)."""
    if not isinstance(val, np.ndarray):
        if len(idx) != 1:
            raise fail(node, f"the parameter {name} is a scalar: index it with one body index "
                             "(shared by every body) or not at all")
        if not 0 <= idx[0] < n:
            raise fail(node, f"body index {idx[0]} out of range for {name}: the family has "
                             f"N = {n} bodies (0..{n - 1})")
        return val
    if val.shape[0] != n:
        raise fail(node, f"the body-indexed parameter {name} has {val.shape[0]} entries but the "
                         f"family has N = {n} bodies; expected one entry per body or one shared "
                         "value (a shared vector or matrix is written without the index)")
    if len(idx) > len(val.shape) or not all(0 <= i < s for i, s in zip(idx, val.shape)):
        raise fail(node, f"index {list(idx)} out of range for the parameter {name} (shape "
                         f"{' x '.join(map(str, val.shape))})")
    return val[idx] if len(idx) == len(val.shape) else val[idx[0]]
