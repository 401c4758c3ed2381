"""The guard on an accepted step (hpgen_runs.c hpgen_guard_ratio / hpgen_guard_resolve,
hpgen.runtime.guard; docs/numerics.md sec. 8): a step whose root's offset z - G jumps away
from the run's offsets is solved again from G, and the root nearer the offsets taken.

The model: a particle on R1 with l = xi^2/2 - xi^4/4 - x^2/2, whose Legendre map
xi - xi^3 is not monotone, so that the SV step has three roots (xi_{k+1/2} near 0.09, 0.95
and -1.04 at h = 0.1 from xi_0 = 0.2); Newton from G (0.10) finds the trajectory's, from
G + 0.8 the one near 0.95. A run's predictor history is rewritten (the run's snapshot) so
that the quintic extrapolation lands at G + 0.8 while the newest offset stays the run's: the
run with the guard continues on the trajectory's root (that of the same run without the
rewrite, to Newton's tolerance), the run without it (C built with
-DHPGEN_GUARD_RATIO=1e300; Python with loop.GUARD_RATIO = inf) takes the other. The same in
a composed run (suzuki4), whose substeps keep their own offsets, and in the lanes (a lane
over the ratio is handed to the scalar step). A run without a rewritten history is not
re-solved and is bitwise that of the build without the guard.
"""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen import abi
from hpgen.runtime import loop
from hpgen.runtime.newton import NewtonOptions

MODEL = {"name": "guard_two_roots", "group": "R1", "parameters": {"b": 1.0},
         "lagrangian": "0.5*xi[0]**2 - 0.25*b*xi[0]**4 - 0.5*x[0]**2"}
H = 0.1
#: the extrapolated start's distance from G, inside the other root's basin
SHIFT = 0.8
OFF = ["-DHPGEN_GUARD_RATIO=1e300"]


def _integ(backend, compose=None, cflags=None):
    extra = {"compose": compose, "rkmk": "truncated"} if compose else {}
    return hpgen.compile(MODEL, backend=backend, cflags=cflags, **extra)


def _started(integ, steps=10):
    """(backend, run after ``steps`` steps of full Newton with the predictor, options)."""
    eng = integ.engine
    b = eng.backend
    g0 = np.eye(2).ravel(order="F")
    p0 = np.asarray(eng.kernel("legendre", g0, [0.2])[0])
    z0 = eng.kernel("guess", [0.2], g0, p0, [H])[0]
    opts = NewtonOptions(abi.DEFAULT_TOL, abi.DEFAULT_MAXIT, False, True)
    run = b.start(g0, p0, z0)
    done, _, _, st = b.advance(run, H, steps, 1, opts)
    assert done == steps and st["guarded"] == 0
    return b, run, opts


def _misleading(snap, rows_of):
    """The snapshot with its offsets d_1 .. d_5 rewritten (rows_of(snap) -> the (6, nz) view
    to edit): d_1 = .. = d_4 = d_0, d_5 = 2 d_0 - SHIFT, so that the quintic's start
    G + 6 d_0 - 15 d_1 + 20 d_2 - 15 d_3 + 6 d_4 - d_5 = G + SHIFT (every entry)."""
    snap = {k: np.array(v) for k, v in snap.items()}
    d = rows_of(snap)
    assert d.shape == (abi.PREDICTOR_HISTORY, len(d[0]))
    d[1:5] = d[0]
    d[5] = 2.0 * d[0] - SHIFT
    return snap


def _c_rows(snap, nz, n, dim, known=None):
    """The C run's offsets: hpgen_run starts g[nn], p[d], z[nz], dz[6][nz]; known (a composed
    run: the Python twin's cdz[0], bitwise the C run's) located by its contents."""
    buf = snap["run"].view(np.float64)
    size = abi.PREDICTOR_HISTORY * nz
    if known is None:
        start = n * n + dim + nz
    else:
        flat = np.ascontiguousarray(known).ravel()
        hits = [i for i in range(buf.size - size + 1) if np.array_equal(buf[i:i + size], flat)]
        assert len(hits) == 1
        start = hits[0]
    return buf[start:start + size].reshape(-1, nz)


def _step_after_rewrite(integ, composed=False, known=None):
    """One step from a run of 10 steps with its history rewritten (a composed run: substep
    0's), and the same step without the rewrite: ((p, z) after it, (p, z) without the
    rewrite, status, status without the rewrite, the run's substep-0 offsets before)."""
    b, run, opts = _started(integ)
    eng = integ.engine
    snap = b.snapshot(run)
    if integ.backend == "c":
        def rows(s):
            return _c_rows(s, eng.nz, eng.n, eng.d, known)
    else:
        def rows(s):
            return s["cdz"][0] if composed else s["dz"]
    before = rows(snap).copy()
    bad = b.restore(_misleading(snap, rows))
    ref = b.restore(snap)
    _, _, _, st = b.advance(bad, H, 1, 1, opts)
    _, _, _, st_ref = b.advance(ref, H, 1, 1, opts)
    assert st["code"] == abi.OK and st_ref["code"] == abi.OK
    (_, p1, z1, _), (_, p_ref, z_ref, _) = b.state(bad), b.state(ref)
    return (p1, z1), (p_ref, z_ref), st, st_ref, before


@pytest.mark.parametrize("backend", ["c", "python"])
def test_guard_takes_the_trajectory_root(backend):
    (p1, z1), (p_ref, z_ref), st, st_ref, _ = _step_after_rewrite(_integ(backend))
    assert st["guarded"] == 1 and st_ref["guarded"] == 0
    # the root from G: the reference run's to Newton's tolerance (z ~ 0.1)
    assert np.abs(z1 - z_ref).max() <= 1e-13
    assert np.abs(p1 - p_ref).max() <= 1e-13


def test_without_the_guard_the_other_root_is_taken(monkeypatch):
    (p1, z1), (p_ref, z_ref), st, _, _ = _step_after_rewrite(_integ("c", cflags=OFF))
    assert st["guarded"] == 0
    assert np.abs(z1 - z_ref).max() > 0.5         # the root near 0.95, not near 0.09
    monkeypatch.setattr(loop, "GUARD_RATIO", float("inf"))
    (p1, z1), (p_ref, z_ref), st, _, _ = _step_after_rewrite(_integ("python"))
    assert st["guarded"] == 0
    assert np.abs(z1 - z_ref).max() > 0.5


def test_guarded_step_c_equals_python():
    """The guard's decision and its second solve: the same operations in C and Python
    (nz <= UNROLL_MAX: bitwise)."""
    c = _step_after_rewrite(_integ("c"))
    py = _step_after_rewrite(_integ("python"))
    assert np.array_equal(c[0][0], py[0][0]) and np.array_equal(c[0][1], py[0][1])
    assert c[2]["total_iterations"] == py[2]["total_iterations"]
    assert c[2]["jacobians"] == py[2]["jacobians"]


def test_composed_substep_guarded():
    """suzuki4: substep 0's own offsets rewritten; C and Python alike."""
    py = _step_after_rewrite(_integ("python", "suzuki4"), composed=True)
    c = _step_after_rewrite(_integ("c", "suzuki4"), composed=True, known=py[4])
    off = _step_after_rewrite(_integ("c", "suzuki4", OFF), composed=True, known=py[4])
    for (p1, z1), (p_ref, z_ref), st, st_ref, _ in (py, c):
        assert st["guarded"] == 1 and st_ref["guarded"] == 0
        assert np.abs(z1 - z_ref).max() <= 1e-13 and np.abs(p1 - p_ref).max() <= 1e-13
    assert off[2]["guarded"] == 0 and np.abs(off[0][0] - off[1][0]).max() > 1e-3


def test_normal_run_not_resolved_and_bitwise_unchanged():
    """1000 steps without a rewritten history: no re-solve, and the states are bitwise
    those of the build without the guard (C), and of the Python backend."""
    runs = {}
    for key, backend, flags in (("c", "c", None), ("off", "c", OFF), ("py", "python", None)):
        b, run, opts = _started(_integ(backend, cflags=flags))
        done, _, p_rec, st = b.advance(run, H, 1000, 10, opts)
        assert done == 1000 and st["code"] == abi.OK and st["guarded"] == 0
        runs[key] = p_rec
    assert np.array_equal(runs["c"], runs["off"])
    assert np.array_equal(runs["c"], runs["py"])


def test_lanes_hand_a_guarded_lane_to_the_scalar_step():
    """hpgen_advance_batch_lanes: L runs at the same step, lane 1's history rewritten; the
    lane over the ratio is stepped by the scalar code (its guard), the others in lanes: each
    run's state after the step is bitwise that of hpgen_advance on the same run."""
    import ctypes

    from hpgen.runtime.cstructs import _Options, _Status
    integ = _integ("c")
    b, run, opts = _started(integ)
    eng = integ.engine
    L, size = b.lanes, b.run_size
    snap = b.snapshot(run)
    bad = _misleading(snap, lambda s: _c_rows(s, eng.nz, eng.n, eng.d))["run"]
    raws = [bad if lane == 1 else snap["run"] for lane in range(L)]
    buf = np.concatenate(raws).astype(np.uint8)
    g_rec, p_rec = np.zeros((L, eng.n * eng.n)), np.zeros((L, eng.d))
    sts = (_Status * L)()
    o = _Options.of(opts)
    failed = b.lib.hpgen_advance_batch_lanes(buf.ctypes.data, L, H, 1, 1, ctypes.byref(o), 1,
                                             g_rec.ctypes.data, p_rec.ctypes.data, sts)
    assert failed == 0
    assert [sts[lane].guarded for lane in range(L)] == [int(lane == 1) for lane in range(L)]
    for lane, raw in enumerate(raws):
        one = b.restore({"run": raw})
        _, _, p1, st = b.advance(one, H, 1, 1, opts)
        assert np.array_equal(p_rec[lane], p1[0]) and st["guarded"] == int(lane == 1)
        lane_state = b.restore({"run": buf[lane * size:(lane + 1) * size]})
        assert all(np.array_equal(x, y) for x, y in zip(b.state(lane_state), b.state(one)))
