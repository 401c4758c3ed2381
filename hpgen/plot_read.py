"""Reading the files ``hpgen plot`` draws (hpgen.plot): a run's .npz (memory-mapped where
stored uncompressed), a run or a sweep saved as .nc / .zarr (through xarray), whether an .npz
is a saved sweep, and the benchmark table. Every unreadable file is a ModelError naming it.
"""
from __future__ import annotations

import csv
import math
import re
import struct
import zipfile
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from .errors import ModelError
from .runtime.counters import NAMES as COUNTER_NAMES

#: arrays of a saved run that are metadata, not records (the counters: newton_iterations,
#: guarded, hpgen.runtime.counters; a file of an older hpgen may lack some)
META_KEYS = ("h", "every", "partial", *COUNTER_NAMES, "error", "module", "hash", "group",
             "forced")


def load_npz(path: Path) -> dict:
    if not path.is_file():
        raise ModelError("expected an .npz file written by hpgen run / save, or a bench "
                         "directory", file=str(path))
    if not zipfile.is_zipfile(path):
        raise ModelError("not an .npz file (expected the output of hpgen run / save)",
                         file=str(path))
    try:
        data = npz_arrays(path)
    except (OSError, ValueError, zipfile.BadZipFile, EOFError, struct.error) as e:
        raise ModelError(f"not a readable .npz file ({type(e).__name__}: "
                         f"{str(e).splitlines()[0] if str(e) else 'unreadable'})",
                         file=str(path)) from None
    t = data.get("t")
    if t is None or t.ndim != 1:
        raise ModelError("expected the array t of a saved hpgen run (and its records)",
                         file=str(path))
    if len(t) == 0:
        raise ModelError("the file holds no sample (t is empty): nothing to plot",
                         file=str(path))
    for name, a in data.items():
        if name not in META_KEYS and (a.dtype.kind not in "fiub" or len(a) != len(t)):
            raise ModelError(f"array {name!r} is not a record of the run (expected {len(t)} "
                             f"numeric rows, got shape {a.shape}, dtype {a.dtype})",
                             file=str(path))
    return data


def is_saved_sweep(path: Path) -> bool:
    """An .npz of SweepResult.save (its member results and attributes)."""
    try:
        with zipfile.ZipFile(path) as zf:
            return {"failed.npy", "attrs_keys.npy", "step.npy"} <= set(zf.namelist())
    except (OSError, zipfile.BadZipFile):
        return False


def load_labelled(path: Path):
    """None for a sweep (.npz, .nc, .zarr); the arrays of a run saved as .nc or .zarr
    (hpgen.runtime.save_formats): t, the records and the scalars, as _load_npz gives."""
    if path.suffix == ".npz":
        return None
    from .ensemble.result import _need
    xr = _need("xarray")
    try:
        with (xr.open_zarr if path.suffix == ".zarr" else xr.open_dataset)(path) as ds:
            if "member" in ds.dims:
                return None
            if "t" not in ds.coords or ds["t"].dims != ("time",):
                raise ValueError("no coordinate t on the dimension time")
            data = {"t": ds["t"].values, **{k: ds[k].values for k in ds.data_vars}}
            data.update({k: np.asarray(v) for k, v in ds.attrs.items() if k in META_KEYS})
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise ModelError(f"not a saved hpgen run or sweep ({type(e).__name__}: "
                         f"{str(e).splitlines()[0] if str(e) else 'unreadable'})",
                         file=str(path)) from None
    if len(data["t"]) == 0:
        raise ModelError("the file holds no sample (t is empty): nothing to plot",
                         file=str(path))
    return data


def load_csv_run(path: Path):
    """The arrays of a run saved as a .csv table (hpgen.runtime.save_formats: header t,
    g[0][0], ..., mu[0], ..., energy, ...), or None when the table does not start with t
    (a benchmark's table)."""
    try:
        with open(path, newline="") as fh:
            header = next(csv.reader(fh), [])
    except (OSError, UnicodeDecodeError) as e:
        raise ModelError(f"cannot read the table ({e})", file=str(path)) from None
    if not header or header[0] != "t":
        return None
    names: dict = {}
    for col, label in enumerate(header):
        m = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*)((?:\[\d+\])*)", label)
        if m is None:
            raise ModelError(f"column {col + 1} is named {label!r}; expected a record name "
                             "with [i] indices", file=str(path), line=1)
        names.setdefault(m.group(1), []).append(
            (col, tuple(int(i) for i in re.findall(r"\d+", m.group(2)))))
    try:
        rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    except ValueError as e:
        raise ModelError(f"expected numbers in every row ({e})", file=str(path)) from None
    if rows.shape[1] != len(header) or len(rows) == 0:
        raise ModelError(f"expected {len(header)} numbers in each of one or more rows",
                         file=str(path))
    data = {}
    for name, cols in names.items():
        shape = tuple(max(ix[k] for _, ix in cols) + 1 for k in range(len(cols[0][1])))
        a = np.full((len(rows),) + shape, np.nan)
        for col, ix in cols:
            a[(slice(None),) + ix] = rows[:, col]
        data[name] = a
    return data


def npz_arrays(path: Path) -> dict:
    """{name: array} of an .npz, memory-mapped where the member is stored uncompressed (as
    np.savez and hpgen's writers store them), so that a file larger than memory is read
    bin by bin; compressed members and scalars are loaded."""
    out = {}
    with zipfile.ZipFile(path) as zf, open(path, "rb") as fh:
        for info in zf.infolist():
            name = info.filename[:-4] if info.filename.endswith(".npy") else info.filename
            arr = None
            if info.compress_type == zipfile.ZIP_STORED:
                fh.seek(info.header_offset)
                local = fh.read(30)
                if local[:4] != b"PK\x03\x04":
                    raise ValueError(f"bad local header of member {info.filename!r}")
                n_name, n_extra = struct.unpack("<HH", local[26:30])
                fh.seek(info.header_offset + 30 + n_name + n_extra)
                version = np.lib.format.read_magic(fh)
                read = (np.lib.format.read_array_header_1_0 if version == (1, 0)
                        else np.lib.format.read_array_header_2_0)
                shape, fortran, dtype = read(fh)
                if dtype.hasobject:
                    raise ValueError(f"member {name!r} holds Python objects")
                if shape and dtype.itemsize and int(np.prod(shape)):
                    arr = np.memmap(path, dtype=dtype, mode="r", offset=fh.tell(), shape=shape,
                                    order="F" if fortran else "C")
            if arr is None:
                with zf.open(info) as member:
                    arr = np.lib.format.read_array(member, allow_pickle=False)
            out[name] = arr
    return out


def read_bench_csv(path: Path) -> list:
    from .bench.report import CSV_COLUMNS
    try:
        with open(path, newline="") as fh:
            rows = list(csv.DictReader(fh))
    except (OSError, UnicodeDecodeError) as e:
        raise ModelError(f"cannot read the benchmark table ({e})", file=str(path)) from None
    if not rows or not set(CSV_COLUMNS) <= set(rows[0]):
        raise ModelError("expected work_precision.csv of hpgen bench (columns "
                         f"{', '.join(CSV_COLUMNS)})", file=str(path))
    points = []
    for k, r in enumerate(rows, start=2):
        try:
            err, wall = float(r["error"]), float(r["wall_time_s"])
        except ValueError:
            raise ModelError("expected numbers in error and wall_time_s", file=str(path),
                             line=k) from None
        points.append(SimpleNamespace(family=r["family"], kind=r["kind"], error=err,
                                      wall_s=wall, ok=math.isfinite(err)))
    return points
