"""Euler-Poincare integrators on SO(3) for a left-invariant l(xi) = 1/2 xi.I xi, coded from the
paper's equations (section "Lie Group VPRK Integrators", paragraph "Euler-Poincare
Integrators"): eq. dlp specialised to

- tau = cay:  eq. cayhpvi (written out with the matrices of dcay^{-1}, eq. dcay),
- tau = exp:  eq. exphpvi (dexp^{-1} as the Bernoulli series, eq. dexp),
- tau = skew: eq. skewprojector (the skew-symmetrization projector, tau(x) = x + (x^2+e)^{1/2}).

State and indexing (the paper's). xi_k = tau^{-1}(g_{k-1}^{-1} g_k)/h is the velocity of the
step that ENDS at g_k, and mu_k = dl/dxi(xi_k) = I xi_k is the multiplier of that step (the
paper's mu_k). One step is: given mu_{k-1}, solve the scheme's equation for mu_k (Newton,
complex-step Jacobian), then g_k = g_{k-1} tau(h xi_k).

Relation to hpgen's state (g_k, p_k). The term of the action sum for the step ending at
g_k contains <mu_k, tau^{-1}(g_{k-1}^{-1} g_k)/h>; its left-trivialized derivative in g_k is
the node momentum

    p_k = (dtau^{-1}_{-h xi_k})^* mu_k,

which is exactly the right-hand side ("k-1 side") of eq. dlp written one index later:
eq. dlp reads (dtau^{-1}_{h xi_{k+1}})^* mu_{k+1} = p_k. In eq. cayhpvi the k-1 side is
mu_{k-1} + h/2 ad*_{xi_{k-1}} mu_{k-1} - h^2/4 xi_{k-1}^* mu_{k-1} xi_{k-1}^*, in
eq. skewprojector it is (mu S + S mu)/2 + h/2 ad*_xi mu with S = (h^2 xi^2 + e)^{1/2}.
So a run started from hpgen's (g_0, p_0) first solves p_0 = (dtau^{-1}_{-h xi_0})^* mu_0 for
the paper's mu_0 (xi_0 = I^{-1} mu_0: a virtual previous step), then iterates the scheme;
the momentum compared with hpgen is p_k, never mu_k (mu_k - p_k = O(h), see
``test_node_momentum_is_not_the_papers_multiplier``).

Notation of eq. cayhpvi: mu and xi are identified with matrices of so(3) (hat map), ^* is the
matrix transpose (the dual of dcay^{-1}(x) y = (e - x/2) y (e + x/2) for the trace pairing is
y -> (e - x^*/2) y (e + x^*/2)), so xi^* mu xi^* = hat(xi)^T hat(mu) hat(xi)^T, and
ad*_xi mu = [mu, xi] = hat(mu x xi).
"""
from __future__ import annotations

import numpy as np

from .lie import TAU, adstar, dexp_inv, hat, mv, newton, sqrtm_sym, tr, vee


def _inertia(I):
    I = np.asarray(I, dtype=float)
    return np.diag(I) if I.ndim == 1 else I


class EulerPoincare:
    """Base: l(xi) = 1/2 xi.I xi on SO(3). Subclasses define ``lhs(mu)`` (the k side of the
    scheme's equation, in terms of mu_k) and ``node_momentum(mu)`` (its k-1 side, = p_k)."""
    tau_name = ""

    def __init__(self, inertia, h):
        self.I = _inertia(inertia)
        self.Iinv = np.linalg.inv(self.I)
        self.h = float(h)
        self.tau = TAU[self.tau_name][0]

    def xi(self, mu):
        return mv(self.Iinv, mu)

    def lhs(self, mu):
        raise NotImplementedError

    def node_momentum(self, mu):
        raise NotImplementedError

    def residual(self, mu_new, mu_old):
        """The scheme's equation (LHS at step k minus its k-1 side)."""
        return self.lhs(mu_new) - self.node_momentum(mu_old)

    # ---- stepping ------------------------------------------------------------------------
    def mu_from_node_momentum(self, p):
        """The paper's mu with node_momentum(mu) = p (a virtual previous step)."""
        return newton(lambda m: self.node_momentum(m) - p, p)

    def step(self, g, mu):
        """(g_{k-1}, mu_{k-1}) -> (g_k, mu_k)."""
        p = self.node_momentum(mu)
        mu1 = newton(lambda m: self.lhs(m) - p, mu)
        return g @ self.tau(self.h * self.xi(mu1)), mu1

    def simulate(self, g0, p0, steps):
        """From hpgen's state (g_0, p_0); returns g (N+1, 3, 3), node momenta p (N+1, 3) and
        the paper's multipliers mu (N+1, 3). g0 (..., 3, 3), p0 (..., 3) may carry a leading
        axis of independent initial states (integrated side by side)."""
        g, mu = np.array(g0, dtype=float), self.mu_from_node_momentum(np.asarray(p0, float))
        gs, ps, mus = [g], [self.node_momentum(mu)], [mu]
        for _ in range(steps):
            g, mu = self.step(g, mu)
            gs.append(g)
            ps.append(self.node_momentum(mu))
            mus.append(mu)
        return np.array(gs), np.array(ps), np.array(mus)


class CayleyEP(EulerPoincare):
    """Eq. cayhpvi:
        mu_k = mu_{k-1} + h/2 ad*_{xi_k} mu_k + h/2 ad*_{xi_{k-1}} mu_{k-1}
               + h^2/4 (xi_k^* mu_k xi_k^* - xi_{k-1}^* mu_{k-1} xi_{k-1}^*)
    in matrix form (mu, xi as elements of so(3), ^* = transpose)."""
    tau_name = "cay"

    def _ad_star_mat(self, X, M):
        return M @ X - X @ M            # hat(ad*_xi mu) = hat(mu x xi) = [M, X]

    def lhs(self, mu):
        M, X = hat(mu), hat(self.xi(mu))
        Xs, h = tr(X), self.h
        return vee(M - h / 2 * self._ad_star_mat(X, M) - h**2 / 4 * (Xs @ M @ Xs))

    def node_momentum(self, mu):
        M, X = hat(mu), hat(self.xi(mu))
        Xs, h = tr(X), self.h
        return vee(M + h / 2 * self._ad_star_mat(X, M) - h**2 / 4 * (Xs @ M @ Xs))


class ExpEP(EulerPoincare):
    """Eq. exphpvi: (dexp^{-1}(h xi_k))^* mu_k = (dexp^{-1}(-h xi_{k-1}))^* mu_{k-1}."""
    tau_name = "exp"

    def lhs(self, mu):
        return mv(tr(dexp_inv(self.h * self.xi(mu))), mu)

    def node_momentum(self, mu):
        return mv(tr(dexp_inv(-self.h * self.xi(mu))), mu)


class SkewEP(EulerPoincare):
    """Eq. skewprojector:
        (mu_k S_k + S_k mu_k)/2 = (mu_{k-1} S_{k-1} + S_{k-1} mu_{k-1})/2
                                  + h/2 ad*_{xi_k} mu_k + h/2 ad*_{xi_{k-1}} mu_{k-1},
    S = (h^2 xi^2 + e)^{1/2} (symmetric square root), mu, xi as matrices of so(3); needs
    h |xi| < 1 (the domain of the projector's inverse)."""
    tau_name = "skew"

    def _sym_part(self, mu):
        X = hat(self.h * self.xi(mu))
        S = sqrtm_sym(X @ X + np.eye(3))
        M = hat(mu)
        return vee((M @ S + S @ M) / 2)

    def lhs(self, mu):
        return self._sym_part(mu) - self.h / 2 * adstar(self.xi(mu), mu)

    def node_momentum(self, mu):
        return self._sym_part(mu) + self.h / 2 * adstar(self.xi(mu), mu)


SCHEMES = {"cay": CayleyEP, "exp": ExpEP, "skew": SkewEP}


def dlp_node_momentum(tau_name, inertia, h, mu):
    """(dtau^{-1}_{-h xi})^* mu straight from eq. dlp with the matrices of ``lie`` (used to
    check that each scheme's k-1 side is this node momentum)."""
    Iinv = np.linalg.inv(_inertia(inertia))
    return mv(tr(TAU[tau_name][1](-h * mv(Iinv, mu))), mu)

