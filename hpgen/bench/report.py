"""Tables, the figure and the equal-error comparisons of a benchmark run.

Files written into the output directory:
- ``work_precision.csv``: one row per point, columns CSV_COLUMNS: method, family, kind
  (hpgen | peer), parameter_name (h | rtol), parameter, error, energy_drift, group_defect,
  wall_time_s (median), steps_per_s, f_evals (empty when not counted), repeats, setup_s (not
  in wall_time_s), notes ('; '-separated). Numbers in repr precision; NaN for "not
  available" (a failed point, or no reference).
- ``work_precision.md``: the same points as a Markdown table with MD_COLUMNS, then the
  setup times and the equal-error comparisons.
- ``work_precision.png``: error against wall time, log-log, one line per family
  (matplotlib, Agg backend, imported only here): hpgen solid, general ODE peers dashed, the
  structure-preserving rigid-body peers (STRUCTURE_PEERS) dash-dotted.

Equal error: a peer's time at error e is read off its Pareto front (the points no other
point of the family beats in both error and time: the setting a user would pick), by linear
interpolation of log(time) in log(error) between the two front points around e; "no
overlap" when e is outside the front's error range. ratio = that time / hpgen's time (> 1:
hpgen is faster at equal error). Every figure comes from the same run.
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from .rigid import FAMILIES as STRUCTURE_PEERS

CSV_COLUMNS = ("method", "family", "kind", "parameter_name", "parameter", "error",
               "energy_drift", "group_defect", "wall_time_s", "steps_per_s", "f_evals",
               "repeats", "setup_s", "notes")
MD_COLUMNS = ("method", "parameter (h or rtol)", "error", "energy drift", "group defect",
              "wall time s", "steps/s or f-evals", "notes")


def _usable(p):
    return p.ok and math.isfinite(p.error) and p.error > 0 and p.wall_s > 0


def pareto(points):
    """[(error, time)] of the Pareto front, error ascending (time then descending)."""
    front, best = [], math.inf
    for p in sorted((p for p in points if _usable(p)), key=lambda p: (p.wall_s, p.error)):
        if p.error < best:
            front.append((p.error, p.wall_s))
            best = p.error
    return sorted(front)


def time_at_error(points, e):
    """The family's time at error e (log-log interpolation on its Pareto front) or None."""
    front = pareto(points)
    if not front or not (math.isfinite(e) and e > 0):
        return None
    errs = np.log([a for a, _ in front])
    times = np.log([b for _, b in front])
    le = math.log(e)
    if le < errs[0] - 1e-12 or le > errs[-1] + 1e-12:
        return None
    return float(math.exp(np.interp(le, errs, times)))


def families(points, kind=None):
    """{family: [points]} in first-seen order."""
    out = {}
    for p in points:
        if kind is None or p.kind == kind:
            out.setdefault(p.family, []).append(p)
    return out


def comparisons(points):
    """[(hpgen point, {peer family: ratio or None})] for every usable hpgen point."""
    peers = families(points, "peer")
    rows = []
    for p in points:
        if p.kind == "hpgen" and _usable(p):
            rows.append((p, {fam: (None if (t := time_at_error(pts, p.error)) is None
                                   else t / p.wall_s) for fam, pts in peers.items()}))
    return rows


# ---- formatting -----------------------------------------------------------------------
def _e(x):
    return "-" if x is None or not math.isfinite(x) else f"{x:.2e}"


def _param(p):
    return f"{p.param_name} = {p.param:.4g}"


def _rate(p):
    if p.param_name == "h":
        return "-" if not math.isfinite(p.steps_per_s) else f"{p.steps_per_s:.3g} steps/s"
    return "-" if p.f_evals is None else f"{p.f_evals} f-evals"


def _ratio(r):
    return "no overlap" if r is None else f"{r:.3g}x"


def md_table(points):
    rows = ["| " + " | ".join(MD_COLUMNS) + " |", "|" + "---|" * len(MD_COLUMNS)]
    for p in points:
        rows.append("| " + " | ".join([p.method, _param(p), _e(p.error), _e(p.energy_drift),
                                       _e(p.group_defect), _e(p.wall_s), _rate(p),
                                       "; ".join(p.notes)]) + " |")
    return "\n".join(rows)


def comparison_table(points):
    rows = comparisons(points)
    peers = list(families(points, "peer"))
    if not rows or not peers:
        return "(no hpgen point with a finite error, or no peer: nothing to compare)"
    head = ["hpgen scheme", "h", "error", "hpgen time s"] + [f"{f} / hpgen" for f in peers]
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for p, r in rows:
        out.append("| " + " | ".join([p.family, f"{p.param:.4g}", _e(p.error), _e(p.wall_s)]
                                     + [_ratio(r[f]) for f in peers]) + " |")
    return "\n".join(out)


def setup_table(points):
    """Setup seconds: once per hpgen scheme and per C-vector-field family (shared), per
    point for the CasADi integrators (constructed per tolerance / h)."""
    out, seen = ["| method | setup s (not in wall time) |", "|---|---|"], set()
    for p in points:
        per_point = p.family.startswith("cvodes") or p.family == "collocation"
        key = (p.family, p.param) if per_point else p.family
        if key in seen:
            continue
        seen.add(key)
        what = f"{p.method}, {_param(p)}" if per_point else p.method
        if p.family in ("DOP853", "RK45", "RK4-numpy", "RK4-C"):
            what += " (C vector field: emit, build, load; shared)"
        elif p.family in STRUCTURE_PEERS:
            what += " (hand-written rigid.c: build, load; shared)"
        if p.setup_note:
            what += f" ({p.setup_note})"
        out.append(f"| {what} | {_e(p.setup_s)} |")
    return "\n".join(out)


def markdown(result):
    r = result
    lines = [f"# Work-precision benchmark: {r.model_name}", "",
             f"Model file `{r.path}`, T = {r.T:g}, initial state from the scene. "
             f"Reference at T: {r.reference}.", "",
             "Error = max(|g - g_ref|max, |mu - mu_ref|max) at T (mu: hpgen's node momentum "
             "p_N). Energy drift = max |E - E(0)| over the samples of a separate untimed run "
             "(fixed-step methods: every max(1, steps // "
             f"{r.samples})-th node and the end; SciPy: its accepted steps thinned to about "
             f"{r.samples}; CasADi: an output grid). Group defect |R^T R - I|-type distance at "
             "T. Wall time: median of repeats in one process "
             f"({r.timing_rule}), setup excluded.", "",
             md_table(r.points), "", "## Setup (compile, build, construction)", "",
             setup_table(r.points), "", "## hpgen against each peer at equal error", "",
             "peer time at hpgen's error (log-log interpolation on the peer's Pareto front) "
             "divided by hpgen's time; > 1: hpgen faster.", "", comparison_table(r.points)]
    if r.notes:
        lines += ["", "Notes: " + " ".join(r.notes)]
    lines.append("")
    return "\n".join(lines)


def write_csv(points, path: Path):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_COLUMNS)
        for p in points:
            w.writerow([p.method, p.family, p.kind, p.param_name, repr(p.param), repr(p.error),
                        repr(p.energy_drift), repr(p.group_defect), repr(p.wall_s),
                        repr(p.steps_per_s), "" if p.f_evals is None else p.f_evals,
                        p.repeats, repr(p.setup_s), "; ".join(p.notes)])


def write_png(result, path: Path):
    """Error against wall time (log-log), one line per family; False if matplotlib is
    missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return False
    fig = draw_work_precision(plt, result.points, f"{result.model_name}, T = {result.T:g}")
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def draw_work_precision(plt, points, title):
    """The work-precision figure of ``points`` (objects with family, kind, ok, error, wall_s;
    hpgen.bench.measure.Point or rows read back by hpgen.plot) with pyplot ``plt``."""
    fig, ax = plt.subplots(figsize=(8, 5.5))
    drawn = 0
    for fam, pts in families(points).items():
        pts = sorted((p for p in pts if _usable(p)), key=lambda p: p.wall_s)
        if not pts:
            continue
        style = ("-o" if pts[0].kind == "hpgen" else "-.^" if fam in STRUCTURE_PEERS
                 else "--s")
        ax.loglog([p.wall_s for p in pts], [p.error for p in pts], style, label=fam, ms=4)
        drawn += 1
    ax.set_xlabel("wall time [s] (median)")
    ax.set_ylabel("error at T: max(|g - g_ref|, |mu - mu_ref|)")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    if drawn:
        ax.legend(fontsize=7)
    else:
        ax.text(0.5, 0.5, "no point with a finite error (no reference?)", ha="center",
                transform=ax.transAxes)
    fig.tight_layout()
    return fig
