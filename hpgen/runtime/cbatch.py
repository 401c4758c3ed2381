"""Ensembles on the C backend: B independent runs started and stepped by C calls per
thread slice (``hpgen_run_init_batch``, then ``hpgen_advance_batch``, its 8-lane variant
``hpgen_advance_batch_lanes`` when the module has lane code, or
``hpgen_advance_record_batch``); ctypes releases the GIL during each call, so the threads
start their own runs while the others step theirs. The functions take the CBackend (its
``lib``, sizes, ``run_size``, ``lanes``, ``compose``, ``set_inputs`` and ``record``);
CBackend.simulate_batch / record_batch call them. Standard library and numpy only.
"""
from __future__ import annotations

import ctypes

import numpy as np

from .. import abi
from . import loop
from .cstructs import _Options, _Status
from .workers import run_slices


#: slices per thread of an ensemble without a progress bar: a thread that finishes early
#: (its cores shared, its bodies cheaper) takes the next slice, at a few microseconds a slice
SLICES_PER_THREAD = 4


def _over_threads(B: int, threads: int, work, bar=None, align: int = 1) -> None:
    """work(lo, hi) on contiguous slices of range(B) over at most B threads, SLICES_PER_THREAD
    slices a thread taken in turn (the C calls inside release the GIL through ctypes). With
    a progress ``bar`` (hpgen.runtime.progress) the slices are about 20 per thread, the bar
    advancing by each slice's members as it completes (runs are independent: the states do
    not change). Inner slice bounds are multiples of ``align`` (lane groups stay whole).
    The threads are the process's pool's (hpgen.runtime.workers)."""
    threads = max(1, min(int(threads), B))
    per = 20 if bar is not None else SLICES_PER_THREAD if threads > 1 else 1
    parts = min(B, per * threads)
    bounds = [min(B, (B * i // parts + align // 2) // align * align) for i in range(parts)] + [B]
    slices = [(lo, hi) for lo, hi in zip(bounds, bounds[1:]) if hi > lo]

    def run(s):
        work(*s)
        if bar is not None:
            bar.update(s[1] - s[0])

    run_slices(slices, threads, run)


def _rows(a, B: int, size: int, what: str) -> np.ndarray:
    """``a`` (B sequences or arrays of ``size`` values) as one C-contiguous (B, size) float64
    array; ValueError naming ``what`` for another shape."""
    arr = np.ascontiguousarray(a, dtype=np.float64)
    if B == 0:
        return np.zeros((0, size))
    if arr.shape != (B, size):
        raise ValueError(f"{what}: expected {B} flat arrays of {size} values, got shape "
                         f"{arr.shape}")
    return arr


class BatchRuns:
    """B C runs in one buffer (``base`` its address, run b at base + b * run_size), to be
    started from (B, size) start arrays by ``init`` (hpgen_run_init_batch: one C call per
    slice of runs, the runs' own hpgen_run_init and hpgen_run_set_compose; a shared g0 is
    one row read by every run). ``starts``: (g0s, p0s) as given to record 0 (g0s a row when
    shared). An open module's runs are started at once, with their inputs (kept alive in
    ``keep``)."""

    def __init__(self, cb, g0s, p0s, z0s, inputs=None):
        nn, d, B = cb.n * cb.n, cb.d, len(g0s)
        self.cb, self.B, self.size = cb, B, cb.run_size
        shared = (isinstance(g0s, np.ndarray) and g0s.ndim == 2 and B > 0
                  and g0s.strides[0] == 0)
        G = np.ascontiguousarray(g0s[0], dtype=np.float64) if shared else _rows(
            g0s, B, nn, "g0")
        if shared and G.shape != (nn,):
            raise ValueError(f"g0: expected flat arrays of {nn} values, got shape {G.shape}")
        self.g_stride = 0 if shared else nn
        self.G, self.P, self.Z = G, _rows(p0s, B, d, "p0"), _rows(z0s, B, cb.nz, "z0")
        self.starts = (G, self.P)
        self.gammas = np.array(cb.compose, dtype=np.float64)
        # no zero fill: hpgen_run_init clears each run (pages first touched by its thread)
        self.buffer = np.empty(self.size * B, dtype=np.uint8)
        self.base = self.buffer.ctypes.data
        self.keep: list = []
        self.started = False
        if cb.open:
            self.init(0, B)
            self.keep = [cb.set_inputs(self.base + b * self.size, inputs[b]) for b in range(B)]
            self.started = True

    def init(self, lo: int, hi: int) -> None:
        """Start runs lo..hi-1 (releases the GIL); ValueError for a composed step of more
        substeps than the library takes."""
        if self.started:
            return                                    # an open module's, with their inputs
        cs = len(self.gammas)
        fn = _init_batch(self.cb.lib)
        if fn(self.base + lo * self.size, hi - lo, self.G.ctypes.data + 8 * self.g_stride * lo,
              self.g_stride, self.P[lo:].ctypes.data, self.Z[lo:].ctypes.data, cs,
              self.gammas.ctypes.data) != 0:
            raise ValueError(f"a composed step of {cs} substeps: this library takes at "
                             "most HPGEN_CS_MAX")


def _init_batch(lib):
    """lib's hpgen_run_init_batch, its argument types set (once per library)."""
    fn = lib.hpgen_run_init_batch
    if fn.argtypes is None:
        P, LL = ctypes.c_void_p, ctypes.c_longlong
        fn.argtypes, fn.restype = [P, LL, P, LL, P, P, LL, P], ctypes.c_int
    return fn


def batch_runs(cb, g0s, p0s, z0s, inputs=None) -> BatchRuns:
    """B C runs, run b started at (g0s[b], p0s[b]), z0s[b] (flat, g column-major), with
    inputs[b] (StepInputs) for an open module: a BatchRuns, every run started."""
    runs = BatchRuns(cb, g0s, p0s, z0s, inputs)
    runs.init(0, runs.B)
    runs.started = True
    return runs


#: numpy's dtype of _Status (its fields, offsets and size): an ensemble's statuses are
#: written by C straight into one structured array
_STATUS_DTYPE = np.ctypeslib.as_array((_Status * 1)()).dtype


def status(a: np.ndarray, b: int) -> dict:
    """Member b's status dict (Python numbers, as _Status.as_dict) of simulate_batch's
    status array."""
    row = a[b]
    return {name: row[name].item() for name, _ in abi.STATUS_FIELDS}


def simulate_batch(cb, g0s, p0s, h, z0s, steps, every, opts, threads, inputs=None,
                   bar=None, lanes=True):
    """B independent runs; each thread advances a contiguous slice of them with one C
    call (ctypes releases the GIL). Returns (done (B,), g_rec (B, K, nn), p_rec (B, K, d),
    statuses (B,) structured array, fields abi.STATUS_FIELDS: ``status(sts, b)`` is run b's
    dict); K = steps // every + 1 including step 0; rows after a failure are 0.
    With ``lanes`` and a module that has lane code (``cb.lanes`` > 0), the C call is
    hpgen_advance_batch_lanes (L bodies a call, the plain or the composed step, bitwise the
    same results), else hpgen_advance_batch."""
    nn, d, B = cb.n * cb.n, cb.d, len(g0s)
    K = steps // every + 1
    runs = BatchRuns(cb, g0s, p0s, z0s, inputs)
    base = runs.base
    g_rec, p_rec = np.zeros((B, K, nn)), np.zeros((B, K, d))
    g_rec[:, 0], p_rec[:, 0] = runs.starts
    sts, o = np.zeros(B, dtype=_STATUS_DTYPE), _Options.of(opts)
    st_size = sts.itemsize

    use_lanes = bool(lanes and cb.lanes)
    advance = (cb.lib.hpgen_advance_batch_lanes if use_lanes
               else cb.lib.hpgen_advance_batch)

    def work(lo, hi):
        runs.init(lo, hi)
        advance(base + lo * cb.run_size, hi - lo, float(h), steps, every,
                ctypes.byref(o), K, g_rec[lo:, 1:].ctypes.data, p_rec[lo:, 1:].ctypes.data,
                sts.ctypes.data + lo * st_size)

    _over_threads(B, threads, work, bar, cb.lanes if use_lanes else 1)
    return sts["step"].copy(), g_rec, p_rec, sts


def record_batch(cb, g0s, p0s, h, z0s, steps, every, opts, threads, bar=None,
                 inputs=None):
    """B independent runs keeping record rows (hpgen_advance_record_batch), each thread
    a contiguous slice in one C call. Returns (rows (B, K, W) with row 0 the start,
    rows written per run (B,) including row 0, statuses); codes of row 0 that failed
    are reported in the status with step 0 (the run is not stepped). inputs: per-run
    StepInputs of an open module."""
    B, W = len(g0s), cb.record_width
    K = steps // every + 1
    runs = batch_runs(cb, g0s, p0s, z0s, inputs)       # (alive until the steps are done)
    base = runs.base
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
