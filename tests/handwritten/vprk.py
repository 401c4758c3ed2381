"""The general s-stage Lie group VPRK method of the paper's theorem (eqs. lievprk1 - lievprk,
the paper's q = 0), for a Lagrangian whose Legendre transform does not depend on g
(dl/dxi(g, xi) = I xi, e.g. the heavy top of ``heavy_top``), with any tableau (A, b), b_j != 0:

    Theta^i = sum_j a_ij Xi^j,  xi_{k+1} = sum_j b_j Xi^j,  G^i = g_k tau(h Theta^i),
    (dtau^{-1}_{h xi_{k+1}})^* M^i = (dtau^{-1}_{-h xi_k})^* mu_k
        + h sum_j ( b_j (dtau^{-1}_{h Theta^j})^* - (b_j a_ji / b_i) (dtau^{-1}_{h xi_{k+1}})^* )
                  (dtau_{-h Theta^j})^* G^j dl/dg(G^j, Xi^j),
    (dtau^{-1}_{h xi_{k+1}})^* mu_{k+1} = (dtau^{-1}_{-h xi_k})^* mu_k
        + h sum_j b_j (dtau^{-1}_{h Theta^j})^* (dtau_{-h Theta^j})^* G^j dl/dg(G^j, Xi^j),
    M^i = dl/dxi(G^i, Xi^i),     g_{k+1} = g_k tau(h xi_{k+1}).

As in ``heavy_top`` the state is hpgen's node momentum p_k = (dtau^{-1}_{-h xi_k})^* mu_k (the
paper's right-hand side), so the step is: solve the s stage equations for Xi^1..Xi^s (Newton,
complex-step Jacobian, through tau and the stage forces), then mu_{k+1} from the second
equation and p_{k+1} = (dtau^{-1}_{-h xi_{k+1}})^* mu_{k+1}.
"""
from __future__ import annotations

import numpy as np

from .lie import TAU, mv, newton, solve_vec, tr


class VPRK:
    def __init__(self, problem, A, b, tau, h):
        self.P, self.h = problem, float(h)
        self.A, self.b = np.asarray(A, float), np.asarray(b, float)
        self.s = len(self.b)
        self.tau, self.dtau_inv, self.dtau = TAU[tau]
        # C[i, j] = b_j a_ji / b_i
        self.C = self.b[None, :] * self.A.T / self.b[:, None]

    def _stages(self, g, X):
        """Theta (..., s, 3), xi_{k+1}, and per stage (dtau_{-h Theta^j})^* f_j and
        (dtau^{-1}_{h Theta^j})^* (dtau_{-h Theta^j})^* f_j."""
        h = self.h
        Th = np.einsum("ij,...jd->...id", self.A, X)
        xi = np.einsum("j,...jd->...d", self.b, X)
        G = g[..., None, :, :] @ self.tau(h * Th)
        f = self.P.force(G, X)
        D = mv(tr(self.dtau(-h * Th)), f)
        F = mv(tr(self.dtau_inv(h * Th)), D)
        return xi, D, F

    def step(self, g, p):
        h, s = self.h, self.s

        def residual(Xf):
            X = Xf.reshape(Xf.shape[:-1] + (s, 3))
            xi, D, F = self._stages(g, X)
            Dxi = tr(self.dtau_inv(h * xi))[..., None, :, :]
            M = self.P.legendre(None, X)
            rhs = (p[..., None, :] + h * np.einsum("j,...jd->...d", self.b, F)[..., None, :]
                   - h * mv(Dxi, np.einsum("ij,...jd->...id", self.C, D)))
            return (mv(Dxi, M) - rhs).reshape(Xf.shape)

        X0 = np.repeat(self.P.velocity(g, p)[..., None, :], s, axis=-2)
        X = newton(residual, X0.reshape(p.shape[:-1] + (3 * s,))).reshape(X0.shape)
        xi, D, F = self._stages(g, X)
        mu1 = solve_vec(tr(self.dtau_inv(h * xi)), p + h * np.einsum("j,...jd->...d", self.b, F))
        return g @ self.tau(h * xi), mv(tr(self.dtau_inv(-h * xi)), mu1)

    def simulate(self, g0, p0, steps):
        g, p = np.array(g0, float), np.array(p0, float)
        gs, ps = [g], [p]
        for _ in range(steps):
            g, p = self.step(g, p)
            gs.append(g)
            ps.append(p)
        return np.array(gs), np.array(ps)
