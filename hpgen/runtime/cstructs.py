"""ctypes mirrors of the C runtime's structs (``hpgen_status``, ``hpgen_options`` of
hpgen/runtime/c/hpgen_runtime.h: their fields from hpgen.abi) and fixed-address argument
buffers for calls into kernels.c, shared by the C backend's run loops (cbackend.py, cbatch.py)
and simulate's fast path (prologue.py). Standard library and numpy only.
"""
from __future__ import annotations

import ctypes

import numpy as np

from .. import abi
from . import newton


def _addr(a: np.ndarray) -> int:
    """Address of the data of a writable C-contiguous float64 array (through the buffer
    protocol when it is not empty: a quarter of the cost of ``a.ctypes.data``)."""
    return (ctypes.addressof(ctypes.c_char.from_buffer(a))  # type: ignore[arg-type]
            if a.size else a.ctypes.data)


def _views(sizes):
    """(block, views, addresses): consecutive flat views of the given sizes in one block."""
    block = np.zeros(max(1, sum(sizes)))
    base, views, ptrs, off = _addr(block), [], [], 0
    for s in sizes:
        views.append(block[off:off + s])
        ptrs.append(base + 8 * off)
        off += s
    return block, views, ptrs


class _Staging:
    """One thread's argument buffers for a C function of flat double arrays: ``ins`` and
    ``outs`` views of one block each (``out_all`` the outputs' block), ``ptrs`` their
    addresses in argument order (inputs, then outputs), made once. Callers copy arguments
    in and results out: no array handed out is a view of these buffers."""
    __slots__ = ("ins", "outs", "out_all", "ptrs")

    def __init__(self, ins, outs):
        _, self.ins, pin = _views(ins)
        self.out_all, self.outs, pout = _views(outs)
        self.ptrs = tuple(pin + pout)


_CTYPES: dict[str, type[ctypes._SimpleCData]] = {"q": ctypes.c_longlong, "d": ctypes.c_double}


class _Status(ctypes.Structure):
    """The C ``hpgen_status`` (abi.STATUS_FIELDS)."""
    _fields_ = [(name, _CTYPES[kind]) for name, kind in abi.STATUS_FIELDS]

    def as_dict(self) -> dict:
        return {f[0]: getattr(self, f[0]) for f in self._fields_}


class _Options(ctypes.Structure):
    """The C ``hpgen_options`` (abi.OPTIONS_FIELDS)."""
    _fields_ = [(name, _CTYPES[kind]) for name, kind in abi.OPTIONS_FIELDS]

    @classmethod
    def of(cls, o: newton.NewtonOptions) -> "_Options":
        return cls(float(o.tol), int(o.maxit), int(bool(o.simplified)), int(bool(o.predictor)))
