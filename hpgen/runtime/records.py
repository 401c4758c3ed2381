"""Runs that keep only what the scene's ``record:`` list asks for (Integrator.record).

The C loop (``hpgen_advance_record``) evaluates the compiled record row (kernel ``record``:
g, mu, xi, energy, momentum, defect and user expressions, in the scene's order; layout in
meta.json "record") every ``every`` steps and keeps nothing else; when neither the step nor
the row use g, the group element is not reconstructed at all (meta step_uses_g /
record_uses_g). Record k is the state after step k*every, at t_k = k*every*h; record 0 is the
initial state. The Python backend runs the same loop on lists (hpgen.runtime.newton).
numpy and the standard library only.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import abi
from ..errors import ModelError, RecordError
from . import loop
from .args import _error, _fits, _int
from .newton import NewtonOptions
from .progress import bar as progress_bar
from .trajectory import npz_path, run_metadata, write_npz
from .work import R as WORK_START, WorkSum, fill_work, work_offset


@dataclass(frozen=True, eq=False)
class Records:
    """The recorded samples of a run: ``t`` (K,) and one array per record name (``names``, the
    scene's order): g (K, n, n), mu / xi / momentum (K, d), energy / defect / expressions
    (K,). ``arrays`` maps names to arrays; ``records[name]`` is the same. partial / error as
    for Trajectory."""
    t: np.ndarray
    arrays: dict
    h: float
    every: int
    partial: bool = False
    error: Any = None
    newton_iterations: int = 0
    jacobians: int = 0
    integrator: Any = field(default=None, repr=False, compare=False)

    def __post_init__(self):
        for a in (self.t, *self.arrays.values()):
            a.flags.writeable = False

    def save(self, path) -> Path:
        """Write t and the record arrays to an .npz (".npz" appended if missing) atomically,
        with the scalars of Trajectory.save (h, every, partial, newton_iterations, error,
        module, hash): the file ``hpgen run`` writes. Returns the path written."""
        path = npz_path(path)
        write_npz(path, {"t": self.t, **self.arrays,
                         **run_metadata(self.integrator, self.h, self.every, self.partial,
                                        self.newton_iterations, self.error)})
        return path

    def as_quat(self, factor=None) -> np.ndarray:
        """(K, 4) attitudes of the recorded g as unit quaternions [w, x, y, z], scalar first
        (Trajectory.as_quat); ArgumentError when g is not recorded."""
        return self.integrator.group.as_quat(self.arrays.get("g"), factor)

    def as_rotvec(self, factor=None) -> np.ndarray:
        """(K, 3) attitudes of the recorded g as rotation vectors (Trajectory.as_rotvec)."""
        return self.integrator.group.as_rotvec(self.arrays.get("g"), factor)

    @property
    def names(self) -> tuple:
        return tuple(self.arrays)

    def __getitem__(self, name) -> np.ndarray:
        return self.arrays[name]

    def __len__(self) -> int:
        return len(self.t)


def split_rows(rows, layout, n) -> dict:
    """{name: array} from record rows (K, W) and meta "record" [[name, offset, shape]]; g
    rows are column-major n*n blocks, returned as (K, n, n) matrices."""
    rows = np.asarray(rows, dtype=np.float64)
    K, out = len(rows), {}
    for name, off, shape in layout:
        width = int(np.prod(shape))
        block = rows[:, off:off + width]
        if list(shape) == [n, n]:
            out[name] = np.ascontiguousarray(block.reshape(K, n, n).transpose(0, 2, 1))
        elif shape:
            out[name] = np.array(block)
        else:
            out[name] = np.array(block[:, 0])
    return out


def _not_finite(row, layout) -> list:
    return [name for name, off, shape in layout
            if not np.isfinite(row[off:off + int(np.prod(shape))]).all()]


def make_records(integ, rows, st, h, every, first=0, t_start=0.0, start=None) -> Records:
    """Records of flat rows, the first of them record number ``first`` (t = t_start + j every
    h for record j, computed so: a chunk's t is bitwise the whole run's); error set
    (partial) when st failed (start: the run's (g0 flat, mu0), for what the chart needs
    when the first start is outside it)."""
    layout = integ.meta["record"]
    err = None
    if st["code"] == abi.RECORD:
        bad = _not_finite(rows[-1], layout) if len(rows) else []
        err = RecordError(f"the recorded value(s) {', '.join(bad) or '?'} are not finite "
                          "(or the velocity xi behind them did not converge); check where "
                          "the record expressions are defined", step=int(st["step"]),
                          time=float(st["step"]) * h, names=bad)
    elif st["code"] != abi.OK:
        hint = ""
        if st["code"] == abi.DOMAIN and st["iterations"] == 0 and start is not None:
            hint = integ._domain_hint(*start, None, h)
        err = _error(st["code"], st["step"], st["step"] * h, st["residual"], st["iterations"],
                     hint)
    t = (first + np.arange(len(rows))) * every * h
    rec = Records(t=t_start + t if t_start else t,
                  arrays=split_rows(rows, layout, integ.n), h=h, every=every,
                  partial=err is not None, error=err,
                  newton_iterations=int(st["total_iterations"]), jacobians=int(st["jacobians"]),
                  integrator=integ)
    if err is not None:
        err.partial = rec
    return rec


def stream_records(integ, backend, gf, mu0, z0, h, steps, every, chunk, opts, run=None,
                   inputs=None, t_start=0.0):
    """Yield Records per chunk of at most ``chunk`` steps (the first starts with record 0,
    the initial state); raises the chunk's error (with .partial) on a failure. ``run``: the
    run to advance (default a new one at gf, mu0, z0); one restored from a snapshot
    (``backend.restore``) after k > 0 steps continues at step k without record 0, bitwise as
    the uninterrupted run (hpgen.runtime.chunked_output's resume). inputs: an open module's
    StepInputs; t_start: the time of step 0. A ``work`` record (hpgen.runtime.work) has the
    row evaluated at every step, the work accumulated, and every ``every``-th row kept."""
    if run is None:
        run = backend.start(gf, mu0, z0) if inputs is None else \
            backend.start(gf, mu0, z0, inputs)
    k = backend.steps_done(run)
    first = k == 0
    col = work_offset(integ.meta)
    acc = None if col is None else WorkSum(h)
    if acc is not None and not first:
        raise ModelError("a run that records work cannot be resumed (the work is accumulated "
                         "from its start); run it again", field="record")
    if first:
        code, row0 = backend.record(gf, mu0) if inputs is None else \
            backend.record(gf, mu0, inputs)
        if code != abi.OK:
            rec = make_records(integ, row0.reshape(1, -1), {**loop.new_status(), "code": code},
                               h, every, 0, t_start)
            raise rec.error
        row0 = np.array(row0, dtype=np.float64).reshape(1, -1)
    while first or k < steps:
        # (work: the first chunk holds the first R + 1 nodes, which its start rule needs)
        todo = min(chunk if acc is None or not first else max(chunk, WORK_START), steps - k)
        done, rows, st = backend.advance_record(run, h, todo, 1 if acc else every, opts)
        z1 = (integ._restart(st, gf, mu0, h, z0, opts)
              if first and inputs is None and z0 is not None else None)
        if z1 is not None:                   # (closed modules only: no work record)
            run = backend.start(gf, mu0, z1)
            done, rows, st = backend.advance_record(run, h, todo, every, opts)
        if acc is not None:
            rows = _keep_every(rows, col, acc, k, every, row0 if first else None)
        elif first:
            rows = np.concatenate([row0, rows])
        rec = make_records(integ, rows, st, h, every, k // every + (0 if first else 1),
                           t_start, (gf, mu0) if first and inputs is None else None)
        if rec.error is not None:
            raise rec.error
        yield rec
        k += done
        first = False


def _keep_every(rows, col, acc, k, every, row0=None):
    """Rows after steps k + 1, k + 2, ... (one per step; preceded by record 0's row ``row0``
    when given): the work column filled, then the rows of the steps that are multiples of
    ``every``."""
    rows = np.array(rows, dtype=np.float64).reshape(len(rows), -1)
    if row0 is not None:
        rows, k = np.concatenate([row0, rows]), k - 1
    fill_work(rows, col, acc)
    return rows[(k + 1 + np.arange(len(rows))) % every == 0]


class RecordsMixin:
    """Integrator methods for scene records (uses the Integrator's _prepare, _prepare_batch
    and backend)."""

    @property
    def record_names(self) -> tuple:
        """What this module's record row holds (the scene's ``record:`` list, in order)."""
        return tuple(name for name, _, _ in self.meta["record"])

    def stream_record(self, g0, h, steps, xi0=None, mu0=None, every=1, chunk=100_000, *,
                      newton: NewtonOptions | None = None, u=None, params=None, t0=0.0):
        """Like ``record`` in chunks of at most ``chunk`` steps (bounded memory): yields one
        Records per chunk (the first starts with record 0; ``t`` is global). A failure raises
        ConvergenceError / DomainError / RecordError with ``.partial`` the failing chunk's
        records. u, params, t0: as in ``simulate``."""
        chunk = _int(chunk, "chunk", 1)
        h, steps, every, opts, gf, mu0, z0, inputs = self._prepare(
            g0, h, steps, xi0, mu0, every, newton, u, params, t0)
        yield from stream_records(self, self._b, gf, mu0, z0, h, steps, every, chunk, opts,
                                  inputs=inputs, t_start=float(t0))

    def record(self, g0, h, steps, xi0=None, mu0=None, every=1, *,
               newton: NewtonOptions | None = None, u=None, params=None, t0=0.0):
        """Run ``steps`` steps keeping only the scene's record row every ``every`` steps.

        The row (``record_names``: the scene's g, mu, xi, energy, momentum, defect and
        expressions) is evaluated inside the C loop; when neither the step nor the row use
        g, g is not reconstructed. The states are bitwise those of ``simulate``.

        Parameters
        ----------
        g0, h, steps, xi0, mu0
            As for ``simulate``: g0 (n, n) on the group, h != 0 in the model's time unit,
            steps >= 0, exactly one of xi0 / mu0 (d,).
        every : int, optional
            Record interval in steps, >= 1 (default 1); record 0 is the initial state.
        newton : NewtonOptions or None, optional
            Newton settings, as for ``simulate``.
        u, params, t0
            As for ``simulate`` (an open module's inputs, runtime parameters, start time).

        Returns
        -------
        Records
            ``t`` (K,) and one array per record name, K = steps // every + 1: g (K, n, n);
            mu, xi, momentum (K, d); energy, defect, expressions (K,). ``rec["energy"]``,
            ``rec.save(path)``.

        Raises
        ------
        ModelError
            A bad argument.
        ConvergenceError, DomainError, RecordError
            A step failed, or a recorded value is not finite (``RecordError`` names the
            entries); ``.partial`` holds the records up to the failure.
        """
        _fits(_int(steps, "steps", 0) // _int(every, "every", 1) + 1, self._b.record_width or 1,
              "record")
        chunks = list(self.stream_record(g0, h, steps, xi0, mu0, every, max(steps, 1),
                                         newton=newton, u=u, params=params, t0=t0))
        return chunks[0]

    def record_batch(self, g0, h, steps, xi0=None, mu0=None, every=1, threads=None, *,
                     newton: NewtonOptions | None = None, u=None, params=None, t0=0.0,
                     progress=None) -> list:
        """``record`` for an ensemble (starts as in ``simulate_batch``), in C over ``threads``
        threads (default: the CPU count); each run's rows are bitwise those of ``record`` on
        its own. Returns B Records; a failed run's Records is partial with ``.error`` set
        (nothing is raised). u, params, t0 and progress: as for ``simulate_batch`` (a params
        value with a leading axis of length B is a sweep: run b takes entry b)."""
        h, steps, every, opts, threads, gs, ms, z0s, inputs = self._prepare_batch(
            g0, h, steps, xi0, mu0, every, threads, newton, "record_batch", u, params, t0)
        col = work_offset(self.meta)
        _fits(len(gs) * (steps // (every if col is None else 1) + 1),
              self._b.record_width or 1, "record_batch")
        with progress_bar(len(gs), "record_batch", "member", progress) as bar:
            rows, n_rows, sts = self._b.record_batch(gs, ms, h, z0s, steps,
                                                     every if col is None else 1, opts,
                                                     threads, bar, inputs)
        out = []
        for b in range(len(gs)):
            mine = rows[b, :n_rows[b]]
            if col is not None and len(mine):     # the work from the every-step rows
                mine = _keep_every(mine[1:], col, WorkSum(h), 0, every, mine[:1])
            out.append(make_records(self, mine, sts[b], h, every, 0, float(t0)))
        return out
