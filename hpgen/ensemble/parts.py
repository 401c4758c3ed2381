"""The checkpoint of a sweep on disk: one file per completed chunk ("part"), checked on load.

The folder holds ``sweep.json`` (the sweep's fingerprint: module content hash, inputs, steps,
every, record, chunking) and ``chunk-<lo>-<hi>.npz``, one per completed chunk of members
[lo, hi), written atomically. Each part carries its member range (``part_range``) and the
fingerprint next to the chunk's arrays (``a:<record>`` (hi - lo, K, *shape) and the
per-member ``failed``, ``error``, ``samples``, ``steps_done`` and the run's counters
``newton_iterations``, ``guarded`` (hpgen.runtime.counters; one that a part of an older
hpgen lacks reads as 0)). A part is used only when it is readable, its range and fingerprint
are this chunk's and this sweep's, and every array has the expected shape and kind; any
other part (damaged, renamed, swapped with another, from another sweep, or a foreign .npz)
is run again and overwritten.

While a sweep uses the folder it holds an exclusive lock on it (flock on the directory): a
sweep of another process on the same folder is refused (ModelError) instead of racing the
first. The lock is released when the Checkpoint is closed or collected (and shared within a
process, so that an interrupted sweep's Checkpoint still referenced by a traceback does not
lock out the next one). numpy and the standard
library only.
"""
from __future__ import annotations

import json
import os
import weakref
import zipfile
from pathlib import Path

import numpy as np

from ..errors import ModelError
from ..files import atomic_output
from ..runtime import counters

FINGERPRINT = "sweep.json"
CHUNK_KEYS = ("failed", "error", "samples", "steps_done", *counters.NAMES)
#: the kind of each per-member array of a part (numpy dtype kinds)
_KINDS = {"failed": "b", "error": "U", "samples": "iu", "steps_done": "iu",
          **dict.fromkeys(counters.NAMES, "iu")}


class Checkpoint:
    """The parts of one sweep in ``directory``: locked on creation; ``load`` the valid parts,
    ``save`` one more. ``shapes``: {record name: (K, *sample shape)} each part must hold."""

    def __init__(self, directory, fingerprint: str, shapes: dict | None = None):
        self.dir, self.fingerprint = Path(directory), fingerprint
        self.shapes = None if shapes is None else {k: tuple(v) for k, v in shapes.items()}
        self.dir.mkdir(parents=True, exist_ok=True)
        self._lock = _lock(self.dir)
        self._release = weakref.finalize(self, _unlock, self._lock)
        path = self.dir / FINGERPRINT
        if path.exists():
            try:
                found = json.loads(path.read_text()).get("fingerprint")
            except (OSError, ValueError, AttributeError):
                found = None
            if found != fingerprint:
                self.close()
                raise ModelError("holds the chunks of a different sweep (other module, inputs "
                                 "or chunking); remove it or choose another", file=str(self.dir))
        else:
            with atomic_output(path, "w") as fh:
                fh.write(json.dumps({"fingerprint": fingerprint}) + "\n")

    def close(self) -> None:
        """Release the folder's lock (also done when the Checkpoint is collected)."""
        self._release()

    def path(self, bounds) -> Path:
        return self.dir / f"chunk-{bounds[0]}-{bounds[1]}.npz"

    def save(self, bounds, result: dict) -> None:
        data = {f"a:{k}": v for k, v in result["arrays"].items()}
        data.update({k: result[k] for k in CHUNK_KEYS})
        data["error"] = np.asarray(result["error"], dtype=str)
        data["part_range"] = np.array(bounds, dtype=np.int64)
        data["fingerprint"] = np.str_(self.fingerprint)
        self.dir.mkdir(parents=True, exist_ok=True)
        with atomic_output(self.path(bounds)) as fh:
            np.savez(fh, **data)

    def load(self, bounds) -> dict:
        """{bounds: chunk dict} of the valid parts on disk (any other is redone)."""
        out = {}
        for b in bounds:
            part = self._read(b)
            if part is not None:
                out[b] = part
        return out

    def _read(self, bounds):
        try:
            with np.load(self.path(bounds), allow_pickle=False) as z:
                data = {k: z[k] for k in z.files}
        except (OSError, ValueError, KeyError, EOFError, zipfile.BadZipFile):
            return None
        if not self._valid(bounds, data):
            return None
        zeros = np.zeros(bounds[1] - bounds[0], dtype=np.int64)
        return {"arrays": {k[2:]: v for k, v in data.items() if k.startswith("a:")},
                **{k: data.get(k, zeros) for k in CHUNK_KEYS}}

    def _valid(self, bounds, data: dict) -> bool:
        """The part's range, fingerprint, keys, shapes and kinds are this chunk's."""
        lo, hi = bounds
        b = hi - lo
        rng, fp = data.get("part_range"), data.get("fingerprint")
        if rng is None or fp is None or rng.shape != (2,) or rng.tolist() != [lo, hi] \
                or fp.shape != () or str(fp) != self.fingerprint:
            return False
        for k in CHUNK_KEYS:
            a = data.get(k)
            if a is None and k in counters.NAMES:         # (a part of an older hpgen)
                continue
            if a is None or a.shape != (b,) or a.dtype.kind not in _KINDS[k]:
                return False
        arrays = {k[2:]: v for k, v in data.items() if k.startswith("a:")}
        if not arrays or (self.shapes is not None and set(arrays) != set(self.shapes)):
            return False
        return all(a.dtype.kind == "f" and (a.shape[:1] == (b,) if self.shapes is None
                                             else a.shape == (b,) + self.shapes[k])
                   for k, a in arrays.items())


def refuse_if_in_use(directory) -> None:
    """ModelError when another process's sweep holds the lock of the parts folder
    ``directory`` (nothing when it does not exist, is free or is held by this process)."""
    directory = Path(directory)
    if directory.is_dir():
        _unlock(_lock(directory))


#: the parts folders this process holds: (st_dev, st_ino) -> [fd, holders]
_HELD: dict = {}


def _lock(directory: Path) -> tuple:
    """Hold the exclusive flock of ``directory`` (shared by this process's holders: a
    Checkpoint kept alive by a traceback does not lock out the next sweep of the same
    process); ModelError if another process holds it. Returns the key for _unlock."""
    import fcntl
    st = os.stat(directory)
    key = (st.st_dev, st.st_ino)
    if key in _HELD:
        _HELD[key][1] += 1
        return key
    fd = os.open(directory, os.O_RDONLY)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        raise ModelError("another hpgen sweep is using this folder of completed chunks; wait "
                         "for it to finish (or stop it) before resuming", file=str(directory)
                         ) from None
    _HELD[key] = [fd, 1]
    return key


def _unlock(key) -> None:
    held = _HELD.get(key)
    if held is None:
        return
    held[1] -= 1
    if held[1] == 0:
        os.close(held[0])
        del _HELD[key]
