"""A list whose items are made on first access: an ensemble's B results
(Integrator.simulate_batch), so that a call whose members are never looked at makes none of
them, and looking at one makes that one only.

A ``LazyList`` is a ``list`` (isinstance, len, indexing, slicing, iteration, comparison,
``+``, copying and pickling behave as on the list of all items; copies and pickles are plain
lists). Item i is ``make(i)``, made once and kept (the same object on every access). Any use
other than indexing and slicing (iteration, a comparison, ``in``, repr, any mutation) makes
all items first. C code that reads a list's storage directly without iterating it (numpy's
``np.array(a_list)``) sees None for an item not made yet: ``list(x)`` first. Standard library
only.
"""
from __future__ import annotations

import operator
from typing import Any, Callable


class LazyList(list):
    """n items, item i made by ``make(i)`` on its first access (None marks one not made);
    ``make_all()``, when given, makes the list of all n at once (the same items as ``make``,
    cheaper a piece), for iteration and the methods that need every item."""

    def __init__(self, n: int, make: Callable[[int], Any],
                 make_all: Callable[[], list] | None = None):
        super().__init__()
        list.extend(self, [None] * n)
        self._make: Callable[[int], Any] | None = make
        self._make_all = make_all

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        x = list.__getitem__(self, i)
        if x is None and self._make is not None:
            j = operator.index(i)
            j = j + len(self) if j < 0 else j
            x = self._make(j)
            list.__setitem__(self, j, x)
        return x

    def __iter__(self):
        return list.__iter__(self.made())

    def made(self) -> "LazyList":
        """Self with every item made (then it is a plain list in all but its type); an item
        made already stays the same object."""
        if self._make is not None:
            if self._make_all is not None:
                fresh = self._make_all()
                list.__setitem__(self, slice(None), [
                    x if x is not None else y for x, y in zip(list.__iter__(self), fresh)])
            else:
                for i in range(len(self)):
                    self[i]
            self._make = self._make_all = None
        return self

    def __reduce_ex__(self, protocol):
        return (list, (list(self),))

    def __radd__(self, other):
        if not isinstance(other, list):
            return NotImplemented
        return list(other) + list(self)


def _making_all(name: str):
    """list.<name>, called after every item is made."""
    method = getattr(list, name)

    def call(self, *args, **kwargs):
        args = tuple(a.made() if isinstance(a, LazyList) else a for a in args)
        return method(self.made(), *args, **kwargs)

    call.__name__, call.__doc__ = name, method.__doc__
    return call


for _name in ("__contains__", "__eq__", "__ne__", "__lt__", "__le__", "__gt__", "__ge__",
              "__repr__", "__reversed__", "__add__", "__mul__", "__rmul__", "__iadd__",
              "__imul__", "__setitem__", "__delitem__", "append", "extend", "insert", "pop",
              "remove", "reverse", "sort", "clear", "copy", "index", "count"):
    setattr(LazyList, _name, _making_all(_name))
LazyList.__hash__ = None  # type: ignore[assignment]
