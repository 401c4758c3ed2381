"""The run loop's predictor (hpgen_run_step of hpgen/runtime/c/hpgen_runs.c,
hpgen.runtime.loop._run_step): the Newton start of step k is G_k + the polynomial extrapolation
of the offsets dz_j = z_j - G_j of the last m = min(k, 6) solutions (quintic once six exist),
G_j = guess(velocity_step(g_j, p_j, 0), g_j, p_j, h).

Checked on the Python backend (bitwise the C backend's runs: tests/unit/test_newton_python.py
compares whole runs, iteration counts included): the start Newton receives is that formula,
bitwise, and on a smooth run (heavy top, Gauss 2 and 3, Cayley, exact) it is closer to the
solution than the extrapolation of z itself (the predictor of ABI 4) and than the quadratic
through three offsets (that of ABI 5). (Not its residual's
inf-norm: the rows of F scale differently, |F| at the new start is about that at the old.)
The margin asked (half the old distance; measured 11x smaller
for Gauss 2 at h = 0.05, 5x for Gauss 3 at h = 0.1) follows from dz = O(h) being
a smooth function of t_k carrying what z's extrapolation error has beyond G's exact p_k and
velocity.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import HEAVY_TOP
from hpgen.runtime import loop, newton
from reference import rotvec


def _starts_and_solutions(integ, h, steps):
    """[(Newton start of step k, solution z_k, G_k)] of a Python-backend run, step by step
    through hpgen.runtime.loop.advance; the start is the first z a residual kernel receives."""
    b = integ.engine.backend
    kern = b._newton
    g0, xi0 = rotvec([0.3, 0.2, 0.0]), [0.2, 1.0, 3.0]
    gf = np.asarray(g0, dtype=float).ravel(order="F")
    p0 = integ.kernel("legendre", gf, xi0)[0]
    z0 = integ.kernel("guess", xi0, gf, p0, [h])[0]
    run = b.start(gf, p0, z0)
    first = []
    saved = kern.residual, kern.residual_jacobian, kern.iterate, kern.iterate_full

    def spy(f):
        def wrapped(*a):
            if not first:
                first.append(list(a[0]))
            return f(*a)
        return wrapped
    # the fused iterates (ITERATE, the same arithmetic) would not show their z: off here
    kern.residual, kern.residual_jacobian = spy(saved[0]), spy(saved[1])
    kern.iterate = kern.iterate_full = None
    out = []
    try:
        for _ in range(steps):
            first.clear()
            G = loop.predictor_base(kern, run.g, run.p, [h], False)
            done, _, st = loop.advance(kern, run, h, 1, 1,
                                       newton.NewtonOptions(simplified=True))
            assert done == 1, st
            out.append((np.array(first[0]), np.array(run.z), np.array(G)))
    finally:
        kern.residual, kern.residual_jacobian, kern.iterate, kern.iterate_full = saved
    return out


@pytest.mark.parametrize("tableau,h", [("gauss2", 0.05), ("gauss3", 0.1)])
def test_predictor_is_the_start_and_beats_z_extrapolation(compile_model, tableau, h):
    integ = compile_model(HEAVY_TOP, tableau=tableau, tau="cay", rkmk="exact",
                          backend="python")
    rows = _starts_and_solutions(integ, h, 60)
    starts = [r[0] for r in rows]
    z = [r[1] for r in rows]
    G = [r[2] for r in rows]
    dz = [a - b for a, b in zip(z, G)]
    new_err, old_err, quad_err = [], [], []
    for k in range(1, len(rows)):
        # the start of step k, bitwise the formula: t = c_0 dz_{k-1}, t += c_i dz_{k-1-i},
        # c_i = (-1)^i binomial(m, i + 1) over the m = min(k, 6) newest offsets, start G_k + t
        m = min(k, 6)
        t = float(m) * dz[k - 1]
        for i in range(1, m):
            t = t + float((-1) ** i * math.comb(m, i + 1)) * dz[k - 1 - i]
        assert np.array_equal(starts[k], G[k] + t), k
        if k >= 6:
            old = 3.0 * (z[k - 1] - z[k - 2]) + z[k - 3]
            quad = G[k] + (3.0 * (dz[k - 1] - dz[k - 2]) + dz[k - 3])
            new_err.append(np.abs(starts[k] - z[k]).max())
            old_err.append(np.abs(old - z[k]).max())
            quad_err.append(np.abs(quad - z[k]).max())
    for ref in (old_err, quad_err):
        assert max(new_err) < 0.5 * max(ref)
        assert np.median(new_err) < 0.5 * np.median(ref)
