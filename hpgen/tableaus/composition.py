"""The catalog of compositions of a compiled symmetric step.

A composition ``c`` with coefficients gamma_1 .. gamma_s (symmetric, summing to 1) turns the
module's step S(h) (a symmetric implicit scheme: a symmetric tableau with truncated RKMK
steps, see check_base) into the step

    Phi(h) = S(gamma_s h) o ... o S(gamma_1 h),

each substep a full Newton solve of the same compiled kernels with h_i = gamma_i h. A
symmetric composition of a symmetric method of order 2 with these coefficients has the order
given (Hairer, Lubich, Wanner, Geometric Numerical Integration, 2nd ed., sec. V.3). The
coefficients are those of the splitting catalog (hpgen.splitting.coefficients): one table.

Refused with one line (field ``integrator.compose``): an unknown name, more than
MAX_STAGES stages (the C run keeps one predictor offset per substep in a fixed array), and a
base step that is not symmetric (check_base): a non-symmetric tableau, an explicit splitting
scheme, ``rkmk: exact``, and a tableau with a stage point inside the step when the step
depends on g. Standard library plus mpmath only (``hpgen list`` and the runtime's loader read
it).
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


def check_base(tableau: str, *, rkmk: str, step_uses_g: bool, explicit: bool = True) -> None:
    """ModelError (field integrator.compose) unless the module's step S(h) is symmetric,
    S(-h) o S(h) = id: a composition of a non-symmetric step does not raise its order.
    ``tableau`` is the module's catalog name, ``rkmk`` its RKMK constraint, ``step_uses_g``
    meta.json's flag (the residual or the momentum update depends on g: l, a force or a
    constraint depends on g), ``explicit`` meta.json's (False for a splitting scheme on a
    constrained family model, hpgen.derive.family_split).

    Accepted: a one-stage splitting scheme on a constrained model (RATTLE around the
    symmetric basic step K(h/2) F(h) K(h/2): symmetric, order 2).

    Symmetric, and accepted: a symmetric tableau with rkmk: truncated (the chart maps
    satisfy tau(-x) = tau(x)^-1), provided the stage points g_k tau(h sum_j a_ij Xi_j) seen
    from the step's two ends coincide whenever the step evaluates them, i.e. the step does
    not depend on g or every stage point is a node (c_i in {0, 1}: Stormer-Verlet).
    Refused: rkmk: exact always (dtau^-1 of the stage chart points breaks the symmetry of
    every tableau with two or more stages, even for a left-invariant l), and a symmetric
    tableau with an interior stage point on a step that depends on g (docs/numerics.md,
    compositions, for the defects measured)."""
    from ..splitting import is_splitting
    from . import TABLEAU_NAMES, get_tableau
    if is_splitting(tableau) and not explicit:
        from ..splitting.coefficients import get_splitting
        if get_splitting(tableau).stages == 1:
            return
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
    if rkmk != "truncated":
        raise ModelError(f"rkmk {rkmk} does not keep the step of {tableau} symmetric "
                         "(S(-h) S(h) != id), so a composition does not raise its order; "
                         "use rkmk: truncated", field=FIELD)
    if step_uses_g and any(0.0 < c < 1.0 for c in tab.c):
        raise ModelError(f"the step of {tableau} is not symmetric on a model whose step "
                         "depends on g (a stage point inside the step), so a composition "
                         "does not raise its order; use tableau: stormer-verlet with rkmk: "
                         "truncated", field=FIELD)
