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


def _outer(a, b):
    """a b^T + b a^T as a 3 x 3 SX (symmetric: each entry built once); a b^T + b a^T = 2 a a^T
    when b is a."""
    if b is a:
        e = [[None] * 3 for _ in range(3)]
        for i in range(3):
            for j in range(i, 3):
                e[i][j] = e[j][i] = a[i] * a[j]
        return e
    e = [[None] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(i, 3):
            e[i][j] = e[j][i] = a[i] * b[j] + b[i] * a[j] if i != j else 2 * a[i] * b[i]
    return e


def _so3_combo(alpha, beta, gamma, w, delta=0, v=None, V_coef=0):
    """alpha I + beta w^ + gamma w w^T [+ delta (v w^T + w v^T) + V_coef v^], entry by entry.

    Every so3 map is of this form (W^2 = w w^T - s I, WV + VW = v w^T + w v^T - 2 (w.v) I for
    W = w^, V = v^), which keeps the expression graph small under AD: no 3 x 3 products."""
    ww = _outer(w, w)
    vw = _outer(v, w) if v is not None and not _is_zero(delta) else None
    rows = []
    for i in range(3):
        row = []
        for j in range(3):
            e = gamma * ww[i][j]
            if vw is not None:
                e = e + delta * vw[i][j]
            if i == j:
                e = alpha + e
            else:
                k = 3 - i - j  # W[i, j] = sign * w[k]
                sign = 1 if (i, j) in ((1, 0), (0, 2), (2, 1)) else -1
                if not _is_zero(beta):
                    e = e + (sign * beta) * w[k]
                if not _is_zero(V_coef):
                    e = e + (sign * V_coef) * v[k]
            row.append(e)
        rows.append(ca.horzcat(*row))
    return ca.vertcat(*rows)


def _is_zero(c):
    return isinstance(c, (int, float)) and c == 0


def _cross(a, b):
    return ca.vertcat(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                      a[0] * b[1] - a[1] * b[0])


def _exp_margin(s):
    return (math.pi**2 - s) / (2 * math.pi)


# ---- so3 building blocks (w a 3-vector, W = w^, s = |w|^2, P = series.Point(s)) ----------
def _so3_exp(w, s, P):
    """Rodrigues: I + (sin t/t) W + ((1 - cos t)/t^2) W^2."""
    return _so3_combo(1 - s * P["cosc"], P["sinc"], P["cosc"], w)


def _so3_dexp(w, s, P):
    """dexp = I + cosc W + sinc3 W^2 = sinc I + cosc W + sinc3 w w^T (1 - s sinc3 = sinc);
    also the V of the se3 exponential."""
    return _so3_combo(P["sinc"], P["cosc"], P["sinc3"], w)


def _so3_dexpinv(w, s, P):
    """dexp^{-1} = I - W/2 + c W^2 = (1 - s c) I - W/2 + c w w^T."""
    c = P["dexpinv_c"]
    return _so3_combo(1 - s * c, -0.5, c, w)


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
    if kind == "exp":
        s = ca.dot(x, x)
        return _so3_exp(x, s, series.Point(s))
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "cay":
        return _so3_cay(W, s)
    return _I3 + W + ca.mtimes(W, W) / (1 + ca.sqrt(1 - s))


def so3_dtau_inv(group, kind, x):
    _check(group, kind, _SO_KINDS)
    if kind == "exp":
        s = ca.dot(x, x)
        return _so3_dexpinv(x, s, series.Point(s))
    W, s = _hat3(x), ca.dot(x, x)
    if kind == "cay":
        return _so3_dcay_inv(x, W)
    r = ca.sqrt(1 - s)
    return ((1 + r) / 2) * _I3 - W / 2 - ca.mtimes(x, x.T) / (2 * (1 + r))


def so3_dtau(group, kind, x):
    _check(group, kind, _SO_KINDS)
    if kind == "exp":
        s = ca.dot(x, x)
        return _so3_dexp(x, s, series.Point(s))
    W, s = _hat3(x), ca.dot(x, x)
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


def _se2_poly(x, s, a, b, c):
    """a I + b M + c M^2 for M = ad_x = [[0, 0, 0], [vy, 0, -w], [-vx, w, 0]] in
    (omega, vx, vy), M^2 = [[0, 0, 0], [w vx, -s, 0], [w vy, 0, -s]] (s = w^2), entrywise."""
    w, vx, vy = x[0], x[1], x[2]
    d = a - c * s
    return ca.vertcat(ca.horzcat(a, 0, 0),
                      ca.horzcat(b * vy + c * (w * vx), d, -b * w),
                      ca.horzcat(-b * vx + c * (w * vy), b * w, d))


def se2_tau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W = _se2_parts(x)
    if kind == "exp":  # R = rot(w), p = (sinc I + cosc W) v, cos w = 1 - s cosc, sin w = w sinc
        P = series.Point(s)
        sc, cc = P["sinc"], P["cosc"]
        Jv = ca.vertcat(-v[1], v[0])
        return _affine(_so2_rot(1 - s * cc, w * sc), sc * v + (cc * w) * Jv)
    P = (_I2 + W / 2) / (1 + s / 4)  # (I - W/2)^{-1}
    return _affine(so2_tau(group, "cay", x[0:1]), ca.mtimes(P, v))


def se2_dtau_inv(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        c = series.Point(s)["dexpinv_c"]  # f(M) = I - M/2 + c M^2
        return _se2_poly(x, s, 1, -0.5, c)
    lower = ca.mtimes(_I2 - W / 2, ca.mtimes(_J, v)) / 2
    return _blocks(ca.SX(1 + s / 4), ca.SX.zeros(1, 2), lower, _I2 - W / 2)


def se2_dtau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    w, v, s, W = _se2_parts(x)
    if kind == "exp":
        P = series.Point(s)  # g(M) = I + cosc M + sinc3 M^2
        return _se2_poly(x, s, 1, P["cosc"], P["sinc3"])
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
    if kind == "exp":  # [[exp(W), V v], [0, 1]], V v = sinc v + cosc w x v + sinc3 (w.v) w
        w, v = x[0:3], x[3:6]
        s = ca.dot(w, w)
        P = series.Point(s)
        t = P["sinc"] * v + P["cosc"] * _cross(w, v) + (P["sinc3"] * ca.dot(w, v)) * w
        return _affine(_so3_exp(w, s, P), t)
    w, v, s, W, _ = _se3_parts(x)
    return _affine(_so3_cay(W, s), ca.mtimes(_so3_inv_i_minus_half(W, s), v))


def se3_dtau_inv(group, kind, x):
    _check(group, kind, _SE_KINDS)
    Z = ca.SX.zeros(3, 3)
    if kind == "exp":
        # C = Df(W)[V] = -V/2 + c (WV + VW) + 2 (w.v) c' W^2
        #   = -V/2 + c (v w^T + w v^T) + 2 (w.v) c' w w^T - 2 (w.v) (c + s c') I
        w, v = x[0:3], x[3:6]
        s, wv = ca.dot(w, w), ca.dot(w, v)
        P = series.Point(s)
        c, dc = P["dexpinv_c"], P["d_dexpinv_c"]
        A = _so3_combo(1 - s * c, -0.5, c, w)
        k = 2 * wv
        C = _so3_combo(-k * (c + s * dc), 0, k * dc, w, delta=c, v=v, V_coef=-0.5)
        return _blocks(A, Z, C, A)
    w, v, s, W, V = _se3_parts(x)
    F = _I3 - W / 2
    return _blocks(_so3_dcay_inv(w, W), Z, -ca.mtimes(F, V) / 2, F)


def se3_dtau(group, kind, x):
    _check(group, kind, _SE_KINDS)
    Z = ca.SX.zeros(3, 3)
    if kind == "exp":
        # C = cosc V + sinc3 (WV + VW) + 2 (w.v) (cosc' W + sinc3' W^2)
        #   = cosc V + 2 (w.v) cosc' W + sinc3 (v w^T + w v^T) + 2 (w.v) sinc3' w w^T
        #     - 2 (w.v) (sinc3 + s sinc3') I
        w, v = x[0:3], x[3:6]
        s, wv = ca.dot(w, w), ca.dot(w, v)
        P = series.Point(s)
        s3, ds3 = P["sinc3"], P["d_sinc3"]
        A = _so3_combo(P["sinc"], P["cosc"], s3, w)
        k = 2 * wv
        C = _so3_combo(-k * (s3 + s * ds3), k * P["d_cosc"], k * ds3, w, delta=s3, v=v,
                       V_coef=P["cosc"])
        return _blocks(A, Z, C, A)
    w, v, s, W, V = _se3_parts(x)
    Dinv = _so3_dcay(W, s)
    return _blocks(Dinv, Z, ca.mtimes(V, Dinv) / 2, _so3_inv_i_minus_half(W, s))


def se3_margin(group, kind, x):
    _check(group, kind, _SE_KINDS)
    s = ca.dot(x[0:3], x[0:3])
    return {"exp": _exp_margin(s), "cay": ca.SX(1.0)}[kind]
