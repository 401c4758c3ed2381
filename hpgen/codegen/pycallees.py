"""The functions that kernels call (CasADi OP_CALL: a family model's per-body and per-joint
functions and their derivatives), printed once each as module-level Python functions, and
the SX form of kernels composed over MX.

A callee ``f`` is printed as ``_call_<name>(*a)``: ``a`` the nonzeros of its inputs in
order, the result the nonzeros of its outputs in order, which is what an OP_CALL instruction
passes and receives (hpgen.codegen.pysource prints the call); its body is printed like a
kernel's (fast body, safe fallback with C semantics), so a call never raises.
"""
from __future__ import annotations

from .pysource import _callees, callee_name, kernel_lines


class _Callee:
    """A called function printed like a kernel whose arguments are their nonzeros."""

    def __init__(self, fn, name: str):
        self.function, self.name = fn, name
        self.inputs = tuple(f"x{i}" for i in range(fn.n_in()))
        self.outputs = tuple(f"y{i}" for i in range(fn.n_out()))


class _Expanded:
    """A kernel over MX seen as its SX expansion (calls of never_inline functions stay
    calls): the form the printer walks."""

    def __init__(self, kernel):
        self.name, self.inputs, self.outputs = kernel.name, kernel.inputs, kernel.outputs
        self.function = kernel.function.expand()


_EXPANDED: dict = {}


def as_sx(kernel):
    """``kernel`` itself when its function is over SX, else its SX expansion (cached per
    kernel object)."""
    f = kernel.function
    if not f.is_a("MXFunction"):
        return kernel
    key = id(kernel)
    hit = _EXPANDED.get(key)
    if hit is None or hit[0] is not kernel:
        _EXPANDED.clear() if len(_EXPANDED) > 64 else None
        hit = _EXPANDED[key] = (kernel, _Expanded(kernel))
    return hit[1]


def callee_functions(kernels) -> list:
    """The functions that ``kernels`` call (OP_CALL), directly or through other callees, in
    order of first use (CasADi names the functions of one derivation uniquely), as
    (Python name, SX function) pairs."""
    seen: dict = {}
    stack = [as_sx(k).function for k in reversed(list(kernels))]
    order = []
    while stack:
        f = stack.pop()
        for fn in _callees(f).values():
            name = fn.name()
            if name in seen:
                continue
            # a callee over MX (a wrapper) is printed from its SX expansion, whose calls of
            # never_inline functions stay calls
            sx = fn.expand() if fn.is_a("MXFunction") else fn
            seen[name] = sx
            order.append((callee_name(fn), sx))
            stack.append(sx)
    return order


def callee_lines(kernels) -> list[str]:
    """Module-level Python functions ``_call_<name>(*a)``, one per called function: ``a`` the
    nonzeros of its inputs in order, the result the nonzeros of its outputs in order (what an
    OP_CALL instruction passes and receives); the same statements as a kernel body."""
    lines: list[str] = []
    for pyname, fn in callee_functions(kernels):
        c = _Callee(fn, pyname)
        lines += ["", "", f"def {c.name}(*a):",
                  f'    """{fn.name()}: the nonzeros of ({", ".join(fn.name_in())}) -> the '
                  f'nonzeros of ({", ".join(fn.name_out())})"""']
        off = 0
        for i in range(fn.n_in()):
            lines.append(f"    x{i} = a[{off}:{off + fn.nnz_in(i)}]")
            off += fn.nnz_in(i)
        lines += ["    " + t for t in kernel_lines(c, nonzeros=True)]
        outs = ", ".join(f"*r{i}" for i in range(fn.n_out()))
        lines.append(f"    return ({outs}{',' if fn.n_out() == 1 else ''})")
    return lines
