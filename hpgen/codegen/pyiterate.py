"""The Python backend's simplified-Newton iterations as one printed function (kernels.py
``ITERATE``), for one module: the residual kernel's fast body (hpgen.codegen.pysource,
inputs and outputs as locals), the product dz = J^{-1} F and z - dz with the inf-norms
(hpgen.codegen.pylinear) and the stopping tests of hpgen.runtime.newton.solve's simplified
branch, in a loop over the iterates that keep J^{-1}.

Every floating-point operation is the one the unfused path performs (residual kernel, then
``_lin_update``, then solve's tests), on the same operands in the same order: only the calls,
the lists between them and the unpacking of J^{-1}, g, p and h at every iterate are gone.
The function returns None where the unfused path would leave its fast arithmetic (a math
error in the residual's fast body, or a non-finite dz or z): the caller then redoes these
iterates the general way from the same start (everything here is pure), which gives the
unfused path's results. Deterministic: the same kernel and nz give the same text.
"""
from __future__ import annotations

import casadi

from ..abi import NO_CONVERGENCE, OK, REFRESH, ROUNDOFF_FLOOR, THETA_MAX
from . import pylinear
from .contract import CodegenError, dense_positions
from .pysource import fast_lines, float_literal

#: the name the printed function has in kernels.py
FUNCTION = "_newton_iterate"


def _used_positions(f, arg: int) -> set[int]:
    """Dense positions of input ``arg`` that some OP_INPUT instruction reads."""
    pos = dense_positions(f.sparsity_in(arg))
    return {pos[f.instruction_input(k)[1]] for k in range(f.n_instructions())
            if f.instruction_id(k) == casadi.OP_INPUT and f.instruction_input(k)[0] == arg}


def iterate_source(residual, nz: int) -> str:
    """The source of FUNCTION for the module's residual kernel (inputs z, g, p, h; output F)
    and nz <= pylinear.UNROLL_MAX:

    ``_newton_iterate(f, z, g, p, h, it, maxit, dprev, stol) -> (code, z, it, dn, rn)`` runs
    simplified-Newton iterates it, it + 1, ... with J^{-1} = f (a kept matrix, column-major)
    from z, dprev the previous |dz| (inf before the first): F = residual(z, g, p, h),
    dz = f F, z = z - dz, dn = |dz|, then solve's tests in its order: code OK (converged,
    round-off floor or the linear-rate estimate), abi.REFRESH (dn > THETA_MAX dprev: the
    caller refreshes J, or with a J fresh from this step goes on with full Newton), or
    NO_CONVERGENCE once iterate ``maxit`` did neither; z (a list) and rn = |F| of the last
    iterate.
    None: see the module docstring. The source is empty for a residual with a side effect
    (OP_PRINTME: the kernel runs once per call, in order)."""
    f = residual.function
    if any(f.instruction_id(k) == casadi.OP_PRINTME for k in range(f.n_instructions())):
        return ""
    if tuple(residual.inputs) != ("z", "g", "p", "h") or tuple(residual.outputs) != ("F",):
        raise CodegenError(f"kernel {residual.name}: the fused Newton iterate needs inputs "
                           f"(z, g, p, h) and output F, not {residual.inputs} -> "
                           f"{residual.outputs}")
    if not 1 <= nz <= pylinear.UNROLL_MAX or f.numel_in(0) != nz or f.numel_out(0) != nz:
        raise CodegenError(f"kernel {residual.name}: no fused Newton iterate for nz = {nz}")
    body, _ = fast_lines(residual, bound=True)
    n = nz
    zs = ", ".join(f"z{i}" for i in range(n))
    Fs = ", ".join(f"F{i}" for i in range(n))
    L = [f"def {FUNCTION}(f, z, g, p, h, it, maxit, dprev, stol):",
         '    """simplified-Newton iterates from z with J^{-1} = f (hpgen.codegen.pyiterate)"""',
         f"    {pylinear.unpack_inverse(n)}",
         f"    {zs}, = z"]
    for arg in range(1, 4):
        used = _used_positions(f, arg)
        if used:
            name = residual.inputs[arg]
            L.append("    " + ", ".join(f"{name}{j}" if j in used else "_"
                                        for j in range(f.numel_in(arg))) + f", = {name}")
    floor, theta = float_literal(ROUNDOFF_FLOOR), float_literal(THETA_MAX)
    loop = body + pylinear.matvec_lines(n, "F") + pylinear.finish_lines(n) + [
        f"if it > 1 and dn >= dprev and dn <= {floor} * (1.0 + zn):",
        f"    code = {OK}",
        "    break",
        "th = dn / dprev",
        "if dn <= stol * (1.0 + zn) or (it > 1 and th < 1.0 and "
        "th / (1.0 - th) * dn <= stol * (1.0 + zn)):",
        f"    code = {OK}",
        "    break",
        f"if it > 1 and dn > {theta} * dprev:",
        f"    code = {REFRESH}",
        "    break",
        "if it >= maxit:",
        f"    code = {NO_CONVERGENCE}",
        "    break",
        "dprev = dn",
        "it += 1"]
    L += ["    try:", "        while True:"] + ["            " + s for s in loop] + [
        "    except (ArithmeticError, ValueError):",
        "        return None",
        "    # |F| of the last iterate: F is finite here (a non-finite F_j makes all of f F so)"]
    L += ["    " + s for s in pylinear.max_abs("F", "rn", n)]
    L.append(f"    return code, [{zs}], it, dn, rn")
    return "\n".join(L)
