"""The states output: runs that keep the state (g_k, p_k) every ``every`` steps, as
Trajectory (hpgen.runtime.trajectory): Integrator.simulate, stream and simulate_batch on
the run engine (hpgen.runtime.engine). The backend calls are ``advance`` (hpgen_advance)
and, for ensembles, ``simulate_batch``; simulate takes the C backend's fast path
(hpgen.runtime.prologue) when it applies. numpy and the standard library only.
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from .. import abi
from . import counters, loop
from .args import _error, _fits, _int
from .batch_starts import ExplicitStarts
from .cbatch import status as cbatch_status
from .engine import SLICE_FIRST, Engine, Part, RunArgs, RunStart, Sliced
from .inputs import check_t0
from .progress import bar as progress_bar
from .progress import _NoBar as NoBar
from .trajectory import Trajectory
from .trajectory_list import LazyList


class States:
    """The states output of one run, in chunks of at most ``chunk`` steps."""

    def __init__(self, engine: Engine, s: RunStart, chunk: int):
        self.engine, self.s, self.chunk = engine, s, chunk

    def span(self, k, first):
        if not first and k >= self.s.steps:
            return None
        return (min(self.chunk, self.s.steps - k),)

    def advance(self, run, span) -> Part:
        s = self.s
        done, g_rec, p_rec, st = self.engine.backend.advance(run, s.h, span[0], s.every,
                                                             s.opts)
        return Part(done, (g_rec, p_rec), st)

    def trajectory(self, k, first, part, t_start) -> Trajectory:
        """The Trajectory of one part (the first prepended with the start, record 0)."""
        s = self.s
        g_rec, p_rec = part.data
        if first:
            g_rec = np.concatenate([s.g0.reshape(1, -1), g_rec])
            p_rec = np.concatenate([s.mu0.reshape(1, -1), p_rec])
        tc = (k // s.every + (0 if first else 1)) * s.every * s.h
        return records(self.engine, g_rec, p_rec, part.status, s.h, s.every,
                       t_start + tc if t_start else tc, s.inputs)


def records(engine: Engine, g_rec, p_rec, st, h, every, t0, inputs=None) -> Trajectory:
    """Trajectory of flat column-major records starting at time t0; error set (and its
    .partial) when the status is a failure."""
    K, n = len(p_rec), engine.n
    g = np.ascontiguousarray(g_rec.reshape(K, n, n).transpose(0, 2, 1))
    err = None
    if st["code"] != abi.OK:
        hint = ""
        if st["code"] == abi.DOMAIN and st["iterations"] == 0 and t0 == 0.0:
            hint = engine.first_step.domain_hint(g_rec[0], p_rec[0], None, h)
        err = _error(st["code"], st["step"], st["step"] * h, st["residual"],
                     st["iterations"], hint)
    # t0 + (k every) h; arange(0, K every, every) is arange(K) * every, and adding
    # t0 = 0.0 to these non-negative numbers changes no bit
    t = np.arange(0, K * every, every) * h
    traj = Trajectory.made(t=t0 + t if t0 else t, g=g, mu=np.array(p_rec), h=h,
                           every=every, partial=err is not None, error=err,
                           jacobians=int(st["jacobians"]), **counters.of_status(st),
                           integrator=engine.owner, inputs=inputs)
    if err is not None:
        err.partial = traj
    return traj


def trajectory(engine: Engine, done, g_rec, p_rec, st, h, every, inputs=None,
               t0=0.0) -> Trajectory:
    """The Trajectory of a whole run's records (record 0 the start), ``done`` steps."""
    K = done // every + 1
    return records(engine, np.asarray(g_rec)[:K], np.asarray(p_rec)[:K], st, h, every, t0,
                   inputs)


def stream(engine: Engine, a: RunArgs, chunk=100_000):
    """Integrator.stream: a Trajectory per chunk; raises a failed chunk's error."""
    chunk = _int(chunk, "chunk", 1)
    s = engine.prepare(a)
    yield from _pieces(engine, s, chunk, check_t0(a.t0))


def _pieces(engine: Engine, s: RunStart, chunk: int, t_start: float):
    out = States(engine, s, chunk)
    for k, first, part in engine.parts(out, s):
        traj = out.trajectory(k, first, part, t_start)
        if traj.error is not None:
            raise traj.error
        yield traj


def simulate(engine: Engine, a: RunArgs) -> Trajectory:
    """Integrator.simulate's generic path (every module, backend and argument): the run in
    one piece, advanced in slices (hpgen.runtime.engine.Sliced) so that Ctrl-C interrupts it; a
    KeyboardInterrupt is re-raised with ``.partial``, the Trajectory of the steps done
    (partial=True)."""
    s = engine.prepare(a)
    _fits(s.steps // s.every + 1, engine.n * engine.n + engine.d, "simulate")
    t0 = check_t0(a.t0)
    got: list = []            # (g_rec, p_rec, status) per slice, appended in one operation
    try:
        for _, _, part in engine.parts(Sliced(States(engine, s, SLICE_FIRST)), s):
            got.append((*part.data, part.status))
    except KeyboardInterrupt as exc:
        exc.partial = _joined(  # type: ignore[attr-defined]
            engine, s, list(got), t0, interrupted=True)
        raise
    traj = _joined(engine, s, got, t0)
    if traj.error is not None:
        raise traj.error
    return traj


def _joined(engine: Engine, s: RunStart, got: list, t0: float,
            interrupted=False) -> Trajectory:
    """The Trajectory of a run's slices ``got`` (record 0, the start, prepended); Newton
    totals summed over the slices; partial when ``interrupted``."""
    g_rec = np.concatenate([s.g0.reshape(1, -1), *(g for g, _, _ in got)])
    p_rec = np.concatenate([s.mu0.reshape(1, -1), *(p for _, p, _ in got)])
    st = dict(got[-1][2]) if got else loop.new_status()
    for key in counters.STATUS_TOTALS:
        st[key] = sum(int(part[2][key]) for part in got)
    traj = records(engine, g_rec, p_rec, st, s.h, s.every, t0, s.inputs)
    return replace(traj, partial=True) if interrupted else traj


def simulate_batch(engine: Engine, a: RunArgs, threads=None, progress=None,
                   lanes=True) -> list:
    """Integrator.simulate_batch: B Trajectories (made on access: batch_trajectories) from
    one backend call per thread slice."""
    engine.require_c("simulate_batch")
    e = engine.prepare_batch(a)
    threads = engine.threads(threads)
    runs, inputs = e.members, e.inputs
    _fits(len(runs) * (e.steps // e.every + 1), engine.n * engine.n + engine.d,
          "simulate_batch")
    g0s, p0s, z0s = (runs.arrays() if isinstance(runs, ExplicitStarts) else
                     ([s.g0 for s in runs], [s.mu0 for s in runs], [s.z0 for s in runs]))
    with progress_bar(len(runs), "simulate_batch", "member", progress) as bar:
        done, g_rec, p_rec, sts = engine.backend.simulate_batch(
            g0s, p0s, e.h, z0s, e.steps, e.every, e.opts, threads, inputs,
            None if type(bar) is NoBar else bar, lanes=bool(lanes))   # (no bar: few slices)
    return batch_trajectories(engine, done, g_rec, p_rec, sts, e.h, e.every, inputs,
                              check_t0(a.t0))


def batch_trajectories(engine: Engine, done, g_rec, p_rec, sts, h, every, inputs=None,
                       t0=0.0) -> list:
    """The B Trajectories of a batch's records g_rec (B, K, n*n, column-major), p_rec
    (B, K, d) (record 0 the start) and statuses ``sts`` (a structured array,
    hpgen.runtime.cbatch.simulate_batch),
    as a LazyList (hpgen.runtime.trajectory_list): member b's Trajectory is made when first
    looked at. A member that finished has all K records: its g, mu and t are read-only views
    of three arrays shared by the members (the batch's g transposed to row-major, made at
    the first member's access; p_rec itself; one time axis); a member's arrays keep the
    batch's alive. A failed member's Trajectory is made by ``trajectory`` (its records up to
    the failure, error, .partial)."""
    B, K = g_rec.shape[:2]
    n = engine.n
    p_rec.setflags(write=False)
    t = np.arange(0, K * every, every) * h
    t = t0 + t if t0 else t
    t.setflags(write=False)
    codes = sts["code"]
    # Trajectory field: the status column of its totals
    totals = {f: sts[key] for f, key in (("jacobians", "jacobians"), *counters.COUNTERS)}
    base = Trajectory.shared_fields(t=t, h=h, every=every, integrator=engine.owner)
    g_made: list = []

    def g_all() -> np.ndarray:
        """The batch's g (B, K, n, n) row-major, read-only, made once."""
        if not g_made:
            g = np.ascontiguousarray(g_rec.reshape(B, K, n, n).transpose(0, 1, 3, 2))
            g.setflags(write=False)
            g_made.append(g)
        return g_made[0]

    def failed(b: int) -> Trajectory:
        return trajectory(engine, int(done[b]), g_rec[b], p_rec[b], cbatch_status(sts, b), h,
                          every, None if inputs is None else inputs[b], t0)

    def member(b: int) -> Trajectory:
        if codes[b] != abi.OK:
            return failed(b)
        return Trajectory.member(base, g_all()[b], p_rec[b],
                                 {f: int(col[b]) for f, col in totals.items()},
                                 None if inputs is None else inputs[b])

    def every_member() -> list:
        out = Trajectory.members(base, list(g_all()), list(p_rec),
                                 {f: col.tolist() for f, col in totals.items()},
                                 [None] * B if inputs is None else inputs)
        for b in np.flatnonzero(codes != abi.OK).tolist():
            out[b] = failed(b)
        return out

    return LazyList(B, member, every_member)
