"""Build and load heavy_top_sv.c (the hand-written Lie Stormer-Verlet heavy top) with ctypes.

    lib = build(out_dir, extra_flags=())          # path of the shared library
    hand = HandSV(lib)
    R, p, iters = hand.simulate(R0, p0, h, steps, every=1)   # (K, 3, 3), (K, 3), total Newton its
    R1, p1, X, it = hand.step(R, p, h)

Used by benchmarks/sv_vs_hand.py and tests/regression/test_hand_c.py. Standard library and
numpy only.
"""
from __future__ import annotations

import ctypes
import hashlib
import os
import subprocess
from pathlib import Path

import numpy as np

SOURCE = Path(__file__).resolve().parent / "heavy_top_sv.c"
CODES = {0: "ok", 1: "no convergence", 2: "non-finite", 3: "outside the Cayley chart"}


def build(out_dir, cflags, cc=None) -> Path:
    """Compile SOURCE into out_dir with ``cc cflags -o lib SOURCE -lm``; returns the library.
    The name carries a hash of the flags and the source (differently built libraries never
    mix). Raises subprocess.CalledProcessError (with stderr) when the compiler fails."""
    cc = cc or os.environ.get("CC", "cc")
    flags = list(cflags)
    tag = hashlib.sha256("\0".join([cc] + flags).encode() + SOURCE.read_bytes()).hexdigest()[:12]
    lib = Path(out_dir) / f"hand_sv_{tag}.so"
    if not lib.exists():
        tmp = lib.with_suffix(f".tmp{os.getpid()}.so")
        subprocess.run([cc, *flags, "-o", str(tmp), str(SOURCE), "-lm"], check=True,
                       capture_output=True, text=True)
        os.replace(tmp, lib)
    return lib


class HandSV:
    def __init__(self, library):
        lib = ctypes.CDLL(str(library))
        P, LL, D = ctypes.c_void_p, ctypes.c_longlong, ctypes.c_double
        lib.hand_sv_abi.restype = ctypes.c_int
        lib.hand_sv_abi.argtypes = []
        if lib.hand_sv_abi() != 1:
            raise RuntimeError(f"{library}: unexpected ABI version {lib.hand_sv_abi()}")
        lib.hand_sv_step.restype = ctypes.c_int
        lib.hand_sv_step.argtypes = [P, P, D, P, P, P, P, P]
        lib.hand_sv_simulate.restype = LL
        lib.hand_sv_simulate.argtypes = [P, P, D, LL, LL, P, P, P, P]
        self._lib = lib

    @staticmethod
    def _flat(R, p):
        return (np.ascontiguousarray(np.asarray(R, dtype=float).reshape(3, 3).ravel(order="F")),
                np.ascontiguousarray(p, dtype=float).reshape(3))

    def simulate(self, R0, p0, h, steps, every=1):
        """(R (K, 3, 3), p (K, 3), total Newton iterations), K = steps // every + 1.
        Raises RuntimeError if a step fails."""
        R0, p0 = self._flat(R0, p0)
        K = steps // every + 1
        R_rec, p_rec = np.zeros((K, 9)), np.zeros((K, 3))
        total, code = ctypes.c_longlong(0), ctypes.c_int(0)
        done = self._lib.hand_sv_simulate(R0.ctypes.data, p0.ctypes.data, float(h), steps,
                                          every, R_rec.ctypes.data, p_rec.ctypes.data,
                                          ctypes.byref(total), ctypes.byref(code))
        if done != steps:
            raise RuntimeError(f"hand_sv_simulate stopped at step {done}: "
                               f"{CODES.get(code.value, code.value)}")
        return R_rec.reshape(K, 3, 3).transpose(0, 2, 1), p_rec, total.value

    def step(self, R, p, h, x0=None):
        """One step: (R1 (3, 3), p1 (3,), X = xi_{k+1} (3,), Newton iterations); x0: Newton
        start (default: the velocity I^{-1} p)."""
        R, p = self._flat(R, p)
        x0 = None if x0 is None else np.ascontiguousarray(x0, dtype=float).reshape(3)
        R1, p1, x1, it = np.zeros(9), np.zeros(3), np.zeros(3), ctypes.c_longlong(0)
        code = self._lib.hand_sv_step(R.ctypes.data, p.ctypes.data, float(h),
                                      None if x0 is None else x0.ctypes.data, x1.ctypes.data,
                                      R1.ctypes.data, p1.ctypes.data, ctypes.byref(it))
        if code != 0:
            raise RuntimeError(f"hand_sv_step: {CODES.get(code, code)}")
        return R1.reshape(3, 3, order="F"), p1, x1, it.value
