"""The Python backend's Newton iterations as printed functions (kernels.py ``ITERATE`` and
``ITERATE_FULL``), for one module:

- ITERATE, the simplified iterates that keep J^{-1}: the residual kernel's fast body
  (hpgen.codegen.pysource, inputs and outputs as locals), the product dz = J^{-1} F and
  z - dz with the inf-norms (hpgen.codegen.pylinear) and the stopping tests of
  hpgen.runtime.newton.solve's simplified branch, in a loop;
- ITERATE_FULL, full Newton without a kept J: the residual_jacobian kernel's fast body,
  LINEAR's _lin_factor_solve, z - dz and the tests of solve's full branch, in a loop.

Every floating-point operation is the one the unfused path performs (the kernels, then
LINEAR's functions, then solve's tests), on the same operands in the same order: only the
calls, the lists between them and the unpacking of J^{-1}, g, p and h at every iterate are
gone. A function returns None where the unfused path would leave its fast arithmetic (a math
error in a kernel's fast body, a non-finite value, a singular J): the caller then redoes
these iterates the general way from the same start (everything here is pure), which gives
the unfused path's results. Deterministic: the same kernel and nz give the same text.
"""
from __future__ import annotations

import casadi

from ..abi import NO_CONVERGENCE, OK, REFRESH, ROUNDOFF_FLOOR, THETA_FLOOR, THETA_MAX
from . import pylinear
from .contract import CodegenError, dense_positions
from .pysource import fast_lines, float_literal

#: the names the printed functions have in kernels.py (ITERATE, ITERATE_FULL)
FUNCTION = "_newton_iterate"
FULL = "_newton_full"


def _used_positions(f, arg: int) -> set[int]:
    """Dense positions of input ``arg`` that some OP_INPUT instruction reads."""
    pos = dense_positions(f.sparsity_in(arg))
    return {pos[f.instruction_input(k)[1]] for k in range(f.n_instructions())
            if f.instruction_id(k) == casadi.OP_INPUT and f.instruction_input(k)[0] == arg}


def _no_fused(f) -> bool:
    """Whether the kernel function f gets no fused iterate: a side effect (OP_PRINTME), or
    an MX composition of call nodes (a family's step kernels with few unknowns, e.g. a
    constrained splitting step: kernels.py calls the kernel instead)."""
    return f.is_a("MXFunction") or any(
        f.instruction_id(k) == casadi.OP_PRINTME for k in range(f.n_instructions()))


def _check(kernel, nz: int, outputs: tuple):
    f = kernel.function
    if tuple(kernel.inputs) != ("z", "g", "p", "h") or tuple(kernel.outputs) != outputs:
        raise CodegenError(f"kernel {kernel.name}: the fused Newton iterate needs inputs "
                           f"(z, g, p, h) and outputs {outputs}, not {kernel.inputs} -> "
                           f"{kernel.outputs}")
    if not 1 <= nz <= pylinear.UNROLL_MAX or f.numel_in(0) != nz or f.numel_out(0) != nz:
        raise CodegenError(f"kernel {kernel.name}: no fused Newton iterate for nz = {nz}")


def _function(kernel, nz: int, signature: str, doc: str, prologue: list[str],
              loop: list[str]) -> str:
    """def <signature>: prologue, z, g, p, h unpacked, then ``while True:`` over the kernel's
    fast body and ``loop`` (which sets ``code`` and breaks) inside a try whose math errors
    return None; at the end |F| of the last iterate (F finite there) and the result
    (code, z, it, dn, rn)."""
    f = kernel.function
    body, _ = fast_lines(kernel, bound=True)
    zs = ", ".join(f"z{i}" for i in range(nz))
    L = [f"def {signature}:", f'    """{doc} (hpgen.codegen.pyiterate)"""']
    L += ["    " + s for s in prologue] + [f"    {zs}, = z"]
    for arg in range(1, 4):
        used = _used_positions(f, arg)
        if used:
            name = kernel.inputs[arg]
            L.append("    " + ", ".join(f"{name}{j}" if j in used else "_"
                                        for j in range(f.numel_in(arg))) + f", = {name}")
    L += ["    try:", "        while True:"] + ["            " + s for s in body + loop] + [
        "    except (ArithmeticError, ValueError):",
        "        return None"]
    L += ["    " + s for s in pylinear.max_abs("F", "rn", nz)]
    L.append(f"    return code, [{zs}], it, dn, rn")
    return "\n".join(L)


def _stop(code) -> list[str]:
    return [f"    code = {code}", "    break"]


def iterate_source(residual, nz: int) -> str:
    """The source of FUNCTION for the module's residual kernel (inputs z, g, p, h; output F)
    and nz <= pylinear.UNROLL_MAX:

    ``_newton_iterate(f, z, g, p, h, it, maxit, dprev, stol) -> (code, z, it, dn, rn)`` runs
    simplified-Newton iterates it, it + 1, ... with J^{-1} = f (a kept matrix, column-major)
    from z, dprev the previous |dz| (inf before the first): F = residual(z, g, p, h),
    dz = f F, z = z - dz, dn = |dz|, then solve's tests in its order: code OK (converged,
    round-off floor or the linear-rate estimate, its rate at least THETA_FLOOR),
    abi.REFRESH (dn > THETA_MAX dprev: the caller refreshes J, or with a J fresh from this
    step goes on with full Newton), or
    NO_CONVERGENCE once iterate ``maxit`` did neither; z (a list) and rn = |F| of the last
    iterate (F is finite when dz is: a non-finite F_j makes every entry of f F so).
    None: see the module docstring. The source is empty for a residual with a side effect
    (OP_PRINTME: the kernel runs once per call, in order) or an MX composition (_no_fused)."""
    f = residual.function
    if _no_fused(f):
        return ""
    _check(residual, nz, ("F",))
    floor, theta = float_literal(ROUNDOFF_FLOOR), float_literal(THETA_MAX)
    tfloor = float_literal(THETA_FLOOR)
    loop = pylinear.matvec_lines(nz, "F") + pylinear.finish_lines(nz) + [
        f"if it > 1 and dn >= dprev and dn <= {floor} * (1.0 + zn):", *_stop(OK),
        "th = dn / dprev",
        f"te = th if th > {tfloor} else {tfloor}",
        "if dn <= stol * (1.0 + zn) or (it > 1 and te < 1.0 and "
        "te / (1.0 - te) * dn <= stol * (1.0 + zn)):", *_stop(OK),
        f"if it > 1 and dn > {theta} * dprev:", *_stop(REFRESH),
        "if it >= maxit:", *_stop(NO_CONVERGENCE),
        "dprev = dn",
        "it += 1"]
    return _function(residual, nz, f"{FUNCTION}(f, z, g, p, h, it, maxit, dprev, stol)",
                     "simplified-Newton iterates from z with J^{-1} = f",
                     [pylinear.unpack_inverse(nz)], loop)


def full_source(residual_jacobian, nz: int) -> str:
    """The source of FULL (full Newton, J never kept) for the module's residual_jacobian
    kernel (inputs z, g, p, h; outputs F, J):

    ``_newton_full(z, g, p, h, it, maxit, dprev, tol) -> (code, z, it, dn, rn)`` runs
    iterates it, it + 1, ... from z: F and J from the kernel's body, dz = J^{-1} F by
    LINEAR's _lin_factor_solve (keep False), z = z - dz, then solve's tests for full Newton:
    OK (round-off floor, or dn <= tol (1 + |z|)) or NO_CONVERGENCE after iterate ``maxit``;
    one Jacobian per iterate. None where solve's general way would leave this one: a math
    error, a non-finite F (or a sum of F overflowing), J singular or not finite, a
    non-finite dz or z. Empty source for a kernel with a side effect."""
    f = residual_jacobian.function
    if _no_fused(f):
        return ""
    _check(residual_jacobian, nz, ("F", "J"))
    Fs = ", ".join(f"F{i}" for i in range(nz))
    Js = ", ".join(f"J{k}" for k in range(nz * nz))
    floor = float_literal(ROUNDOFF_FLOOR)
    loop = [f"s = {' + '.join(f'F{i}' for i in range(nz))}",
            "if not s - s == 0.0:", "    return None",
            f"res = _lin_factor_solve([{Js}], [{Fs}], False)",
            "if res is None:", "    return None",
            f"{', '.join(f'b{i}' for i in range(nz))}, = res[0]"] + pylinear.finish_lines(nz) + [
        f"if it > 1 and dn >= dprev and dn <= {floor} * (1.0 + zn):", *_stop(OK),
        "if dn <= tol * (1.0 + zn):", *_stop(OK),
        "if it >= maxit:", *_stop(NO_CONVERGENCE),
        "dprev = dn",
        "it += 1"]
    return _function(residual_jacobian, nz, f"{FULL}(z, g, p, h, it, maxit, dprev, tol)",
                     "full-Newton iterates from z", [], loop)
