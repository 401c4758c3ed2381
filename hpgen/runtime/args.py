"""Argument checks and status-to-exception mapping shared by the Integrator API (one-line
ModelError naming the argument; ConvergenceError / DomainError for a failed step)."""
from __future__ import annotations

import math
import numbers

import numpy as np

from .. import abi
from ..errors import ConvergenceError, DomainError, ModelError


def _error(code, step, time, residual, iterations):
    """The exception of a failed step's status code (abi.STATUS): DomainError for DOMAIN,
    else ConvergenceError, with the code's message."""
    cls = DomainError if code == abi.DOMAIN else ConvergenceError
    return cls(abi.MESSAGES.get(code, f"step failed with status {code}"), step=int(step),
               time=float(time), residual=float(residual), iterations=int(iterations))


def _array(x, shape, field, what):
    try:
        a = np.array(x, dtype=np.float64)
    except (TypeError, ValueError):
        raise ModelError(f"expected {what}, got {type(x).__name__}", field=field) from None
    if a.shape != shape:
        raise ModelError(f"expected {what} of shape {shape}, got shape {a.shape}", field=field)
    if not np.isfinite(a).all():
        raise ModelError(f"{what} has non-finite entries", field=field)
    return a


def _int(x, field, low):
    if type(x) is int and x >= low:        # the common case, without the ABC checks
        return x
    if isinstance(x, bool) or not isinstance(x, numbers.Integral) or x < low:
        raise ModelError(f"expected an integer >= {low}, got {x!r}", field=field)
    return int(x)


def _positive(x, field):
    if type(x) is float and 0.0 < x < math.inf:     # the common case
        return x
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or not (
            math.isfinite(x) and x > 0):
        raise ModelError(f"expected a finite number > 0, got {x!r}", field=field)
    return float(x)
