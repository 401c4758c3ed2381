"""The figures of a saved sweep (hpgen.ensemble.result: .npz, .nc or .zarr).

- ``<stem>-spread.png``: the spread over members of what each member conserves or changes,
  against t (or the step when the members' h differ): the energy-work balance
  |(E - W) - (E0 - W0)| when energy and work are recorded, else |E(t) - E(0)| (the energy
  error; its change for a forced model), and the spatial momentum change |m(t) - m(0)|
  (2-norm over components). Drawn on a log axis: the median over members, the 25-75 and
  5-95 percentile bands and the maximum. Failed members count up to their failure.
- ``<stem>-vs-<p>.png``: per member, against the swept value p (a runtime parameter that
  varies, else h, else the initial-state component that varies most): the largest change
  of the conserved quantity over the run and the last value of each scalar record (of mu's
  components for a sweep of the states g, mu; a failed member: a dotted line at its value).
- ``<stem>-members.png``: the scalar records (and the components of the first vector record)
  of at most MAX_MEMBERS members spread over the swept values, against t.
The title says how many members failed.
"""
from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np

MAX_MEMBERS = 5
#: percentile bands over members (low, high) and their opacity
BANDS = ((5, 95, 0.18), (25, 75, 0.35))
MAX_PANELS = 4


def sweep_figures(res, out: Path, stem: str, source: Path) -> list:
    """Write the PNGs of the SweepResult ``res``; returns their paths."""
    from .plot import _pyplot, _save
    plt = _pyplot()
    title = _title(res, source)
    files = []
    changes = _changes(res)
    x, xlabel = _time_axis(res)
    if changes:
        files.append(_save(_spread(plt, x, xlabel, changes, title), out / f"{stem}-spread.png"))
    swept = swept_value(res)
    per_member = _per_member(res, changes)
    if swept is not None and per_member:
        name, values = swept
        fig = _against(plt, name, values, per_member, res.failed, title)
        files.append(_save(fig, out / f"{stem}-vs-{_file_part(name)}.png"))
    fig = _members(plt, res, swept, title)
    if fig is not None:
        files.append(_save(fig, out / f"{stem}-members.png"))
    if not files:
        from .errors import ModelError
        raise ModelError("the sweep holds no record hpgen plot can draw (expected some of "
                         "energy, momentum, mu or scalar records)", file=str(source))
    return files


# ---- what is drawn --------------------------------------------------------------------------
def forced(res) -> bool:
    """Whether the sweep's model has forces (its attrs, else work or power recorded)."""
    if "forced" in res.attrs:
        return bool(int(res.attrs["forced"]))
    return "work" in res.arrays or "power" in res.arrays


def _changes(res) -> list:
    """[(label, short label, (B, K) changes)] of the conserved (or changing) quantities."""
    out = []
    if "energy" in res.arrays:
        E = np.asarray(res["energy"], dtype=float)
        if "work" in res.arrays:
            E = E - np.asarray(res["work"], dtype=float)
            label, short = ("energy-work balance |(E - W) - (E0 - W0)|",
                            "max over t of\n|(E - W) - (E0 - W0)|")
        else:
            label = ("energy change |E(t) - E(0)|" if forced(res) else
                     "energy error |E(t) - E(0)|")
            short = "max over t of\n|E(t) - E(0)|"
        out.append((label, short, np.abs(E - E[:, :1])))
    if "momentum" in res.arrays:
        m = np.asarray(res["momentum"], dtype=float)
        out.append(("momentum change |m(t) - m(0)|" + (" (forced)" if forced(res) else ""),
                    "max over t of\n|m(t) - m(0)|", np.linalg.norm(m - m[:, :1], axis=2)))
    return out


def swept_value(res):
    """(name, (B,) values) of what the members are swept over, or None (one member, or
    nothing varies): a varying runtime parameter (a vector one: its most varying entry),
    else h, else the initial-state component that varies most."""
    if len(res) < 2:
        return None
    candidates = [(name, np.asarray(v, dtype=float).reshape(len(res), -1))
                  for name, v in res.params.items()]
    candidates.append(("h", np.asarray(res.h, dtype=float)[:, None]))
    kind = "xi0" if "xi0" in res.initial else "mu0"
    candidates.append((kind, np.asarray(res.initial[kind], dtype=float)))
    for name, a in candidates:
        spread = np.ptp(a, axis=0)
        if spread.max() > 0:
            i = int(np.argmax(spread))
            return (name if a.shape[1] == 1 else f"{name}[{i}]"), a[:, i]
    return None


def _per_member(res, changes) -> list:
    """[(label, (B,) value)]: the largest change per member, the last values of scalars."""
    out = []
    for _, short, v in changes[:1]:
        peak = np.full(len(res), np.nan)
        some = (np.asarray(res.samples) > 1) & np.isfinite(v).any(axis=1)
        peak[some] = np.nanmax(v[some], axis=1)
        out.append((short, peak))
    last = np.maximum(np.asarray(res.samples) - 1, 0)
    columns = [(name, None) for name, a in res.arrays.items() if a.ndim == 2]
    vectors = [name for name, a in res.arrays.items() if a.ndim == 3]
    if not columns and vectors:                  # states only: the components of mu
        columns = [(vectors[-1], i) for i in range(res[vectors[-1]].shape[2])]
    for name, i in columns[:MAX_PANELS - len(out)]:
        a = np.asarray(res[name] if i is None else res[name][:, :, i], dtype=float)
        v = a[np.arange(len(res)), last]
        label = name if i is None else f"{name}[{i}]"
        out.append((f"{label} at the end", np.where(res.failed, np.nan, v)))
    return out


def _time_axis(res):
    h = np.asarray(res.h, dtype=float)
    if np.all(h == h[0]):
        return np.asarray(res.step, dtype=float) * h[0], "t"
    return np.asarray(res.step, dtype=float), "step (members' h differ)"


# ---- figures --------------------------------------------------------------------------------
def _spread(plt, x, xlabel, changes, title):
    fig, axes = plt.subplots(len(changes), 1, figsize=(7.4, 1.4 + 2.6 * len(changes)),
                             sharex=True, squeeze=False)
    for ax, (label, _, v) in zip(axes[:, 0], changes):
        # at the first sample every change is 0: left out of the log axis
        xs, vs = x[1:], v[:, 1:]
        if vs.shape[1] == 0 or not np.isfinite(vs).any():
            ax.text(0.5, 0.5, "no sample after the first", transform=ax.transAxes,
                    ha="center")
        else:
            with warnings.catch_warnings():      # samples where every member has failed
                warnings.simplefilter("ignore", RuntimeWarning)
                bands = [np.nanpercentile(vs, [lo, hi], axis=0) for lo, hi, _ in BANDS]
                median, top = np.nanmedian(vs, axis=0), np.nanmax(vs, axis=0)
            for (lo, hi, alpha), (a, b) in zip(BANDS, bands):
                a, b = _positive(a), _positive(b)
                ax.fill_between(xs, a, b, alpha=alpha, color="C0", lw=0,
                                label=f"{lo}-{hi} % of members")
            ax.semilogy(xs, _positive(median), color="C0", lw=1.2, label="median")
            ax.semilogy(xs, _positive(top), color="C3", lw=0.8, label="max")
            ax.legend(fontsize=7, loc="lower right")
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    axes[-1, 0].set_xlabel(xlabel)
    axes[0, 0].set_title(f"{title}: spread over members", fontsize=9)
    fig.tight_layout()
    return fig


def _against(plt, name, values, per_member, failed, title):
    fig, axes = plt.subplots(len(per_member), 1, figsize=(7, 1.4 + 2.2 * len(per_member)),
                             sharex=True, squeeze=False)
    order = np.argsort(values, kind="stable")
    failed = np.asarray(failed, dtype=bool)
    for ax, (label, v) in zip(axes[:, 0], per_member):
        ok = np.isfinite(v[order]) & ~failed[order]
        log = label.startswith("max over t") and np.all(v[ok[np.argsort(order)]] > 0)
        draw = ax.semilogy if log else ax.plot
        draw(values[order][ok], v[order][ok], ".-", ms=4, lw=0.8)
        for k, b in enumerate(np.flatnonzero(failed)):      # failed: where, not a value
            ax.axvline(values[b], color="C3", lw=0.8, ls=":",
                       label="failed member" if k == 0 else None)
        if failed.any():
            ax.legend(fontsize=7)
        ax.set_ylabel(label, fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    axes[-1, 0].set_xlabel(name)
    axes[0, 0].set_title(f"{title}: against {name}", fontsize=9)
    fig.tight_layout()
    return fig


def _members(plt, res, swept, title):
    scalars = [n for n, a in res.arrays.items() if a.ndim == 2]
    vectors = [n for n, a in res.arrays.items() if a.ndim == 3]
    rows = [(n, None) for n in scalars[:MAX_PANELS]]
    if vectors:
        v = vectors[0]
        rows += [(v, i) for i in range(res[v].shape[2])][:max(0, MAX_PANELS + 1 - len(rows))]
    if not rows:
        return None
    order = np.argsort(swept[1], kind="stable") if swept else np.arange(len(res))
    pick = order[np.unique(np.linspace(0, len(res) - 1, min(MAX_MEMBERS, len(res))).round()
                           .astype(int))]
    h = np.asarray(res.h, dtype=float)
    fig, axes = plt.subplots(len(rows), 1, figsize=(7.6, 1.2 + 1.9 * len(rows)), sharex=True,
                             squeeze=False)
    for ax, (name, comp) in zip(axes[:, 0], rows):
        for j, b in enumerate(pick):
            y = res[name][b] if comp is None else res[name][b, :, comp]
            label = f"member {b}" + (f", {swept[0]} = {swept[1][b]:.4g}" if swept else "")
            ax.plot(np.asarray(res.step) * h[b], y, lw=0.9, color=f"C{j}", label=label)
        ax.set_ylabel(name if comp is None else f"{name}[{comp}]", fontsize=8)
        ax.grid(True, alpha=0.3)
    axes[0, 0].legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.005, 1.0),
                      borderaxespad=0.0)
    axes[-1, 0].set_xlabel("t")
    axes[0, 0].set_title(f"{title}: {len(pick)} of {len(res)} members", fontsize=9)
    fig.tight_layout()
    return fig


def _positive(a):
    """a with entries <= 0 as NaN (gaps on a log axis)."""
    a = np.asarray(a, dtype=float)
    return np.where(a > 0, a, np.nan)


def _title(res, source) -> str:
    mod = str(res.attrs.get("module", "")) or Path(source).name
    failed = int(np.asarray(res.failed).sum())
    return f"{mod}, {len(res)} members" + (f" ({failed} failed)" if failed else "")


def _file_part(name: str) -> str:
    return "".join(c if c.isalnum() or c in "_-" else "_" for c in name).strip("_")
