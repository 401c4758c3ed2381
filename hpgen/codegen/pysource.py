"""Print one CasADi SX function as straight-line Python (the Python backend).

The walk follows the function's SX algorithm instruction by instruction, so the generated
Python performs the same IEEE double operations in the same order as CasADi's C: ``+ - *``
inline, ``/`` inline with a zero-divisor fallback, and math functions through small helpers
(defined in templates/kernels.py.j2) that return the C99 result (inf/nan) where Python's
``math`` would raise. Work variables are locals ``w<k>`` (CasADi reuses work slots, so a
``w<k>`` may be reassigned); outputs are lists ``r<i>`` in dense column-major layout.
"""
from __future__ import annotations

import math

import casadi

from .contract import CodegenError, dense_positions

# op code -> format over work-variable names x, y (z = result, used for division)
_UNARY = {
    "OP_ASSIGN": "{x}", "OP_NEG": "-{x}", "OP_SQ": "{x} * {x}", "OP_TWICE": "2.0 * {x}",
    "OP_FABS": "math.fabs({x})", "OP_SIGN": "_sign({x})", "OP_EXP": "_exp({x})",
    "OP_LOG": "_log({x})", "OP_SQRT": "_sqrt({x})", "OP_SIN": "_sin({x})",
    "OP_COS": "_cos({x})", "OP_TAN": "_tan({x})", "OP_ASIN": "_asin({x})",
    "OP_ACOS": "_acos({x})", "OP_ATAN": "math.atan({x})", "OP_SINH": "_sinh({x})",
    "OP_COSH": "_cosh({x})", "OP_TANH": "math.tanh({x})", "OP_ASINH": "math.asinh({x})",
    "OP_ACOSH": "_acosh({x})", "OP_ATANH": "_atanh({x})", "OP_ERF": "math.erf({x})",
    "OP_LOG1P": "_log1p({x})", "OP_EXPM1": "_expm1({x})", "OP_FLOOR": "_floor({x})",
    "OP_CEIL": "_ceil({x})", "OP_NOT": "0.0 if {x} else 1.0",
    "OP_INV": "1.0 / {x} if {x} else _div(1.0, {x})",
}
_BINARY = {
    "OP_ADD": "{x} + {y}", "OP_SUB": "{x} - {y}", "OP_MUL": "{x} * {y}",
    "OP_DIV": "{x} / {y} if {y} else _div({x}, {y})",
    "OP_POW": "_pow({x}, {y})", "OP_CONSTPOW": "_pow({x}, {y})",
    "OP_LT": "1.0 if {x} < {y} else 0.0", "OP_LE": "1.0 if {x} <= {y} else 0.0",
    "OP_EQ": "1.0 if {x} == {y} else 0.0", "OP_NE": "1.0 if {x} != {y} else 0.0",
    "OP_AND": "1.0 if {x} and {y} else 0.0", "OP_OR": "1.0 if {x} or {y} else 0.0",
    "OP_IF_ELSE_ZERO": "{y} if {x} else 0.0",
    "OP_FMIN": "_fmin({x}, {y})", "OP_FMAX": "_fmax({x}, {y})",
    "OP_FMOD": "_fmod({x}, {y})", "OP_REMAINDER": "_remainder({x}, {y})",
    "OP_COPYSIGN": "math.copysign({x}, {y})", "OP_ATAN2": "math.atan2({x}, {y})",
    "OP_HYPOT": "math.hypot({x}, {y})", "OP_PRINTME": "_printme({x}, {y})",
}


def _table(spec: dict) -> dict[int, str]:
    return {getattr(casadi, k): v for k, v in spec.items() if hasattr(casadi, k)}


UNARY, BINARY = _table(_UNARY), _table(_BINARY)
_OP_NAMES = {getattr(casadi, k): k for k in dir(casadi) if k.startswith("OP_")}


def float_literal(v: float) -> str:
    """Exact Python literal of a double (repr round-trips; inf/nan via math)."""
    v = float(v)
    if math.isnan(v):
        return "math.nan"
    if math.isinf(v):
        return "math.inf" if v > 0 else "-math.inf"
    return repr(v)


def kernel_lines(kernel) -> list[str]:
    """Body statements (unindented) of the Python function for one kernel, after the input
    conversion and output initialisation that the template prints."""
    f = kernel.function
    ins = [dense_positions(f.sparsity_in(i)) for i in range(f.n_in())]
    outs = [dense_positions(f.sparsity_out(i)) for i in range(f.n_out())]
    lines = []
    for k in range(f.n_instructions()):
        op = f.instruction_id(k)
        i_in, i_out = f.instruction_input(k), f.instruction_output(k)
        if op == casadi.OP_INPUT:
            arg, nz = i_in[0], i_in[1]
            lines.append(f"w{i_out[0]} = {kernel.inputs[arg]}[{ins[arg][nz]}]")
        elif op == casadi.OP_OUTPUT:
            res, nz = i_out[0], i_out[1]
            lines.append(f"r{res}[{outs[res][nz]}] = w{i_in[0]}")
        elif op == casadi.OP_CONST:
            lines.append(f"w{i_out[0]} = {float_literal(f.instruction_constant(k))}")
        elif op in UNARY:
            lines.append(f"w{i_out[0]} = " + UNARY[op].format(x=f"w{i_in[0]}"))
        elif op in BINARY:
            lines.append(f"w{i_out[0]} = "
                         + BINARY[op].format(x=f"w{i_in[0]}", y=f"w{i_in[1]}"))
        else:
            name = _OP_NAMES.get(op, "?")
            raise CodegenError(f"kernel {kernel.name}: instruction {k} has CasADi op code "
                               f"{op} ({name}) which the Python code generator cannot print")
    return lines


def py_kernel_context(kernel) -> dict:
    """What kernels.py.j2 needs for one kernel."""
    f = kernel.function
    return {"name": kernel.name,
            "inputs": [{"name": kernel.inputs[i], "numel": f.numel_in(i)}
                       for i in range(f.n_in())],
            "outputs": [{"name": kernel.outputs[i], "numel": f.numel_out(i)}
                        for i in range(f.n_out())],
            "lines": kernel_lines(kernel)}
