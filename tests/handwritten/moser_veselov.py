"""The Moser-Veselov (MV) discrete rigid body, and which Hamilton-Pontryagin scheme it is.

MV (Moser & Veselov 1991): the rigid body as a constrained system in R^{3x3} with
L(R, R') = 1/2 tr(R' J R'^T), J = tr(I)/2 e - I (J_i = (I_j + I_k - I_i)/2, so that
L = 1/2 Omega.I Omega), discretized by L_d(R_k, R_{k+1}) = 1/(2h) |R_{k+1} - R_k|_J^2
= (tr J - tr(f_k J))/h, f_k = R_k^T R_{k+1} in SO(3). Its discrete Euler-Lagrange equations,
with the node momentum p_k = -left-trivialized D_1 L_d (as in hpgen, docs/numerics.md sec. 4), are

    f_k J - J f_k^T = h hat(p_k)      (solved for f_k in SO(3)),
    hat(p_{k+1}) = f_k^T hat(p_k) f_k  (= (J f_k - f_k^T J)/h),     R_{k+1} = R_k f_k,

the MV equations M_{k+1} = Omega_k^T M_k Omega_k, M_k = Omega_k J - J Omega_k^T in body form
(M = h hat(p), Omega_k = f_k). Here f_k is found by Newton in the exponential chart
f = exp(hat(w)) (complex-step Jacobian), so nothing is borrowed from the schemes compared.

FINDING (derivation; verified to round-off in tests/regression/test_handwritten.py):

An Euler-Poincare VPRK step of hpgen (left-invariant l, rkmk = truncated, any tableau: the
step reduces to eq. dlp) is the discrete Euler-Lagrange map of l_d(f) = h l(tau^{-1}(f)/h).
MV is the DEL map of l_d(f) = (tr J - tr(f J))/h. Writing f = tau(x), x = h xi:

- tau = cay:  f = e + 4/(4 + |x|^2) (x^ + x^2/2), so tr J - tr(f J) = 2 x.I x / (4 + |x|^2):
              l_d^MV = h/2 xi.I xi / (1 + h^2 |xi|^2 / 4)  versus  l_d^cay = h/2 xi.I xi.
- tau = exp:  l_d^MV = h/2 xi.I xi * 2 (1 - cos t)/t^2, t = h |xi|.
- tau = skew: l_d^MV = h/2 xi.I xi * 2 / (1 + sqrt(1 - t^2))
(for exp and skew: tr(tau(x) J) = tr J - c(|x|) x.I x for any tau(x) = e + a X + c X^2).

So MV coincides with NONE of hpgen's catalog schemes for l = 1/2 xi.I xi: its discrete
Lagrangian differs from each Euler-Poincare one (rkmk = truncated, any tableau) by a relative
O(h^2 |xi|^2) (absolute O(h^3)), hence the one-step maps differ by O(h^3) and trajectories on a
fixed interval by O(h^2) (both are order 2). Measured against every catalog combination
(I = (2, 1, 2/3), one random state with |p| = 1, one step from the same (g, p) at
h = 0.1 / 0.05 / 0.025; the T = 2 column is the difference at t = 2 for h = 0.1; ratios when
halving h in brackets; the regression test re-measures five rows over its three states):

    tau   rkmk       tableau(s)                 one step, h = 0.1      at T = 2
    cay   truncated  any (SV, midpoint, ...)    1.0e-3 (8.4, 8.2)      2.4e-2 (4.0)
    exp   truncated  any                        3.4e-4 (8.5, 8.2)      8.2e-3 (4.0)
    skew  truncated  any                        1.1e-3 (8.7, 8.3)      2.5e-2 (4.1)
    cay   exact      euler-backward             1.1e-3 (8.7)           2.5e-2
    cay   exact      stormer-verlet             2.1e-5 (8.3, 8.1)      2.5e-4 (5.5, 4.4)
    cay   exact      midpoint                   5.1e-4 (8.4)           1.2e-2 (4.0)
    any   exact      gauss2, gauss3, lobatto3a3 3.3e-4 (8.5, 8.2)      7.9e-3 (4.0)
    exp   exact      euler-*, SV, midpoint      3.3e-4 - 3.4e-4 (8.5)  8.0e-3 - 8.2e-3 (4.0)
    skew  exact      euler-backward             2.9e-3 (8.1)           7.0e-2 (3.9)
    skew  exact      stormer-verlet             9.9e-4 (8.3)           2.4e-2 (4.0)
    skew  exact      midpoint                   7.5e-6 (34.3, 33.0)    1.8e-4 (16.3, 16.1)

(rkmk = exact with euler-forward is the truncated step, Theta = 0.) The order-4 schemes
(gauss2, gauss3, lobatto3a3 with the exact constraint) all sit at the same distance: that is
MV's own error. The closest catalog scheme is skew + exact RKMK + midpoint, which agrees with
MV to O(h^5) per step and O(h^4) on a fixed interval, but is not MV either.

But MV is EXACTLY:

(a) hpgen's Euler-Poincare Cayley step (tau = cay, rkmk = truncated, any tableau) applied to
    the h-dependent Lagrangian  l_h(xi) = 1/2 xi.I xi / (1 + h^2 |xi|^2 / 4), and
(b) eq. dlp with the "quaternion" chart tau_q(x) = e + sqrt(1 - |x|^2/4) x^ + x^2/2, i.e. the
    rotation by 2 arcsin(|x|/2) about x, x = 2 (vector part of the unit quaternion, q_0 > 0):
    tr J - tr(tau_q(x) J) = x.I x / 2 exactly, so l_d^MV = h l(tau_q^{-1}(f)/h). This chart is
    not in hpgen's catalog. Its inverse is tau_q^{-1}(R) = vee(R - R^T) / sqrt(1 + tr R), and
    its inverse right-trivialized tangent (differentiate along delta = y^ R, R = tau_q(x)):
    dtau_q^{-1}_x(y) = vee(y^ R + R^T y^)/sqrt(1 + tr R)
                       - vee(R - R^T) tr(y^ R) / (2 (1 + tr R)^{3/2}).

MV is also known to be RATTLE applied to the constrained formulation in R^{3x3}
(McLachlan-Scovel); among hpgen's schemes it is a Cayley Euler-Poincare step, but for the
modified Lagrangian l_h, not for l.
"""
from __future__ import annotations

import numpy as np

from .lie import exp_so3, hat, linear_map_matrix, mv, newton, tr, vee


def mass_matrix(inertia):
    I = np.diag(np.asarray(inertia, float))
    return np.trace(I) / 2 * np.eye(3) - I


class MoserVeselov:
    def __init__(self, inertia, h):
        self.I = np.diag(np.asarray(inertia, float))
        self.J = mass_matrix(inertia)
        self.h = float(h)

    def body_step(self, p):
        """f_k in SO(3) with f J - J f^T = h hat(p) (Newton in the exp chart, from the
        first-order guess w = h I^{-1} p)."""
        J, h = self.J, self.h

        def F(w):
            f = exp_so3(w)
            return vee(f @ J - J @ tr(f)) - h * p
        return exp_so3(newton(F, h * mv(np.linalg.inv(self.I), p)))

    def step(self, R, p):
        f = self.body_step(p)
        M1 = tr(f) @ hat(p) @ f                    # M_{k+1} = Omega_k^T M_k Omega_k
        return R @ f, vee(M1)

    def simulate(self, R0, p0, steps):
        R, p = np.array(R0, float), np.array(p0, float)
        Rs, ps = [R], [p]
        for _ in range(steps):
            R, p = self.step(R, p)
            Rs.append(R)
            ps.append(p)
        return np.array(Rs), np.array(ps)

    def discrete_lagrangian(self, f):
        return (np.trace(self.J) - np.trace(f @ self.J)) / self.h


# ---- the quaternion chart and eq. dlp with it ---------------------------------------------------
def tau_q(x):
    """e + sqrt(1 - x.x/4) x^ + x^2/2: rotation by 2 arcsin(|x|/2) about x (|x| <= 2)."""
    X = hat(x)
    a = np.sqrt(1 - np.sum(x * x, axis=-1) / 4)
    return np.eye(3) + a[..., None, None] * X + X @ X / 2


def tau_q_inv(R):
    return vee(R - tr(R)) / np.sqrt(1 + np.trace(R, axis1=-2, axis2=-1))[..., None]


def dtau_q_inv(x):
    """Matrix of y -> dtau_q^{-1}_x(y) (see the module docstring)."""
    R = tau_q(x)
    t = (1 + np.trace(R, axis1=-2, axis2=-1))[..., None]
    v = vee(R - tr(R))

    def f(y):
        YR = hat(y) @ R
        return (vee(YR + tr(R) @ hat(y)) / np.sqrt(t)
                - v * np.trace(YR, axis1=-2, axis2=-1)[..., None] / (2 * t ** 1.5))
    return linear_map_matrix(f, R.dtype, R.shape[:-2])


class QuaternionChartEP:
    """Eq. dlp with tau = tau_q for l = 1/2 xi.I xi, in hpgen's state (g_k, p_k):
    solve (dtau_q^{-1}_{h xi})^* I xi = p_k, g_{k+1} = g_k tau_q(h xi),
    p_{k+1} = (dtau_q^{-1}_{-h xi})^* I xi."""

    def __init__(self, inertia, h):
        self.I = np.diag(np.asarray(inertia, float))
        self.h = float(h)

    def step(self, R, p):
        h, I = self.h, self.I

        def F(xi):
            return mv(tr(dtau_q_inv(h * xi)), mv(I, xi)) - p
        xi = newton(F, mv(np.linalg.inv(I), p))
        return R @ tau_q(h * xi), mv(tr(dtau_q_inv(-h * xi)), mv(I, xi))

    def simulate(self, R0, p0, steps):
        R, p = np.array(R0, float), np.array(p0, float)
        Rs, ps = [R], [p]
        for _ in range(steps):
            R, p = self.step(R, p)
            Rs.append(R)
            ps.append(p)
        return np.array(Rs), np.array(ps)
