"""Scalar functions of s = t^2 with removable singularities at s = 0, safe for casadi AD.

The chart maps of ``hpgen.groups.maps`` need functions such as sin t / t whose exact formula
is 0/0 at t = 0 (math.md section 3). Each is coded as a branch on s = t^2 = dot(w, w):

    f(s) = if_else(s < s0, taylor(s_small), exact(s_big))
    s_small = if_else(s < s0, s, 0)      (the polynomial never sees a large argument)
    s_big   = if_else(s < s0, s0, s)     (the exact formula never sees a singular argument)

An AD tool differentiates both branches, and NaN * 0 is NaN (casadi's SX if_else happens to
mask the unused branch, generated code or other backends need not), so both branches are
kept finite for every s >= 0: the exact branch is evaluated at s_big >= s0 > 0
(its sqrt, 1/t, cot are then smooth), the Taylor branch is a polynomial. Hence f, f' and f''
are NaN-free at s = 0 and at s = s0 exactly. t = sqrt(s) appears only in the exact branch.

Taylor coefficients in s come from ``sympy.series`` of the even function f(t), computed on
first use (not at import) and cached. The number of terms N is chosen automatically: the
smallest N with sum_{k >= N} |a_k| s0^k <= 1e-17 |f(s0)| (a bound on the truncation error at
s0, relative to f; for s < s0 the omitted tail shrinks like (s/s0)^N).

Thresholds s0 (chosen by comparing both branches in double precision with 50-digit mpmath
values; "exact err" is the worst relative rounding error of the exact formula just above s0):

=============  ==============================  ====  =====  ==========  =================
name           f                               s0    terms  exact err   radius in s
=============  ==============================  ====  =====  ==========  =================
sinc           sin t / t                       1     9      1.2e-16     entire
cosc           (1 - cos t) / t^2               1     9      3.2e-16     entire
sinc3          (t - sin t) / t^3               4     11     2.7e-16     entire
dexpinv_c      (1 - (t/2) cot(t/2)) / t^2      4     17     5.2e-16     4 pi^2
d_cosc         d/ds cosc                       4     11     4.8e-16     entire
d_sinc3        d/ds sinc3                      16    15     5.8e-16     entire
d_dexpinv_c    d/ds dexpinv_c                  16    48     9e-16       4 pi^2
=============  ==============================  ====  =====  ==========  =================

The exact branches lose accuracy to cancellation as s -> 0 (e.g. t - sin t; the error grows
like eps / s for f and eps / s^2 for f'), so s0 is taken large enough that the exact branch
is accurate to about 1e-15 at s0; in the Taylor branch no term exceeds the first one up to
these s0, so it is accurate to a few eps (measured <= 2.2e-16 relative). cosc is evaluated as
(1/2) (sin(t/2)/(t/2))^2, which has no cancellation. dexpinv_c has poles at t = 2 pi k
(k >= 1), where dexp^{-1} is singular; see the exp chart margin in ``maps``.
Derivatives' exact branches are casadi's AD of the exact formula of f.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable

import casadi as ca
import sympy as sp

#: relative truncation error allowed for the Taylor branch
TRUNCATION_TOL = sp.Rational(1, 10**17)

_t = sp.Symbol("t", positive=True)


@dataclass(frozen=True)
class _Base:
    """An even function f(t), as a sympy expression and a casadi formula in s = t^2 > 0."""
    sym: Callable[[sp.Symbol], sp.Expr]
    exact: Callable[[ca.SX], ca.SX]
    kmax: int  # number of Taylor coefficients (in s) computed with sympy


def _sinc_exact(s):
    t = ca.sqrt(s)
    return ca.sin(t) / t


def _cosc_exact(s):
    u = ca.sqrt(s) / 2
    q = ca.sin(u) / u
    return 0.5 * q * q


def _sinc3_exact(s):
    t = ca.sqrt(s)
    return (t - ca.sin(t)) / (s * t)


def _dexpinv_c_exact(s):
    u = ca.sqrt(s) / 2
    return (1 - u * ca.cos(u) / ca.sin(u)) / s


_BASES = {
    "sinc": _Base(lambda t: sp.sin(t) / t, _sinc_exact, 24),
    "cosc": _Base(lambda t: (1 - sp.cos(t)) / t**2, _cosc_exact, 24),
    "sinc3": _Base(lambda t: (t - sp.sin(t)) / t**3, _sinc3_exact, 24),
    "dexpinv_c": _Base(lambda t: (1 - (t / 2) * sp.cot(t / 2)) / t**2, _dexpinv_c_exact, 62),
}


@dataclass(frozen=True)
class Spec:
    """One function of s: base function, derivative order (0 or 1, d/ds) and threshold s0."""
    base: str
    deriv: int
    s0: float


#: every function of s the chart maps use; adding one is one entry here (plus a base above)
SPECS = {
    "sinc": Spec("sinc", 0, 1.0),
    "cosc": Spec("cosc", 0, 1.0),
    "sinc3": Spec("sinc3", 0, 4.0),
    "dexpinv_c": Spec("dexpinv_c", 0, 4.0),
    "d_cosc": Spec("cosc", 1, 4.0),
    "d_sinc3": Spec("sinc3", 1, 16.0),
    "d_dexpinv_c": Spec("dexpinv_c", 1, 16.0),
}


@functools.lru_cache(maxsize=None)
def _base_coefficients(base: str) -> tuple[sp.Rational, ...]:
    """Exact Taylor coefficients a_k of f(t) = sum_k a_k s^k, k < kmax (sympy series in t)."""
    b = _BASES[base]
    ser = sp.series(b.sym(_t), _t, 0, 2 * b.kmax).removeO()
    coeffs = tuple(sp.Rational(ser.coeff(_t, 2 * k)) for k in range(b.kmax))
    if any(ser.coeff(_t, 2 * k + 1) != 0 for k in range(b.kmax)):
        raise RuntimeError(f"series base {base!r} is not an even function of t")
    return coeffs


@functools.lru_cache(maxsize=None)
def coefficients(name: str) -> tuple[float, ...]:
    """Taylor coefficients (in s, as floats) of SPECS[name], truncated as the module doc says."""
    spec = SPECS[name]
    a = _base_coefficients(spec.base)
    if spec.deriv == 1:
        a = tuple((k + 1) * a[k + 1] for k in range(len(a) - 1))
    s0 = sp.Rational(spec.s0)
    terms = [abs(c) * s0**k for k, c in enumerate(a)]
    scale = abs(sum(c * s0**k for k, c in enumerate(a)))
    if terms[-1] > scale * TRUNCATION_TOL * sp.Rational(1, 1000):
        raise RuntimeError(f"{name}: increase kmax of base {spec.base!r} (series too short)")
    tail = sp.Integer(0)
    n = len(a)
    while n > 1 and tail + terms[n - 1] <= TRUNCATION_TOL * scale:
        tail += terms[n - 1]
        n -= 1
    return tuple(float(c) for c in a[:n])


def threshold(name: str) -> float:
    """The branch point s0 of SPECS[name]."""
    return SPECS[name].s0


def taylor(name: str, s):
    """The Taylor branch (Horner polynomial in s); accurate for 0 <= s < s0."""
    out = 0
    for c in reversed(coefficients(name)):
        out = out * s + c
    return ca.SX(out) if not isinstance(out, (ca.SX, ca.MX)) else out


@functools.lru_cache(maxsize=None)
def _exact_function(name: str) -> ca.Function:
    spec = SPECS[name]
    S = ca.SX.sym("s")
    expr = _BASES[spec.base].exact(S)
    if spec.deriv == 1:
        expr = ca.gradient(expr, S)
    return ca.Function(f"exact_{name}", [S], [expr])


def exact(name: str, s):
    """The exact branch; only valid (and only evaluated by ``evaluate``) for s >= s0 > 0."""
    return _exact_function(name)(s)


def branches(name: str, s):
    """(small, taylor(s_small), exact(s_big)): the two branches of ``evaluate``.

    Each branch is finite, with finite derivatives of every order, for every s >= 0, so the
    result does not rely on how a backend masks the unused branch of if_else.
    """
    s0 = threshold(name)
    small = s < s0
    s_small = ca.if_else(small, s, 0)
    s_big = ca.if_else(small, s0, s)
    return small, taylor(name, s_small), exact(name, s_big)


def evaluate(name: str, s):
    """f(s) for s = t^2 >= 0 as a NaN-free branch (see the module docstring)."""
    small, lo, hi = branches(name, s)
    return ca.if_else(small, lo, hi)


def sinc(s):
    """sin t / t, t^2 = s."""
    return evaluate("sinc", s)


def cosc(s):
    """(1 - cos t) / t^2, t^2 = s."""
    return evaluate("cosc", s)


def sinc3(s):
    """(t - sin t) / t^3, t^2 = s."""
    return evaluate("sinc3", s)


def dexpinv_c(s):
    """c(s) = (1 - (t/2) cot(t/2)) / t^2 -> 1/12, the t^2 coefficient of dexp^{-1} (eq:dexp)."""
    return evaluate("dexpinv_c", s)


def d_cosc(s):
    """d/ds of (1 - cos t) / t^2."""
    return evaluate("d_cosc", s)


def d_sinc3(s):
    """d/ds of (t - sin t) / t^3."""
    return evaluate("d_sinc3", s)


def d_dexpinv_c(s):
    """c'(s), d/ds of dexpinv_c."""
    return evaluate("d_dexpinv_c", s)
