"""The sympy symbols of a model's time, runtime parameters and control inputs (compile-time
stack only: hpgen.model.types, the IR, stays free of sympy so that reading a model file's
bytes or fingerprinting it imports none of it)."""
from __future__ import annotations

from typing import Any

import sympy as sp

#: the time t of the Lagrangian and the forces (at stage i of step k: t_k + c_i h)
TIME_SYMBOL = sp.Symbol("t", real=True)


def runtime_symbol(name: str, index=()) -> Any:
    """The symbol of entry ``index`` (() for a scalar) of the runtime parameter ``name``.
    Its name holds a ':' so it can clash with no variable or parameter symbol."""
    return sp.Symbol("param:" + name + "".join(f"[{i}]" for i in index), real=True)


def input_symbol(name: str) -> Any:
    """The symbol of the control input ``name`` (held constant over each step)."""
    return sp.Symbol("input:" + name, real=True)
