"""Ensembles on the C backend: B independent runs stepped by one C call per thread slice
(``hpgen_advance_batch``, its 8-lane variant ``hpgen_advance_batch_lanes`` when the module
has lane code, ``hpgen_advance_record_batch``); ctypes releases the GIL during each call.
The functions take the CBackend (its ``lib``, sizes, ``run_size``, ``lanes``, ``init_run``,
``set_inputs`` and ``record``); CBackend.simulate_batch / record_batch call them. Standard
library and numpy only.
"""
from __future__ import annotations

import ctypes

import numpy as np

from .. import abi
from . import loop
from .backends import _flat
from .cstructs import _Options, _Status


def _over_threads(B: int, threads: int, work, bar=None, align: int = 1) -> None:
    """work(lo, hi) on contiguous slices of range(B), one slice per thread (at most B
    threads; the C calls inside release the GIL through ctypes). With a progress ``bar``
    (hpgen.runtime.progress) the slices are about 20 per thread, the bar advancing by each
    slice's members as it completes (runs are independent: the states do not change).
    Inner slice bounds are multiples of ``align`` (lane groups stay whole)."""
    from concurrent.futures import ThreadPoolExecutor
    threads = max(1, min(int(threads), B))
    parts = threads if bar is None else min(B, 20 * threads)
    bounds = [min(B, (B * i // parts + align // 2) // align * align) for i in range(parts)] + [B]
    slices = [(lo, hi) for lo, hi in zip(bounds, bounds[1:]) if hi > lo]

    def run(s):
        work(*s)
        if bar is not None:
            bar.update(s[1] - s[0])

    if threads <= 1 or len(slices) <= 1:
        for s in slices:
            run(s)
        return
    with ThreadPoolExecutor(threads) as pool:
        list(pool.map(run, slices))


def batch_runs(cb, g0s, p0s, z0s, inputs=None):
    """(buffer, its address): B C runs, run b started at (g0s[b], p0s[b]), z0s[b], with
    inputs[b] (StepInputs) for an open module."""
    nn, d, B = cb.n * cb.n, cb.d, len(g0s)
    runs = ctypes.create_string_buffer(cb.run_size * B)
    base = ctypes.addressof(runs)
    keep = []
    for b in range(B):
        g0, p0 = _flat(g0s[b], nn, "g0"), _flat(p0s[b], d, "p0")
        cb.init_run(base + b * cb.run_size, g0, p0, _flat(z0s[b], cb.nz, "z0"))
        if cb.open:
            keep.append(cb.set_inputs(base + b * cb.run_size, inputs[b]))
    runs.keep = keep
    return runs, base


def simulate_batch(cb, g0s, p0s, h, z0s, steps, every, opts, threads, inputs=None,
                   bar=None, lanes=True):
    """B independent runs; each thread advances a contiguous slice of them with one C
    call (ctypes releases the GIL). Returns (done (B,), g_rec (B, K, nn), p_rec (B, K, d),
    statuses); K = steps // every + 1 including step 0; rows after a failure are 0.
    With ``lanes`` and a module that has lane code (``cb.lanes`` > 0), the C call is
    hpgen_advance_batch_lanes (L bodies a call, the plain or the composed step, bitwise the
    same results), else hpgen_advance_batch."""
    nn, d, B = cb.n * cb.n, cb.d, len(g0s)
    K = steps // every + 1
    runs, base = batch_runs(cb, g0s, p0s, z0s, inputs)
    g_rec, p_rec = np.zeros((B, K, nn)), np.zeros((B, K, d))
    g_rec[:, 0] = np.asarray(g0s, dtype=np.float64).reshape(B, nn)
    p_rec[:, 0] = np.asarray(p0s, dtype=np.float64).reshape(B, d)
    sts, o = (_Status * B)(), _Options.of(opts)

    use_lanes = bool(lanes and cb.lanes)
    advance = (cb.lib.hpgen_advance_batch_lanes if use_lanes
               else cb.lib.hpgen_advance_batch)

    def work(lo, hi):
        advance(base + lo * cb.run_size, hi - lo, float(h), steps, every,
                ctypes.byref(o), K, g_rec[lo:, 1:].ctypes.data, p_rec[lo:, 1:].ctypes.data,
                ctypes.byref(sts, lo * ctypes.sizeof(_Status)))

    _over_threads(B, threads, work, bar, cb.lanes if use_lanes else 1)
    done = np.array([s.step for s in sts])
    return done, g_rec, p_rec, [s.as_dict() for s in sts]


def record_batch(cb, g0s, p0s, h, z0s, steps, every, opts, threads, bar=None,
                 inputs=None):
    """B independent runs keeping record rows (hpgen_advance_record_batch), each thread
    a contiguous slice in one C call. Returns (rows (B, K, W) with row 0 the start,
    rows written per run (B,) including row 0, statuses); codes of row 0 that failed
    are reported in the status with step 0 (the run is not stepped). inputs: per-run
    StepInputs of an open module."""
    B, W = len(g0s), cb.record_width
    K = steps // every + 1
    runs, base = batch_runs(cb, g0s, p0s, z0s, inputs)
    rows = np.zeros((B, K, W))
    first = [cb.record(g0s[b], p0s[b]) if inputs is None else
             cb.record(g0s[b], p0s[b], inputs[b]) for b in range(B)]
    for b, (_, row) in enumerate(first):
        rows[b, 0] = row
    n_rec = np.zeros(B, dtype=np.int64)
    sts, o = (_Status * B)(), _Options.of(opts)

    def work(lo, hi):
        cb.lib.hpgen_advance_record_batch(
            base + lo * cb.run_size, hi - lo, float(h), steps, every,
            ctypes.byref(o), K, rows[lo:, 1:].ctypes.data, n_rec[lo:].ctypes.data,
            ctypes.byref(sts, lo * ctypes.sizeof(_Status)))

    _over_threads(B, threads, work, bar)
    out = [s.as_dict() for s in sts]
    for b, (code, _) in enumerate(first):
        if code != abi.OK:
            out[b] = {**loop.new_status(), "code": int(code)}
            n_rec[b] = 0
    return rows, n_rec + 1, out
