"""The folder ``<out>.partial/`` of a chunked run (hpgen.runtime.chunked_output) and the
run's running totals: ``PartialFolder`` creates it (or takes it over to resume), locks it
against a second writer, commits one chunk file per completed chunk (written to a temp file
and renamed: a chunk is committed when its file exists), streams the chunks into the final
``.npz`` and removes the folder unless the run was interrupted; ``Progress`` holds the
totals (chunks, steps, samples, the run's counters (hpgen.runtime.counters: Newton
iterations, steps re-solved by the guard), first values and max changes of energy,
momentum, conserved directions and a forced model's energy-work balance) saved in each
chunk next to the backend's snapshot of the run. numpy and the standard library only.
"""
from __future__ import annotations

import json
import shutil
import signal
import threading
import zipfile
from contextlib import contextmanager
from pathlib import Path

import numpy as np

from ..errors import ModelError
from ..files import atomic_output, write_file
from . import counters
from .checked_npz import is_intact
from .trajectory import write_npz

#: the layout of ``<out>.partial/`` (bump when it changes: an older folder is not resumed)
PARTIAL_FORMAT = 1
MANIFEST = "manifest.json"
STATE = "state."          # key prefix of the run state in a chunk file
OPEN_MAX = 256            # chunk files held open at once while assembling the output


@contextmanager
def interrupts_deferred():
    """Within: SIGINT and SIGTERM are recorded, not acted on, and the first is raised again
    on exit to the handler in place before, so a file being written is complete before the
    interrupt's KeyboardInterrupt (raised inside zipfile's writer it left a half-closed
    archive and a ValueError instead). Python handlers run in the main thread whichever
    thread the signal reaches; elsewhere this changes nothing."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    pending: list = []
    old = {s: signal.signal(s, lambda signum, frame: pending.append(signum))
           for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    finally:
        for s, handler in old.items():
            signal.signal(s, signal.SIG_DFL if handler is None else handler)
        if pending:
            signal.raise_signal(pending[0])


class Progress:
    """Running totals of a chunked run: chunks, steps done k, samples, ``counts`` {name:
    total} of the run's counters (hpgen.runtime.counters; a resumed run's count those of
    both runs), the first samples of energy / momentum and the max change so far of energy, momentum
    and its projections on ``directions`` ("conserved"); ``state`` the snapshot to continue
    from (a resumed run) and ``work`` the accumulated work's (WorkSum.state; empty when
    the run records no work)."""
    CHANGES = ("energy", "momentum", "conserved", "balance")

    def __init__(self, directions=None):
        self.chunks = self.k = self.samples = 0
        self.counts = dict.fromkeys(counters.NAMES, 0)
        self.first, self.change, self.state = {}, {}, None
        #: a run that records work: the WorkSum's state (hpgen.runtime.work) to continue
        self.work = {}
        self.directions = directions

    def added(self, rec, k) -> "Progress":
        """A copy with one more chunk, ``rec``, folded in; k: the steps done after it."""
        new = Progress(self.directions)
        new.chunks, new.k = self.chunks + 1, k
        new.samples = self.samples + len(rec.t)
        new.counts = {name: self.counts[name] + n for name, n in counters.of(rec).items()}
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
        """The totals as arrays (saved next to the run's state): "totals" (chunks, k, samples,
        newton_iterations: the layout an older hpgen reads) and "count_<name>" per counter."""
        out = {"totals": np.array([self.chunks, self.k, self.samples,
                                   self.counts["newton_iterations"]], dtype=np.int64)}
        out.update({f"count_{k}": np.array(v, dtype=np.int64) for k, v in self.counts.items()})
        out.update({f"first_{k}": np.asarray(v) for k, v in self.first.items()})
        out.update({f"change_{k}": np.asarray(v) for k, v in self.change.items()})
        return out

    @classmethod
    def from_state(cls, arrays: dict) -> "Progress":
        prog = cls()
        prog.chunks, prog.k, prog.samples, iterations = (int(v) for v in arrays["totals"])
        # (a folder of an older hpgen: no count_*; its Newton iterations are in totals)
        prog.counts = counters.read({k[len("count_"):]: v for k, v in arrays.items()
                                     if k.startswith("count_")})
        if "count_newton_iterations" not in arrays:
            prog.counts["newton_iterations"] = iterations
        for name in cls.CHANGES:
            if f"first_{name}" in arrays:
                prog.first[name] = arrays[f"first_{name}"]
            if f"change_{name}" in arrays:
                prog.change[name] = arrays[f"change_{name}"]
        prog.state = {k[len("run_"):]: v for k, v in arrays.items() if k.startswith("run_")}
        prog.work = {k[len("work_"):]: v for k, v in arrays.items() if k.startswith("work_")}
        return prog


class PartialFolder:
    """``<out>.partial/``: created (or resumed) on entry, locked against a second writer,
    removed on exit unless ``keep`` (an interrupted or crashed run). ``progress``: the
    Progress of the last committed chunk (the run's start before the first), set with the
    commit itself, so that an interrupt delivered as the commit ends sees it."""

    def __init__(self, parts: Path, out: Path):
        self.parts, self.out, self.keep, self._lock = parts, out, True, None
        self.progress = Progress()

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

    def committed_files(self) -> list:
        """The committed chunk files 0, 1, ... (consecutive; the last holds a state)."""
        files: list = []    # up to the first damaged file (it and those after are redone)
        while is_intact(self.parts / _chunk_name(len(files))):
            files.append(self.parts / _chunk_name(len(files)))
        while files and STATE + "totals" not in _npz_names(files[-1]):
            files.pop()          # a failed run's last chunk (no state), never committed
        return files

    def fresh(self, ident, hint) -> Progress:
        self._take_lock()
        if self.committed_files():
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
        self.progress = Progress()
        return self.progress

    def resume(self, ident, hint) -> Progress:
        self._take_lock()
        files = self.committed_files()
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
                prog = Progress.from_state({k[len(STATE):]: f[k] for k in f.files
                                             if k.startswith(STATE)})
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
        self.keep, self.progress = True, prog
        return prog

    def write_chunk(self, i, rec, extra=None, committed: Progress | None = None):
        """Write chunk file i; ``committed``: the Progress the file commits (a chunk with
        the run's state), recorded before a deferred interrupt is delivered."""
        with interrupts_deferred():
            write_npz(self.parts / _chunk_name(i), {"t": rec.t, **rec.arrays, **(extra or {})})
            if committed is not None:
                self.keep, self.progress = True, committed

    def commit(self, prog: Progress, rec, snapshot: dict, work: dict | None = None):
        """Chunk prog.chunks - 1, ``rec`` (folded into prog), is complete: write it with the
        run's state after it (``snapshot``; ``work``: the accumulated work's WorkSum.state,
        a run that records work) and the totals; its file is the commit (``progress``
        becomes prog, the folder is kept)."""
        state = {**prog.totals(), **{f"run_{k}": v for k, v in snapshot.items()},
                 **{f"work_{k}": v for k, v in (work or {}).items()}}
        self.write_chunk(prog.chunks - 1, rec, {STATE + k: v for k, v in state.items()}, prog)

    def assemble(self, path: Path, prog: Progress, meta: dict):
        """Stream the chunk files 0 .. prog.chunks - 1 into the .npz ``path`` (atomically;
        an interrupt meanwhile is delivered once the file is complete)."""
        files = [self.parts / _chunk_name(i) for i in range(prog.chunks)]
        with interrupts_deferred(), atomic_output(path, directory=self.parts) as fh:
            with zipfile.ZipFile(fh, "w", zipfile.ZIP_STORED, allowZip64=True) as zf:
                with np.load(files[0]) as first:
                    names = [k for k in first.files if not k.startswith(STATE)]
                    heads = {k: (first[k].dtype, first[k].shape[1:]) for k in names}
                # chunk files kept open across the names (their zip directories read once),
                # at most OPEN_MAX at a time
                opened: dict | None = {} if len(files) <= OPEN_MAX else None
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
        files = PartialFolder(parts, parts).committed_files()   # (lists chunks only)
        with np.load(files[-1]) as f:
            chunks, k, samples, _ = (int(v) for v in f[STATE + "totals"])
        what = (f"holds {chunks} completed chunks ({k} of {man['run']['steps']} steps, "
                f"{samples} samples) of an interrupted run")
        how = f"continue it with `{man['resume']}`" if man.get("resume") else \
            "continue it with --resume"
    except (ModelError, OSError, ValueError, KeyError, IndexError, zipfile.BadZipFile):
        what, how = "is left by an interrupted run (unreadable)", "delete it"
    return f"{what}; {how}, or delete the folder to start over"
