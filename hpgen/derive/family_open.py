"""The open part of a family model's per-body derivation (hpgen.derive.family): the step
vector of an open model and the per-body force.

An open family model's body functions take, besides (g_i, xi_i, i), the environment
e = (t, params) (the Lagrangian: t the time, params the runtime parameters in
Model.runtime_symbols' order) or (t, u, params) (the per-body force, u the control inputs in
Model.input_symbols' order); the step functions take the whole step vector
hv = [h, t_k, u, params] of hpgen.abi as their ``h``.

Body data (runtime per-body lists, hpgen.model.bodyterms.LocalTerms.data): a body function's
index input i is then the column (i, q_i), q_i body i's entries of the data in
LocalTerms.data's order, taken from hv's params; without body data it is the number i.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from .lagrangian import to_casadi
from .family_calls import CALL


def open_layout(model):
    """(m, P): the numbers of control inputs and runtime parameter entries of an open family
    model (its step vector hv = [h, t_k, u (m), params (P)], hpgen.abi), None when closed."""
    if not model.open_system:
        return None
    return len(model.inputs), len(model.runtime_symbols)


def split_step_vector(model, hv):
    """(h, e_k, e_1) from the step input hv: h the step (hv itself when closed), e_k and e_1
    the environment (t, params) at t_k and at t_k + h, or None when closed."""
    lay = open_layout(model)
    if lay is None:
        return hv, None, None
    h, t, P = hv[0], hv[1], hv[2 + lay[0]:]
    return h, ca.vertcat(t, P), ca.vertcat(t + h, P)


def index_symbol(model):
    """(I, i, data map): the SX index input of a body function (1 + q entries, q the body
    data's size), the expression of the index i in it and {body data symbol: its entry}."""
    data = model.family.local.data
    I = ca.SX.sym("i", 1 + len(data))
    if not data:
        return I, I, {}
    return I, I[0], {s: I[1 + j] for j, (s, _) in enumerate(data)}


def _data_positions(model) -> list:
    """For each body data entry, the positions in Model.runtime_symbols of bodies 0..N-1's
    values."""
    where = {s: k for k, s in enumerate(model.runtime_symbols)}
    return [[where[v] for v in vals] for _, vals in model.family.local.data]


def body_index(model, k: int, hv):
    """Body k's index input: k, or the column (k, q_k) with q_k from the params of the step
    vector hv."""
    if not model.family.local.data:
        return k
    P = hv[2 + len(model.inputs):]
    return ca.vertcat(k, *[P[pos[k]] for pos in _data_positions(model)])


def body_indices(model, hv):
    """The index inputs of all bodies as columns (1 x N, or (1 + q) x N with body data from
    the params of the step vector hv)."""
    N = model.family.count
    I = ca.DM(np.arange(N)).T
    if not model.family.local.data:
        return I
    pos = _data_positions(model)
    P = hv[2 + len(model.inputs):]
    return ca.vertcat(I, ca.reshape(P[[p[k] for k in range(N) for p in pos]], len(pos), N))


def with_env(args, e):
    """A body function's arguments, with the environment e (t, params) appended when open."""
    return [*args, e] if e is not None else list(args)


def body_force_function(model, body, inline: bool = False):
    """Function(vec g, xi, i, e) -> the body's force (d) of a per-body ``forces:``, e = (t, u,
    params) (Model.input_symbols', Model.runtime_symbols' orders); None without one. A call
    node (hpgen.derive.family_calls), or with ``inline`` a plain SX Function, whose call on SX
    arguments is its expression: a step's Jacobian then sees through the force instead of
    calling its forward derivative once per direction."""
    out = body_force_expression(model, body)
    if out is None:
        return None
    return ca.Function("body_force_inline", *out) if inline else \
        ca.Function("body_force", *out, CALL)


def body_force_expression(model, body):
    """([vec g, xi, i, e], [f]): body_force_function's inputs and output as SX (for a caller
    that inlines the force into its own expression); None without a per-body force."""
    from ..model.symbols import TIME_SYMBOL
    bf = model.family.local.force
    if bf is None:
        return None
    m, nP = open_layout(model)
    G, X = ca.SX.sym("g", body.n, body.n), ca.SX.sym("xi", body.d)
    I, i, data = index_symbol(model)
    E = ca.SX.sym("e", 1 + m + nP)
    mapping = {TIME_SYMBOL: E[0], bf.index: i, **data,
               **{s: E[1 + k] for k, s in enumerate(model.input_symbols)},
               **{s: E[1 + m + k] for k, s in enumerate(model.runtime_symbols)}}
    for e in bf.exprs:
        for sym in e.free_symbols:
            name = str(sym)
            if name.startswith("xi_"):
                mapping[sym] = X[int(name[3:])]
            elif name.startswith("g_"):
                a, b = map(int, name[2:].split("_"))
                mapping[sym] = G[a, b]
    f = ca.vertcat(*[to_casadi(e, mapping) for e in bf.exprs])
    return [ca.vec(G), X, I, E], [f]


def product_force(fb, model, hv, nb, db, N, joint_forces=()):
    """(G, X, t) -> the product's force as N calls of the body force ``fb`` with (t, u,
    params) of the step vector hv, plus the forces between bodies (hpgen.derive.
    family_joint_forces: [(Function, JointForce), ...]); None without a per-body force."""
    if fb is None:
        return None
    m = len(model.inputs)
    u, P = hv[2:2 + m], hv[2 + m:]

    def force(Gp, Xp, tt):
        own = [fb(ca.vec(Gp[k * nb:(k + 1) * nb, k * nb:(k + 1) * nb]), Xp[k * db:(k + 1) * db],
                  body_index(model, k, hv), ca.vertcat(tt, u, P)) for k in range(N)]
        if joint_forces:
            from .family_joint_forces import joint_power_force
            between = joint_power_force(model, joint_forces, Gp, Xp, tt, hv, nb, db, N)
            own = [a + b for a, b in zip(own, between)]
        return ca.vertcat(*own)
    return force
