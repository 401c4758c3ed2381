"""``run_bench``: the work-precision benchmark of a model's scene.

    from hpgen.bench import run_bench
    res = run_bench("examples/heavy_top.yaml", T=10, out="bench-heavy_top")
    res.points, res.comparisons(), res.markdown()

Grids (API lists, or comma lists on the CLI), defaults from the scene's h = h0:
- hpgen schemes: ``schemes`` [(tableau, tau, rkmk)], or the product of ``tableau`` x ``tau``
  x ``rkmk`` lists (a missing one: the model's default), else DEFAULT_SCHEMES
  (stormer-verlet/cay/truncated, gauss2/exp/exact, gauss2/cay/exact, gauss3/cay/exact) and,
  when the model has their structure (l = 1/2 xi.M xi - V(g)), the explicit splittings
  DEFAULT_SPLITTINGS. Catalog names (tableaus and splitting schemes) only.
- ``h`` (hpgen): h0 * 2^-k, k = -1..4 (one step coarser than the scene's h: where the
  6th-order schemes reach errors around 1e-6); ``rk4_h``: as ``h``; ``collocation_h``:
  h0 * 2^-k, k = 0..2. Every h is turned into steps = round(T / h), h = T / steps (noted if it moves).
- ``rtol`` (SciPy DOP853 / RK45) and ``cvodes_tol``: 1e-4, 1e-6, ..., 1e-12 (``cvodes_tol``
  defaults to ``rtol``); atol = rtol * 1e-3 (hpgen.bench.peers.ATOL_FACTOR).
- ``peers``: names of hpgen.bench.peers.PEERS (default all; the rigid-body C peers
  splitting-2/4/6 and RATTLE are skipped, with a note, on a model they do not fit).
Reference: ``reference`` = auto (exact solution when hpgen.analysis.exact has one, else
DOP853 at rtol = atol = 1e-13 on the same f), exact, dop853 or none; computed once per run.
Forced and time-dependent models (forces, inputs, runtime parameters, t): every method
integrates the continuous forced equations (hpgen.bench.problem) with the default runtime
parameters, t0 = 0 and a constant u (``u``, else the scene's); no energy drift is reported
for them (the energy is not conserved), and the rigid-body peers are skipped.
Bad input (file, scene, grid values, names) raises ModelError before anything is built.
"""
from __future__ import annotations

import itertools
import math
import numbers
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import ModelError
from . import report
from .measure import Timing
from .peers import PEERS

DEFAULT_RTOL = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
REFERENCES = ("auto", "exact", "dop853", "none")
MAX_STEPS = 2 ** 31 - 1


@dataclass
class BenchResult:
    """Everything one run measured. points: [hpgen.bench.measure.Point]; files: paths
    written (empty when write=False)."""
    model_name: str
    path: str
    T: float
    reference: str
    samples: int
    timing_rule: str
    points: list
    notes: list = field(default_factory=list)
    files: list = field(default_factory=list)

    def comparisons(self):
        return report.comparisons(self.points)

    def markdown(self) -> str:
        return report.markdown(self)

    def family(self, name):
        return [p for p in self.points if p.family == name]


# ---- input checking ---------------------------------------------------------------------
def parse_list(text, field, convert=float):
    """A comma list from the CLI -> list (ModelError naming ``field`` on a bad item)."""
    if text is None:
        return None
    items = [s.strip() for s in str(text).split(",")]
    try:
        return [convert(s) for s in items if s] or _empty(field)
    except ValueError:
        raise ModelError(f"expected a comma-separated list, got {text!r}", field=field) \
            from None


def _empty(field):
    raise ModelError("expected at least one value", field=field)


def _grid(values, field, upper=None):
    if values is None:
        return None
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        values = [values]
    values = list(values)
    if not values:
        _empty(field)
    for v in values:
        if isinstance(v, bool) or not isinstance(v, numbers.Real) or not (
                math.isfinite(v) and v > 0 and (upper is None or v < upper)):
            bound = f" and < {upper:g}" if upper is not None else ""
            raise ModelError(f"expected finite numbers > 0{bound}, got {v!r}", field=field)
    return [float(v) for v in values]


def _names(values, field, choices):
    if values is None:
        return None
    if isinstance(values, str):
        values = [values]
    values = list(values)
    if not values:
        _empty(field)
    for v in values:
        if v not in choices:
            raise ModelError(f"expected some of {', '.join(choices)}, got {v!r}", field=field)
    return values


def _peer_names(values):
    if values is None:
        return list(PEERS)
    lower = {p.lower(): p for p in PEERS}
    if isinstance(values, str):
        values = [values]
    values = list(values)
    for v in values:
        if not isinstance(v, str) or v.lower() not in lower:
            raise ModelError(f"expected some of {', '.join(PEERS)}, got {v!r}",
                             field="option peers")
    return [lower[v.lower()] for v in values]


def _scheme_grid(model, schemes, tableau, tau, rkmk):
    from .schemes import DEFAULT_SCHEMES, validate_schemes
    if schemes is not None:
        return validate_schemes([tuple(s) for s in schemes])
    if tableau is None and tau is None and rkmk is None:
        return validate_schemes(list(DEFAULT_SCHEMES) + _default_splittings(model))
    ic = model.integrator
    tabs = [tableau] if isinstance(tableau, str) else list(tableau or [ic.tableau])
    taus = [tau] if isinstance(tau, str) else list(tau or [ic.tau])
    rks = [rkmk] if isinstance(rkmk, str) else list(rkmk or [ic.rkmk])
    return validate_schemes(list(itertools.product(tabs, taus, rks)))


def _default_splittings(model):
    """The splitting schemes the default grid adds when the model has their structure
    (hpgen.splitting.structure), else none."""
    from ..derive.lagrangian import lagrangian_function
    from ..splitting.structure import recognise
    from .schemes import DEFAULT_SPLITTINGS
    if model.open_system or model.constraints:
        return []
    try:
        recognise(model, lagrangian_function(model))
    except ModelError:
        return []
    return [(s, "cay", "exact") for s in DEFAULT_SPLITTINGS]


def _check_steps(T, hs, field):
    for h in hs or ():
        if T / h > MAX_STEPS:
            raise ModelError(f"T / h = {T / h:.3g} steps is more than {MAX_STEPS}", field=field)


# ---- the run ----------------------------------------------------------------------------
def run_bench(model, *, T=None, schemes=None, tableau=None, tau=None, rkmk=None, h=None,
              rtol=None, cvodes_tol=None, collocation_h=None, rk4_h=None, peers=None,
              reference="auto", out=None, cache_dir=None, samples=200, min_time=0.2,
              min_repeats=3, max_time=1.0, write=True, log=None, u=None) -> BenchResult:
    """Run the benchmark (see the module docstring); write the files into ``out`` (default
    bench-<model name>/) unless write=False. ``log``: progress callback (default: stderr).
    ``u``: the constant inputs (m,) of a model with inputs (default: the scene's u)."""
    from .problem import Problem, positive

    log = log or (lambda s: print(s, file=sys.stderr, flush=True))
    hs = _grid(h, "option h")
    rtols = _grid(rtol, "option rtol", upper=1.0)
    ctols = _grid(cvodes_tol, "option cvodes_tol", upper=1.0)
    chs = _grid(collocation_h, "option collocation_h")
    rhs_ = _grid(rk4_h, "option rk4_h")
    peers = _peer_names(peers)
    tableau = _names(tableau, "option tableau", _tableau_names())
    if reference not in REFERENCES:
        raise ModelError(f"expected one of {', '.join(REFERENCES)}, got {reference!r}",
                         field="option reference")
    if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
        raise ModelError(f"expected an integer >= 1, got {samples!r}", field="option samples")
    timing = Timing(positive(min_time, "option min_time") if min_time else 0.0,
                    max(1, int(min_repeats)), positive(max_time, "option max_time"))
    if T is not None:
        T = positive(T, "option T")

    t_start = time.perf_counter()
    pb = Problem(model, T, u=u)
    sc = pb.scene
    if reference == "exact" and pb.exact_inertia() is None:
        pb.reference("exact", None)           # raises the ModelError, before any build
    from .schemes import hpgen_points, ladder
    schemes = _scheme_grid(pb.model, schemes, tableau, tau, rkmk)
    hs = hs or ladder(2.0 * sc.h, 5)
    rhs_ = rhs_ or hs
    chs = chs or ladder(sc.h, 2)
    rtols = rtols or list(DEFAULT_RTOL)
    ctols = ctols or rtols
    for grid, fld in ((hs, "option h"), (rhs_, "option rk4_h"), (chs, "option collocation_h")):
        _check_steps(pb.T, grid, fld)

    from .crk4 import CRK4
    from .peers import (RIGID_PEERS, collocation_points, cvodes_points, rk4_points,
                        scipy_points)
    from .rigid import RigidPeers, rigid_parameters, rigid_points
    log(f"hpgen bench {pb.model.name}: T = {pb.T:g}, {len(schemes)} schemes x {len(hs)} h, "
        f"peers {', '.join(peers)}")
    crk4 = CRK4(pb, cache_dir)
    log(f"  C vector field + RK4 built in {crk4.setup_s:.2f} s")
    t0 = time.perf_counter()
    y_ref, ref_text = pb.reference(reference, crk4.rhs)
    ref_text += f", {time.perf_counter() - t0:.2f} s"
    log(f"  reference: {ref_text}")

    points = hpgen_points(pb, y_ref, schemes, hs, timing, samples, cache_dir, log)
    notes, rigid = list(pb.notes), None
    if not pb.conservative:
        notes.append("forced or time-dependent model: the energy is not conserved, no energy "
                     "drift is reported; every method integrates the forced equations"
                     + ("" if pb.u is None else f" with u = {pb.u.tolist()}"))
    if any(name in RIGID_PEERS for name in peers):
        body = rigid_parameters(pb.eq)
        if body is None:
            skipped = [name for name in peers if name in RIGID_PEERS]
            peers = [name for name in peers if name not in RIGID_PEERS]
            notes.append(f"{', '.join(skipped)} skipped: they need an SO3 body with "
                         "l = 1/2 xi.diag(I) xi - m.(R^T e3) and no forces")
        else:
            rigid = RigidPeers(*body, cache_dir)
            log(f"  rigid-body peers (C) built in {rigid.setup_s:.2f} s")
    for name in peers:
        log(f"  {name} ...")
        if name in ("DOP853", "RK45"):
            points += scipy_points(pb, y_ref, crk4, name, rtols, timing, samples)
        elif name.startswith("cvodes-"):
            points += cvodes_points(pb, y_ref, name.split("-")[1], ctols, timing, samples)
        elif name == "collocation":
            points += collocation_points(pb, y_ref, chs, timing, samples)
        elif name in RIGID_PEERS:
            points += rigid_points(pb, y_ref, rigid, name, rhs_, timing, samples)
        else:
            points += rk4_points(pb, y_ref, crk4, rhs_, timing, samples, name)
    rule = (f"repeats until >= {timing.min_repeats} runs and >= {timing.min_time:g} s, or "
            f">= {timing.max_time:g} s")
    res = BenchResult(pb.model.name, pb.path, pb.T, ref_text, samples, rule, points,
                      notes=notes)
    if write:
        res.files = write_files(res, Path(out) if out else Path(f"bench-{pb.model.name}"))
    log(f"  done in {time.perf_counter() - t_start:.1f} s")
    return res


def _tableau_names():
    from ..splitting import SPLITTING_NAMES
    from ..tableaus import TABLEAU_NAMES
    return TABLEAU_NAMES + SPLITTING_NAMES


def write_files(res: BenchResult, out: Path) -> list:
    """work_precision.csv, .md and .png into ``out`` (created); returns the paths."""
    try:
        out.mkdir(parents=True, exist_ok=True)
        files = [out / "work_precision.csv", out / "work_precision.md"]
        report.write_csv(res.points, files[0])
        files[1].write_text(res.markdown())
    except OSError as e:
        raise ModelError(f"cannot write the results ({e.strerror})", file=str(out)) from None
    png = out / "work_precision.png"
    if report.write_png(res, png):
        files.append(png)
    else:
        res.notes.append("matplotlib is not installed: no work_precision.png")
    return files
