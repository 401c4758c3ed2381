"""Holonomic constraints phi(g) = 0 in one step: RATTLE-type multipliers at the nodes.

Conventions (docs/numerics.md sec. 14):
- Phi(g) (m x d) is the body-frame (left-trivialized) constraint Jacobian,
  Phi(g) eta = d/de phi(g exp(e eta)) at e = 0; it is taken by CasADi as the derivative of
  phi(g (I + eta^)) at eta = 0 (same first derivative).
- The action sum gains -h <lambda_k, phi(g_k)> at every node. Its variation in g_k is the
  impulse -h Phi(g_k)^T lambda_k: the reaction force in g* is f_c = -Phi^T lambda (the sign of
  the forces f, docs/numerics.md sec. 13, applied to -Phi^T lambda). RATTLE splits the node's impulse
  into two multipliers, lambda_k (fixed by phi(g_{k+1}) = 0, SHAKE's) and nu_{k+1} (fixed by
  the hidden constraint at the end of the step, Phi(g_{k+1}) xi_{k+1} = 0); the node
  momentum p_{k+1} is the one between the two impulses, on the hidden constraint.
- One step from (g_k, p_k), both on the constraint and the hidden constraint:
      p_k^+     = p_k - h Phi(g_k)^T lambda_k
      (Z; g_{k+1}, p_{k+1}^-) = the unconstrained step from (g_k, p_k^+)
      phi(g_{k+1}) / h = 0                                          (m rows)
      p_{k+1}   = p_{k+1}^- - h Phi(g_{k+1})^T nu_{k+1}
      dl/dxi(g_{k+1}, v_{k+1}) - p_{k+1} = 0,  Phi(g_{k+1}) v_{k+1} = 0   (d + m rows)
  Unknowns z = (Z, h lambda_k, h nu_{k+1}, v_{k+1}): the unconstrained step's unknowns, the
  two impulses and the node velocity v_{k+1} = xi(g_{k+1}, p_{k+1}) (the inverse Legendre
  transform, an unknown so that l need not be quadratic). When d2l/dxi2 is a constant
  matrix H (l = 1/2 xi.H xi + b(g, t).xi + ...), v_{k+1} = H^{-1} (p_{k+1} - b) is explicit
  and the d Legendre rows and unknowns are dropped.
  Since p_k enters the unconstrained step only through its eta_0 condition
  p_k + ds_k/deta_0 = 0, "the step from p_k^+" is the substitution p_k -> p_k^+ in it.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from .action import StepEquations
from .lagrangian import to_casadi


def constraint_function(model):
    """phi(g) as a casadi.Function of the n x n matrix g -> m rows (file order)."""
    n = model.group.n
    g = ca.SX.sym("g", n, n)
    mapping = {s: g[i, j] for i, row in enumerate(model.g_symbols) for j, s in enumerate(row)}
    rows = [to_casadi(r, mapping) for c in model.constraints for r in c.rows]
    return ca.Function("phi", [g], [ca.vertcat(*rows)], ["g"], ["phi"])


def body_jacobian(group, phi, G):
    """Phi(G) (m x d): Phi(G) eta = d/de phi(G exp(e eta)) at e = 0."""
    eta = ca.SX.sym("eta", group.d)
    varied = phi(ca.mtimes(G, ca.SX.eye(group.n) + group.hat(eta)))
    return ca.substitute(ca.jacobian(varied, eta), eta, ca.SX.zeros(group.d))


def constrain_step(eqs: StepEquations, group, phi, lag1, g, p, h) -> StepEquations:
    """The constrained step (module docstring) built around the unconstrained ``eqs``.

    phi: constraint_function(model); lag1(G, X): l at t_{k+1} (inputs and parameters bound);
    g (n x n), p (d), h: the SX symbols the unconstrained step was derived with."""
    m, d = phi.size1_out(0), group.d
    lam, nu, v1 = ca.SX.sym("lambda", m), ca.SX.sym("nu", m), ca.SX.sym("v1", d)
    p_plus = p - ca.mtimes(body_jacobian(group, phi, g).T, lam)
    sub = lambda e: ca.substitute(e, p, p_plus)  # noqa: E731
    g1 = sub(eqs.g1)
    Phi1 = body_jacobian(group, phi, g1)
    p1 = sub(eqs.p1) - ca.mtimes(Phi1.T, nu)
    nz = eqs.z.numel()
    blocks = eqs.blocks + (("lambda", nz, nz + m), ("nu", nz + m, nz + 2 * m))
    free = ca.SX.sym("xi", d)
    dl = ca.gradient(lag1(g1, free), free)
    hess = ca.jacobian(dl, free)
    if hess.is_constant():
        # l = 1/2 xi.H xi + b(g).xi + ...: the node velocity is explicit, H^{-1} (p - b)
        Hinv = np.linalg.inv(np.array(ca.evalf(hess), dtype=float))
        vel = ca.mtimes(ca.DM(Hinv), p1 - ca.substitute(dl, free, ca.SX.zeros(d)))
        residual = ca.vertcat(sub(eqs.residual), phi(g1) / h, ca.mtimes(Phi1, vel))
        return StepEquations(ca.vertcat(eqs.z, lam, nu), blocks, residual, g1, p1,
                             ca.vertcat(eqs.guess, ca.SX.zeros(2 * m)), eqs.xi_hat,
                             sub(eqs.margin), sub(eqs.chart_step))
    mu1 = ca.substitute(dl, free, v1)
    residual = ca.vertcat(sub(eqs.residual), phi(g1) / h, mu1 - p1, ca.mtimes(Phi1, v1))
    blocks += (("v1", nz + 2 * m, nz + 2 * m + d),)
    guess = ca.vertcat(eqs.guess, ca.SX.zeros(2 * m), eqs.xi_hat)
    return StepEquations(ca.vertcat(eqs.z, lam, nu, v1), blocks, residual, g1, p1, guess,
                         eqs.xi_hat, sub(eqs.margin), sub(eqs.chart_step))
