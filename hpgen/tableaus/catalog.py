"""Butcher tableaus (A, b) of the VPRK / Hamilton-Pontryagin methods and their catalog.

Conventions: s stages, A an s x s tuple of rows, b the s weights, c = row sums of A (the
stage nodes). The discrete Hamilton-Pontryagin principle (docs/numerics.md sec. 2) divides by every
b_j, so all weights must be nonzero; consistency requires sum(b) = 1. The VPRK method built
from ANY such tableau is symplectic; ``is_symplectic`` reports whether the Runge-Kutta method
itself is (b_i a_ij + b_j a_ji = b_i b_j).

``order`` is the classical Runge-Kutta order, checked from the order conditions of the rooted
trees up to order MAX_CHECKED_ORDER = 6 (37 trees): Phi(t) = 1/gamma(t), with the elementary
weight Phi(t) = b . g(t), g(leaf) = 1, g([t1 ... tm]) = prod_k (A g(t_k)) (componentwise) and
the density gamma(t) = |t| prod_k gamma(t_k); tolerance 1e-12.

Adding a tableau is one new entry in ``_ENTRIES`` (name -> CatalogEntry(A, b, order, summary));
the CLI, ``hpgen list`` and the order-of-convergence tests pick it up from there.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from numbers import Real

import mpmath as mp

from ..errors import ModelError

FIELD = "integrator.tableau"
TOL = 1e-12
WEIGHT_TOL = 1e-14
MAX_CHECKED_ORDER = 6


def _err(msg: str) -> ModelError:
    return ModelError(msg, field=FIELD)


# ---- rooted trees and order conditions -----------------------------------------------------
@functools.lru_cache(maxsize=None)
def rooted_trees(order: int) -> tuple[tuple, ...]:
    """All rooted trees with ``order`` vertices; a tree is the sorted tuple of its subtrees."""
    if order == 1:
        return ((),)
    out = set()
    for children in _forests(order - 1, order - 1):
        out.add(tuple(sorted(children)))
    return tuple(sorted(out))


def _forests(n: int, max_order: int):
    """Multisets of trees with n vertices in total, each tree of order <= max_order."""
    if n == 0:
        yield ()
        return
    for k in range(min(n, max_order), 0, -1):
        for t in rooted_trees(k):
            for rest in _forests(n - k, k):
                yield (t,) + rest


def _size(tree) -> int:
    return 1 + sum(_size(c) for c in tree)


def _density(tree) -> int:
    return _size(tree) * math.prod(_density(c) for c in tree)


def _stage_weights(A, tree) -> list[float]:
    s = len(A)
    g = [1.0] * s
    for child in tree:
        gc = _stage_weights(A, child)
        Ag = [math.fsum(A[i][j] * gc[j] for j in range(s)) for i in range(s)]
        g = [g[i] * Ag[i] for i in range(s)]
    return g


def order_residual(A, b, tree) -> float:
    """|Phi(t) - 1/gamma(t)| for one rooted tree."""
    g = _stage_weights(A, tree)
    return abs(math.fsum(bi * gi for bi, gi in zip(b, g)) - 1.0 / _density(tree))


def compute_order(A, b, max_order: int = MAX_CHECKED_ORDER, tol: float = TOL) -> int:
    """The largest p <= max_order such that every order condition up to order p holds."""
    for p in range(1, max_order + 1):
        if any(order_residual(A, b, t) > tol for t in rooted_trees(p)):
            return p - 1
    return max_order


# ---- validation helpers --------------------------------------------------------------------
def _is_seq(x) -> bool:
    return hasattr(x, "__len__") and hasattr(x, "__iter__") and not isinstance(x, (str, bytes,
                                                                                    dict))


def _number(x, where: str) -> float:
    if isinstance(x, bool) or not isinstance(x, Real):
        raise _err(f"{where} must be a real number, got {x!r}")
    v = float(x)
    if not math.isfinite(v):
        raise _err(f"{where} must be finite, got {v!r}")
    return v


def _matrix(A) -> tuple[tuple[float, ...], ...]:
    if not _is_seq(A) or len(A) == 0 or not all(_is_seq(r) for r in A):
        raise _err(f"A must be a square list of lists with at least one row, got {A!r}")
    s = len(A)
    if any(len(r) != s for r in A):
        raise _err(f"A must be a square list of lists, got rows of lengths "
                   f"{[len(r) for r in A]} for {s} rows")
    return tuple(tuple(_number(a, f"A[{i}][{j}]") for j, a in enumerate(r))
                 for i, r in enumerate(A))


def _vector(v, s: int, label: str) -> tuple[float, ...]:
    if not _is_seq(v):
        raise _err(f"{label} must be a list of {s} numbers, got {v!r}")
    if len(v) != s:
        raise _err(f"{label} must have s = {s} entries (one per stage, s = rows of A), "
                   f"got {len(v)}")
    return tuple(_number(x, f"{label}[{i}]") for i, x in enumerate(v))


# ---- the tableau ------------------------------------------------------------------------
@dataclass(frozen=True)
class ButcherTableau:
    """A validated Butcher tableau; ``order`` is its classical RK order (see module doc)."""
    name: str
    A: tuple[tuple[float, ...], ...]
    b: tuple[float, ...]
    order: int

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise _err(f"the tableau name must be a non-empty string, got {self.name!r}")
        A = _matrix(self.A)
        b = _vector(self.b, len(A), "b")
        object.__setattr__(self, "A", A)
        object.__setattr__(self, "b", b)
        for j, bj in enumerate(b):
            if abs(bj) <= WEIGHT_TOL:
                raise _err(f"{self.name}: b[{j}] = {bj!r}, but every weight must be nonzero: "
                           "the VPRK (Hamilton-Pontryagin) principle divides by b_j")
        if abs(math.fsum(b) - 1.0) > TOL:
            raise _err(f"{self.name}: the weights b must sum to 1 (consistency), got "
                       f"sum(b) = {math.fsum(b)!r}")
        if isinstance(self.order, bool) or not isinstance(self.order, int) or self.order < 1:
            raise _err(f"{self.name}: order must be a positive integer, got {self.order!r}")
        checked = compute_order(A, b, min(self.order, MAX_CHECKED_ORDER))
        if checked < min(self.order, MAX_CHECKED_ORDER):
            raise _err(f"{self.name}: claimed order {self.order}, but the order conditions "
                       f"fail at order {checked + 1}")

    @property
    def stages(self) -> int:
        return len(self.b)

    @property
    def c(self) -> tuple[float, ...]:
        """The nodes, c_i = sum_j a_ij."""
        return tuple(math.fsum(r) for r in self.A)

    @property
    def is_symplectic(self) -> bool:
        """Whether the RK method itself is symplectic (the VPRK method always is)."""
        A, b, s = self.A, self.b, self.stages
        return all(abs(b[i] * A[i][j] + b[j] * A[j][i] - b[i] * b[j]) <= TOL
                   for i in range(s) for j in range(s))

    @property
    def is_explicit(self) -> bool:
        """a_ij = 0 for j >= i."""
        return all(self.A[i][j] == 0.0 for i in range(self.stages)
                   for j in range(i, self.stages))

    @classmethod
    def from_user(cls, A, b, c=None, name: str = "user") -> "ButcherTableau":
        """Validate a user tableau (c optional, checked against row sums) and compute its order."""
        Af = _matrix(A)
        s = len(Af)
        bf = _vector(b, s, "b")
        if c is not None:
            cf = _vector(c, s, "c")
            for i, (row, ci) in enumerate(zip(Af, cf)):
                if abs(math.fsum(row) - ci) > TOL:
                    raise _err(f"row {i} of A sums to {math.fsum(row)!r} but c[{i}] = {ci!r}: "
                               "the rows of A must sum to c")
        # weights and consistency are checked by __post_init__ (order 0 never reaches it)
        return cls(name, Af, bf, compute_order(Af, bf))


# ---- catalog -----------------------------------------------------------------------------
@dataclass(frozen=True)
class CatalogEntry:
    """One catalog tableau as exact data: A, b (mpmath numbers or ints), its classical order
    (checked by ButcherTableau) and a one-line summary for ``hpgen list``."""
    A: list
    b: list
    order: int
    summary: str


def _q(p, r=1):
    return mp.mpf(p) / r


with mp.workdps(50):  # irrational entries in 50 digits, rounded once to double
    _R3, _R15 = mp.sqrt(3), mp.sqrt(15)
    #: name -> CatalogEntry; the order of TABLEAU_NAMES is the order of this dict
    _ENTRIES = {
        "euler-forward": CatalogEntry([[0]], [1], 1, "variational Euler, explicit stage"),
        "euler-backward": CatalogEntry([[1]], [1], 1, "variational Euler, implicit stage"),
        "stormer-verlet": CatalogEntry(  # the paper's Stormer-Verlet: trapezoid / Lobatto IIIA
            [[0, 0], [_q(1, 2), _q(1, 2)]], [_q(1, 2), _q(1, 2)], 2,
            "the paper's Stormer-Verlet (Lobatto IIIA, 2 stages)"),
        "midpoint": CatalogEntry([[_q(1, 2)]], [1], 2, "implicit midpoint (Gauss, 1 stage)"),
        "gauss2": CatalogEntry([[_q(1, 4), _q(1, 4) - _R3 / 6],
                                [_q(1, 4) + _R3 / 6, _q(1, 4)]], [_q(1, 2), _q(1, 2)], 4,
                               "Gauss-Legendre, 2 stages"),
        "gauss3": CatalogEntry([[_q(5, 36), _q(2, 9) - _R15 / 15, _q(5, 36) - _R15 / 30],
                                [_q(5, 36) + _R15 / 24, _q(2, 9), _q(5, 36) - _R15 / 24],
                                [_q(5, 36) + _R15 / 30, _q(2, 9) + _R15 / 15, _q(5, 36)]],
                               [_q(5, 18), _q(4, 9), _q(5, 18)], 6, "Gauss-Legendre, 3 stages"),
        "lobatto3a3": CatalogEntry([[0, 0, 0], [_q(5, 24), _q(1, 3), _q(-1, 24)],
                                    [_q(1, 6), _q(2, 3), _q(1, 6)]],
                                   [_q(1, 6), _q(2, 3), _q(1, 6)], 4, "Lobatto IIIA, 3 stages"),
    }

TABLEAU_NAMES = tuple(_ENTRIES)


@functools.lru_cache(maxsize=None)
def _build(name: str) -> ButcherTableau:
    e = _ENTRIES[name]
    return ButcherTableau(name, tuple(tuple(float(a) for a in r) for r in e.A),
                          tuple(float(x) for x in e.b), e.order)


def tableau_summary(name: str) -> str:
    """The one-line description of the catalog tableau ``name`` (for ``hpgen list``)."""
    get_tableau(name)
    return _ENTRIES[name].summary


def get_tableau(name) -> ButcherTableau:
    """The catalog tableau ``name``, or the splitting scheme ``name``
    (hpgen.splitting.SplittingScheme, chosen in the tableau's place); ModelError (field
    integrator.tableau) if unknown."""
    from ..splitting import SPLITTING_NAMES, get_splitting
    if isinstance(name, str) and name in SPLITTING_NAMES:
        return get_splitting(name)
    if not isinstance(name, str) or name not in _ENTRIES:
        raise _err(f"unknown tableau {name!r}: expected one of {', '.join(TABLEAU_NAMES)}, "
                   f"a splitting scheme ({', '.join(SPLITTING_NAMES)}) "
                   "or a user tableau {A: [[...]], b: [...]}")
    return _build(name)


def resolve_tableau(spec) -> ButcherTableau:
    """A catalog name -> its tableau; a ButcherTableau -> itself."""
    from ..splitting import SplittingScheme
    if isinstance(spec, (ButcherTableau, SplittingScheme)):
        return spec
    if isinstance(spec, str):
        return get_tableau(spec)
    raise _err(f"expected a tableau name ({', '.join(TABLEAU_NAMES)}) or a ButcherTableau, "
               f"got {spec!r}")
