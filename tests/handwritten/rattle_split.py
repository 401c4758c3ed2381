"""RATTLE with the exact free flow of a symmetric body (McLachlan, Modin, Verdier, Wilkins,
Found. Comput. Math. 2014) on the N-link capsule chain, coded by hand (NumPy only; after the
session's prototype /work/brief/rattle.py): the reference of hpgen's constrained ``split2``.

Chain (examples/capsule_chain.yaml's physics): link i has its centre x_i (world), rotation
R_i, mass m, principal moments J = (Ia, Ia, Ic) about the centre; its top is x_i + R_i a,
its bottom x_i - R_i a (a in the link frame). Joint 0 pins the top of link 0 to the origin,
joint i >= 1 joins the top of link i to the bottom of link i-1:
    phi_0 = x_0 + R_0 a,   phi_i = x_i + R_i a - x_{i-1} + R_{i-1} a.
State: (x, P, R, pi), P the world momentum m v, pi = J omega the body angular momentum.

One step of size h (L_i the joint impulses, world frame; a world impulse L at the point
R r of a body gives dP = L, dpi = r x R^T L):
    P <- P + h/2 F (gravity F = -m g e3)
    (P, pi) <- (P, pi) + impulse(R; L),  L such that the free flow below ends on phi = 0
    free flow over h: x <- x + h P / m; R <- R exp(h pi^ / Ia) exp(h (1/Ic - 1/Ia) pi_3 e3^),
      pi <- rotated by the second factor (exact for a symmetric body)
    P <- P + h/2 F
    (P, pi) <- (P, pi) + impulse(R_1; L'),  L' linear: the joints' velocities vanish.
Newton on L with the linear response of phi at the step's start (a chord; run to 1e-15).
"""
from __future__ import annotations

import numpy as np


def _hat(w):
    K = np.zeros(w.shape[:-1] + (3, 3))
    K[..., 0, 1], K[..., 0, 2], K[..., 1, 2] = -w[..., 2], w[..., 1], -w[..., 0]
    K[..., 1, 0], K[..., 2, 0], K[..., 2, 1] = w[..., 2], -w[..., 1], w[..., 0]
    return K


def expm_so3(w):
    """exp(w^) for rows w (n, 3), Rodrigues' formula."""
    th = np.linalg.norm(w, axis=1)
    safe = np.where(th > 1e-8, th, 1.0)
    s = np.where(th > 1e-8, np.sin(th) / safe, 1 - th ** 2 / 6)
    c = np.where(th > 1e-8, (1 - np.cos(th)) / safe ** 2, 0.5 - th ** 2 / 24)
    K = _hat(w)
    return np.eye(3) + s[:, None, None] * K + c[:, None, None] * (K @ K)


class Chain:
    """The chain's constants: n links, mass m, moments J (Ia, Ia, Ic), top point a, g."""

    def __init__(self, n, m, J, a, grav):
        self.n, self.m, self.J = n, float(m), np.asarray(J, float)
        self.a, self.grav = np.asarray(a, float), float(grav)

    def free(self, x, P, R, pi, t):
        Ia, Ic = self.J[0], self.J[2]
        x = x + t * P / self.m
        R = R @ expm_so3(t * pi / Ia)
        w3 = np.zeros_like(pi)
        w3[:, 2] = t * (1 / Ic - 1 / Ia) * pi[:, 2]
        Q = expm_so3(w3)
        return x, R @ Q, np.einsum("nji,nj->ni", Q, pi)

    def impulse(self, R, L):
        Ln = np.vstack([L[1:], np.zeros((1, 3))])
        return L - Ln, np.cross(self.a, np.einsum("nji,nj->ni", R, L + Ln))

    def phi(self, x, R):
        top, bot = x + R @ self.a, x - R @ self.a
        return np.vstack([top[:1], top[1:] - bot[:-1]])

    def dphi(self, P, R, pi):
        w = np.einsum("nij,nj->ni", R, pi / self.J)
        r, v = R @ self.a, P / self.m
        top, bot = v + np.cross(w, r), v - np.cross(w, r)
        return np.vstack([top[:1], top[1:] - bot[:-1]])

    def response(self, R, t):
        """d phi / d L (3n x 3n) at fixed R for a drift of time t (t = 1: the velocities)."""
        n, a = self.n, self.a
        A = _hat(a)
        Jac = np.zeros((3 * n, 3 * n))
        for k in range(n):
            for b, s in [(k, 1.0)] + ([(k - 1, -1.0)] if k > 0 else []):
                for j, sj in ((b, 1.0), (b + 1, -1.0)):
                    if j < n:
                        blk = s * sj * (t / self.m) * np.eye(3) \
                            - R[b] @ A @ np.diag(t / self.J) @ A @ R[b].T
                        Jac[3 * k:3 * k + 3, 3 * j:3 * j + 3] += blk
        return Jac

    def step(self, x, P, R, pi, h, tol=1e-15, maxit=60):
        n = self.n
        F = np.zeros((n, 3))
        F[:, 2] = -self.m * self.grav
        P = P + 0.5 * h * F
        L = np.zeros((n, 3))
        Jm = self.response(R, h)
        for _ in range(maxit):
            dP, dpi = self.impulse(R, L)
            x1, R1, pi1 = self.free(x, P + dP, R, pi + dpi, h)
            P1 = P + dP
            r = self.phi(x1, R1).ravel()
            if np.abs(r).max() < tol:
                break
            L = L - np.linalg.solve(Jm, r).reshape(n, 3)
        P1 = P1 + 0.5 * h * F
        L2 = -np.linalg.solve(self.response(R1, 1.0),
                              self.dphi(P1, R1, pi1).ravel()).reshape(n, 3)
        dP, dpi = self.impulse(R1, L2)
        return x1, P1 + dP, R1, pi1 + dpi
