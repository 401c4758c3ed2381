"""Scalar functions of s = t^2 with removable singularities at s = 0, as branch-free
polynomials in the half angle (safe for casadi AD, cheap in the generated kernels).

The exp chart maps of ``hpgen.groups.maps`` need functions such as sin t / t whose exact
formula is 0/0 at t = 0 (docs/numerics.md sec. 6). A map evaluates every function it needs at one
``Point(s)``, s = t^2 = |w|^2. Everything is built from two entire functions of the half
angle u = t/2, x = u^2 = s/4 (exact in floating point):

    A(x) = (u - sin u) / u^3  = 1/6 - x/120 + ...     (series_data 'sinc3', in x)
    B(x) = (1 - cos u) / u^2  = 1/2 - x/24 + ...      (series_data 'cosc', in x)

each a polynomial of ``TERMS`` terms evaluated by Estrin's scheme (pairs c_2j + c_2j+1 x,
then x^2, x^4, ...: depth log2(n) instead of Horner's n, which halves the latency chain),
and combined without cancellation (q = sin u / u >= 2/pi and every sum below has terms of
one sign for t <= pi; cos u is only ever needed to absolute accuracy):

=============  ===========================  ==============================
name           f(s), t^2 = s                formula (q = 1 - x A)
=============  ===========================  ==============================
sinc           sin t / t                    q (1 - x B)         (= sinc u cos u)
cosc           (1 - cos t) / t^2            q^2 / 2             (= 2 sin^2 u / t^2)
sinc3          (t - sin t) / t^3            (A + q B) / 4
dexpinv_c      (1 - (t/2) cot(t/2)) / t^2   (B - A) / (4 q)     (u cot u = cos u / q)
d_cosc         d/ds cosc                    -q D / 8
d_sinc3        d/ds sinc3                   ((1 + q) A'/4 + q D'/4 - D B / 8) / 4
d_dexpinv_c    d/ds dexpinv_c               r D'/4 + c^2 / 2,   r = 1 / (4 q)
=============  ===========================  ==============================

with D = B - A (= 1/3 + (B - 1/2) - (A - 1/6), exactly 1/3 at s = 0), A' and D' the
x-derivatives as polynomials (coefficients (k + 1) a_{k+1}, each rounded once), and the
identity d(sin u / u)/dx = (A - B)/2, i.e. dq/ds = -D/8, which needs no derivative
polynomial (it holds for the truncated A, B up to their tails, below 2^-54). Every sum in
them has terms of one sign except c' = r D'/4 + c^2/2 (2:1 at t = pi, 5:3 at t = 0).

Why no branch (the previous design had one, at s = 1, with the closed forms on the other
side): casadi SX evaluates both sides of every if_else, so the closed-form side cost a
sqrt, sin, cos, tan, three divisions and the masks on every call, also for the small
arguments that actually occur (|h Theta| ~ 0.2 on the heavy top), and the derive stage
differentiates all of it twice more. The closed forms could not be moved to a much smaller
switch point either: their AD derivatives cancel (d/du (sin u / u) = (cos u - sin u / u)/u
loses ~1/u^2 digits), which forced the switch to s = 1 and 9-11 term Taylor branches. A and
B are entire, so polynomials cover the whole chart domain, and AD of a polynomial is a
polynomial: value and every derivative are accurate, and exactly finite at s = 0 (no NaN,
nothing to mask: docs/numerics.md sec. 6's branch rule is met trivially).

Accuracy domain: t <= T_MAX = pi, the exp chart's own domain (its margin (pi^2 - s)/(2 pi)
is > 0 exactly there; the runtime accepts a step only with every chart argument inside,
so values beyond T_MAX never reach an accepted result; they only steer Newton iterates,
which are then reported as DOMAIN errors). ``TERMS`` are the fewest for which the truncation
tail of each base, times the largest matrix factor it reaches at t = pi (``WEIGHTS``:
A enters exp through x A in q and W^2 ~ 4x: 4 x^2 + t x; B through x B in sinc, times
W ~ t: t x), is below 2^-54 for the value and for x d/dx
(``hpgen.tools.gen_series.required_terms``; a test checks them). Measured against 50-digit
mpmath (tests/unit/test_groups.py, tests/unit/test_maps_series.py): matrices of exp,
dexp^{-1}, dexp and their first directional derivatives on SO3 and SE3 within 1e-15 of
max(1, max entry) for |w| <= pi; the functions themselves within a few eps (relative for
s <= 0.2, weighted absolute up to pi^2). Beyond pi the truncation shows, smoothly: the
SO3 exp matrix is off by 4e-16 at |w| = 4, 3e-14 at 2 pi - 0.3, 2e-11 at 7, 5e-8 at 3 pi
and 1e-5 at 4 pi (dexpinv_c and its derivative relative 1e-12 at 2 pi - 0.3, next to their
pole at 2 pi). The maps and their first two derivatives stay finite up to |w| = 1e7 (at
1e8 the products of the degree-10 polynomials overflow; the margin is -1.6e15 there, and a
Newton iterate that far out is reported as a DOMAIN error). dexpinv_c has poles at
t = 2 pi k (k >= 1), where dexp^{-1} is singular (q = 0); see the exp chart margin in
``maps``.

Cost, measured against the branched design on heavy_top.yaml (gauss2, exp, exact RKMK,
default -O3, AMD EPYC, min of repeats, interleaved): the residual kernel 1055 -> 1006
casadi instructions with no sqrt/sin/cos/tan (3/2/2/3 before) and a latency chain of ~240
instead of ~330 cycles, 249 -> 156 ns per call (cay: 90 ns); the step 2.34 -> 1.59 us
(cay 1.01 us); residual_jacobian 7661 -> 7675 instructions, unchanged time. On SE3
(underwater_vehicle.yaml compiled with tau exp): residual 2320 -> 2252 and
residual_jacobian 26541 -> 26478 instructions, the step 4.51 -> 3.54 us, gcc time of the
module unchanged (~13 s).

The exact Taylor coefficients are precomputed with sympy by ``hpgen.tools.gen_series`` into
``series_data`` (a test regenerates them and compares); nothing here imports sympy.
"""
from __future__ import annotations

import functools
import math
from fractions import Fraction

import casadi as ca

from .series_data import COEFFICIENTS

#: accuracy domain of every function: t = |w| <= T_MAX (the exp chart's domain |w| < pi)
T_MAX = math.pi
#: the half-angle argument's bound, x = (t/2)^2 <= X_MAX
X_MAX = T_MAX**2 / 4

#: terms of the two base polynomials in x (series_data names: the base functions at u)
TERMS = {"sinc3": 11, "cosc": 11}

#: largest matrix factor a unit error in each base reaches at t (x = t^2/4), for choosing
#: TERMS (see the module docstring; hpgen.tools.gen_series.required_terms)
WEIGHTS = {
    "sinc3": lambda t: 4 * (t * t / 4)**2 + t * (t * t / 4),   # A: x A in q, q^2/2 W^2
    "cosc": lambda t: t * (t * t / 4),                         # B: x B in sinc, sinc W
}

#: every function of s a Point provides (module docstring table)
NAMES = ("sinc", "cosc", "sinc3", "dexpinv_c", "d_cosc", "d_sinc3", "d_dexpinv_c")


@functools.lru_cache(maxsize=None)
def exact_coefficients(base: str) -> tuple[Fraction, ...]:
    """All the stored Taylor coefficients of a base function in x, as exact fractions."""
    return tuple(Fraction(p, q) for p, q in COEFFICIENTS[base])


@functools.lru_cache(maxsize=None)
def coefficients(base: str, deriv: int = 0) -> tuple[float, ...]:
    """The coefficients (in x, correctly rounded) of the polynomial used for a base
    (deriv = 0) or of its derivative d/dx (deriv = 1: (k + 1) a_{k+1}, one term fewer)."""
    a = exact_coefficients(base)
    n = TERMS[base]
    if n > len(a):
        raise RuntimeError(f"{base}: series_data holds {len(a)} coefficients, {n} wanted")
    a = a[:n]
    for _ in range(deriv):
        a = tuple((k + 1) * a[k + 1] for k in range(len(a) - 1))
    return tuple(float(c) for c in a)


@functools.lru_cache(maxsize=None)
def difference_derivative_coefficients() -> tuple[float, ...]:
    """Coefficients of D'(x), D = B - A (the polynomials as used), each rounded once."""
    a, b = exact_coefficients("sinc3"), exact_coefficients("cosc")
    n = min(TERMS["sinc3"], TERMS["cosc"])
    return tuple(float((k + 1) * (b[k + 1] - a[k + 1])) for k in range(n - 1))


def polynomial(c, x):
    """sum_k c[k] x^k by Estrin's scheme: (c0 + c1 x) + (c2 + c3 x) x^2 + ..., paired again
    in x^2, x^4, ... (latency log2(n) multiply-adds instead of Horner's n)."""
    terms = [c[k] + c[k + 1] * x if k + 1 < len(c) else ca.SX(c[k])
             for k in range(0, len(c), 2)]
    p = x
    while len(terms) > 1:
        p = p * p
        terms = [terms[k] + terms[k + 1] * p if k + 1 < len(terms) else terms[k]
                 for k in range(0, len(terms), 2)]
    return terms[0]


class Point:
    """The functions of ``NAMES`` at one s >= 0 (an SX scalar), sharing the two base
    polynomials and the half-angle quantities (module docstring). ``P[name]`` is the value."""

    def __init__(self, s):
        self.s = s
        self.x = 0.25 * s
        self._cache: dict = {}

    def _memo(self, key, build):
        if key not in self._cache:
            self._cache[key] = build()
        return self._cache[key]

    def base(self, base: str, deriv: int = 0):
        """A (base 'sinc3') or B ('cosc') at x, or their x-derivative (deriv = 1)."""
        if deriv:
            return self._memo(("base", base, deriv),
                              lambda: polynomial(coefficients(base, deriv), self.x))
        return self._memo(("base", base), lambda: coefficients(base)[0] + self._rest(base))

    def _rest(self, base):
        """A - 1/6, B - 1/2: the polynomials without their constant terms (so that
        B - A = 1/3 + (B - 1/2) - (A - 1/6) rounds once, exactly 1/3 at s = 0)."""
        return self._memo(("rest", base),
                          lambda: polynomial((0.0,) + coefficients(base)[1:], self.x))

    def _b_minus_a(self):  # B - A, from 1/3 at s = 0
        a0, b0 = exact_coefficients("sinc3")[0], exact_coefficients("cosc")[0]
        return self._memo("B-A", lambda: float(b0 - a0)
                          + (self._rest("cosc") - self._rest("sinc3")))

    def _q(self):  # sin u / u
        return self._memo("q", lambda: 1 - self.x * self.base("sinc3"))

    def _r4q(self):  # 1 / (4 q), shared by dexpinv_c and d_dexpinv_c
        return self._memo("1/4q", lambda: 1 / (4 * self._q()))

    def _dd(self):  # D'(x), D = B - A
        return self._memo("D'", lambda: polynomial(difference_derivative_coefficients(),
                                                   self.x))

    def __getitem__(self, name: str):
        def build():
            A, B, q = self.base("sinc3"), self.base("cosc"), self._q()
            if name == "sinc":
                return q * (1 - self.x * B)
            if name == "cosc":
                return 0.5 * (q * q)
            if name == "sinc3":
                return 0.25 * (A + q * B)
            if name == "dexpinv_c":
                return self._b_minus_a() * self._r4q()
            D = self._b_minus_a()
            if name == "d_cosc":  # q dq/ds, dq/ds = -D/8 (d(sin u/u)/dx = (A - B)/2)
                return -0.125 * (q * D)
            if name == "d_sinc3":  # (A_s + q_s B + q B_s) / 4, B' = D' + A'
                dA, dD = self.base("sinc3", 1), self._dd()
                return 0.25 * (0.25 * (dA * (1 + q)) + 0.25 * (q * dD) - 0.125 * (D * B))
            if name == "d_dexpinv_c":  # c = D r, r = 1/(4q), r_s = D r^2 / 2
                c = self["dexpinv_c"]
                return 0.25 * (self._r4q() * self._dd()) + 0.5 * (c * c)
            raise KeyError(name)
        return self._memo(("value", name), build)


# ---- single functions (tests, one-off use; the maps use one Point per map) ------------------
def evaluate(name: str, s):
    """f(s) for s = t^2 >= 0, NaN-free with all its derivatives (module docstring)."""
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
