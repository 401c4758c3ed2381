"""Long runs to disk with bounded memory: ``record_to_npz`` steps a scene in chunks
(``Integrator.stream_record``: the compiled record row, evaluated inside the C loop, holds
only what the scene's ``record:`` asks for: g, mu, xi, energy, momentum, defect, expressions)
and writes each chunk's arrays (and t) into preallocated ``.npy`` memory maps, then packs them
into one ``.npz``.

Memory holds one chunk of steps' records (``chunk`` steps, every ``every``-th recorded), never
the run: a 10^8-step run recorded every 10^3 steps keeps 10^5 rows on disk and at most
chunk / every rows in memory. The file equals that of ``Integrator.record`` on the whole run
saved at once (the states are bitwise those of ``simulate``).
The output appears atomically (temp file + os.replace); a failed step saves the records
before it with partial=True and re-raises. numpy and the standard library only.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

from ..errors import ConvergenceError
from .progress import bar as progress_bar
from .trajectory import npz_path, run_metadata, write_npz


def record_to_npz(integ, out, g0, h, steps, xi0=None, mu0=None, every=1,
                  chunk=1_000_000, progress=False, **newton_kw):
    """Run and save the module's record row (``integ.record_names``, one array each, and t);
    returns (path, summary): samples written, energy_max_change
    (max |E - E0|, if energy is recorded) and momentum_max_change (per component, if
    momentum is recorded). On a failed step the records before it are saved (partial=True)
    and the ConvergenceError is re-raised with ``.saved = (path, samples)``. progress: a bar
    of the steps done, per chunk (hpgen.runtime.progress; None: when stderr is a terminal)."""
    path = npz_path(out)
    K = steps // every + 1
    work = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
    maps, n, iters, error = {}, 0, 0, None
    summary = {"energy_max_change": None, "momentum_max_change": None}
    try:
        try:
            stepped = 0
            with progress_bar(steps, "run", "step", progress) as bar:
                for rec in integ.stream_record(g0=g0, h=h, steps=steps, xi0=xi0, mu0=mu0,
                                               every=every, chunk=chunk, **newton_kw):
                    n = _append(maps, work, K, n, {"t": rec.t, **rec.arrays}, summary)
                    iters += rec.newton_iterations
                    bar.update(min(chunk, steps - stepped))
                    stepped += min(chunk, steps - stepped)
        except ConvergenceError as exc:
            if exc.partial is None:
                raise
            n = _append(maps, work, K, n, {"t": exc.partial.t, **exc.partial.arrays}, summary)
            iters += exc.partial.newton_iterations
            error = exc
        arrays = {k: v[:n] for k, v in maps.items()}
        meta = run_metadata(integ, h, every, partial=error is not None,
                            newton_iterations=iters, error=error)
        write_npz(path, {**arrays, **meta})
    finally:
        maps.clear()
        shutil.rmtree(work, ignore_errors=True)
    summary["samples"] = n
    if error is not None:
        error.saved = (path, n)
        raise error
    return path, summary


def _append(maps, work, K, n, arrays, summary) -> int:
    """Copy one chunk's arrays into the memory maps (created on the first chunk); fold the
    chunk into the energy / momentum change summaries. Returns the rows written so far."""
    rows = len(arrays["t"])
    if not rows:
        return n
    for name, a in arrays.items():
        a = np.asarray(a)
        if name not in maps:
            maps[name] = np.lib.format.open_memmap(work / f"{name}.npy", mode="w+",
                                                   dtype=a.dtype, shape=(K,) + a.shape[1:])
        maps[name][n:n + rows] = a
    for name in ("energy", "momentum"):
        if name in arrays:
            change = np.abs(np.asarray(arrays[name]) - maps[name][0])
            change = change.max(axis=0)
            prev = summary[f"{name}_max_change"]
            summary[f"{name}_max_change"] = change if prev is None else np.maximum(prev, change)
    return n + rows
