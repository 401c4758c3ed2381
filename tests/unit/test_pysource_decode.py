"""The Python printer decodes each function's SX algorithm once per kernel (every SWIG call
costs ~1 us; the rod's step_partials at N = 64 has 7e5 instructions)."""
from __future__ import annotations

import casadi as ca

from hpgen.codegen.pycallees import callee_functions
from hpgen.codegen.pysource import _callees, instructions, kernel_lines
from hpgen.derive.step import Kernel


class _Counting:
    """A casadi.Function that counts its instruction_id calls."""

    def __init__(self, f):
        self._f, self.reads = f, 0

    def instruction_id(self, k):
        self.reads += 1
        return self._f.instruction_id(k)

    def __getattr__(self, name):
        return getattr(self._f, name)


def _calling_function():
    """An SX function with OP_CALL instructions (a never_inline callee) and a division (so
    kernel_lines prints both the fast and the safe body)."""
    y = ca.MX.sym("y", 2)
    inner = ca.Function("inner", [y], [ca.sin(y) * y[0]], {"never_inline": True})
    x = ca.MX.sym("x", 2)
    outer = ca.Function("outer", [x], [inner(x) / x[1] + inner(2 * x)], ["x"], ["r"])
    return outer.expand()


def test_kernel_lines_reads_each_instruction_once():
    f = _calling_function()
    ops = [op for op, _, _ in instructions(f)]
    assert ca.OP_CALL in ops and ca.OP_DIV in ops
    counted = _Counting(f)
    lines = kernel_lines(Kernel("residual", counted, ("x",), ("r",)))
    assert counted.reads == f.n_instructions()
    assert lines == kernel_lines(Kernel("residual", f, ("x",), ("r",)))
    assert "except (ArithmeticError, ValueError):" in lines


def test_callees_are_the_same_from_decoded_instructions():
    f = _calling_function()
    direct = {k: fn.name() for k, fn in _callees(f).items()}
    g = _calling_function()                  # another object: not served from the cache
    decoded = {k: fn.name() for k, fn in _callees(g, instructions(g)).items()}
    assert direct == decoded and set(direct.values()) == {"inner"}
    assert [name for name, _ in callee_functions([Kernel("residual", f, ("x",), ("r",))])] \
        == ["_call_inner"]
