"""The C backend's inputs: CasADi's own C code for every kernel, and the per-kernel facts the
``kernels.c.j2`` template needs (work sizes, sparse gather/scatter positions); the Newton
loop and the runs around them are the static C runtime (hpgen/runtime/c).

CasADi-generated functions read/write only the structural nonzeros of each argument; the
hpgen wrappers present dense column-major arrays (gathering/scattering when an argument is
not dense) so that every exported ``hpgen_kernel_<name>`` follows the DiscreteStep contract.
"""
from __future__ import annotations

import casadi

from .contract import CodegenError, dense_positions
from .sparse import aux_function, jacobian_sparsity

#: CasADi CodeGenerator options. with_mem False: no memory objects, no static mutable state.
CG_OPTIONS = {"casadi_real": "double", "casadi_int": "long long int", "with_mem": False,
              "verbose": False, "cpp": False, "with_header": False, "main": False,
              "mex": False}

#: CasADi's fmin/fmax helpers call libm (not inlined without -ffinite-math-only); the same
#: IEEE semantics (a NaN argument yields the other one) as plain comparisons
_INLINE_MINMAX = {"  return fmin(x, y);\n": "  return (x < y || y != y) ? x : y;\n",
                  "  return fmax(x, y);\n": "  return (x > y || y != y) ? x : y;\n"}

#: kernels whose C body is not generated separately but taken from a fused kernel's outputs:
#: name -> (fused kernel, index of the output). jacobian is residual_jacobian's J: one copy of
#: the (largest) Jacobian code in kernels.c halves gcc's time on big steps.
C_FROM_FUSED = {"jacobian": ("residual_jacobian", 1)}

#: op codes whose CasADi C output does not compile as C99 (no erfinv in <math.h>)
_C_UNSUPPORTED = {casadi.OP_ERFINV: "erfinv"}


def casadi_c_code(step, module: str) -> str:
    """CasADi's C for all kernels of ``step`` in one translation unit (a string).

    Internal CasADi symbols get the prefix ``hpgen_<module>_``; the kernels.c template hides
    all of CasADi's symbols (GCC visibility) and exports only ``hpgen_*``.
    """
    for k in step.kernels:
        f = k.function
        for i in range(f.n_instructions()):
            op = f.instruction_id(i)
            if op in _C_UNSUPPORTED:
                raise CodegenError(f"kernel {k.name}: {_C_UNSUPPORTED[op]} is not supported "
                                   "by hpgen's code generators")
    opts = dict(CG_OPTIONS, prefix=f"hpgen_{module}_")
    cg = casadi.CodeGenerator(f"{module}_kernels", opts)
    for k in step.kernels:
        if k.name not in C_FROM_FUSED:
            cg.add(k.function)
    sp = jacobian_sparsity(step)
    if sp is not None:       # a sparse J: casadi_qr, casadi_qr_solve for the runtime's Newton
        cg.add(aux_function(sp))
    code = cg.dump()
    for call, inline in _INLINE_MINMAX.items():
        code = code.replace(call, inline)
    if not code.endswith("\n"):
        code += "\n"
    return code


def _arg(f, i: int, out: bool, name: str) -> dict:
    sp = f.sparsity_out(i) if out else f.sparsity_in(i)
    numel = sp.numel()
    dense = sp.is_dense()
    return {"name": name, "numel": numel, "nnz": sp.nnz(), "dense": dense,
            "positions": [] if dense else dense_positions(sp)}


def work_sizes(f) -> dict[str, int]:
    """CasADi's work vector sizes (elements) of one function, known at codegen time."""
    return {"sz_arg": int(f.sz_arg()), "sz_res": int(f.sz_res()), "sz_iw": int(f.sz_iw()),
            "sz_w": int(f.sz_w())}


def c_kernel_context(kernel, nz_variant: bool = False) -> dict:
    """What kernels.c.j2 needs to wrap one kernel: symbol, args and work sizes; nz_variant:
    also a wrapper hpgen_k_<name>_nz writing every output's structural nonzeros."""
    f = kernel.function
    fused = C_FROM_FUSED.get(kernel.name)
    return {"name": kernel.name, "symbol": f.name(),
            # a sparse Newton matrix: hpgen_k_residual_jacobian_nz writes F and J's nonzeros
            "nz_variant": nz_variant,
            "fused": None if fused is None else {"name": fused[0], "output": fused[1]},
            "inputs": [_arg(f, i, False, kernel.inputs[i]) for i in range(f.n_in())],
            "outputs": [_arg(f, i, True, kernel.outputs[i]) for i in range(f.n_out())],
            "work": work_sizes(f)}
