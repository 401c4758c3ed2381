"""Lie Stormer-Verlet (eqs. sv1-sv5) and the forward / backward variational Euler methods on
SO(3), coded from the paper's equations (section "Lie Group VPRK Integrators"), for the heavy
top

    l(R, Omega) = 1/2 Omega.I Omega - Mg chi.(R^T e3),      tau = cay or exp (q = 0).

Derivatives of l (by hand):
    dl/dxi(R, Omega) = I Omega,
    g dl/dg (R) = Mg (R^T e3) x chi    (left-trivialized: d/de l(R (e + e eta^)) =
                  -Mg chi.((e - e eta^) R^T e3)' = Mg chi.(eta x R^T e3) = eta.((R^T e3) x chi)).

Every method below keeps the paper's state and indexing, and reports hpgen's node momentum
p_k (the left-trivialized derivative of the action sum's terms in g_k, docs/numerics.md sec. 4). The
paper's multiplier mu_k is a different quantity in each method:

Stormer-Verlet (tableau [[0, 0], [1/2, 1/2]], b = (1/2, 1/2)). State (g_k, mu_k, xi_k) with
  xi_k = tau^{-1}(g_{k-1}^{-1} g_k)/h the previous step's increment: eq. sv3 needs
  (dtau^{-1}_{-h xi_k})^* mu_k, i.e. mu_k alone does not determine the step. That combination
  is the node momentum,
      p_k = (dtau^{-1}_{-h xi_k})^* mu_k,
  because g_k enters the previous step's term of the action only through
  <mu_k, tau^{-1}(g_{k-1}^{-1} g_k)/h> (the stage G^2 = g_k is an independent variable).
  Any (mu_0, xi_0) with this p_0 gives the same trajectory (checked in the tests).
  The Lagrangian is separable, so (paper: "one does not need to eliminate g_{k+1} in sv2")
  sv1, sv2 give Xi^1 = Xi^2 = I^{-1} M^{1/2} and sv3 is solved for M^{1/2} alone.

Forward Euler (tableau [[0]], b = 1; action h [l(g_k, xi_k) + <mu_k, tau^{-1}(g_k^{-1} g_{k+1})/h
  - xi_k>]). Here xi_k, mu_k = dl/dxi(g_k, xi_k) belong to the step that STARTS at g_k, and
      p_{k+1} = (dtau^{-1}_{-h xi_k})^* mu_k      (explicit, after the step),
      p_k = (dtau^{-1}_{h xi_k})^* mu_k - h g_k dl/dg(g_k, xi_k)   (the scheme's implicit eq.).

Backward Euler (tableau [[1]], b = 1; action h [l(g_{k+1}, xi_{k+1}) + <mu_{k+1}, ... - xi_{k+1}>]).
  xi_k, mu_k = dl/dxi(g_k, xi_k) belong to the step that ENDS at g_k, and
      p_k = (dtau^{-1}_{-h xi_k})^* mu_k + h g_k dl/dg(g_k, xi_k).

Starting from hpgen's (g_0, p_0), each method first solves for its own initial (mu_0, xi_0).
"""
from __future__ import annotations

import numpy as np

from .lie import TAU, cross, mv, newton, solve_vec, tr

E3 = np.array([0.0, 0.0, 1.0])


class HeavyTop:
    """l(R, Omega) = 1/2 Omega.I Omega - Mg chi.(R^T e3)."""

    def __init__(self, inertia=(1.0, 5.0, 6.0), Mg=1.0, chi=(0.0, 0.0, 1.0)):
        I = np.asarray(inertia, dtype=float)
        self.I = np.diag(I) if I.ndim == 1 else I
        self.Iinv = np.linalg.inv(self.I)
        self.Mg, self.chi = float(Mg), np.asarray(chi, dtype=float)

    def legendre(self, g, xi):
        """dl/dxi (g, xi)."""
        return mv(self.I, xi)

    def velocity(self, g, mu):
        return mv(self.Iinv, mu)

    def force(self, g, xi):
        """g dl/dg (g, xi) = Mg (R^T e3) x chi."""
        return self.Mg * cross(tr(g) @ E3, self.chi)

    def energy(self, g, p):
        xi = self.velocity(g, p)
        return 0.5 * np.sum(xi * mv(self.I, xi), axis=-1) + self.Mg * ((tr(g) @ E3) @ self.chi)


class _Method:
    def __init__(self, problem, tau, h):
        self.P, self.h = problem, float(h)
        self.tau_name = tau
        self.tau, self.dtau_inv, self.dtau = TAU[tau]

    def simulate(self, g0, p0, steps):
        """From hpgen's (g_0, p_0): g (N+1, 3, 3) and node momenta p (N+1, 3). g0 (..., 3, 3),
        p0 (..., 3) may carry a leading axis of independent initial states (then g is
        (N+1, S, 3, 3) and p (N+1, S, 3))."""
        state = self.initial(np.array(g0, dtype=float), np.asarray(p0, dtype=float))
        gs, ps = [state[0]], [self.node_momentum(state)]
        for _ in range(steps):
            state = self.step(state)
            gs.append(state[0])
            ps.append(self.node_momentum(state))
        return np.array(gs), np.array(ps)


class StormerVerlet(_Method):
    """Eqs. sv1-sv5. State (g_k, mu_k, xi_k)."""

    def node_momentum(self, state):
        g, mu, xi = state
        return mv(tr(self.dtau_inv(-self.h * xi)), mu)

    def initial(self, g0, p0, xi0=None):
        """(g_0, mu_0, xi_0) with (dtau^{-1}_{-h xi_0})^* mu_0 = p_0; xi_0 is free (default
        I^{-1} p_0, a plausible previous increment)."""
        xi0 = self.P.velocity(g0, p0) if xi0 is None else np.asarray(xi0, float)
        mu0 = solve_vec(tr(self.dtau_inv(-self.h * xi0)), p0)
        return g0, mu0, xi0

    def step(self, state):
        g, mu, xi = state
        h, P = self.h, self.P
        rhs = mv(tr(self.dtau_inv(-h * xi)), mu) + h / 2 * P.force(g, None)     # eq. sv3, right

        def sv3(M):
            Xi = P.velocity(g, M)              # sv1 = sv2: Xi^1 = Xi^2 (kinetic l_xi, no g)
            return mv(tr(self.dtau_inv(h * Xi)), M) - rhs   # xi_{k+1} = (Xi^1 + Xi^2)/2 = Xi

        M = newton(sv3, mu)
        Xi1 = Xi2 = P.velocity(g, M)
        xi1 = (Xi1 + Xi2) / 2
        g1 = g @ self.tau(h * xi1)                                                 # eq. sv4
        mu1 = M + h / 2 * mv(tr(self.dtau(-h * xi1)), P.force(g1, Xi2))            # eq. sv5
        # the residuals of sv1 and sv2 are zero by construction: M = I Xi^1 = I Xi^2
        return g1, mu1, xi1


class ForwardEuler(_Method):
    """g_{k+1} = g_k tau(h xi_k);
    (dtau^{-1}_{h xi_{k+1}})^* mu_{k+1} = (dtau^{-1}_{-h xi_k})^* mu_k
                                          + h g_{k+1} dl/dg(g_{k+1}, xi_{k+1});
    mu_{k+1} = dl/dxi(g_{k+1}, xi_{k+1}).  State (g_k, mu_k, xi_k), plus the node momentum
    p_k carried along (it is the right-hand side computed in the previous step)."""

    def _solve(self, g, p):
        """xi with (dtau^{-1}_{h xi})^* dl/dxi(g, xi) - h g dl/dg(g, xi) = p."""
        h, P = self.h, self.P

        def F(xi):
            return mv(tr(self.dtau_inv(h * xi)), P.legendre(g, xi)) - h * P.force(g, xi) - p
        return newton(F, P.velocity(g, p))

    def node_momentum(self, state):
        return state[3]

    def initial(self, g0, p0):
        xi0 = self._solve(g0, p0)
        return g0, self.P.legendre(g0, xi0), xi0, p0

    def step(self, state):
        g, mu, xi, _ = state
        g1 = g @ self.tau(self.h * xi)
        p1 = mv(tr(self.dtau_inv(-self.h * xi)), mu)
        xi1 = self._solve(g1, p1)
        return g1, self.P.legendre(g1, xi1), xi1, p1


class BackwardEuler(_Method):
    """g_{k+1} = g_k tau(h xi_{k+1});
    (dtau^{-1}_{h xi_{k+1}})^* mu_{k+1} = (dtau^{-1}_{-h xi_k})^* mu_k + h g_k dl/dg(g_k, xi_k);
    mu_{k+1} = dl/dxi(g_{k+1}, xi_{k+1}).  State (g_k, mu_k, xi_k)."""

    def node_momentum(self, state):
        g, mu, xi = state
        return mv(tr(self.dtau_inv(-self.h * xi)), mu) + self.h * self.P.force(g, xi)

    def initial(self, g0, p0):
        h, P = self.h, self.P

        def F(xi):
            return (mv(tr(self.dtau_inv(-h * xi)), P.legendre(g0, xi)) + h * P.force(g0, xi)
                    - p0)
        xi0 = newton(F, P.velocity(g0, p0))
        return g0, P.legendre(g0, xi0), xi0

    def step(self, state):
        g, mu, xi = state
        h, P = self.h, self.P
        rhs = self.node_momentum(state)

        def F(xi1):
            g1 = g @ self.tau(h * xi1)
            return mv(tr(self.dtau_inv(h * xi1)), P.legendre(g1, xi1)) - rhs
        xi1 = newton(F, xi)
        g1 = g @ self.tau(h * xi1)
        return g1, P.legendre(g1, xi1), xi1


METHODS = {"stormer-verlet": StormerVerlet, "euler-forward": ForwardEuler,
           "euler-backward": BackwardEuler}
