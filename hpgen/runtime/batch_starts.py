"""The starts of an explicit closed module's ensemble with one shared g0 (the common case
of ``Engine.prepare_batch``): held as arrays, g0 flat column-major (n*n,) and the members'
momenta (B, d), each member's RunStart (hpgen.runtime.engine) made only when asked for.
An ensemble call that takes the starts as arrays (hpgen.runtime.states.simulate_batch)
reads ``arrays()`` and makes none. numpy and the standard library only.
"""
from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np


class ExplicitStarts(Sequence):
    """B RunStarts sharing h, steps, every, options and g0: member b is ``first`` with
    mu0 = mu[b] and z0 a copy of it (an explicit step's Newton start is its momentum), as
    Engine.start makes it; ``first`` is member 0's (its mu0 a row of ``mu``)."""

    def __init__(self, first: Any, gf: np.ndarray, mu: np.ndarray):
        self.first, self.gf, self.mu = first, gf, mu
        self._made: list | None = None

    def __len__(self) -> int:
        return len(self.mu)

    def __getitem__(self, b):  # type: ignore[override]
        if self._made is None and not isinstance(b, slice):
            row = self.mu[b]            # one member (e.g. Ensemble.inputs' look at member 0)
            s = object.__new__(type(self.first))
            s.__dict__.update(self.first.__dict__, mu0=row, z0=row.copy())
            return s
        return self._members()[b]

    def __iter__(self):
        return iter(self._members())

    def _members(self) -> list:
        """The B RunStarts, made on the first access (``first``'s fields, a frozen
        dataclass's, copied without its per-field setattr)."""
        if self._made is None:
            cls, fields, new, made = type(self.first), self.first.__dict__, object.__new__, []
            for row in self.mu:
                s = new(cls)
                s.__dict__.update(fields, mu0=row, z0=row.copy())
                made.append(s)
            self._made = made
        return self._made

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(g0s (B, n*n), mu0s (B, d), z0s (B, d)): the members' starts, one row each."""
        B = len(self.mu)
        return np.broadcast_to(self.gf, (B, len(self.gf))), self.mu, self.mu
