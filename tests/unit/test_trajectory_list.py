"""LazyList (hpgen.runtime.trajectory_list): items made on first access, once; every list
operation gives what the list of all items gives."""
import copy
import pickle

import pytest

from hpgen.runtime.trajectory_list import LazyList


def _lazy(n=5):
    calls = []

    def make(i):
        calls.append(i)
        return ("item", i)

    return LazyList(n, make), calls


def test_items_made_on_access_once():
    a, calls = _lazy()
    assert isinstance(a, list) and len(a) == 5 and bool(a)
    assert calls == []
    x = a[3]
    assert x == ("item", 3) and calls == [3]
    assert a[3] is x and a[-2] is x and calls == [3]
    assert a[-1] == ("item", 4) and calls == [3, 4]
    with pytest.raises(IndexError):
        a[5]
    with pytest.raises(TypeError):
        a["0"]


def test_slices_and_iteration():
    a, calls = _lazy()
    assert a[1:4:2] == [("item", 1), ("item", 3)] and type(a[1:4:2]) is list
    assert sorted(set(calls)) == [1, 3]
    assert list(a) == [("item", i) for i in range(5)]
    assert [x for x in reversed(a)] == [("item", i) for i in range(4, -1, -1)]
    first, *rest = a
    assert first == ("item", 0) and len(rest) == 4
    assert len(calls) == 5                       # each item made once


def test_list_operations_see_all_items():
    a, _ = _lazy(3)
    b, _ = _lazy(3)
    full = [("item", i) for i in range(3)]
    assert a == b and a == full and full == b and not a != full
    assert ("item", 2) in b
    c, _ = _lazy(3)
    assert full + c == full + full and c + full == full + full
    d, _ = _lazy(3)
    assert repr(d) == repr(full) and d.index(("item", 1)) == 1 and d.count(("item", 0)) == 1
    e, _ = _lazy(3)
    e.append("x")
    assert e == full + ["x"]
    f, _ = _lazy(3)
    assert 2 * f == full * 2


def test_copies_and_pickles_are_plain_lists():
    full = [("item", i) for i in range(4)]
    for clone in (pickle.loads(pickle.dumps(_lazy(4)[0])), copy.copy(_lazy(4)[0]),
                  copy.deepcopy(_lazy(4)[0]), _lazy(4)[0].copy()):
        assert type(clone) is list and clone == full


def test_make_all_for_every_item_keeps_items_made():
    calls = []
    a = LazyList(4, lambda i: ["one", i], lambda: calls.append("all") or [["all", i]
                                                                          for i in range(4)])
    x = a[2]
    assert list(a) == [["all", 0], ["all", 1], ["one", 2], ["all", 3]] and calls == ["all"]
    assert a[2] is x and list(a) == list(a) and calls == ["all"]


def test_empty():
    a, calls = _lazy(0)
    assert a == [] and list(a) == [] and not a and calls == []


def test_simulate_batch_makes_members_on_access(compile_model):
    """An ensemble's members are made when looked at, each bitwise simulate's own run, the
    arrays read-only views of the ensemble's."""
    from pathlib import Path

    import numpy as np

    body = compile_model(Path(__file__).resolve().parents[2] / "examples"
                         / "free_rigid_body.yaml")
    mus = np.array([0.45, 0.0, 0.89]) * np.linspace(0.5, 2.0, 11)[:, None]
    out = body.simulate_batch(np.eye(3), 0.1, 40, mu0=mus, every=7, threads=2)
    assert isinstance(out, LazyList) and len(out) == 11
    assert all(list.__getitem__(out, b) is None for b in range(11))
    for b in (0, 9, 10):
        one = body.simulate(np.eye(3), 0.1, 40, mu0=mus[b], every=7)
        tr = out[b]
        assert tr is out[b] and tr.error is None and not tr.partial
        for name in ("t", "g", "mu"):
            assert np.array_equal(getattr(one, name), getattr(tr, name))
            assert not getattr(tr, name).flags.writeable
        assert (tr.newton_iterations, tr.jacobians) == (one.newton_iterations, one.jacobians)
        assert np.array_equal(tr.energy(), one.energy())
    assert list.__getitem__(out, 1) is None
