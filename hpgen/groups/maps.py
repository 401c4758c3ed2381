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

``GROUP_CHARTS`` tabulates the four functions of each group family; the groups of
``hpgen.groups.catalog`` dispatch through it after checking the kind against the charts
registered for their family in ``hpgen.schemes.TAU`` (``LieGroup.require_chart``: a
``ModelError`` on ``integrator.tau``), so the functions here assume a supported kind.

Kinds:

- ``exp`` (eq:dexp): dexp^{-1}_x = f(ad_x), f(z) = z/(e^z - 1) = sum_j B_j/j! z^j, and
  dexp_x = g(ad_x), g(z) = (e^z - 1)/z. On so3 and se2, M = ad_x satisfies M^3 = -s M,
  s = |omega|^2, so f(M) = I - M/2 + c(s) M^2 (the odd part of f is exactly -z/2) and
  g(M) = I + cosc(s) M + sinc3(s) M^2 (odd part (cosh z - 1)/z, even part sinh z / z).
  On se3, ad_x = [[W, 0], [V, W]] and f(ad_x) = [[f(W), 0], [Df(W)[V], f(W)]], the Frechet
  derivative taken through the closed form: Df(W)[V] = -V/2 + c (WV + VW) + 2 (w.v) c' W^2,
  and likewise Dg(W)[V] = cosc V + sinc3 (WV + VW) + 2 (w.v) (cosc' W + sinc3' W^2).
  Everything is assembled entry by entry from W^2 = w w^T - s I and WV + VW =
  v w^T + w v^T - 2 (w.v) I (no 3 x 3 products, no generic ad matrices), and the scalar
  functions of s of one map come from one ``series.Point`` (two shared half-angle
  polynomials, no branch and no sqrt/sin/cos/tan): the derive stage differentiates dexp^{-1}
  up to twice more, so the size of these expressions is the size of the generated kernels.
  The functions are accurate to round-off on the chart's domain |omega| <= pi and
  approximate beyond it (``hpgen.groups.series``), where no accepted step evaluates them.
  Margin: the exp chart is injective for |omega| < pi (dexp^{-1} blows up at 2 pi); the
  margin is (pi^2 - |omega|^2) / (2 pi), a smooth function with the sign of pi - |omega|
  and equal to it to first order at the boundary (pi - |omega| itself is not differentiable
  at omega = 0). R<n> and SO2 are abelian: dexp = dexp^{-1} = I.
- ``cay`` (eq:cay, eq:dcay): cay(X) = (I - X/2)^{-1} (I + X/2), dcay^{-1}_x(y) =
  vee((I - X/2) Y (I + X/2)), dcay_x(y) = vee((I - X/2)^{-1} Y (I + X/2)^{-1}), all in closed
  form (no symbolic inverse). The Cayley map and dcay^{-1} are defined and smooth on the
  whole algebra (every denominator is 4 + |omega|^2 >= 4), but the chart compresses angles:
  cay(x) rotates by 2 atan(|omega|/2), and cond(dcay^{-1}_x) = 1 + |omega|^2/4. Margin
  4 - |omega|^2: at most a quarter turn per chart evaluation. Beyond it the step equations
  were measured to have spurious roots (Gauss 2, exact RKMK, |h omega| = 3 on a spinning
  body converged to a root rotating 0.04 rad instead of 3); inside it they did not.
- ``skew`` (eq:dskew, SO2 and SO3 only): tau(x) = X + (X^2 + I)^{1/2} (symmetric square root),
  the inverse of g -> (g - g^T)/2; defined for |w| < 1, but the discrete Legendre map of a
  spin, p = sqrt(1 - |h xi|^2) I xi, folds at |h xi|^2 = 1/2 (no step exists beyond it, and a
  spurious branch lies past it), so the margin is 1/2 - |w|^2. With r = sqrt(1 - s):
  dskew^{-1}_x(y) = vee((Y tau - (Y tau)^T)/2) = ((1 + r)/2) I - X/2 - x x^T / (2 (1 + r)) and
  its inverse dskew_x = I + X/(1 + r) + x x^T / (r (1 + r)) (solved in the basis I, X, x x^T;
  x is the eigenvector with eigenvalue r of dskew^{-1}).

Removable singularities go through ``hpgen.groups.series`` (polynomials in s = |omega|^2,
exactly finite with all derivatives at s = 0).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import casadi as ca

from . import series

_I2 = ca.SX.eye(2)
_I3 = ca.SX.eye(3)
_J = ca.SX(ca.DM([[0, -1], [1, 0]]))


# ---- helpers ---------------------------------------------------------------------------
def _hat3(w):
    return ca.vertcat(ca.horzcat(0, -w[2], w[1]), ca.horzcat(w[2], 0, -w[0]),
                      ca.horzcat(-w[1], w[0], 0))


def _affine(R, x):
    k = R.shape[0]
    return ca.vertcat(ca.horzcat(R, x), ca.horzcat(ca.SX.zeros(1, k), ca.SX.ones(1, 1)))


def _blocks(A, B, C, D):
    """[[A, B], [C, D]]."""
    return ca.vertcat(ca.horzcat(A, B), ca.horzcat(C, D))


# ---- so3 matrices entry by entry ----------------------------------------------------------
# The exp-chart maps are linear combinations of I, W = w^, W^2 and (se3) V = v^, WV + VW with
# scalar coefficients of s = |w|^2. They are built entry by entry from the closed forms
#   W^2     = w w^T - s I   (diagonal -(w_j^2 + w_k^2), no cancellation),
#   WV + VW = v w^T + w v^T - 2 (w.v) I   (symmetric),
# which keeps the expression graph, and so its AD, small: no 3 x 3 matrix products.
_OFF = ((0, 1, -1, 2), (0, 2, 1, 1), (1, 0, 1, 2), (1, 2, -1, 0), (2, 0, -1, 1), (2, 1, 1, 0))
# (i, j, sign, k): hat(w)[i, j] = sign * w[k] off the diagonal


def _sq3(w):
    """W^2 = hat(w)^2 as a symmetric 3 x 3 list of SX scalars."""
    q = [w[i] * w[i] for i in range(3)]
    e = [[None] * 3 for _ in range(3)]
    for i in range(3):
        e[i][i] = -(q[(i + 1) % 3] + q[(i + 2) % 3])
        for j in range(i + 1, 3):
            e[i][j] = e[j][i] = w[i] * w[j]
    return e


def _anticomm3(w, v):
    """WV + VW = v w^T + w v^T - 2 (w.v) I as a symmetric 3 x 3 list of SX scalars."""
    p = [w[i] * v[i] for i in range(3)]
    e = [[None] * 3 for _ in range(3)]
    for i in range(3):
        e[i][i] = -2 * (p[(i + 1) % 3] + p[(i + 2) % 3])
        for j in range(i + 1, 3):
            e[i][j] = e[j][i] = v[i] * w[j] + w[i] * v[j]
    return e


def _so3_matrix(diag, terms):
    """diag I + sum_k coef_k M_k, terms = [(coef_k, M_k)] with M_k a 3 x 3 list (symmetric
    parts) or a 3-vector a standing for hat(a) (antisymmetric parts); coef == 0 is skipped."""
    rows = [[diag if i == j else None for j in range(3)] for i in range(3)]

    def add(i, j, e):
        rows[i][j] = e if rows[i][j] is None else rows[i][j] + e

    for coef, M in terms:
        if isinstance(coef, (int, float)) and coef == 0:
            continue
        if isinstance(M, list):
            for i in range(3):
                for j in range(3):
                    add(i, j, coef * M[i][j])
        else:
            for i, j, sign, k in _OFF:
                add(i, j, (sign * coef) * M[k] if isinstance(coef, (int, float))
                    else sign * (coef * M[k]))
    return ca.vertcat(*[ca.horzcat(*[0 if e is None else e for e in r]) for r in rows])


def _cross(a, b):
    return ca.vertcat(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0])


def _exp_margin(s):
    return (math.pi**2 - s) / (2 * math.pi)


def _cay_margin(s):
    """At most a quarter turn, 2 atan(|omega|/2) <= pi/2, per chart evaluation."""
    return 4 - s


def _skew_margin(s):
    """Inside the fold |omega|^2 = 1/2 of the skew chart's discrete Legendre map."""
    return 0.5 - s


#: chart -> its margin as a function of s = |omega|^2 (the domains of hpgen.schemes.TAU)
_MARGINS = {"exp": _exp_margin, "cay": _cay_margin, "skew": _skew_margin}


# ---- so3 building blocks (w a 3-vector, s = |w|^2, P = series.Point(s)) --------------------
def _so3_exp(w, P, W2):
    """Rodrigues: I + (sin t/t) W + ((1 - cos t)/t^2) W^2."""
    return _so3_matrix(1, [(P["sinc"], w), (P["cosc"], W2)])


def _so3_dexp(w, P, W2):
    """dexp = I + cosc W + sinc3 W^2 (eq:dexp)."""
    return _so3_matrix(1, [(P["cosc"], w), (P["sinc3"], W2)])


def _so3_dexpinv(w, P, W2):
    """dexp^{-1} = I - W/2 + c W^2 (eq:dexp)."""
    return _so3_matrix(1, [(-0.5, w), (P["dexpinv_c"], W2)])


def _so3_cay(W, s):
    return _I3 + (4 / (4 + s)) * (W + ca.mtimes(W, W) / 2)


def _so3_inv_i_minus_half(W, s):
    """(I - W/2)^{-1} = I + (2/(4 + s)) W + (1/(4 + s)) W^2."""
    return _I3 + (2 * W + ca.mtimes(W, W)) / (4 + s)


def _so3_dcay_inv(w, W):
    return _I3 - W / 2 + ca.mtimes(w, w.T) / 4


def so3_dcay_inv_T_times(w, m):
    """(dcay^{-1}_w)^T m = (I - w^/2 + w w^T/4)^T m = m + (w x m)/2 + (w.m) w/4: 15
    multiplications instead of forming the matrix (the hand-written Stormer-Verlet's form)."""
    return m + ca.cross(w, m) / 2 + (ca.dot(w, m) / 4) * w


def so3_dcay_inv_times(w, m):
    """dcay^{-1}_w m = (I - w^/2 + w w^T/4) m = m - (w x m)/2 + (w.m) w/4."""
    return m - ca.cross(w, m) / 2 + (ca.dot(w, m) / 4) * w


def so3_dcay_times(w, m):
    """dcay_w m = (4/(4 + |w|^2)) (I + w^/2) m = (4/(4 + |w|^2)) (m + (w x m)/2)."""
    return (4 / (4 + ca.dot(w, w))) * (m + ca.cross(w, m) / 2)


def so3_dcay_T_times(w, m):
    """(dcay_w)^T m = (4/(4 + |w|^2)) (I - w^/2) m = (4/(4 + |w|^2)) (m - (w x m)/2)."""
    return (4 / (4 + ca.dot(w, w))) * (m - ca.cross(w, m) / 2)


def _so3_dcay(W, s):
    return (4 / (4 + s)) * (_I3 + W / 2)


def _so2_rot(c, s_):
    return ca.vertcat(ca.horzcat(c, -s_), ca.horzcat(s_, c))


# ---- R<n> --------------------------------------------------------------------------------
def rn_tau(group, kind, x):
    """exp and cay both give I + x^ (x^ is nilpotent)."""
    return ca.SX.eye(group.n) + group.hat(x)


def rn_dtau_inv(group, kind, x):
    return ca.SX.eye(group.d)


def rn_dtau(group, kind, x):
    return ca.SX.eye(group.d)


def rn_margin(group, kind, x):
    return ca.SX(1.0)


# ---- SO2 ---------------------------------------------------------------------------------
def so2_tau(group, kind, x):
    w = x[0]
    if kind == "exp":
        return _so2_rot(ca.cos(w), ca.sin(w))
    if kind == "cay":
        q = w * w / 4
        return _so2_rot(1 - q, w) / (1 + q)
    return _so2_rot(ca.sqrt(1 - w * w), w)


def so2_dtau_inv(group, kind, x):
    w = x[0]
    if kind == "exp":
        return ca.SX.eye(1)
    if kind == "cay":
        return ca.SX(1 + w * w / 4)
    return ca.SX(ca.sqrt(1 - w * w))


def so2_dtau(group, kind, x):
    w = x[0]
    if kind == "exp":
        return ca.SX.eye(1)
    if kind == "cay":
        return ca.SX(1 / (1 + w * w / 4))
    return ca.SX(1 / ca.sqrt(1 - w * w))


def so2_margin(group, kind, x):
    s = x[0] * x[0]
    return _MARGINS[kind](s)


# ---- SO3 ---------------------------------------------------------------------------------
def so3_tau(group, kind, x):
    if kind == "exp":
        return _so3_exp(x, series.Point(ca.dot(x, x)), _sq3(x))
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "cay":
        return _so3_cay(W, s)
    return _I3 + W + ca.mtimes(W, W) / (1 + ca.sqrt(1 - s))


def so3_dtau_inv(group, kind, x):
    if kind == "exp":
        return _so3_dexpinv(x, series.Point(ca.dot(x, x)), _sq3(x))
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "cay":
        return _so3_dcay_inv(x, W)
    r = ca.sqrt(1 - s)
    return ((1 + r) / 2) * _I3 - W / 2 - ca.mtimes(x, x.T) / (2 * (1 + r))


def so3_dtau(group, kind, x):
    if kind == "exp":
        return _so3_dexp(x, series.Point(ca.dot(x, x)), _sq3(x))
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "cay":
        return _so3_dcay(W, s)
    r = ca.sqrt(1 - s)
    return _I3 + W / (1 + r) + ca.mtimes(x, x.T) / (r * (1 + r))


def so3_margin(group, kind, x):
    s = ca.dot(x, x)
    return _MARGINS[kind](s)


# ---- SE2: xi = (omega, vx, vy), g = [[R, p], [0, 1]] --------------------------------------
def _se2_parts(x):
    w, v = x[0], x[1:3]
    return w, v, w * w, w * _J


def _se2_poly(x, s, a, b, c):
    """a I + b M + c M^2 for M = ad_x = [[0, 0, 0], [vy, 0, -w], [-vx, w, 0]] in
    (omega, vx, vy), M^2 = [[0, 0, 0], [w vx, -s, 0], [w vy, 0, -s]] (s = w^2), entrywise."""
    w, vx, vy = x[0], x[1], x[2]
    d = a - c * s
    return ca.vertcat(ca.horzcat(a, 0, 0),
                      ca.horzcat(b * vy + c * (w * vx), d, -b * w),
                      ca.horzcat(-b * vx + c * (w * vy), b * w, d))


def se2_tau(group, kind, x):
    w, v, s, W = _se2_parts(x)
    if kind == "exp":  # R = rot(w), p = (sinc I + cosc W) v, cos w = 1 - s cosc, sin w = w sinc
        P = series.Point(s)
        sc, cc = P["sinc"], P["cosc"]
        Jv = ca.vertcat(-v[1], v[0])
        return _affine(_so2_rot(1 - s * cc, w * sc), sc * v + (cc * w) * Jv)
    P = (_I2 + W / 2) / (1 + s / 4)  # (I - W/2)^{-1}
    return _affine(so2_tau(group, "cay", x[0:1]), ca.mtimes(P, v))


def se2_dtau_inv(group, kind, x):
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        c = series.Point(s)["dexpinv_c"]  # f(M) = I - M/2 + c M^2
        return _se2_poly(x, s, 1, -0.5, c)
    lower = ca.mtimes(_I2 - W / 2, ca.mtimes(_J, v)) / 2
    return _blocks(ca.SX(1 + s / 4), ca.SX.zeros(1, 2), lower, _I2 - W / 2)


def se2_dtau(group, kind, x):
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        P = series.Point(s)  # g(M) = I + cosc M + sinc3 M^2
        return _se2_poly(x, s, 1, P["cosc"], P["sinc3"])
    q = 1 + s / 4
    return _blocks(ca.SX(1 / q), ca.SX.zeros(1, 2), -ca.mtimes(_J, v) / (2 * q),
                   (_I2 + W / 2) / q)


def se2_margin(group, kind, x):
    s = x[0] * x[0]
    return _MARGINS[kind](s)


# ---- SE3: xi = (omega, v), g = [[R, p], [0, 1]] -------------------------------------------
def _se3_parts(x):
    w, v = x[0:3], x[3:6]
    return w, v, ca.dot(w, w), _hat3(w), _hat3(v)


def se3_tau(group, kind, x):
    if kind == "exp":  # [[exp(W), V v], [0, 1]], V v = sinc v + cosc w x v + sinc3 (w.v) w
        w, v = x[0:3], x[3:6]
        P = series.Point(ca.dot(w, w))
        t = P["sinc"] * v + P["cosc"] * _cross(w, v) + (P["sinc3"] * ca.dot(w, v)) * w
        return _affine(_so3_exp(w, P, _sq3(w)), t)
    w, v, s, W, _ = _se3_parts(x)
    return _affine(_so3_cay(W, s), ca.mtimes(_so3_inv_i_minus_half(W, s), v))


def se3_dtau_inv(group, kind, x):
    Z = ca.SX.zeros(3, 3)
    if kind == "exp":  # [[f(W), 0], [Df(W)[V], f(W)]], Df(W)[V] = -V/2 + c S + 2 (w.v) c' W^2
        w, v = x[0:3], x[3:6]
        P = series.Point(ca.dot(w, w))
        W2, S = _sq3(w), _anticomm3(w, v)
        c = P["dexpinv_c"]
        A = _so3_matrix(1, [(-0.5, w), (c, W2)])
        C = _so3_matrix(0, [(-0.5, v), (c, S), ((2 * ca.dot(w, v)) * P["d_dexpinv_c"], W2)])
        return _blocks(A, Z, C, A)
    w, v, s, W, V = _se3_parts(x)
    F = _I3 - W / 2
    return _blocks(_so3_dcay_inv(w, W), Z, -ca.mtimes(F, V) / 2, F)


def se3_dtau(group, kind, x):
    Z = ca.SX.zeros(3, 3)
    if kind == "exp":  # [[g(W), 0], [Dg(W)[V], g(W)]]
        # Dg(W)[V] = cosc V + sinc3 S + 2 (w.v) (cosc' W + sinc3' W^2)
        w, v = x[0:3], x[3:6]
        P = series.Point(ca.dot(w, w))
        W2, S = _sq3(w), _anticomm3(w, v)
        cc, s3 = P["cosc"], P["sinc3"]
        k = 2 * ca.dot(w, v)
        A = _so3_matrix(1, [(cc, w), (s3, W2)])
        C = _so3_matrix(0, [(cc, v), (s3, S), (k * P["d_cosc"], w), (k * P["d_sinc3"], W2)])
        return _blocks(A, Z, C, A)
    w, v, s, W, V = _se3_parts(x)
    Dinv = _so3_dcay(W, s)
    return _blocks(Dinv, Z, ca.mtimes(V, Dinv) / 2, _so3_inv_i_minus_half(W, s))


def se3_margin(group, kind, x):
    s = ca.dot(x[0:3], x[0:3])
    return _MARGINS[kind](s)


# ---- the table: group family (hpgen.groups.GROUP_NAMES spelling) -> its chart functions --------
@dataclass(frozen=True)
class GroupCharts:
    """The chart functions of one group family, each ``(group, kind, x)`` as above."""
    tau: Callable
    dtau_inv: Callable
    dtau: Callable
    margin: Callable


#: (family, chart) -> {(map, transposed): f(x, m)}: the products dtau^{-1}_x m, (dtau^{-1}_x)^T m,
#: dtau_x m and (dtau_x)^T m in closed form (LieGroup.chart_product), where tabulated: the
#: same linear maps as the matrices of GROUP_CHARTS, without forming them
CHART_PRODUCTS = {("SO3", "cay"): {("dtau_inv", False): so3_dcay_inv_times,
                                   ("dtau_inv", True): so3_dcay_inv_T_times,
                                   ("dtau", False): so3_dcay_times,
                                   ("dtau", True): so3_dcay_T_times}}

GROUP_CHARTS = {
    "R<n>": GroupCharts(rn_tau, rn_dtau_inv, rn_dtau, rn_margin),
    "SO2": GroupCharts(so2_tau, so2_dtau_inv, so2_dtau, so2_margin),
    "SO3": GroupCharts(so3_tau, so3_dtau_inv, so3_dtau, so3_margin),
    "SE2": GroupCharts(se2_tau, se2_dtau_inv, se2_dtau, se2_margin),
    "SE3": GroupCharts(se3_tau, se3_dtau_inv, se3_dtau, se3_margin),
}
