"""hpgen.sweep: run many members of one integrator, on local threads or on a Dask cluster.

    res = hpgen.sweep(integ, xi0=W0, h=0.05, steps=10**5, record=["energy"], every=100)
    res = hpgen.sweep(integ, xi0=W0, h=0.05, steps=10**5, client=Client("tcp://..."))
    res.save("sweep.zarr")            # or .nc, .npz: hpgen.ensemble.result

The members are split into contiguous chunks (``chunk_size`` members); each chunk runs the C
batch loop of the integrator (hpgen.ensemble.chunk). Without ``client`` the chunks run one
after the other, each over ``threads`` local threads; with a dask.distributed Client each
chunk is one task, shipped with the module's sources and their content hash
(hpgen.ensemble.remote) and run on one worker thread. The numbers do not depend on the path,
the chunking or the threads: every member's samples are bitwise those of ``simulate_batch``
(or ``record_batch``) on the same inputs. A worker lost mid-task costs its chunk only: the
scheduler runs it again on another worker (Dask's own retry of tasks of lost workers).

``checkpoint``: a directory where each completed chunk is saved as it completes; a sweep
started again with the same inputs and checkpoint reuses the chunks found there (``hpgen sweep
--resume``); its parts are checked on load and the folder is locked while the sweep runs
(hpgen.ensemble.parts).
"""
from __future__ import annotations

import hashlib
import json
import os

import numpy as np

from ..errors import ModelError
from ..runtime.args import _int
from ..runtime.progress import bar as progress_bar
from . import remote
from .chunk import layout, run_chunk
from .members import chunk_bounds, default_chunk_size, members, run_length
from .parts import Checkpoint
from .result import concat


def sweep(integ, g0=None, xi0=None, mu0=None, h=None, steps=None, record=None, every=1,
          chunk_size=None, client=None, threads=None, progress=None, params=None,
          checkpoint=None, u=None):
    """Run B members and return a SweepResult (hpgen.ensemble.result).

    integ: a C-backend Integrator (hpgen.compile / hpgen.load). g0: (n, n) shared or
    (B, n, n), default the identity; xi0 or mu0: (B, d), exactly one; h: a step shared by all
    members or one per member (B,); steps, every: as for simulate (K = steps // every + 1
    samples). record: None keeps g and mu; a list of names keeps those entries of the
    module's record row (``integ.record_names``). params: {runtime parameter name: values
    (B, *shape), member i's in row i} (a model with runtime_parameters; no recompile).
    u: the control inputs of a model with inputs, shared ((m,) constant or (steps, m) one
    row per step) or one per member ((B, m) or (B, steps, m); a (B, m) u with B == steps is
    the shared (steps, m)), held over each step as for simulate. chunk_size: members per
    chunk (default: all in one chunk locally, about 4 chunks per worker thread on Dask,
    smaller when a checkpoint or progress bar wants progress). client: a dask.distributed Client, or None for the local
    threads (``threads``, default the CPU count). progress: tqdm bar of members done on
    stderr (None: when stderr is a terminal). checkpoint: directory of completed chunks (see
    the module docstring). Failed members are marked (``failed``, ``error``) with their
    samples before the failure; nothing is raised for them. Raises ModelError for bad input.
    """
    if integ.backend != "c":
        raise ModelError("sweep needs the C backend (hpgen.compile(..., backend='c'))",
                         field="backend")
    if h is None or steps is None:
        raise ModelError("give the step h and the number of steps", field="h" if h is None
                         else "steps")
    g0 = np.eye(integ.n) if g0 is None else g0
    steps, every, K = run_length(steps, every)
    m = members(integ, g0, xi0, mu0, h, params, u, steps)
    _, names, shapes = layout(integ, record)                # check the names before running
    B = len(m)
    threads = _int(threads if threads is not None else (os.cpu_count() or 1), "threads", 1)
    slots = sum(client.nthreads().values()) if client is not None else threads
    if chunk_size is None:
        local_whole = client is None and checkpoint is None and not _wants(progress)
        chunk_size = B if local_whole else (default_chunk_size(B, slots) if client is not None
                                            else max(threads, -(-B // 20)))
    bounds = chunk_bounds(B, chunk_size)
    payload = remote.payload_of(integ) if (client is not None or checkpoint) else None
    store = Checkpoint(checkpoint, _fingerprint(payload, m, steps, every, record, bounds),
                       {r: (K, *shapes[r]) for r in names}) if checkpoint is not None else None
    done = {} if store is None else store.load(bounds)
    with progress_bar(B, "sweep", "member", progress) as pbar:
        pbar.update(sum(hi - lo for lo, hi in done))
        todo = [b for b in bounds if b not in done]
        if client is None:
            for lo, hi in todo:
                done[lo, hi] = _keep(store, (lo, hi), run_chunk(
                    integ, m.slice(lo, hi), lo, steps, every, record, threads))
                pbar.update(hi - lo)
        else:
            _on_dask(client, payload, m, todo, steps, every, record, store, done, pbar)
    step = np.arange(0, K * every, every)
    initial = {"g0": np.array(m.g0), m.kind: m.init}
    attrs = {"module": integ.meta["module"], "hash": integ.meta["hash"], "steps": steps,
             "every": every, "forced": int(bool((integ.meta.get("open") or {}).get("forced")))}
    return concat([done[b] for b in bounds], step, m.h, initial, attrs, m.params)


def _wants(progress) -> bool:
    from ..runtime.progress import wanted
    return wanted(progress)


def _keep(store, bounds, result):
    if store is not None:
        store.save(bounds, result)
    return result


def _on_dask(client, payload, m, todo, steps, every, record, store, done, pbar):
    """One task per chunk; results kept as they complete; on an error (bad input) or an
    interrupt the remaining tasks are cancelled."""
    from distributed import as_completed
    if not todo:
        return
    shipped = client.scatter(payload, broadcast=True, hash=False)
    futures = {client.submit(remote.run_task, shipped, m.slice(lo, hi), lo, steps, every,
                             record, 1, pure=False): (lo, hi) for lo, hi in todo}
    try:
        for fut in as_completed(list(futures)):
            lo, hi = futures[fut]
            done[lo, hi] = _keep(store, (lo, hi), fut.result())
            pbar.update(hi - lo)
    finally:
        client.cancel(list(futures) + [shipped])


def _fingerprint(payload, m, steps, every, record, bounds) -> str:
    h = hashlib.sha256()
    h.update(payload.digest.encode())
    for a in (m.g0, m.init, m.h, *m.params.values(), *([] if m.u is None else [m.u])):
        h.update(np.ascontiguousarray(a, dtype=np.float64).tobytes())
    h.update(json.dumps([m.kind, steps, every, None if record is None else list(record),
                         bounds, list(m.params)]
                        + ([] if m.u is None else [list(m.u.shape), m.u_per_member])).encode())
    return h.hexdigest()
