"""One chunk of a sweep: a contiguous slice of members run by the C batch loops.

The same function runs a chunk on the local threads and inside a Dask task on a worker, so
both paths give bitwise the same numbers. ``record`` None keeps the states (g, mu) through
``Integrator.simulate_batch``; a list of names keeps those entries of the module's compiled
record row (the scene's ``record:`` list) through ``Integrator.record_batch``.

A member whose run fails (ConvergenceError, DomainError, RecordError: Newton, the chart's
domain, a non-finite recorded value, or inverting the Legendre transform at its start) is
marked failed with the error's text; the samples before the failure are kept and the later
ones are NaN. Bad input (ModelError, e.g. g0 off the group) fails the sweep, naming the member.
numpy and the standard library only.
"""
from __future__ import annotations

import numpy as np

from ..errors import ArgumentError, ConvergenceError, ModelError
from ..runtime import counters
from .members import Members

STATE = ("g", "mu")


def layout(integ, record) -> tuple[bool, tuple, dict]:
    """(uses the record row, names, {name: sample shape}) of ``record`` (None: g and mu)."""
    n, d = integ.n, integ.d
    if record is None:
        return False, STATE, {"g": (n, n), "mu": (d,)}
    if isinstance(record, str) or not all(isinstance(r, str) for r in record) or not record:
        raise ModelError("expected a non-empty list of record names", field="record")
    names = tuple(record)
    shapes = {name: tuple(shape) for name, _, shape in integ.meta["record"]}
    missing = [r for r in names if r not in shapes]
    if missing:
        raise ModelError(f"{missing[0]!r} is not in the module's record row "
                         f"({', '.join(shapes)}: the scene's record: list); add it there, or "
                         "give record=None for the states g and mu", field="record")
    if len(set(names)) != len(names):
        raise ModelError("a record name is listed twice", field="record")
    return True, names, {r: shapes[r] for r in names}


def run_chunk(integ, m: Members, start: int, steps: int, every: int, record,
              threads: int = 1) -> dict:
    """Run the members ``m`` (global indices start, start + 1, ...): a dict of arrays,
    ``arrays`` {name: (b, K, *shape)}, ``failed`` (b,) bool, ``error`` (b,) str,
    ``samples`` (b,) samples kept, ``steps_done`` (b,), and per counter of
    hpgen.runtime.counters (``newton_iterations``, ``guarded``) its (b,) totals."""
    rows, names, shapes = layout(integ, record)
    b, K = len(m), steps // every + 1
    out = {"arrays": {r: np.full((b, K) + shapes[r], np.nan) for r in names},
           "failed": np.zeros(b, dtype=bool), "error": np.full(b, "", dtype=object),
           "samples": np.zeros(b, dtype=np.int64), "steps_done": np.zeros(b, dtype=np.int64),
           **{name: np.zeros(b, dtype=np.int64) for name in counters.NAMES}}
    for hv in dict.fromkeys(m.h.tolist()):            # distinct h, in member order
        idx = np.flatnonzero(m.h == hv)
        try:
            runs = _batch(integ, m, idx, hv, steps, every, rows, threads)
        except (ConvergenceError, ModelError, ArgumentError):
            runs = [_alone(integ, m, i, hv, steps, every, rows, start) for i in idx]
        for i, run in zip(idx, runs):
            _store(out, i, run, names, steps)
    out["error"] = out["error"].astype(str)
    return out


def _batch(integ, m, idx, h, steps, every, rows, threads):
    run = integ.record_batch if rows else integ.simulate_batch
    return run(m.g0[idx], h, steps, every=every, threads=threads, progress=False,
               **m.take(idx))


def _alone(integ, m, i, h, steps, every, rows, start):
    """Member i on its own (its batch raised at the start): the run, or the error when its
    start fails to converge; ModelError names the member."""
    try:
        return _batch(integ, m, [i], h, steps, every, rows, 1)[0]
    except ModelError as e:
        raise e.located(field=f"member {start + i}") if not e.field else ModelError(
            e.message, file=e.file, line=e.line, field=f"member {start + i}: {e.field}") \
            from None
    except ArgumentError as e:        # the runtime's check of one member's start
        raise ModelError(e.message, field=f"member {start + i}"
                         + (f": {e.field}" if e.field else "")) from None
    except ConvergenceError as e:
        return e


def _store(out, i, run, names, steps):
    if isinstance(run, ConvergenceError):          # failed at its start: no sample
        out["failed"][i], out["error"][i] = True, str(run)
        return
    K = len(run.t)
    for r in names:
        out["arrays"][r][i, :K] = run[r] if hasattr(run, "arrays") else getattr(run, r)
    out["samples"][i] = K
    for name, n in counters.of(run).items():
        out[name][i] = n
    out["steps_done"][i] = steps if run.error is None else run.error.step
    if run.error is not None:
        out["failed"][i], out["error"][i] = True, str(run.error)
