"""Exact solution of the free rigid body (Euler's equations) in Jacobi elliptic functions.

Body angular momentum Pi (hpgen's convention, docs/numerics.md sec. 9): Pi' = Pi x Omega,
Omega = Pi / I, I the principal moments (a diagonal inertia). Energy E = 1/2 Pi.Omega and
M^2 = |Pi|^2 are constant. Landau-Lifshitz, Mechanics, par. 37:

1. Sort the axes J1 < J2 < J3 by a signed permutation P with det P = +1 (y = P Pi obeys the
   same equations with the sorted moments, since P is a rotation).
2. If M^2 < 2 E J2 the body turns about the axis of the smallest moment: apply the further
   rotation Q: (y1, y2, y3) -> (y3, -y2, y1), which reverses the order of the moments. The
   formulas below then hold in both cases, "axis 3" being the one the body turns about:

       y1 = a1 cn(u | m),  y2 = a2 sn(u | m),  y3 = s3 a3 dn(u | m),  u = u0 + lam t,

   with A = M^2 - 2 E J1, B = 2 E J3 - M^2, D = M^2 - 2 E J2 written as sums of squares of
   y (no cancellation besides D's own, which is the data's):
       a1^2 = J1 B / (J3 - J1),  a2^2 = J2 B / (J3 - J2),  a3^2 = J3 A / (J3 - J1),
       lam = s3 sign(J3 - J1) sqrt(A (J3 - J2) / (J1 J2 J3)),  s3 = sign(y3(0)),
       m = k^2 = (J2 - J1) B / ((J3 - J2) A),  1 - m = (J3 - J1) D / ((J3 - J2) A).
   u0 = F(phi0 | m) (incomplete elliptic integral of the first kind) with
   phi0 = am(u0) = atan2(y2(0) / a2, y1(0) / a1).
3. Near the separatrix (1 - m small) SciPy's ``ellipj`` / ``ellipkinc`` take m, not 1 - m,
   and lose the information in 1 - m (3e-8 measured at 1 - m = 2.7e-8). There every
   parameter (A, B, D, 1 - m, m = 1 - (1 - m), the amplitudes, lam, u0) is recomputed by
   mpmath at 40 digits from the exact binary inputs (the solution is very sensitive to
   1 - m there, and D cancels) and sn, cn, dn are evaluated by mpmath (about 1 ms per
   time). Measured at 1 - m = 5.4e-8 over a half period through the saddle: identical
   doubles to mpmath's 20-digit Taylor ODE solution; SciPy's functions are off by 3e-10
   to 1e-9 there.

The attitude (``free_rigid_body_attitude``) follows from Pi(t): in a spatial frame whose e3
is along the (constant) spatial momentum m = R Pi, R = Rz(phi) Rx(theta) Rz(psi) (Euler
angles of the body frame y), with cos theta = y3 / M, tan psi = y1 / y2, and the precession
rate phi' = M (y1 Omega1 + y2 Omega2) / (y1^2 + y2^2) (Landau-Lifshitz eq. 37.16) integrated
by 20-point Gauss-Legendre quadrature on panels of at most 1/4 in u (the integrand is
analytic; the panels resolve it to round-off).
"""
from __future__ import annotations

import numpy as np
from scipy import special

#: below this 1 - k^2 the elliptic functions are evaluated by mpmath (see module docstring);
#: measured over t in [0, 60] (I = (2, 1, 2/3)): SciPy against mpmath 6e-15 at 1 - k^2 =
#: 4e-2, 3.6e-14 at 4e-3, 2.3e-13 at 4e-4, 2.6e-11 at 4e-6, 2.2e-9 at 4e-8
MPMATH_BELOW = 1e-2
MP_DPS = 40

_Q = np.array([[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], [1.0, 0.0, 0.0]])


def _rz(a):
    c, s = np.cos(a), np.sin(a)
    out = np.zeros(np.shape(a) + (3, 3))
    out[..., 0, 0], out[..., 0, 1], out[..., 1, 0], out[..., 1, 1] = c, -s, s, c
    out[..., 2, 2] = 1.0
    return out


def _rx(a):
    c, s = np.cos(a), np.sin(a)
    out = np.zeros(np.shape(a) + (3, 3))
    out[..., 1, 1], out[..., 1, 2], out[..., 2, 1], out[..., 2, 2] = c, -s, s, c
    out[..., 0, 0] = 1.0
    return out


def _sums(y, J, num):
    """(A, B, D) = (M^2 - 2 E J1, 2 E J3 - M^2, M^2 - 2 E J2) as sums over the axes, in the
    number type ``num`` (float or mpmath.mpf): only D has terms of both signs."""
    y, J = [num(v) for v in y], [num(v) for v in J]
    A = y[1] ** 2 * ((J[1] - J[0]) / J[1]) + y[2] ** 2 * ((J[2] - J[0]) / J[2])
    B = y[0] ** 2 * ((J[2] - J[0]) / J[0]) + y[1] ** 2 * ((J[2] - J[1]) / J[1])
    D = y[0] ** 2 * ((J[0] - J[1]) / J[0]) + y[2] ** 2 * ((J[2] - J[1]) / J[2])
    return A, B, D


def _parameters(y, J, num, sqrt, atan2):
    """(m, 1 - m, amplitudes (a3 signed), lam, am(u0)) in the number type ``num``."""
    A, B, D = _sums(y, J, num)
    y, (J1, J2, J3) = [num(v) for v in y], [num(v) for v in J]
    m = (J2 - J1) * B / ((J3 - J2) * A)
    m1 = (J3 - J1) * D / ((J3 - J2) * A)
    s3 = 1 if y[2] > 0 else -1
    a = [sqrt(J1 * B / (J3 - J1)), sqrt(J2 * B / (J3 - J2)), s3 * sqrt(J3 * A / (J3 - J1))]
    lam = s3 * (1 if J3 > J1 else -1) * sqrt(A * (J3 - J2) / (J1 * J2 * J3))
    phi0 = atan2(y[1] / a[1], y[0] / a[0])
    return m, m1, a, lam, phi0

class FreeRigidBody:
    """The exact motion from body momentum ``pi0`` with principal moments ``inertia``.

    Attributes: P (the rotation y = P Pi to the frame of the formulas), J (moments in that
    frame), m, m1 = 1 - m, lam, u0, a (amplitudes, a[2] signed), steady (Pi constant),
    method ('scipy' or 'mpmath').
    """

    def __init__(self, inertia, pi0, method="auto"):
        I = np.asarray(inertia, dtype=float).reshape(3)
        pi0 = np.asarray(pi0, dtype=float).reshape(3)
        if not (np.all(np.isfinite(I)) and np.all(I > 0) and np.all(np.isfinite(pi0))):
            raise ValueError("inertia must be 3 positive numbers and pi0 3 finite numbers")
        if method not in ("auto", "scipy", "mpmath"):
            raise ValueError(f"method must be auto, scipy or mpmath, got {method!r}")
        import mpmath
        self.inertia, self.pi0 = I, pi0
        order = np.argsort(I, kind="stable")
        P = np.zeros((3, 3))
        P[np.arange(3), order] = 1.0
        if np.linalg.det(P) < 0:
            P[1] *= -1.0
        J, y = I[order], P @ pi0        # exact: P is a signed permutation
        with mpmath.workdps(MP_DPS):    # the sign of D decides the case: no rounding there
            D = _sums(y, J, mpmath.mpf)[2]
        if D < 0:                       # M^2 < 2 E J2: turn about the smallest moment's axis
            P, J, y = _Q @ P, J[::-1].copy(), _Q @ y
        self.P, self.J, self.y0 = P, J, y
        self.M = float(np.sqrt(y @ y))
        A, B, D = _sums(y, J, float)
        self.steady = (A == 0.0 or B == 0.0 or J[2] == J[1] or J[2] == J[0]
                       or (y[0] == 0.0 and y[2] == 0.0))
        self.method = "scipy"
        if self.steady:                 # Pi along a principal axis (or a degenerate plane)
            return
        m, m1, a, lam, phi0 = _parameters(y, J, float, np.sqrt, np.arctan2)
        self.m, self.m1, self.a, self.lam = float(m), float(m1), np.array(a, float), float(lam)
        if method == "mpmath" or (method == "auto" and self.m1 < MPMATH_BELOW):
            # every parameter again at MP_DPS digits from the (exact) binary inputs: near the
            # separatrix the solution is very sensitive to m1, and m1 = 1 - k^2 computed in
            # double carries a rounding error of ~1e-16 / m1 relative (D cancels)
            self.method = "mpmath"
            with mpmath.workdps(MP_DPS):
                m, m1, a, lam, phi0 = _parameters(y, J, mpmath.mpf, mpmath.sqrt, mpmath.atan2)
                self._mp = (1 - m1, a, lam, mpmath.ellipf(phi0, 1 - m1))
                self.u0 = float(self._mp[3])
        else:
            self.u0 = float(special.ellipkinc(float(phi0), self.m))

    def _y(self, t):
        """y(t) in the frame of the formulas, shape t.shape + (3,)."""
        t = np.asarray(t, dtype=float)
        if self.steady:
            return np.broadcast_to(self.y0, t.shape + (3,)).copy()
        if self.method == "scipy":
            sn, cn, dn, _ = special.ellipj(self.u0 + self.lam * t, self.m)
            return np.stack([self.a[0] * cn, self.a[1] * sn, self.a[2] * dn], axis=-1)
        import mpmath
        out = np.empty(t.shape + (3,))
        with mpmath.workdps(MP_DPS):
            m, a, lam, u0 = self._mp
            for idx, tk in np.ndenumerate(t):
                u = u0 + lam * mpmath.mpf(float(tk))
                sn, cn, dn = (mpmath.ellipfun(kind, u, m=m) for kind in ("sn", "cn", "dn"))
                out[idx] = (float(a[0] * cn), float(a[1] * sn), float(a[2] * dn))
        return out

    # ---- public -----------------------------------------------------------------------------
    def momentum(self, t):
        """Body angular momentum Pi(t), shape t.shape + (3,)."""
        return self._y(t) @ self.P        # Pi = P^T y, row-wise

    def _phidot(self, t):
        y = self._y(t)
        w = y / self.J
        return self.M * (y[..., 0] * w[..., 0] + y[..., 1] * w[..., 1]) / (
            y[..., 0] ** 2 + y[..., 1] ** 2)

    def attitude(self, R0, t):
        """(R(t), Pi(t)): rotation matrices (len(t), 3, 3) from R(0) = R0, and Pi(t)."""
        R0 = np.asarray(R0, dtype=float).reshape(3, 3)
        t = np.atleast_1d(np.asarray(t, dtype=float))
        if t.ndim != 1:
            raise ValueError("t must be a 1-d array of times")
        Pi = self.momentum(t)
        if self.M == 0.0:
            return np.broadcast_to(R0, (len(t), 3, 3)).copy(), Pi
        w = R0 @ self.pi0 / self.M                  # unit spatial momentum
        e = np.eye(3)[int(np.argmin(np.abs(w)))]
        u = e - (e @ w) * w
        u /= np.linalg.norm(u)
        S = np.stack([u, np.cross(w, u), w])        # rotation with S m = M e3
        if self.steady:                            # uniform rotation about m
            rate = 2.0 * (0.5 * self.pi0 @ (self.pi0 / self.inertia)) / self.M
            return np.einsum("ij,kjl,lm->kim", S.T, _rz(rate * t), S @ R0), Pi
        y = Pi @ self.P.T
        theta = np.arccos(np.clip(y[:, 2] / self.M, -1.0, 1.0))
        psi = np.arctan2(y[:, 0], y[:, 1])
        B0 = S @ R0 @ self.P.T
        y0 = self.pi0 @ self.P.T                   # the angles at t = 0 (t need not start at 0)
        theta0 = np.arccos(np.clip(y0[2] / self.M, -1.0, 1.0))
        C = B0 @ (_rx(theta0) @ _rz(np.arctan2(y0[0], y0[1]))).T
        phi0 = np.arctan2(C[1, 0], C[0, 0])
        phi = phi0 + self._integrate_phidot(t)
        B = _rz(phi) @ _rx(theta) @ _rz(psi)
        return np.einsum("ij,kjl,lm->kim", S.T, B, self.P), Pi

    def _integrate_phidot(self, t):
        """int_0^t phi' ds for each t (Gauss-Legendre, panels <= 1/4 in u)."""
        x, wts = np.polynomial.legendre.leggauss(20)
        panel = 0.25 / abs(self.lam)
        out = np.zeros(len(t))
        for sign in (1.0, -1.0):        # t >= 0 forwards from 0, t < 0 backwards from 0
            sel = np.nonzero(t >= 0)[0] if sign > 0 else np.nonzero(t < 0)[0]
            acc, prev = 0.0, 0.0
            for idx in sel[np.argsort(np.abs(t[sel]), kind="stable")]:
                tk = t[idx]
                n = max(1, int(np.ceil(abs(tk - prev) / panel)))
                edges = np.linspace(prev, tk, n + 1)
                mid, half = 0.5 * (edges[1:] + edges[:-1]), 0.5 * (edges[1:] - edges[:-1])
                nodes = mid[:, None] + half[:, None] * x[None, :]
                acc += float(np.sum(half[:, None] * wts[None, :] * self._phidot(nodes)))
                out[idx], prev = acc, tk
        return out

def free_rigid_body_momentum(inertia, pi0, t, method="auto"):
    """Exact body angular momentum Pi(t) of the free rigid body, shape (len(t), 3).

    inertia: the 3 principal moments (any order; a diagonal inertia tensor); pi0 = Pi(0);
    t: times (1-d). Pi' = Pi x (Pi / inertia). method: 'auto' (SciPy, mpmath for
    1 - k^2 < MPMATH_BELOW), 'scipy' or 'mpmath'.
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    return FreeRigidBody(inertia, pi0, method).momentum(t).reshape(len(t), 3)


def free_rigid_body_attitude(inertia, pi0, R0, t, method="auto"):
    """Exact (R(t), Pi(t)) of the free rigid body with R' = R Omega^, R(0) = R0:
    shapes (len(t), 3, 3) and (len(t), 3)."""
    return FreeRigidBody(inertia, pi0, method).attitude(R0, t)
