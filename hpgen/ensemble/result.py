"""The result of a sweep: labelled member x time arrays, saved as .npz, .zarr or .nc.

Dimensions: ``member`` (input order, 0..B-1), ``time`` (sample k, at global step k*every,
coordinate ``step``), and the sample's own axes: ``row``, ``col`` for g (n x n), ``component``
for mu, xi, momentum (d). ``t`` (member, time) = step * h[member]. Per member: ``failed``,
``error`` (the error's text, "" when it completed), ``samples`` (samples kept: after a failure
the rest are NaN), ``steps_done``, and the run's counters ``newton_iterations``, ``guarded``
(hpgen.runtime.counters; a sweep saved by an older hpgen without one reads it as 0).
What tells the members apart is a coordinate of the member dimension: ``h``, the initial
state (``g0`` and ``xi0`` or ``mu0``) and each swept runtime parameter under its own name
(``param_<name>`` if the name is taken by a record; the attribute ``params`` lists them,
comma-separated). Attributes: module, hash, steps, every, forced (1 for a model with forces),
params, hpgen_version.
``load(path)`` reads any of the three forms back into a SweepResult.

.npz needs numpy only (no pickles: text as fixed-width unicode); .zarr and .nc go through
xarray (``pip install hpgen[scale]``; NetCDF through scipy's NetCDF 3 writer or h5netcdf).
Every file is written beside its final name and renamed into place (never half-written).
"""
from __future__ import annotations

import os
import shutil
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .. import __version__
from ..errors import ModelError
from ..runtime import counters

SUFFIXES = (".npz", ".zarr", ".nc")
_SCALE_HINT = "install the scale extra: pip install 'hpgen[scale]'"


@dataclass(frozen=True, eq=False)
class SweepResult:
    """arrays {name: (B, K, *shape)}; step (K,); h, failed, error, samples, steps_done,
    newton_iterations, guarded (steps re-solved by the wrong-root guard) (B,); initial
    {"g0": (B, n, n), "xi0" or "mu0": (B, d)}; attrs; params {runtime parameter name:
    (B, *shape)} of a params sweep ({} without)."""
    arrays: dict
    step: np.ndarray
    h: np.ndarray
    failed: np.ndarray
    error: np.ndarray
    samples: np.ndarray
    steps_done: np.ndarray
    newton_iterations: np.ndarray
    initial: dict
    #: (B,); None (a result made without it) is zeros
    guarded: np.ndarray | None = None
    attrs: dict = field(default_factory=dict)
    params: dict = field(default_factory=dict)

    def __post_init__(self):
        if self.guarded is None:
            object.__setattr__(self, "guarded", np.zeros(len(self.h), dtype=np.int64))

    def __len__(self) -> int:
        return len(self.h)

    def __getitem__(self, name) -> np.ndarray:
        return self.arrays[name]

    @property
    def names(self) -> tuple:
        return tuple(self.arrays)

    @property
    def t(self) -> np.ndarray:
        """(B, K) sample times step * h (the bits of Trajectory.t of each member)."""
        return self.step[None, :] * self.h[:, None]

    def coordinate_names(self) -> dict:
        """{runtime parameter name: the name of its coordinate} (the name itself unless a
        record or another variable has it: then ``param_<name>``)."""
        taken = set(self.arrays) | set(self.initial) | set(_PER_MEMBER) | {
            "h", "t", "step", "member"}
        return {p: (f"param_{p}" if p in taken else p) for p in self.params}

    def _coordinates(self) -> dict:
        """{name: (dims, array)} of the member dimension's coordinates (h, initial states,
        swept runtime parameters)."""
        out = {"h": (("member",), self.h)}
        for name, a in self.initial.items():
            out[name] = (("member",) + _axes(a.shape[1:]), a)
        for p, name in self.coordinate_names().items():
            a = np.asarray(self.params[p])
            out[name] = (("member",) + _param_axes(p, a.shape[1:]), a)
        return out

    def _variables(self) -> dict:
        """{name: (dims, array)} of the data a saved sweep holds (besides coordinates)."""
        out = {}
        for name, a in self.arrays.items():
            out[name] = (("member", "time") + _axes(a.shape[2:]), a)
        for name in _PER_MEMBER:
            out[name] = (("member",), getattr(self, name))
        return out

    def _attrs(self) -> dict:
        return {**self.attrs, "params": ",".join(self.coordinate_names().values())}

    def to_xarray(self):
        """The sweep as an xarray.Dataset (needs xarray): the records and per-member
        results as data, member (index), step, t, h, the initial states and the swept runtime
        parameters as coordinates."""
        xr = _need("xarray")
        coords = {"member": np.arange(len(self)), "step": ("time", self.step),
                  "t": (("member", "time"), self.t), **self._coordinates()}
        return xr.Dataset(self._variables(), coords=coords, attrs=self._attrs())

    def save(self, path) -> Path:
        """Write to ``path`` by its suffix (.npz, .zarr, .nc); returns the path."""
        path = Path(path)
        if path.suffix not in SUFFIXES:
            raise ModelError(f"expected a file name ending in {', '.join(SUFFIXES)}, got "
                             f"{path.name!r}", field="out")
        path.parent.mkdir(parents=True, exist_ok=True)
        if path.suffix == ".npz":
            data = {k: a for k, (_, a) in {**self._variables(), **self._coordinates()}.items()}
            attrs = self._attrs()
            data.update(step=self.step, attrs_keys=np.array(list(attrs), dtype=str),
                        attrs_values=np.array([str(v) for v in attrs.values()], dtype=str))
            _atomic(path, lambda tmp: np.savez(tmp, **data), directory=False)
        elif path.suffix == ".zarr":
            ds = self.to_xarray()
            _need("zarr")
            _atomic(path, lambda tmp: ds.to_zarr(tmp, mode="w", zarr_format=2), directory=True)
        else:
            ds = self.to_xarray()
            _atomic(path, lambda tmp: ds.to_netcdf(tmp, engine=_netcdf_engine()),
                    directory=False)
        return path


_PER_MEMBER = ("failed", "error", "samples", "steps_done", *counters.NAMES)


def _axes(shape) -> tuple:
    return {0: (), 1: ("component",), 2: ("row", "col")}[len(shape)]


def _param_axes(name, shape) -> tuple:
    """A runtime parameter's own axes (its shape after the member axis): ``<name>_i`` ..."""
    return tuple(f"{name}_{i}" for i in range(len(shape)))


def _need(module: str):
    import importlib
    try:
        return importlib.import_module(module)
    except ImportError:
        raise ModelError(f"{module} is not installed; {_SCALE_HINT}", field="out") from None


def _netcdf_engine() -> str:
    import importlib.util
    for engine, module in (("h5netcdf", "h5netcdf"), ("scipy", "scipy")):
        if importlib.util.find_spec(module) is not None:
            return engine
    raise ModelError(f"writing NetCDF needs h5netcdf or scipy; {_SCALE_HINT}", field="out")


def _atomic(path: Path, write, directory: bool) -> None:
    """write(tmp) beside ``path``, then rename it into place (a directory store too)."""
    tmp_dir = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
    tmp = tmp_dir / path.name
    try:
        write(str(tmp))
        if directory and path.exists():
            old = tmp_dir / "old"
            os.replace(path, old)
        os.replace(tmp, path)
    finally:
        shutil.rmtree(tmp_dir, ignore_errors=True)


def concat(chunks: list, step, h, initial, attrs, params=None) -> SweepResult:
    """The SweepResult of chunk dicts (hpgen.ensemble.chunk.run_chunk) in member order;
    params: the swept runtime parameters {name: (B, *shape)}."""
    def cat(key):
        return np.concatenate([c[key] for c in chunks])
    names = tuple(chunks[0]["arrays"])
    arrays = {r: np.concatenate([c["arrays"][r] for c in chunks]) for r in names}
    error = np.array(cat("error"), dtype=str)
    return SweepResult(arrays=arrays, step=step, h=h, failed=cat("failed"), error=error,
                       samples=cat("samples"), steps_done=cat("steps_done"),
                       **{name: cat(name) for name in counters.NAMES}, initial=initial,
                       attrs={**attrs, "hpgen_version": __version__},
                       params={k: np.asarray(v) for k, v in (params or {}).items()})


def load(path) -> SweepResult:
    """The SweepResult saved in ``path`` (.npz, .zarr or .nc, as ``SweepResult.save`` writes
    them; .zarr and .nc need xarray). ModelError naming the file when it is not a sweep."""
    path = Path(path)
    if path.suffix not in SUFFIXES:
        raise ModelError(f"expected a saved sweep ending in {', '.join(SUFFIXES)}",
                         file=str(path))
    if not path.exists():
        raise ModelError("no such file", file=str(path))
    try:
        if path.suffix == ".npz":
            with np.load(path, allow_pickle=False) as z:
                data = {k: z[k] for k in z.files}
            attrs = dict(zip(data.pop("attrs_keys").tolist(), data.pop("attrs_values").tolist()))
        else:
            xr = _need("xarray")
            opener = xr.open_zarr if path.suffix == ".zarr" else xr.open_dataset
            with opener(path) as ds:
                ds = ds.load()
            data = {k: ds[k].values for k in (*ds.data_vars, *ds.coords)}
            attrs = dict(ds.attrs)
        return from_arrays(data, attrs)
    except ModelError as e:
        raise e.located(file=str(path)) from None
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise ModelError(f"not a saved hpgen sweep ({type(e).__name__}: "
                         f"{str(e).splitlines()[0] if str(e) else 'unreadable'})",
                         file=str(path)) from None


def from_arrays(data: dict, attrs: dict) -> SweepResult:
    """A SweepResult from the named arrays and attributes of a saved sweep."""
    # (a counter a sweep of an older hpgen lacks: zeros)
    B = len(data["h"]) if "h" in data else 0
    data = {**{name: np.zeros(B, dtype=np.int64) for name in counters.NAMES}, **data}
    missing = [k for k in ("step", "h", "g0", *_PER_MEMBER) if k not in data]
    if missing or ("xi0" in data) == ("mu0" in data):
        raise ModelError("not a saved hpgen sweep (no " + (missing[0] if missing else "xi0 / "
                                                            "mu0") + " array)")
    attrs = {k: _attr(v) for k, v in attrs.items()}
    coord_names = [c for c in str(attrs.pop("params", "")).split(",") if c]
    kind = "xi0" if "xi0" in data else "mu0"
    fixed = {"step", "h", "g0", kind, "t", "member", *_PER_MEMBER, *coord_names}
    arrays = {k: np.asarray(a) for k, a in data.items() if k not in fixed}
    bad = [k for k, a in arrays.items() if a.ndim < 2 or a.shape[:2] != (B, len(data["step"]))]
    if bad:
        raise ModelError(f"array {bad[0]!r} is not a (member, time) record of the sweep")
    params = {}
    for c in coord_names:
        name = c[len("param_"):] if c.startswith("param_") and c[len("param_"):] in fixed \
            | set(arrays) else c
        params[name] = np.asarray(data[c])
    return SweepResult(arrays=arrays, step=np.asarray(data["step"]), h=np.asarray(data["h"]),
                       failed=np.asarray(data["failed"]),
                       error=np.asarray(data["error"]).astype(str),
                       samples=np.asarray(data["samples"]),
                       steps_done=np.asarray(data["steps_done"]),
                       **{name: np.asarray(data[name]) for name in counters.NAMES},
                       initial={"g0": np.asarray(data["g0"]), kind: np.asarray(data[kind])},
                       attrs=attrs, params=params)


def _attr(v):
    """An attribute as saved (.npz keeps text): integers back to int."""
    if isinstance(v, str) and v.lstrip("-").isdigit():
        return int(v)
    return v.item() if isinstance(v, np.generic) else v
