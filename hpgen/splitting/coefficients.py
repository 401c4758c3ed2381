"""The catalog of composition coefficients for the explicit splitting schemes.

A splitting scheme is the symmetric composition

    Phi(h) = S(gamma_1 h) S(gamma_2 h) ... S(gamma_s h),   gamma_{s+1-i} = gamma_i,

of a symmetric second-order basic step S (hpgen.splitting.flows: potential kick, exact
kinetic sub-flows, potential kick). Symmetric compositions of a symmetric order-2 step
with these coefficients have the order given (Hairer, Lubich, Wanner, Geometric Numerical
Integration, 2nd ed., sec. V.3.2). Coefficients are typed from the published tables to 26
digits, or computed from their closed forms in 50 digits; every entry is checked on import:
symmetric, sum(gamma) = 1 to the typed precision, and the odd-order condition
sum(gamma^3) = 0 for order >= 4 (the measured orders are tested in tests/unit).

Standard library plus mpmath only (no casadi/sympy): ``hpgen list`` and the model loader
read this catalog.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import mpmath as mp

from ..errors import ModelError

#: the basic step's name in summaries
BASIC = "kick / exact kinetic sub-flows (principal-axis rotations, drifts) / kick"


@dataclass(frozen=True)
class SplittingScheme:
    """One composition scheme: ``gammas`` the s coefficients of the basic step (floats,
    symmetric, summing to 1), ``order`` its classical order, ``summary`` its line in
    ``hpgen list``. ``stages`` = s basic steps per step."""
    name: str
    gammas: tuple
    order: int
    summary: str

    @property
    def stages(self) -> int:
        return len(self.gammas)


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
    #: how far the typed tables may miss sum = 1 and sum gamma^3 = 0 (26 typed digits)
    _TYPED_TOL = mp.mpf("1e-24")
    for _name, (_g, _order, _) in _ENTRIES.items():
        if _g != _g[::-1] or abs(mp.fsum(_g) - 1) > _TYPED_TOL or (
                _order >= 4 and abs(mp.fsum(x ** 3 for x in _g)) > _TYPED_TOL):
            raise AssertionError(f"splitting coefficients {_name}: not a symmetric consistent "
                                 "composition of its order")

#: the catalog's names, in catalog order
SPLITTING_NAMES = tuple(_ENTRIES)


@functools.lru_cache(maxsize=None)
def get_splitting(name: str) -> SplittingScheme:
    """The catalog scheme ``name``; ModelError (field integrator.tableau) if unknown."""
    if not isinstance(name, str) or name not in _ENTRIES:
        raise ModelError(f"unknown splitting scheme {name!r}: expected one of "
                         f"{', '.join(SPLITTING_NAMES)}", field="integrator.tableau")
    g, order, summary = _ENTRIES[name]
    return SplittingScheme(name, tuple(float(x) for x in g), order, summary)


def is_splitting(spec) -> bool:
    """Whether ``spec`` names (or is) a splitting scheme."""
    return isinstance(spec, SplittingScheme) or (isinstance(spec, str) and spec in _ENTRIES)
