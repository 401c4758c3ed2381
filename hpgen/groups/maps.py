"""Chart maps tau: g -> G and their right-trivialized tangents, closed forms over casadi.SX.

Every function takes ``(group, kind, x)``, x a d x 1 SX column in the conventions of
``hpgen.groups.catalog`` (SE3 xi = (omega, v), SE2 xi = (omega, vx, vy), R<n> translations):

- ``<g>_tau``       n x n matrix tau(x^).
- ``<g>_dtau``      d x d matrix of y -> dtau_x(y) = vee(D tau(x)[y^] tau(x)^{-1}), the right
                    trivialized tangent (Definition def:dtau).
- ``<g>_dtau_inv``  d x d matrix of y -> dtau^{-1}_x(y), its inverse, the paper's inverse
                    right-trivialized tangent (Definition def:dtauinverse):
                    D tau^{-1}(g) . delta = dtau^{-1}_x(delta tau(x)^{-1}), g = tau(x).
- ``<g>_margin``    scalar SX, > 0 while x is inside the domain where tau is a usable chart.

Kinds (``ModelError`` on ``integrator.tau`` for a kind the group does not support):

- ``exp`` (eq:dexp): dexp^{-1}_x = f(ad_x), f(z) = z/(e^z - 1) = sum_j B_j/j! z^j, and
  dexp_x = g(ad_x), g(z) = (e^z - 1)/z. On so3 and se2, M = ad_x satisfies M^3 = -s M,
  s = |omega|^2, so f(M) = I - M/2 + c(s) M^2 (the odd part of f is exactly -z/2) and
  g(M) = I + cosc(s) M + sinc3(s) M^2 (odd part (cosh z - 1)/z, even part sinh z / z).
  On se3, ad_x = [[W, 0], [V, W]] and f(ad_x) = [[f(W), 0], [Df(W)[V], f(W)]], the Frechet
  derivative taken through the closed form: Df(W)[V] = -V/2 + c (WV + VW) + 2 (w.v) c' W^2.
  Margin: the exp chart is injective for |omega| < pi (dexp^{-1} blows up at 2 pi); the
  margin is (pi^2 - |omega|^2) / (2 pi), a smooth function with the sign of pi - |omega|
  and equal to it to first order at the boundary (pi - |omega| itself is not differentiable
  at omega = 0). R<n> and SO2 are abelian: dexp = dexp^{-1} = I.
- ``cay`` (eq:cay, eq:dcay): cay(X) = (I - X/2)^{-1} (I + X/2), dcay^{-1}_x(y) =
  vee((I - X/2) Y (I + X/2)), dcay_x(y) = vee((I - X/2)^{-1} Y (I + X/2)^{-1}), all in closed
  form (no symbolic inverse). Margin 1.0: on SO2, SO3, SE2, SE3 the Cayley map and dcay^{-1}
  are defined and smooth on the whole algebra (every denominator is 4 + |omega|^2 >= 4); the
  chart only misses the half-turns, reached as |omega| -> infinity, where it degrades
  gracefully (dcay ~ 1/|omega|), so there is no finite boundary to report.
- ``skew`` (eq:dskew, SO2 and SO3 only): tau(x) = X + (X^2 + I)^{1/2} (symmetric square root),
  the inverse of g -> (g - g^T)/2; defined for |w| < 1, margin 1 - |w|^2. With r = sqrt(1 - s):
  dskew^{-1}_x(y) = vee((Y tau - (Y tau)^T)/2) = ((1 + r)/2) I - X/2 - x x^T / (2 (1 + r)) and
  its inverse dskew_x = I + X/(1 + r) + x x^T / (r (1 + r)) (solved in the basis I, X, x x^T;
  x is the eigenvector with eigenvalue r of dskew^{-1}).

Removable singularities go through ``hpgen.groups.series`` (branch on s = |omega|^2).
"""
from __future__ import annotations

import math

import casadi as ca

from ..errors import ModelError
from . import series

_I2 = ca.SX.eye(2)
_I3 = ca.SX.eye(3)
_J = ca.SX(ca.DM([[0, -1], [1, 0]]))


# ---- helpers ---------------------------------------------------------------------------
def _check(group, kind, allowed):
    if kind not in allowed:
        raise ModelError(f"tau = {kind} is not available on {group.name}; use one of "
                         f"{', '.join(allowed)}", field="integrator.tau")


def _hat3(w):
    return ca.vertcat(ca.horzcat(0, -w[2], w[1]), ca.horzcat(w[2], 0, -w[0]),
                      ca.horzcat(-w[1], w[0], 0))


def _affine(R, x):
    k = R.shape[0]
    return ca.vertcat(ca.horzcat(R, x), ca.horzcat(ca.SX.zeros(1, k), ca.SX.ones(1, 1)))


def _blocks(A, B, C, D):
    """[[A, B], [C, D]]."""
    return ca.vertcat(ca.horzcat(A, B), ca.horzcat(C, D))


def _dexpinv_poly(M, s):
    """f(M), f(z) = z/(e^z - 1), for M with M^3 = -s M (so3, se2)."""
    return ca.SX.eye(M.shape[0]) - M / 2 + series.dexpinv_c(s) * ca.mtimes(M, M)


def _dexp_poly(M, s):
    """g(M), g(z) = (e^z - 1)/z, for M with M^3 = -s M (so3, se2)."""
    return ca.SX.eye(M.shape[0]) + series.cosc(s) * M + series.sinc3(s) * ca.mtimes(M, M)


def _exp_margin(s):
    return (math.pi**2 - s) / (2 * math.pi)


# ---- so3 building blocks (w a 3-vector, W = w^, s = |w|^2) --------------------------------
def _so3_exp(W, s):
    """Rodrigues: I + (sin t/t) W + ((1 - cos t)/t^2) W^2."""
    return _I3 + series.sinc(s) * W + series.cosc(s) * ca.mtimes(W, W)


def _so3_V(W, s):
    """V = I + ((1 - cos t)/t^2) W + ((t - sin t)/t^3) W^2 (also dexp on so3)."""
    return _dexp_poly(W, s)


def _so3_cay(W, s):
    return _I3 + (4 / (4 + s)) * (W + ca.mtimes(W, W) / 2)


def _so3_inv_i_minus_half(W, s):
    """(I - W/2)^{-1} = I + (2/(4 + s)) W + (1/(4 + s)) W^2."""
    return _I3 + (2 * W + ca.mtimes(W, W)) / (4 + s)


def _so3_dcay_inv(w, W):
    return _I3 - W / 2 + ca.mtimes(w, w.T) / 4


def _so3_dcay(W, s):
    return (4 / (4 + s)) * (_I3 + W / 2)


def _so2_rot(c, s_):
    return ca.vertcat(ca.horzcat(c, -s_), ca.horzcat(s_, c))


# ---- R<n> --------------------------------------------------------------------------------
def rn_tau(group, kind, x):
    """exp and cay both give I + x^ (x^ is nilpotent)."""
    _check(group, kind, ("exp", "cay"))
    return ca.SX.eye(group.n) + group.hat(x)


def rn_dtau_inv(group, kind, x):
    _check(group, kind, ("exp", "cay"))
    return ca.SX.eye(group.d)


def rn_dtau(group, kind, x):
    _check(group, kind, ("exp", "cay"))
    return ca.SX.eye(group.d)


def rn_margin(group, kind, x):
    _check(group, kind, ("exp", "cay"))
    return ca.SX(1.0)


# ---- SO2 ---------------------------------------------------------------------------------
_SO_KINDS = ("exp", "cay", "skew")


def so2_tau(group, kind, x):
    _check(group, kind, _SO_KINDS)
    w = x[0]
    if kind == "exp":
        return _so2_rot(ca.cos(w), ca.sin(w))
    if kind == "cay":
        q = w * w / 4
        return _so2_rot(1 - q, w) / (1 + q)
    return _so2_rot(ca.sqrt(1 - w * w), w)


def so2_dtau_inv(group, kind, x):
    _check(group, kind, _SO_KINDS)
    w = x[0]
    if kind == "exp":
        return ca.SX.eye(1)
    if kind == "cay":
        return ca.SX(1 + w * w / 4)
    return ca.SX(ca.sqrt(1 - w * w))


def so2_dtau(group, kind, x):
    _check(group, kind, _SO_KINDS)
    w = x[0]
    if kind == "exp":
        return ca.SX.eye(1)
    if kind == "cay":
        return ca.SX(1 / (1 + w * w / 4))
    return ca.SX(1 / ca.sqrt(1 - w * w))


def so2_margin(group, kind, x):
    _check(group, kind, _SO_KINDS)
    s = x[0] * x[0]
    return {"exp": _exp_margin(s), "cay": ca.SX(1.0), "skew": 1 - s}[kind]


# ---- SO3 ---------------------------------------------------------------------------------
def so3_tau(group, kind, x):
    _check(group, kind, _SO_KINDS)
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "exp":
        return _so3_exp(W, s)
    if kind == "cay":
        return _so3_cay(W, s)
    return _I3 + W + ca.mtimes(W, W) / (1 + ca.sqrt(1 - s))


def so3_dtau_inv(group, kind, x):
    _check(group, kind, _SO_KINDS)
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "exp":
        return _dexpinv_poly(W, s)
    if kind == "cay":
        return _so3_dcay_inv(x, W)
    r = ca.sqrt(1 - s)
    return ((1 + r) / 2) * _I3 - W / 2 - ca.mtimes(x, x.T) / (2 * (1 + r))


def so3_dtau(group, kind, x):
    _check(group, kind, _SO_KINDS)
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "exp":
        return _dexp_poly(W, s)
    if kind == "cay":
        return _so3_dcay(W, s)
    r = ca.sqrt(1 - s)
    return _I3 + W / (1 + r) + ca.mtimes(x, x.T) / (r * (1 + r))


def so3_margin(group, kind, x):
    _check(group, kind, _SO_KINDS)
    s = ca.dot(x, x)
    return {"exp": _exp_margin(s), "cay": ca.SX(1.0), "skew": 1 - s}[kind]


# ---- SE2: xi = (omega, vx, vy), g = [[R, p], [0, 1]] --------------------------------------
_SE_KINDS = ("exp", "cay")


def _se2_parts(x):
    w, v = x[0], x[1:3]
    return w, v, w * w, w * _J


def _se2_ad(x):
    """ad_x in (omega, vx, vy): [[0, 0, 0], [vy, 0, -omega], [-vx, omega, 0]]."""
    w, vx, vy = x[0], x[1], x[2]
    return ca.vertcat(ca.horzcat(0, 0, 0), ca.horzcat(vy, 0, -w), ca.horzcat(-vx, w, 0))


def se2_tau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        V = series.sinc(s) * _I2 + series.cosc(s) * W
        return _affine(_so2_rot(ca.cos(w), ca.sin(w)), ca.mtimes(V, v))
    P = (_I2 + W / 2) / (1 + s / 4)  # (I - W/2)^{-1}
    return _affine(so2_tau(group, "cay", x[0:1]), ca.mtimes(P, v))


def se2_dtau_inv(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        return _dexpinv_poly(_se2_ad(x), s)
    lower = ca.mtimes(_I2 - W / 2, ca.mtimes(_J, v)) / 2
    return _blocks(ca.SX(1 + s / 4), ca.SX.zeros(1, 2), lower, _I2 - W / 2)


def se2_dtau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        return _dexp_poly(_se2_ad(x), s)
    q = 1 + s / 4
    return _blocks(ca.SX(1 / q), ca.SX.zeros(1, 2), -ca.mtimes(_J, v) / (2 * q),
                   (_I2 + W / 2) / q)


def se2_margin(group, kind, x):
    _check(group, kind, _SE_KINDS)
    s = x[0] * x[0]
    return {"exp": _exp_margin(s), "cay": ca.SX(1.0)}[kind]


# ---- SE3: xi = (omega, v), g = [[R, p], [0, 1]] -------------------------------------------
def _se3_parts(x):
    w, v = x[0:3], x[3:6]
    return w, v, ca.dot(w, w), _hat3(w), _hat3(v)


def se3_tau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W, _ = _se3_parts(x)
    if kind == "exp":
        return _affine(_so3_exp(W, s), ca.mtimes(_so3_V(W, s), v))
    return _affine(_so3_cay(W, s), ca.mtimes(_so3_inv_i_minus_half(W, s), v))


def se3_dtau_inv(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W, V = _se3_parts(x)
    Z = ca.SX.zeros(3, 3)
    if kind == "exp":
        A = _dexpinv_poly(W, s)
        W2 = ca.mtimes(W, W)
        C = (-V / 2 + series.dexpinv_c(s) * (ca.mtimes(W, V) + ca.mtimes(V, W))
             + 2 * ca.dot(w, v) * series.d_dexpinv_c(s) * W2)
        return _blocks(A, Z, C, A)
    F = _I3 - W / 2
    return _blocks(_so3_dcay_inv(w, W), Z, -ca.mtimes(F, V) / 2, F)


def se3_dtau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W, V = _se3_parts(x)
    Z = ca.SX.zeros(3, 3)
    if kind == "exp":
        A = _dexp_poly(W, s)
        W2 = ca.mtimes(W, W)
        C = (series.cosc(s) * V + series.sinc3(s) * (ca.mtimes(W, V) + ca.mtimes(V, W))
             + 2 * ca.dot(w, v) * (series.d_cosc(s) * W + series.d_sinc3(s) * W2))
        return _blocks(A, Z, C, A)
    Dinv = _so3_dcay(W, s)
    return _blocks(Dinv, Z, ca.mtimes(V, Dinv) / 2, _so3_inv_i_minus_half(W, s))


def se3_margin(group, kind, x):
    _check(group, kind, _SE_KINDS)
    s = ca.dot(x[0:3], x[0:3])
    return {"exp": _exp_margin(s), "cay": ca.SX(1.0)}[kind]
