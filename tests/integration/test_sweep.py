"""hpgen.sweep on local threads: bitwise equal to simulate_batch / record_batch, failed members
marked with their partial samples, the saved files (.npz, .zarr, .nc), the grid file and
``hpgen sweep`` (errors, interruption and --resume), the module shipped to workers (content
hash), and the local path with none of the scale extra installed.

Every comparison is bitwise: a sweep runs the same C batch loop on the same inputs, whatever
its chunking or thread count (each member is an independent run).
"""
from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import hpgen
from conftest import EXAMPLES, ROOT
from hpgen.ensemble import remote
from hpgen.ensemble.result import SweepResult
from hpgen.errors import ArgumentError, BuildError, ModelError

W0 = np.array([0.2, 1.0, 3.0]) + 0.05 * np.arange(18).reshape(6, 3)
H = 0.1


@pytest.fixture(scope="module")
def body(compile_model):
    """The free rigid body (Stormer-Verlet, Cayley): record row g, mu, energy, momentum."""
    return compile_model(EXAMPLES / "free_rigid_body.yaml")


def _equal(a, b):
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True)


@pytest.mark.parametrize("chunk_size,threads", [(None, None), (2, 2), (4, 1)])
def test_states_bitwise_simulate_batch(body, chunk_size, threads):
    res = hpgen.sweep(body, xi0=W0, h=H, steps=60, every=7, chunk_size=chunk_size,
                      threads=threads, progress=False)
    ref = body.simulate_batch(np.eye(3), H, 60, xi0=W0, every=7)
    assert res.names == ("g", "mu") and len(res) == len(W0)
    for i, r in enumerate(ref):
        assert _equal(res["g"][i], r.g) and _equal(res["mu"][i], r.mu)
        assert _equal(res.t[i], r.t)
        assert res.newton_iterations[i] == r.newton_iterations
    assert not res.failed.any() and (res.samples == 60 // 7 + 1).all()


def test_records_bitwise_record_batch_with_h_per_member(body):
    h = np.array([0.1, 0.05, 0.1, 0.2, 0.05, 0.1])
    res = hpgen.sweep(body, mu0=W0, h=h, steps=40, every=3, record=["energy", "momentum"],
                      chunk_size=4, progress=False)
    assert res.names == ("energy", "momentum")
    for i in range(len(W0)):
        r = body.record_batch(np.eye(3), h[i], 40, mu0=W0[i:i + 1], every=3)[0]
        assert _equal(res["energy"][i], r["energy"])
        assert _equal(res["momentum"][i], r["momentum"])
        assert _equal(res.t[i], r.t)


def test_failed_member_is_marked_and_others_complete(body):
    # h = 1.5 takes the Cayley map out of its domain at the first step of member 2 only
    h = np.array([0.1, 0.1, 1.5, 0.1])
    res = hpgen.sweep(body, xi0=W0[:4], h=h, steps=30, every=5, record=["energy"],
                      chunk_size=2, progress=False)
    assert res.failed.tolist() == [False, False, True, False]
    assert "outside the chart map tau's domain" in res.error[2] and res.error[0] == ""
    assert res.samples[2] == 1 and res.steps_done[2] == 0
    ref = body.record_batch(np.eye(3), 1.5, 30, xi0=W0[2:3], every=5)[0]
    assert ref.error is not None and str(ref.error) == res.error[2]
    assert _equal(res["energy"][2, :1], ref["energy"])           # the partial samples
    assert np.isnan(res["energy"][2, 1:]).all()                   # and nothing after them
    ok = body.record_batch(np.eye(3), 0.1, 30, xi0=W0[[0, 1, 3]], every=5)
    for i, r in zip((0, 1, 3), ok):
        assert _equal(res["energy"][i], r["energy"])


def test_bad_inputs_are_one_line_model_errors(body):
    cases = [(dict(xi0=W0, mu0=W0), "exactly one"), (dict(xi0=W0[:, :2]), "shape"),
             (dict(xi0=W0, h=[0.1, 0.2]), "one per member"),
             (dict(xi0=W0, h=0.0), "non-zero"), (dict(xi0=W0, record=["height"]), "record row"),
             (dict(xi0=W0, g0=2 * np.eye(3)), "member 0"),
             (dict(xi0=W0, params={"c": [1.0] * 6}), "runtime_parameters")]
    for kw, text in cases:
        kw = {"h": H, "steps": 5, **kw}
        # ModelError, or ArgumentError (a ValueError) from the runtime's shared checks
        with pytest.raises((ModelError, ArgumentError), match=text) as e:
            hpgen.sweep(body, progress=False, **kw)
        assert "\n" not in str(e.value)


def test_save_npz_zarr_nc_round_trip(body, tmp_path):
    xr = pytest.importorskip("xarray")
    res = hpgen.sweep(body, xi0=W0[:3], h=np.array([0.1, 1.5, 0.1]), steps=20, every=4,
                      record=["energy", "g"], progress=False)
    ds = res.to_xarray()
    assert ds["g"].dims == ("member", "time", "row", "col")
    assert ds["energy"].dims == ("member", "time")
    assert ds["failed"].values.tolist() == [False, True, False]
    with np.load(res.save(tmp_path / "s.npz"), allow_pickle=False) as z:
        assert _equal(z["energy"], res["energy"]) and _equal(z["g"], res["g"])
        assert z["error"].tolist() == res.error.tolist()
    pytest.importorskip("zarr")
    for name, opener in (("s.zarr", xr.open_zarr), ("s.nc", xr.open_dataset)):
        with opener(res.save(tmp_path / name)) as back:
            back = back.load()
        assert back.equals(ds), name                 # values, dims, coordinates; bitwise
        assert back.attrs["hash"] == body.meta["hash"]
    with pytest.raises(ModelError, match="ending in"):
        res.save(tmp_path / "s.csv")


def test_checkpoint_reuses_completed_chunks(body, tmp_path, monkeypatch):
    from hpgen.ensemble import sweep as sweep_mod
    kw = dict(xi0=W0, h=H, steps=25, every=5, chunk_size=2, progress=False,
              checkpoint=tmp_path / "parts")
    full = hpgen.sweep(body, **kw)
    assert sorted(p.name for p in (tmp_path / "parts").glob("chunk-*.npz")) == \
        ["chunk-0-2.npz", "chunk-2-4.npz", "chunk-4-6.npz"]
    ran = []
    real = sweep_mod.run_chunk
    monkeypatch.setattr(sweep_mod, "run_chunk", lambda i, m, lo, *a: ran.append(lo) or
                        real(i, m, lo, *a))
    (tmp_path / "parts" / "chunk-2-4.npz").write_bytes(b"truncated")   # damaged: redone
    again = hpgen.sweep(body, **kw)
    assert ran == [2]
    for name in full.names:
        assert _equal(again[name], full[name])
    with pytest.raises(ModelError, match="different sweep"):
        hpgen.sweep(body, **{**kw, "steps": 30})


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "hpgen", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)


GRID = """\
xi0: [[0.2, 1.0, 3.0], [0.25, 1.0, 3.0], [0.3, 1.0, 3.0], [0.35, 1.0, 3.0], [0.4, 1.0, 3.0]]
h: [0.1, 0.1, 0.05, 1.5, 0.1]
steps: 40
every: 4
record: [energy, momentum]
chunk_size: 2
"""


def test_cli_interrupt_then_resume(body, tmp_path, monkeypatch, capsys, cache_dir):
    from hpgen import cli
    from hpgen.ensemble import sweep as sweep_mod
    grid = tmp_path / "grid.yaml"
    grid.write_text(GRID)
    out = tmp_path / "s.npz"
    base = [str(EXAMPLES / "free_rigid_body.yaml"), "--grid", str(grid), "--out", str(out),
            "--cache-dir", str(cache_dir), "--no-progress"]
    real, ran = sweep_mod.run_chunk, []

    def interrupted(integ, m, lo, *a):
        if lo == 2:
            raise KeyboardInterrupt
        ran.append(lo)
        return real(integ, m, lo, *a)

    monkeypatch.setattr(sweep_mod, "run_chunk", interrupted)
    assert cli.main(["sweep", *base]) == 130
    assert "--resume" in capsys.readouterr().err and not out.exists()
    parts = tmp_path / "s.npz.parts"
    assert [p.name for p in parts.glob("chunk-*.npz")] == ["chunk-0-2.npz"]
    assert cli.main(["sweep", *base]) == 2                      # parts there, no --resume
    assert "--resume" in capsys.readouterr().err
    monkeypatch.setattr(sweep_mod, "run_chunk", lambda i, m, lo, *a: ran.append(lo) or
                        real(i, m, lo, *a))
    assert cli.main(["sweep", *base, "--resume"]) == 0
    assert ran == [0, 2, 4] and not parts.exists()              # chunk 0 was not run again
    assert "1 failed" in capsys.readouterr().out
    ref = hpgen.sweep(body, xi0=[[0.2, 1.0, 3.0], [0.25, 1.0, 3.0], [0.3, 1.0, 3.0],
                                   [0.35, 1.0, 3.0], [0.4, 1.0, 3.0]],
                      h=np.array([0.1, 0.1, 0.05, 1.5, 0.1]), steps=40, every=4,
                      record=["energy", "momentum"], progress=False)
    with np.load(out, allow_pickle=False) as z:
        for name in ("energy", "momentum", "failed", "samples", "h"):
            assert _equal(z[name], getattr(ref, name, None) if name in
                          ("failed", "samples", "h") else ref[name]), name


@pytest.mark.parametrize("text,where", [
    ("xi0: [[1, 2]]\n", "grid.yaml:1: xi0[0]: expected a list of 3 numbers"),
    ("mu0: [[1, 2, 3]]\nxi0: [[1, 2, 3]]\n", "grid.yaml:2: xi0: give exactly one of xi0"),
    ("xi0: [[1, 2, 3]]\nh: [0.1, 0.2]\n", "grid.yaml:2: h: expected one value per member"),
    ("xi0: [[1, 2, 3]]\nsteps: 1.5\n", "grid.yaml:2: steps: expected an integer"),
    ("xi0: [[1, 2, 3]]\nh: !!python/object/apply:os.system [ls]\n", "is not allowed"),
    ("xi0: [[1, 2, 3]]\nrecord: [height]\n", "grid.yaml: record: 'height' is not in"),
    ("xi0: [[1, 2, 3]]\nparams: {c: [0.5]}\n", "params sweeps need runtime_parameters"),
    ("xi0: [[1, 2, 3]]\nseed: 3\n", "grid.yaml:2: seed: unknown key"),
])
def test_cli_grid_errors_exit_2(tmp_path, text, where, cache_dir):
    (tmp_path / "grid.yaml").write_text(text)
    p = _cli("sweep", EXAMPLES / "free_rigid_body.yaml", "--grid", tmp_path / "grid.yaml",
             "--out", tmp_path / "s.npz", "--cache-dir", cache_dir)
    assert p.returncode == 2, p.stderr
    assert where in p.stderr and p.stderr.count("\n") == 1 and "Traceback" not in p.stderr
    assert not (tmp_path / "s.npz").exists()


def test_module_payload_checked_before_use(body, tmp_path):
    payload = remote.payload_of(body)
    assert [n for n, _ in payload.files] == ["meta.json", "kernels.c"]
    entry = remote.install(payload, tmp_path)
    assert entry == tmp_path / remote.SUBDIR / payload.digest
    (entry / "kernels.c").write_text("int damaged;")          # a damaged entry is rewritten
    assert remote.install(payload, tmp_path) == entry
    assert (entry / "kernels.c").read_bytes() == dict(payload.files)["kernels.c"]
    bad = remote.ModulePayload(payload.digest, (("meta.json", b"{}"), payload.files[1]))
    with pytest.raises(BuildError, match="content hash"):
        remote.install(bad, tmp_path / "other")
    assert not (tmp_path / "other" / remote.SUBDIR / payload.digest).exists()
    res = remote.run_task(payload, hpgen.ensemble.members.members(body, np.eye(3), W0[:2],
                          None, H), 0, 10, 2, None, 1, tmp_path)
    ref = body.simulate_batch(np.eye(3), H, 10, xi0=W0[:2], every=2)
    assert all(_equal(res["arrays"]["mu"][i], r.mu) for i, r in enumerate(ref))


def test_local_path_without_the_scale_extra(tmp_path, cache_dir):
    """dask, distributed, xarray, zarr and tqdm blocked: the local sweep and .npz still work,
    .zarr is a one-line ModelError naming the extra."""
    script = textwrap.dedent(f"""
        import sys
        class Block:
            def find_spec(self, name, path=None, target=None):
                if name.split(".")[0] in ("dask", "distributed", "xarray", "zarr", "tqdm"):
                    raise ImportError("blocked " + name)
        sys.meta_path.insert(0, Block())
        import numpy as np, hpgen
        from hpgen.errors import ModelError
        integ = hpgen.compile({str(EXAMPLES / 'free_rigid_body.yaml')!r},
                              cache_dir={str(cache_dir)!r})
        res = hpgen.sweep(integ, xi0=np.ones((3, 3)), h=0.1, steps=5, progress=True)
        res.save({str(tmp_path / 's.npz')!r})
        try:
            res.save({str(tmp_path / 's.zarr')!r})
        except ModelError as e:
            print(e)
        print(sorted(m for m in sys.modules
                     if m.split(".")[0] in ("dask", "distributed", "xarray", "zarr", "tqdm")))
    """)
    p = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True,
                       text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stdout.splitlines() == ["out: xarray is not installed; install the scale extra: "
                                     "pip install 'hpgen[scale]'", "[]"]
    assert (tmp_path / "s.npz").exists() and not (tmp_path / "s.zarr").exists()


def test_progress_bar_only_when_asked(body, capsys, monkeypatch):
    pytest.importorskip("tqdm")
    hpgen.sweep(body, xi0=W0, h=H, steps=5, progress=False)
    body.simulate_batch(np.eye(3), H, 5, xi0=W0)                 # stderr not a terminal
    assert capsys.readouterr().err == ""
    hpgen.sweep(body, xi0=W0, h=H, steps=5, progress=True, chunk_size=2)
    body.simulate_batch(np.eye(3), H, 5, xi0=W0, progress=True, threads=2)
    err = capsys.readouterr().err
    assert "sweep:" in err and "simulate_batch:" in err and "0/6 [" in err
    # the bars count every member once
    from hpgen.ensemble import sweep as sweep_mod
    from hpgen.runtime import progress, states
    counts = []

    def counting(total, desc, unit, wanted=None):
        if wanted is False:                       # the batches inside a sweep's chunks
            return progress._NoBar()
        entry = [desc, total, 0]
        counts.append(entry)

        class Bar(progress._NoBar):
            def update(self, n=1):
                entry[2] += n
        return Bar()

    monkeypatch.setattr(sweep_mod, "progress_bar", counting)
    monkeypatch.setattr(states, "progress_bar", counting)
    hpgen.sweep(body, xi0=W0, h=H, steps=5, chunk_size=4)
    body.simulate_batch(np.eye(3), H, 5, xi0=W0, threads=2)
    assert counts == [["sweep", 6, 6], ["simulate_batch", 6, 6]]


def test_result_type(body):
    res = hpgen.sweep(body, xi0=W0[:2], h=H, steps=4, progress=False)
    assert isinstance(res, SweepResult) and res.attrs["module"] == body.meta["module"]


def test_run_progress_bar_keeps_the_file(body, tmp_path, capsys):
    """record_to_npz (hpgen run) with its bar on gives the same file as without."""
    pytest.importorskip("tqdm")
    from hpgen.runtime.chunked_output import record_to_npz
    kw = dict(g0=np.eye(3), h=H, steps=50, xi0=W0[0], every=5, chunk=20)
    a, _ = record_to_npz(body, tmp_path / "a.npz", progress=False, **kw)
    assert capsys.readouterr().err == ""
    b, _ = record_to_npz(body, tmp_path / "b.npz", progress=True, **kw)
    assert "run:" in capsys.readouterr().err
    with np.load(a) as za, np.load(b) as zb:
        assert za.files == zb.files and all(np.array_equal(za[k], zb[k]) for k in za.files)


DAMPED = """\
name: damped_body
group: SO3
parameters: {I: [1.0, 2.0, 3.0], c: 0.1}
runtime_parameters: [c]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)
forces: ["-c*xi[0]", "-c*xi[1]", "-c*xi[2]"]
scene:
  h: 0.1
  steps: 40
  initial: {g: identity, xi: [0.2, 1.0, 3.0]}
  record: [mu, energy]
"""


def test_params_sweep_bitwise_one_at_a_time(compile_model, tmp_path):
    """params={"c": C}: member i runs with c = C[i] (one compile), chunked or not, bitwise the
    one-at-a-time record / simulate; a value per member is required."""
    path = tmp_path / "damped_body.yaml"
    path.write_text(DAMPED)
    integ = compile_model(path)
    C = np.linspace(0.0, 0.5, 6)
    res = hpgen.sweep(integ, xi0=W0, h=H, steps=40, every=5, chunk_size=4, threads=2,
                      params={"c": C}, record=["mu", "energy"], progress=False)
    states = hpgen.sweep(integ, xi0=W0, h=H, steps=40, every=5, params={"c": C},
                         progress=False)
    for i in range(6):
        one = integ.record(np.eye(3), H, 40, xi0=W0[i], every=5, params={"c": C[i]})
        assert _equal(res["mu"][i], one["mu"]) and _equal(res["energy"][i], one["energy"])
        sim = integ.simulate(np.eye(3), H, 40, xi0=W0[i], every=5, params={"c": C[i]})
        assert _equal(states["mu"][i], sim.mu) and _equal(states["g"][i], sim.g)
    assert res["energy"][5, -1] < 0.5 * res["energy"][0, -1]      # more damping, less energy
    for bad, text in (({"c": C[:3]}, r"params.c: expected shape \(6,\)"),
                      ({"k": C}, "unknown runtime parameter 'k'")):
        with pytest.raises(ModelError, match=text):
            hpgen.sweep(integ, xi0=W0, h=H, steps=4, params=bad, progress=False)
