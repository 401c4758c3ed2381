"""Translate the model's sympy Lagrangian into CasADi SX, by walking the expression tree.

Only the node types hpgen's own parser can produce are accepted (numbers, symbols, +, *, **,
sin cos tan exp log, pi); anything else is a BuildError, never a silent approximation.
"""
from __future__ import annotations

import casadi as ca
import sympy as sp

from ..errors import BuildError

_FUNCS = {sp.sin: ca.sin, sp.cos: ca.cos, sp.tan: ca.tan, sp.exp: ca.exp, sp.log: ca.log}


def to_casadi(expr, mapping: dict):
    """CasADi SX for a sympy expression; ``mapping`` sends each free symbol to an SX scalar."""
    memo: dict = {}

    def walk(e):
        if e in memo:
            return memo[e]
        if e.is_Symbol:
            out = mapping[e]
        elif e.is_Number or e is sp.pi or e is sp.E:
            out = ca.SX(float(e))
        elif e.is_Add:
            out = ca.SX(0)
            for a in e.args:
                out = out + walk(a)
        elif e.is_Mul:
            out = ca.SX(1)
            for a in e.args:
                out = out * walk(a)
        elif e.is_Pow:
            base, ex = e.args
            if ex == sp.Rational(1, 2):
                out = ca.sqrt(walk(base))
            elif ex == -1:
                out = 1 / walk(base)
            elif ex.is_Integer and ex > 0:
                out = ca.constpow(walk(base), int(ex))
            elif ex.is_Number:
                out = ca.power(walk(base), float(ex))
            else:
                out = ca.power(walk(base), walk(ex))
        elif e.func in _FUNCS:
            out = _FUNCS[e.func](walk(e.args[0]))
        else:
            raise BuildError(f"cannot translate the Lagrangian node {e.func.__name__} to CasADi")
        memo[e] = out
        return out

    return walk(expr)


def _mapping(model, g, xi, t=None, params=None, u=None) -> dict:
    mapping = {s: xi[k] for k, s in enumerate(model.xi_symbols)}
    for i, row in enumerate(model.g_symbols):
        for j, s in enumerate(row):
            mapping[s] = g[i, j]
    if t is not None:
        from ..model.symbols import TIME_SYMBOL
        mapping[TIME_SYMBOL] = t
        mapping.update({s: params[k] for k, s in enumerate(model.runtime_symbols)})
        mapping.update({s: u[k] for k, s in enumerate(model.input_symbols)})
    return mapping


def open_functions(model):
    """(l, f) for a model with forces, inputs, runtime parameters or time (Model.open_system):
    l(g, xi, t, params) -> scalar and f(g, xi, t, u, params) -> d (the generalized force in
    g*, left-trivialized, zero when the model has none) as casadi.Functions; g n x n, t a
    scalar, u (m) the control inputs, params (P) the flat runtime parameters
    (Model.runtime_symbols order)."""
    n, d = model.group.n, model.group.d
    g, xi, t = ca.SX.sym("g", n, n), ca.SX.sym("xi", d), ca.SX.sym("t", 1)
    u = ca.SX.sym("u", len(model.input_symbols))
    P = ca.SX.sym("params", len(model.runtime_symbols))
    mapping = _mapping(model, g, xi, t, P, u)
    lag = ca.Function("l", [g, xi, t, P], [to_casadi(model.lagrangian, mapping)],
                      ["g", "xi", "t", "params"], ["l"])
    f = ca.vertcat(*[to_casadi(e, mapping) for e in model.forces]) if model.forces \
        else ca.SX.zeros(d)
    force = ca.Function("f", [g, xi, t, u, P], [f], ["g", "xi", "t", "u", "params"], ["f"])
    return lag, force


def lagrangian_function(model):
    """l(g, xi) as a casadi.Function of the n x n matrix g and the d-vector xi (a closed
    model: no t, no runtime parameter; see open_functions otherwise)."""
    n, d = model.group.n, model.group.d
    g = ca.SX.sym("g", n, n)
    xi = ca.SX.sym("xi", d)
    expr = to_casadi(model.lagrangian, _mapping(model, g, xi))
    return ca.Function("l", [g, xi], [expr], ["g", "xi"], ["l"])
