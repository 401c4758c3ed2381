"""The registry of scheme options: chart maps (tau), RKMK constraints (rkmk) and backends,
each registered once, plus the lookup of the tableau catalog.

Everything that names, validates or lists these choices reads them from here: the API's
CompileOptions, the model file's ``integrator:`` section, derive, codegen, the runtime
loader, the CLI's ``choices`` and help texts, ``hpgen list`` and the order-of-convergence
test matrix. Standard library only (the runtime reads ``BACKENDS`` from here without the
compile-time stack); the implementations stay with their stage:

- a chart map: its ``ChartMap`` entry here (name, groups, domain) and its formulas in
  ``hpgen.groups.maps`` (one ``GroupCharts`` per group family, dispatched by table);
- an RKMK constraint: its ``RkmkVariant`` here (with the order it caps the scheme at) and the
  constraint in ``hpgen.derive.action``;
- a backend: its ``Backend`` here and its loader in ``hpgen.runtime``;
- a tableau: one entry in ``hpgen.tableaus.catalog`` (A, b, order, summary); ``tableaus()``
  reads that catalog (it imports mpmath, not sympy/casadi/jinja2);
- a splitting scheme (explicit, for l = 1/2 xi.M xi - V(g); chosen where a tableau is): one
  entry in ``hpgen.splitting.coefficients`` (composition coefficients, order, summary);
  ``splittings()`` reads that catalog, ``is_splitting(name)`` tells them from tableaus;
- a composition of a symmetric step (``integrator.compose``): one entry in
  ``hpgen.tableaus.composition`` (a name of the splitting catalog's coefficients, summary);
  ``compositions()`` reads that catalog. The runtime composes the compiled step.

Choices are listed in registration order, which is the order of CLI choices and messages.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from .errors import ModelError


@dataclass(frozen=True)
class Choice:
    """One registered value of an option; ``summary`` is its line in ``hpgen list``."""
    name: str
    summary: str


@dataclass(frozen=True)
class ChartMap(Choice):
    """A chart map tau: g -> G. ``groups``: the group families (``hpgen.groups.GROUP_NAMES``
    spelling) that implement it, None for every group (and so every product of groups);
    ``domain``: where steps may evaluate it (where ``tau_margin`` > 0), in words;
    ``radius``: that domain as |omega| < radius, omega the rotation part of a chart argument
    (the runtime's message for a start outside it)."""
    groups: tuple[str, ...] | None
    domain: str
    radius: float = math.inf

    def on(self, family: str) -> bool:
        """Whether the group family ``family`` (e.g. "SO3", "R<n>") implements this chart."""
        return self.groups is None or family in self.groups

    @property
    def groups_text(self) -> str:
        return "all groups" if self.groups is None else ", ".join(self.groups)


@dataclass(frozen=True)
class RkmkVariant(Choice):
    """An RKMK constraint on the stage velocities; ``order_cap``: the order it limits the
    scheme to (None: the tableau's order is kept)."""
    order_cap: int | None

    def order(self, tableau_order: int) -> int:
        """The classical order of the scheme built from a tableau of order ``tableau_order``."""
        return tableau_order if self.order_cap is None else min(tableau_order, self.order_cap)


@dataclass(frozen=True)
class Backend(Choice):
    """A way to run the generated kernels."""


@dataclass(frozen=True)
class Option:
    """One option (``tau``, ``rkmk``, ``backend``) and its registered entries, in order."""
    name: str
    what: str          # what the option chooses, for help texts and ``hpgen list``
    entries: tuple

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(e.name for e in self.entries)

    def get(self, name: str):
        """The entry called ``name``; ModelError (field ``integrator.<option>``) if unknown."""
        for e in self.entries:
            if e.name == name:
                return e
        raise ModelError(f"{self.expected()}, got {name!r}", field=f"integrator.{self.name}")

    def expected(self) -> str:
        return f"expected one of {', '.join(self.names)}"

    def check(self, value, field: str, show=repr) -> str:
        """``value`` if it is a registered name, else ModelError(field) in the one-line form
        ``expected one of a, b, got <show(value)>``."""
        if not isinstance(value, str) or value not in self.names:
            raise ModelError(f"{self.expected()}, got {show(value)}", field=field)
        return value

    def help(self, tail: str) -> str:
        """CLI help: ``<what>: name (summary), ...; <tail>``."""
        return (f"{self.what}: " + ", ".join(f"{e.name} ({e.summary})" for e in self.entries)
                + f"; {tail}")


# ---- the registry: one entry per choice ------------------------------------------------------
TAU = Option("tau", "chart map", (
    ChartMap("exp", "exponential map", None,
             "|omega| < pi (margin (pi^2 - |omega|^2) / (2 pi))", math.pi),
    ChartMap("cay", "Cayley map", None,
             "|omega|^2 < 4, at most a quarter turn per evaluation", 2.0),
    ChartMap("skew", "inverse of g -> (g - g^T)/2", ("SO2", "SO3"),
             "|omega|^2 < 1/2, the fold of the discrete Legendre map", math.sqrt(0.5)),
))
RKMK = Option("rkmk", "RKMK constraint", (
    RkmkVariant("exact", "R = dtau^-1 Xi, keeps the tableau's order", None),
    RkmkVariant("truncated", "the paper's q = 0, R = Xi, order <= 2", 2),
))
BACKEND = Option("backend", "backend", (
    Backend("c", "the generated C, compiled once and loaded with ctypes"),
    Backend("python", "the generated Python kernels, no C compiler needed"),
))

TAU_CHOICES = TAU.names
RKMK_CHOICES = RKMK.names
BACKENDS = BACKEND.names
#: the options a generated module is specialized for (its name and header list them)
OPTION_KEYS = ("tableau", "tau", "rkmk")


def charts_on(family: str) -> tuple[str, ...]:
    """The chart maps the group family ``family`` implements, in registry order."""
    return tuple(c.name for c in TAU.entries if c.on(family))


def scheme_order(tableau_order: int, rkmk: str) -> int:
    """The classical order of a scheme: the tableau's, capped by its RKMK constraint."""
    return RKMK.get(rkmk).order(tableau_order)


def tableaus():
    """The catalog tableaus (``hpgen.tableaus.ButcherTableau``), in catalog order."""
    from .tableaus import TABLEAU_NAMES, get_tableau
    return tuple(get_tableau(name) for name in TABLEAU_NAMES)


def splittings():
    """The catalog splitting schemes (``hpgen.splitting.SplittingScheme``), in catalog order."""
    from .splitting import SPLITTING_NAMES, get_splitting
    return tuple(get_splitting(name) for name in SPLITTING_NAMES)


def compositions():
    """The catalog compositions of a symmetric step (``hpgen.tableaus.composition``), in
    catalog order."""
    from .tableaus.composition import COMPOSITION_NAMES, get_composition
    return tuple(get_composition(name) for name in COMPOSITION_NAMES)


def is_splitting(spec) -> bool:
    """Whether ``spec`` (a name or a scheme object) is a splitting scheme, not a tableau."""
    from .splitting import is_splitting as check
    return check(spec)
