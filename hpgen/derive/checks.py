"""Compile-time checks on a derived step."""
from __future__ import annotations

import numpy as np

from ..errors import ModelError

#: a Legendre transform whose Hessian is worse conditioned than this is called singular
MAX_HESSIAN_CONDITION = 1e12


def check_legendre(step, model) -> None:
    """d^2 l / d xi^2 must be nonsingular at the initial state (the scene's, else g = identity,
    xi = 0; t = 0 and the default runtime parameters for an open model), or the discrete
    Legendre transform, and with it the step, is not defined."""
    n, d = step.n, step.d
    if model.scene is not None:
        g0 = np.array(model.scene.g0, dtype=float)
        xi0 = np.array(model.scene.xi0 if model.scene.xi0 is not None else np.zeros(d), float)
        where = "at the scene's initial state"
    else:
        g0, xi0, where = np.eye(n), np.zeros(d), "at g = identity, xi = 0"
    spec = step.open_spec     # an open model: at t = 0 with the default runtime parameters
    extra = () if spec is None else (np.concatenate([[0.0, 0.0], np.zeros(spec.m),
                                                     spec.defaults]),)
    H = np.array(step.kernel("hessian").function(g0.ravel(order="F"), xi0, *extra)).reshape(
        d, d, order="F")
    cond = np.linalg.cond(H) if np.all(np.isfinite(H)) else np.inf
    if not cond < MAX_HESSIAN_CONDITION:
        raise ModelError(f"the Legendre transform is singular {where}: d2l/dxi2 has condition "
                         f"number {cond:.3g} (limit {MAX_HESSIAN_CONDITION:.0e})"
                         f"{_null_direction(H)}; the Lagrangian must be nondegenerate in xi "
                         "(e.g. a positive definite kinetic energy)",
                         file=model.path, field="lagrangian", line=_lagrangian_line(model))


def _null_direction(H) -> str:
    """Where l has no curvature: the coordinates xi[k] of the (near) null vector of H."""
    if not np.all(np.isfinite(H)):
        return ""
    v = np.linalg.svd(H)[2][-1]
    ks = [k for k in range(len(v)) if abs(v[k]) > 1e-8 * np.abs(v).max()]
    if len(ks) == 1:
        return f"; l has no second derivative in xi[{ks[0]}]"
    if len(ks) <= 4:
        parts = " ".join(f"{'+' if v[k] > 0 else '-'} {abs(v[k]):.3g} xi[{k}]" for k in ks)
        return f"; l is flat along the velocity {parts.lstrip('+ ')}"
    return ""


def _lagrangian_line(model):
    """The model file's line of ``lagrangian:`` (None for a model without source text)."""
    from ..model.yamldoc import compose_document
    try:
        return compose_document(model.source, model.path).line(("lagrangian",))
    except (ModelError, TypeError, AttributeError):
        return None
