"""Argument checks and status-to-exception mapping shared by the Integrator API (one-line
ArgumentError naming the argument; ConvergenceError / DomainError for a failed step)."""
from __future__ import annotations

import math
import numbers
import os

import numpy as np

from .. import abi
from ..errors import ArgumentError, ConvergenceError, DomainError
from .newton import NewtonOptions

#: the largest steps / every the C loops take (long long)
STEPS_MAX = 2**63 - 1

_START = "the Newton start lies outside the chart map tau's domain (margin(z, h) <= 0)"


def _error(code, step, time, residual, iterations, hint=""):
    """The exception of a failed step's status code (abi.STATUS): DomainError for DOMAIN,
    else ConvergenceError, with the code's message; DOMAIN after 0 iterations is the first
    step's start (``hint``: what the chart needs, FirstStep.domain_hint)."""
    cls = DomainError if code == abi.DOMAIN else ConvergenceError
    msg = abi.MESSAGES.get(code, f"step failed with status {code}")
    if code == abi.DOMAIN and int(iterations) == 0:
        msg = _START + (f"; {hint}" if hint else "")
    return cls(msg, step=int(step), time=float(time), residual=float(residual),
               iterations=int(iterations))


def _non_numeric(x, a):
    """What makes ``x`` (as the array ``a``) non-numeric ("strings", "booleans", ...), or
    None: real numbers only (int, float, numpy numbers), never strings, booleans, None or
    other objects (a list's booleans included, which numpy would turn into integers)."""
    kind = a.dtype.kind
    if kind in "iu" and not isinstance(x, np.ndarray) and a.size:
        if a.ndim == 1 and isinstance(x, (list, tuple)):     # a list may hide True among ints
            return "booleans" if any(isinstance(v, (bool, np.bool_)) for v in x) else None
        a = np.asarray(x, dtype=object)
        kind = "O"
    if kind in "fiu":
        return None
    if kind == "O":
        for v in a.flat:
            if isinstance(v, (bool, np.bool_)):
                return "booleans"
            if not isinstance(v, numbers.Real):
                return "None" if v is None else f"{type(v).__name__} entries"
        return None
    return {"b": "booleans", "U": "strings", "S": "bytes", "c": "complex entries"}.get(
        kind, f"{a.dtype} entries")


def _array(x, shape, field, what, finite=True):
    """``x`` as a float64 array of ``shape`` (a scalar for shape (1,)); ArgumentError naming
    ``field`` otherwise. ``finite=False`` leaves the non-finite check to the caller."""
    try:
        a = np.asarray(x)
        bad = _non_numeric(x, a)
        if bad is not None:
            raise ArgumentError(f"expected {what} of real numbers, got {bad}", field=field)
        a = np.array(a, dtype=np.float64)
    except (TypeError, ValueError) as e:
        if isinstance(e, ArgumentError):
            raise
        raise ArgumentError(f"expected {what}, got {type(x).__name__}", field=field) from None
    if a.shape != shape:
        if shape == (1,) and a.shape == ():         # a scalar for a 1-dimensional algebra
            return a.reshape(1)
        raise ArgumentError(f"expected {what} of shape {shape}, got shape {a.shape}",
                            field=field)
    if finite and not np.isfinite(a).all():
        raise ArgumentError(f"{what} has non-finite entries", field=field)
    return a


def _int(x, field, low, high=STEPS_MAX):
    if type(x) is int and low <= x <= high:        # the common case, without the ABC checks
        return x
    if isinstance(x, bool) or not isinstance(x, numbers.Integral) or x < low:
        raise ArgumentError(f"expected an integer >= {low}, got {x!r}", field=field)
    if x > high:
        raise ArgumentError(f"{x} is more than a run can count (at most {high}); run long "
                            "runs in pieces with stream / stream_record", field=field)
    return int(x)


def _positive(x, field):
    if type(x) is float and 0.0 < x < math.inf:     # the common case
        return x
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or not (
            math.isfinite(x) and x > 0):
        raise ArgumentError(f"expected a finite number > 0, got {x!r}", field=field)
    return float(x)


def _step_size(x, field="h"):
    """h: a finite non-zero number (h < 0 integrates backwards in time)."""
    if type(x) is float and 0.0 < abs(x) < math.inf:     # the common case
        return x
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or not (
            math.isfinite(x) and x != 0):
        raise ArgumentError(f"expected a finite non-zero number (h < 0 runs backwards in "
                            f"time), got {x!r}", field=field)
    return float(x)


def newton_options(newton, simplified_default: bool, full: bool = False) -> NewtonOptions:
    """The checked Newton settings of a call, simplified resolved to a bool (None: full
    Newton when ``full``, else ``simplified_default``). ArgumentError naming the field."""
    if newton is None:
        newton = NewtonOptions()
    elif not isinstance(newton, NewtonOptions):
        raise ArgumentError("expected hpgen.runtime.NewtonOptions(tol=, maxit=, "
                            f"simplified=, predictor=) or None, got "
                            f"{type(newton).__name__}", field="newton")
    simplified = newton.simplified
    if simplified is None:
        simplified = False if full else simplified_default
    return NewtonOptions(_positive(newton.tol, "newton.tol"),
                         _int(newton.maxit, "newton.maxit", 1), bool(simplified),
                         bool(newton.predictor))


def _memory_bytes():
    """This machine's physical memory in bytes, None where the OS does not say."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (AttributeError, ValueError, OSError):
        return None


def _fits(records, doubles, what):
    """Refuse a run whose ``records`` rows of ``doubles`` float64 each would not fit in this
    machine's memory (before allocating them)."""
    need = records * doubles * 8
    have = _memory_bytes()
    if have is not None and need > have:
        raise ArgumentError(f"{what} would keep {records} records ({need:.3g} bytes), more "
                            f"than this machine's memory ({have:.3g} bytes); record fewer "
                            "(every=...) or run long runs with stream / stream_record "
                            "(hpgen run --chunk)", field="steps")
