"""Ensembles on the C backend: B independent runs stepped by one C call per thread slice
(``hpgen_advance_batch``, its 8-lane variant ``hpgen_advance_batch_lanes`` when the module
has lane code, ``hpgen_advance_record_batch``); ctypes releases the GIL during each call.
The functions take the CBackend (its ``lib``, sizes, ``run_size``, ``lanes``, ``init_run``,
``set_inputs`` and ``record``); CBackend.simulate_batch / record_batch call them. Standard
library and numpy only.
"""
from __future__ import annotations

import ctypes
import weakref

import numpy as np

from .. import abi
from . import loop
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


_RUN_INIT: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _run_init(cb):
    """hpgen_run_init of cb's library through a PyDLL handle (made once per library): a
    call of well under a microsecond that keeps the GIL, where a CDLL call releases and
    takes it back (hpgen.runtime.prologue calls it the same way)."""
    fn = _RUN_INIT.get(cb.lib)
    if fn is None:
        py = ctypes.PyDLL(str(cb.library), handle=cb.lib._handle)   # (no second dlopen)
        fn = py.hpgen_run_init
        fn.argtypes, fn.restype = [ctypes.c_void_p] * 4, None
        _RUN_INIT[cb.lib] = fn
    return fn


def batch_runs(cb, g0s, p0s, z0s, inputs=None):
    """(buffer, its address): B C runs, run b started at (g0s[b], p0s[b]), z0s[b] (flat,
    g column-major), with inputs[b] (StepInputs) for an open module. The starts are read
    from three (B, size) arrays, one hpgen_run_init per run at fixed offsets (no staging
    copies); a composed step's substep fractions are one array for all runs."""
    nn, d, B, rs = cb.n * cb.n, cb.d, len(g0s), cb.run_size
    G, P, Z = _rows(g0s, B, nn, "g0"), _rows(p0s, B, d, "p0"), _rows(z0s, B, cb.nz, "z0")
    runs = ctypes.create_string_buffer(rs * B)
    base = ctypes.addressof(runs)
    lib, keep = cb.lib, []
    init, ga, pa, za = _run_init(cb), G.ctypes.data, P.ctypes.data, Z.ctypes.data
    for b in range(B):
        init(base + b * rs, ga + 8 * nn * b, pa + 8 * d * b, za + 8 * cb.nz * b)
    if cb.compose:
        gam = np.array(cb.compose, dtype=np.float64)
        compose, cs, gp = lib.hpgen_run_set_compose, len(gam), gam.ctypes.data
        for b in range(B):
            if compose(base + b * rs, cs, gp) != 0:
                raise ValueError(f"a composed step of {cs} substeps: this library takes at "
                                 "most HPGEN_CS_MAX")
    if cb.open:
        keep = [cb.set_inputs(base + b * rs, inputs[b]) for b in range(B)]
    runs.keep = keep
    runs.starts = (G, P)
    return runs, base


def statuses(sts) -> np.ndarray:
    """The ctypes array of B _Status as a (B,) structured numpy array (a copy), one field
    per abi.STATUS_FIELDS; ``status(a, b)`` is member b's dict."""
    return np.ctypeslib.as_array(sts).copy()


def status(a: np.ndarray, b: int) -> dict:
    """Member b's status dict (Python numbers, as _Status.as_dict) of ``statuses``' array."""
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
    runs, base = batch_runs(cb, g0s, p0s, z0s, inputs)
    g_rec, p_rec = np.zeros((B, K, nn)), np.zeros((B, K, d))
    g_rec[:, 0], p_rec[:, 0] = runs.starts
    sts, o = (_Status * B)(), _Options.of(opts)

    use_lanes = bool(lanes and cb.lanes)
    advance = (cb.lib.hpgen_advance_batch_lanes if use_lanes
               else cb.lib.hpgen_advance_batch)

    def work(lo, hi):
        advance(base + lo * cb.run_size, hi - lo, float(h), steps, every,
                ctypes.byref(o), K, g_rec[lo:, 1:].ctypes.data, p_rec[lo:, 1:].ctypes.data,
                ctypes.byref(sts, lo * ctypes.sizeof(_Status)))

    _over_threads(B, threads, work, bar, cb.lanes if use_lanes else 1)
    out = statuses(sts)
    return out["step"].copy(), g_rec, p_rec, out


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
