"""``hpgen recommend MODEL --error E --T T``: which of hpgen's schemes reaches the error E over
the horizon T at the least cost, from a short measured run.

For every candidate scheme (the splitting schemes when the model has their structure,
hpgen.splitting.structure; the VPRK schemes of the bench's default grid):

1. the error at the short horizon Ts = min(T, TS_MAX) of runs with steps h and h/2, against
   the bench's reference (exact free body, else DOP853 at rtol = atol = 1e-13), starting
   from the scene's h and halving (doubling) h until both errors lie between the
   reference floor and 0.1 and their slope is the scheme's order within SLOPE_TOL;
2. the error model err(t, h) = C t h^p (p the scheme's order, C from the run at h/2): the
   global error of a symplectic scheme on a (near-)integrable problem grows about linearly
   in t. The step for the target is h* = (E / (C T))^(1/p), the cost (T / h*) times the
   measured time per step (C backend, the median of repeated runs at h/2);
3. the ranking by that cost. A scheme whose errors never enter the asymptotic range is
   listed as not measurable, with the reason.

The prediction is an extrapolation: check it with ``hpgen bench`` at the recommended h over
T when it matters (chaotic motion makes the linear growth optimistic).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from ..errors import HpgenError, ModelError
from .measure import Timing, steps_for

#: the short horizon's upper bound (model time units)
TS_MAX = 10.0
#: errors below this count as the reference floor
FLOOR = 1e-11
#: the splittings and VPRK schemes tried, cheapest family first
SPLITTINGS = ("split2", "split4-suzuki", "split6-kahan-li", "split8-kahan-li",
              "split4-blanes-moan-fasso", "split6-blanes-moan-fasso")
VPRK = (("stormer-verlet", None, None), ("gauss2", "cay", "exact"), ("gauss3", "cay", "exact"))
MAX_HALVINGS = 8
#: how far the measured slope may miss the order (high orders approach it from below)
SLOPE_TOL = 1.0


@dataclass
class Candidate:
    """One scheme's measurement and prediction (h_star, steps, seconds None when not
    measurable: ``why`` says why)."""
    label: str
    order: int
    explicit: bool
    h: float = math.nan
    errors: tuple = ()
    slope: float = math.nan
    constant: float = math.nan
    step_s: float = math.nan
    h_star: float | None = None
    steps: int | None = None
    seconds: float | None = None
    why: str = ""


def _measure(integ, pb, y_ref, order, kw, Ts, timing):
    """(h, (e_h, e_h/2), slope, C, seconds per step) in the asymptotic range, or raises
    ValueError with the reason."""
    def err(h):
        steps, hu = steps_for(Ts, h)
        tr = integ.simulate(h=hu, steps=steps, every=steps, **kw)
        return pb.error(pb.pack(tr.g[-1], tr.mu[-1]), y_ref), steps, hu
    h = float(pb.scene.h)
    last = "no step size tried"
    for _ in range(MAX_HALVINGS):
        (e1, _, h1), (e2, steps2, h2) = err(h), err(h / 2)
        if not (math.isfinite(e1) and math.isfinite(e2)) or e1 > 0.1:
            last = f"error {e1:.2g} at h = {h1:.3g}"
            h /= 2
            continue
        if e2 < FLOOR:
            last = f"error {e2:.2g} at h = {h2:.3g} is at the reference floor"
            h *= 4
            continue
        slope = math.log2(e1 / e2) if e2 > 0 else math.inf
        if abs(slope - order) > SLOPE_TOL:
            last = f"slope {slope:.2f} between h = {h1:.3g} and {h2:.3g} (order {order})"
            h /= 2
            continue
        t_run = timing.median(lambda: integ.simulate(h=h2, steps=steps2, every=steps2, **kw))[0]
        return h2, (e1, e2), slope, e2 / (Ts * h2 ** order), t_run / steps2
    raise ValueError(last)


def recommend(path, error, T, cache_dir=None, log=None, timing=Timing(0.05, 3, 0.5),
              candidates=None):
    """[Candidate] ranked by predicted seconds (not measurable last), and a dict of notes:
    reference, Ts. ``candidates``: [(tableau or splitting name, tau, rkmk)] instead of
    SPLITTINGS and VPRK (tau, rkmk None: the model's). ModelError on bad input."""
    import hpgen
    from .problem import Problem, positive
    error = positive(error, "option error")
    if not error < 1.0:
        raise ModelError(f"expected an error < 1, got {error!r}", field="option error")
    T = positive(T, "option T")
    log = log or (lambda s: None)
    Ts = min(T, TS_MAX)
    pb = Problem(path, Ts)
    if not pb.conservative:
        raise ModelError("hpgen recommend ranks schemes of closed, conservative models (no "
                         "forces, inputs or t)", file=str(path), field="option model")
    y_ref, ref_text = pb.reference("auto", lambda t, y: np.asarray(pb.f(t, y)).ravel())
    kw = {"g0": pb.g0, **({"xi0": pb.xi0} if pb.xi0 is not None else {"mu0": pb.mu0})}
    from ..splitting import get_splitting, is_splitting
    from ..tableaus import get_tableau
    ic = pb.model.integrator
    tries = []
    for tab, tau, rkmk in (candidates if candidates is not None else
                           [(s, None, None) for s in SPLITTINGS] + list(VPRK)):
        if is_splitting(tab):
            tries.append((tab, None, None, get_splitting(tab).order, True))
            continue
        tau, rkmk = tau or ic.tau, rkmk or ic.rkmk
        order = get_tableau(tab).order if rkmk == "exact" else min(get_tableau(tab).order, 2)
        tries.append((tab, tau, rkmk, order, False))
    out = []
    for tab, tau, rkmk, order, explicit in tries:
        label = tab if explicit else f"{tab}/{tau}/{rkmk}"
        c = Candidate(label, order, explicit)
        t0 = time.perf_counter()
        try:
            integ = hpgen.build(path, tableau=tab, tau=tau, rkmk=rkmk, backend="c",
                               cache_dir=cache_dir).load()
        except ModelError as e:
            if explicit:
                log(f"  {label}: not applicable ({e.message})")
                continue
            raise
        try:
            c.h, c.errors, c.slope, c.constant, c.step_s = _measure(
                integ, pb, y_ref, order, kw, Ts, timing)
        except (ValueError, HpgenError, ArithmeticError) as e:
            c.why = str(e)
        else:
            c.h_star = (error / (c.constant * T)) ** (1.0 / order)
            c.steps = max(1, math.ceil(T / c.h_star))
            c.seconds = c.steps * c.step_s
        log(f"  {label}: measured in {time.perf_counter() - t0:.1f} s")
        out.append(c)
    out.sort(key=lambda c: (c.seconds is None, c.seconds or 0.0))
    return out, {"reference": ref_text, "Ts": Ts}


def report(cands, notes, error, T) -> str:
    """The ranking as Markdown and the recommendation with its reasons."""
    lines = [f"Schemes ranked by the predicted time to reach error {error:g} over T = {T:g} "
             f"(measured over Ts = {notes['Ts']:g} against {notes['reference']}; error model "
             "C t h^p):", "",
             "| rank | scheme | order | C | h for the target | steps | predicted time | "
             "time per step |", "|---|---|---|---|---|---|---|---|"]
    for i, c in enumerate(cands, 1):
        if c.seconds is None:
            lines.append(f"| - | {c.label} | {c.order} | - | - | - | not measurable: {c.why} "
                         "| - |")
            continue
        lines.append(f"| {i} | {c.label} | {c.order} | {c.constant:.3g} | {c.h_star:.4g} | "
                     f"{c.steps:,} | {_seconds(c.seconds)} | {c.step_s * 1e9:,.0f} ns |")
    ok = [c for c in cands if c.seconds is not None]
    if not ok:
        lines += ["", "no scheme could be measured: see the reasons above"]
        return "\n".join(lines)
    best = ok[0]
    why = [f"the least predicted time ({_seconds(best.seconds)}"
           + (f", {ok[1].seconds / best.seconds:.2g}x less than {ok[1].label}" if len(ok) > 1
              else "") + ")"]
    why.append("explicit (no Newton), symplectic, keeps the group and the momentum maps of "
               "symmetric potentials" if best.explicit else
               "variational (symplectic, momentum maps kept), implicit")
    lines += ["", f"recommendation: {best.label} with h = {best.h_star:.4g} "
              f"({best.steps:,} steps): " + "; ".join(why) + ". Check with `hpgen bench "
              f"MODEL --T {T:g} --tableau {best.label.split('/')[0]} --h {best.h_star:.4g}`."]
    return "\n".join(lines)


def _seconds(s):
    return f"{s * 1e3:.3g} ms" if s < 1 else f"{s:.3g} s"


def cmd_recommend(args) -> int:
    import sys
    from .cli import _number
    cands, notes = recommend(args.model, _number(args.error, "option error"),
                             _number(args.T, "option T"), cache_dir=args.cache_dir,
                             log=lambda s: print(s, file=sys.stderr, flush=True))
    print(report(cands, notes, float(args.error), float(args.T)))
    return 0
