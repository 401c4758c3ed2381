"""Classical (flat-space) partitioned Runge-Kutta methods for q' = p, p' = F(q) = -grad V(q),
i.e. l(x, v) = 1/2 |v|^2 - V(x) on R^n (hpgen's group R<n>: g = [[I, x], [0, 1]], xi = v).

- ``stormer_verlet``: the classical velocity Verlet scheme
      p_{1/2} = p_k + h/2 F(q_k),  q_{k+1} = q_k + h p_{1/2},  p_{k+1} = p_{1/2} + h/2 F(q_{k+1}).
- ``lobatto_iiia_iiib3``: the 3-stage Lobatto IIIA-IIIB pair (order 4), IIIA for q, IIIB for p
  (Hairer-Lubich-Wanner, Geometric Numerical Integration, sec. II.2.2):
      Q_i = q_k + h sum_j a_ij P_j,  P_i = p_k + h sum_j abar_ij F(Q_j),
      q_{k+1} = q_k + h sum_j b_j P_j,  p_{k+1} = p_k + h sum_j b_j F(Q_j),
  A = Lobatto IIIA = [[0, 0, 0], [5/24, 1/3, -1/24], [1/6, 2/3, 1/6]],
  Abar = Lobatto IIIB = [[1/6, -1/6, 0], [1/6, 1/3, 0], [1/6, 5/6, 0]], b = (1/6, 2/3, 1/6).

Why these are hpgen's schemes. On R^n, tau(x) = I + x^ for both exp and cay and
dtau^{-1} = dtau = identity, so the VPRK equations of the paper's theorem (eqs. lievprk1 -
lievprk) become, with M^i = dl/dxi = Xi^i and f = g dl/dg = F(x):
      Theta^i = sum_j a_ij Xi^j,  G^i = x_k + h Theta^i,  x_{k+1} = x_k + h sum_j b_j Xi^j,
      M^i = p_k + h sum_j (b_j - b_j a_ji / b_i) F(G^j),   mu_{k+1} = p_k + h sum_j b_j F(G^j),
and the node momentum is p_{k+1} = (dtau^{-1})^* mu_{k+1} = mu_{k+1}: a partitioned RK method
with A for the positions and abar_ij = b_j (1 - a_ji / b_i) for the momenta, the symplectic
partner (b_i abar_ij + b_j a_ji = b_i b_j). For hpgen's "stormer-verlet" tableau (trapezoid,
Lobatto IIIA 2-stage) abar = [[1/2, 0], [1/2, 0]] is Lobatto IIIB 2-stage and the pair is
velocity Verlet; for "lobatto3a3" abar is Lobatto IIIB 3-stage (checked in ``abar``).
The rkmk option is irrelevant on R^n (dtau^{-1} = identity).
"""
from __future__ import annotations

import numpy as np

from .lie import newton

LOBATTO_IIIA3 = np.array([[0.0, 0.0, 0.0], [5 / 24, 1 / 3, -1 / 24], [1 / 6, 2 / 3, 1 / 6]])
LOBATTO_IIIB3 = np.array([[1 / 6, -1 / 6, 0.0], [1 / 6, 1 / 3, 0.0], [1 / 6, 5 / 6, 0.0]])
LOBATTO_B3 = np.array([1 / 6, 2 / 3, 1 / 6])


def abar(A, b):
    """The momentum coefficients of the VPRK pair: abar_ij = b_j (1 - a_ji / b_i)."""
    A, b = np.asarray(A, float), np.asarray(b, float)
    return b[None, :] * (1 - A.T / b[:, None])


# ---- problems ----------------------------------------------------------------------------------
class Kepler:
    """l = 1/2 |v|^2 + 1/|x| on R^2: F(q) = -q / |q|^3."""
    n = 2

    @staticmethod
    def force(q):
        r2 = np.sum(q * q, axis=-1)[..., None]       # q.q (analytic: complex-step safe)
        return -q / (r2 * np.sqrt(r2))

    @staticmethod
    def energy(q, p):
        return 0.5 * np.sum(p * p, axis=-1) - 1 / np.sqrt(np.sum(q * q, axis=-1))


class Pendulum:
    """l = 1/2 v^2 + cos(x) on R^1: F(q) = -sin(q)."""
    n = 1

    @staticmethod
    def force(q):
        return -np.sin(q)

    @staticmethod
    def energy(q, p):
        return 0.5 * np.sum(p * p, axis=-1) - np.cos(q[..., 0])


# ---- methods -----------------------------------------------------------------------------------
def stormer_verlet(problem, q0, p0, h, steps):
    """Velocity Verlet; returns q (N+1, n), p (N+1, n)."""
    q, p = np.array(q0, float), np.array(p0, float)
    qs, ps = [q], [p]
    F = problem.force(q)
    for _ in range(steps):
        p_half = p + h / 2 * F
        q = q + h * p_half
        F = problem.force(q)
        p = p_half + h / 2 * F
        qs.append(q)
        ps.append(p)
    return np.array(qs), np.array(ps)


def lobatto_iiia_iiib3(problem, q0, p0, h, steps, A=LOBATTO_IIIA3, Abar=LOBATTO_IIIB3,
                       b=LOBATTO_B3):
    """The Lobatto IIIA-IIIB pair (any PRK pair (A, Abar, b) in fact); the stage equations are
    solved for the stage positions Q (s x n) by Newton with a complex-step Jacobian, from the
    explicit guess Q_i = q + c_i h p. q0, p0 (..., n) may carry a leading axis of independent
    initial states."""
    A, Abar, b = (np.asarray(a, float) for a in (A, Abar, b))
    s, n = len(b), problem.n
    c = A.sum(axis=1)
    q, p = np.array(q0, float), np.array(p0, float)
    qs, ps = [q], [p]
    for _ in range(steps):
        def residual(Qflat):
            Q = Qflat.reshape(Qflat.shape[:-1] + (s, n))
            FQ = problem.force(Q)                                              # (..., s, n)
            P = p[..., None, :] + h * np.einsum("ij,...jn->...in", Abar, FQ)  # P_i
            Qnew = q[..., None, :] + h * np.einsum("ij,...jn->...in", A, P)   # Q_i
            return (Q - Qnew).reshape(Qflat.shape)
        guess = q[..., None, :] + h * c[:, None] * p[..., None, :]
        Q = newton(residual, guess.reshape(q.shape[:-1] + (s * n,))).reshape(guess.shape)
        FQ = problem.force(Q)
        P = p[..., None, :] + h * np.einsum("ij,...jn->...in", Abar, FQ)
        q = q + h * np.einsum("j,...jn->...n", b, P)
        p = p + h * np.einsum("j,...jn->...n", b, FQ)
        qs.append(q)
        ps.append(p)
    return np.array(qs), np.array(ps)
