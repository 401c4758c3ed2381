"""``scene.initial.project: true``: the scene's initial state moved onto the constraints
phi(g) = 0 and their velocity form Phi(g) xi = 0 before the admissibility checks of
hpgen.model.constraints, and how far it moved (Scene.projection, an InitialProjection).

Conventions:
- The metric is the kinetic one, H = d2l/dxi2 at the scene's (g0, xi0) (xi0 = 0 for a scene
  given by mu; t = 0, runtime parameters at their defaults): the corrections are the
  H-orthogonal ones, so a velocity is moved as a perfectly plastic impulse on the constraints
  would move it, and the result does not depend on the units of the body coordinates.
- g: Gauss-Newton on the group, g <- g exp(eta) with eta = -H^-1 Phi^T (Phi H^-1 Phi^T)^-1
  phi(g) (the smallest H-norm step that cancels phi to first order), until |phi|max stops
  decreasing below PROJECT_TOL or after MAX_ITER iterations; refused when the residual is
  still above hpgen.model.constraints.INITIAL_TOL (too far from the constraints).
- xi (a scene given by xi): xi <- xi - H^-1 Phi^T (Phi H^-1 Phi^T)^-1 Phi xi at the projected
  g, exact on the velocity form. A scene given by mu keeps its mu (the first step's impulse
  puts the momentum on the velocity form).
- ``moved_g``: max |g_projected - g0| over the entries (positions in the model's length unit,
  rotations in radians to first order); ``moved_xi``: max |xi_projected - xi0| (0 for mu).
CasADi evaluates phi, Phi and H (the compile-time stack, as the constraint rank check).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Gauss-Newton stops once |phi|max <= PROJECT_TOL (absolute) or stops decreasing
PROJECT_TOL = 1e-15
MAX_ITER = 50


@dataclass(frozen=True)
class InitialProjection:
    """How far ``scene.initial.project`` moved the initial state (module docstring)."""
    moved_g: float
    moved_xi: float
    residual_before: float           #: max |phi(g0)| as written
    residual_after: float            #: max |phi(g)| after the projection
    iterations: int

    @property
    def note(self) -> str:
        """One line for a user: what the projection changed."""
        return (f"scene.initial projected onto the constraints: g moved by {self.moved_g:.3e}, "
                f"xi by {self.moved_xi:.3e} (max entry); |phi| {self.residual_before:.3e} -> "
                f"{self.residual_after:.3e} in {self.iterations} Gauss-Newton steps")


def casadi_maps(constraints, g_symbols, group, lagrangian, xi_symbols, fixed):
    """casadi.Function (g, xi) -> (phi, Phi, H) (module docstring); ``lagrangian`` a sympy
    l or a BodyLagrangian (hpgen.model.family_load: a family's, its joint potentials left
    out, they do not enter H)."""
    import casadi as ca

    from ..derive.lagrangian import to_casadi
    from .symbols import TIME_SYMBOL
    n, d = group.n, group.d
    G, X, eta = ca.SX.sym("g", n, n), ca.SX.sym("xi", d), ca.SX.sym("eta", d)
    gmap = {s: G[i, j] for i, row in enumerate(g_symbols) for j, s in enumerate(row)}
    rows = [to_casadi(r, gmap) for c in constraints for r in c.rows]
    phi = ca.vertcat(*rows)
    varied = ca.substitute(phi, G, ca.mtimes(G, ca.SX.eye(n) + group.hat(eta)))
    Phi = ca.substitute(ca.jacobian(varied, eta), eta, ca.SX.zeros(d))
    from .family_load import BodyLagrangian, body_terms_sx
    if isinstance(lagrangian, BodyLagrangian):      # a family loaded body by body
        runtime = {s: v for s, v in fixed.items() if s is not TIME_SYMBOL}
        l_sx = body_terms_sx(lagrangian, group, X, lambda r, c: G[r, c], runtime)
    else:
        mapping = {**gmap, **{s: X[k] for k, s in enumerate(xi_symbols)}}
        l_sx = to_casadi(lagrangian.xreplace(fixed), mapping)
    H = ca.hessian(l_sx, X)[0]
    return ca.Function("projection", [G, X], [phi, Phi, H])


def _retract(group, g, eta):
    """g exp(eta^) with each factor's fixed entries (affine bottom row, the identity block of
    R<k>, the zero off-diagonal blocks of a product) kept exact."""
    import casadi as ca
    from scipy.linalg import expm

    from ..groups import group_from_spec
    step = g @ expm(np.array(ca.evalf(group.hat(ca.SX(eta))), dtype=float))
    out = np.zeros_like(g)
    for f in group.factors:
        fg = group_from_spec(f.name)
        block = np.eye(f.n)
        moved = step[f.row:f.row + f.n, f.row:f.row + f.n]
        if fg.rotation_block is not None:
            a, b = fg.rotation_block
            block[a:b, a:b] = moved[a:b, a:b]
        if fg.translation_block is not None:
            a, b = fg.translation_block
            block[a:b, -1] = moved[a:b, -1]
        out[f.row:f.row + f.n, f.row:f.row + f.n] = block
    return out


def _correction(Phi, Hinv, r):
    """H^-1 Phi^T (Phi H^-1 Phi^T)^-1 r."""
    HPt = Hinv @ Phi.T
    return HPt @ np.linalg.solve(Phi @ HPt, r)


def project(constraints, g_symbols, group, lagrangian, xi_symbols, fixed, g0, xi0):
    """(g, xi or None, InitialProjection, residual) for the scene's (g0, xi0) (module
    docstring); ``fixed`` the substitutions that make l a function of (g, xi) only (t and the
    runtime parameters). The caller refuses a residual above its tolerance and a singular
    Phi (its rank check names the row) or H (the Legendre check)."""
    fun = casadi_maps(constraints, g_symbols, group, lagrangian, xi_symbols, fixed)
    g = np.array(g0, dtype=float)
    xi = None if xi0 is None else np.array(xi0, dtype=float)
    probe = np.zeros(group.d) if xi is None else xi

    def evaluate(g):
        phi, Phi, H = fun(g, probe)
        return (np.array(phi, dtype=float).ravel(), np.array(Phi, dtype=float),
                np.array(H, dtype=float))

    phi, Phi, H = evaluate(g)
    Hinv = np.linalg.inv(H)
    before = best = float(np.abs(phi).max())
    its = 0
    while best > PROJECT_TOL and its < MAX_ITER:
        trial = _retract(group, g, -_correction(Phi, Hinv, phi))
        tphi, tPhi, _ = evaluate(trial)
        res = float(np.abs(tphi).max())
        if not res < best:
            break
        g, phi, Phi, best, its = trial, tphi, tPhi, res, its + 1
    moved_xi = 0.0
    if xi is not None:
        new = xi - _correction(Phi, Hinv, Phi @ xi)
        moved_xi, xi = float(np.abs(new - xi).max()), new
    note = InitialProjection(float(np.abs(g - np.asarray(g0, dtype=float)).max()), moved_xi,
                             before, best, its)
    return g, xi, note
