"""C code of the static LU's numeric factorization (hpgen.codegen.static_lu), generated at
compile time: every multiply-add of the left-looking elimination with its storage positions
as constants, instead of the runtime's loop over the index arrays (hpgen_slu_factor in
hpgen/runtime/c/hpgen_linalg.c), whose indirect scatters into a dense work column cost most
of its time.

Column t of the filled pattern (storage X, compressed columns, 1 / u_tt on the diagonal):

    cmax = max |X[q]| over the column (J's entries and zeros at the fill)
    for k in the column's U part, ascending: X[at(t, r)] -= X[s] X[at(t, k)] for the
        entries s of L(:, k) (row r)
    pivot test on d = X[diag]; X[diag] = 1 / d; the L part scaled by 1 / d

which is the runtime loop's arithmetic operation for operation (the same products and
differences in the same order; the loop skips a zero multiplier, this code subtracts its zero
product, which changes at most the sign of a zero), so both give the same factors bit for bit.

Columns whose code is the same up to a shift of all their positions by the same amount (the
bodies and joints of a chain or a tree, eliminated one like the next) are emitted once, as the
body of a C loop over a base pointer; the rest is straight-line code. The code's length then
grows with the number of distinct columns, not with N.
"""
from __future__ import annotations

from dataclasses import dataclass

from .static_lu import StaticLU

#: the longest run period (columns) looked for; a chain's body with its joints is 12
MAX_PERIOD = 64
#: above this many multiply-adds in the emitted code (after the loops) the runtime's loop is
#: kept: straight-line code of that size costs more in compile time and instruction cache
#: than it saves
MAX_EMITTED_OPS = 12000


@dataclass(frozen=True)
class Column:
    """Column t's work in absolute storage positions: c0 (first entry), size (entries),
    diag (position of the diagonal), ops ((target, l, u): X[target] -= X[l] * X[u])."""
    c0: int
    size: int
    diag: int
    ops: tuple

    @property
    def shape(self):
        """What must agree for two columns to share code (their positions may differ)."""
        return (self.size, self.diag - self.c0, len(self.ops))

    def positions(self) -> list[int]:
        return [self.c0, self.diag] + [q for op in self.ops for q in op]


def columns(lu: StaticLU) -> list[Column]:
    """The left-looking elimination's work per column."""
    n = len(lu.perm)
    out = []
    for t in range(n):
        c0, c1, dt = lu.colptr[t], lu.colptr[t + 1], lu.diag[t]
        at = {lu.row[q]: q for q in range(c0, c1)}
        ops = []
        for q in range(c0, dt):
            k = lu.row[q]
            for s in range(lu.diag[k] + 1, lu.colptr[k + 1]):
                ops.append((at[lu.row[s]], s, q))
        out.append(Column(c0, c1 - c0, dt, tuple(ops)))
    return out


def _block(cols, t, p):
    return [q for col in cols[t:t + p] for q in col.positions()]


def runs(cols: list[Column], max_period: int = MAX_PERIOD) -> list[tuple[int, int, int]]:
    """(start, period, repeats) covering the columns: blocks of ``period`` columns repeated
    (at least twice) with the same shapes and every position advancing by its own constant
    from one repeat to the next (an affine function of the repeat), else single columns
    (period 1, repeats 1). Greedy from the left, the longest cover first, the shortest period
    among equal covers."""
    n, t, out = len(cols), 0, []
    shapes = [c.shape for c in cols]
    while t < n:
        best = (1, 1)
        for p in range(1, min(max_period, (n - t) // 2) + 1):
            if shapes[t + p:t + 2 * p] != shapes[t:t + p]:
                continue
            b0, b1 = _block(cols, t, p), _block(cols, t + p, p)
            step = [y - x for x, y in zip(b0, b1)]
            m, prev = 2, b1
            while t + (m + 1) * p <= n and shapes[t + m * p:t + (m + 1) * p] == shapes[t:t + p]:
                nxt = _block(cols, t + m * p, p)
                if any(y - x != s for x, y, s in zip(prev, nxt, step)):
                    break
                m, prev = m + 1, nxt
            if m * p > best[0] * best[1]:
                best = (p, m)
        out.append((t, *best))
        t += best[0] * best[1]
    return out


def _column_code(col: Column, ptr) -> list[str]:
    """C lines of one column, its entries in local variables v<k> (entry c0 + k) from load to
    store; ptr(k) names the pointer that the k-th of col.positions() is indexed from (the
    column's own entries share the first's, its c0)."""
    c0, n = col.c0, col.size
    base = ptr(0)

    def mine(q):
        return f"v{q - c0}"
    lines = ["{", "double " + ", ".join(f"v{k} = {base}[{c0 + k}]" for k in range(n)) + ";",
             "cmax = 0.0;"]
    lines += [f"cmax = fabs(v{k}) > cmax ? fabs(v{k}) : cmax;" for k in range(n)]
    lines += [f"{mine(a)} -= {ptr(3 + 3 * e)}[{b}] * {mine(c)};"
              for e, (a, b, c) in enumerate(col.ops)]
    dk = col.diag - c0
    lines += [f"if (!(fabs(v{dk}) > HPGEN_STATIC_PIVOT_TOL * cmax) || !isfinite(v{dk})) return 1;",
              f"r = 1.0 / v{dk};"]
    lines += [f"{base}[{c0 + k}] = v{k};" for k in range(dk)]
    lines += [f"{base}[{col.diag}] = r;"]
    lines += [f"{base}[{c0 + k}] = v{k} * r;" for k in range(dk + 1, n)]
    return lines + ["}"]


def factor_code(lu: StaticLU) -> str | None:
    """The body of ``static int hpgen_slu_numeric(double* X)`` (X: J's values scattered into
    the filled pattern, zeros at the fill; returns 1 on a failed pivot), or None when the
    code would exceed MAX_EMITTED_OPS multiply-adds."""
    cols = columns(lu)
    plan = runs(cols)
    emitted = sum(len(cols[t + j].ops) for t, p, _ in plan for j in range(p))
    if emitted > MAX_EMITTED_OPS:
        return None
    lines = ["double cmax, r;", "int i;"]
    for t, p, m in plan:
        if m == 1:
            lines.append(f"/* column {t} */")
            lines += _column_code(cols[t], lambda k: "X")
            continue
        b0, b1 = _block(cols, t, p), _block(cols, t + p, p)
        step = [y - x for x, y in zip(b0, b1)]
        names = {s: f"P{k}" for k, s in enumerate(sorted(set(step)))}
        lines.append(f"for (i = 0; i < {m}; ++i) {{     /* columns {t} + {p} i + (0..{p - 1}) */")
        body = [f"double* {v} = X + {s} * i;" for s, v in names.items()]
        off = 0
        for j in range(p):
            col = cols[t + j]
            body += _column_code(col, lambda k, o=off: names[step[o + k]])
            off += len(col.positions())
        lines += ["    " + s for s in body]
        lines.append("}")
    lines.append("(void)i;")
    lines.append("return 0;")
    return "\n".join("    " + s for s in lines)


def fill_positions(lu: StaticLU) -> list[int]:
    """The storage positions that are not a nonzero of J (zeroed before each factorization)."""
    taken = set(lu.jmap)
    return [q for q in range(lu.nnz) if q not in taken]
