"""Independent reference solutions: the continuous equations (docs/numerics.md sec. 9)
    g' = g xi,  mu' = ad*_xi mu + f(g),  mu = dl/dxi = diag(inertia) xi,
hand-coded per problem (no hpgen import), integrated by SciPy's DOP853.

f(g) = g dl/dg is the left-trivialized force: for SO3 a torque (d = 3); for SE3
(xi = (Omega, v), angular first) a torque and a body-frame force (d = 6).
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp


def hat3(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def rotvec(v):
    """Rodrigues' formula, numpy."""
    v = np.asarray(v, float)
    t = np.linalg.norm(v)
    if t == 0.0:
        return np.eye(3)
    K = hat3(v / t)
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


class SO3Problem:
    """l = 1/2 Omega.I Omega - Mg chi.(R^T e3)  (heavy top; Mg = 0: free rigid body)."""
    n, d = 3, 3

    def __init__(self, inertia, Mg=0.0, chi=(0.0, 0.0, 1.0)):
        self.I, self.Mg, self.chi = np.asarray(inertia, float), float(Mg), np.asarray(chi, float)

    def force(self, g):
        return -self.Mg * np.cross(self.chi, g.T @ np.array([0.0, 0.0, 1.0]))

    def rhs(self, t, y):
        g, mu = y[:9].reshape(3, 3), y[9:]
        w = mu / self.I
        return np.concatenate([(g @ hat3(w)).ravel(), np.cross(mu, w) + self.force(g)])

    def energy(self, g, mu):
        return 0.5 * mu @ (mu / self.I) + self.Mg * self.chi @ (g.T @ np.array([0.0, 0.0, 1.0]))


class SE3Problem:
    """l = 1/2 Omega.I Omega + 1/2 v.M v - Mg chi.(R^T e3) - k/2 |x|^2 on SE3.

    Kirchhoff's underwater vehicle for Mg = k = 0; ad*_(Omega, v)(Pi, P) =
    (Pi x Omega + P x v, P x Omega); the force of V(R, x) is (-Mg chi x R^T e3, -k R^T x).
    """
    n, d = 4, 6

    def __init__(self, inertia, mass, Mg=0.0, chi=(0.0, 0.0, 1.0), k=0.0):
        self.I = np.concatenate([np.asarray(inertia, float), np.asarray(mass, float)])
        self.Mg, self.chi, self.k = float(Mg), np.asarray(chi, float), float(k)

    def force(self, g):
        R, x = g[:3, :3], g[:3, 3]
        return np.concatenate([-self.Mg * np.cross(self.chi, R.T @ np.array([0.0, 0.0, 1.0])),
                               -self.k * (R.T @ x)])

    def rhs(self, t, y):
        g, mu = y[:16].reshape(4, 4), y[16:]
        xi = mu / self.I
        W, v, Pi, P = xi[:3], xi[3:], mu[:3], mu[3:]
        X = np.zeros((4, 4))
        X[:3, :3], X[:3, 3] = hat3(W), v
        dmu = np.concatenate([np.cross(Pi, W) + np.cross(P, v), np.cross(P, W)]) + self.force(g)
        return np.concatenate([(g @ X).ravel(), dmu])


def reference(problem, g0, mu0, times, rtol=1e-12):
    """(g(t), mu(t)) at the given times, DOP853 with rtol = atol = ``rtol``."""
    n = problem.n
    y0 = np.concatenate([np.asarray(g0, float).ravel(), np.asarray(mu0, float)])
    times = np.atleast_1d(np.asarray(times, float))
    sol = solve_ivp(problem.rhs, (0.0, times[-1]), y0, method="DOP853", rtol=rtol, atol=rtol,
                    t_eval=times)
    assert sol.success, sol.message
    return sol.y[: n * n].T.reshape(-1, n, n), sol.y[n * n:].T
