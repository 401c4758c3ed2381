"""The records output: runs that keep only what the scene's ``record:`` list asks for, as
Records (Integrator.record, stream_record, record_batch on the run engine,
hpgen.runtime.engine).

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
from . import counters, loop
from .args import _error, _fits, _int
from .engine import SLICE_FIRST, Engine, Part, RunArgs, RunHandle, RunStart, Sliced
from .progress import bar as progress_bar
from .save_formats import save_run
from .trajectory import run_metadata
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
    guarded: int = 0              # accepted steps the wrong-root guard solved again
    integrator: Any = field(default=None, repr=False, compare=False)

    def __post_init__(self):
        for a in (self.t, *self.arrays.values()):
            a.flags.writeable = False

    def save(self, path) -> Path:
        """Write t and the record arrays atomically with the scalars of Trajectory.save (h,
        every, partial, newton_iterations, guarded, error, module, hash, group, forced): .npz
        (the file ``hpgen run`` writes; ".npz" appended when there is no suffix), .nc, .zarr or
        a .csv table, by the suffix (hpgen.runtime.save_formats). Returns the path written."""
        return save_run(path, {"t": self.t, **self.arrays},
                        run_metadata(self.integrator, self.h, self.every, self.partial,
                                     counters.of(self), self.error))

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


def make_records(engine: Engine, rows, st, h, every, first=0, t_start=0.0,
                 start=None) -> Records:
    """Records of flat rows, the first of them record number ``first`` (t = t_start + j every
    h for record j, computed so: a chunk's t is bitwise the whole run's); error set
    (partial) when st failed (start: the run's (g0 flat, mu0), for what the chart needs
    when the first start is outside it)."""
    layout = engine.meta["record"]
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
            hint = engine.first_step.domain_hint(start[0], start[1], None, h)
        err = _error(st["code"], st["step"], st["step"] * h, st["residual"], st["iterations"],
                     hint)
    t = (first + np.arange(len(rows))) * every * h
    rec = Records(t=t_start + t if t_start else t,
                  arrays=split_rows(rows, layout, engine.n), h=h, every=every,
                  partial=err is not None, error=err, jacobians=int(st["jacobians"]),
                  **counters.of_status(st), integrator=engine.owner)
    if err is not None:
        err.partial = rec
    return rec


class RecordRows:
    """The records output of one run, in chunks of at most ``chunk`` steps. A ``work``
    record (hpgen.runtime.work) has the row evaluated at every step, the work accumulated,
    and every ``every``-th row kept; its first chunk holds at least the first R + 1 nodes,
    which its start rule needs; ``acc``: the WorkSum to continue (a resumed run's, restored
    with WorkSum.restore), default a new one."""

    def __init__(self, engine: Engine, s: RunStart, chunk: int, acc: WorkSum | None = None):
        self.engine, self.s, self.chunk = engine, s, chunk
        self.col = work_offset(engine.meta)
        self.acc = None if self.col is None else (WorkSum(s.h) if acc is None else acc)

    def span(self, k, first):
        if not first and k >= self.s.steps:
            return None
        chunk = self.chunk if self.acc is None or not first else max(self.chunk, WORK_START)
        return (min(chunk, self.s.steps - k),)

    def advance(self, run, span) -> Part:
        s = self.s
        done, rows, st = self.engine.backend.advance_record(
            run, s.h, span[0], 1 if self.acc else s.every, s.opts)
        return Part(done, (rows,), st)

    def head(self):
        """Record 0's row (1, W), the start's; raises its RecordError when not finite."""
        s, b = self.s, self.engine.backend
        code, row0 = b.record(s.g0, s.mu0) if s.inputs is None else \
            b.record(s.g0, s.mu0, s.inputs)
        if code != abi.OK:
            rec = make_records(self.engine, row0.reshape(1, -1),
                               {**loop.new_status(), "code": code}, s.h, s.every, 0)
            raise rec.error
        return np.array(row0, dtype=np.float64).reshape(1, -1)

    def records(self, k, first, part, row0, t_start) -> Records:
        s = self.s
        rows = part.data[0]
        if self.acc is not None:
            rows = _keep_every(rows, self.col, self.acc, k, s.every, row0 if first else None)
        elif first:
            rows = np.concatenate([row0, rows])
        return make_records(self.engine, rows, part.status, s.h, s.every,
                            k // s.every + (0 if first else 1), t_start,
                            (s.g0, s.mu0) if first and s.inputs is None else None)


def stream_records(engine: Engine, s: RunStart, chunk: int, handle: RunHandle | None = None,
                   t_start=0.0, work: WorkSum | None = None):
    """Yield Records per chunk of at most ``chunk`` steps (the first starts with record 0,
    the initial state); raises the chunk's error (with .partial) on a failure. ``handle``:
    the run to advance (default a new one at s's start); one restored from a snapshot
    (Engine.restore) after k > 0 steps continues at step k without record 0, bitwise as
    the uninterrupted run (hpgen.runtime.chunked_output's resume). t_start: the time of
    step 0. work: a run that records work continues this WorkSum (it is updated in place
    as the chunks are yielded: after each, its state is the run's after the chunk); a
    resumed run that records work needs the one saved with its snapshot."""
    out = RecordRows(engine, s, chunk, work)
    first = handle is None or handle.steps_done() == 0
    if out.acc is not None and not first and work is None:
        raise ModelError("a resumed run that records work needs the work accumulated up to "
                         "its snapshot (WorkSum.state)", field="record")
    row0 = out.head() if first else None
    for k, first, part in engine.parts(out, s, handle):
        rec = out.records(k, first, part, row0, t_start)
        if rec.error is not None:
            raise rec.error
        yield rec


def record_names(meta) -> tuple:
    """What a module's record row holds (the scene's ``record:`` list, in order)."""
    return tuple(name for name, _, _ in meta["record"])


def stream_record(engine: Engine, a: RunArgs, chunk=100_000):
    """Integrator.stream_record."""
    chunk = _int(chunk, "chunk", 1)
    s = engine.prepare(a)
    yield from stream_records(engine, s, chunk, t_start=float(a.t0))


def record(engine: Engine, a: RunArgs) -> Records:
    """Integrator.record: the run in one piece, advanced in slices
    (hpgen.runtime.engine.Sliced) so that Ctrl-C interrupts it; a KeyboardInterrupt is
    re-raised with ``.partial``, the Records of the steps done (partial=True)."""
    _fits(_int(a.steps, "steps", 0) // _int(a.every, "every", 1) + 1,
          engine.backend.record_width or 1, "record")
    s = engine.prepare(a)
    t0 = float(a.t0)
    out = RecordRows(engine, s, SLICE_FIRST)
    row0 = out.head()
    got: list = []            # the Records of each slice, appended in one operation
    try:
        for k, first, part in engine.parts(Sliced(out), s):
            got.append(out.records(k, first, part, row0, t0))
    except KeyboardInterrupt as exc:
        exc.partial = _joined(engine, s, list(got), True)  # type: ignore[attr-defined]
        raise
    rec = _joined(engine, s, got)
    if rec.error is not None:
        raise rec.error
    return rec


def _joined(engine: Engine, s: RunStart, got: list, interrupted=False) -> Records:
    """The Records of a run's slices ``got`` joined (Newton totals summed; the last slice's
    error, its .partial the joined Records); partial when ``interrupted``."""
    names = record_names(engine.meta)
    width = {name: shape for name, _, shape in engine.meta["record"]}
    arrays = {name: np.concatenate([r.arrays[name] for r in got]) if got else
              np.zeros((0, *width[name])) for name in names}
    err = got[-1].error if got else None
    rec = Records(t=np.concatenate([r.t for r in got]) if got else np.zeros(0),
                  arrays=arrays, h=s.h, every=s.every,
                  partial=interrupted or err is not None, error=err,
                  jacobians=sum(r.jacobians for r in got), **counters.summed(got),
                  integrator=engine.owner)
    if err is not None:
        err.partial = rec
    return rec


def record_batch(engine: Engine, a: RunArgs, threads=None, progress=None) -> list:
    """Integrator.record_batch: B Records from one backend call per thread slice."""
    engine.require_c("record_batch")
    e = engine.prepare_batch(a)
    threads = engine.threads(threads)
    runs, steps, every = e.members, e.steps, e.every
    col = work_offset(engine.meta)
    _fits(len(runs) * (steps // (every if col is None else 1) + 1),
          engine.backend.record_width or 1, "record_batch")
    with progress_bar(len(runs), "record_batch", "member", progress) as bar:
        rows, n_rows, sts = engine.backend.record_batch(
            [s.g0 for s in runs], [s.mu0 for s in runs], e.h, [s.z0 for s in runs], steps,
            every if col is None else 1, e.opts, threads, bar, e.inputs)
    out = []
    for b in range(len(runs)):
        mine = rows[b, :n_rows[b]]
        if col is not None and len(mine):     # the work from the every-step rows
            mine = _keep_every(mine[1:], col, WorkSum(e.h), 0, every, mine[:1])
        out.append(make_records(engine, mine, sts[b], e.h, every, 0, float(a.t0)))
    return out


def _keep_every(rows, col, acc, k, every, row0=None):
    """Rows after steps k + 1, k + 2, ... (one per step; preceded by record 0's row ``row0``
    when given): the work column filled, then the rows of the steps that are multiples of
    ``every``."""
    rows = np.array(rows, dtype=np.float64)
    if rows.ndim != 2:                    # (an empty (0, W) block keeps its width)
        rows = rows.reshape(len(rows), -1)
    if row0 is not None:
        rows, k = np.concatenate([row0, rows]), k - 1
    fill_work(rows, col, acc)
    return rows[(k + 1 + np.arange(len(rows))) % every == 0]
