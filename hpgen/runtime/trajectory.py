"""The result of Integrator.simulate.

Records are taken every ``every`` steps, starting with step 0: record k is the state after
step k*every, at time t_k = k*every*h (time in the model's unit). ``g`` is (K, n, n), ``mu``
(K, d) the node momenta p_k (body frame, the pairing of g* with the algebra). The last step
is recorded only if steps % every == 0. A partial trajectory (partial=True, error set) holds
the records up to the last step completed before a failure.
"""
from __future__ import annotations

from dataclasses import MISSING, dataclass, field, fields
from pathlib import Path
from typing import Any

import numpy as np

from ..files import atomic_output
from . import counters
from .save_formats import run_path, save_run


@dataclass(frozen=True, eq=False)
class Trajectory:
    t: np.ndarray                 # (K,)
    g: np.ndarray                 # (K, n, n)
    mu: np.ndarray                # (K, d) node momentum p_k
    h: float
    every: int
    partial: bool = False
    error: Any = None             # None or the ConvergenceError that stopped the run
    newton_iterations: int = 0    # total over all steps attempted
    jacobians: int = 0            # Jacobian evaluations (LU factorizations) over all steps
    guarded: int = 0              # accepted steps the wrong-root guard solved again
    integrator: Any = field(default=None, repr=False, compare=False)
    #: an open module's run inputs (hpgen.runtime.inputs.StepInputs: t0, u, params) or None
    inputs: Any = field(default=None, repr=False, compare=False)
    _obs: dict = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self):
        for a in (self.t, self.g, self.mu):
            a.setflags(write=False)

    @classmethod
    def made(cls, **values) -> "Trajectory":
        """The Trajectory ``cls(**values)`` makes, without the frozen dataclass's setattr per
        field (a quarter of the cost: simulate's fast path, hpgen.runtime.prologue)."""
        traj = object.__new__(cls)
        d = traj.__dict__
        d.update(_DEFAULTS)
        d.update(values)
        d["_obs"] = {}
        traj.__post_init__()
        return traj

    @staticmethod
    def shared_fields(**shared) -> dict:
        """The fields an ensemble's members share (t, h, every, integrator), with the other
        fields' defaults: the ``base`` of ``member`` and ``members``."""
        return {**_DEFAULTS, **shared}

    @classmethod
    def member(cls, base: dict, g, mu, counts: dict, inputs) -> "Trajectory":
        """An ensemble member's Trajectory: the fields ``base`` (``shared_fields``), g, mu,
        the totals ``counts`` ({field: int}: newton_iterations, jacobians and the counters of
        hpgen.runtime.counters) and inputs, as ``made`` makes it; t, g and mu read-only
        already (views of the ensemble's arrays, hpgen.runtime.states.batch_trajectories):
        no flags set."""
        traj = object.__new__(cls)
        d = traj.__dict__
        d.update(base)
        d.update(counts)
        d.update(g=g, mu=mu, inputs=inputs, _obs={})
        return traj

    @classmethod
    def members(cls, base: dict, g, mu, counts: dict, inputs) -> list:
        """``member`` j = 0, 1, ... of the sequences g, mu, inputs and ``counts`` ({field:
        sequence}) (all members at once: one loop, no call per member)."""
        new, out = object.__new__, []
        names = tuple(counts)
        for gj, mj, inp, cj in zip(g, mu, inputs, zip(*counts.values())):
            traj = new(cls)
            d = traj.__dict__
            d.update(base)
            d.update(g=gj, mu=mj, inputs=inp, _obs={})
            for name, value in zip(names, cj):
                d[name] = value
            out.append(traj)
        return out

    def __len__(self) -> int:
        return len(self.t)

    def _need(self):
        if self.integrator is None:
            raise ValueError("this Trajectory has no integrator attached")
        return self.integrator

    def _observed(self, name) -> np.ndarray:
        """One of Integrator.observe's arrays, computed once for all of them (cached)."""
        if not self._obs:
            integ = self._need()
            if self.inputs is None:
                self._obs.update(integ.observe(self.g, self.mu))
            else:
                self._obs.update(integ.observe(self.g, self.mu, t=self.t, inputs=self.inputs))
        return self._obs[name].copy()

    def energy(self) -> np.ndarray:
        """(K,) energy <dl/dxi, xi> - l at each record (xi from the Legendre inverse)."""
        return self._observed("energy")

    def momentum(self) -> np.ndarray:
        """(K, d) spatial momentum Ad*_{g^{-1}} p at each record."""
        return self._observed("momentum")

    def defect(self) -> np.ndarray:
        """(K,) distance of g_k from the group."""
        return self._observed("defect")

    def xi(self) -> np.ndarray:
        """(K, d) body velocities xi_k = (dl/dxi)^{-1}(g_k, mu_k)."""
        return self._observed("xi")

    def as_quat(self, factor=None) -> np.ndarray:
        """(K, 4) attitudes of g as unit quaternions [w, x, y, z], scalar first, w >= 0
        (Integrator.group.as_quat: the SO3 block, or factor ``factor`` of a product)."""
        return self._need().group.as_quat(self.g, factor)

    def as_rotvec(self, factor=None) -> np.ndarray:
        """(K, 3) attitudes of g as rotation vectors, angle in [0, pi] (Integrator.group)."""
        return self._need().group.as_rotvec(self.g, factor)

    def observables(self, names) -> dict:
        """The arrays a scene's ``record:`` list asks for, by name: g, mu, xi, energy,
        momentum (spatial, Ad*_{g^-1} p), defect; t is always included."""
        compute = {"g": lambda: self.g, "mu": lambda: self.mu, "xi": self.xi,
                   "energy": self.energy, "momentum": self.momentum, "defect": self.defect}
        unknown = [n for n in names if n not in compute]
        if unknown:
            raise ValueError(f"unknown record names {unknown}; expected some of {sorted(compute)}")
        return {"t": self.t, **{n: compute[n]() for n in names}}

    def save(self, path, arrays: dict | None = None) -> Path:
        """Write the run atomically (temp file + os.replace) as .npz, .nc, .zarr or .csv by
        the suffix of ``path`` (none: ".npz" appended; any other: ArgumentError; formats:
        hpgen.runtime.save_formats).

        Arrays t, g, mu (or, if ``arrays`` is given, those: see ``observables``); scalars h,
        every, partial, the counters newton_iterations and guarded (hpgen.runtime.counters);
        error (message or ""); module, hash, group and forced (whether its model has forces)
        of the generating module when known. Returns the path written.
        """
        data = dict(arrays) if arrays is not None else {"t": self.t, "g": self.g, "mu": self.mu}
        return save_run(path, data, run_metadata(self.integrator, self.h, self.every,
                                                 self.partial, counters.of(self), self.error))


#: the defaults of Trajectory's fields (Trajectory.made; _obs is a new dict each time)
_DEFAULTS = {f.name: f.default for f in fields(Trajectory) if f.default is not MISSING}


def npz_path(path) -> Path:
    """``path`` with ".npz" appended when it has no suffix; ArgumentError for another."""
    return run_path(path, (".npz",))


def run_metadata(integrator, h, every, partial, counts: dict, error) -> dict:
    """The scalars a saved run carries next to its arrays; counts: {name: total} of the
    counters (hpgen.runtime.counters.NAMES; one missing is saved as 0)."""
    meta = getattr(integrator, "meta", None) or {}
    return {"h": np.float64(h), "every": np.int64(every), "partial": np.bool_(partial),
            **{name: np.int64(counts.get(name, 0)) for name in counters.NAMES},
            "error": np.str_("" if error is None else str(error)),
            "module": np.str_(meta.get("module", "")), "hash": np.str_(meta.get("hash", "")),
            "group": np.str_(meta.get("group", "")),
            "forced": np.bool_((meta.get("open") or {}).get("forced", False))}


def write_npz(path: Path, data: dict) -> None:
    """np.savez to a temp file in path's directory, then os.replace (atomic). Arrays may be
    memory maps: np.savez streams them in buffers."""
    with atomic_output(path) as fh:
        np.savez(fh, **data)


@dataclass(frozen=True, eq=False)
class SectionCrossings:
    """Upward crossings of the scene's Poincare section s(g, mu) = 0 (Integrator.sections).

    Crossing j lies in step ``step[j]`` -> step[j] + 1 at the fraction theta of the step:
    ``t`` (K,) = (step + theta) h; ``mu`` (K, d) the node momenta interpolated linearly in
    the step (an O(h^2) estimate of the momentum on the section); ``g`` (K, n, n) the point
    g_k tau(theta h xi_{k+1}) of the step's own chart curve (on the group). ``steps`` is the
    number of steps run; on a failure partial is True and error is set; newton_iterations
    and guarded are the run's counters (hpgen.runtime.counters).
    """
    t: np.ndarray
    g: np.ndarray
    mu: np.ndarray
    step: np.ndarray
    h: float
    steps: int
    partial: bool = False
    error: Any = None
    newton_iterations: int = 0
    guarded: int = 0

    def __post_init__(self):
        for a in (self.t, self.g, self.mu, self.step):
            a.flags.writeable = False

    def __len__(self) -> int:
        return len(self.t)
