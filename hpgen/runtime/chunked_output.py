"""Long runs to disk with bounded memory, that survive being killed: ``record_to_npz`` steps
a scene in chunks (the compiled record row, evaluated inside the C loop, holds only what the
scene's ``record:`` asks for) and keeps every completed chunk on disk, so that an interrupted
run (kill -9, SIGTERM, SIGINT, a crash) loses at most the chunk in progress and ``resume``
continues it.

While the run goes, the folder ``<out>.partial/`` next to the output holds:

- ``manifest.json`` (written first): what the folder is, the run it belongs to (module hash,
  backend, h, steps, every, digests of the start and of the Newton options) and the command
  that resumes it;
- ``chunk_000000.npz``, ``chunk_000001.npz``, ...: one per completed chunk: ``t`` and the
  record arrays of the chunk (``np.load`` reads them; ``load_partial`` joins them), and,
  under keys ``state.*``, the run's whole state after the chunk (the backend's snapshot:
  for C the bytes of its ``hpgen_run``: state, Newton start and memory, steps done) with the
  running totals (chunks, steps done, samples, Newton iterations, energy / momentum change).

Each chunk file is written to a temp file and renamed (atomic): a chunk is committed when
its file exists, so a kill at any instant leaves a consistent folder (one rename to a new
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
import json
import shutil
import zipfile
from pathlib import Path

import numpy as np

from ..files import atomic_output, write_file
from ..errors import ConvergenceError, ModelError
from .args import _int
from .progress import bar as progress_bar
from .records import stream_records
from .trajectory import npz_path, run_metadata, write_npz
from .work import work_offset

#: the layout of ``<out>.partial/`` (bump when it changes: an older folder is not resumed)
PARTIAL_FORMAT = 1
MANIFEST = "manifest.json"
_STATE = "state."         # key prefix of the run state in a chunk file
OPEN_MAX = 256            # chunk files held open at once while assembling the output


def partial_dir(out) -> Path:
    """The folder holding the completed chunks of a run writing ``out``."""
    path = npz_path(out)
    return path.with_name(path.name + ".partial")


def record_to_npz(integ, out, g0, h, steps, xi0=None, mu0=None, every=1,
                  chunk=1_000_000, resume=False, resume_hint="", directions=None, *,
                  newton=None, progress=False):
    """Run and save the module's record row (``integ.record_names``, one array each, and t);
    returns (path, summary): samples written, steps (done), resumed_at (steps the run
    started from: 0, or the resumed run's steps done), energy_max_change (max |E - E0|, if
    energy is recorded), momentum_max_change (per component, if momentum is recorded),
    removed (the folders an older hpgen's killed run of this output left, now removed),
    conserved_max_change (max_k |V (m_k - m_0)| per row of ``directions`` V (q, d), the
    conserved directions of hpgen.analysis.symmetry, if given and momentum is recorded),
    balance_max_change (max |(E - W) - (E_0 - W_0)|, a forced model's energy-work balance,
    if energy and work are recorded).

    resume: continue the interrupted run in ``partial_dir(out)`` (a fresh run if there is
    none); without it such a folder is refused (ModelError naming it and how to resume).
    resume_hint: the command that resumes, written into the manifest and the messages.
    newton: the run's hpgen.runtime.newton.NewtonOptions (None: the module's defaults).
    progress: a bar of the steps done, per chunk (hpgen.runtime.progress; None: when stderr
    is a terminal).
    On a failed step the records before it are saved (partial=True) and the
    ConvergenceError is re-raised with ``.saved = (path, samples)``; on KeyboardInterrupt
    the completed chunks are saved (partial=True) and it is re-raised with ``.saved =
    (path or None, samples, steps done, partial folder)``."""
    path = npz_path(out)
    parts = partial_dir(path)
    chunk = _int(chunk, "chunk", 1)
    h, steps, every, opts, gf, mu0, z0, inputs = integ._prepare(g0, h, steps, xi0, mu0, every,
                                                                newton)
    ident = _identity(integ, h, steps, every, opts, gf, mu0, z0)
    removed = _remove_old_leftovers(path)
    with _Folder(parts, path) as folder:
        prog = (folder.resume if resume else folder.fresh)(ident, resume_hint)
        prog.directions = None if directions is None else np.asarray(directions, np.float64)
        if prog.state is not None and work_offset(integ.meta) is not None:
            raise ModelError(f"cannot resume {parts}: a run that records work cannot be "
                             "resumed (the work is accumulated from its start); delete the "
                             "folder and run it again", file=str(parts))
        run = None if prog.state is None else integ._b.restore(prog.state, inputs)
        if run is not None and integ._b.steps_done(run) != prog.k:
            raise ModelError(f"cannot resume {parts}: its state is not at step {prog.k}; "
                             "delete the folder to start over", file=str(parts))
        resumed_at, error = prog.k, None
        try:
            run = integ._b.start(gf, mu0, z0, inputs) if run is None else run
            with progress_bar(steps, "run", "step", progress) as bar:
                bar.update(prog.k)
                for rec in stream_records(integ, integ._b, gf, mu0, z0, h, steps, every, chunk,
                                          opts, run=run, inputs=inputs):
                    new = prog.added(rec, integ._b.steps_done(run))
                    folder.commit(new, rec, integ._b.snapshot(run))
                    bar.update(new.k - prog.k)
                    prog = new       # only once the chunk is committed (an interrupt may come)
        except ConvergenceError as exc:
            if exc.partial is None:
                raise
            prog = prog.added(exc.partial, prog.k)
            folder.write_chunk(prog.chunks - 1, exc.partial)
            error = exc
        except KeyboardInterrupt as exc:
            saved = None
            if prog.chunks:
                msg = f"interrupted after {prog.k} of {steps} steps"
                folder.assemble(path, prog, run_metadata(integ, h, every, True,
                                                         prog.iterations, msg))
                saved = path
            else:
                folder.keep = False
            exc.saved = (saved, prog.samples, prog.k, parts if folder.keep else None)
            raise
        folder.assemble(path, prog, run_metadata(integ, h, every, error is not None,
                                                 prog.iterations, error))
        folder.keep = False
    summary = {"samples": prog.samples, "steps": prog.k, "resumed_at": resumed_at,
               "energy_max_change": prog.change.get("energy"),
               "momentum_max_change": prog.change.get("momentum"),
               "conserved_max_change": prog.change.get("conserved"),
               "balance_max_change": prog.change.get("balance"), "removed": removed}
    if error is not None:
        error.saved = (path, prog.samples)
        raise error
    return path, summary


def load_partial(out) -> dict:
    """The samples an interrupted run kept in ``partial_dir(out)`` (its committed chunks),
    joined: {"t": ..., name: ..., "steps_done": steps the chunks cover}."""
    files = _Folder(partial_dir(out), npz_path(out))._committed()
    if not files:
        raise ModelError("no completed chunk to read", file=str(partial_dir(out)))
    loaded = [np.load(f) for f in files]
    out = {k: np.concatenate([f[k] for f in loaded]) for k in loaded[0].files
           if not k.startswith(_STATE)}
    out["steps_done"] = int(loaded[-1][_STATE + "totals"][1])
    return out


# ---- the run's progress and its folder -------------------------------------------------------

class _Progress:
    """Running totals of a chunked run: chunks, steps done k, samples, Newton iterations,
    the first samples of energy / momentum and the max change so far of energy, momentum
    and its projections on ``directions`` ("conserved"); ``state`` the snapshot to continue
    from (a resumed run)."""
    CHANGES = ("energy", "momentum", "conserved", "balance")

    def __init__(self, directions=None):
        self.chunks = self.k = self.samples = self.iterations = 0
        self.first, self.change, self.state = {}, {}, None
        self.directions = directions

    def added(self, rec, k) -> "_Progress":
        """A copy with one more chunk, ``rec``, folded in; k: the steps done after it."""
        new = _Progress(self.directions)
        new.chunks, new.k = self.chunks + 1, k
        new.samples = self.samples + len(rec.t)
        new.iterations = self.iterations + rec.newton_iterations
        new.first, new.change = dict(self.first), dict(self.change)
        for name in ("energy", "momentum"):
            if name in rec.arrays and len(rec.t):
                a = np.asarray(rec.arrays[name])
                new.first.setdefault(name, a[0].copy())
                new._fold(name, np.abs(a - new.first[name]).max(axis=0))
                if name == "momentum" and self.directions is not None:
                    proj = (a - new.first[name]) @ self.directions.T
                    new._fold("conserved", np.abs(proj).max(axis=0))
        if "energy" in rec.arrays and "work" in rec.arrays and len(rec.t):
            # a forced model's conserved balance E - W (hpgen.runtime.work)
            bal = np.asarray(rec.arrays["energy"]) - np.asarray(rec.arrays["work"])
            new.first.setdefault("balance", bal[0].copy())
            new._fold("balance", np.abs(bal - new.first["balance"]).max(axis=0))
        return new

    def _fold(self, name, change):
        prev = self.change.get(name)
        self.change[name] = change if prev is None else np.maximum(prev, change)

    def totals(self) -> dict:
        """The totals as arrays (saved next to the run's state)."""
        out = {"totals": np.array([self.chunks, self.k, self.samples, self.iterations],
                                  dtype=np.int64)}
        out.update({f"first_{k}": np.asarray(v) for k, v in self.first.items()})
        out.update({f"change_{k}": np.asarray(v) for k, v in self.change.items()})
        return out

    @classmethod
    def from_state(cls, arrays: dict) -> "_Progress":
        prog = cls()
        prog.chunks, prog.k, prog.samples, prog.iterations = (int(v) for v in arrays["totals"])
        for name in cls.CHANGES:
            if f"first_{name}" in arrays:
                prog.first[name] = arrays[f"first_{name}"]
            if f"change_{name}" in arrays:
                prog.change[name] = arrays[f"change_{name}"]
        prog.state = {k[len("run_"):]: v for k, v in arrays.items() if k.startswith("run_")}
        return prog


class _Folder:
    """``<out>.partial/``: created (or resumed) on entry, locked against a second writer,
    removed on exit unless ``keep`` (an interrupted or crashed run)."""

    def __init__(self, parts: Path, out: Path):
        self.parts, self.out, self.keep, self._lock = parts, out, True, None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self._lock is not None:
            self._lock.close()
        if not self.keep:
            shutil.rmtree(self.parts, ignore_errors=True)
        return False

    def _take_lock(self):
        import fcntl
        if self._lock is not None:
            return
        self.parts.mkdir(parents=True, exist_ok=True)
        self._lock = open(self.parts / ".lock", "w")
        try:
            fcntl.flock(self._lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            self._lock.close()
            self._lock = None
            raise ModelError(f"another hpgen run is writing {self.out} (its chunks are in "
                             f"{self.parts})", file=str(self.out)) from None

    def _committed(self) -> list:
        """The committed chunk files 0, 1, ... (consecutive; the last holds a state)."""
        files = []
        while (self.parts / _chunk_name(len(files))).is_file():
            files.append(self.parts / _chunk_name(len(files)))
        while files and _STATE + "totals" not in _npz_names(files[-1]):
            files.pop()          # a failed run's last chunk (no state), never committed
        return files

    def fresh(self, ident, hint) -> _Progress:
        self._take_lock()
        if self._committed():
            raise ModelError(_leftover_line(self.parts), file=str(self.parts))
        for p in self.parts.iterdir():     # killed before its first chunk was committed
            if p.name != ".lock":
                shutil.rmtree(p) if p.is_dir() else p.unlink()
        _write_text(self.parts / MANIFEST, json.dumps(
            {"what": "the completed chunks of an interrupted `hpgen run` (chunk_*.npz: t and "
                     "the records of each chunk, and under state.* the run's state after "
                     "it); continue it with --resume, or delete this folder",
             "format": PARTIAL_FORMAT, "output": self.out.name, "run": ident,
             "resume": hint}, indent=1, sort_keys=True) + "\n")
        self.keep = False          # nothing worth keeping until the first chunk is committed
        return _Progress()

    def resume(self, ident, hint) -> _Progress:
        self._take_lock()
        files = self._committed()
        if not files:
            return self.fresh(ident, hint)
        man = _read_manifest(self.parts)
        for key, value in ident.items():
            if man["run"].get(key) != value:
                raise ModelError(f"cannot resume {self.parts}: it is a run with {key} "
                                 f"{man['run'].get(key)!r}, this run has {value!r}; run with "
                                 "the same model, options and scene, or delete the folder to "
                                 "start over", file=str(self.parts))
        try:
            with np.load(files[-1], allow_pickle=False) as f:
                prog = _Progress.from_state({k[len(_STATE):]: f[k] for k in f.files
                                             if k.startswith(_STATE)})
        except (OSError, ValueError, KeyError, zipfile.BadZipFile) as e:
            raise ModelError(f"cannot resume {self.parts}: {files[-1].name} is unreadable "
                             f"({e}); delete the folder to start over",
                             file=str(self.parts)) from None
        if prog.chunks != len(files):
            raise ModelError(f"cannot resume {self.parts}: {files[-1].name} says "
                             f"{prog.chunks} chunks; delete the folder to start over",
                             file=str(self.parts))
        for p in self.parts.glob(".*.tmp"):      # temp files of a write that was killed
            p.unlink()
        for p in self.parts.glob("chunk_*.npz"):  # chunks after the last committed one
            if p not in files:
                p.unlink()
        self.keep = True
        return prog

    def write_chunk(self, i, rec, extra=None):
        write_npz(self.parts / _chunk_name(i), {"t": rec.t, **rec.arrays, **(extra or {})})

    def commit(self, prog: _Progress, rec, snapshot: dict):
        """Chunk prog.chunks - 1, ``rec`` (folded into prog), is complete: write it with the
        run's state after it (``snapshot``) and the totals; its file is the commit."""
        state = {**prog.totals(), **{f"run_{k}": v for k, v in snapshot.items()}}
        self.write_chunk(prog.chunks - 1, rec, {_STATE + k: v for k, v in state.items()})
        self.keep = True

    def assemble(self, path: Path, prog: _Progress, meta: dict):
        """Stream the chunk files 0 .. prog.chunks - 1 into the .npz ``path`` (atomically)."""
        files = [self.parts / _chunk_name(i) for i in range(prog.chunks)]
        with atomic_output(path, directory=self.parts) as fh:
            with zipfile.ZipFile(fh, "w", zipfile.ZIP_STORED, allowZip64=True) as zf:
                with np.load(files[0]) as first:
                    names = [k for k in first.files if not k.startswith(_STATE)]
                    heads = {k: (first[k].dtype, first[k].shape[1:]) for k in names}
                # chunk files kept open across the names (their zip directories read once),
                # at most OPEN_MAX at a time
                opened = {} if len(files) <= OPEN_MAX else None
                for name in names:
                    dtype, tail = heads[name]
                    with zf.open(name + ".npy", "w", force_zip64=True) as f:
                        np.lib.format.write_array_header_1_0(f, {
                            "descr": np.lib.format.dtype_to_descr(dtype),
                            "fortran_order": False, "shape": (prog.samples,) + tail})
                        for file in files:
                            part = opened.get(file) if opened is not None else None
                            if part is None:
                                part = np.load(file)
                                if opened is not None:
                                    opened[file] = part
                            f.write(np.ascontiguousarray(part[name], dtype=dtype).data)
                            if opened is None:
                                part.close()
                for part in (opened or {}).values():
                    part.close()
                for name, value in meta.items():
                    with zf.open(name + ".npy", "w", force_zip64=True) as f:
                        np.lib.format.write_array(f, np.asanyarray(value), allow_pickle=False)


def _chunk_name(i: int) -> str:
    return f"chunk_{i:06d}.npz"


def _write_text(path: Path, text: str):
    write_file(path, text)


def _npz_names(file: Path) -> list:
    try:
        with zipfile.ZipFile(file) as zf:
            return [n[:-4] for n in zf.namelist()]
    except (OSError, zipfile.BadZipFile):
        return []


def _read_manifest(parts: Path) -> dict:
    try:
        man = json.loads((parts / MANIFEST).read_text())
        if man.get("format") != PARTIAL_FORMAT:
            raise ValueError(f"format {man.get('format')!r}")
        if not isinstance(man["run"], dict):
            raise ValueError("no run")
        return man
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise ModelError(f"{parts} is not a resumable partial run ({MANIFEST}: {e}); delete "
                         "it to start over", file=str(parts)) from None


def _leftover_line(parts: Path) -> str:
    """One line naming what an earlier, interrupted run left and how to continue it."""
    try:
        man = _read_manifest(parts)
        files = _Folder(parts, None)._committed()
        with np.load(files[-1]) as f:
            chunks, k, samples, _ = (int(v) for v in f[_STATE + "totals"])
        what = (f"holds {chunks} completed chunks ({k} of {man['run']['steps']} steps, "
                f"{samples} samples) of an interrupted run")
        how = f"continue it with `{man['resume']}`" if man.get("resume") else \
            "continue it with --resume"
    except (ModelError, OSError, ValueError, KeyError, IndexError, zipfile.BadZipFile):
        what, how = "is left by an interrupted run (unreadable)", "delete it"
    return f"{what}; {how}, or delete the folder to start over"


def _identity(integ, h, steps, every, opts, gf, mu0, z0) -> dict:
    """What a resumed run must share with the interrupted one (JSON-comparable)."""
    start = hashlib.sha256()
    for a in (gf, mu0, z0):
        start.update(np.ascontiguousarray(a, dtype=np.float64).tobytes())
    meta = integ.meta
    return {"module": meta["module"], "hash": meta["hash"], "backend": integ._b.name,
            "h": float(h).hex(), "steps": int(steps), "every": int(every),
            "start_sha256": start.hexdigest(), "newton": repr(opts)}


def _remove_old_leftovers(path: Path) -> list:
    """hpgen <= 0.1 kept a chunked run in a hidden ``.<out>.<random>/`` folder of memory
    maps, never resumable: remove those of this output; returns their paths."""
    removed = []
    for old in sorted(path.parent.glob(f".{path.name}.*")):
        if old.is_dir() and not old.is_symlink():
            shutil.rmtree(old, ignore_errors=True)
            removed.append(old)
    return removed
