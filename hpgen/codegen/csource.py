"""The C backend's inputs: CasADi's own C code for every kernel, and the per-kernel facts the
``kernels.c.j2`` template needs (work sizes, sparse gather/scatter positions); the Newton
loop and the runs around them are the static C runtime (hpgen/runtime/c).

CasADi-generated functions read/write only the structural nonzeros of each argument; the
hpgen wrappers present dense column-major arrays (gathering/scattering when an argument is
not dense) so that every exported ``hpgen_kernel_<name>`` follows the DiscreteStep contract.
"""
from __future__ import annotations

import re

import casadi

from .contract import CodegenError, dense_positions
from .sparse import AUX_FUNCTION, aux_function, jacobian_sparsity

#: CasADi CodeGenerator options. with_mem False: no memory objects, no static mutable state.
#: casadi_int int: the index arrays of CasADi's gathers (a family's F and J move thousands of
#: entries through them) half the size of long long; every array the runtime hands to
#: CasADi's code is declared casadi_int.
CG_OPTIONS = {"casadi_real": "double", "casadi_int": "int", "with_mem": False,
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

#: kernels no run calls per step or per record: linearize's partials and the kernels Python
#: calls one point at a time. Their CasADi functions, and the functions only they call, are
#: compiled at COLD_OPTIMIZE (gcc spends most of a family module's compile on -O3 of CasADi's
#: code; -O1 keeps IEEE semantics, so their results are unchanged)
COLD_KERNELS = ("legendre", "hessian", "energy", "momentum", "defect", "step_partials")
COLD_OPTIMIZE = "O1"
#: cold kernels that only linearize calls: in a family module their CasADi functions (those
#: only they reach), their wrappers and hpgen_linearize are compiled only into the lazily
#: built second library (kernels.c with -DHPGEN_LAZY_LIBRARY, hpgen.runtime.build.LAZY_FLAG),
#: between ``#if HPGEN_WITH_LAZY`` and ``#endif``. The other cold kernels stay in the step
#: library: a run's start calls defect and legendre, and the state maps call the rest.
LAZY_KERNELS = ("step_partials",)
#: the guard around the lazily built library's code
LAZY_BEGIN, LAZY_END = "#if HPGEN_WITH_LAZY", "#endif /* HPGEN_WITH_LAZY */"

#: op codes whose CasADi C output does not compile as C99 (no erfinv in <math.h>)
_C_UNSUPPORTED = {casadi.OP_ERFINV: "erfinv"}


def casadi_c_code(step, module: str, family: bool = False) -> str:
    """CasADi's C for all kernels of ``step`` in one translation unit (a string).

    Internal CasADi symbols get the prefix ``hpgen_<module>_``; the kernels.c template hides
    all of CasADi's symbols (GCC visibility) and exports only ``hpgen_*``. ``family``: the
    kernels are a family's (MX, calling per-body and per-joint functions): the functions
    only COLD_KERNELS reach are marked for COLD_OPTIMIZE (mark_cold_functions); the code is
    otherwise CasADi's as is.
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
    if family:
        roots = [k.function.name() for k in step.kernels if k.name in COLD_KERNELS]
        if sp is not None:       # printed for the casadi_qr helpers it brings; never called
            roots.append(AUX_FUNCTION)
        # the step's functions stay as CasADi prints them; step_partials' copies of the
        # per-body derivatives (printed once per calling kernel) go to the cold level
        code = mark_cold_functions(code, roots)
        code = guard_lazy_functions(code, [k.function.name() for k in step.kernels
                                           if k.name in LAZY_KERNELS])
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
    outputs = [_arg(f, i, True, kernel.outputs[i]) for i in range(f.n_out())]
    if nz_variant and kernel.name == "update":
        # the runtime packs g only when g_{k+1} is sparse and p_{k+1} dense (HPGEN_G_PACKED
        # in hpgen_newton.c); otherwise the variant would be an unused static function
        nz_variant = not outputs[0]["dense"] and all(a["dense"] for a in outputs[1:])
    return {"name": kernel.name, "symbol": f.name(),
            # a sparse Newton matrix: hpgen_k_residual_jacobian_nz writes F and J's nonzeros
            "nz_variant": nz_variant,
            "fused": None if fused is None else {"name": fused[0], "output": fused[1]},
            "inputs": [_arg(f, i, False, kernel.inputs[i]) for i in range(f.n_in())],
            "outputs": outputs,
            "work": work_sizes(f)}


_FUNCTION = re.compile(r"static int (casadi_f[0-9]+)\(")
_CALLEE = re.compile(r"\bcasadi_f[0-9]+\b")
_EXPORT = re.compile(r"CASADI_SYMBOL_EXPORT int ([A-Za-z0-9_]+)\(const casadi_real\*\* arg")


def _functions(lines: list[str]):
    """(blocks, calls, roots) of CasADi's C as lines: each internal function's (first line,
    closing line), the internal functions each calls, and the internal function each
    exported top-level function (by name) calls."""
    blocks: dict[str, tuple[int, int]] = {}
    calls: dict[str, set[str]] = {}
    roots: dict[str, str] = {}
    i = 0
    while i < len(lines):
        m = _FUNCTION.match(lines[i])
        e = _EXPORT.match(lines[i])
        if m is not None:
            end = lines.index("}", i)
            blocks[m.group(1)] = (i, end)
            calls[m.group(1)] = set(_CALLEE.findall("\n".join(lines[i + 1:end])))
            i = end + 1
            continue
        if e is not None and i + 1 < len(lines):
            target = _CALLEE.search(lines[i + 1])
            if target is not None:
                roots[e.group(1)] = target.group(0)
        i += 1
    return blocks, calls, roots


def cold_functions(code: str, cold_roots) -> set[str]:
    """The internal functions (``casadi_f<k>``) of CasADi's C that only the top-level
    functions named in ``cold_roots`` reach (not another top-level function, nor the runtime:
    a function nobody in the code calls counts as the runtime's)."""
    return _cold(_functions(code.split("\n")), cold_roots)


def _cold(parsed, cold_roots) -> set[str]:
    """cold_functions of the code whose _functions are ``parsed``."""
    blocks, calls, roots = parsed
    cold_roots = set(cold_roots)
    called = set().union(*calls.values()) if calls else set()
    hot: set[str] = set()
    stack = [f for name, f in roots.items() if name not in cold_roots]
    stack += [f for f in blocks if f not in roots.values() and f not in called]
    while stack:
        f = stack.pop()
        if f not in hot:
            hot.add(f)
            stack.extend(calls.get(f, ()))
    return {f for f in blocks if f not in hot}


def _wrapped(lines: list[str], begin: set[int], end: set[int], opening: str,
             closing: str) -> list[str]:
    """lines with ``opening`` before each line index in begin and ``closing`` after each in
    end."""
    out = []
    for j, line in enumerate(lines):
        if j in begin:
            out.append(opening)
        out.append(line)
        if j in end:
            out.append(closing)
    return out


def _extent(lines: list[str], first: int, last: int) -> tuple[int, int]:
    """A function's lines with its leading comment and cold-level markers."""
    if first > 0 and lines[first - 1].startswith("/* ") and lines[first - 1].endswith(" */"):
        first -= 1
    if first > 0 and lines[first - 1] == "HPGEN_COLD_BEGIN":
        first -= 1
    if last + 1 < len(lines) and lines[last + 1] == "HPGEN_COLD_END":
        last += 1
    return first, last


def _reached_only(code: str, roots):
    """(code's lines, first lines, last lines) of the internal functions that only the
    top-level functions ``roots`` reach (cold_functions), each with its leading comment and
    cold markers; None when there are none."""
    lines = code.split("\n")
    parsed = _functions(lines)
    found = _cold(parsed, roots)
    if not found:
        return None
    blocks = parsed[0]
    spans = [_extent(lines, *blocks[f]) for f in found]
    return lines, {first for first, _ in spans}, {last for _, last in spans}


def mark_cold_functions(code: str, cold_roots) -> str:
    """CasADi's C with each internal function that only the functions ``cold_roots`` (casadi
    names of top-level functions) reach (cold_functions) wrapped in HPGEN_COLD_BEGIN /
    HPGEN_COLD_END (GCC: compiled at COLD_OPTIMIZE; kernels.c.j2 defines them). Code that no
    cold root reaches alone is returned unchanged."""
    found = _reached_only(code, cold_roots)
    if found is None:
        return code
    return "\n".join(_wrapped(*found, "HPGEN_COLD_BEGIN", "HPGEN_COLD_END"))


def guard_lazy_functions(code: str, lazy_roots) -> str:
    """CasADi's C (after mark_cold_functions) with the internal functions only the top-level
    functions ``lazy_roots`` reach, and those top-level functions' entry points, each between
    LAZY_BEGIN and LAZY_END (compiled only into the lazily built library). Unchanged when
    nothing is lazy."""
    found = _reached_only(code, lazy_roots)
    if found is None:
        return code
    lines, begin, end = found
    entries = {f"CASADI_SYMBOL_EXPORT int {name}(const casadi_real** arg" for name in lazy_roots}
    for j, line in enumerate(lines):
        if any(line.startswith(e) for e in entries):
            begin.add(j)
            end.add(j if line.count("{") == line.count("}") else lines.index("}", j))
    return _guard_lazy_arrays(_wrapped(lines, begin, end, LAZY_BEGIN, LAZY_END))


_ARRAY_DEF = re.compile(r"static const casadi_(?:int|real) (casadi_[sc][0-9]+)\[")
_ARRAY_NAME = re.compile(r"\bcasadi_[sc][0-9]+\b")


def _guard_lazy_arrays(lines: list[str]) -> str:
    """The lines joined, with CasADi's constant arrays that only lazily built code uses
    (between LAZY_BEGIN and LAZY_END) guarded as well: the step library would otherwise
    carry them unused."""
    outside: set[str] = set()
    inside: set[str] = set()
    defs: dict[str, tuple[int, int]] = {}
    depth = 0
    j = 0
    while j < len(lines):
        line = lines[j]
        if line == LAZY_BEGIN:
            depth += 1
        elif line == LAZY_END:
            depth -= 1
        m = _ARRAY_DEF.match(line)
        if m is not None and depth == 0:
            end = j
            while not lines[end].rstrip().endswith(";"):
                end += 1
            defs[m.group(1)] = (j, end)
            j = end + 1
            continue
        if not line.startswith("#define "):         # the prefixing macros are not uses
            (inside if depth else outside).update(_ARRAY_NAME.findall(line))
        j += 1
    lazy_only = {name: span for name, span in defs.items()
                 if name in inside and name not in outside}
    begin = {a for a, _ in lazy_only.values()}
    end = {b for _, b in lazy_only.values()}
    return "\n".join(_wrapped(lines, begin, end, LAZY_BEGIN, LAZY_END))
