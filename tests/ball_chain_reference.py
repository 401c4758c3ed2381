"""Reference solutions for a chain of rigid links joined by ball joints, the first pinned to the
world origin, under gravity -grav e3 (independent of hpgen: Newton-Euler equations with the
joint reactions solved at the acceleration level, integrated by SciPy's DOP853).

Link i: mass m, body inertia J (diagonal, about its centre of mass, the frame origin), joint
points ``top`` (towards the pin) and ``bot`` in body coordinates. Joint 0 joins the world
origin to top of link 0, joint j >= 1 joins bot of link j-1 to top of link j. State per link:
R_i, omega_i (body), x_i, u_i = dx_i/dt (spatial). f_j is the spatial force joint j exerts
on link j at its top (and -f_j on link j-1 at its bottom).
"""
from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp


def hat(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def rotvec(v):
    v = np.asarray(v, dtype=float)
    t = np.linalg.norm(v)
    if t == 0.0:
        return np.eye(3)
    K = hat(v / t)
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


class BallChain:
    def __init__(self, N, m, J, top, bot, grav):
        self.N, self.m, self.grav = N, m, grav
        self.J = np.asarray(J, dtype=float)
        self.top, self.bot = np.asarray(top, float), np.asarray(bot, float)

    def admissible(self, Rs, ws):
        """(x_i, v_i) (v_i = R_i^T dx_i/dt, body frame) putting the links with rotations Rs and
        body angular velocities ws on the constraints and their velocity form."""
        xs, vs, joint, jvel = [], [], np.zeros(3), np.zeros(3)
        for R, w in zip(Rs, ws):
            x = joint - R @ self.top
            u = jvel - R @ np.cross(w, self.top)
            xs.append(x)
            vs.append(R.T @ u)
            joint, jvel = x + R @ self.bot, u + R @ np.cross(w, self.bot)
        return xs, vs

    def _accelerations(self, Rs, ws):
        """(a_i, alpha_i, f_j) from the Newton-Euler equations and the joints' acceleration
        constraints (one dense linear solve)."""
        N, m, J = self.N, self.m, self.J
        n = 9 * N                    # a (3N), alpha (3N), f (3N)
        A, b = np.zeros((n, n)), np.zeros(n)
        ia, ial, jf = (lambda i: 3 * i), (lambda i: 3 * N + 3 * i), (lambda j: 6 * N + 3 * j)
        for i in range(N):
            R, w = Rs[i], ws[i]
            r = slice(ia(i), ia(i) + 3)          # m a_i - f_i + f_{i+1} = -m grav e3
            A[r, ia(i):ia(i) + 3] = m * np.eye(3)
            A[r, jf(i):jf(i) + 3] = -np.eye(3)
            if i + 1 < N:
                A[r, jf(i + 1):jf(i + 1) + 3] = np.eye(3)
            b[r] = [0.0, 0.0, -m * self.grav]
            r = slice(ial(i), ial(i) + 3)        # J alpha - top x R^T f_i + bot x R^T f_{i+1}
            A[r, ial(i):ial(i) + 3] = np.diag(J)
            A[r, jf(i):jf(i) + 3] = -hat(self.top) @ R.T
            if i + 1 < N:
                A[r, jf(i + 1):jf(i + 1) + 3] = hat(self.bot) @ R.T
            b[r] = -np.cross(w, J * w)
        for j in range(N):                       # acceleration of joint j's two points agree
            r = slice(jf(j), jf(j) + 3)
            R, w = Rs[j], ws[j]
            A[r, ia(j):ia(j) + 3] = np.eye(3)
            A[r, ial(j):ial(j) + 3] = -R @ hat(self.top)
            rhs = -R @ np.cross(w, np.cross(w, self.top))
            if j > 0:
                Rp, wp = Rs[j - 1], ws[j - 1]
                A[r, ia(j - 1):ia(j - 1) + 3] = -np.eye(3)
                A[r, ial(j - 1):ial(j - 1) + 3] = Rp @ hat(self.bot)
                rhs += Rp @ np.cross(wp, np.cross(wp, self.bot))
            b[r] = rhs
        s = np.linalg.solve(A, b)
        return s[:3 * N].reshape(N, 3), s[3 * N:6 * N].reshape(N, 3), s[6 * N:].reshape(N, 3)

    def _unpack(self, y):
        N = self.N
        Rs = y[:9 * N].reshape(N, 3, 3)
        ws = y[9 * N:12 * N].reshape(N, 3)
        xs = y[12 * N:15 * N].reshape(N, 3)
        us = y[15 * N:18 * N].reshape(N, 3)
        return Rs, ws, xs, us

    def rhs(self, t, y):
        Rs, ws, xs, us = self._unpack(y)
        a, al, _ = self._accelerations(Rs, ws)
        dR = np.array([R @ hat(w) for R, w in zip(Rs, ws)])
        return np.concatenate([dR.ravel(), al.ravel(), us.ravel(), a.ravel()])

    def solve(self, Rs, ws, times, rtol=1e-13):
        """States at ``times``: a list of (Rs, ws, xs, us, f) per time (f the joint forces)."""
        xs, vs = self.admissible(Rs, ws)
        us = [R @ v for R, v in zip(Rs, vs)]
        y0 = np.concatenate([np.ravel(Rs), np.ravel(ws), np.ravel(xs), np.ravel(us)])
        sol = solve_ivp(self.rhs, (0.0, times[-1]), y0, method="DOP853", rtol=rtol,
                        atol=rtol * 1e-2, t_eval=times)
        assert sol.success, sol.message
        out = []
        for y in sol.y.T:
            Rs_, ws_, xs_, us_ = self._unpack(y)
            f = self._accelerations(Rs_, ws_)[2]
            out.append((Rs_, ws_, xs_, us_, f))
        return out
