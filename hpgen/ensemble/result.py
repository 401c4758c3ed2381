"""The result of a sweep: labelled member x time arrays, saved as .npz, .zarr or .nc.

Dimensions: ``member`` (input order, 0..B-1), ``time`` (sample k, at global step k*every,
coordinate ``step``), and the sample's own axes: ``row``, ``col`` for g (n x n), ``component``
for mu, xi, momentum (d). ``t`` (member, time) = step * h[member]. Per member: ``failed``,
``error`` (the error's text, "" when it completed), ``samples`` (samples kept: after a failure
the rest are NaN), ``steps_done``, ``newton_iterations``, ``h`` and the initial state (``g0``
and ``xi0`` or ``mu0``). Attributes: module, hash, steps, every, hpgen_version.

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

SUFFIXES = (".npz", ".zarr", ".nc")
_SCALE_HINT = "install the scale extra: pip install 'hpgen[scale]'"


@dataclass(frozen=True, eq=False)
class SweepResult:
    """arrays {name: (B, K, *shape)}; step (K,); h, failed, error, samples, steps_done,
    newton_iterations (B,); initial {"g0": (B, n, n), "xi0" or "mu0": (B, d)}; attrs."""
    arrays: dict
    step: np.ndarray
    h: np.ndarray
    failed: np.ndarray
    error: np.ndarray
    samples: np.ndarray
    steps_done: np.ndarray
    newton_iterations: np.ndarray
    initial: dict
    attrs: dict = field(default_factory=dict)

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

    def _variables(self) -> dict:
        """{name: (dims, array)} of everything a saved sweep holds."""
        out = {}
        for name, a in self.arrays.items():
            out[name] = (("member", "time") + _axes(a.shape[2:]), a)
        for name, a in self.initial.items():
            out[name] = (("member",) + _axes(a.shape[1:]), a)
        for name in ("h", "failed", "error", "samples", "steps_done", "newton_iterations"):
            out[name] = (("member",), getattr(self, name))
        return out

    def to_xarray(self):
        """The sweep as an xarray.Dataset (needs xarray)."""
        xr = _need("xarray")
        data = {k: (dims, a) for k, (dims, a) in self._variables().items()}
        coords = {"member": np.arange(len(self)), "step": ("time", self.step),
                  "t": (("member", "time"), self.t)}
        return xr.Dataset(data, coords=coords, attrs=dict(self.attrs))

    def save(self, path) -> Path:
        """Write to ``path`` by its suffix (.npz, .zarr, .nc); returns the path."""
        path = Path(path)
        if path.suffix not in SUFFIXES:
            raise ModelError(f"expected a file name ending in {', '.join(SUFFIXES)}, got "
                             f"{path.name!r}", field="out")
        path.parent.mkdir(parents=True, exist_ok=True)
        if path.suffix == ".npz":
            data = {k: a for k, (_, a) in self._variables().items()}
            data.update(step=self.step, attrs_keys=np.array(list(self.attrs), dtype=str),
                        attrs_values=np.array([str(v) for v in self.attrs.values()], dtype=str))
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


def _axes(shape) -> tuple:
    return {0: (), 1: ("component",), 2: ("row", "col")}[len(shape)]


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


def concat(chunks: list, step, h, initial, attrs) -> SweepResult:
    """The SweepResult of chunk dicts (hpgen.ensemble.chunk.run_chunk) in member order."""
    def cat(key):
        return np.concatenate([c[key] for c in chunks])
    names = tuple(chunks[0]["arrays"])
    arrays = {r: np.concatenate([c["arrays"][r] for c in chunks]) for r in names}
    error = np.array(cat("error"), dtype=str)
    return SweepResult(arrays=arrays, step=step, h=h, failed=cat("failed"), error=error,
                       samples=cat("samples"), steps_done=cat("steps_done"),
                       newton_iterations=cat("newton_iterations"), initial=initial,
                       attrs={**attrs, "hpgen_version": __version__})
