"""The symbolic analysis of the sparse Newton matrix's LU with a static pivot order, at compile
time (the numeric factorization is hpgen/runtime/c/hpgen_linalg.c's hpgen_slu_factor).

P J P^T = L U with one permutation P of the unknowns (diagonal pivots, no pivoting at run
time). The order is Markowitz's on the structure with fill: at each step the pivot of least
(|L column| |U row|), ties by index, among the unknowns whose diagonal is structurally
nonzero, where an unknown whose diagonal in J is structurally zero (a constraint multiplier:
RATTLE's rows C dz = ..., its column the force B) is eligible only once every unknown it is
coupled to is eliminated: its pivot is then the complete Schur complement -(C A^{-1} B)_kk of
the bodies it joins, not a partial one that may vanish at a configuration. For chains and
trees the order eliminates the bodies from the leaves inwards with their joints, and L + U
stay O(nz).

The filled pattern (that of L + U in the new numbering) is stored as compressed columns with
ascending rows, the diagonal's position of each column, and for every structural nonzero of J
(column-major, the kernels' order) its position in that storage. The run-time pivot test and
the fallback to the QR for a J on which a static pivot fails are the runtime's.
"""
from __future__ import annotations

import heapq
from dataclasses import dataclass


@dataclass(frozen=True)
class StaticLU:
    """perm[t]: the unknown eliminated at step t (P); colptr (n + 1), row: the filled pattern
    in the new numbering, compressed columns with ascending rows; diag[t]: the index of
    (t, t) in row; jmap[p]: the index of J's nonzero p (CCS order) in row."""
    perm: tuple
    colptr: tuple
    row: tuple
    diag: tuple
    jmap: tuple

    @property
    def nnz(self) -> int:
        return len(self.row)


def static_lu(n: int, colind, row) -> StaticLU | None:
    """The analysis for the n x n pattern (colind, row) (CCS), or None when no static order
    exists (an unknown whose diagonal never fills in: no diagonal pivot for it)."""
    rows = [set() for _ in range(n)]
    cols = [set() for _ in range(n)]
    entries = []
    for c in range(n):
        for r in row[colind[c]:colind[c + 1]]:
            rows[r].add(c)
            cols[c].add(r)
            entries.append((r, c))
    waits = {k: (rows[k] | cols[k]) - {k} for k in range(n) if k not in rows[k]}
    waiting = [0] * n                          # of unknown k: its waits not yet eliminated
    waiters: list[list[int]] = [[] for _ in range(n)]
    for k, ws in waits.items():
        waiting[k] = len(ws)
        for w in ws:
            waiters[w].append(k)

    def cost(v):
        return (len(rows[v]) - 1) * (len(cols[v]) - 1)

    # the ready unknowns by (cost, index); an entry whose cost has changed since it was
    # pushed (its newer entry is in the heap too) or whose unknown is gone is skipped
    heap = [(cost(k), k) for k in range(n) if k in rows[k] and not waiting[k]]
    heapq.heapify(heap)
    alive, perm, steps = [True] * n, [], []
    while heap:
        c, k = heapq.heappop(heap)
        if not alive[k] or c != cost(k):
            continue
        lower, upper = cols[k] - {k}, rows[k] - {k}
        perm.append(k)
        steps.append((lower, upper))
        for i in lower:
            rows[i] |= upper
            rows[i].discard(k)
        for j in upper:
            cols[j] |= lower
            cols[j].discard(k)
        alive[k] = False
        for w in waiters[k]:
            waiting[w] -= 1
        for v in lower | upper | set(waiters[k]):
            if alive[v] and v in rows[v] and not waiting[v]:
                heapq.heappush(heap, (cost(v), v))
    if len(perm) < n:
        return None
    pos = {v: t for t, v in enumerate(perm)}
    columns = [[t] for t in range(n)]                  # rows of column t, new numbering
    for t, (lower, upper) in enumerate(steps):
        columns[t] += [pos[i] for i in lower]          # L(:, t)
        for j in upper:
            columns[pos[j]].append(t)                  # U(t, :)
    colptr, flat, diag = [0], [], []
    for t in range(n):
        rs = sorted(columns[t])
        diag.append(len(flat) + rs.index(t))
        flat += rs
        colptr.append(len(flat))
    where = {(r, t): colptr[t] + i for t in range(n)
             for i, r in enumerate(flat[colptr[t]:colptr[t + 1]])}
    jmap = tuple(where[pos[r], pos[c]] for r, c in entries)
    return StaticLU(tuple(perm), tuple(colptr), tuple(flat), tuple(diag), jmap)


def flops(lu: StaticLU) -> int:
    """Multiply-adds x 2 of one numeric factorization (left-looking: every U(k, j) above the
    diagonal applies column k of L), plus one multiplication per entry of L."""
    n = len(lu.perm)
    lower = [lu.colptr[k + 1] - lu.diag[k] - 1 for k in range(n)]
    total = 0
    for j in range(n):
        for q in range(lu.colptr[j], lu.diag[j]):
            total += 2 * lower[lu.row[q]]
        total += lower[j]
    return total
