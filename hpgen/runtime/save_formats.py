"""Saving a run (Trajectory.save, Records.save) in the format its file name asks for.

    tr.save("run.npz")    # numpy arrays t, g, mu (or the records) and the run's scalars
    tr.save("run.nc")     # NetCDF through xarray: dims time, row, col, component
    tr.save("run.zarr")   # a Zarr store through xarray, same layout
    tr.save("run.csv")    # a flat table: one row per record, one column per entry
    tr.save("run")        # no suffix: ".npz" is appended

.nc and .zarr hold one variable per record with dimensions ``time`` (sample k), ``row`` and
``col`` for g (n x n), ``component`` for mu, xi, momentum (d), the coordinates ``t`` and
``step`` (k * every) on ``time``, and the run's scalars (h, every, partial and forced as
0/1, newton_iterations, error, module, hash, group) as attributes; they need xarray (and
zarr, or h5netcdf / scipy for NetCDF): ``pip install 'hpgen[scale]'``. The .csv table has the header
``t, g[0][0], g[0][1], ..., mu[0], ..., energy, ...`` (g row by row) and every number written
as its shortest round-trip decimal (read back bitwise); the scalars are not in it. Any other suffix
raises ArgumentError. Every file is written beside its final name and renamed into place.
numpy and the standard library at import.
"""
from __future__ import annotations

import os
import shutil
import tempfile
from pathlib import Path

import numpy as np

from ..errors import ArgumentError
from ..files import atomic_output

RUN_SUFFIXES = (".npz", ".nc", ".zarr", ".csv")
#: rows of the .csv table formatted at once
CSV_BLOCK = 100_000
_SCALE_HINT = "install the scale extra: pip install 'hpgen[scale]'"


def run_path(path, suffixes=RUN_SUFFIXES) -> Path:
    """``path`` checked against ``suffixes`` (no suffix: ".npz" appended); ArgumentError
    naming the suffixes otherwise."""
    path = Path(path)
    if path.suffix == "":
        return path.with_name(path.name + ".npz")
    if path.suffix not in suffixes:
        raise ArgumentError(f"cannot save a run as {path.name!r}: expected a file name ending "
                            f"in {', '.join(suffixes)} (none: .npz)", field="path")
    return path


def save_run(path, arrays: dict, meta: dict) -> Path:
    """Write ``arrays`` (t and the records, each with the sample axis first) and the scalars
    ``meta`` (hpgen.runtime.trajectory.run_metadata) to ``path`` by its suffix (module
    doc); returns the path written."""
    path = run_path(path)
    if path.parent != Path(""):
        path.parent.mkdir(parents=True, exist_ok=True)
    if path.suffix == ".npz":
        with atomic_output(path) as fh:
            np.savez(fh, **arrays, **meta)
    elif path.suffix == ".csv":
        _write_csv(path, arrays)
    else:
        ds = run_dataset(arrays, meta)
        if path.suffix == ".zarr":
            _need("zarr")
            _atomic_store(path, lambda tmp: ds.to_zarr(tmp, mode="w", zarr_format=2))
        else:
            engine = _netcdf_engine()
            _atomic_store(path, lambda tmp: ds.to_netcdf(tmp, engine=engine))
    return path


def run_dataset(arrays: dict, meta: dict):
    """The run as an xarray.Dataset (labelled dims time, row, col, component)."""
    xr = _need("xarray")
    t = np.asarray(arrays["t"])
    every = int(meta.get("every", 1))
    data = {}
    for name, a in arrays.items():
        if name == "t":
            continue
        a = np.asarray(a)
        data[name] = (("time",) + {1: (), 2: ("component",), 3: ("row", "col")}[a.ndim], a)
    attrs = {k: (int(v) if np.asarray(v).dtype.kind == "b" else np.asarray(v).item())
             for k, v in meta.items()}
    coords = {"t": ("time", t), "step": ("time", np.arange(len(t), dtype=np.int64) * every)}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def csv_columns(arrays: dict) -> list:
    """The .csv header: t, then each record's entries (g[i][j] row by row, mu[i], energy)."""
    cols = []
    for name, a in arrays.items():
        shape = np.shape(a)[1:]
        cols += [name + "".join(f"[{i}]" for i in idx) for idx in np.ndindex(*shape)] \
            if shape else [name]
    return cols


def _write_csv(path: Path, arrays: dict) -> None:
    K = len(arrays["t"])
    with atomic_output(path, "w") as fh:
        fh.write(",".join(csv_columns(arrays)) + "\n")
        for lo in range(0, K, CSV_BLOCK):
            block = np.hstack([np.asarray(a[lo:lo + CSV_BLOCK], dtype=np.float64).reshape(
                min(CSV_BLOCK, K - lo), -1) for a in arrays.values()])
            fh.write("".join(",".join(map(repr, row)) + "\n" for row in block.tolist()))


def _need(module: str):
    import importlib
    try:
        return importlib.import_module(module)
    except ImportError:
        raise ArgumentError(f"saving .nc / .zarr needs {module}, which is not installed; "
                            f"{_SCALE_HINT}", field="path") from None


def _netcdf_engine() -> str:
    import importlib.util
    for engine, module in (("h5netcdf", "h5netcdf"), ("scipy", "scipy")):
        if importlib.util.find_spec(module) is not None:
            return engine
    raise ArgumentError(f"writing NetCDF needs h5netcdf or scipy; {_SCALE_HINT}",
                        field="path")


def _atomic_store(path: Path, write) -> None:
    """write(tmp) in a temp directory beside ``path``, then rename it into place (a
    directory store, or a file, replacing what was there)."""
    tmp_dir = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
    tmp = tmp_dir / path.name
    try:
        write(str(tmp))
        if path.is_dir() and tmp.is_dir():
            os.replace(path, tmp_dir / "old")
        os.replace(tmp, path)
    finally:
        shutil.rmtree(tmp_dir, ignore_errors=True)
