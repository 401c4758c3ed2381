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
re-solved and is bitwise that of the build without the guard. The count (``guarded``,
hpgen.runtime.counters) reaches the Trajectory, the saved file, a resumed run, the ensemble's
members and sweep arrays, and ``hpgen run``'s summary.
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


# ---- the count in the results (hpgen.runtime.counters) --------------------------------------

OPTS = NewtonOptions(abi.DEFAULT_TOL, abi.DEFAULT_MAXIT, False, True)   # as _started's


def _rows_of(integ):
    """The function giving a (non-composed) snapshot's (6, nz) offsets to rewrite."""
    eng = integ.engine
    if integ.backend == "c":
        return lambda s: _c_rows(s, eng.nz, eng.n, eng.d)
    return lambda s: s["dz"]


@pytest.mark.parametrize("backend", ["c", "python"])
def test_count_reaches_the_trajectory_and_its_saved_file(backend, tmp_path):
    """10 more steps of a run whose history was rewritten after 10, through the states
    output: Trajectory.guarded 1 (in its repr), saved and read back; the same without the
    rewrite: 0, its states those of the guarded run to Newton's tolerance."""
    from hpgen.plot_read import load_npz
    from hpgen.runtime.counters import read
    from hpgen.runtime.engine import RunArgs
    from hpgen.runtime.states import States
    integ = _integ(backend)
    b, run, _ = _started(integ)
    eng, snap = integ.engine, b.snapshot(run)
    s = eng.prepare(RunArgs(np.eye(2), H, 20, xi0=[0.2], newton=OPTS))
    trajs = []
    for state in (_misleading(snap, _rows_of(integ)), snap):
        out = States(eng, s, 100)
        [(k, first, part)] = list(eng.parts(out, s, eng.restore(state)))
        trajs.append(out.trajectory(k, first, part, 0.0))
    bad, ref = trajs
    assert (bad.guarded, ref.guarded) == (1, 0) and "guarded=1" in repr(bad)
    assert bad.newton_iterations > ref.newton_iterations        # the second solve's
    assert np.abs(bad.mu - ref.mu).max() <= 1e-12
    with np.load(bad.save(tmp_path / "run.npz")) as f:
        assert int(f["guarded"]) == 1 and int(f["newton_iterations"]) == bad.newton_iterations
        old = {k: f[k] for k in f.files if k != "guarded"}     # a file of an older hpgen
    np.savez(tmp_path / "old.npz", **old)
    data = load_npz(tmp_path / "old.npz")
    assert read(data)["guarded"] == 0 and read(data)["newton_iterations"] == bad.newton_iterations
    assert read(load_npz(tmp_path / "run.npz"))["guarded"] == 1


def test_count_in_a_netcdf_file(tmp_path):
    pytest.importorskip("xarray")
    pytest.importorskip("scipy")
    from hpgen.plot_read import load_labelled
    from hpgen.runtime.trajectory import Trajectory
    tr = Trajectory(t=np.zeros(2), g=np.zeros((2, 2, 2)), mu=np.zeros((2, 1)), h=H, every=1,
                    newton_iterations=7, guarded=3)
    data = load_labelled(tr.save(tmp_path / "run.nc"))
    assert int(data["guarded"]) == 3 and int(data["newton_iterations"]) == 7


@pytest.mark.parametrize("backend", ["c", "python"])
def test_count_of_a_resumed_run_is_the_sum(backend, tmp_path, monkeypatch):
    """record_to_npz interrupted after its second chunk (step 10), whose committed run state
    has the rewritten history: the resumed run's first step is re-solved; the file and the
    summary count it, with the Newton iterations of both runs; an uninterrupted run counts
    0."""
    from hpgen.runtime.chunked_output import record_to_npz
    from hpgen.runtime.partial_run import PartialFolder
    integ = _integ(backend)
    kw = dict(g0=np.eye(2), h=H, steps=20, xi0=[0.2], chunk=5, newton=OPTS)
    ref, ref_summary = record_to_npz(integ, tmp_path / "ref", **kw)
    commit, rows = PartialFolder.commit, _rows_of(integ)

    def misleading_commit(self, prog, rec, snapshot, work=None):
        if prog.chunks < 2:
            return commit(self, prog, rec, snapshot, work)
        commit(self, prog, rec, _misleading(snapshot, rows), work)
        raise KeyboardInterrupt

    monkeypatch.setattr(PartialFolder, "commit", misleading_commit)
    with pytest.raises(KeyboardInterrupt) as info:
        record_to_npz(integ, tmp_path / "run", **kw)
    monkeypatch.undo()
    with np.load(info.value.saved[0]) as f:
        first = int(f["newton_iterations"])
        assert int(f["guarded"]) == 0 and bool(f["partial"])
    path, summary = record_to_npz(integ, tmp_path / "run", resume=True, **kw)
    assert summary["resumed_at"] == 10 and (summary["guarded"], ref_summary["guarded"]) == (1, 0)
    with np.load(path) as f, np.load(ref) as r:
        assert int(f["guarded"]) == 1 and int(r["guarded"]) == 0
        assert int(f["newton_iterations"]) == summary["newton_iterations"] > first
        assert summary["newton_iterations"] > int(r["newton_iterations"])
        assert np.abs(f["mu"] - r["mu"]).max() <= 1e-12


def test_count_of_ensemble_members():
    """The lanes' statuses (lane 1 re-solved) into the members' Trajectories
    (batch_trajectories), a sweep's per-member arrays (run_chunk's store, concat), a saved
    sweep and a checkpoint part read back; a sweep saved without the counter reads 0."""
    import ctypes
    import tempfile
    from pathlib import Path

    from hpgen.ensemble import chunk as sweep_chunk
    from hpgen.ensemble.parts import Checkpoint
    from hpgen.ensemble.result import concat, load
    from hpgen.runtime.cstructs import _Options, _Status
    from hpgen.runtime.states import batch_trajectories
    integ = _integ("c")
    b, run, opts = _started(integ)
    eng = integ.engine
    L, size, nn = b.lanes, b.run_size, eng.n * eng.n
    snap = b.snapshot(run)
    bad = _misleading(snap, _rows_of(integ))["run"]
    buf = np.concatenate([bad if lane == 1 else snap["run"] for lane in range(L)])
    buf = buf.astype(np.uint8)
    g_rec, p_rec = np.zeros((L, 2, nn)), np.zeros((L, 2, eng.d))
    g_rec[:, 0], p_rec[:, 0] = b.state(run)[0], b.state(run)[1]
    sts = (_Status * L)()
    failed = b.lib.hpgen_advance_batch_lanes(buf.ctypes.data, L, H, 1, 1,
                                             ctypes.byref(_Options.of(opts)), 2,
                                             g_rec[:, 1:].ctypes.data, p_rec[:, 1:].ctypes.data,
                                             sts)
    assert failed == 0 and size
    sts = np.ctypeslib.as_array(sts)
    expect = [int(lane == 1) for lane in range(L)]
    members = batch_trajectories(eng, sts["step"].copy(), g_rec, p_rec, sts, H, 1)
    assert [m.guarded for m in members] == expect
    assert [members[j].guarded for j in range(L)] == expect          # one by one
    out = {"arrays": {"mu": np.zeros((L, 2, eng.d))}, "failed": np.zeros(L, dtype=bool),
           "error": np.full(L, "", dtype=object), "samples": np.zeros(L, dtype=np.int64),
           "steps_done": np.zeros(L, dtype=np.int64), "newton_iterations": np.zeros(L, int),
           "guarded": np.zeros(L, int)}
    for i, m in enumerate(members):
        sweep_chunk._store(out, i, m, ("mu",), 1)
    out["error"] = out["error"].astype(str)
    assert out["guarded"].tolist() == expect
    res = concat([out], np.arange(2), np.full(L, H), {"g0": np.zeros((L, 2, 2)),
                                                       "xi0": np.zeros((L, 1))}, {})
    assert res.guarded.tolist() == expect
    assert res.newton_iterations.tolist() == [m.newton_iterations for m in members]
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        assert load(res.save(d / "sweep.npz")).guarded.tolist() == expect
        with np.load(d / "sweep.npz") as f:                   # a sweep of an older hpgen
            np.savez(d / "old.npz", **{k: f[k] for k in f.files if k != "guarded"})
        assert load(d / "old.npz").guarded.tolist() == [0] * L
        cp = Checkpoint(d / "parts", "fp")
        cp.save((0, L), out)
        assert cp.load([(0, L)])[(0, L)]["guarded"].tolist() == expect
        with np.load(cp.path((0, L))) as f:                   # a part of an older hpgen
            np.savez(cp.path((0, L)), **{k: f[k] for k in f.files if k != "guarded"})
        assert cp.load([(0, L)])[(0, L)]["guarded"].tolist() == [0] * L
        cp.close()


@pytest.mark.parametrize("backend", ["c", "python"])
def test_a_normal_run_counts_zero(backend, tmp_path):
    """simulate (C: its fast path), record, record_to_npz and (C) simulate_batch report the
    count, 0 on the trajectory's own offsets."""
    from hpgen.runtime.chunked_output import record_to_npz
    integ = _integ(backend)
    kw = dict(g0=np.eye(2), h=H, steps=200, xi0=[0.2])
    tr, rec = integ.simulate(**kw), integ.record(**kw)
    assert tr.guarded == 0 and rec.guarded == 0 and tr.newton_iterations > 0
    path, summary = record_to_npz(integ, tmp_path / "run", chunk=50, **kw)
    with np.load(path) as f:
        assert int(f["guarded"]) == 0 == summary["guarded"]
    if backend == "c":
        members = integ.simulate_batch(np.eye(2), H, 200, xi0=[[0.2], [0.3]])
        assert [m.guarded for m in members] == [0, 0]


def test_counters_of_a_c_status():
    """simulate's fast path reads the counters from the ctypes status itself."""
    from hpgen.runtime.counters import of_status
    from hpgen.runtime.cstructs import _Status
    st = _Status()
    st.total_iterations, st.guarded = 12, 2
    assert of_status(st) == {"newton_iterations": 12, "guarded": 2} == of_status(st.as_dict())


def test_hpgen_run_says_how_many_steps_were_re_solved(tmp_path, cache_dir, capsys,
                                                      monkeypatch):
    """The summary's line only when the count is > 0 (the count faked: no shipped scene
    meets another root)."""
    from conftest import EXAMPLES
    from hpgen.cli import main
    from hpgen.runtime import chunked_output
    real = chunked_output.record_to_npz

    def counted(*a, **k):
        path, summary = real(*a, **k)
        return path, {**summary, "guarded": 2}

    argv = ["run", str(EXAMPLES / "free_rigid_body.yaml"), "--out", str(tmp_path / "r.npz"),
            "--steps", "20", "--no-plot", "--no-progress", "--cache-dir", str(cache_dir)]
    assert main(argv) == 0
    assert "wrong-root guard" not in capsys.readouterr().out
    monkeypatch.setattr(chunked_output, "record_to_npz", counted)
    assert main(argv) == 0
    assert "\n  2 steps re-solved by the wrong-root guard" in capsys.readouterr().out


@pytest.mark.parametrize("backend", ["c", "python"])
def test_count_reaches_section_crossings(backend):
    from hpgen.runtime.engine import RunArgs
    from hpgen.runtime.sections import Crossings
    scene = {"h": H, "steps": 20, "initial": {"g": "identity", "xi": [0.2]}, "section": "mu[0]"}
    integ = hpgen.compile({**MODEL, "scene": scene}, backend=backend)
    b, run, _ = _started(integ)
    snap, eng = b.snapshot(run), integ.engine
    s = eng.prepare(RunArgs(np.eye(2), H, 80, xi0=[0.2], newton=OPTS))
    bad, ref = (Crossings(eng, s, None, 100).run(eng.restore(state))
                for state in (_misleading(snap, _rows_of(integ)), snap))
    assert (bad.guarded, ref.guarded) == (1, 0) and len(bad) == len(ref) >= 1
