"""The sections output: Poincare sections of the scene's ``section`` s(g, mu) = 0, found
inside the C step loop (backend call ``advance_sections``, hpgen_advance_sections; the
Python backend mirrors it), as SectionCrossings (hpgen.runtime.trajectory, its conventions):
Integrator.sections and sections_batch on the run engine (hpgen.runtime.engine); and the
section in t, ``section: {every_t: T}`` (``sections(..., every_t=T)``): the stroboscopic
samples at t0 + j T, node states of the states output every T / h steps.
"""
from __future__ import annotations

import numpy as np

from .. import abi
from ..errors import ConvergenceError, ModelError
from . import counters
from .args import _error, _int, _positive, _step_size
from .engine import Engine, Part, RunArgs, RunStart
from .inputs import step_inputs
from .states import stream
from .trajectory import SectionCrossings


def strobe_steps(every_t, h) -> int:
    """N = every_t / h, the steps between two samples of a section in t; ModelError unless
    every_t > 0 is a whole number (>= 1) of steps within 1e-9 relative."""
    T = _positive(every_t, "every_t")
    ratio = T / h
    N = round(ratio)
    if N < 1 or abs(ratio - N) > 1e-9 * ratio:
        raise ModelError(f"every_t / h = {ratio:.12g} is not a whole number of steps (within "
                         "1e-9 relative); choose h = every_t / N", field="every_t")
    return int(N)


class Crossings:
    """The sections output of one run: at most ``chunk`` crossings per backend call, at
    most ``cap_total`` in all (None: no cap); ``parts`` the crossings found so far."""

    def __init__(self, engine: Engine, s: RunStart, cap_total, chunk):
        self.engine, self.s, self.cap_total, self.chunk = engine, s, cap_total, chunk
        self.parts: list = []
        self.found = 0

    def span(self, k, first):
        if k >= self.s.steps:
            return None
        cap = self.chunk if self.cap_total is None else min(self.chunk,
                                                            self.cap_total - self.found)
        return None if cap < 1 else (self.s.steps - k, cap)

    def advance(self, run, span) -> Part:
        s = self.s
        done, *data, st = self.engine.backend.advance_sections(run, s.h, span[0], span[1],
                                                               s.opts)
        return Part(done, tuple(data), st)

    def run(self, handle=None) -> SectionCrossings:
        """The crossings of the whole run; the error (if any) is set, not raised."""
        s, engine = self.s, self.engine
        k, err = 0, None
        counts = dict.fromkeys(counters.NAMES, 0)
        for _, _, part in engine.parts(self, s, handle):
            st = part.status
            self.parts.append(part.data)
            k = k + part.done
            for name, n in counters.of_status(st).items():
                counts[name] += n
            self.found += len(part.data[1])
            if st["code"] != abi.OK:
                hint = ""
                if st["code"] == abi.DOMAIN and st["iterations"] == 0:
                    hint = engine.first_step.domain_hint(s.g0, s.mu0, s.xi0, s.h)
                err = _error(st["code"], st["step"], st["step"] * s.h, st["residual"],
                             st["iterations"], hint)
        n, d, parts = engine.n, engine.d, self.parts
        cat = lambda i, shape: (np.concatenate([q[i] for q in parts]) if parts  # noqa: E731
                                else np.zeros(shape))
        gs = cat(2, (0, n * n)).reshape(-1, n, n).transpose(0, 2, 1)
        t = cat(1, (0,))
        if s.inputs is not None and s.inputs.t0:
            t = s.inputs.t0 + t
        out = SectionCrossings(t=t, g=np.ascontiguousarray(gs),
                               mu=cat(3, (0, d)).reshape(-1, d),
                               step=cat(0, (0,)).astype(np.int64), h=s.h, steps=k,
                               partial=err is not None, error=err, **counts)
        if err is not None:
            err.partial = out
        return out


def _section_args(engine: Engine, h, steps, max_crossings, chunk, newton):
    """(h, steps, crossing cap or None, chunk, options), checked; the module must have a
    section."""
    if not engine.meta.get("section"):
        raise ModelError("the model's scene has no section; add `section: <expression in "
                         "mu and g>` to the scene and recompile", field="scene.section")
    h = _step_size(h)
    steps = _int(steps, "steps", 0)
    cap_total = None if max_crossings is None else _int(max_crossings, "max_crossings", 1)
    return h, steps, cap_total, _int(chunk, "chunk", 1), engine.options(newton)


def sections(engine: Engine, a: RunArgs, max_crossings=None, chunk=100_000,
             every_t=None) -> SectionCrossings:
    """Integrator.sections: raises a failed run's error (with .partial)."""
    if every_t is not None:
        return stroboscopic(engine, a, max_crossings, chunk, every_t)
    h, steps, cap_total, chunk, opts = _section_args(engine, a.h, a.steps, max_crossings,
                                                     chunk, a.newton)
    s = engine.start(a.g0, a.xi0, a.mu0, h, steps, 1, opts,
                     step_inputs(engine.open, steps, a.u, a.params, a.t0))
    out = Crossings(engine, s, cap_total, chunk).run()
    if out.error is not None:
        raise out.error
    return out


def sections_batch(engine: Engine, a: RunArgs, max_crossings=None, threads=None,
                   chunk=100_000) -> list:
    """Integrator.sections_batch: the members' runs on ``threads`` threads (the C backend;
    one after the other on the Python backend); errors set, not raised."""
    h, steps, cap_total, chunk, opts = _section_args(engine, a.h, a.steps, max_crossings,
                                                     chunk, a.newton)
    runs = engine.member_starts(a, h, steps, 1, opts)
    return engine.each(lambda s: Crossings(engine, s, cap_total, chunk).run(), runs,
                       engine.threads(threads))


def stroboscopic(engine: Engine, a: RunArgs, max_crossings, chunk,
                 every_t) -> SectionCrossings:
    """sections(..., every_t=T): the states at t0 + j T from the states output every N
    steps."""
    h = _positive(a.h, "h")
    N = strobe_steps(every_t, h)
    steps = _int(a.steps, "steps", 0)
    if max_crossings is not None:
        steps = min(steps, (_int(max_crossings, "max_crossings", 1) - 1) * N)
    parts, err = [], None
    try:
        parts.extend(stream(engine, a.but(h=h, steps=steps, every=N),
                            _int(chunk, "chunk", 1)))
    except ConvergenceError as e:
        err = e
        if e.partial is not None and len(e.partial.t):
            parts.append(e.partial)
    cat = lambda name, shape: (np.concatenate([getattr(p, name) for p in parts])  # noqa
                               if parts else np.zeros(shape))
    t = cat("t", (0,))
    k = np.rint((t - float(a.t0)) / h).astype(np.int64) if len(t) else np.zeros(0, np.int64)
    out = SectionCrossings(t=t, g=cat("g", (0, engine.n, engine.n)),
                           mu=cat("mu", (0, engine.d)), step=k, h=h,
                           steps=steps if err is None else int(err.step),
                           partial=err is not None, error=err,
                           **counters.summed(parts))
    if err is not None:
        err.partial = out
        raise err
    return out
