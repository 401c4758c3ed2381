"""The ``work`` record of a forced model: the work done by the forces since the start of a run,
accumulated from the node power (docs/numerics.md, "Work and the energy balance").

The compiled record row evaluates the forces' power P_j = <f(g_j, xi_j, t_j, u), xi_j> at
every node (hpgen.derive.records; u the input of the step that ends at node j). The work at
node k is Gregory's end-corrected trapezoid rule on the nodes 0..k,

    W_k = h (P_0/2 + P_1 + ... + P_{k-1} + P_k/2)
          - h sum_{m=1}^{r} gamma_m (nabla^m P_k + (-1)^m Delta^m P_0),   r = min(4, k),

gamma = (1/12, 1/24, 19/720, 3/160), nabla / Delta the backward / forward differences: exact
for polynomials of degree 5, error O(h^6) for a power smooth in t (k >= 4); W_1..W_3 are the
integrals of the polynomial through P_0..P_4 (START: exact for degree 4), so the first five
nodes must be fed together (a run of fewer than 5 nodes keeps the r = min(4, k) rule there).
It is cumulative (each node needs the first five and the last five powers), so chunks of a
run give bitwise the whole run's values, and so does a run continued from a saved
``WorkSum.state``. The error is below the order of every shipped scheme
(<= 6): energy - work is the conserved balance to the scheme's order. A control input u that
jumps between steps makes the power jump: the rule is then first order at each jump.
numpy and the standard library only.
"""
from __future__ import annotations

from math import comb

import numpy as np

#: Gregory's coefficients gamma_1..gamma_4
GREGORY = (1.0 / 12.0, 1.0 / 24.0, 19.0 / 720.0, 3.0 / 160.0)
R = len(GREGORY)
#: W_k = h sum_i START[k][i] P_i / 720 for k = 1..3: the integral over [0, k h] of the
#: polynomial through P_0..P_4 (exact for degree 4)
START = ((251, 646, -264, 106, -19), (232, 992, 192, 32, -8), (243, 918, 648, 378, -27))


class WorkSum:
    """Running W_k from the powers P_0, P_1, ... fed in order (``add``)."""

    def __init__(self, h: float):
        self.h = float(h)
        self.k = -1              # the last node fed
        self.s = 0.0             # P_0 + ... + P_k
        self.head: list = []     # P_0 .. P_R
        self.tail = np.zeros(0)  # the last R powers fed

    def add(self, power) -> np.ndarray:
        """W at the next len(power) nodes, from their powers (N,)."""
        P = np.asarray(power, dtype=np.float64).ravel()
        N = len(P)
        if N == 0:
            return np.zeros(0)
        ks = self.k + 1 + np.arange(N)
        self.head.extend(P[:R + 1 - len(self.head)].tolist())
        S = np.cumsum(np.concatenate([[self.s], P]))[1:]      # sequential: chunk-free
        W = S - 0.5 * (self.head[0] + P)
        allp = np.concatenate([self.tail, P])
        pos = len(self.tail) + np.arange(N)
        corr = np.zeros(N)
        for m, gamma in enumerate(GREGORY, start=1):
            ok = ks >= m
            if not ok.any():
                break
            back = np.diff(allp, m)[pos[ok] - m]                   # nabla^m P_k
            fwd = sum((-1) ** (m - i) * comb(m, i) * self.head[i] for i in range(m + 1))
            corr[ok] += gamma * (back + (-1) ** m * fwd)
        out = self.h * W - self.h * corr
        if len(self.head) == R + 1:               # nodes 1..3: the start rule
            for j in np.flatnonzero((ks >= 1) & (ks <= R - 1)):
                w = START[ks[j] - 1]
                out[j] = self.h * sum(w[i] * self.head[i] for i in range(R + 1)) / 720.0
        self.k += N
        self.s = float(S[-1])
        self.tail = allp[-R:].copy()
        return out

    def state(self) -> dict:
        """What continues the sum bitwise (``restore``): the last node k, the running sum
        and the first and last powers fed, as arrays."""
        return {"k": np.array(self.k, dtype=np.int64), "s": np.array(self.s),
                "head": np.array(self.head, dtype=np.float64), "tail": self.tail.copy()}

    @classmethod
    def restore(cls, h: float, state: dict) -> "WorkSum":
        """The WorkSum ``state`` (WorkSum.state) holds, for step h."""
        acc = cls(h)
        acc.k, acc.s = int(state["k"]), float(state["s"])
        acc.head = [float(v) for v in np.asarray(state["head"], dtype=np.float64)]
        acc.tail = np.array(state["tail"], dtype=np.float64)
        return acc


def work_offset(meta) -> int | None:
    """The column of ``work`` in a forced module's record row (meta.json "record"), or None
    (an unforced module's ``work`` is a user expression)."""
    if not (meta.get("open") or {}).get("forced"):
        return None
    for name, off, _ in meta["record"]:
        if name == "work":
            return off
    return None


def fill_work(rows, col: int, acc: WorkSum) -> None:
    """Replace column ``col`` of record rows taken at consecutive nodes (every step), which
    holds the node power there, by the accumulated work (in place)."""
    if len(rows):
        rows[:, col] = acc.add(rows[:, col])
