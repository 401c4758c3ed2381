"""What a scene's ``record:`` list asks for, as one SX row per sample (kernel ``record``).

The row is the concatenation, in the scene's order, of the requested items (widths in doubles):

    g        n*n  the group element, column-major (g.ravel(order="F"))
    mu       d    the node momentum p_k
    xi       d    the body velocity (dl/dxi)^{-1}(g, mu)
    energy   1    <dl/dxi, xi> - l at that xi
    momentum d    the spatial momentum Ad*_{g^{-1}} mu
    defect   1    distance of g from the group
    <label>  1    a user expression in g, xi, mu (hpgen.model.types.RecordExpr)
    power    1    <f(g, xi, t, u), xi>: the forces' power (forced models; t, u, params from
                  the record kernel's step vector: u of the step that ends at the record)
    work     1    the same node power: the runtime replaces this column by the work
                  accumulated from the power at every step (hpgen.runtime.work)

Without a scene the row is (g, mu). The layout ((name, offset, shape), ...) travels with the
DiscreteStep to meta.json ("record"), where the runtime reads it to slice the rows.
"""
from __future__ import annotations

import casadi as ca

from .lagrangian import to_casadi

DEFAULT_RECORD = ("g", "mu")


def record_names(model) -> tuple:
    scene = getattr(model, "scene", None)
    return tuple(scene.record) if scene is not None else DEFAULT_RECORD


def _expressions(model) -> dict:
    scene = getattr(model, "scene", None)
    return {e.label: e for e in getattr(scene, "expressions", ())} if scene is not None else {}


def record_row(model, group, g, p, xi, lag, power=None):
    """(row SX column, layout) for ``model``'s scene at (g (n x n SX), p, xi); lag(g, xi) the
    Lagrangian; power(g, xi) the forces' power <f, xi> (forced models). layout: ((name,
    offset, shape), ...) with shape () for scalars, (d,) for vectors and (n, n) for g."""
    n, d = group.n, group.d
    lval = lag(g, xi)
    mu = ca.gradient(lval, xi)
    exprs = _expressions(model)
    parts, layout, offset = [], [], 0
    for name in record_names(model):
        if name == "g":
            item, shape = ca.reshape(g, n * n, 1), (n, n)
        elif name == "mu":
            item, shape = p, (d,)
        elif name == "xi":
            item, shape = xi, (d,)
        elif name == "energy":
            item, shape = ca.dot(mu, xi) - lval, ()
        elif name == "momentum":
            item, shape = group.momentum_map(g, p), (d,)
        elif name == "defect":
            item, shape = group.group_defect(g), ()
        elif name in ("power", "work") and name not in exprs:
            item, shape = power(g, xi), ()
        else:
            spec = exprs[name]
            mapping = {s: xi[k] for k, s in enumerate(spec.xi_symbols)}
            mapping.update({s: p[k] for k, s in enumerate(spec.mu_symbols)})
            for i, row in enumerate(spec.g_symbols):
                for j, s in enumerate(row):
                    mapping[s] = g[i, j]
            item, shape = to_casadi(spec.expr, mapping), ()
        width = item.numel()
        layout.append((name, offset, shape))
        parts.append(ca.densify(ca.reshape(item, width, 1)))
        offset += width
    return ca.vertcat(*parts), tuple(layout)


def velocity_step(g, p, xi, lag):
    """One Newton step of dl/dxi (g, xi) = p in xi: xi - H^{-1} (dl/dxi - p), H = d2l/dxi2.
    From xi = 0 it is exact when l is quadratic in xi."""
    lval = lag(g, xi)
    mu = ca.gradient(lval, xi)
    return xi - ca.solve(ca.jacobian(mu, xi), mu - p)
