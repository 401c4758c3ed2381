"""What codegen expects from a DiscreteStep (see hpgen.derive.step) and checks before emitting.

Every kernel takes and returns flat float64 vectors (matrices column-major, h a 1-vector).
The positional contract (kernel names, order, sizes) is hpgen.abi.KERNELS; names come from
``Kernel.inputs/outputs``.
"""
from __future__ import annotations

import keyword
import re

from .. import abi
from ..abi import KERNEL_NAMES, signature, sizes
from ..errors import HpgenError

#: identifiers: module names, C symbols, Python argument names
MODULE_RE = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,127}\Z")
ARG_RE = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}\Z")
HASH_RE = re.compile(r"[0-9a-f]{16,128}\Z")
#: argument names the generated Python would shadow (work variables, outputs, imports)
_RESERVED_ARG = re.compile(r"([wr][0-9]+|math|numpy)\Z")

class CodegenError(HpgenError, ValueError):
    """The DiscreteStep or the emit() info violates the codegen contract (an internal error
    between stages, or an expression hpgen's code generators cannot print)."""


def check_arg_name(name: str, where: str) -> str:
    if (not isinstance(name, str) or not ARG_RE.match(name) or keyword.iskeyword(name)
            or _RESERVED_ARG.match(name)):
        raise CodegenError(f"{where}: argument name {name!r} is not usable in generated code "
                           "(need a letter then letters/digits/_, not a keyword, w<k>, r<k>, "
                           "math or numpy)")
    return name


def check_step(step) -> None:
    """Validate dimensions, the presence of every kernel and each kernel's in/out sizes."""
    for attr in ("n", "d", "nz"):
        v = getattr(step, attr)
        if not isinstance(v, int) or isinstance(v, bool) or v < 1:
            raise CodegenError(f"DiscreteStep.{attr} must be a positive int, got {v!r}")
    spec = getattr(step, "open_spec", None)
    size = sizes(step.n, step.d, step.nz, step.record_width, 1 if spec is None else spec.H)
    check_record_layout(step)
    names = [k.name for k in step.kernels]
    if tuple(names) != KERNEL_NAMES:
        raise CodegenError(f"DiscreteStep.kernels must be {KERNEL_NAMES} in this order, "
                           f"got {tuple(names)}")
    seen_fn = set()
    for k in step.kernels:
        f = k.function
        if not hasattr(f, "is_a") or not (f.is_a("SXFunction") or f.is_a("MXFunction")):
            raise CodegenError(f"kernel {k.name}: expected a casadi.Function over SX or MX")
        if f.has_free():
            raise CodegenError(f"kernel {k.name}: the function has free variables")
        fname = f.name()
        if fname in seen_fn or fname.startswith(("hpgen", "casadi")):
            raise CodegenError(f"kernel {k.name}: casadi function name {fname!r} is reused "
                               "or reserved")
        seen_fn.add(fname)
        ins, outs = signature(k.name, spec is not None)
        if len(k.inputs) != f.n_in() or len(k.outputs) != f.n_out():
            raise CodegenError(f"kernel {k.name}: Kernel.inputs/outputs do not match the "
                               f"function ({f.n_in()} inputs, {f.n_out()} outputs)")
        if f.n_in() != len(ins) or f.n_out() != len(outs):
            raise CodegenError(f"kernel {k.name}: expected {len(ins)} inputs and {len(outs)} "
                               f"outputs, got {f.n_in()} and {f.n_out()}")
        for i, s in enumerate(ins):
            check_arg_name(k.inputs[i], f"kernel {k.name}")
            if f.numel_in(i) != size[s]:
                raise CodegenError(f"kernel {k.name}: input {i} ({k.inputs[i]}) has "
                                   f"{f.numel_in(i)} elements, expected {size[s]}")
        for i, s in enumerate(outs):
            check_arg_name(k.outputs[i], f"kernel {k.name}")
            if f.numel_out(i) != size[s]:
                raise CodegenError(f"kernel {k.name}: output {i} ({k.outputs[i]}) has "
                                   f"{f.numel_out(i)} elements, expected {size[s]}")
        if len(set(k.inputs) | set(k.outputs)) != len(k.inputs) + len(k.outputs):
            raise CodegenError(f"kernel {k.name}: argument names are not distinct")


def check_record_layout(step) -> None:
    """record_layout: the conventions of hpgen.abi.record_width (names distinct identifiers,
    offsets contiguous from 0, shapes () | (d,) | (n, n), at least one entry)."""
    if not step.record_layout:
        raise CodegenError("DiscreteStep.record_layout is empty (the scene records nothing)")
    try:
        abi.record_width(step.record_layout, step.n, step.d)
    except ValueError as exc:
        raise CodegenError(f"record_layout: {exc}") from None


def dense_positions(sp) -> list[int]:
    """Column-major dense position of each structural nonzero of a casadi.Sparsity."""
    rows, cols, nrow = sp.row(), sp.get_col(), sp.size1()
    return [int(r) + int(c) * nrow for r, c in zip(rows, cols)]
