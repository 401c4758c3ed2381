"""``hpgen check`` on a model with holonomic constraints phi(g) = 0 (docs/numerics.md sec. 14).

The constrained step (RATTLE-type at the nodes) keeps the states on the constraint manifold

    M = {(g, p) : phi(g) = 0,  Phi(g) xi(g, p) = 0},

Phi(g) eta = d/de phi(g exp(e eta)) the constraint's body-frame Jacobian (m x d) and
xi(g, p) the velocity of the node momentum (dl/dxi(g, xi) = p). On M (dimension 2(d - m))
the step is symplectic; off it the map is not (the projection onto M), so the symplecticity
check compares T^T (Phi'^T Omega(p_1) Phi' - Omega(p_0)) T with zero, T an orthonormal basis
of the tangent space T_(g,p) M: the null space of the 2m x 2d Jacobian of (phi(g),
Phi(g) xi(g, p)) in the left-trivialized chart (g (I + delta^), p + dp) of
hpgen.analysis.symplectic, by CasADi AD, xi's derivative by the implicit function theorem
on the Legendre map. ``ManifoldCheck`` also measures the residuals max |phi(g_k)| and
max |Phi(g_k) xi_k| along a run. Compile-time stack (casadi, scipy): the check's side.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

#: a constraint residual (position max |phi|, velocity max |Phi xi|) at most this passes:
#: the constrained step solves phi(g_{k+1}) = 0 and Phi xi = 0 with Newton to 1e-14 relative
#: (docs/numerics.md sec. 14: round-off, 1e-15 .. 1e-13 measured on the pendulum chains);
#: a model's lengths of order 1 leave a factor 10 to 1000
CONSTRAINT_TOL = 1e-12


class ManifoldCheck:
    """The constraint manifold of ``model`` (closed, or open with the step vector's t and the
    file's runtime parameters): ``residuals(g, mu)`` along a run and ``tangent_basis(g, p)``
    (2d x 2(d - m), orthonormal columns)."""

    def __init__(self, model):
        from ..derive.constraints import body_jacobian, constraint_function
        grp, n, d = model.group, model.group.n, model.group.d
        phi = constraint_function(model)
        G, X, P, D, dP = (ca.SX.sym("g", n, n), ca.SX.sym("xi", d), ca.SX.sym("p", d),
                          ca.SX.sym("delta", d), ca.SX.sym("dp", d))
        t = ca.SX.sym("t", 1)
        if model.open_system:
            from ..derive.lagrangian import open_functions
            lag_f, _ = open_functions(model)
            params = ca.DM(np.asarray(model.runtime_defaults, float).reshape(-1, 1))
            lag = lambda g, x: lag_f(g, x, t, params)  # noqa: E731
        else:
            from ..derive.lagrangian import lagrangian_function
            lag = lagrangian_function(model)
        Gv = ca.mtimes(G, ca.SX.eye(n) + grp.hat(D))
        C = ca.vertcat(phi(Gv), ca.mtimes(body_jacobian(grp, phi, Gv), X))
        R = ca.gradient(lag(Gv, X), X) - (P + dP)        # the Legendre map's residual
        S = ca.vertcat(D, dP)
        at0 = lambda e: ca.substitute(e, ca.vertcat(D, dP), ca.SX.zeros(2 * d))  # noqa: E731
        outs = [at0(ca.jacobian(C, S)), at0(ca.jacobian(C, X)), at0(ca.jacobian(R, S)),
                at0(ca.jacobian(R, X))]
        self._jac = ca.Function("manifold", [G, X, P, t], outs)
        Phi = body_jacobian(grp, phi, G)
        self._res = ca.Function("residuals", [G, X], [phi(G), ca.mtimes(Phi, X)])
        self.m, self.d = phi.size1_out(0), d

    def tangent_basis(self, g, p, xi, t=0.0) -> np.ndarray:
        """T (2d, 2(d - m)): orthonormal basis of T_(g,p) M; xi the velocity of (g, p)."""
        from scipy.linalg import null_space
        Cs, Cx, Rs, Rx = (np.array(a, dtype=float) for a in self._jac(g, xi, p, t))
        return null_space(Cs - Cx @ np.linalg.solve(Rx, Rs))

    def residuals(self, g, xi) -> tuple[float, float]:
        """(|phi(g)|_inf, |Phi(g) xi|_inf) at one state."""
        a, b = self._res(g, xi)
        return float(np.abs(np.array(a)).max()), float(np.abs(np.array(b)).max())


def manifold_defect(Phi, T, Omega0, Omega1) -> tuple[float, float]:
    """(absolute, relative) symplecticity defect of Phi' restricted to the tangent vectors T
    (columns) of the constraint manifold: |T^T (Phi'^T Omega1 Phi' - Omega0) T|_max, and that
    over |Phi'|_2^2 |Omega1|_2 (as hpgen.analysis.symplectic.symplectic_defect)."""
    E = T.T @ (Phi.T @ Omega1 @ Phi - Omega0) @ T
    absolute = float(np.abs(E).max())
    scale = float(np.linalg.norm(Phi, 2) ** 2 * np.linalg.norm(Omega1, 2))
    return absolute, absolute / max(scale, np.finfo(float).tiny)
