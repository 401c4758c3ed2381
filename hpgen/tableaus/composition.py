"""The catalog of compositions of a compiled symmetric step.

A composition ``c`` with coefficients gamma_1 .. gamma_s (symmetric, summing to 1) turns the
module's step S(h) (a symmetric implicit scheme: a symmetric tableau with exact RKMK steps)
into the step

    Phi(h) = S(gamma_s h) o ... o S(gamma_1 h),

each substep a full Newton solve of the same compiled kernels with h_i = gamma_i h. A
symmetric composition of a symmetric method of order 2 with these coefficients has the order
given (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed., sec. V.3). The
coefficients are those of the splitting catalog (hpgen.splitting.coefficients): one table.

Refused with one line (field ``integrator.compose``): an unknown name, more than
MAX_STAGES stages (the C run keeps one predictor offset per substep in a fixed array), a base
scheme that is not symmetric (a non-symmetric tableau, an explicit splitting scheme). Standard library plus mpmath only (``hpgen list`` and the runtime's
loader read it).
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

from ..errors import ModelError
from ..splitting.coefficients import get_splitting

FIELD = "integrator.compose"
#: the most substeps a composed step may have (HPGEN_CS_MAX in hpgen_runtime.h)
MAX_STAGES = 9
#: how far A_ij + A_{s+1-i, s+1-j} - b_j and b_j - b_{s+1-j} may be from 0 for a symmetric
#: tableau (catalog entries are exact to round-off of their 50-digit values)
SYMMETRY_TOL = 1e-12

# name -> (splitting catalog entry, summary)
_ENTRIES = {
    "yoshida4": ("split4-yoshida", "Yoshida's triple jump, order 4, 3 substeps"),
    "suzuki4": ("split4-suzuki", "Suzuki's fractal, order 4, 5 substeps"),
    "yoshida6": ("split6-yoshida", "Yoshida's order 6 (solution A), 7 substeps"),
    "kahan-li6": ("split6-kahan-li", "Kahan-Li s9odr6a, order 6, 9 substeps"),
}
#: the catalog's names, in catalog order
COMPOSITION_NAMES = tuple(_ENTRIES)


@dataclass(frozen=True)
class Composition:
    """A composition: ``gammas`` the s substep fractions (floats), ``order`` the order of the
    composed step when the base step is symmetric of order 2, ``summary`` its line in
    ``hpgen list``."""
    name: str
    gammas: tuple
    order: int
    summary: str

    @property
    def stages(self) -> int:
        return len(self.gammas)


@functools.lru_cache(maxsize=None)
def get_composition(name) -> Composition:
    """The catalog composition ``name``; ModelError (field integrator.compose) if unknown."""
    if not isinstance(name, str) or name not in _ENTRIES:
        raise ModelError(f"expected one of {', '.join(COMPOSITION_NAMES)}, got {name!r}",
                         field=FIELD)
    split, summary = _ENTRIES[name]
    sc = get_splitting(split)
    if sc.stages > MAX_STAGES:
        raise AssertionError(f"composition {name}: {sc.stages} > {MAX_STAGES} stages")
    return Composition(name, sc.gammas, sc.order, summary)


def is_symmetric_tableau(A, b, tol: float = SYMMETRY_TOL) -> bool:
    """Whether the Runge-Kutta tableau (A, b) is symmetric: b_{s+1-j} = b_j and
    A_{s+1-i, s+1-j} + A_ij = b_j for all i, j (Hairer, Lubich, Wanner, sec. V.2.2)."""
    s = len(b)
    return all(abs(b[s - 1 - j] - b[j]) <= tol for j in range(s)) and all(
        abs(A[s - 1 - i][s - 1 - j] + A[i][j] - b[j]) <= tol
        for i in range(s) for j in range(s))


def check_base(tableau: str) -> None:
    """ModelError (field integrator.compose) unless the module's tableau (a catalog name) is
    symmetric: a composition of a non-symmetric step does not raise its order. With
    rkmk: truncated a symmetric tableau's step is symmetric (the chart maps satisfy
    tau(-x) = tau(x)^-1; tests/property/test_composition.py checks step(-h) o step(h) = id);
    with rkmk: exact it is not when l depends on g (docs/numerics.md, compositions), which
    this check does not see: `hpgen check --compose` measures S(-h) S(h) - id."""
    from ..splitting import is_splitting
    from . import TABLEAU_NAMES, get_tableau
    if is_splitting(tableau):
        raise ModelError(f"the splitting scheme {tableau} is already a composition; compose "
                         "applies to an implicit symmetric tableau", field=FIELD)
    if tableau not in TABLEAU_NAMES:
        raise ModelError(f"the base scheme must be a symmetric catalog tableau; {tableau!r} "
                         "is not in the catalog", field=FIELD)
    tab = get_tableau(tableau)
    if not is_symmetric_tableau(tab.A, tab.b):
        raise ModelError(f"the tableau {tableau} is not symmetric: a composition does not "
                         "raise its order", field=FIELD)
