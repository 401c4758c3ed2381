"""Print one CasADi SX function as straight-line Python (the Python backend).

The walk follows the function's SX algorithm instruction by instruction, so the generated
Python performs the same IEEE double operations in the same order as CasADi's C: ``+ - * /``
on Python floats (IEEE double, round to nearest, no contraction: what CasADi's C does at
``-std=c99``) and math functions whose results are those of C99 libm. Each kernel body has
two versions of the same instruction list:

- a fast body, tried first: constants are inlined as literals, copies (OP_ASSIGN) are
  aliases, a value used exactly once is folded into the expression that uses it (nesting
  depth at most MAX_DEPTH), each input is unpacked once into locals, outputs are stored where
  CasADi writes them, and work variables ``w<k>`` are reused by a linear-scan allocation over
  the values' live ranges. An operation that CasADi repeats on the same operands is computed
  once (common subexpressions; ``x + y`` and ``y + x``, ``x * y`` and ``y * x`` count as the
  same, IEEE addition and multiplication being commutative), equal constants are one value.
  Only where and how often values are kept changes: every value is still the result of the
  same operation on the same operand values (evaluation order among independent pure
  subexpressions cannot change a rounded result; nothing is re-associated). One
  substitution: ``x / c`` for a constant c = +-2^k with a normal reciprocal
  is printed ``x * (1/c)``, the same IEEE result for every x (gcc makes that replacement in
  the C backend). ``/`` and the math functions are called directly, so a zero divisor or a
  domain/range error raises;
- a safe body, run only if the fast one raised (ArithmeticError or ValueError): one statement
  per instruction, ``/`` with a zero-divisor fallback and math functions through the helpers
  of templates/kernels.py.j2 that return the C99 result (inf/nan) where Python's ``math``
  would raise. It recomputes everything from the inputs (kernels are pure), so its outputs
  are what the fast body would have produced with C semantics.

Both bodies leave the outputs in lists ``r<i>`` (dense column-major). A kernel without an
operation that can raise gets the fast body only; one with OP_PRINTME (a side effect) gets
the safe body only.
"""
from __future__ import annotations

import heapq
import math
import re

import casadi

from .contract import CodegenError, dense_positions

#: deepest expression nesting of the fast body (Python's parser allows 200 nested brackets)
MAX_DEPTH = 40

# op code -> format over work-variable names x, y (safe body: never raises on float inputs
# except where C would not either)
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

# fast body: the ops whose safe format guards against a Python exception call the raw
# operation instead (``_f_<name>`` are module-level aliases of math.<name>, see the template)
_RAISING_UNARY = ("EXP", "LOG", "SQRT", "SIN", "COS", "TAN", "ASIN", "ACOS", "SINH", "COSH",
                  "ACOSH", "ATANH", "LOG1P", "EXPM1")
_FAST_UNARY = dict(_UNARY, OP_INV="1.0 / {x}", OP_FABS="_f_fabs({x})",
                   **{f"OP_{n}": f"_f_{n.lower()}({{x}})" for n in _RAISING_UNARY})
_FAST_BINARY = dict(_BINARY, OP_DIV="{x} / {y}", OP_POW="_f_pow({x}, {y})",
                    OP_CONSTPOW="_f_pow({x}, {y})", OP_FMOD="_f_fmod({x}, {y})",
                    OP_REMAINDER="_f_remainder({x}, {y})")
_RAISING = {"OP_INV", "OP_DIV", "OP_POW", "OP_CONSTPOW", "OP_FMOD", "OP_REMAINDER",
            *(f"OP_{n}" for n in _RAISING_UNARY)}


def _table(spec: dict) -> dict[int, str]:
    return {getattr(casadi, k): v for k, v in spec.items() if hasattr(casadi, k)}


UNARY, BINARY = _table(_UNARY), _table(_BINARY)
FAST_UNARY, FAST_BINARY = _table(_FAST_UNARY), _table(_FAST_BINARY)
RAISING = {getattr(casadi, k) for k in _RAISING if hasattr(casadi, k)}
_COMMUTATIVE = {casadi.OP_ADD, casadi.OP_MUL}
_OP_NAMES = {getattr(casadi, k): k for k in dir(casadi) if k.startswith("OP_")}
_SIMPLE = re.compile(r"[A-Za-z_][A-Za-z0-9_.]*\Z|[0-9][0-9.e+]*\Z|@[0-9]+@\Z")
_REF = re.compile(r"@([0-9]+)@")


def float_literal(v: float) -> str:
    """Exact Python literal of a double (repr round-trips; inf/nan via math)."""
    v = float(v)
    if math.isnan(v):
        return "math.nan"
    if math.isinf(v):
        return "math.inf" if v > 0 else "-math.inf"
    return repr(v)


def _unsupported(kernel, k, op):
    name = _OP_NAMES.get(op, "?")
    return CodegenError(f"kernel {kernel.name}: instruction {k} has CasADi op code {op} "
                        f"({name}) which the Python code generator cannot print")


def _io_positions(f, nonzeros: bool = False):
    """Where each argument's nonzeros sit: dense column-major positions, or (a callee's
    arguments, ``nonzeros``) their own index among the nonzeros."""
    if nonzeros:
        return ([list(range(f.nnz_in(i))) for i in range(f.n_in())],
                [list(range(f.nnz_out(i))) for i in range(f.n_out())])
    ins = [dense_positions(f.sparsity_in(i)) for i in range(f.n_in())]
    outs = [dense_positions(f.sparsity_out(i)) for i in range(f.n_out())]
    return ins, outs


def _numel(f, i: int, out: bool, nonzeros: bool) -> int:
    if nonzeros:
        return f.nnz_out(i) if out else f.nnz_in(i)
    return f.numel_out(i) if out else f.numel_in(i)


def callee_name(fn) -> str:
    """The Python name of a called CasADi function (CasADi names are identifiers)."""
    return "_call_" + fn.name()


def instructions(f) -> list:
    """[(op, inputs, outputs)] of f's SX algorithm, one entry per instruction (each call
    goes through SWIG: a printer decodes a function once and passes the list on)."""
    iid, iin, iout = f.instruction_id, f.instruction_input, f.instruction_output
    return [(iid(k), iin(k), iout(k)) for k in range(f.n_instructions())]


#: {id(f): (f, its callees)}: _callees is asked for every kernel again by callee_functions
_CALLEES: dict = {}


def _callees(f, instrs=None) -> dict:
    """{instruction index: called casadi.Function} of f's OP_CALL instructions (``instrs``:
    f's instructions when the caller has decoded them)."""
    hit = _CALLEES.get(id(f))
    if hit is not None and hit[0] is f:
        return hit[1]
    if instrs is None:
        ks = [k for k in range(f.n_instructions()) if f.instruction_id(k) == casadi.OP_CALL]
    else:
        ks = [k for k, (op, _, _) in enumerate(instrs) if op == casadi.OP_CALL]
    nodes = f.instructions_sx() if ks else None
    calls = {k: nodes[k].which_function() for k in ks}
    if len(_CALLEES) >= 256:
        _CALLEES.clear()
    _CALLEES[id(f)] = (f, calls)
    return calls


def safe_lines(kernel, nonzeros: bool = False, instrs=None) -> list[str]:
    """The safe body: one statement per instruction, outputs into ``r<i> = [0.0] * numel``
    (a callee's, ``nonzeros``: its arguments are their nonzeros)."""
    f = kernel.function
    ins, outs = _io_positions(f, nonzeros)
    instrs = instructions(f) if instrs is None else instrs
    calls = _callees(f, instrs)
    lines = [f"r{i} = [0.0] * {_numel(f, i, True, nonzeros)}" for i in range(f.n_out())]
    for k, (op, i_in, i_out) in enumerate(instrs):
        if op == casadi.OP_CALL:
            targets = [f"w{o}" if o >= 0 else "_" for o in i_out]
            lines.append(", ".join(targets) + ("," if len(targets) == 1 else "") + " = "
                         + callee_name(calls[k]) + "(" + ", ".join(f"w{a}" for a in i_in) + ")")
        elif op == casadi.OP_INPUT:
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
            raise _unsupported(kernel, k, op)
    return lines


class _Value:
    """One SSA value of the fast body: a literal, an input element or an operation."""
    __slots__ = ("kind", "text", "fmt", "args", "uses", "inline", "depth", "value")

    def __init__(self, kind, text=None, fmt=None, args=(), value=None):
        self.kind, self.text, self.fmt, self.args = kind, text, fmt, tuple(args)
        self.uses, self.inline, self.depth, self.value = 0, False, 0, value


def _wrap(text: str) -> str:
    return text if _SIMPLE.match(text) else f"({text})"


def exact_reciprocal(c) -> float | None:
    """1/c if c = +-2^k and 1/c is a normal double, else None. Then x / c and x * (1/c) are
    the same IEEE result for every x (the same exact quotient, rounded once; inf, nan and
    signed zeros alike): the replacement gcc makes in the C backend at -O1 and above."""
    if c is None or not math.isfinite(c) or c == 0.0 or abs(math.frexp(c)[0]) != 0.5:
        return None
    r = 1.0 / c
    return r if abs(r) >= 2.2250738585072014e-308 and math.isfinite(r) else None


def fast_lines(kernel, bound: bool = False, nonzeros: bool = False,
               instrs=None) -> tuple[list[str], bool]:
    """The fast body and whether it contains an operation that may raise.

    bound: the body of a loop (hpgen.codegen.pyiterate) instead of a function: the inputs
    are locals bound before it, element j of input ``x`` named ``x<j>`` (no unpacking,
    never reused as work variables, see bound_inputs), and output ``y``'s element j is
    left in the local ``y<j>`` instead of a list. nonzeros: a callee's body (its arguments
    are their nonzeros). A call (OP_CALL) is one statement unpacking the callee's outputs;
    it may raise (the callee's own safe body runs then, inside the call)."""
    f = kernel.function
    ins, outs = _io_positions(f, nonzeros)
    instrs = instructions(f) if instrs is None else instrs
    calls = _callees(f, instrs)
    vals: list[_Value] = []
    slot: dict[int, int] = {}                 # CasADi work slot -> its current value
    inputs: dict[tuple[int, int], int] = {}   # (argument, dense position) -> value
    consts: dict[str, int] = {}               # literal -> value
    known: dict[tuple, int] = {}              # (format, operands) -> value computed before
    order = []                                # ("op", value) / ("out", output, position, value)
    raising = False

    def new(v):
        vals.append(v)
        return len(vals) - 1

    for k, (op, i_in, i_out) in enumerate(instrs):
        if op == casadi.OP_INPUT:
            key = (i_in[0], ins[i_in[0]][i_in[1]])
            if key not in inputs:
                inputs[key] = new(_Value("input"))
            slot[i_out[0]] = inputs[key]
        elif op == casadi.OP_OUTPUT:
            vals[slot[i_in[0]]].uses += 1
            order.append(("out", i_out[0], outs[i_out[0]][i_out[1]], slot[i_in[0]]))
        elif op == casadi.OP_CONST:
            c = f.instruction_constant(k)
            lit = float_literal(c)
            if lit not in consts:
                consts[lit] = new(_Value("const", text=lit, value=float(c)))
            slot[i_out[0]] = consts[lit]
        elif op == casadi.OP_ASSIGN:
            slot[i_out[0]] = slot[i_in[0]]
        elif op == casadi.OP_CALL:
            args = tuple(slot[a] for a in i_in)
            for a in args:
                vals[a].uses += 1
            results = []
            for o in i_out:
                if o >= 0:
                    slot[o] = new(_Value("result"))
                    results.append(slot[o])
                else:
                    results.append(None)
            order.append(("call", callee_name(calls[k]), args, results))
        elif op in FAST_UNARY or op in FAST_BINARY:
            unary = op in FAST_UNARY
            fmt = FAST_UNARY[op] if unary else FAST_BINARY[op]
            args = (slot[i_in[0]],) if unary else (slot[i_in[0]], slot[i_in[1]])
            recip = exact_reciprocal(vals[args[1]].value) if op == casadi.OP_DIV else None
            if recip is not None:              # x / 2^k -> x * 2^-k (same result)
                fmt, args = "{x} * " + _wrap(float_literal(recip)), args[:1]
            # the same operation on the same operands was computed before: reuse it (x + y
            # and y + x, x * y and y * x are the same IEEE result)
            key = (fmt, tuple(sorted(args)) if op in _COMMUTATIVE else args)
            if key in known:
                slot[i_out[0]] = known[key]
                continue
            if recip is None:
                raising = raising or op in RAISING
            for name, a in zip("xy", args):
                vals[a].uses += fmt.count("{" + name + "}")
            slot[i_out[0]] = known[key] = new(_Value("op", fmt=fmt, args=args))
            order.append(("op", slot[i_out[0]]))
        else:
            raise _unsupported(kernel, k, op)

    # which single-use operations fold into their user: decided in definition order, so the
    # depth of every operand is known
    for v in vals:
        if v.kind == "op":
            v.depth = 1 + max((vals[a].depth for a in v.args if vals[a].inline), default=0)
            v.inline = v.uses == 1 and v.depth <= MAX_DEPTH

    def text(i, wrap=True):
        v = vals[i]
        if v.kind in ("input", "result") or (v.kind == "op" and not v.inline):
            return f"@{i}@"
        t = v.text if v.kind == "const" else expr(v)
        return _wrap(t) if wrap else t

    def expr(v):
        return v.fmt.format(**dict(zip("xy", (text(a) for a in v.args))))

    # statements (values defined, left side, right side), references written @value@;
    # outputs are stored where CasADi writes them (their values need not stay alive)
    stmts: list[tuple[list[int], str, str]] = []
    name: dict[int, str] = {}
    if bound:
        for (arg, pos), i in inputs.items():
            name[i] = f"{kernel.inputs[arg]}{pos}"
    for a in range(f.n_in() if not bound else 0):
        used = {pos: i for (arg, pos), i in inputs.items() if arg == a and vals[i].uses}
        if used:
            targets = [f"@{used[p]}@" if p in used else "_"
                       for p in range(_numel(f, a, False, nonzeros))]
            stmts.append((list(used.values()),
                          ", ".join(targets) + ("," if len(targets) == 1 else ""),
                          kernel.inputs[a]))
    for r in range(f.n_out() if not bound else 0):
        stmts.append(([], f"r{r}", f"[0.0] * {_numel(f, r, True, nonzeros)}"))
    for item in order:
        if item[0] == "call":
            _, fname, args, results = item
            lhs = ", ".join("_" if v is None else f"@{v}@" for v in results)
            stmts.append(([v for v in results if v is not None],
                          lhs + ("," if len(results) == 1 else ""),
                          f"{fname}({', '.join(text(a, wrap=False) for a in args)})"))
        elif item[0] == "op":
            if not vals[item[1]].inline:
                stmts.append(([item[1]], f"@{item[1]}@", expr(vals[item[1]])))
        elif bound:
            stmts.append(([], f"{kernel.outputs[item[1]]}{item[2]}", text(item[3], wrap=False)))
        else:
            stmts.append(([], f"r{item[1]}[{item[2]}]", text(item[3], wrap=False)))

    # linear-scan allocation of the stored values to work variables w<k> (lowest free first)
    last = {int(m.group(1)): s for s, (_, _, rhs) in enumerate(stmts)
            for m in _REF.finditer(rhs)}
    free: list[int] = []
    count = 0
    lines = []
    for s, (defs, lhs, rhs) in enumerate(stmts):
        used = {int(m.group(1)) for m in _REF.finditer(rhs)}
        rhs = _REF.sub(lambda m: name[int(m.group(1))], rhs)
        for i in sorted(used):
            if last[i] == s and (not bound or vals[i].kind == "op"):
                heapq.heappush(free, int(name[i][1:]))
        for i in defs:
            if i not in last:
                name[i] = "_"                 # computed, never used
            elif free:
                name[i] = f"w{heapq.heappop(free)}"
            else:
                name[i], count = f"w{count}", count + 1
        lines.append(_REF.sub(lambda m: name[int(m.group(1))], lhs) + " = " + rhs)
    return lines, raising


def kernel_lines(kernel, nonzeros: bool = False) -> list[str]:
    """Body statements (unindented) of the Python function for one kernel, after the input
    conversion that the template prints; they leave the outputs in lists ``r<i>``."""
    f = kernel.function
    instrs = instructions(f)
    if any(op == casadi.OP_PRINTME for op, _, _ in instrs):
        return safe_lines(kernel, nonzeros, instrs)   # a side effect: run once, in order
    fast, raising = fast_lines(kernel, nonzeros=nonzeros, instrs=instrs)
    if not raising:
        return fast
    return (["try:"] + ["    " + s for s in fast]
            + ["except (ArithmeticError, ValueError):",
               "    # a zero divisor or a math domain/range error: recompute with C semantics"]
            + ["    " + s for s in safe_lines(kernel, nonzeros, instrs)])


def py_kernel_context(kernel) -> dict:
    """What kernels.py.j2 needs for one kernel (an MX kernel through its SX expansion)."""
    from .pycallees import as_sx
    kernel = as_sx(kernel)
    f = kernel.function
    return {"name": kernel.name,
            "inputs": [{"name": kernel.inputs[i], "numel": f.numel_in(i)}
                       for i in range(f.n_in())],
            "outputs": [{"name": kernel.outputs[i], "numel": f.numel_out(i)}
                        for i in range(f.n_out())],
            "lines": kernel_lines(kernel)}
