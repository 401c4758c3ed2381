"""Sweeps whose results keep their meaning: members failing at their start or zero steps on a
model that records work, the grid's shared runtime parameters, the swept values as
coordinates of the member dimension in every saved form, and the checkpoint's parts checked
on load (member range, fingerprint, shapes) and locked against a second sweep.
"""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import hpgen
from conftest import EXAMPLES, ROOT
from hpgen.errors import ModelError

DAMPED = EXAMPLES / "damped_top.yaml"
XI = np.array([0.2, 1.0, 3.0]) + 0.05 * np.arange(24).reshape(8, 3)
H = 0.05


@pytest.fixture(scope="module")
def top(compile_model):
    """The damped heavy top (runtime parameter c; record row with energy and work)."""
    return compile_model(DAMPED)


def _equal(a, b):
    return np.shape(a) == np.shape(b) and np.array_equal(a, b, equal_nan=True)


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "hpgen", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)


def test_member_failing_at_its_start_with_work_recorded(top):
    xi = XI.copy()
    xi[3] = [0.2, 1.0, 300.0]                    # its Newton start is outside the chart
    C = np.linspace(0.0, 0.35, 8)
    res = hpgen.sweep(top, xi0=xi, h=H, steps=30, every=5, chunk_size=3, params={"c": C},
                      record=["energy", "work"], progress=False)
    assert res.failed.tolist() == [i == 3 for i in range(8)]
    assert res.samples[3] == 1 and np.isnan(res["energy"][3, 1:]).all()   # its start kept
    E0 = 0.5 * (1.0 * 0.2**2 + 5.0 * 1.0**2 + 6.0 * 300.0**2) + 1.0   # at g0 = I: V = Mg R22
    assert res["energy"][3, 0] == pytest.approx(E0, rel=1e-14)
    assert "step 0" in res.error[3]
    for i in (0, 4, 7):
        one = top.record(np.eye(3), H, 30, xi0=xi[i], every=5, params={"c": C[i]})
        assert _equal(res["energy"][i], one["energy"]) and _equal(res["work"][i], one["work"])


def test_zero_steps_with_work_recorded(top):
    res = hpgen.sweep(top, xi0=XI[:3], h=H, steps=0, record=["energy", "work"],
                      progress=False)
    assert res["energy"].shape == (3, 1) and not res.failed.any()
    assert res["work"][:, 0].tolist() == [0.0, 0.0, 0.0]
    one = top.record(np.eye(3), H, 0, xi0=XI[0])
    assert _equal(res["energy"][0], one["energy"])


def test_cli_grid_shared_parameter_zero_steps_and_a_failing_member(tmp_path, cache_dir):
    rows = [[0.2 + 0.01 * i, 1.0, 3.0] for i in range(6)]
    rows[2] = [0.2, 1.0, 300.0]
    grid = tmp_path / "grid.yaml"
    grid.write_text(f"xi0: {rows}\nsteps: 20\nchunk_size: 2\nparams: {{c: 0.1}}\n")
    out = tmp_path / "s.npz"
    p = _cli("sweep", DAMPED, "--grid", grid, "--out", out, "--cache-dir", cache_dir,
             "--no-progress")
    assert p.returncode == 0, p.stderr
    assert "1 failed" in p.stdout and "member 2: step 0" in p.stdout
    with np.load(out, allow_pickle=False) as z:
        assert z["c"].tolist() == [0.1] * 6 and z["failed"].tolist() == [i == 2 for i in range(6)]
    grid.write_text("xi0: [[0.2, 1, 3], [0.3, 1, 3]]\nsteps: 0\n")
    p = _cli("sweep", DAMPED, "--grid", grid, "--out", out, "--cache-dir", cache_dir,
             "--no-progress")
    assert p.returncode == 0 and "0 failed" in p.stdout, p.stderr
    for text, msg in (('params: {c: "x"}', "params.c: expected a number (shared by all "
                                           "members) or a list of 2 values"),
                      ('params: {c: ["0.1", 0.2]}', "params.c[0]: expected a number, got the "
                                                    "string '0.1'")):
        grid.write_text(f"xi0: [[0.2, 1, 3], [0.3, 1, 3]]\nsteps: 2\n{text}\n")
        p = _cli("sweep", DAMPED, "--grid", grid, "--out", tmp_path / "t.npz",
                 "--cache-dir", cache_dir)
        assert p.returncode == 2 and msg in p.stderr and p.stderr.count("\n") == 1, p.stderr


def test_shared_parameter_equals_per_member_values(top, tmp_path):
    from hpgen.ensemble.grid import read_grid
    path = tmp_path / "g.yaml"
    path.write_text("xi0: [[0.2, 1, 3], [0.3, 1, 3], [0.4, 1, 3]]\nparams: {c: 0.25}\n")
    assert read_grid(path, 3, 3)["params"] == {"c": [0.25, 0.25, 0.25]}
    path.write_text("xi0: [[0.2, 1, 3]]\nparams: {c: true}\n")
    with pytest.raises(ModelError, match="params.c: expected a number"):
        read_grid(path, 3, 3)


def test_swept_values_are_coordinates_of_the_member_dimension(top, tmp_path):
    from hpgen.ensemble.result import load
    C = np.linspace(0.0, 0.3, 4)
    res = hpgen.sweep(top, xi0=XI[:4], h=np.array([0.05, 0.05, 0.025, 0.05]), steps=20,
                      every=5, params={"c": C}, record=["energy", "work"], progress=False)
    assert _equal(res.params["c"], C)
    with np.load(res.save(tmp_path / "s.npz"), allow_pickle=False) as z:
        assert _equal(z["c"], C) and _equal(z["xi0"], XI[:4])
        assert dict(zip(z["attrs_keys"].tolist(), z["attrs_values"].tolist()))["params"] == "c"
    back = load(tmp_path / "s.npz")
    assert _equal(back.params["c"], C) and _equal(back["energy"], res["energy"])
    assert _equal(back.initial["xi0"], XI[:4]) and _equal(back.h, res.h)
    assert back.attrs["steps"] == 20 and back.names == res.names
    xr = pytest.importorskip("xarray")
    ds = res.to_xarray()
    for name, dims in (("c", ("member",)), ("h", ("member",)), ("xi0", ("member", "component")),
                       ("g0", ("member", "row", "col"))):
        assert name in ds.coords and ds[name].dims == dims, name
    assert _equal(ds.sel(member=ds.c > 0.15)["energy"].values, res["energy"][2:])
    pytest.importorskip("zarr")
    for name, opener in (("s.zarr", xr.open_zarr), ("s.nc", xr.open_dataset)):
        with opener(res.save(tmp_path / name)) as saved:
            assert saved.load().equals(ds), name
        again = load(tmp_path / name)
        assert _equal(again.params["c"], C) and _equal(again["work"], res["work"])


def test_a_parameter_named_like_a_record_gets_a_prefixed_coordinate(tmp_path):
    from hpgen.ensemble.result import SweepResult, load
    B = 2
    res = SweepResult(arrays={"k": np.zeros((B, 3))}, step=np.arange(3), h=np.full(B, 0.1),
                      failed=np.zeros(B, bool), error=np.array(["", ""]),
                      samples=np.full(B, 3), steps_done=np.full(B, 2),
                      newton_iterations=np.zeros(B, int),
                      initial={"g0": np.broadcast_to(np.eye(3), (B, 3, 3)),
                               "mu0": np.ones((B, 3))},
                      params={"k": np.array([1.0, 2.0]), "u": np.ones((B, 2))})
    assert res.coordinate_names() == {"k": "param_k", "u": "u"}
    back = load(res.save(tmp_path / "s.npz"))
    assert _equal(back.params["k"], [1.0, 2.0]) and _equal(back.params["u"], np.ones((B, 2)))
    assert _equal(back["k"], np.zeros((B, 3)))
    with pytest.raises(ModelError, match="not a saved hpgen sweep"):
        np.savez(tmp_path / "x.npz", t=np.arange(3))
        load(tmp_path / "x.npz")


GRID = """\
xi0: {xi}
params: {{c: {c}}}
steps: 30
every: 5
record: [energy, work, momentum]
chunk_size: 4
"""


def _grid(tmp_path):
    C = np.linspace(0.0, 0.35, 12)
    xi = np.vstack([XI, XI[:4] + 1.0])
    grid = tmp_path / "grid.yaml"
    grid.write_text(GRID.format(xi=xi.tolist(), c=C.tolist()))
    ref = dict(xi0=xi, h=H, steps=30, every=5, params={"c": C},
               record=["energy", "work", "momentum"])
    return grid, ref


def test_cli_resume_redoes_swapped_foreign_and_misshaped_parts(top, tmp_path, monkeypatch,
                                                                 capsys, cache_dir):
    from hpgen import cli
    from hpgen.ensemble import sweep as sweep_mod
    grid, ref_kw = _grid(tmp_path)
    out = tmp_path / "s.npz"
    base = ["sweep", str(DAMPED), "--grid", str(grid), "--out", str(out), "--cache-dir",
            str(cache_dir), "--no-progress"]
    real, ran = sweep_mod.run_chunk, []

    def interrupted(integ, m, lo, *a):
        if lo == 8:
            raise KeyboardInterrupt
        return real(integ, m, lo, *a)

    monkeypatch.setattr(sweep_mod, "run_chunk", interrupted)
    assert cli.main(base) == 130
    parts = tmp_path / "s.npz.parts"
    a, b = parts / "chunk-0-4.npz", parts / "chunk-4-8.npz"
    ab, bb = a.read_bytes(), b.read_bytes()
    a.write_bytes(bb)                                        # swapped on disk
    b.write_bytes(ab)
    monkeypatch.setattr(sweep_mod, "run_chunk", lambda i, m, lo, *r: ran.append(lo) or
                        real(i, m, lo, *r))
    capsys.readouterr()
    assert cli.main([*base, "--resume"]) == 0
    assert ran == [0, 4, 8]
    with np.load(out, allow_pickle=False) as z:
        g0 = z["g0"]                                  # the scene's initial attitude
        assert not np.allclose(g0[0], np.eye(3))
        ref = hpgen.sweep(top, g0=g0, progress=False, **ref_kw)
        for name in ("energy", "work", "momentum"):
            assert _equal(z[name], ref[name]), name
        assert _equal(z["newton_iterations"], ref.newton_iterations)
        assert _equal(z["c"], ref_kw["params"]["c"])

    # a valid .npz of the wrong shapes, and a part of another sweep: redone, same result
    monkeypatch.setattr(sweep_mod, "run_chunk", interrupted)
    assert cli.main(base) == 130
    with np.load(a) as z:
        good = {k: z[k] for k in z.files}
    np.savez(a, **{**good, "a:energy": good["a:energy"][:, :3]})
    np.savez(b, **{**good, "part_range": np.array([4, 8]), "fingerprint": np.str_("0" * 64)})
    ran.clear()
    monkeypatch.setattr(sweep_mod, "run_chunk", lambda i, m, lo, *r: ran.append(lo) or
                        real(i, m, lo, *r))
    assert cli.main([*base, "--resume"]) == 0
    assert ran == [0, 4, 8] and not parts.exists()
    with np.load(out, allow_pickle=False) as z:
        assert _equal(z["energy"], ref["energy"]) and _equal(z["work"], ref["work"])


def test_a_sweep_on_locked_parts_is_refused_in_one_line(top, tmp_path, cache_dir):
    grid, _ = _grid(tmp_path)
    out = tmp_path / "s.npz"
    parts = tmp_path / "s.npz.parts"
    holder = subprocess.Popen(                           # a sweep still running on the parts
        [sys.executable, "-c", "import sys; from hpgen.ensemble.parts import Checkpoint; "
         f"c = Checkpoint({str(parts)!r}, 'f' * 64); print('held', flush=True); "
         "sys.stdin.read()"], cwd=ROOT, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
        text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        for extra in (["--resume"], []):
            p = _cli("sweep", DAMPED, "--grid", grid, "--out", out, "--cache-dir", cache_dir,
                     "--no-progress", *extra)
            assert p.returncode == 2 and p.stderr.count("\n") == 1, p.stderr
            assert "s.npz.parts: another hpgen sweep is using this folder" in p.stderr
        assert not out.exists()
        with pytest.raises(ModelError, match="another hpgen sweep"):
            hpgen.sweep(top, xi0=XI[:2], h=H, steps=2, checkpoint=parts, progress=False)
    finally:
        holder.communicate("")
    p = _cli("sweep", DAMPED, "--grid", grid, "--out", out, "--cache-dir", cache_dir,
             "--no-progress", "--resume")
    assert p.returncode == 2 and "different sweep" in p.stderr, p.stderr   # its fingerprint


def test_the_lock_is_shared_within_a_process(top, tmp_path):
    from hpgen.ensemble import parts
    kw = dict(xi0=XI[:4], h=H, steps=10, chunk_size=2, progress=False,
              checkpoint=tmp_path / "parts")
    first = hpgen.sweep(top, **kw)
    assert not parts._HELD                              # released when the sweep returns
    key = parts._lock(tmp_path / "parts")               # held on, as by a kept traceback
    again = hpgen.sweep(top, **kw)                      # the same process: not locked out
    assert _equal(again["mu"], first["mu"]) and parts._HELD[key][1] == 1
    parts._unlock(key)
    assert not parts._HELD
