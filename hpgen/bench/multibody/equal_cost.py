"""Energy error at equal cost: comparisons of runners' (cost, band) points on one chain.

A row is a dict with at least ``runner``, ``cost`` (seconds of stepping per simulated second),
``band`` (the energy band, any normalisation shared by the rows compared) and ``stable``;
unstable rows and rows with a zero band are left out of every comparison.

- :func:`band_at` / :func:`cost_at`: a peer's band at a cost / cost at a band, interpolated
  log-log between its rows (piecewise linear in log cost - log band; None outside its range:
  no extrapolation);
- :func:`compare`: for one row, the ratio of its band to the peer's at equal cost and of its
  cost to the peer's at equal band (below 1: the row wins), and which of the peer's rows it
  dominates (cost and band both at most the peer row's) or is dominated by;
- :func:`summary`: over several rows against one peer, the best of those ratios;
- :func:`crossover`: the N at which a ratio measured at several N crosses 1 (log-log
  interpolation between neighbouring N).
"""
from __future__ import annotations

import math

import numpy as np


def usable(rows) -> list:
    """The stable rows with a finite positive cost and band."""
    return [r for r in rows if r["stable"] and r["band"] > 0 and np.isfinite(r["band"])
            and r["cost"] > 0 and np.isfinite(r["cost"])]


def _loglog(x: float, pts) -> float | None:
    """y at x of points (x_i, y_i), piecewise linear in (log x, log y); None outside
    [min x_i, max x_i] or with fewer than two points. Points of equal x keep the smaller y."""
    best: dict = {}
    for a, b in pts:
        best[a] = min(b, best.get(a, math.inf))
    if len(best) < 2 or not min(best) <= x <= max(best):
        return None
    xs = sorted(best)
    return float(np.exp(np.interp(np.log(x), np.log(xs), np.log([best[a] for a in xs]))))


def band_at(cost: float, peer_rows) -> float | None:
    """The peer's band at ``cost`` (log-log between its usable rows) or None outside them."""
    return _loglog(cost, [(r["cost"], r["band"]) for r in usable(peer_rows)])


def cost_at(band: float, peer_rows) -> float | None:
    """The peer's cost at ``band`` (log-log along its frontier) or None outside it. The
    frontier: the usable rows by rising cost, each kept only when its band is below every
    cheaper row's (a dearer, less accurate row is dominated), so the cost is one-valued."""
    rows = sorted(usable(peer_rows), key=lambda r: r["cost"])
    kept: list = []
    for r in rows:
        if not kept or r["band"] < kept[-1]["band"]:
            kept.append(r)
    return _loglog(band, [(r["band"], r["cost"]) for r in kept])


def compare(row: dict, peer_rows) -> dict:
    """``band_ratio`` row band / peer band at the row's cost, ``cost_ratio`` row cost / peer
    cost at the row's band (None where the peer's rows do not reach), ``dominates`` /
    ``dominated_by``: the peer rows' step sizes ``h`` that this row beats on both counts or
    that beat it on both."""
    peers = usable(peer_rows)
    b, c = band_at(row["cost"], peers), cost_at(row["band"], peers)
    return dict(band_ratio=None if b is None else row["band"] / b,
                cost_ratio=None if c is None else row["cost"] / c,
                dominates=[p["h"] for p in peers
                           if row["cost"] <= p["cost"] and row["band"] <= p["band"]],
                dominated_by=[p["h"] for p in peers
                              if p["cost"] <= row["cost"] and p["band"] <= row["band"]])


def summary(rows, peer_rows) -> dict:
    """The best (smallest) band ratio at equal cost and cost ratio at equal band of ``rows``
    against the peer, each with its row's runner and h (None where no row is in the peer's
    range), and ``wins``: whether some row has a ratio below 1 or dominates a peer row."""
    out: dict = dict(band_ratio=None, band_row=None, cost_ratio=None, cost_row=None,
                     wins=False)
    for r in usable(rows):
        cmp = compare(r, peer_rows)
        for key in ("band", "cost"):
            value = cmp[f"{key}_ratio"]
            if value is not None and (out[f"{key}_ratio"] is None or value < out[f"{key}_ratio"]):
                out[f"{key}_ratio"], out[f"{key}_row"] = value, (r["runner"], r["h"])
        out["wins"] = out["wins"] or bool(cmp["dominates"]) or any(
            v is not None and v < 1 for v in (cmp["band_ratio"], cmp["cost_ratio"]))
    return out


def crossover(ns, ratios) -> float | None:
    """The N where ``ratios`` (one per N, ascending N; None: not measured) first falls
    through 1, interpolated linearly in (log N, log ratio) between the two neighbouring
    measured N; the first N when it is already below 1 there; None when it never is."""
    pts = [(n, r) for n, r in zip(ns, ratios) if r is not None and r > 0]
    for i, (n, r) in enumerate(pts):
        if r < 1:
            if i == 0:
                return float(n)
            n0, r0 = pts[i - 1]
            f = math.log(r0) / (math.log(r0) - math.log(r))
            return float(math.exp(math.log(n0) + f * (math.log(n) - math.log(n0))))
    return None


def plot(panels, path, title="energy band against cost") -> None:
    """A work-precision figure: one panel per (N, T, rows), band against ms per simulated
    second, log-log, a line per runner (its usable rows by cost)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels), 4.2), squeeze=False)
    runners = list(dict.fromkeys(r["runner"] for _, _, rows in panels for r in rows))
    colour = {name: f"C{i % 10}" for i, name in enumerate(runners)}
    for ax, (n, T, rows) in zip(axes[0], panels):
        for runner in runners:
            pts = sorted(usable([r for r in rows if r["runner"] == runner]),
                         key=lambda r: r["cost"])
            if pts:
                ax.loglog([1e3 * r["cost"] for r in pts], [r["band"] for r in pts],
                          marker="o" if runner.startswith("hpgen") else "s", label=runner,
                          color=colour[runner])
        ax.set(xlabel="ms of stepping per simulated s", ylabel="energy band / (E0 - V_rest)",
               title=f"N = {n}, T = {T:g}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
