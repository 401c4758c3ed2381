"""The IR produced by the model stage: a validated, immutable description of a model file."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

#: names the Lagrangian may use besides parameters (see hpgen.model.expr for products)
RESERVED_NAMES = ("xi", "g", "R", "x", "dot", "sin", "cos", "tan", "exp", "log", "sqrt")


@dataclass(frozen=True)
class IntegratorChoice:
    """Defaults from the model's ``integrator:`` section (CLI flags / API arguments override).

    tableau: a catalog name (str) or a hpgen.tableaus.ButcherTableau built from {A, b}.
    tau: 'exp' | 'cay' | 'skew'.  rkmk: 'exact' | 'truncated' (the paper's q = 0).
    """
    tableau: Any = "stormer-verlet"
    tau: str = "cay"
    rkmk: str = "exact"


@dataclass(frozen=True)
class SectionSpec:
    """The scene's Poincare section s(g, mu): the runtime records its upward zero crossings
    (s < 0 at one node, s >= 0 at the next).

    text: the expression as written. expr: sympy scalar in ``mu_symbols`` (mu_0 .. mu_{d-1},
    real; the node momentum) and ``g_symbols`` (g_i_j, real, an n x n tuple of tuples),
    parameters substituted as for the Lagrangian; never xi. The g symbols are equal (==, same
    hash) to Model.g_symbols (same names and assumptions). expr depends on mu or on an entry of
    g that varies on the group. Built by hpgen.model.expr.parse_section (whitelist parser).
    """
    text: str
    expr: Any                      # sympy.Expr
    mu_symbols: tuple
    g_symbols: tuple


@dataclass(frozen=True)
class RecordExpr:
    """A user expression recorded at each sample: ``label`` (its array name) and ``text``
    as written; ``expr`` a sympy scalar in ``xi_symbols`` (xi_0..xi_{d-1}, the same
    symbols as Model.xi_symbols), ``mu_symbols`` (mu_0..mu_{d-1}, real, as SectionSpec's)
    and ``g_symbols`` (equal to Model.g_symbols), parameters substituted as for the
    Lagrangian. Built by hpgen.model.expr.parse_record (whitelist parser)."""
    label: str
    text: str
    expr: Any                      # sympy.Expr
    xi_symbols: tuple
    mu_symbols: tuple
    g_symbols: tuple


@dataclass(frozen=True)
class Scene:
    """What ``hpgen run`` simulates. g0 is an n x n tuple-of-tuples matrix on the group;
    exactly one of xi0 / mu0 is set (tuples of length d); section: the optional Poincare
    section (SectionSpec) or None. record: the names to record in file order, built-in names
    (hpgen.model.scene.RECORDABLE) and the labels of the user expressions; expressions: those
    expressions (RecordExpr, file order), looked up by label."""
    h: float
    steps: int
    g0: tuple
    xi0: tuple | None = None
    mu0: tuple | None = None
    record: tuple[str, ...] = ("g", "mu")
    every: int = 1
    section: SectionSpec | None = None
    expressions: tuple = ()        # tuple of RecordExpr, in file order


@dataclass(frozen=True)
class Model:
    """A validated model.

    lagrangian: sympy expression in the symbols ``xi_symbols`` (xi_0 .. xi_{d-1}) and
    ``g_symbols`` (g_i_j, an n x n tuple of tuples), parameters already substituted as exact
    binary floats. It was built by hpgen's own whitelist parser, never by eval/sympify.
    """
    name: str
    path: str                      # file name used in error messages ("<string>" if none)
    source: str                    # the model file's text, copied next to generated code
    group_spec: Any                # the ``group`` field as written (str or list of str)
    group: Any                     # hpgen.groups.LieGroup
    parameters: tuple              # ((name, value), ...), value float | tuple | tuple of tuples
    lagrangian_text: str
    lagrangian: Any                # sympy.Expr
    xi_symbols: tuple
    g_symbols: tuple
    integrator: IntegratorChoice = field(default_factory=IntegratorChoice)
    scene: Scene | None = None

    @property
    def left_invariant(self) -> bool:
        """True when l does not depend on g (the Euler-Poincare case)."""
        gs = {s for row in self.g_symbols for s in row}
        return not (self.lagrangian.free_symbols & gs)
