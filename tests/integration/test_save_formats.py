"""Trajectory.save and Records.save by the file name's suffix: .npz (none: .npz appended),
.nc and .zarr (labelled dims time, row, col, component; the run's scalars as attributes) and
.csv (a flat table, numbers read back bitwise); any other suffix is one ArgumentError and
writes nothing, and ``hpgen run --out`` with another suffix than .npz is one line, exit 2."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from conftest import EXAMPLES, ROOT
from hpgen.errors import ArgumentError
from hpgen.runtime.save_formats import csv_columns

XI0 = [0.2, 1.0, 3.0]


@pytest.fixture(scope="module")
def top(compile_model):
    """The damped heavy top: record row g, mu, energy, work, power, momentum, height."""
    return compile_model(EXAMPLES / "damped_top.yaml")


def test_npz_and_no_suffix(top, tmp_path):
    tr = top.simulate(np.eye(3), 0.05, 20, xi0=XI0, every=5)
    assert tr.save(tmp_path / "a") == tmp_path / "a.npz"
    assert tr.save(tmp_path / "b.npz") == tmp_path / "b.npz"
    with np.load(tmp_path / "a.npz") as z:
        assert np.array_equal(z["g"], tr.g) and np.array_equal(z["mu"], tr.mu)
        assert str(z["group"]) == "SO3" and float(z["h"]) == 0.05 and int(z["every"]) == 5


@pytest.mark.parametrize("name", ["run.csv.txt", "run.txt", "run.h5", "run.CSV"])
def test_unknown_suffix_is_refused_and_nothing_written(top, tmp_path, name):
    tr = top.simulate(np.eye(3), 0.05, 4, xi0=XI0)
    rec = top.record(np.eye(3), 0.05, 4, xi0=XI0)
    for obj in (tr, rec):
        with pytest.raises(ArgumentError, match=r"expected a file name ending in \.npz, \.nc, "
                                                r"\.zarr, \.csv") as info:
            obj.save(tmp_path / "out" / name)
        assert "\n" not in str(info.value)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_csv_is_a_flat_table_read_back_bitwise(top, tmp_path):
    rec = top.record(np.eye(3), 0.05, 30, xi0=XI0, every=3)
    path = rec.save(tmp_path / "out" / "run.csv")
    assert path == tmp_path / "out" / "run.csv" and not (tmp_path / "out" / "run.csv.npz").exists()
    header = path.read_text().splitlines()[0].split(",")
    assert header == csv_columns({"t": rec.t, **rec.arrays})
    assert header[:4] == ["t", "g[0][0]", "g[0][1]", "g[0][2]"]
    assert header[-5:] == ["power", "momentum[0]", "momentum[1]", "momentum[2]", "height"]
    table = np.loadtxt(path, delimiter=",", skiprows=1)
    assert table.shape == (len(rec.t), 1 + 9 + 3 + 3 + 3 + 1)
    assert np.array_equal(table[:, 0], rec.t)
    assert np.array_equal(table[:, 1:10].reshape(-1, 3, 3), rec["g"])     # row by row
    assert np.array_equal(table[:, 13], rec["energy"])
    assert np.array_equal(table[:, -1], rec["height"])
    tr = top.simulate(np.eye(3), 0.05, 30, xi0=XI0, every=3)
    table = np.loadtxt(tr.save(tmp_path / "tr.csv"), delimiter=",", skiprows=1)
    assert np.array_equal(table[:, 10:], tr.mu)


@pytest.mark.parametrize("suffix", [".nc", ".zarr"])
def test_nc_and_zarr_are_labelled(top, tmp_path, suffix):
    xr = pytest.importorskip("xarray")
    if suffix == ".zarr":
        pytest.importorskip("zarr")
    rec = top.record(np.eye(3), 0.05, 30, xi0=XI0, every=3)
    path = rec.save(tmp_path / f"run{suffix}")
    with (xr.open_zarr if suffix == ".zarr" else xr.open_dataset)(path) as ds:
        ds = ds.load()
    assert ds["g"].dims == ("time", "row", "col") and ds["momentum"].dims == ("time", "component")
    assert ds["energy"].dims == ("time",)
    assert np.array_equal(ds["t"].values, rec.t) and ds["step"].values.tolist() == \
        list(range(0, 31, 3))
    for name in rec.names:
        assert np.array_equal(ds[name].values, rec[name]), name
    assert ds.attrs["group"] == "SO3" and ds.attrs["every"] == 3 and ds.attrs["partial"] == 0
    tr = top.simulate(np.eye(3), 0.05, 30, xi0=XI0, every=3)
    path = tr.save(tmp_path / f"tr{suffix}")          # written again over itself: replaced
    path = tr.save(tmp_path / f"tr{suffix}")
    with (xr.open_zarr if suffix == ".zarr" else xr.open_dataset)(path) as ds:
        assert np.array_equal(ds["mu"].values, tr.mu) and ds["mu"].dims == ("time", "component")


def test_cli_run_out_with_another_suffix_is_one_line(tmp_path, cache_dir):
    p = subprocess.run([sys.executable, "-m", "hpgen", "run", str(EXAMPLES / "heavy_top.yaml"),
                        "--out", str(tmp_path / "run.csv"), "--steps", "10", "--no-plot",
                        "--cache-dir", str(cache_dir)], cwd=ROOT, capture_output=True,
                       text=True, timeout=300)
    assert p.returncode == 2 and p.stderr.count("\n") == 1, p.stderr
    assert "expected a file name ending in .npz" in p.stderr
    assert list(tmp_path.iterdir()) == []
