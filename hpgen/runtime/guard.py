"""The guard on an accepted step of a run (hpgen/runtime/c/hpgen_runs.c: hpgen_guard_ratio,
hpgen_guard_resolve; docs/numerics.md sec. 8) in Python, the same operations: a step whose
root's offset z - G jumps away from the run's offsets (guard_ratio > abi.GUARD_RATIO) is
solved again from G, the start of a run without history, and the root nearer the offsets
taken. Used by hpgen.runtime.loop's run step. numpy-free: lists of Python floats.

The rule needs three offsets (the ratio's scale is their first and second difference), so a
run's first three steps are not guarded: step 0 starts from the guess kernel (no offset),
steps 1 and 2 are predicted from one and two offsets; from step 3 on every accepted step is
(in a composed run, each substep on its own offsets). The count of re-solved steps reaches
the results as ``guarded`` (hpgen.runtime.counters).
"""
from __future__ import annotations

from ..abi import GUARD_FLOOR, OK
from .newton import Kernels, NewtonMemory, NewtonOptions, step_lists


def guard_ratio(z, G, dz) -> float:
    """|(z - G) - dz_0| / (max(|dz_0 - dz_1|, |(dz_0 - dz_1) - (dz_1 - dz_2)|) + GUARD_FLOOR
    (1 + |z|)), inf-norms, like ``hpgen_guard_ratio`` in C (the same operations): the jump of
    a root's offset from the newest offset over the offsets' last change and its change."""
    jump = change = zn = 0.0
    for a, b, x, y, w in zip(z, G, dz[0], dz[1], dz[2]):
        u, v, c, m = abs((a - b) - x), abs(x - y), abs((x - y) - (y - w)), abs(a)
        if u > jump:
            jump = u
        if v > change:
            change = v
        if c > change:
            change = c
        if m > zn:
            zn = m
    return jump / (change + GUARD_FLOOR * (1.0 + zn))


def guard_jump(z, G, d0) -> float:
    """|(z - G) - d0|, inf-norm (guard_ratio's jump; ``hpgen_guard_jump`` in C)."""
    jump = 0.0
    for a, b, x in zip(z, G, d0):
        u = abs((a - b) - x)
        if u > jump:
            jump = u
    return jump


def guard_resolve(kern: Kernels, run, hv, full: NewtonOptions, G, found, st, with_g):
    """``hpgen_guard_resolve`` in C: the step whose root ``found`` = (g1, p1, z, it, r) failed
    the guard, solved again from G by full Newton with its own J; the second root replaces
    the first when its jump from the offsets is less than half the first's (then the kept
    J^{-1} is dropped). Both solves count in st (and st["guarded"]). Returns (g1, p1, z, it,
    r) of the root taken, it the iterations of both solves."""
    g1, p1, z1, it, r = found
    code, gb, pb, zb, itb, rb, jacs = step_lists(kern, run.g, run.p, hv, G, full,
                                                 NewtonMemory(), True, with_g)
    st["total_iterations"] += itb
    st["jacobians"] += jacs
    st["guarded"] += 1
    if code != OK or not 2.0 * guard_jump(zb, G, run.dz[0]) < guard_jump(z1, G, run.dz[0]):
        return g1, p1, z1, it + itb, r
    run.memory.lu = None
    return gb, pb, zb, it + itb, rb
