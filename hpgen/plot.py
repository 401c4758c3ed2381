"""``hpgen plot``: PNG figures of what a run, a section run, a sweep or a benchmark saved.

    files = plot_file("heavy_top.npz")            # -> [heavy_top-energy.png, ...]

What is drawn depends on what the file holds (names as ``scene.record`` spells them):
- a run (.npz of ``hpgen run``, ``Trajectory.save`` or ``Records.save``, or their .nc /
  .zarr / .csv: ``t`` and records): ``<stem>-energy.png`` what the run conserves: the energy-work
  balance |(E - W) - (E0 - W0)| when energy and work are recorded (a forced model), else
  |E(t) - E(0)|, labelled the energy error for a conservative model and the energy change
  for a forced one (the file's ``forced``, the integrator's meta, or work / power recorded);
  ``<stem>-momentum.png`` |m_i(t) - m_i(0)| per component of the spatial momentum if
  ``momentum`` is; ``<stem>-group.png`` the distance of g from the group if ``defect`` is
  recorded (or computed from ``g`` by the ``integrator`` passed in, as ``hpgen run`` does);
  ``<stem>-pose.png`` the attitude and position read from ``g`` by the group
  (hpgen.plot_pose); ``<stem>-records.png`` the user expressions and mu / xi against t.
  Changes are drawn on a log axis as the maximum over bins of at most MAX_POINTS bins (a
  long run keeps its peaks).
- a section run (.npz with ``step``: ``hpgen run`` on a scene with ``section``):
  ``<stem>-sections.png``, the crossings in the planes of the momentum components that vary
  most (up to three panels).
- a sweep (SweepResult.save: .npz, .nc, .zarr): the spread over members, a quantity against
  the swept value and a few members' trajectories (hpgen.plot_sweep).
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

from pathlib import Path

import numpy as np

from .errors import HpgenError, ModelError
from .files import atomic_output
from .plot_read import META_KEYS, is_saved_sweep, load_csv_run, load_labelled, load_npz, \
    npz_arrays, read_bench_csv

#: (the name tests and older callers use)
_npz_arrays = npz_arrays

MAX_POINTS = 4000
#: rows read at once from a (memory-mapped) record array
BLOCK_ROWS = 1_000_000
#: records at which the group distance is computed from g when it is not recorded
MAX_DEFECT_SAMPLES = 100_000
CHANGE_FIGURES = (("energy", "energy error |E(t) - E(0)|"),
                  ("momentum", "spatial momentum change |m_i(t) - m_i(0)|"),
                  ("defect", "distance of g from the group"))


def plot_file(path, out_dir=None, integrator=None) -> list[Path]:
    """Write the PNGs of ``path`` (see the module doc); returns their paths. ``integrator``
    (optional, the run's hpgen Integrator) computes the group distance from recorded g when
    the file has no ``defect`` record."""
    path = Path(path)
    table = load_csv_run(path) if path.suffix == ".csv" and path.is_file() else None
    if table is None and path.suffix != ".zarr" and (path.is_dir() or path.suffix == ".csv"):
        csv_path = path / "work_precision.csv" if path.is_dir() else path
        if not csv_path.is_file():
            raise ModelError("expected the output directory of hpgen bench (with "
                             "work_precision.csv) or an .npz of hpgen run", file=str(path))
        return [_work_precision(csv_path, Path(out_dir) if out_dir else csv_path.parent)]
    out = Path(out_dir) if out_dir else path.parent
    stem = path.name[:-len(path.suffix)] if path.suffix in (".npz", ".nc", ".zarr", ".csv") \
        else path.name
    if table is not None:
        data = table
    elif path.suffix in (".nc", ".zarr") or is_saved_sweep(path):
        data = load_labelled(path)
        if data is None:                                   # a sweep
            from .ensemble.result import load
            from .plot_sweep import sweep_figures
            return sweep_figures(load(path), out, stem, path)
    else:
        data = load_npz(path)
    if "step" in data:
        return [_sections(data, out / f"{stem}-sections.png", path)]
    return _run(data, out, stem, path, integrator)


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
    labels_of = dict(CHANGE_FIGURES)
    if "energy" in data:
        sources["energy"], labels_of["energy"] = energy_source(data, _forced(data, integrator))
    if "momentum" in data and _forced(data, integrator):
        labels_of["momentum"] = "spatial momentum change |m_i(t) - m_i(0)| (forced: not conserved)"
    title = _title(data, path)
    for name, _ in CHANGE_FIGURES:
        if name not in sources:
            continue
        tn, v = sources[name]
        labels = [f"m_{i}" for i in range(v.shape[1])] if v.ndim == 2 else None
        png = out / f"{stem}-{'group' if name == 'defect' else name}.png"
        files.append(_change_figure(tn, v, labels_of[name], png, title, labels,
                                    absolute=name == "defect"))
    if "g" in data:
        pose = _pose(t, data, integrator, out / f"{stem}-pose.png", title)
        files += [pose] if pose else []
    series = [k for k in data if k not in META_KEYS + ("t", "g", "energy", "momentum",
                                                       "defect")]
    if series:
        files.append(_series(t, data, series, out / f"{stem}-records.png", title))
    if not files:
        raise ModelError("the file holds no record hpgen plot can draw (expected some of "
                         "energy, momentum, defect, mu, xi or expressions next to t; g alone "
                         "needs `defect` in scene.record)", file=str(path))
    return files


class _Difference:
    """a - b read row block by row block (two records, possibly memory maps)."""

    def __init__(self, a, b):
        self.a, self.b, self.shape, self.ndim = a, b, a.shape, a.ndim

    def __len__(self):
        return len(self.a)

    def __getitem__(self, rows):
        return np.asarray(self.a[rows], dtype=float) - np.asarray(self.b[rows], dtype=float)


def energy_source(data, forced: bool):
    """((t, values), label) of the energy figure: what is conserved where the file has it.
    With work recorded, the energy-work balance E - W (a forced model's conserved quantity,
    docs/numerics.md sec. 13); without, E itself: its error for a conservative model, its
    change for a forced one."""
    t = data["t"]
    if "work" in data:
        return ((t, _Difference(data["energy"], data["work"])),
                "energy-work balance |(E - W) - (E0 - W0)|")
    if forced:
        return (t, data["energy"]), "energy change |E(t) - E(0)| (forced: not conserved)"
    return (t, data["energy"]), "energy error |E(t) - E(0)|"


def _forced(data, integrator) -> bool:
    """Whether the run's model has forces: said by the file, the integrator or its records."""
    if "forced" in data:
        return bool(data["forced"])
    meta = getattr(integrator, "meta", None) or {}
    return bool((meta.get("open") or {}).get("forced")) or "work" in data or "power" in data


def _pose(t, data, integrator, path, title):
    from .plot_pose import pose_figure
    group = str(data["group"]) if "group" in data else \
        str((getattr(integrator, "meta", None) or {}).get("group", ""))
    step = max(1, len(t) // MAX_POINTS)
    fig = pose_figure(_pyplot(), np.asarray(t[::step], dtype=float), data["g"][::step], group,
                      title)
    return None if fig is None else _save(fig, path)


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
    points = read_bench_csv(csv_path)
    fig = draw_work_precision(_pyplot(), points, f"hpgen bench: {csv_path.parent.name}")
    return _save(fig, out / "work_precision.png")
