"""``hpgen plot``: PNG figures of what a run, a section run or a benchmark saved.

    files = plot_file("heavy_top.npz")            # -> [heavy_top-energy.png, ...]

What is drawn depends on what the file holds (names as ``scene.record`` spells them):
- a run (.npz of ``hpgen run``, ``Trajectory.save`` or ``Records.save``: ``t`` and records):
  ``<stem>-energy.png`` |E(t) - E(0)| if ``energy`` is recorded; ``<stem>-momentum.png``
  |m_i(t) - m_i(0)| per component of the spatial momentum if ``momentum`` is;
  ``<stem>-group.png`` the distance of g from the group if ``defect`` is recorded (or computed
  from ``g`` by the ``integrator`` passed in, as ``hpgen run`` does); ``<stem>-records.png``
  the user expressions and mu / xi against t. Changes are drawn on a log axis as the maximum
  over bins of at most MAX_POINTS bins (a long run keeps its peaks).
- a section run (.npz with ``step``: ``hpgen run`` on a scene with ``section``):
  ``<stem>-sections.png``, the crossings in the planes of the momentum components that vary
  most (up to three panels).
- a benchmark (the ``hpgen bench`` output directory or its ``work_precision.csv``):
  ``work_precision.png``, error against wall time (hpgen.bench.report).
Figures go next to the input unless ``out_dir`` is given; each is written atomically.
Memory stays bounded for runs larger than memory: uncompressed members (as hpgen writes
them) are memory-mapped and read BLOCK_ROWS rows at a time; the group distance computed from
g uses at most MAX_DEFECT_SAMPLES evenly spaced records.
matplotlib (Agg backend) is imported only when a figure is drawn: never on the runtime path.
A file that is none of these raises ModelError naming it (``hpgen plot``: exit status 2).
"""
from __future__ import annotations

import csv
import math
import struct
import zipfile
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from .files import atomic_output
from .errors import HpgenError, ModelError

MAX_POINTS = 4000
#: rows read at once from a (memory-mapped) record array
BLOCK_ROWS = 1_000_000
#: records at which the group distance is computed from g when it is not recorded
MAX_DEFECT_SAMPLES = 100_000
#: arrays of a saved run that are metadata, not records
META_KEYS = ("h", "every", "partial", "newton_iterations", "error", "module", "hash", "group")
CHANGE_FIGURES = (("energy", "energy error |E(t) - E(0)|"),
                  ("momentum", "spatial momentum change |m_i(t) - m_i(0)|"),
                  ("defect", "distance of g from the group"))


def plot_file(path, out_dir=None, integrator=None) -> list[Path]:
    """Write the PNGs of ``path`` (see the module doc); returns their paths. ``integrator``
    (optional, the run's hpgen Integrator) computes the group distance from recorded g when
    the file has no ``defect`` record."""
    path = Path(path)
    if path.is_dir() or path.suffix == ".csv":
        csv_path = path / "work_precision.csv" if path.is_dir() else path
        if not csv_path.is_file():
            raise ModelError("expected the output directory of hpgen bench (with "
                             "work_precision.csv) or an .npz of hpgen run", file=str(path))
        return [_work_precision(csv_path, Path(out_dir) if out_dir else csv_path.parent)]
    data = _load_npz(path)
    out = Path(out_dir) if out_dir else path.parent
    stem = path.name[:-4] if path.name.endswith(".npz") else path.name
    if "step" in data:
        return [_sections(data, out / f"{stem}-sections.png", path)]
    return _run(data, out, stem, path, integrator)


# ---- reading ------------------------------------------------------------------------------
def _load_npz(path: Path) -> dict:
    if not path.is_file():
        raise ModelError("expected an .npz file written by hpgen run / save, or a bench "
                         "directory", file=str(path))
    if not zipfile.is_zipfile(path):
        raise ModelError("not an .npz file (expected the output of hpgen run / save)",
                         file=str(path))
    try:
        data = _npz_arrays(path)
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


def _npz_arrays(path: Path) -> dict:
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


def _read_bench_csv(path: Path) -> list:
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


# ---- drawing ------------------------------------------------------------------------------
def _pyplot():
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise HpgenError("plotting needs matplotlib: pip install matplotlib") from None
    return plt


def _save(fig, path: Path) -> Path:
    """savefig to ``path`` atomically (hpgen.files.atomic_output)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        with atomic_output(path) as fh:
            fig.savefig(fh, dpi=110, format="png")
    finally:
        import matplotlib.pyplot as plt
        plt.close(fig)
    return path


def envelope(t, y, n=MAX_POINTS, ref=None, block=BLOCK_ROWS):
    """(t, m): t at the start of each of at most n bins of rows and m the largest
    |y - ref| in each bin (|y| when ref is None), per column; y (K,) or (K, c), possibly a
    memory map, read ``block`` rows at a time (memory stays bounded)."""
    K = len(t)
    bins = min(n, K)
    edges = np.linspace(0, K, bins + 1).astype(np.int64)
    width = max(1, int(np.prod(y.shape[1:])))
    out = np.empty((bins, width))
    b = 0
    while b < bins:
        e = b + 1
        while e < bins and edges[e + 1] - edges[b] <= block:
            e += 1
        rows = np.asarray(y[edges[b]:edges[e]], dtype=float).reshape(-1, width)
        dev = np.abs(rows if ref is None else rows - ref)
        out[b:e] = np.maximum.reduceat(dev, edges[b:e] - edges[b], axis=0)
        b = e
    return np.asarray(t[edges[:-1]], dtype=float), out


def _change_figure(t, values, what, path, title, labels=None, absolute=False):
    """|values - values[0]| (or |values| when ``absolute``) against t, log axis."""
    plt = _pyplot()
    ref = None if absolute else np.asarray(values[0], dtype=float).reshape(-1)
    tt, env = envelope(t, values, ref=ref)
    fig, ax = plt.subplots(figsize=(7, 4))
    for i in range(env.shape[1]):
        col = np.where(env[:, i] > 0, env[:, i], np.nan)     # exact zeros: gaps on a log axis
        lab = labels[i] if labels else None
        if np.isfinite(col).any():
            ax.semilogy(tt, col, lw=0.9, label=lab)
        elif lab:
            ax.plot([], [], label=f"{lab}: 0 throughout")
    ax.set_xlabel("t")
    ax.set_ylabel(what)
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    if labels:
        ax.legend(fontsize=8)
    fig.tight_layout()
    return _save(fig, path)


def _run(data, out, stem, path, integrator) -> list[Path]:
    t = data["t"]
    files = []
    sources = {name: (t, data[name]) for name, _ in CHANGE_FIGURES if name in data}
    if "defect" not in data and "g" in data and integrator is not None:
        stride = -(-len(t) // MAX_DEFECT_SAMPLES)          # ceil: at most that many samples
        sources["defect"] = (t[::stride], np.array([integrator.defect(gk)
                                                    for gk in data["g"][::stride]]))
    title = _title(data, path)
    for name, what in CHANGE_FIGURES:
        if name not in sources:
            continue
        tn, v = sources[name]
        labels = [f"m_{i}" for i in range(v.shape[1])] if v.ndim == 2 else None
        png = out / f"{stem}-{'group' if name == 'defect' else name}.png"
        files.append(_change_figure(tn, v, what, png, title, labels, absolute=name == "defect"))
    series = [k for k in data if k not in META_KEYS + ("t", "g", "energy", "momentum",
                                                       "defect")]
    if series:
        files.append(_series(t, data, series, out / f"{stem}-records.png", title))
    if not files:
        raise ModelError("the file holds no record hpgen plot can draw (expected some of "
                         "energy, momentum, defect, mu, xi or expressions next to t; g alone "
                         "needs `defect` in scene.record)", file=str(path))
    return files


def _title(data, path) -> str:
    mod = str(data.get("module", "")) or path.name
    h = float(data["h"]) if "h" in data else None
    part = " (partial: the run failed)" if bool(data.get("partial", False)) else ""
    return f"{mod}" + (f", h = {h:g}" if h else "") + part


def _series(t, data, names, path, title) -> Path:
    plt = _pyplot()
    names = names[:6]
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 1.0 + 1.9 * len(names)), sharex=True,
                             squeeze=False)
    step = max(1, len(t) // MAX_POINTS)
    ts = np.asarray(t[::step], dtype=float)
    for ax, name in zip(axes[:, 0], names):
        v = np.asarray(data[name][::step], dtype=float).reshape(len(ts), -1)
        for i in range(v.shape[1]):
            ax.plot(ts, v[:, i], lw=0.9,
                    label=f"{name}[{i}]" if v.shape[1] > 1 else None)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
        if v.shape[1] > 1:
            ax.legend(fontsize=7, ncol=min(v.shape[1], 6), loc="best")
    axes[-1, 0].set_xlabel("t")
    axes[0, 0].set_title(title, fontsize=9)
    fig.tight_layout()
    return _save(fig, path)


def _sections(data, path, src) -> Path:
    plt = _pyplot()
    mu = np.asarray(data["mu"], dtype=float)
    if len(mu) < 2:
        raise ModelError(f"the file holds {len(mu)} section crossing(s): nothing to plot",
                         file=str(src))
    order = np.argsort(-mu.std(axis=0))
    moving = [int(i) for i in order if mu[:, i].std() > 0][:4]
    pairs = [(moving[a], moving[b]) for a in range(len(moving))
             for b in range(a + 1, len(moving))][:3] or [(0, min(1, mu.shape[1] - 1))]
    fig, axes = plt.subplots(1, len(pairs), figsize=(4.2 * len(pairs), 4.2), squeeze=False)
    for ax, (i, j) in zip(axes[0], pairs):
        ax.plot(mu[:, i], mu[:, j], ".", ms=1.5)
        ax.set_xlabel(f"mu[{i}]")
        ax.set_ylabel(f"mu[{j}]")
        ax.grid(True, alpha=0.3)
    fig.suptitle(f"{_title(data, src)}: {len(mu)} section crossings", fontsize=9)
    fig.tight_layout()
    return _save(fig, path)


def _work_precision(csv_path: Path, out: Path) -> Path:
    from .bench.report import draw_work_precision
    points = _read_bench_csv(csv_path)
    fig = draw_work_precision(_pyplot(), points, f"hpgen bench: {csv_path.parent.name}")
    return _save(fig, out / "work_precision.png")
