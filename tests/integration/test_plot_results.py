"""Figures that keep their meaning: a forced run's energy figure draws what the run's
summary reports (the energy-work balance E - W when work is recorded, the energy change
otherwise), a run's pose figure draws the attitude and position read from g by its group,
and a saved sweep (.npz, .nc) gives the spread over members, a quantity against the swept
value and a few members' trajectories."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES, SE3_BODY
from hpgen.cli import main
from hpgen.plot import _forced, _npz_arrays, energy_source, envelope, plot_file
from hpgen.plot_pose import factors, guess_group, panels
from hpgen.plot_sweep import _changes, swept_value

PNG = b"\x89PNG\r\n\x1a\n"
DAMPED = EXAMPLES / "damped_top.yaml"


def _png(path):
    data = path.read_bytes()
    assert data.startswith(PNG) and len(data) > 5000, path
    return path


def test_forced_run_energy_figure_is_the_balance_the_summary_reports(tmp_path, compile_model):
    from hpgen.model import load_model
    from hpgen.runtime.chunked_output import record_to_npz
    integ = compile_model(DAMPED)
    sc = load_model(DAMPED).scene
    out, summary = record_to_npz(integ, tmp_path / "dt.npz", g0=sc.g0, h=sc.h, steps=600,
                                 xi0=sc.xi0, every=sc.every, chunk=250)
    reported = float(summary["balance_max_change"])          # what hpgen run prints
    data = _npz_arrays(out)
    assert _forced(data, None) and bool(data["forced"])
    (t, v), label = energy_source(data, True)
    assert label == "energy-work balance |(E - W) - (E0 - W0)|"
    _, peak = envelope(t, v, ref=v[0])
    assert peak.max() == reported                             # the same numbers, bitwise
    E = np.asarray(data["energy"])
    assert np.abs(E - E[0]).max() > 1e3 * reported            # what it used to draw
    assert [p.name for p in plot_file(out, integrator=integ)] == [
        "dt-energy.png", "dt-momentum.png", "dt-group.png", "dt-pose.png", "dt-records.png"]
    _png(tmp_path / "dt-energy.png")


def test_energy_labels_say_error_only_for_a_conservative_model(tmp_path, compile_model):
    text = DAMPED.read_text().replace("record: [g, mu, energy, work, power, momentum, "
                                      '{height: "R[2,2]"}]', "record: [g, mu, energy]")
    integ = compile_model(text)
    rec = integ.record(np.eye(3), 0.05, 40, xi0=[0.2, 1.0, 3.0])
    data = _npz_arrays(rec.save(tmp_path / "forced.npz"))
    assert "work" not in data and _forced(data, None)
    assert energy_source(data, True)[1].startswith("energy change |E(t) - E(0)|")
    closed = compile_model(EXAMPLES / "heavy_top.yaml")
    data = _npz_arrays(closed.record(np.eye(3), 0.05, 40, xi0=[0.2, 1.0, 3.0])
                       .save(tmp_path / "closed.npz"))
    assert not _forced(data, None)
    assert energy_source(data, False)[1] == "energy error |E(t) - E(0)|"


def test_pose_panels_read_attitude_and_position_by_group(tmp_path, compile_model):
    assert factors("SE3") == [("SE3", 0, 4)]
    assert factors("[SO3, R3]") == [("SO3", 0, 3), ("R3", 3, 4)]
    assert factors("[SO2, SE2]") == [("SO2", 0, 2), ("SE2", 2, 3)]
    integ = compile_model(SE3_BODY)
    tr = integ.simulate(np.eye(4), 0.05, 200, xi0=[0.3, 0.2, 1.0, 0.5, 0.0, 0.2])
    rows = panels(tr.g, "SE3")
    assert [r[0].split("\n")[0] for r in rows] == ["R e_1", "R e_2", "R e_3", "position x"]
    for j in range(3):
        assert np.array_equal(rows[j][1], tr.g[:, :3, j])
    assert np.array_equal(rows[3][1], tr.g[:, :3, 3]) and np.abs(rows[3][1]).max() > 0.1
    assert guess_group(tr.g) == "SE3"
    path = tr.save(tmp_path / "se3.npz")
    assert [p.name for p in plot_file(path)] == ["se3-pose.png", "se3-records.png"]
    _png(tmp_path / "se3-pose.png")
    # a planar rotation: its angle unwrapped past pi
    k = np.arange(40)
    c, s = np.cos(0.3 * k), np.sin(0.3 * k)
    g = np.zeros((40, 2, 2))
    g[:, 0, 0], g[:, 0, 1], g[:, 1, 0], g[:, 1, 1] = c, -s, s, c
    (label, angle, _), = panels(g, guess_group(g))
    assert label == "angle (rad)" and np.allclose(angle[:, 0], 0.3 * k, atol=1e-12)
    product = np.zeros((40, 5, 5))
    product[:, :2, :2] = g
    product[:, 2:, 2:] = np.eye(3)
    product[:, 2:4, 4] = np.stack([k, -k], axis=1)
    names = [r[0] for r in panels(product, "[SO2, R2]")]
    assert names == ["SO2: angle (rad)", "R2: position x"]
    assert np.array_equal(panels(product, "[SO2, R2]")[1][1], np.stack([k, -k], axis=1))


@pytest.fixture(scope="module")
def sweep_file(compile_model, tmp_path_factory):
    import hpgen
    integ = compile_model(DAMPED)
    xi = np.array([0.2, 1.0, 3.0]) + np.zeros((12, 3))
    xi[:, 0] += np.linspace(0.0, 0.5, 12)
    xi[5] = [0.2, 1.0, 300.0]                             # fails at its start
    res = hpgen.sweep(integ, xi0=xi, h=0.05, steps=300, every=5,
                      params={"c": np.linspace(0.0, 0.2, 12)},
                      record=["energy", "work", "momentum", "height"], progress=False)
    return res, res.save(tmp_path_factory.mktemp("sweep") / "sw.npz")


def test_cli_plot_of_a_sweep(sweep_file, tmp_path, capsys):
    res, path = sweep_file
    assert main(["plot", str(path), "--out-dir", str(tmp_path)]) == 0
    printed = capsys.readouterr().out.split()
    assert [p.rsplit("/", 1)[-1] for p in printed] == ["sw-spread.png", "sw-vs-c.png",
                                                       "sw-members.png"]
    for p in printed:
        _png(tmp_path / p.rsplit("/", 1)[-1])
    (label, _, balance), (mlabel, _, dm) = _changes(res)
    assert label.startswith("energy-work balance") and mlabel.endswith("(forced)")
    E, W = res["energy"], res["work"]
    assert np.array_equal(balance, np.abs((E - W) - (E - W)[:, :1]), equal_nan=True)
    ok = ~res.failed
    assert np.nanmax(balance[ok]) < 1e-4 < np.nanmax(np.abs(E - E[:, :1])[ok])
    name, values = swept_value(res)
    assert name == "c" and np.array_equal(values, res.params["c"])


def test_plot_of_a_netcdf_sweep_and_what_is_swept(sweep_file, tmp_path):
    pytest.importorskip("xarray")
    res, _ = sweep_file
    files = plot_file(res.save(tmp_path / "sw.nc"))
    assert [p.name for p in files] == ["sw-spread.png", "sw-vs-c.png", "sw-members.png"]
    from dataclasses import replace
    plain = replace(res, params={})
    assert swept_value(plain)[0] == "xi0[2]"              # the member failing at 300
    same = replace(plain, initial={**res.initial, "xi0": np.ones((12, 3))},
                   h=np.linspace(0.01, 0.05, 12))
    assert swept_value(same)[0] == "h"


def test_plot_of_a_saved_run_as_netcdf(tmp_path, compile_model):
    pytest.importorskip("xarray")
    integ = compile_model(DAMPED)
    rec = integ.record(np.eye(3), 0.05, 100, xi0=[0.2, 1.0, 3.0], every=2)
    files = plot_file(rec.save(tmp_path / "run.nc"))
    assert [p.name for p in files] == ["run-energy.png", "run-momentum.png", "run-pose.png",
                                       "run-records.png"]


def test_a_forced_sweep_without_work_plots_the_energy_change(compile_model, tmp_path):
    import hpgen
    from hpgen.ensemble.result import load
    integ = compile_model(DAMPED)
    res = hpgen.sweep(integ, xi0=np.ones((3, 3)), h=0.05, steps=20, record=["energy"],
                      params={"c": [0.0, 0.1, 0.2]}, progress=False)
    assert res.attrs["forced"] == 1
    back = load(res.save(tmp_path / "s.npz"))
    assert back.attrs["forced"] == 1
    assert _changes(back)[0][0] == "energy change |E(t) - E(0)|"
    closed = compile_model(EXAMPLES / "heavy_top.yaml")
    res = hpgen.sweep(closed, xi0=np.ones((3, 3)), h=0.05, steps=20, record=["energy"],
                      progress=False)
    assert res.attrs["forced"] == 0 and _changes(res)[0][0] == "energy error |E(t) - E(0)|"


def test_plot_of_a_run_table_and_a_zarr_sweep(compile_model, tmp_path, capsys):
    from hpgen.plot_read import load_csv_run
    integ = compile_model(DAMPED)
    rec = integ.record(np.eye(3), 0.05, 100, xi0=[0.2, 1.0, 3.0], every=2)
    path = rec.save(tmp_path / "run.csv")
    table = load_csv_run(path)
    for name in rec.names:
        assert np.array_equal(table[name], rec[name]), name
    assert [p.name for p in plot_file(path)] == ["run-energy.png", "run-momentum.png",
                                                 "run-pose.png", "run-records.png"]
    (tmp_path / "bad.csv").write_text("t,g[0][0]\n0.0,abc\n")
    assert main(["plot", str(tmp_path / "bad.csv")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "bad.csv: expected numbers" in err
    pytest.importorskip("zarr")
    import hpgen
    res = hpgen.sweep(integ, xi0=np.ones((4, 3)), h=0.05, steps=40, every=5,
                      params={"c": [0.0, 0.1, 0.2, 0.3]}, record=["energy", "work"],
                      progress=False)
    files = plot_file(res.save(tmp_path / "sw.zarr"))
    assert [p.name for p in files] == ["sw-spread.png", "sw-vs-c.png", "sw-members.png"]


def test_plot_of_a_states_sweep_and_of_an_all_failed_sweep(compile_model, tmp_path):
    import warnings

    import hpgen
    integ = compile_model(DAMPED)
    states = hpgen.sweep(integ, xi0=np.outer([1.0, 2.0, 3.0], [1.0, 0.5, 2.0]), h=0.05,
                         steps=40, every=5, progress=False)
    assert [p.name for p in plot_file(states.save(tmp_path / "gm.npz"))] == [
        "gm-vs-xi0_2.png", "gm-members.png"]
    failed = hpgen.sweep(integ, xi0=[[0.2, 1, 300], [0.3, 1, 300]], h=0.05, steps=40,
                         every=5, record=["energy", "momentum"], progress=False)
    assert failed.failed.all()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        files = plot_file(failed.save(tmp_path / "f.npz"))
    assert [p.name for p in files] == ["f-spread.png", "f-vs-xi0_0.png", "f-members.png"]


def test_a_sweep_of_g_alone_is_one_line(compile_model, tmp_path, capsys):
    import hpgen
    integ = compile_model(DAMPED)
    res = hpgen.sweep(integ, xi0=np.ones((2, 3)), h=0.05, steps=10, record=["g"],
                      progress=False)
    assert main(["plot", str(res.save(tmp_path / "g.npz"))]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "g.npz: the sweep holds no record" in err
    assert not list(tmp_path.glob("*.png"))
