"""The run engine behind Integrator: every kind of run is one start -> advance -> restart
loop over the module's kernel backend (hpgen.runtime.backends).

What a run keeps is an *output* (``Output``): it says how far each backend call goes
(``span``), makes the call (``advance``: states, record rows, section crossings) and turns
what came back into its result type (hpgen.runtime.states, .records, .sections). The
engine owns everything else, the same for every output:

- ``prepare`` / ``prepare_batch``: a run's arguments as given (``RunArgs``: start, step,
  steps, record interval, Newton settings, an open module's inputs, parameters and start
  time) checked, and the run's start (or each ensemble member's), a frozen ``RunStart``
  (h, steps, every, Newton options, g0 flat, mu0, xi0, the first step's Newton start z0, an
  open module's StepInputs);
- ``parts``: the one loop. It starts a run (or continues a ``RunHandle``, e.g. one
  restored from a snapshot), advances it span by span (a chunk of steps: streaming), and
  when a fresh run's first step fails from z0 it starts again from the first step solved by
  continuation in h (hpgen.runtime.first_step) and repeats that call;
- ``Sliced``: an output advanced in slices of bounded wall time (simulate, record), so that
  Ctrl-C (a KeyboardInterrupt raised between backend calls) stops a long run;
- ``threads`` / ``each``: an ensemble's worker count and its members' runs through the loop
  on threads; an output with an ensemble call of its own (states and records on the C
  backend: one C call per thread slice) makes that call instead.

Interface for the modules built on the engine (linearize, chunked output, simulate's fast
path, ensembles): the attributes ``backend``, ``meta``, ``n``, ``d``, ``nz``, ``open``,
``maps`` (StateMaps), ``first_step`` (FirstStep), ``owner`` (the Integrator results are
attached to) and the methods below; nothing else of an Integrator is theirs to touch.
numpy and the standard library only.
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, replace
from typing import Any, Iterator, Protocol, Sequence

import numpy as np

from .. import abi
from ..errors import ArgumentError
from .args import _array, _error, _int, _step_size, newton_options
from .batch_starts import ExplicitStarts
from .first_step import FirstStep
from .inputs import StepInputs, batch_inputs, step_inputs
from .newton import NewtonOptions
from .state_maps import StateMaps

#: how far g0 may be from the group (the defect kernel)
DEFECT_MAX = 1e-10
#: simplified Newton is the runs' default when the Jacobian kernel costs more than this many
#: residual kernels (CasADi instruction counts in meta.json)
SIMPLIFIED_RATIO = 4.0


@dataclass(frozen=True, eq=False)
class RunArgs:
    """The arguments of a run as the caller gave them (Integrator.simulate's, unchecked:
    ``Engine.prepare`` checks them): g0, h, steps, one of xi0 / mu0, every, newton, and an
    open module's u, params and t0."""
    g0: Any
    h: Any
    steps: Any
    xi0: Any = None
    mu0: Any = None
    every: Any = 1
    newton: Any = None
    u: Any = None
    params: Any = None
    t0: Any = 0.0

    def but(self, **changes) -> RunArgs:
        """A copy with ``changes``."""
        return replace(self, **changes)


@dataclass(frozen=True, eq=False)
class RunStart:
    """The checked arguments of one run and its start: step h, steps, record interval every,
    resolved Newton options, g0 flat column-major, mu0, xi0, z0 (the first step's Newton
    start), inputs (an open module's StepInputs, None when closed)."""
    h: float
    steps: int
    every: int
    opts: NewtonOptions
    g0: np.ndarray
    mu0: np.ndarray
    xi0: np.ndarray | None       # None: an explicit module's mu0 start (no velocity)
    z0: np.ndarray
    inputs: StepInputs | None = None


@dataclass(frozen=True, eq=False)
class Ensemble:
    """The checked arguments of an ensemble and its members' RunStarts (each with the
    shared h, steps, every and options; a list, or hpgen.runtime.batch_starts'
    ExplicitStarts holding them as arrays)."""
    h: float
    steps: int
    every: int
    opts: NewtonOptions
    members: Sequence

    @property
    def inputs(self) -> list | None:
        """The members' StepInputs (an open module), None for a closed module."""
        if not self.members or self.members[0].inputs is None:
            return None
        return [s.inputs for s in self.members]


@dataclass(frozen=True, eq=False)
class Part:
    """What one backend call of a run returned: steps done, the output's arrays (``data``)
    and the status (hpgen.abi.STATUS_FIELDS)."""
    done: int
    data: tuple
    status: dict


class Output(Protocol):
    """What a run keeps, for one run (see the module docstring). ``span(k, first)``: the
    arguments of the next backend call after k steps (first: no call made yet), None when
    the run is done; ``advance(run, span)``: that call on the backend run ``run``."""

    def span(self, k: int, first: bool) -> tuple | None: ...

    def advance(self, run: Any, span: tuple) -> Part: ...


#: a run advanced in slices (``Sliced``) has backend calls of about this many seconds, so
#: that a pending interrupt (Ctrl-C: KeyboardInterrupt) is taken between them; the first
#: slice has SLICE_FIRST steps
SLICE_SECONDS = 0.05
SLICE_FIRST = 256


class Sliced:
    """An output (``out``, whose calls go at most ``out.chunk`` steps) advanced in slices of
    bounded wall time: after each call, ``out.chunk`` is set from that call's time to about
    SLICE_SECONDS (at most 4 times the call's steps). The slices continue one run: what
    they return is bitwise what one call returns."""

    def __init__(self, out):
        self.out = out

    def span(self, k: int, first: bool) -> tuple | None:
        return self.out.span(k, first)

    def advance(self, run: Any, span: tuple) -> Part:
        t = time.perf_counter()
        part = self.out.advance(run, span)
        dt = time.perf_counter() - t
        rate = span[0] * SLICE_SECONDS / dt if dt > 0 else 4 * span[0]
        self.out.chunk = max(1, min(4 * span[0], int(rate)))
        return part


class RunHandle:
    """A backend run in progress. ``run`` is the backend's run object (it changes when the
    first step is restarted); ``steps_done()`` and ``snapshot()`` (a checkpoint that
    ``Engine.restore`` continues bitwise) query the current one."""

    def __init__(self, backend, run):
        self.backend, self.run = backend, run

    def steps_done(self) -> int:
        return self.backend.steps_done(self.run)

    def snapshot(self) -> dict:
        return self.backend.snapshot(self.run)


class Engine:
    """The run engine of one loaded module (see the module docstring). owner: the object
    the results are attached to (the Integrator)."""

    def __init__(self, backend, meta: dict, owner=None):
        self.backend, self.meta, self.owner = backend, meta, owner
        self.n, self.d, self.nz = meta["n"], meta["d"], meta["nz"]
        #: an open module's step vector (meta.json "open", hpgen.abi), None when closed
        self.open = meta.get("open")
        self.maps = StateMaps(backend, meta)
        self.first_step = FirstStep(backend, meta, self.maps.velocity_flat)

    def kernel(self, name, *args):
        """Evaluate one kernel on flat column-major arrays; returns its outputs (a list)."""
        return self.backend.call(name, *args)

    @property
    def simplified_default(self) -> bool:
        """True when simplified Newton pays: J costs > SIMPLIFIED_RATIO residuals. A sparse J
        (many bodies) defaults to full Newton: the kept J's rate-based stop leaves the joints'
        velocity form at about KEEP_J_FLOOR instead of round-off, and from about 32 bodies the
        predictor's start is far enough off that J is refreshed nearly every step anyway
        (NewtonOptions(simplified=True) asks for it; docs/performance.md, many bodies)."""
        if self.meta.get("jacobian", {}).get("storage") == "sparse":
            return False
        k = self.meta["kernels"]
        cost = [k[n].get("instructions", 0) for n in ("jacobian", "residual")]
        return cost[0] > SIMPLIFIED_RATIO * cost[1]

    def options(self, newton: NewtonOptions | None, full: bool = False) -> NewtonOptions:
        """The checked Newton settings of a call, simplified resolved to a bool (None: full
        Newton when ``full``, else simplified_default). ArgumentError naming the field."""
        return newton_options(newton, self.simplified_default, full)

    # ---- starts ---------------------------------------------------------------------------
    def initial(self, g0, xi0, mu0, lv=()):
        """(g0 flat, mu0, xi0) from g0 and exactly one of xi0 / mu0, checked; lv: an open
        module's extra argument of l at the start (StateMaps.lv)."""
        g0 = _array(g0, (self.n, self.n), "g0", "an n x n matrix")
        if (xi0 is None) == (mu0 is None):
            raise ArgumentError("give exactly one of xi0 (velocity) and mu0 (momentum)",
                                field="xi0" if xi0 is not None else "mu0")
        gf = g0.ravel(order="F")      # g0 checked: the kernels take it as it is
        e = float(self.backend.call("defect", gf)[0][0])
        if not e <= DEFECT_MAX:
            raise ArgumentError(f"g0 is not on the group (defect {e:.3g} > {DEFECT_MAX:g})",
                                field="initial g")
        if xi0 is not None:
            xi0 = self.maps.vector(xi0, "xi0")
            mu0 = self.backend.call("legendre", gf, xi0, *lv)[0]
        else:
            mu0 = self.maps.vector(mu0, "mu0")
            # (an explicit step's start needs no velocity: FirstStep.start)
            xi0 = None if self.first_step.explicit else self.maps.velocity_flat(gf, mu0, lv=lv)
        return gf, mu0, xi0

    def start(self, g0, xi0, mu0, h, steps, every, opts, inputs=None) -> RunStart:
        """The RunStart of checked h, steps, every, options and inputs from g0 and one of
        xi0 / mu0 (checked here)."""
        lv = () if inputs is None else self.maps.lv(inputs.t0, inputs.params)
        gf, mu0, xi0 = self.initial(g0, xi0, mu0, lv)
        z0 = self.first_step.start(gf, mu0, xi0, h, opts, inputs)
        return RunStart(h, steps, every, opts, gf, mu0, xi0, z0, inputs)

    def prepare(self, a: RunArgs) -> RunStart:
        """The checked arguments of a run and its start."""
        h = _step_size(a.h)
        steps, every = _int(a.steps, "steps", 0), _int(a.every, "every", 1)
        opts = self.options(a.newton)
        return self.start(a.g0, a.xi0, a.mu0, h, steps, every, opts,
                          step_inputs(self.open, steps, a.u, a.params, a.t0))

    def prepare_batch(self, a: RunArgs) -> Ensemble:
        """The Ensemble of g0 (n, n) shared or (B, n, n) and xi0 or mu0 (B, d); u and t0
        shared, a params value with a leading axis of length B a sweep
        (hpgen.runtime.inputs.batch_inputs)."""
        h = _step_size(a.h)
        steps, every = _int(a.steps, "steps", 0), _int(a.every, "every", 1)
        opts = self.options(a.newton)
        fast = self._explicit_starts(a, h, steps, every, opts)
        return Ensemble(h, steps, every, opts, fast if fast is not None else
                        self.member_starts(a, h, steps, every, opts))

    def member_starts(self, a: RunArgs, h, steps, every, opts) -> list:
        """prepare_batch's members, h, steps, every and the options checked already."""
        fast = self._explicit_starts(a, h, steps, every, opts)
        if fast is not None:
            return list(fast)
        xi0, mu0 = a.xi0, a.mu0
        init = xi0 if xi0 is not None else mu0
        B = len(init) if hasattr(init, "__len__") else None
        inputs = batch_inputs(self.open, B or 0, steps, a.u, a.params, a.t0) if B else None
        G0 = self._batch_g0(a.g0, xi0, mu0)
        return [self.start(G0[b], None if xi0 is None else xi0[b],
                           None if mu0 is None else mu0[b], h, steps, every, opts,
                           None if inputs is None else inputs[b]) for b in range(len(G0))]

    def _explicit_starts(self, a: RunArgs, h, steps, every, opts) -> ExplicitStarts | None:
        """member_starts of an explicit closed module in the common case, a (B, d) float64
        mu0 of finite rows and one shared (n, n) float64 g0 on the group: g0 checked once,
        each start (g0, mu0 row, z0 = the row) as ``start`` makes it; None for anything else
        (member_starts then checks every member and raises what it finds)."""
        if not self.first_step.explicit or self.open is not None or a.xi0 is not None:
            return None
        mu, g = a.mu0, a.g0
        if not (type(mu) is np.ndarray and type(g) is np.ndarray and mu.dtype == np.float64
                and g.dtype == np.float64 and mu.ndim == 2 and mu.shape[1] == self.d
                and g.shape == (self.n, self.n) and len(mu) >= 1
                and np.isfinite(mu).all() and np.isfinite(g).all()):
            return None
        gf = np.array(g, dtype=np.float64).ravel(order="F")
        if not float(self.backend.call("defect", gf)[0][0]) <= DEFECT_MAX:
            return None
        mu = np.array(mu, dtype=np.float64)
        return ExplicitStarts(RunStart(h, steps, every, opts, gf, mu[0], None, mu[0].copy()),
                              gf, mu)

    def _batch_g0(self, g0, xi0, mu0) -> np.ndarray:
        """g0 as (B, n, n), B the length of xi0 / mu0, checked."""
        init = xi0 if xi0 is not None else mu0
        try:
            B = len(init)
        except TypeError:
            raise ArgumentError("expected a (B, d) array of initial states",
                                field="xi0" if xi0 is not None else "mu0") from None
        try:
            G0 = np.asarray(g0)
        except (TypeError, ValueError):
            raise ArgumentError("expected an (n, n) or (B, n, n) array", field="g0") from None
        if np.iscomplexobj(G0):
            raise ArgumentError("expected real numbers, got complex entries", field="g0")
        G0 = G0.astype(np.float64)
        if G0.shape == (self.n, self.n):
            G0 = np.broadcast_to(G0, (B, self.n, self.n))
        if G0.shape != (B, self.n, self.n):
            raise ArgumentError(f"expected g0 of shape ({self.n}, {self.n}) or ({B}, {self.n}, "
                                f"{self.n}), got {G0.shape}", field="g0")
        return G0

    @staticmethod
    def threads(threads) -> int:
        """The checked worker count of an ensemble (None: the CPU count)."""
        return _int(threads if threads is not None else (os.cpu_count() or 1), "threads", 1)

    def each(self, run_one, members: list, threads: int) -> list:
        """[run_one(s) for s in members]: on ``threads`` threads on the C backend (its calls
        release the GIL), one after the other on the Python backend."""
        if threads == 1 or self.backend.name != "c":
            return [run_one(s) for s in members]
        from concurrent.futures import ThreadPoolExecutor
        with ThreadPoolExecutor(min(threads, len(members))) as pool:
            return list(pool.map(run_one, members))

    def require_c(self, what: str):
        """ArgumentError unless the module runs on the C backend (``what``: the method)."""
        if self.backend.name != "c":
            raise ArgumentError(f"{what} needs the C backend", field="backend")

    # ---- the run loop -----------------------------------------------------------------------
    def new_run(self, s: RunStart) -> RunHandle:
        """A run at s's start."""
        return RunHandle(self.backend, self.backend.start(s.g0, s.mu0, s.z0, s.inputs))

    def restore(self, state: dict, inputs=None) -> RunHandle:
        """The run a snapshot (RunHandle.snapshot) holds (an open module's with its inputs)."""
        return RunHandle(self.backend, self.backend.restore(state, inputs))

    def parts(self, out: Output, s: RunStart, handle: RunHandle | None = None
              ) -> Iterator[tuple[int, bool, Part]]:
        """The one start -> advance -> restart loop: yields (k, first, part) per backend
        call (k: steps done before it; first: the run's first call). A fresh run (handle
        None, or one at step 0) whose first call fails at step 0 is started again from the
        first step solved by continuation (FirstStep.restart) and the call repeated. Stops
        after a failed call, or when ``out.span`` says the run is done."""
        if handle is None:
            handle, k = self.new_run(s), 0
        else:
            k = handle.steps_done()
        first = k == 0
        while True:
            span = out.span(k, first)
            if span is None:
                return
            part = out.advance(handle.run, span)
            if first:
                z1 = self.first_step.restart(part.status, s.g0, s.mu0, s.h, s.z0, s.opts)
                if z1 is not None:
                    handle.run = self.backend.start(s.g0, s.mu0, z1, s.inputs)
                    part = out.advance(handle.run, span)
            yield k, first, part
            if part.status["code"] != abi.OK:
                return
            k += part.done
            first = False

    # ---- one step -------------------------------------------------------------------------
    def step(self, g, p, h, z=None, newton=None, u=None, params=None, t=0.0):
        """Integrator.step: (g1 (n, n), p1)."""
        gf, p = self.maps.flat_g(g), self.maps.vector(p, "p")
        h = _step_size(h)
        inputs = step_inputs(self.open, None, u, params, t)
        hv = np.array([h] if inputs is None else inputs.hv(h, 0))
        opts = self.options(newton, full=True)
        xi = None
        if z is None and self.first_step.explicit:      # its unknown is p (FirstStep.start)
            z = p.copy()
        elif z is None:
            if inputs is None:
                xi = self.maps.velocity_flat(gf, p)
                z = self.first_step.closed_start(gf, p, xi, h, opts)
            else:
                lv = self.maps.lv(inputs.t0, inputs.params)
                z = self.backend.call("guess", self.maps.velocity_flat(gf, p, lv=lv), gf, p,
                                      hv)[0]
        else:
            z = _array(z, (self.nz,), "z", "a vector of length nz")
        code, g1, p1, _, it, r = self.backend.step(gf, p, hv, z, opts)
        z1 = None if xi is None else self.first_step.restart(
            {"code": code, "step": 0}, gf, p, h, z, opts)
        if z1 is not None:
            code, g1, p1, _, it, r = self.backend.step(gf, p, hv, z1, opts)
        if code != abi.OK:
            hint = self.first_step.domain_hint(gf, p, xi, h) if xi is not None else ""
            raise _error(code, 0, 0.0, r, it, hint)
        return g1.reshape(self.n, self.n, order="F"), p1
