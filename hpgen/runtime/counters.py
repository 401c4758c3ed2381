"""A run's counters: totals over its steps that every result of a run carries, in one list.

Each is read from the backend's status ``hpgen_status`` (abi.STATUS_FIELDS) of a backend
call and summed over the calls of a run: Trajectory, Records and SectionCrossings have it as
an attribute (an int); a saved run (Trajectory.save, Records.save, ``hpgen run``'s file) as
a scalar of that name; a chunked run (hpgen.runtime.partial_run) in its running totals, a
resumed run's the sum over both runs; a sweep (hpgen.ensemble) as a (B,) per-member array.
A file or a checkpoint written before a counter existed reads it as 0. A new counter is one
more entry of COUNTERS. The standard library only.
"""
from __future__ import annotations

#: (name, hpgen_status field): the name is the results' attribute and a saved file's key.
#: newton_iterations: the Newton iterations of every solve over all steps attempted;
#: guarded: the accepted steps the wrong-root guard solved again from the predictor's
#: base G (docs/numerics.md sec. 8; hpgen.runtime.guard), whichever root was kept
COUNTERS = (("newton_iterations", "total_iterations"), ("guarded", "guarded"))
#: the counters' names, in order
NAMES = tuple(name for name, _ in COUNTERS)
#: the status fields summed when a run's backend calls are joined: COUNTERS' and jacobians
#: (Trajectory and Records only: it is not saved)
STATUS_TOTALS = tuple(key for _, key in COUNTERS) + ("jacobians",)


def of_status(st) -> dict:
    """{name: int} of a status: a dict (``_Status.as_dict``, loop.new_status) or the ctypes
    ``_Status`` itself."""
    if isinstance(st, dict):
        return {name: int(st[key]) for name, key in COUNTERS}
    return {name: int(getattr(st, key)) for name, key in COUNTERS}


def of(result) -> dict:
    """{name: int} of one result (an object with the counters as attributes)."""
    return {name: int(getattr(result, name)) for name in NAMES}


def summed(results) -> dict:
    """{name: total} over ``results`` (objects with the counters as attributes)."""
    results = list(results)
    return {name: sum(int(getattr(r, name)) for r in results) for name in NAMES}


def read(data) -> dict:
    """{name: int} from a saved run's scalars (a mapping: an .npz, an xarray's attrs); a
    counter the file does not hold (written by an older hpgen) is 0."""
    return {name: int(data[name]) if name in data else 0 for name in NAMES}
