"""Butcher tableaus: validation, order from rooted-tree conditions, the catalog."""
from __future__ import annotations

import dataclasses
import math

import mpmath as mp
import pytest

from hpgen.errors import ModelError
from hpgen.tableaus import (TABLEAU_NAMES, ButcherTableau, compute_order, get_tableau,
                            resolve_tableau, rooted_trees)

EXPECTED = {  # name: (stages, order, is_symplectic, is_explicit)
    "euler-forward": (1, 1, False, True),
    "euler-backward": (1, 1, False, False),
    "stormer-verlet": (2, 2, False, False),
    "midpoint": (1, 2, True, False),
    "gauss2": (2, 4, True, False),
    "gauss3": (3, 6, True, False),
    "lobatto3a3": (3, 4, False, False),
}


def _radau2a3():
    r6 = math.sqrt(6)
    A = [[(88 - 7 * r6) / 360, (296 - 169 * r6) / 1800, (-2 + 3 * r6) / 225],
         [(296 + 169 * r6) / 1800, (88 + 7 * r6) / 360, (-2 - 3 * r6) / 225],
         [(16 - r6) / 36, (16 + r6) / 36, 1 / 9]]
    return A, A[2]


def test_names_contract():
    assert TABLEAU_NAMES == tuple(EXPECTED)


def test_tree_counts():
    assert [len(rooted_trees(p)) for p in range(1, 7)] == [1, 1, 2, 4, 9, 20]


@pytest.mark.parametrize("name", TABLEAU_NAMES)
def test_catalog_entry(name):
    t = get_tableau(name)
    stages, order, sympl, expl = EXPECTED[name]
    assert (t.name, t.stages, t.order, t.is_symplectic, t.is_explicit) == \
        (name, stages, order, sympl, expl)
    assert all(isinstance(a, float) for r in t.A for a in r)
    assert abs(sum(t.b) - 1) < 1e-15
    assert t.c == tuple(math.fsum(r) for r in t.A)
    # from_user recomputes the same order, also when given c
    u = ButcherTableau.from_user([list(r) for r in t.A], list(t.b), c=list(t.c), name=name)
    assert u.order == t.order and u == t
    assert resolve_tableau(name) is t and resolve_tableau(t) is t


def test_irrational_entries_are_correctly_rounded():
    g2, g3 = get_tableau("gauss2"), get_tableau("gauss3")
    r3, r15 = math.sqrt(3), math.sqrt(15)
    assert g2.c[0] == pytest.approx(0.5 - r3 / 6, abs=1e-16)
    assert g3.c[0] == pytest.approx(0.5 - r15 / 10, abs=1e-16)
    assert g3.c[1] == pytest.approx(0.5, abs=1e-16)
    with mp.workdps(50):  # each entry is the double nearest to its exact value
        assert g3.A[0][1] == float(mp.mpf(2) / 9 - mp.sqrt(15) / 15)
        assert g3.A[1][0] == float(mp.mpf(5) / 36 + mp.sqrt(15) / 24)
        assert g2.A[0][1] == float(mp.mpf(1) / 4 - mp.sqrt(3) / 6)


def test_order_of_known_methods():
    rk4 = ([[0, 0, 0, 0], [.5, 0, 0, 0], [0, .5, 0, 0], [0, 0, 1, 0]], [1 / 6, 1 / 3, 1 / 3, 1 / 6])
    three8 = ([[0, 0, 0, 0], [1 / 3, 0, 0, 0], [-1 / 3, 1, 0, 0], [1, -1, 1, 0]],
              [1 / 8, 3 / 8, 3 / 8, 1 / 8])
    heun = ([[0, 0], [1, 0]], [.5, .5])
    radau2 = ([[5 / 12, -1 / 12], [3 / 4, 1 / 4]], [3 / 4, 1 / 4])
    for (A, b), p in ((rk4, 4), (three8, 4), (heun, 2), (radau2, 3), (_radau2a3(), 5)):
        t = ButcherTableau.from_user(A, b)
        assert t.order == p and t.name == "user"
    assert ButcherTableau.from_user(*rk4).is_explicit
    assert compute_order(*rk4, max_order=3) == 3


def test_constructor_checks_claimed_order():
    with pytest.raises(ModelError, match="claimed order 3.*fail at order 3"):
        ButcherTableau("bad", ((0.5,),), (1.0,), 3)
    with pytest.raises(ModelError, match="positive integer"):
        ButcherTableau("bad", ((0.5,),), (1.0,), 0)


def test_frozen_and_hashable():
    t = get_tableau("gauss2")
    with pytest.raises(dataclasses.FrozenInstanceError):
        t.order = 3  # type: ignore[misc]
    assert hash(t) == hash(ButcherTableau.from_user([list(r) for r in t.A], list(t.b),
                                                    name="gauss2"))


@pytest.mark.parametrize("A,b,c,pattern", [
    ([[0.5, 0.5], [0.5, 0.5]], [1.0, 0.0], None, r"b\[1\] = 0.0.*divides by b_j"),
    ([[0, 0], [1, 0]], [1e-15, 1 - 1e-15], None, r"b\[0\].*nonzero"),
    ([[0, 0], [1]], [0.5, 0.5], None, "A must be a square list of lists"),
    ([[0, 0, 0], [1, 0, 0]], [0.5, 0.5], None, "A must be a square list of lists"),
    ([], [], None, "A must be a square list of lists"),
    ("AB", [1], None, "A must be a square list of lists"),
    ([[0, 0], [1, 0]], [1.0], None, "b must have s = 2 entries"),
    ([[0, 0], [1, 0]], [0.5, 0.5], [0.0, 0.5], r"row 1 of A sums to 1.0 but c\[1\] = 0.5"),
    ([[0, 0], [1, 0]], [0.5, 0.5], [0.0], "c must have s = 2 entries"),
    ([[0, 0], [1, float("nan")]], [0.5, 0.5], None, r"A\[1\]\[1\] must be finite"),
    ([[0, 0], [1, 0]], [float("inf"), 0.5], None, r"b\[0\] must be finite"),
    ([[0, 0], [1, "x"]], [0.5, 0.5], None, r"A\[1\]\[1\] must be a real number"),
    ([[0, 0], [1, 0]], [0.5, 0.6], None, r"sum to 1 \(consistency\)"),
])
def test_rejections(A, b, c, pattern):
    with pytest.raises(ModelError, match=pattern) as err:
        ButcherTableau.from_user(A, b, c)
    assert err.value.field == "integrator.tableau"


def test_unknown_names():
    with pytest.raises(ModelError) as err:
        get_tableau("rk4")
    assert err.value.field == "integrator.tableau"
    assert all(n in str(err.value) for n in TABLEAU_NAMES)
    with pytest.raises(ModelError, match="expected a tableau name"):
        resolve_tableau(3)
