"""The bodies' Legendre maps in a family's per-body derivation (hpgen.derive.family): the
momentum dl/dxi, the node velocity (one Newton step from xi = 0, exact where d2l/dxi2 is
constant) with its Hessian and inverse per body, and whether the Lagrangian is quadratic in
the velocity body by body. Conventions as hpgen.derive.family's: body functions take
(g, xi or p, i[, e]), i the body's index input (index, then body data), e = (t, params)."""
from __future__ import annotations

import casadi as ca
import numpy as np

from .family_open import index_symbol, with_env
from .family_calls import CALL


def quadratic(lags, body) -> bool:
    """Whether every body class's d2l/dxi2 is free of xi (the Lagrangian is quadratic in
    the velocity body by body; the product's Hessian, built from call nodes, cannot say)."""
    for lag_in, _ in lags.values():
        X = ca.SX.sym("xi", body.d)
        args = [ca.SX.sym(f"a{k}", lag_in.sparsity_in(k)) for k in range(lag_in.n_in())]
        args[1] = X
        if ca.depends_on(ca.hessian(lag_in(*args), X)[0], X):
            return False
    return True


def momentum_functions(model, lags, body, ne):
    """{class key: Function(g, xi, i[, e]) -> dl/dxi} (call nodes); ne: e's size (0: closed)."""
    G, X, I = ca.SX.sym("g", body.n, body.n), ca.SX.sym("xi", body.d), index_symbol(model)[0]
    E = ca.SX.sym("e", ne) if ne else None
    return {key: ca.Function(f"body{c}_momentum", with_env([G, X, I], E),
                             [ca.gradient(lag_in(*with_env([G, X, I], E)), X)], CALL)
            for c, (key, (lag_in, _)) in enumerate(sorted(lags.items()))}


def node_velocity(model, lags, body, lay=None):
    """{class key: (Function(g (vec), p, i, Hinv (d*d, column-major)[, e]) -> Hinv (p -
    dl/dxi(g, 0)), Function(i) -> d2l/dxi2, Function(i) -> Hinv or None)}, or None for a
    class whose d2l/dxi2 depends on g or xi, or on e = (t, params) (lay: open_layout). It
    may depend on i: its inverse is taken numerically per body, as the expanded step does;
    when it depends on body data (runtime per-body lists, hpgen.derive.family_open) the
    third function inverts it symbolically, from the body's index input."""
    G, X, P = ca.SX.sym("g", body.n, body.n), ca.SX.sym("xi", body.d), ca.SX.sym("p", body.d)
    I = index_symbol(model)[0]
    E = ca.SX.sym("e", 1 + lay[1]) if lay is not None else None
    Hinv = ca.SX.sym("Hinv", body.d, body.d)
    out = {}
    for c, (key, (lag_in, _)) in enumerate(sorted(lags.items())):
        dl = ca.gradient(lag_in(*with_env([G, X, I], E)), X)
        hess = ca.jacobian(dl, X)
        if ca.depends_on(hess, ca.vertcat(ca.vec(G), X, *([E] if E is not None else []))):
            out[key] = None
            continue
        vel = ca.mtimes(Hinv, P - ca.substitute(dl, X, ca.SX.zeros(body.d)))
        inverse = None
        if I.numel() > 1 and ca.depends_on(hess, I[1:]):
            inverse = ca.Function(f"body{c}_hessian_inverse", [I],
                                  [ca.vec(ca.inv(hess))], CALL)
        out[key] = (ca.Function(f"body{c}_velocity", with_env([ca.vec(G), P, I, ca.vec(Hinv)], E),
                                [vel], CALL), ca.Function(f"body{c}_hessian", [I], [hess]),
                    inverse)
    return out


def numeric_index(model, k: int):
    """Body k's index input with zero body data (for a function that does not read them)."""
    q = len(model.family.local.data)
    return k if not q else ca.DM([k] + [0.0] * q)


def hessian_inverse(model, entry, k: int, index):
    """Body k's (d2l/dxi2)^-1, column-major: numerically (a DM) unless it depends on body
    data (``entry``: a node_velocity value; ``index``: body k's index input)."""
    if entry[2] is not None:
        return entry[2](index)
    H = np.array(entry[1](numeric_index(model, k)), dtype=float)
    return ca.DM(np.linalg.inv(H).ravel(order="F"))
