"""Long runs to disk with bounded memory, that survive being killed: ``record_to_npz`` steps
a scene in chunks (the compiled record row, evaluated inside the C loop, holds only what the
scene's ``record:`` asks for) and keeps every completed chunk on disk, so that an interrupted
run (kill -9, SIGTERM, SIGINT, a crash) loses at most the chunk in progress and ``resume``
continues it.

While the run goes, the folder ``<out>.partial/`` next to the output (hpgen.runtime.partial_run)
holds:

- ``manifest.json`` (written first): what the folder is, the run it belongs to (module hash,
  backend, h, steps, every, digests of the start and of the Newton options) and the command
  that resumes it;
- ``chunk_000000.npz``, ``chunk_000001.npz``, ...: one per completed chunk: ``t`` and the
  record arrays of the chunk (``np.load`` reads them; ``load_partial`` joins them), and,
  under keys ``state.*``, the run's whole state after the chunk (the backend's snapshot:
  for C the bytes of its ``hpgen_run``: state, Newton start and memory, steps done) with the
  running totals (chunks, steps done, samples, the run's counters, energy / momentum change)
  and, for a run that records work, the work accumulated so far (hpgen.runtime.work).

Each chunk file is written to a temp file and renamed (atomic): a chunk is committed when
its file exists (and counted so by the folder before an interrupt that came during its
write is delivered), so a kill at any instant leaves a consistent folder (one rename to a new
name per chunk, no file rewritten; written, not fsync'ed: a killed process loses nothing, a
power cut may). ``resume=True`` restores the state of the last chunk and continues; the
final file's arrays are bitwise those of an uninterrupted run (the C run advanced n1 then n2
steps is bitwise the run advanced n1 + n2 steps). At the end the chunks are streamed into
one ``.npz`` (one chunk's array in memory at a time), which appears atomically, and the
folder is removed.

Memory holds one chunk of steps' records (``chunk`` steps, every ``every``-th recorded), never
the run. A failed step saves the records before it with partial=True and re-raises; an
interrupt (KeyboardInterrupt, or a subclass a caller raises from a SIGTERM handler) saves the
completed chunks with partial=True, keeps the folder for ``resume`` and re-raises, with
``.saved`` set on the exception in both cases. numpy and the standard library only.
"""
from __future__ import annotations

import hashlib
import shutil
from pathlib import Path

import numpy as np

from ..errors import ConvergenceError, ModelError
from .args import _int
from .engine import RunArgs
from .progress import bar as progress_bar
from .partial_run import STATE, PartialFolder
from .records import stream_records
from .trajectory import npz_path, run_metadata
from .work import WorkSum, work_offset


def partial_dir(out) -> Path:
    """The folder holding the completed chunks of a run writing ``out``."""
    path = npz_path(out)
    return path.with_name(path.name + ".partial")


def record_to_npz(integ, out, g0, h, steps, xi0=None, mu0=None, every=1,
                  chunk=1_000_000, resume=False, resume_hint="", directions=None, *,
                  newton=None, progress=False, u=None):
    """Run and save the module's record row (``integ.record_names``, one array each, and t)
    of the Integrator ``integ`` (its run engine, hpgen.runtime.engine: the run's start, the
    records output's chunks, the run's snapshot after each and its restore on resume);
    returns (path, summary): samples written, steps (done), resumed_at (steps the run
    started from: 0, or the resumed run's steps done), energy_max_change (max |E - E0|, if
    energy is recorded), momentum_max_change (per component, if momentum is recorded),
    removed (the folders an older hpgen's killed run of this output left, now removed),
    conserved_max_change (max_k |V (m_k - m_0)| per row of ``directions`` V (q, d), the
    conserved directions of hpgen.analysis.symmetry, if given and momentum is recorded),
    balance_max_change (max |(E - W) - (E_0 - W_0)|, a forced model's energy-work balance,
    if energy and work are recorded), and the run's counters by name (newton_iterations,
    guarded: hpgen.runtime.counters; a resumed run's over both runs).

    resume: continue the interrupted run in ``partial_dir(out)`` (a fresh run if there is
    none); without it such a folder is refused (ModelError naming it and how to resume).
    resume_hint: the command that resumes, written into the manifest and the messages.
    newton: the run's hpgen.runtime.newton.NewtonOptions (None: the module's defaults).
    progress: a bar of the steps done, per chunk (hpgen.runtime.progress; None: when stderr
    is a terminal). u: the control inputs of a model with inputs, as for ``simulate``.
    On a failed step the records before it are saved (partial=True) and the
    ConvergenceError is re-raised with ``.saved = (path, samples)``; on KeyboardInterrupt
    the completed chunks are saved (partial=True) and it is re-raised with ``.saved =
    (path or None, samples, steps done, partial folder)``; in both cases with ``.counts``,
    the run's counters by name over what was saved (the failed step's solves included)."""
    path = npz_path(out)
    parts = partial_dir(path)
    chunk = _int(chunk, "chunk", 1)
    engine = integ.engine
    s = engine.prepare(RunArgs(g0, h, steps, xi0, mu0, every, newton, u=u))
    h, steps, every = s.h, s.steps, s.every
    ident = _identity(engine, s)
    if u is not None:                     # a resumed run must have the same inputs
        ident["u_sha256"] = hashlib.sha256(
            np.ascontiguousarray(s.inputs.rows, dtype=np.float64).tobytes()).hexdigest()
    removed = _remove_old_leftovers(path)
    with PartialFolder(parts, path) as folder:
        prog = (folder.resume if resume else folder.fresh)(ident, resume_hint)
        prog.directions = None if directions is None else np.asarray(directions, np.float64)
        work = None
        if work_offset(engine.meta) is not None:    # the work accumulated so far goes on
            if prog.state is None:
                work = WorkSum(h)
            elif prog.work:
                work = WorkSum.restore(h, prog.work)
            else:
                raise ModelError(f"cannot resume {parts}: its chunks do not hold the work "
                                 "accumulated so far; delete the folder to start over",
                                 file=str(parts))
        run = None if prog.state is None else engine.restore(prog.state, s.inputs)
        if run is not None and run.steps_done() != prog.k:
            raise ModelError(f"cannot resume {parts}: its state is not at step {prog.k}; "
                             "delete the folder to start over", file=str(parts))
        resumed_at, error = prog.k, None
        try:
            run = engine.new_run(s) if run is None else run
            with progress_bar(steps, "run", "step", progress) as bar:
                bar.update(prog.k)
                for rec in stream_records(engine, s, chunk, run, work=work):
                    new = prog.added(rec, run.steps_done())
                    folder.commit(new, rec, run.snapshot(),
                                  None if work is None else work.state())
                    bar.update(new.k - prog.k)
                    prog = new
        except ConvergenceError as exc:
            if exc.partial is None:
                raise
            prog = prog.added(exc.partial, prog.k)
            folder.write_chunk(prog.chunks - 1, exc.partial)
            error = exc
        except KeyboardInterrupt as exc:
            # what is committed, not prog: an interrupt deferred while a chunk was written
            # is raised as its commit returns, before prog = new
            prog, saved = folder.progress, None
            if prog.chunks:
                msg = f"interrupted after {prog.k} of {steps} steps"
                folder.assemble(path, prog, run_metadata(integ, h, every, True,
                                                         prog.counts, msg))
                saved = path
            else:
                folder.keep = False
            exc.saved = (saved, prog.samples, prog.k, parts if folder.keep else None)
            exc.counts = dict(prog.counts)
            raise
        folder.assemble(path, prog, run_metadata(integ, h, every, error is not None,
                                                 prog.counts, error))
        folder.keep = False
    summary = {"samples": prog.samples, "steps": prog.k, "resumed_at": resumed_at,
               "energy_max_change": prog.change.get("energy"),
               "momentum_max_change": prog.change.get("momentum"),
               "conserved_max_change": prog.change.get("conserved"),
               "balance_max_change": prog.change.get("balance"), "removed": removed,
               **prog.counts}
    if error is not None:
        error.saved, error.counts = (path, prog.samples), dict(prog.counts)
        raise error
    return path, summary


def load_partial(out) -> dict:
    """The samples an interrupted run kept in ``partial_dir(out)`` (its committed chunks),
    joined: {"t": ..., name: ..., "steps_done": steps the chunks cover}."""
    files = PartialFolder(partial_dir(out), npz_path(out)).committed_files()
    if not files:
        raise ModelError("no completed chunk to read", file=str(partial_dir(out)))
    loaded = [np.load(f) for f in files]
    out = {k: np.concatenate([f[k] for f in loaded]) for k in loaded[0].files
           if not k.startswith(STATE)}
    out["steps_done"] = int(loaded[-1][STATE + "totals"][1])
    return out


def _identity(engine, s) -> dict:
    """What a resumed run must share with the interrupted one (JSON-comparable)."""
    start = hashlib.sha256()
    for a in (s.g0, s.mu0, s.z0):
        start.update(np.ascontiguousarray(a, dtype=np.float64).tobytes())
    meta = engine.meta
    return {"module": meta["module"], "hash": meta["hash"], "backend": engine.backend.name,
            "h": float(s.h).hex(), "steps": int(s.steps), "every": int(s.every),
            "start_sha256": start.hexdigest(), "newton": repr(s.opts)}


def _remove_old_leftovers(path: Path) -> list:
    """hpgen <= 0.1 kept a chunked run in a hidden ``.<out>.<random>/`` folder of memory
    maps, never resumable: remove those of this output; returns their paths."""
    removed = []
    for old in sorted(path.parent.glob(f".{path.name}.*")):
        if old.is_dir() and not old.is_symlink():
            shutil.rmtree(old, ignore_errors=True)
            removed.append(old)
    return removed
