"""A family module's CasADi C split into translation units that the C compiler runs in parallel.

kernels.c stays one file. Compiled as it is, it is one translation unit, exactly as without
the split (the macros below then keep every function static). Compiled with
``-DHPGEN_PART=k`` for k < HPGEN_PARTS (hpgen.runtime.build does so when kernels.c defines
HPGEN_PARTS), the preprocessor keeps part k only, and the parts' objects are linked into one
library:

- part 0: everything outside CasADi's code (the model's sizes, the kernel wrappers, the C
  runtime), CasADi's exported functions and every CasADi function not moved;
- part k >= 1: the large CasADi functions (at least MIN_LINES lines) assigned to it, most
  expensive first onto the least loaded part, with the constant arrays they read; those of
  the step library first, then those only the lazily built library compiles
  (csource.guard_lazy_functions), so that the step library's parts are balanced. The step's
  MX functions (loops over the bodies, calls of CasADi's helpers) stay in part 0 with the
  helpers and the runtime, compiled as in one unit; of the step, only straight-line (SX)
  functions such as the per-body Jacobian blocks move.

CasADi's helper functions (casadi_sq, casadi_mtimes, ...) keep their linkage in part 0 and
are static copies in the other parts (HPGEN_PRIVATE); a function called from another part is
extern with hidden visibility (HPGEN_SHARED), declared before the first function. The arithmetic is the same
in every layout (no -ffast-math, no FP contraction in ISO C99 mode): only which calls the
compiler may inline changes.
"""
from __future__ import annotations

import re

from .csource import LAZY_BEGIN, LAZY_END, _extent, _functions

#: translation units of a family module (the machines hpgen targets have 2 or more cores)
PARTS = 2
#: CasADi functions shorter than this stay in part 0 (inlinable into their callers)
MIN_LINES = 100
#: compile cost model (gcc 12, in units of one line of CasADi's straight-line SX code at
#: -O3): a loop or a call to a CasADi helper (MX code) costs LOOP_COST lines, a function at
#: the cold level (HPGEN_COLD_BEGIN) COLD_WEIGHT of the same at -O3, and part 0's fixed
#: content (the C runtime, the kernel wrappers, the tables) BASE_COST
LOOP_COST = 8
COLD_WEIGHT = 0.65
BASE_COST = 15000
_LOOP = re.compile(r"\bfor \(|\bcasadi_[a-z_]+\(")

_ARRAY = re.compile(r"static const casadi_(?:int|real) (casadi_[sc][0-9]+)\[")
_ARRAY_USE = re.compile(r"\bcasadi_[sc][0-9]+\b")
_HELPER = re.compile(r"(?:casadi_real|casadi_int|void|int|const casadi_int\*) casadi_\w+\(")
_EXPORTED = "CASADI_SYMBOL_EXPORT "

MACROS = """/* translation units (hpgen.codegen.cparts): one without HPGEN_PART, else part HPGEN_PART */
#define HPGEN_PARTS {parts}
#ifdef HPGEN_PART
#define HPGEN_IN_PART(k) ((k) == HPGEN_PART)
#define HPGEN_SHARED
#else
#define HPGEN_IN_PART(k) 1
#define HPGEN_SHARED static
#endif
#if defined(HPGEN_PART) && HPGEN_PART > 0
#define HPGEN_PRIVATE static
#else
#define HPGEN_PRIVATE
#endif
"""


def assign_parts(costs: dict[str, float], parts: int, base: float,
                 load: list[float] | None = None) -> dict[str, int]:
    """Functions -> part (1..parts-1, or 0 for those not listed): longest processing time
    first, part 0 starting at ``base`` (or the parts at ``load``, updated in place)."""
    load = [base] + [0.0] * (parts - 1) if load is None else load
    out = {}
    for f in sorted(costs, key=lambda f: (-costs[f], f)):
        k = min(range(parts), key=lambda k: (load[k], k))
        out[f] = k
        load[k] += costs[f]
    return out


def split_casadi_code(code: str, parts: int = PARTS) -> str:
    """CasADi's C (after csource.mark_cold_functions) guarded into ``parts`` translation
    units; the code unchanged when no function reaches MIN_LINES."""
    lines = code.split("\n")
    blocks, calls, roots = _functions(lines)
    extents = {f: _extent(lines, *blocks[f]) for f in blocks}
    # the step library's functions are balanced first, those of the lazily built library
    # (between LAZY_BEGIN and its end, csource.guard_lazy_functions) onto the result
    costs: dict[bool, dict[str, float]] = {False: {}, True: {}}
    fixed = 0.0
    lazy_functions = set()
    for f, (first, last) in extents.items():
        a, b = blocks[f]
        body, cold = "\n".join(lines[a + 1:b]), lines[first] == "HPGEN_COLD_BEGIN"
        lazy = first > 0 and lines[first - 1] == LAZY_BEGIN
        if lazy:
            lazy_functions.add(f)
        cost = (b - a + LOOP_COST * len(_LOOP.findall(body))) * (COLD_WEIGHT if cold else 1.0)
        if b - a >= MIN_LINES and (cold or "for (" not in body):
            costs[lazy][f] = cost
        elif not lazy:
            fixed += cost
    part_of = dict.fromkeys(blocks, 0)
    load = [BASE_COST + fixed] + [0.0] * (parts - 1)
    part_of.update(assign_parts(costs[False], parts, 0.0, load))
    part_of.update(assign_parts(costs[True], parts, 0.0, load))
    if all(k == 0 for k in part_of.values()):
        return code
    shared = {c for f, cs in calls.items() for c in cs if part_of[c] != part_of[f]}
    shared |= {f for f in roots.values() if part_of[f] != 0}
    # owner[j]: the parts that keep line j (None: all)
    owner: list[frozenset | None] = [None] * len(lines)
    users: dict[str, set[int]] = {}
    for f, (first, last) in extents.items():
        for j in range(first, last + 1):
            owner[j] = frozenset({part_of[f]})
        for name in _ARRAY_USE.findall("\n".join(lines[first:last + 1])):
            users.setdefault(name, set()).add(part_of[f])
    everyone = frozenset(range(parts))
    j = 0
    while j < len(lines):
        line = lines[j]
        if owner[j] is not None:
            j += 1
            continue
        m = _ARRAY.match(line)
        if line.startswith(_EXPORTED) or m is not None:
            end = j
            if m is not None:
                while not lines[end].rstrip().endswith(";"):
                    end += 1
            elif line.count("{") != line.count("}"):
                end = lines.index("}", j)
            kept = frozenset({0} | users.get(m.group(1), set())) if m else frozenset({0})
            for i in range(j, end + 1):
                owner[i] = None if kept == everyone else kept
            j = end + 1
            continue
        if _HELPER.match(line):
            lines[j] = "HPGEN_PRIVATE " + line
        j += 1
    for f in shared:
        first = blocks[f][0]
        lines[first] = "HPGEN_SHARED " + lines[first][len("static "):]
    start = min(a for a, _ in extents.values())
    # a lazily built library's functions are declared only where they are defined
    protos = [line for f in sorted(shared, key=lambda f: blocks[f][0])
              for line in ([LAZY_BEGIN, lines[blocks[f][0]].rstrip(" {") + ";", LAZY_END]
                           if f in lazy_functions else [lines[blocks[f][0]].rstrip(" {") + ";"])]
    out = [MACROS.format(parts=parts).rstrip("\n")]
    current: frozenset | None = None
    for j, line in enumerate(lines):
        if j == start:
            out, current = _close(out, current), None
            out.append("/* functions called across translation units */")
            out.extend(protos)
        keep = owner[j]
        if keep != current:
            out = _close(out, current)
            if keep is not None:
                out.append("#if " + " || ".join(f"HPGEN_IN_PART({k})" for k in sorted(keep)))
            current = keep
        out.append(line)
    return "\n".join(_close(out, current))


def _close(out: list[str], current) -> list[str]:
    if current is not None:
        out.append("#endif")
    return out
