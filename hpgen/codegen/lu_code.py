"""C code of the static LU's numeric factorization (hpgen.codegen.static_lu), generated at
compile time: every multiply-add of the elimination with its storage positions as constants,
instead of the runtime's left-looking loop over the index arrays (hpgen_slu_factor in
hpgen/runtime/c/hpgen_linalg.c).

The code is right-looking, pivot k of P J P^T (storage X: the filled pattern in compressed
columns, 1 / u_kk on the diagonal):

    pivot test on d = X[(k, k)] against cmax_k = max |J| over the column's entries;
    X[(k, k)] = 1 / d; l_i = X[(i, k)] / d for L(:, k) (as a product with 1 / d);
    X[(i, j)] -= l_i u_j for every i of L(:, k) and j of U(k, :) (u_j = X[(k, j)])

Every entry receives the same products, subtracted in the same order (k ascending), as in the
runtime's left-looking loop, so both give the same factors bit for bit (the loop skips a zero
multiplier, this code subtracts its zero product: at most the sign of a zero differs). The
right-looking order has no chain of dependent updates inside a pivot (its products are
independent), where the left-looking column is a triangular solve, one update after another.

Pivots whose code is the same up to positions that advance by a constant from one to the next
(the bodies and joints of a chain or a tree, eliminated one like the next) are emitted once,
as the body of a C loop; the rest is straight-line code. The code's length then grows with
the number of distinct pivots, not with N.
"""
from __future__ import annotations

from dataclasses import dataclass

from .static_lu import StaticLU

#: the longest run period (pivots) looked for; a chain's body with its joints is 12
MAX_PERIOD = 64
#: above this many multiply-adds in the emitted code (after the loops) the runtime's loop is
#: kept: the compile time grows with the code (GCC -Og: about 0.2 s per 1000 on a loaded
#: 2-core machine), the run time of the factorization does not shrink with it
MAX_EMITTED_OPS = 8000
#: multiply-adds per generated function
CHUNK_OPS = 600


@dataclass(frozen=True)
class Pivot:
    """Pivot k's work in absolute storage positions: diag ((k, k)), lower (L(:, k), rows
    ascending), upper (U(k, :), columns ascending), ops ((target, a, b): X[target] -=
    l_a u_b, a index into lower, b into upper)."""
    k: int
    diag: int
    lower: tuple
    upper: tuple
    ops: tuple

    @property
    def shape(self):
        """What must agree for two pivots to share code (their positions may differ)."""
        return (len(self.lower), len(self.upper), tuple((a, b) for _, a, b in self.ops))

    def positions(self) -> list[int]:
        return [self.k, self.diag, *self.lower, *self.upper, *(t for t, _, _ in self.ops)]


def pivots(lu: StaticLU) -> list[Pivot]:
    """The right-looking elimination's work per pivot."""
    n = len(lu.perm)
    where, upper = {}, [[] for _ in range(n)]
    for j in range(n):
        for q in range(lu.colptr[j], lu.colptr[j + 1]):
            where[lu.row[q], j] = q
            if q < lu.diag[j]:
                upper[lu.row[q]].append((j, q))      # U(k, j), columns ascending
    out = []
    for k in range(n):
        lo = range(lu.diag[k] + 1, lu.colptr[k + 1])
        ops = tuple((where[lu.row[qi], j], a, b) for a, qi in enumerate(lo)
                    for b, (j, _) in enumerate(upper[k]))
        out.append(Pivot(k, lu.diag[k], tuple(lo), tuple(q for _, q in upper[k]), ops))
    return out


def _block(steps, t, p):
    return [q for st in steps[t:t + p] for q in st.positions()]


def runs(steps: list[Pivot], max_period: int = MAX_PERIOD,
         loop_cost: int = 16) -> list[tuple[int, int, int]]:
    """(start, period, repeats) covering the pivots with the least emitted code: blocks of
    ``period`` pivots repeated (at least twice) with the same shapes and every position
    advancing by its own constant from one repeat to the next (an affine function of the
    repeat), else single pivots (period 1, repeats 1). The cost of a plan is its emitted
    multiply-adds plus ``loop_cost`` per loop (dynamic programming from the end)."""
    n = len(steps)
    ids: dict = {}
    shape = [ids.setdefault(st.shape, len(ids)) for st in steps]
    pos = [st.positions() for st in steps]
    ops = [len(st.ops) + 1 for st in steps]
    acc = [0]
    for c in ops:
        acc.append(acc[-1] + c)
    # reach[p][t]: the most repeats of the block of p pivots at t
    reach = {}
    for p in range(1, min(max_period, n // 2) + 1):
        same = [shape[s] == shape[s + p] for s in range(n - p)]
        if not any(same):
            continue
        affine = [s + 2 * p < n and same[s] and same[s + p]
                  and all(c - b == b - a for a, b, c in zip(pos[s], pos[s + p], pos[s + 2 * p]))
                  for s in range(n - p)]
        # per residue class mod p, consecutive counts along s, s + p, ...
        r_same, r_aff = [0] * (n + p), [0] * (n + p)
        for s in range(n - p - 1, -1, -1):
            r_same[s] = r_same[s + p] + 1 if same[s] else 0
            r_aff[s] = r_aff[s + p] + 1 if affine[s] else 0
        row = [1] * n
        for t in range(n - 2 * p + 1):
            # repeats m need, for every s in [t, t + p): same along m - 1 and affine along
            # m - 2 steps of p from s
            ms = min(r_same[s] for s in range(t, t + p)) + 1
            ma = min(r_aff[s] for s in range(t, t + p)) + 2
            row[t] = min(ms, ma, (n - t) // p)
        reach[p] = row
    best = [0] * (n + 1)
    choice: list = [None] * n
    for t in range(n - 1, -1, -1):
        best[t], choice[t] = ops[t] + best[t + 1], (1, 1)
        for p, row in reach.items():
            if row[t] < 2:
                continue
            code = acc[t + p] - acc[t] + loop_cost
            for m in range(2, row[t] + 1):
                if code + best[t + m * p] < best[t]:
                    best[t], choice[t] = code + best[t + m * p], (p, m)
    out, t = [], 0
    while t < n:
        p, m = choice[t]
        out.append((t, p, m))
        t += p * m
    return out


def _pivot_code(st: Pivot, ptr) -> list[str]:
    """C lines of one pivot, l and u in local variables; ptr(k) names the pointer that the
    k-th of st.positions() is indexed from (pointers X, cm and their shifted copies)."""
    nl, nu = len(st.lower), len(st.upper)
    lines = ["{", f"const double d = {ptr(1, 'X')}[{st.diag}];",
             f"if (!(fabs(d) > HPGEN_STATIC_PIVOT_TOL * {ptr(0, 'cm')}[{st.k}]) || !isfinite(d))"
             " return 1;", "r = 1.0 / d;", f"{ptr(1, 'X')}[{st.diag}] = r;"]
    if st.ops:
        lines.append("double " + ", ".join(
            [f"l{a} = {ptr(2 + a, 'X')}[{q}] * r" for a, q in enumerate(st.lower)]
            + [f"u{b} = {ptr(2 + nl + b, 'X')}[{q}]" for b, q in enumerate(st.upper)]) + ";")
        lines += [f"{ptr(2 + a, 'X')}[{q}] = l{a};" for a, q in enumerate(st.lower)]
    else:
        lines += [f"{ptr(2 + a, 'X')}[{q}] *= r;" for a, q in enumerate(st.lower)]
    lines += [f"{ptr(2 + nl + nu + e, 'X')}[{t}] -= l{a} * u{b};"
              for e, (t, a, b) in enumerate(st.ops)]
    return lines + ["}", "HPGEN_SLU_BARRIER;"]


def _run_code(steps, t, p, m) -> list[str]:
    if m == 1:
        return [f"/* pivot {t} */"] + _pivot_code(steps[t], lambda k, base: base)
    b0, b1 = _block(steps, t, p), _block(steps, t + p, p)
    step = [y - x for x, y in zip(b0, b1)]
    names: dict = {}
    off = 0
    for j in range(p):
        for k in range(len(steps[t + j].positions())):
            names.setdefault(("cm" if k == 0 else "X", step[off + k]), None)
        off += len(steps[t + j].positions())
    names = {key: f"{key[0]}{q}" for q, key in enumerate(sorted(names))}
    body = [f"{'const ' if base == 'cm' else ''}double* {v} = {base} + {s} * i;"
            for (base, s), v in names.items()]
    off = 0
    for j in range(p):
        st = steps[t + j]
        body += _pivot_code(st, lambda k, base, o=off: names[base, step[o + k]])
        off += len(st.positions())
    return ([f"for (i = 0; i < {m}; ++i) {{     /* pivots {t} + {p} i + (0..{p - 1}) */"]
            + ["    " + s for s in body] + ["}"])


def factor_code(lu: StaticLU, chunk: int = CHUNK_OPS) -> str | None:
    """C definitions ending with ``static int hpgen_slu_numeric(double* X, const double* cm)``
    (X: J's values scattered into the filled pattern, zeros at the fill; cm[k]: the pivot
    test's scale of pivot k; returns 1 on a failed pivot), or None when the code would
    exceed MAX_EMITTED_OPS multiply-adds. The pivots are cut into functions of about
    ``chunk`` multiply-adds each, called in turn (a compiler's time grows faster than the
    length of one function)."""
    steps = pivots(lu)
    plan = runs(steps)
    emitted = sum(len(steps[t + j].ops) for t, p, _ in plan for j in range(p))
    if emitted > MAX_EMITTED_OPS:
        return None
    parts: list[list] = [[]]
    size = 0
    for run in plan:
        ops = sum(len(steps[run[0] + j].ops) for j in range(run[1]))
        if size and size + ops > chunk:
            parts.append([])
            size = 0
        parts[-1].append(run)
        size += ops
    out = []
    for q, part in enumerate(parts):
        lines = ["double r;", "int i = 0;"]
        for run in part:
            lines += _run_code(steps, *run)
        lines += ["(void)i; (void)r;", "return 0;"]
        out.append(f"static int hpgen_slu_part{q}(double* X, const double* cm) {{\n"
                   + "\n".join("    " + s for s in lines) + "\n}\n")
    calls = " ||\n        ".join(f"hpgen_slu_part{q}(X, cm)" for q in range(len(parts)))
    out.append("static int hpgen_slu_numeric(double* X, const double* cm) {\n"
               f"    return {calls};\n}}\n")
    return "\n".join(out)


def fill_positions(lu: StaticLU) -> list[int]:
    """The storage positions that are not a nonzero of J (zeroed before each factorization)."""
    taken = set(lu.jmap)
    return [q for q in range(lu.nnz) if q not in taken]
