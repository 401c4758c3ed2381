"""The catalog of composition coefficients for the explicit splitting schemes.

A splitting scheme composes first-order half-steps: with phi(t) the potential kick followed
by the kinetic sub-flows (principal-axis rotations, drifts) over t, and phi*(t) its adjoint
(the same sub-flows in reverse order; hpgen.splitting.flows), a scheme is

    Phi(h) = phi(c_1 h), phi*(c_2 h), phi(c_3 h), ..., phi*(c_2s h)    (in the order applied),

``halves`` = (c_1, ..., c_2s), a palindrome summing to 1 (so Phi is symmetric and
consistent). Two kinds of table fill it:

- symmetric compositions Phi(h) = S(gamma_1 h) ... S(gamma_s h) of the symmetric
  second-order basic step S(t) = phi(t/2) phi*(t/2) (kick / kinetic sub-flows / kick):
  halves (gamma_1/2, gamma_1/2, gamma_2/2, ...). Their orders: Hairer, Lubich, Wanner,
  Geometric Numerical Integration, 2nd ed., sec. V.3.2. Typed to 26 digits or computed from
  their closed forms in 50 digits; checked on import: symmetric, sum(gamma) = 1 to the typed
  precision, sum(gamma^3) = 0 from order 4.
- compositions of phi and phi* (HLW sec. V.3.1, III.5: a splitting method for A + B with
  coefficients (a_i, b_i) is such a composition, a_1 = c_1, b_1 = c_1 + c_2, a_2 = c_2 + c_3,
  ...): McLachlan's order-4 method (closed form), Blanes and Moan's order-4 and order-6
  partitioned methods (15 digits as published; the middle coefficients from consistency).
  ``adjoint_first``: the scheme starts with phi* (rotations first, kicks inside). Checked on
  import: a palindrome summing to 1.

Every scheme's order is measured in tests/unit/test_splitting*.py.

Standard library plus mpmath only (no casadi/sympy): ``hpgen list`` and the model loader
read this catalog.
"""
from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass

import mpmath as mp

from ..errors import ModelError

#: the basic step's name in summaries
BASIC = "kick / exact kinetic sub-flows (principal-axis rotations, drifts) / kick"


@dataclass(frozen=True)
class SplittingScheme:
    """One composition scheme: ``halves`` the coefficients c_1 .. c_2s of the alternating
    half-steps phi, phi* (module docstring; a palindrome summing to 1), ``adjoint_first``
    whether the first is phi* (rotations first), ``order`` its classical order, ``summary``
    its line in ``hpgen list``, ``gammas`` the basic-step coefficients of a symmetric
    composition of S (empty for the phi/phi* tables). ``stages`` = s half-step pairs (basic
    steps) per step."""
    name: str
    gammas: tuple
    order: int
    summary: str
    halves: tuple = ()
    adjoint_first: bool = False
    #: how an asymmetric body's kinetic energy is split: "dlm" (one rotation per principal
    #: axis) or "fasso" (a symmetric top plus one small remainder rotation)
    kinetic: str = "dlm"

    @property
    def stages(self) -> int:
        return len(self.halves) // 2


def _half(*head):
    """The full symmetric list from its first half (middle entry last)."""
    head = [mp.mpf(x) for x in head]
    return head + head[-2::-1]


def _completed(*head):
    """The full symmetric list from its first half without the middle entry, the middle
    being 1 - 2 sum(head) (consistency)."""
    head = [mp.mpf(x) for x in head]
    return head + [1 - 2 * mp.fsum(head)] + head[::-1]


def _triple_jump(inner, order):
    """Yoshida's triple jump raising a symmetric method of order ``order`` by two."""
    w1 = 1 / (2 - mp.root(2, order + 1))
    w0 = 1 - 2 * w1
    return [w * g for w in (w1, w0, w1) for g in inner]


def _prk_halves(a_head, b_head):
    """The halves c_1 .. c_2s of the symmetric PRK method e^{a_1 hA} e^{b_1 hB} ...
    e^{b_s hB} e^{a_{s+1} hA} (A applied first) as phi/phi* halves, phi(t) = e^{tA} then
    e^{tB}: c_1 = a_1, c_{2i} = b_i - c_{2i-1}, c_{2i+1} = a_{i+1} - c_{2i}. ``a_head``,
    ``b_head``: the first entries as published; a = a_head, 1 - 2 sum(a_head), a_head
    reversed; b = b_head, m, m, b_head reversed with m = 1/2 - sum(b_head)."""
    a = [mp.mpf(x) for x in a_head]
    b = [mp.mpf(x) for x in b_head]
    m = mp.mpf(1) / 2 - mp.fsum(b)
    a, b = a + [1 - 2 * mp.fsum(a)] + a[::-1], b + [m, m] + b[::-1]
    c = [a[0]]
    for i, bi in enumerate(b):
        c.append(bi - c[-1])
        if i + 1 < len(b):
            c.append(a[i + 1] - c[-1])
    if abs(c[-1] - a[-1]) > mp.mpf("1e-40"):
        raise AssertionError("a PRK table that is not symmetric")
    return c


def _mirror(head):
    """head followed by head reversed."""
    return list(head) + list(head)[::-1]


with mp.workdps(50):
    _Y4 = _triple_jump([mp.mpf(1)], 2)
    _SUZ = 1 / (4 - mp.cbrt(4))
    _ENTRIES = {
        "split2": ([mp.mpf(1)], 2,
                   "Strang / Dullweber-Leimkuhler-McLachlan, order 2, 1 stage"),
        "split4-yoshida": (_Y4, 4, "Yoshida's triple jump, order 4, 3 stages"),
        "split4-suzuki": ([_SUZ, _SUZ, 1 - 4 * _SUZ, _SUZ, _SUZ], 4,
                          "Suzuki's fractal, order 4, 5 stages"),
        "split6-yoshida": (_half("0.78451361047755726381949763",
                                 "0.23557321335935813368479318",
                                 "-1.17767998417887100694641568",
                                 "1.31518632068391121888424973"), 6,
                           "Yoshida's order 6, 7 stages (his solution A)"),
        "split6-kahan-li": (_half("0.39216144400731413927925056",
                                  "0.33259913678935943859974864",
                                  "-0.70624617255763935980996482",
                                  "0.08221359629355080023149045",
                                  "0.79854399093482996339895035"), 6,
                            "Kahan-Li s9odr6a, order 6, 9 stages"),
        "split8-mclachlan": (_half("0.74167036435061295344822780",
                                   "-0.40910082580003159399730010",
                                   "0.19075471029623837995387626",
                                   "-0.57386247111608226665638773",
                                   "0.29906418130365592384446354",
                                   "0.33462491824529818378495798",
                                   "0.31529309239676659663205666",
                                   "-0.79688793935291635401978884"), 8,
                             "McLachlan's order 8, 15 stages"),
        "split8-kahan-li": (_half("0.13020248308889008087881763",
                                  "0.56116298177510838456196441",
                                  "-0.38947496264484728640807860",
                                  "0.15884190655515560089621075",
                                  "-0.39590389413323757733623154",
                                  "0.18453964097831570709183254",
                                  "0.25837438768632204729397911",
                                  "0.29501172360931029887096624",
                                  "-0.60550853383003451169892108"), 8,
                            "Kahan-Li s17odr8a, order 8, 17 stages"),
    }
    _R19 = mp.sqrt(19)
    #: phi / phi* compositions: name -> (halves, order, summary, adjoint_first)
    _HALVES = {
        # McLachlan (1995), SIAM J. Sci. Comput. 16, 151-168: the order-4, 5-stage method of
        # minimal error, phi*_{b1} phi_{a1} ... phi*_{b5} phi_{a5} with a1 = b5 = (146 +
        # 5 sqrt19)/540, a2 = b4 = (-2 + 10 sqrt19)/135, a3 = b3 = 1/5, a4 = b2 = (-23 -
        # 20 sqrt19)/270, a5 = b1 = (14 - sqrt19)/108 (closed form)
        "split4-mclachlan": (
            _mirror([(14 - _R19) / 108, (146 + 5 * _R19) / 540, (-23 - 20 * _R19) / 270,
                     (-2 + 10 * _R19) / 135, mp.mpf(1) / 5]), 4,
            "McLachlan's order 4 (phi/phi*), 5 stages", True),
        # Blanes and Moan (2002), J. Comput. Appl. Math. 142, 313-330, Table 2: the PRK
        # methods of order 4 (6 stages) and 6 (10 stages), e^{a_1 hA} e^{b_1 hB} ... e^{a_{s+1}
        # hA}, A the kick: a = (0.0792036964311957, 0.353172906049774, -0.0420650803577195,
        # 1 - 2 sum), b = (0.209515106613362, -0.143851773179818, 1/2 - sum); order 6: a =
        # (0.0502627644003922, 0.413514300428344, 0.0450798897943977, -0.188054853819569,
        # 0.541960678450780, 1 - 2 sum), b = (0.148816447901042, -0.132385865767784,
        # 0.067307604692185, 0.432666402578175, 1/2 - sum)
        "split4-blanes-moan": (
            _prk_halves(["0.0792036964311957", "0.353172906049774", "-0.0420650803577195"],
                        ["0.209515106613362", "-0.143851773179818"]), 4,
            "Blanes-Moan PRK order 4, 6 stages", False),
        "split6-blanes-moan": (
            _prk_halves(["0.0502627644003922", "0.413514300428344", "0.0450798897943977",
                         "-0.188054853819569", "0.541960678450780"],
                        ["0.148816447901042", "-0.132385865767784", "0.067307604692185",
                         "0.432666402578175"]), 6,
            "Blanes-Moan PRK order 6, 10 stages", False),
    }
    for _name, _row in _HALVES.items():
        _c = _row[0]
        if max(abs(x - y) for x, y in zip(_c, _c[::-1])) > mp.mpf("1e-40") or \
                abs(mp.fsum(_c) - 1) > mp.mpf("1e-40"):
            raise AssertionError(f"splitting coefficients {_name}: not a symmetric consistent "
                                 "composition of phi and phi*")
    #: how far the typed tables may miss sum = 1 and sum gamma^3 = 0 (26 typed digits)
    _TYPED_TOL = mp.mpf("1e-24")
    for _name, (_g, _order, _) in _ENTRIES.items():
        if _g != _g[::-1] or abs(mp.fsum(_g) - 1) > _TYPED_TOL or (
                _order >= 4 and abs(mp.fsum(x ** 3 for x in _g)) > _TYPED_TOL):
            raise AssertionError(f"splitting coefficients {_name}: not a symmetric consistent "
                                 "composition of its order")

#: the tables' names, in catalog order (their kinetic part split as Dullweber-Leimkuhler-
#: McLachlan's rotations about the three principal axes)
TABLE_NAMES = tuple(_ENTRIES) + tuple(_HALVES)
#: the suffix of a table's variant with Fasso's kinetic splitting (a symmetric top and one
#: remainder rotation; hpgen.splitting.flows)
FASSO = "-fasso"
#: the catalog's names, in catalog order: the tables, then their Fasso variants
SPLITTING_NAMES = TABLE_NAMES + tuple(n + FASSO for n in TABLE_NAMES)


@functools.lru_cache(maxsize=None)
def get_splitting(name: str) -> SplittingScheme:
    """The catalog scheme ``name``; ModelError (field integrator.tableau) if unknown."""
    if not isinstance(name, str) or name not in SPLITTING_NAMES:
        raise ModelError(f"unknown splitting scheme {name!r}: expected one of "
                         f"{', '.join(SPLITTING_NAMES)}", field="integrator.tableau")
    if name.endswith(FASSO):
        base = get_splitting(name[:-len(FASSO)])
        return dataclasses.replace(base, name=name, kinetic="fasso",
                                   summary=base.summary + ", Fasso's kinetic splitting")
    if name in _HALVES:
        c, order, summary, adjoint_first = _HALVES[name]
        return SplittingScheme(name, (), order, summary, tuple(float(x) for x in c),
                               adjoint_first)
    g, order, summary = _ENTRIES[name]
    gammas = tuple(float(x) for x in g)
    return SplittingScheme(name, gammas, order, summary,
                           tuple(x / 2 for x in gammas for _ in range(2)))


def is_splitting(spec) -> bool:
    """Whether ``spec`` names (or is) a splitting scheme."""
    return isinstance(spec, SplittingScheme) or (isinstance(spec, str) and spec in SPLITTING_NAMES)
