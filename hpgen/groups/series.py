"""Scalar functions of s = t^2 with removable singularities at s = 0, safe for casadi AD.

The chart maps of ``hpgen.groups.maps`` need functions such as sin t / t whose exact formula
is 0/0 at t = 0 (math.md section 3). A map evaluates every function it needs at one
``Point(s)``, s = t^2 = |w|^2, which branches once:

    small   = (s < S0)                   a 0/1 value, big = 1 - small
    s_small = s * small                  the polynomials never see a large argument
    s_big   = S0 + (s - S0) * big        the exact formulas never see a singular argument
    f       = taylor_f(s_small) * small + exact_f(s_big) * big     for each f of the map

An AD tool differentiates both branches, so both are kept finite, with finite derivatives,
for every finite s >= 0: the exact branch is evaluated at s_big >= S0 > 0 (its sqrt, 1/s,
1/tan are then smooth), the Taylor branch is a polynomial at s_small <= S0. Hence f, f' and
f'' are NaN-free at s = 0 and at s = S0 exactly, and multiplying a branch by 0 is an exact
selection (NaN * 0 would be NaN; finite * 0 is 0), which needs no masking by the backend.
s - S0 is exact for S0 <= s < 2^49 (S0 is a multiple of 2^-4), so s_big == s there. The
derivative of s_small, s_big is the 0/1 mask itself, 1 on the branch in use, also at s = S0
(unlike fmin/fmax, whose derivative at a tie is 1/2).

Size under AD is what matters here: the derive stage differentiates dexp^{-1} up to twice
more (the action's variations, then the Jacobian in the unknowns), through both branches.
So a Point shares one mask and one (s_small, s_big) between all the functions of a map,
polynomials are plain Horner in s_small, and the exact branches, built on u = t/2, use one
sqrt, one sin and one cos (sinc, cosc, sinc3 and their derivatives) or one tan (dexpinv_c,
d_dexpinv_c), with q = sin(u)/u and a single 1/s:

=============  ===========================  =================================  ======
name           f(s), t^2 = s                exact branch                       terms
=============  ===========================  =================================  ======
sinc           sin t / t                    q cos u                            10
cosc           (1 - cos t) / t^2            q^2 / 2                            9
sinc3          (t - sin t) / t^3            (1 - sinc) / s                     9
dexpinv_c      (1 - (t/2) cot(t/2)) / t^2   (1 - u / tan u) / s                11
d_cosc         d/ds cosc                    (sinc / 2 - cosc) / s              9
d_sinc3        d/ds sinc3                   (cosc / 2 - 3 sinc3 / 2) / s       8
d_dexpinv_c    d/ds dexpinv_c               (1/8 - 3 c / 2) / s + c^2 / 2      11
=============  ===========================  =================================  ======

(The derivative formulas are identities: sinc' = (sinc3 - cosc)/2 with 1 - sinc = s sinc3,
cosc' = (sinc/2 - cosc)/s, and c = dexpinv_c solves the Riccati equation
8 s c' = 1 - 12 c + 4 s c^2 inherited from cot' = -1 - cot^2.)

Accuracy is judged on the d x d matrices of the maps, not on each function: an error e in f
costs e |M| in the matrix, M the factor f multiplies (W ~ t, W^2 ~ s, the se3 terms
(w.v) W^2 ~ t^3 |v|, ...; ``WEIGHTS``). The terms above are the fewest whose Taylor tail,
times |M|, is below 2^-54 at s = S0, for the value and for the first derivative (chain rule:
f'(s) 2 (w.y) M), with |v| = 1 (``hpgen.tools.gen_series.required_terms``; a test checks
them). The exact branches cancel as s -> 0 (t - sin t, 1 - u cot u), but their absolute
error is ~eps / s^k where M ~ s^k, so the matrix error stays at a few eps down to small S0;
only their derivatives degrade (~eps / t0): at S0 = 1/4 the first derivative of the se3
dexp^{-1} reached 1.3e-15; S0 = 9/16 would be fine and ~5% smaller than S0 = 1, which is
kept because tests/hard_cases place arguments exactly on s = 1. Measured against 50-digit
mpmath, SO3 and SE3, |w| in [0, 3], |v| = 1, dense around S0 on both sides (max abs error
over max(1, max abs entry)): dexp^{-1} <= 2.0e-16, dexp <= 2.8e-16, exp <= 8.9e-16 (at
|w| = 3, the cancellation of Rodrigues' formula, as before), first derivatives <= 6.3e-16
(tests/unit/test_groups.py checks 1e-15). dexpinv_c has poles at t = 2 pi k (k >= 1),
where dexp^{-1} is singular; see the exp chart margin in ``maps``.

The exact Taylor coefficients are precomputed with sympy by ``hpgen.tools.gen_series`` into
``series_data`` (a test regenerates them and compares); nothing here imports sympy.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction

import casadi as ca

from .series_data import COEFFICIENTS

#: the branch point of every function, s < S0 (|w| < 1) uses the Taylor polynomials; a
#: square of a double (the tests put |w| exactly on it) and a multiple of 2^-4 (s_big exact)
S0 = 1.0


@dataclass(frozen=True)
class Spec:
    """One function of s: base function (series_data), derivative order (0 or 1, d/ds) and
    the number of Taylor terms used for s < S0."""
    base: str
    deriv: int
    terms: int


#: every function of s the chart maps use; adding one is one entry here, one exact formula
#: in ``Point.exact`` and, for a new base, one entry in ``hpgen.tools.gen_series.BASES``
SPECS = {
    "sinc": Spec("sinc", 0, 10),
    "cosc": Spec("cosc", 0, 9),
    "sinc3": Spec("sinc3", 0, 9),
    "dexpinv_c": Spec("dexpinv_c", 0, 11),
    "d_cosc": Spec("cosc", 1, 9),
    "d_sinc3": Spec("sinc3", 1, 8),
    "d_dexpinv_c": Spec("dexpinv_c", 1, 11),
}

#: size of the matrix factor each function multiplies in the maps, as a function of t = |w|,
#: |v| = 1 (for choosing the terms; see the module docstring)
WEIGHTS = {
    "sinc": lambda t: max(1.0, t),      # W in exp; v in the se3 translation
    "cosc": lambda t: max(1.0, t),      # W^2 in exp, W in dexp, V in se3 dexp, w x v
    "sinc3": lambda t: 2 * t,           # W^2, WV + VW
    "dexpinv_c": lambda t: 2 * t,       # W^2, WV + VW
    "d_cosc": lambda t: 2 * t * t,      # 2 (w.v) W
    "d_sinc3": lambda t: 2 * t**3,      # 2 (w.v) W^2
    "d_dexpinv_c": lambda t: 2 * t**3,  # 2 (w.v) W^2
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
    """The Taylor coefficients (in s, correctly rounded) used for SPECS[name]."""
    a = exact_coefficients(name)
    n = SPECS[name].terms
    if n > len(a):
        raise RuntimeError(f"{name}: series_data holds {len(a)} coefficients, {n} wanted")
    return tuple(float(c) for c in a[:n])


def threshold(name: str | None = None) -> float:
    """The branch point s0 of SPECS[name]: S0 for all, so that a map's functions share it."""
    if name is not None and name not in SPECS:
        raise KeyError(name)
    return S0


class Point:
    """The functions of SPECS at one s >= 0 (an SX scalar), sharing the branch and the
    transcendental calls (module docstring). ``P[name]`` is the value; ``P.taylor(name)`` and
    ``P.exact(name)`` are the two branches. With ``branch=False`` there is no branch:
    s_small = s_big = s (for comparing the two formulas at one s)."""

    def __init__(self, s, branch: bool = True):
        self.s = s
        if branch:
            self.small = s < S0
            self.big = 1 - self.small
            self.s_small = s * self.small
            self.s_big = S0 + (s - S0) * self.big
        else:
            self.small = self.big = None
            self.s_small = self.s_big = s
        self._cache: dict = {}

    def _memo(self, key, build):
        if key not in self._cache:
            self._cache[key] = build()
        return self._cache[key]

    def taylor(self, name: str):
        """Horner polynomial in s_small."""
        def build():
            c = coefficients(name)
            out = ca.SX(c[-1])
            for k in range(len(c) - 2, -1, -1):
                out = out * self.s_small + c[k]
            return out
        return self._memo(("taylor", name), build)

    def _u(self):
        return self._memo("u", lambda: 0.5 * ca.sqrt(self.s_big))

    def _q(self):  # sin(u) / u
        return self._memo("q", lambda: ca.sin(self._u()) / self._u())

    def _cos(self):  # cos(u)
        return self._memo("cos", lambda: ca.cos(self._u()))

    def _inv_s(self):
        return self._memo("1/s", lambda: 1 / self.s_big)

    def exact(self, name: str):
        """The exact formula at s_big (table of the module docstring)."""
        def build():
            f, r = self.exact, self._inv_s
            if name == "sinc":
                return self._q() * self._cos()
            if name == "cosc":
                return 0.5 * (self._q() * self._q())
            if name == "sinc3":
                return (1 - f("sinc")) * r()
            if name == "dexpinv_c":
                u = self._u()
                return (1 - u / ca.tan(u)) * r()
            if name == "d_cosc":
                return (0.5 * f("sinc") - f("cosc")) * r()
            if name == "d_sinc3":
                return (0.5 * f("cosc") - 1.5 * f("sinc3")) * r()
            if name == "d_dexpinv_c":
                c = f("dexpinv_c")
                return (0.125 - 1.5 * c) * r() + 0.5 * (c * c)
            raise KeyError(name)
        return self._memo(("exact", name), build)

    def __getitem__(self, name: str):
        if self.small is None:
            raise ValueError("an unbranched Point has no value; use taylor() or exact()")
        return self._memo(("value", name), lambda: (self.taylor(name) * self.small
                                                    + self.exact(name) * self.big))


# ---- single functions (tests, one-off use; the maps use one Point per map) ------------------
def taylor(name: str, s):
    """The Taylor branch of SPECS[name] at s, unbranched (accurate for 0 <= s < S0)."""
    return Point(s, branch=False).taylor(name)


def exact(name: str, s):
    """The exact branch of SPECS[name] at s, unbranched (valid for s > 0, used for s >= S0)."""
    return Point(s, branch=False).exact(name)


def branches(name: str, s):
    """(small, taylor(s_small), exact(s_big)): the two branches of ``evaluate``, each finite
    with finite derivatives of every order for every finite s >= 0."""
    P = Point(s)
    return P.small, P.taylor(name), P.exact(name)


def evaluate(name: str, s):
    """f(s) for s = t^2 >= 0, NaN-free with its derivatives (see the module docstring)."""
    return Point(s)[name]


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
