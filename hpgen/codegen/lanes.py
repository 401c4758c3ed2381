"""Lane-wise C kernels for ensembles: one CasADi SX function printed as a C function that
evaluates it for L independent arguments at once (the C runtime's
hpgen/runtime/c/hpgen_lanes.c runs the Newton loop of L bodies on them, full or simplified,
hpgen_lane_newton.c; hpgen.runtime's simulate_batch calls it).

Layout (structure of arrays): every argument, input or output, holds L lanes of a dense
column-major vector, entry i of lane l at ``x[i * L + l]``. The printed function is one loop
over the lanes whose body is the kernel's SX algorithm instruction by instruction, on scalar
locals named after CasADi's work slots: the same IEEE double operations in the same order as
CasADi's C code of the scalar kernel (``+ - * /`` at ``-std=c99``, no contraction; libm for
the math functions), so each lane's outputs are bitwise those of the scalar kernel. gcc
vectorises the fixed-count lane loop (SSE2 at the portable ``-O3``: two lanes a vector).

``lane_kernel_source`` returns None for a kernel with an operation it does not print (a side
effect, an op without a C99 equivalent) and raises CodegenError for a kernel over MX or with
calls (a family model's); ``lanes_context`` then gives no lane code and ensembles run the
scalar kernels.
"""
from __future__ import annotations

import casadi

from .contract import CodegenError, dense_positions

#: bodies evaluated per call (8: as fast as 4 with SSE2, the portable build; faster with AVX)
LANES = 8
#: lane code is emitted only for steps this small (unknowns: up to 3 full Newton runs
#: vectorised, the adjugate solve lane-wise; above, and for simplified Newton, the kernels
#: run lane-wise and the LU of hpgen_linalg.c lane by lane) ...
LANES_MAX_NZ = 12
#: ... with a dense Newton matrix, and whose step kernels total at most this many CasADi
#: instructions (the lane kernels about double the C compile time of kernels.c: above this
#: the ensembles' gain does not pay for it)
LANES_MAX_INSTRUCTIONS = 2000
#: the kernels the lane-wise step calls (residual: simplified Newton's iterates with a kept
#: J^{-1})
LANE_KERNELS = ("residual_jacobian", "residual", "margin", "update")
#: ... an explicit step's (meta "explicit": one update a step, no Newton, any nz)
EXPLICIT_LANE_KERNELS = ("update",)
#: an explicit step gets lane code when its update has at most this many instructions
EXPLICIT_MAX_INSTRUCTIONS = 20000

# CasADi op -> C expression over x, y, with CasADi's C semantics (casadi_sq, casadi_sign, the
# inlined fmin/fmax of hpgen.codegen.csource, comparisons as 0/1)
_C_OPS = {
    "OP_ASSIGN": "{x}", "OP_ADD": "({x}+{y})", "OP_SUB": "({x}-{y})", "OP_MUL": "({x}*{y})",
    "OP_DIV": "({x}/{y})", "OP_NEG": "(-{x})", "OP_SQ": "({x}*{x})", "OP_TWICE": "(2.*{x})",
    "OP_INV": "(1./{x})", "OP_EXP": "exp({x})", "OP_LOG": "log({x})", "OP_SQRT": "sqrt({x})",
    "OP_SIN": "sin({x})", "OP_COS": "cos({x})", "OP_TAN": "tan({x})", "OP_ASIN": "asin({x})",
    "OP_ACOS": "acos({x})", "OP_ATAN": "atan({x})", "OP_SINH": "sinh({x})",
    "OP_COSH": "cosh({x})", "OP_TANH": "tanh({x})", "OP_ASINH": "asinh({x})",
    "OP_ACOSH": "acosh({x})", "OP_ATANH": "atanh({x})", "OP_ERF": "erf({x})",
    "OP_LOG1P": "log1p({x})", "OP_EXPM1": "expm1({x})", "OP_FLOOR": "floor({x})",
    "OP_CEIL": "ceil({x})", "OP_FABS": "fabs({x})",
    "OP_SIGN": "({x}<0 ? -1. : ({x}>0 ? 1. : {x}))",
    "OP_POW": "pow({x},{y})", "OP_CONSTPOW": "pow({x},{y})",
    "OP_FMOD": "fmod({x},{y})", "OP_REMAINDER": "remainder({x},{y})",
    "OP_ATAN2": "atan2({x},{y})", "OP_HYPOT": "hypot({x},{y})",
    "OP_COPYSIGN": "copysign({x},{y})",
    "OP_FMIN": "(({x}<{y} || {y}!={y}) ? {x} : {y})",
    "OP_FMAX": "(({x}>{y} || {y}!={y}) ? {x} : {y})",
    "OP_LT": "(double)({x}<{y})", "OP_LE": "(double)({x}<={y})",
    "OP_EQ": "(double)({x}=={y})", "OP_NE": "(double)({x}!={y})",
    "OP_NOT": "(double)(!{x})", "OP_AND": "(double)({x}&&{y})", "OP_OR": "(double)({x}||{y})",
    "OP_IF_ELSE_ZERO": "({x} ? {y} : 0.)",
}
C_OPS = {getattr(casadi, k): v for k, v in _C_OPS.items() if hasattr(casadi, k)}


def c_double(v: float) -> str:
    """A C double literal that reads back bitwise (repr is the shortest round-trip decimal)."""
    v = float(v)
    if v != v:
        return "NAN"
    if v in (float("inf"), float("-inf")):
        return "HUGE_VAL" if v > 0 else "(-HUGE_VAL)"
    text = repr(v)
    return text if ("." in text or "e" in text) else text + "."


def lane_kernel_source(kernel, lanes: int = LANES) -> str | None:
    """C source of ``static void hpgen_lane_<name>(const double* in0, ..., double* out0, ...)``
    evaluating ``kernel`` on ``lanes`` lanes (see the module docstring), or None when the
    kernel has an operation this printer does not support."""
    f = kernel.function
    if _calls(f):
        raise CodegenError(f"kernel {kernel.name}: lane code is printed from SX algorithms "
                           "without calls (a family model's kernels call per-body functions)")
    ins = [dense_positions(f.sparsity_in(i)) for i in range(f.n_in())]
    outs = [dense_positions(f.sparsity_out(i)) for i in range(f.n_out())]
    L = lanes
    body, slots = [], set()
    for k in range(f.n_instructions()):
        op = f.instruction_id(k)
        i_in, i_out = f.instruction_input(k), f.instruction_output(k)
        if op == casadi.OP_INPUT:
            slots.add(i_out[0])
            body.append(f"a{i_out[0]} = in{i_in[0]}[{ins[i_in[0]][i_in[1]] * L} + l];")
        elif op == casadi.OP_OUTPUT:
            body.append(f"out{i_out[0]}[{outs[i_out[0]][i_out[1]] * L} + l] = a{i_in[0]};")
        elif op == casadi.OP_CONST:
            slots.add(i_out[0])
            body.append(f"a{i_out[0]} = {c_double(f.instruction_constant(k))};")
        elif op in C_OPS:
            slots.add(i_out[0])
            fmt = C_OPS[op]
            x = f"a{i_in[0]}"
            y = f"a{i_in[1]}" if "{y}" in fmt else None
            body.append(f"a{i_out[0]} = " + fmt.format(x=x, y=y) + ";")
        else:
            return None
    # entries outside an output's sparsity are zero (the dense contract of hpgen.abi)
    zeros = [f"out{r}[{pos * L} + l] = 0.;"
             for r in range(f.n_out())
             for pos in sorted(set(range(f.numel_out(r))) - set(outs[r]))]
    args = ([f"const double* restrict in{i}" for i in range(f.n_in())]
            + [f"double* restrict out{r}" for r in range(f.n_out())])
    names = sorted(slots)
    decls = [", ".join(f"a{s}" for s in names[i:i + 12]) for i in range(0, len(names), 12)]
    sig = ", ".join(kernel.inputs) + ") -> (" + ", ".join(kernel.outputs)
    lines = [f"/* {kernel.name}({sig}), {L} lanes: x[i * {L} + lane] */",
             f"static void hpgen_lane_{kernel.name}({', '.join(args)}) {{",
             "    int l;",
             "    " + " ".join(f"(void)in{i};" for i in range(f.n_in())),
             f"    for (l = 0; l < {L}; ++l) {{"]
    lines += [f"        double {d};" for d in decls]
    lines += ["        " + s for s in zeros + body]
    lines += [f"        (void){', (void)'.join(f'a{s}' for s in names)};" if names else "",
              "    }", "}"]
    return "\n".join(line for line in lines if line) + "\n"


def _calls(f) -> bool:
    return f.is_a("MXFunction") or any(f.instruction_id(k) == casadi.OP_CALL
                                       for k in range(f.n_instructions()))


def lanes_context(step, step_instructions: int) -> dict | None:
    """kernels.c.j2's ``lanes`` entry: {"L": lanes, "code": the lane kernels' C} when lane code
    pays and can be printed (a closed model, nz <= LANES_MAX_NZ, a dense Newton matrix, step
    kernels of at most LANES_MAX_INSTRUCTIONS instructions, every op printable; an explicit
    step: its update of at most EXPLICIT_MAX_INSTRUCTIONS instructions, any nz), else
    None."""
    explicit = bool(getattr(step, "explicit", False))
    if step.open_spec is not None:
        return None
    if explicit:
        names = EXPLICIT_LANE_KERNELS
        if step.kernel("update").function.n_instructions() > EXPLICIT_MAX_INSTRUCTIONS:
            return None
    else:
        names = LANE_KERNELS
        if step.nz > LANES_MAX_NZ or step_instructions > LANES_MAX_INSTRUCTIONS:
            return None
        from .sparse import jacobian_sparsity
        if jacobian_sparsity(step) is not None:
            return None               # a sparse J: the scalar loop's sparse LU / QR
    if any(_calls(step.kernel(name).function) for name in names):
        return None                   # scalar kernels with calls: ensembles run those
    parts = [lane_kernel_source(step.kernel(name)) for name in names]
    if any(p is None for p in parts):
        return None
    if not explicit:                  # the runtime's sign that the residual is lane-wise
        parts.insert(0, "#define HPGEN_LANE_RESIDUAL 1\n")
    return {"L": LANES, "code": "\n".join(parts)}
