"""One benchmark point: run a method, time it, and compute its figures.

Timing rule (``Timing``): after one untimed run (the sampled run below, or a warm-up), the
timed run is repeated until there are at least ``min_repeats`` runs and ``min_time`` seconds
in total, or ``max_time`` seconds in total, whichever comes first; the wall time is the
median (time.perf_counter, garbage collector off while timing). Every method is timed this
way in the same process. Setup (hpgen compile, C build, CasADi integrator construction) is
never inside the timed call; it is reported as ``setup_s``.

Samples: each method gives the states on which the energy drift is taken: the nodes of a
fixed-step run recorded every max(1, steps // samples) steps (plus the final state), the
accepted steps of a SciPy run (thinned by index to about ``samples``), or an output grid of
``samples`` equal intervals for CasADi integrators (see hpgen.bench.peers).
"""
from __future__ import annotations

import gc
import math
import statistics
import time
from dataclasses import dataclass, field

import numpy as np

from ..errors import HpgenError

#: exceptions that make a point "failed" instead of stopping the benchmark
FAILURES = (HpgenError, RuntimeError, ArithmeticError, np.linalg.LinAlgError)


@dataclass(frozen=True)
class Timing:
    min_time: float = 0.2
    min_repeats: int = 3
    max_time: float = 1.0

    def median(self, fn):
        """(median seconds, repeats, last result of fn())."""
        times, total = [], 0.0
        enabled = gc.isenabled()
        gc.disable()
        try:
            while True:
                t0 = time.perf_counter()
                out = fn()
                dt = time.perf_counter() - t0
                times.append(dt)
                total += dt
                if (len(times) >= self.min_repeats and total >= self.min_time) \
                        or total >= self.max_time:
                    break
        finally:
            if enabled:
                gc.enable()
        return statistics.median(times), len(times), out


@dataclass
class Point:
    """One (method, parameter) of the benchmark. kind: 'hpgen' or 'peer'; family: the
    plot/comparison group (one hpgen scheme, or one peer method); param_name: 'h', 'rtol' or
    'tol'. error / energy_drift / group_defect are NaN when not available (failed run, no
    reference). samples: (t (K,), Y (K, ny)) of the sampled run."""
    method: str
    family: str
    kind: str
    param_name: str
    param: float
    error: float = math.nan
    energy_drift: float = math.nan
    group_defect: float = math.nan
    wall_s: float = math.nan
    repeats: int = 0
    steps: int = 0
    f_evals: int | None = None
    setup_s: float = math.nan
    setup_note: str = ""
    notes: list = field(default_factory=list)
    y_end: np.ndarray | None = field(default=None, repr=False)
    samples: tuple | None = field(default=None, repr=False)

    @property
    def ok(self) -> bool:
        return math.isfinite(self.wall_s) and self.y_end is not None \
            and bool(np.isfinite(self.y_end).all())

    @property
    def steps_per_s(self) -> float:
        return self.steps / self.wall_s if self.ok and self.steps else math.nan


def steps_for(T, h):
    """(steps, h_used = T / steps) with steps = max(1, round(T / h)): every fixed-step
    method (hpgen's schemes and the peers) runs a whole number of steps to T."""
    steps = max(1, int(round(T / h)))
    return steps, T / steps


def fixed_note(h, h_used):
    """The point's note when the requested h moved to T / steps."""
    return [f"h adjusted to T/steps = {h_used:.6g}"] if abs(h_used - h) > 1e-9 * h else []


def thin(t, Y, samples):
    """About ``samples`` + 1 rows of (t, Y) by index stride, always keeping the last."""
    stride = max(1, (len(t) - 1) // max(1, samples))
    idx = np.unique(np.r_[np.arange(0, len(t), stride), len(t) - 1])
    return np.asarray(t)[idx], np.asarray(Y)[idx]


def measure(problem, y_ref, point: Point, timing: Timing, timed, sampled=None) -> Point:
    """Fill ``point``: ``sampled()`` -> (t, Y) runs once untimed (if given); ``timed()`` ->
    (y_T, info) is timed; info may carry 'steps', 'f_evals', 'notes' and, when ``sampled``
    is None, 'samples' = (t, Y). A failure or a non-finite state is recorded in notes."""
    try:
        samples = sampled() if sampled is not None else None
        point.wall_s, point.repeats, (y_end, info) = timing.median(timed)
    except FAILURES as e:
        point.notes.append("failed: " + str(e).splitlines()[0][:160])
        return point
    point.y_end = np.asarray(y_end, dtype=float)
    point.steps = int(info.get("steps", 0))
    point.f_evals = info.get("f_evals")
    point.notes.extend(info.get("notes", ()))
    if samples is None:
        samples = info.get("samples")
    if samples is not None:
        t, Y = samples
        if len(t) == 0 or t[-1] < problem.T * (1 - 1e-12):     # add the final state
            t, Y = np.r_[t, problem.T], np.vstack([Y, point.y_end])
        point.samples = (np.asarray(t), np.asarray(Y))
    if not np.isfinite(point.y_end).all():
        point.notes.append("diverged (non-finite state)")
        return point
    point.error = problem.error(point.y_end, y_ref)
    Ys = point.samples[1] if point.samples is not None else point.y_end[None]
    point.energy_drift = problem.energy_drift(Ys)
    point.group_defect = problem.defect(point.y_end)
    return point
