"""so(3) tools, the maps tau of the paper and their trivialized tangents, and a Newton solver.

Everything is written from the paper's formulas (section "Lie Group VPRK Integrators"),
not from the closed forms specific to SO(3) that hpgen uses (``hpgen/groups/maps.py``):

- hat: R^3 -> so(3), hat(w) y = w x y; vee its inverse. The pairing of g* with g is the dot
  product of vectors (equivalently <M, X> = tr(M^T X) / 2 for M = hat(mu), X = hat(xi)).
- ad_x y = [x, y] = x x y, so ad_x is the matrix hat(x); ad*_x mu = mu x x
  (docs/numerics.md sec. 1).
- cay(x) = (e - x/2)^{-1} (e + x/2)                                   (eq. cay)
  dcay^{-1}(x) y = (e - x/2) y (e + x/2),
  dcay(x) y = (e - x/2)^{-1} y (e + x/2)^{-1}                          (eq. dcay)
- exp: Rodrigues' formula; dexp(x) y = sum_j ad_x^j y / (j+1)!,
  dexp^{-1}(x) y = sum_j B_j / j! ad_x^j y (Bernoulli numbers, B_1 = -1/2)   (eq. dexp)
- skew: tau(x) = x + (x^2 + e)^{1/2} (symmetric square root, theorem of Cardoso-Leite; here
  computed by Newton's iteration for the matrix square root), and
  dskew(x)(y) = (y tau(x) - (y tau(x))^*)/2 (eq. dskew), which is the INVERSE right-trivialized
  tangent dtau^{-1}_x of tau = skew^{-1} (Definition def:dtauinverse:
  D tau^{-1}(g) . delta = dtau^{-1}_x(delta tau(x)^{-1})). Its inverse (dtau_x) is the matrix
  inverse.

A "d x d matrix of a linear map" is built column by column on the basis e_1, e_2, e_3. The
duals (.)^* of the paper are matrix transposes (``tr``, never the conjugate transpose).

Every function accepts complex arguments (for complex-step differentiation: analytic
operations only, no abs/conj on the data path) and leading batch axes: vectors are (..., 3),
matrices (..., 3, 3), so that the complex-step Jacobian of a residual costs one vectorized
evaluation (``cs_eval``), and several initial states can be integrated side by side (the
schemes take states with a leading axis; each state has its own Newton system).
"""
from __future__ import annotations

from fractions import Fraction
from math import comb, factorial

import numpy as np

I3 = np.eye(3)
_E = np.eye(3)


# ---- batched linear algebra helpers -------------------------------------------------------------
def tr(A):
    """Matrix transpose of the last two axes (the paper's ^* for matrices and linear maps)."""
    return np.swapaxes(A, -1, -2)


def mv(A, v):
    """Matrix-vector product over the last axes, batched."""
    return np.einsum("...ij,...j->...i", A, v)


# ---- so(3) -------------------------------------------------------------------------------------
def hat(w):
    w = np.asarray(w)
    W = np.zeros(w.shape[:-1] + (3, 3), dtype=w.dtype)
    W[..., 0, 1], W[..., 0, 2] = -w[..., 2], w[..., 1]
    W[..., 1, 0], W[..., 1, 2] = w[..., 2], -w[..., 0]
    W[..., 2, 0], W[..., 2, 1] = -w[..., 1], w[..., 0]
    return W


def vee(W):
    return np.stack([W[..., 2, 1], W[..., 0, 2], W[..., 1, 0]], axis=-1)


def ad(x):
    """Matrix of y -> ad_x y = [x, y] on so(3) in vector form."""
    return hat(x)


def cross(a, b):
    """a x b over the last axis (explicit: numpy.cross is slow for tiny arrays)."""
    return np.stack([a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
                     a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
                     a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]], axis=-1)


def adstar(x, mu):
    """ad*_x mu = mu x x, from <ad*_x mu, y> = <mu, x x y>."""
    return cross(mu, x)


def linear_map_matrix(f, dtype=float, batch=()):
    """Matrix (..., 3, 3) of a linear map f on R^3 (f applied to the basis vectors)."""
    return np.stack([f(np.broadcast_to(_E[j].astype(dtype), batch + (3,))) for j in range(3)],
                    axis=-1)


# ---- Bernoulli numbers ---------------------------------------------------------------------------
def bernoulli(n: int) -> list[Fraction]:
    """B_0..B_n with B_1 = -1/2 (sum_{k=0}^{m} C(m+1, k) B_k = 0 for m >= 1)."""
    B = [Fraction(1)]
    for m in range(1, n + 1):
        B.append(-sum(comb(m + 1, k) * B[k] for k in range(m)) / (m + 1))
    return B


_NSERIES = 40
_BJ = [float(b / factorial(j)) for j, b in enumerate(bernoulli(_NSERIES))]
_INVFACT1 = [1.0 / factorial(j + 1) for j in range(_NSERIES + 1)]


def _ad_series(x, coeffs, bound):
    """sum_j coeffs[j] ad_x^j, summed until the tail bound(j, |ad_x|) is below 1e-18 (at most
    len(coeffs) terms). ad_x is a real skew matrix (normal), so its spectral norm is |x|; the
    largest |Re x| of the batch is used (the complex-step parts are O(1e-40))."""
    A = ad(x)
    a = float(np.sqrt(np.max(np.sum(x.real * x.real, axis=-1))))
    nterms = next((j for j in range(1, len(coeffs)) if bound(j, a) < 1e-18), len(coeffs))
    out = coeffs[0] * np.broadcast_to(I3, A.shape).astype(A.dtype)
    P = A
    for j in range(1, nterms):
        if coeffs[j] != 0.0:
            out = out + coeffs[j] * P
        if j + 1 < nterms:
            P = P @ A
    return out


# ---- tau = exp -----------------------------------------------------------------------------------
def exp_so3(x):
    """exp(hat(x)), Rodrigues: I + (sin t / t) X + ((1 - cos t) / t^2) X^2, t^2 = x.x
    (Taylor series of both coefficients below t^2 = 1e-6, the exact branch evaluated at a safe
    argument; analytic in x, so complex-step safe)."""
    X = hat(x)
    t2 = np.sum(x * x, axis=-1)            # x.x, not |x|^2: analytic
    small = np.abs(t2.real) < 1e-6
    ts = np.sqrt(np.where(small, 1.0, t2))
    a = np.where(small, 1 - t2 / 6 + t2**2 / 120 - t2**3 / 5040 + t2**4 / 362880,
                 np.sin(ts) / ts)
    b = np.where(small, 0.5 - t2 / 24 + t2**2 / 720 - t2**3 / 40320 + t2**4 / 3628800,
                 (1 - np.cos(ts)) / ts**2)
    return np.eye(3) + a[..., None, None] * X + b[..., None, None] * (X @ X)


def dexp_inv(x):
    """Matrix of y -> dexp^{-1}(x) y = sum_j B_j / j! ad_x^j y (eq. dexp), summed to a
    truncation error below 1e-18 (the series converges for |x| < 2 pi; at most 40 terms)."""
    # |B_j / j!| <= 4 (2 pi)^{-j}: the tail after j is below 8 (a / 2 pi)^j for a < pi
    return _ad_series(x, _BJ, lambda j, a: 8 * (a / (2 * np.pi)) ** j)


def dexp(x):
    """Matrix of y -> dexp(x) y = sum_j ad_x^j y / (j+1)! (eq. dexp)."""
    return _ad_series(x, _INVFACT1, lambda j, a: 2 * a**j / factorial(j + 1))


# ---- tau = cay -----------------------------------------------------------------------------------
def cay(x):
    X = hat(x)
    return np.linalg.solve(np.eye(3) - X / 2, np.eye(3) + X / 2)


def dcay_inv(x):
    """Matrix of y -> dcay^{-1}(x) y = vee((e - x/2) y^ (e + x/2)) (eq. dcay)."""
    X = hat(x)
    L, R = np.eye(3) - X / 2, np.eye(3) + X / 2
    return linear_map_matrix(lambda y: vee(L @ hat(y) @ R), X.dtype, X.shape[:-2])


def dcay(x):
    """Matrix of y -> dcay(x) y = vee((e - x/2)^{-1} y^ (e + x/2)^{-1}) (eq. dcay)."""
    X = hat(x)
    Li, Ri = np.linalg.inv(np.eye(3) - X / 2), np.linalg.inv(np.eye(3) + X / 2)
    return linear_map_matrix(lambda y: vee(Li @ hat(y) @ Ri), X.dtype, X.shape[:-2])


# ---- tau = skew (projector) -------------------------------------------------------------
def sqrtm_sym(A, iters=50):
    """Principal square root of A (here A = x^2 + e, symmetric positive definite, close to e)
    by Newton's iteration S <- (S + S^{-1} A)/2 from S = e: every iterate is a polynomial in A,
    so this is the scalar iteration on each eigenvalue (quadratic convergence). Analytic in A,
    so complex-step safe. Runs to convergence of the real part plus two extra sweeps (the
    derivative converges at the same quadratic rate)."""
    S = np.broadcast_to(np.eye(3), A.shape).astype(A.dtype)
    extra = 2
    for _ in range(iters):
        Sn = (S + np.linalg.solve(S, A)) / 2
        done = np.max(np.abs((Sn - S).real)) <= 4e-16
        S = Sn
        if done:
            extra -= 1
            if extra < 0:
                return S
    raise RuntimeError("matrix square root iteration did not converge")


def skew_tau(x):
    """tau(x) = x + (x^2 + e)^{1/2}, the special orthogonal g with (g - g^*)/2 = x; defined
    for |x| < 1."""
    X = hat(x)
    return X + sqrtm_sym(X @ X + np.eye(3))


def dskew_inv(x):
    """Matrix of y -> dskew(x)(y) = vee((y tau(x) - (y tau(x))^*)/2) (eq. dskew): the
    inverse right-trivialized tangent of tau = skew^{-1}."""
    T = skew_tau(x)

    def f(y):
        YT = hat(y) @ T
        return vee((YT - tr(YT)) / 2)
    return linear_map_matrix(f, T.dtype, T.shape[:-2])


def dskew(x):
    return np.linalg.inv(dskew_inv(x))


#: name -> (tau, dtau^{-1} matrix, dtau matrix)
TAU = {
    "cay": (cay, dcay_inv, dcay),
    "exp": (exp_so3, dexp_inv, dexp),
    "skew": (skew_tau, dskew_inv, dskew),
}


# ---- Newton with complex-step Jacobians --------------------------------------------------
CS_STEP = 1e-40


def cs_eval(F, z):
    """(F(z), dF/dz) by complex step in ONE batched call. z has shape (..., n) (leading axes:
    independent systems, e.g. several initial states integrated side by side); F maps
    (k, ..., n) to (k, ..., m) and must be analytic in z (no abs, no conj). Batch row j is
    z + i eps e_j; column j of the Jacobian is Im F(z + i eps e_j) / eps, exact to round-off
    (no subtractive cancellation), and Re F(z + i eps e_j) = F(z) up to O(eps^2) = 1e-80.
    Returns F (..., m) and J (..., m, n)."""
    z = np.asarray(z, dtype=float)
    n = z.shape[-1]
    E = np.eye(n).reshape((n,) + (1,) * (z.ndim - 1) + (n,))
    Fc = np.asarray(F(z[None] + 1j * CS_STEP * E))
    return Fc[0].real, np.moveaxis(Fc.imag / CS_STEP, 0, -1)


def solve_vec(A, b):
    """Solve A x = b for stacks of matrices A (..., n, n) and vectors b (..., n)."""
    return np.linalg.solve(A, b[..., None])[..., 0]


class NewtonError(RuntimeError):
    pass


def newton(F, z0, tol=1e-15, maxit=50):
    """Solve F(z) = 0 from z0 by Newton's method, the Jacobian by complex step (``cs_eval``).
    z0 may carry leading batch axes (independent systems solved side by side, each with its
    own Jacobian; the iteration stops when all have converged).

    Converged when |dz|_inf <= tol * max(1, |z|_inf) (tol = 1e-15: relative), or when the
    steps stopped shrinking quadratically at the round-off floor (|dz| > |dz_prev| / 2 while
    |dz| <= 1e-13 max(1, |z|)): the iterate is then as accurate as F's round-off allows.
    """
    z = np.array(z0, dtype=float)
    dprev = np.inf
    for _ in range(maxit):
        Fz, J = cs_eval(F, z)
        dz = solve_vec(J, Fz)
        z = z - dz
        dn, scale = np.max(np.abs(dz)), max(1.0, np.max(np.abs(z)))
        if not np.isfinite(dn):
            raise NewtonError("non-finite Newton step")
        if dn <= tol * scale or (dn > dprev / 2 and dn <= 1e-13 * scale):
            return z
        dprev = dn
    raise NewtonError(f"Newton did not converge (last step {dn:.3g})")


def random_rotation(rng, scale=np.pi):
    """A rotation exp(hat(w)) with w uniform in the ball of radius ``scale``."""
    w = rng.normal(size=3)
    w *= scale * rng.uniform() ** (1 / 3) / np.linalg.norm(w)
    return exp_so3(w)
