"""Scalar functions of s = t^2 with removable singularities at s = 0, safe for casadi AD.

The chart maps of ``hpgen.groups.maps`` need functions such as sin t / t whose exact formula
is 0/0 at t = 0 (math.md section 3). A map evaluates all the functions it needs at one
``Point(s)``, s = t^2 = dot(w, w), which branches once:

    small   = s < S0
    s_small = if_else(small, s, 0)      (the polynomials never see a large argument)
    s_big   = if_else(small, S0, s)     (the exact formulas never see a singular argument)
    f       = if_else(small, taylor_f(s_small), exact_f(s_big))    for every f the map uses

An AD tool differentiates both branches, and NaN * 0 is NaN (casadi's SX if_else happens to
mask the unused branch, generated code or other backends need not), so both branches are
kept finite for every s >= 0: the exact branch is evaluated at s_big >= S0 > 0 (its sqrt,
1/t, 1/sin are then smooth), the Taylor branch is a polynomial. Hence f, f' and f'' are
NaN-free at s = 0 and at s = S0 exactly.

Size under AD matters more than anything else here: the derive stage differentiates the
maps up to three times, through both branches of every if_else. So a Point shares, between
all the functions of one map,

- one condition and one pair (s_small, s_big);
- the powers s_small^k of the Taylor branch: each polynomial sum_k a_k s^k is then linear
  in shared nonlinear terms (summed smallest term first);
- one sqrt, one sin and one cos in the exact branch: with u = t/2, sn = sin u, cs = cos u,
  r = 1/u, every exact formula below is a rational expression in (u, r, sn, cs):

=============  ==========================  =====================================  =====
name           f(s), t^2 = s               exact branch (u = t/2)                 terms
=============  ==========================  =====================================  =====
sinc           sin t / t                   sn cs r                                9
cosc           (1 - cos t) / t^2           (sn r)^2 / 2                           9
sinc3          (t - sin t) / t^3           (u - sn cs) r^3 / 4                    8
dexpinv_c      (1 - (t/2) cot(t/2)) / t^2  (sn - u cs) r^2 / (4 sn)               10
d_cosc         d/ds cosc                   -sn (sn - u cs) r^4 / 8                8
d_sinc3        d/ds sinc3                  (2u sn^2 - 3u + 3 sn cs) r^5 / 32      8
d_dexpinv_c    d/ds dexpinv_c              (u sn cs + u^2 - 2 sn^2) r^4/(32 sn^2) 10
=============  ==========================  =====================================  =====

Accuracy is judged on the d x d matrices the maps build, not on each function: an error e
in f costs e |M| in the matrix, M the factor f multiplies (W ~ t, W^2 ~ s, the se3 terms
(w.v) W^2 ~ t^3 |v|, ...; see ``WEIGHTS``). The terms above are the fewest with a Taylor
tail below 2^-54 |M| at s = S0 (|v| = 1). The exact branches cancel as s -> 0 (t - sin t,
sn - u cs, ...), but their absolute error is ~eps / s^k where M ~ s^k, so the matrix-level
error stays at a few eps down to S0 = 1 (measured, tests/unit/test_groups.py). dexpinv_c
has poles at t = 2 pi k (k >= 1), where dexp^{-1} is singular; see the exp chart margin in
``maps``.

The exact Taylor coefficients are precomputed with sympy by ``hpgen.tools.gen_series`` into
``series_data`` (checked against a fresh run by the test suite); nothing here imports sympy.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from fractions import Fraction

import casadi as ca

from .series_data import COEFFICIENTS

#: the branch point of every function: s < S0 uses the Taylor polynomial (|w| < 1 rad)
S0 = 1.0


@dataclass(frozen=True)
class Spec:
    """One function of s: base function (series_data), derivative order (0 or 1, d/ds) and
    the number of Taylor terms used for s < S0."""
    base: str
    deriv: int
    terms: int


#: every function of s the chart maps use; adding one is one entry here, one exact formula
#: in ``Point._exact`` and (for a new base) one entry in ``hpgen.tools.gen_series.BASES``
SPECS = {
    "sinc": Spec("sinc", 0, 9),
    "cosc": Spec("cosc", 0, 9),
    "sinc3": Spec("sinc3", 0, 8),
    "dexpinv_c": Spec("dexpinv_c", 0, 10),
    "d_cosc": Spec("cosc", 1, 8),
    "d_sinc3": Spec("sinc3", 1, 8),
    "d_dexpinv_c": Spec("dexpinv_c", 1, 10),
}

#: size of the matrix factor each function multiplies in the maps, as a function of t = |w|
#: with |v| = 1 (used to choose the terms and by the accuracy tests)
WEIGHTS = {
    "sinc": lambda t: max(1.0, t),          # W in exp, I in dexp, v in the se3 translation
    "cosc": lambda t: max(1.0, t),          # W^2 in exp, W in dexp, V in se3 dexp
    "sinc3": lambda t: 2 * t,               # w w^T - s I, v w^T + w v^T
    "dexpinv_c": lambda t: 2 * t,           # w w^T - s I, v w^T + w v^T
    "d_cosc": lambda t: 2 * t * t,          # 2 (w.v) W
    "d_sinc3": lambda t: 2 * t**3,          # 2 (w.v) W^2
    "d_dexpinv_c": lambda t: 2 * t**3,      # 2 (w.v) W^2
}


@functools.lru_cache(maxsize=None)
def exact_coefficients(name: str) -> tuple[Fraction, ...]:
    """All the stored Taylor coefficients of SPECS[name] in s, as exact fractions."""
    spec = SPECS[name]
    a = tuple(Fraction(p, q) for p, q in COEFFICIENTS[spec.base])
    for _ in range(spec.deriv):
        a = tuple((k + 1) * a[k + 1] for k in range(len(a) - 1))
    return a


@functools.lru_cache(maxsize=None)
def coefficients(name: str) -> tuple[float, ...]:
    """The Taylor coefficients (in s, correctly rounded floats) used for SPECS[name]."""
    a = exact_coefficients(name)
    n = SPECS[name].terms
    if n > len(a):
        raise RuntimeError(f"{name}: series_data holds {len(a)} coefficients, {n} wanted")
    return tuple(float(c) for c in a[:n])


def threshold(name: str | None = None) -> float:
    """The branch point s0 (the same S0 for every function, so that they share it)."""
    if name is not None and name not in SPECS:
        raise KeyError(name)
    return S0


class Point:
    """The functions of SPECS at one s >= 0, sharing the branch, the Taylor powers and the
    transcendental calls of the exact branch (module docstring). ``p[name]`` is the branch
    value; ``p.taylor(name)`` and ``p.exact(name)`` the two branches."""

    def __init__(self, s, s0: float | None = None):
        s0 = S0 if s0 is None else s0
        self.s = s
        self.s0 = s0
        self.small = s < s0
        self.s_small = ca.fmin(s, s0)
        self.s_big = ca.fmax(s, s0)
        self._powers = [ca.SX(1), self.s_small]
        self._cache: dict = {}

    # ---- Taylor branch ---------------------------------------------------------------
    def _power(self, k):
        while len(self._powers) <= k:
            self._powers.append(self._powers[-1] * self.s_small)
        return self._powers[k]

    def taylor(self, name: str):
        key = ("taylor", name)
        if key not in self._cache:
            c = coefficients(name)
            out = c[-1]
            for k in range(len(c) - 2, -1, -1):
                out = out * self.s_small + c[k]
            self._cache[key] = ca.SX(out)
        return self._cache[key]

    # ---- exact branch ------------------------------------------------------------------
    def _q(self, key):
        """Shared intermediate quantities of the exact branch, built on first use."""
        if key in self._cache:
            return self._cache[key]
        q = self._q
        if key == "u":
            v = 0.5 * ca.sqrt(self.s_big)
        elif key == "cs":
            v = ca.cos(q("u"))
        elif key == "q":  # sin(u) / u
            v = ca.sin(q("u")) / q("u")
        elif key == "is":
            v = 1 / self.s_big
        else:
            raise KeyError(key)
        self._cache[key] = v
        return v

    def exact(self, name: str):
        key = ("exact", name)
        if key in self._cache:
            return self._cache[key]
        q, f, inv_s = self._q, self.exact, self._q("is")
        if name == "sinc":
            v = q("q") * q("cs")
        elif name == "cosc":
            v = 0.5 * (q("q") * q("q"))
        elif name == "sinc3":
            v = (1 - f("sinc")) * inv_s
        elif name == "dexpinv_c":  # (1 - u cot u) / s
            v = (1 - q("u") / ca.tan(q("u"))) * inv_s
        elif name == "d_cosc":
            v = (0.5 * f("sinc") - f("cosc")) * inv_s
        elif name == "d_sinc3":
            v = (0.5 * f("cosc") - 1.5 * f("sinc3")) * inv_s
        elif name == "d_dexpinv_c":
            c = f("dexpinv_c")
            v = (0.125 - 1.5 * c) * inv_s + 0.5 * (c * c)
        else:
            raise KeyError(name)
        self._cache[key] = v
        return v

    # ---- the branch --------------------------------------------------------------------
    def __getitem__(self, name: str):
        key = ("value", name)
        if key not in self._cache:
            self._cache[key] = ca.if_else(self.small, self.taylor(name), self.exact(name))
        return self._cache[key]


# ---- single-function interface (tests, one-off use) ------------------------------------------
def taylor(name: str, s):
    """The Taylor branch of SPECS[name] as a polynomial in s; accurate for 0 <= s < S0."""
    return Point(s).taylor(name) if not _is_number(s) else _poly(name, s)


def exact(name: str, s):
    """The exact branch of SPECS[name]; only valid (and only used) for s >= S0 > 0.

    Evaluated as is at s (no branch), so it can be compared with the Taylor branch."""
    p = Point(ca.SX(s) if _is_number(s) else s, s0=-1.0)  # s_big = s
    return p.exact(name)


def branches(name: str, s):
    """(small, taylor(s_small), exact(s_big)): the two branches of ``evaluate``.

    Each branch is finite, with finite derivatives of every order, for every s >= 0, so the
    result does not rely on how a backend masks the unused branch of if_else.
    """
    p = Point(s)
    return p.small, p.taylor(name), p.exact(name)


def evaluate(name: str, s):
    """f(s) for s = t^2 >= 0 as a NaN-free branch (see the module docstring)."""
    return Point(s)[name]


def _is_number(s):
    return isinstance(s, (int, float))


def _poly(name, s):
    out = 0.0
    for c in reversed(coefficients(name)):
        out = out * s + c
    return out


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


_ = math  # noqa: F841  (kept for the WEIGHTS lambdas' callers)
