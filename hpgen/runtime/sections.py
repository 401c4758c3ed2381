"""Poincare sections of the scene's ``section`` s(g, mu) = 0, found inside the C step loop
(hpgen_advance_sections; the Python backend mirrors it): the Integrator methods ``sections``
and ``sections_batch`` (see hpgen.runtime.trajectory.SectionCrossings for the conventions);
and the section in t, ``section: {every_t: T}`` (``sections(..., every_t=T)``): the
stroboscopic samples at t0 + j T, node states of ``stream`` every T / h steps.
"""
from __future__ import annotations

import os

import numpy as np

from ..errors import ConvergenceError, ModelError
from .. import abi
from .args import _error, _int, _positive, _step_size
from .inputs import batch_inputs, step_inputs


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
from .newton import NewtonOptions
from .trajectory import SectionCrossings


class SectionsMixin:
    """Integrator methods for section crossings (uses the Integrator's _options, _initial,
    _batch_starts and backend)."""

    def sections(self, g0, h, steps, xi0=None, mu0=None, max_crossings=None, chunk=100_000,
                 *, newton: NewtonOptions | None = None, u=None, params=None,
                 t0=0.0, every_t=None) -> SectionCrossings:
        """Run up to ``steps`` steps and keep only the upward crossings of ``scene.section``.

        s(g, mu) = 0 is tested inside the step loop (docs/numerics.md sec. 12); the states are
        bitwise those of ``simulate``. The module's model must have a ``section``, unless
        ``every_t`` is given.

        Parameters
        ----------
        g0, h, steps, xi0, mu0
            As for ``simulate``: g0 (n, n) on the group, h != 0 in the model's time unit,
            steps >= 0, exactly one of xi0 / mu0 (d,).
        max_crossings : int or None, optional
            Stop the run at the step of this crossing; None (default): run all steps.
        newton : NewtonOptions or None, optional
            Newton settings, as for ``simulate``.
        chunk : int, optional
            Steps per C call, >= 1 (default 100,000); bounds the memory of a run.
        u, params, t0
            As for ``simulate`` (an open module's inputs, runtime parameters, start time).
        every_t : float or None, optional
            A section in t (the scene's ``section: {every_t: T}``): the stroboscopic section
            at t0 + j T, j = 0, 1, ..., T a whole number N of steps of h (within 1e-9
            relative): the node states after every N steps, exactly (no interpolation);
            ``step`` = j N. No compiled section is needed; max_crossings caps the samples.

        Returns
        -------
        SectionCrossings
            ``t`` (K,), ``g`` (K, n, n) on the step's chart curve, ``mu`` (K, d) interpolated
            linearly, ``step`` (K,) the step of each crossing; ``steps`` run.

        Raises
        ------
        ModelError
            A bad argument, or a model without ``section``.
        ConvergenceError, DomainError
            A step failed; ``.partial`` holds the crossings found before it.
        """
        if every_t is not None:
            return self._stroboscopic(g0, h, steps, xi0, mu0, max_crossings, chunk, newton,
                                      u, params, t0, every_t)
        h, steps, cap_total, chunk, opts = self._section_args(h, steps, max_crossings, chunk,
                                                             newton)
        inputs = step_inputs(self.open, steps, u, params, t0)
        lv = () if inputs is None else self._lv(inputs.t0, inputs.params)
        gf, mu0, xi0 = self._initial(g0, xi0, mu0, lv)
        out = self._sections_run(gf, mu0, xi0, h, steps, cap_total, chunk, opts, inputs)
        if out.error is not None:
            raise out.error
        return out

    def sections_batch(self, g0, h, steps, xi0=None, mu0=None, max_crossings=None,
                       threads=None, chunk=100_000, *,
                       newton: NewtonOptions | None = None, u=None, params=None,
                       t0=0.0) -> list:
        """``sections`` for B initial states (g0 (n, n) shared or (B, n, n); xi0 or mu0
        (B, d)), the runs spread over ``threads`` threads (default: the CPU count); each
        result is bitwise that of ``sections`` on its own. A failed run's SectionCrossings
        is partial with ``.error`` set (nothing is raised). u, params, t0: as for
        ``simulate_batch`` (a params value with a leading axis of length B is a sweep)."""
        from concurrent.futures import ThreadPoolExecutor
        h, steps, cap_total, chunk, opts = self._section_args(h, steps, max_crossings, chunk,
                                                             newton)
        init = xi0 if xi0 is not None else mu0
        B = len(init) if hasattr(init, "__len__") else 0
        inputs = batch_inputs(self.open, B, steps, u, params, t0) if B else None
        lvs = None if inputs is None else [self._lv(i.t0, i.params) for i in inputs]
        starts = self._batch_starts(g0, xi0, mu0, lvs)
        threads = _int(threads if threads is not None else (os.cpu_count() or 1), "threads", 1)

        def one(b):
            gf, m0, x0 = starts[b]
            return self._sections_run(gf, m0, x0, h, steps, cap_total, chunk, opts,
                                      None if inputs is None else inputs[b])

        if threads == 1 or self.backend != "c":
            return [one(b) for b in range(len(starts))]
        with ThreadPoolExecutor(min(threads, len(starts))) as pool:
            return list(pool.map(one, range(len(starts))))

    def _stroboscopic(self, g0, h, steps, xi0, mu0, max_crossings, chunk, newton, u, params,
                      t0, every_t) -> SectionCrossings:
        """sections(..., every_t=T): the states at t0 + j T from ``stream`` every N steps."""
        h = _positive(h, "h")
        N = strobe_steps(every_t, h)
        steps = _int(steps, "steps", 0)
        if max_crossings is not None:
            steps = min(steps, (_int(max_crossings, "max_crossings", 1) - 1) * N)
        parts, err = [], None
        try:
            parts.extend(self.stream(g0, h, steps, xi0, mu0, every=N, chunk=_int(chunk, "chunk",
                                                                                1),
                                     newton=newton, u=u, params=params, t0=t0))
        except ConvergenceError as e:
            err = e
            if e.partial is not None and len(e.partial.t):
                parts.append(e.partial)
        cat = lambda name, shape: (np.concatenate([getattr(p, name) for p in parts])  # noqa
                                   if parts else np.zeros(shape))
        t = cat("t", (0,))
        k = np.rint((t - float(t0)) / h).astype(np.int64) if len(t) else np.zeros(0, np.int64)
        out = SectionCrossings(t=t, g=cat("g", (0, self.n, self.n)),
                               mu=cat("mu", (0, self.d)), step=k, h=h,
                               steps=steps if err is None else int(err.step),
                               partial=err is not None, error=err,
                               newton_iterations=sum(p.newton_iterations for p in parts))
        if err is not None:
            err.partial = out
            raise err
        return out

    def _section_args(self, h, steps, max_crossings, chunk, newton):
        """(h, steps, crossing cap or None, chunk, options), checked; the module must have a
        section."""
        self._need_section()
        h = _step_size(h)
        steps = _int(steps, "steps", 0)
        cap_total = None if max_crossings is None else _int(max_crossings, "max_crossings", 1)
        return (h, steps, cap_total, _int(chunk, "chunk", 1),
                self._options(newton))

    def _need_section(self):
        if not self.meta.get("section"):
            raise ModelError("the model's scene has no section; add `section: <expression in "
                             "mu and g>` to the scene and recompile", field="scene.section")

    def _sections_run(self, gf, mu0, xi0, h, steps, cap_total, chunk, opts, inputs=None):
        """One run of sections from a checked start; the error (if any) is set, not raised.
        inputs: an open module's StepInputs."""
        if inputs is None:
            z0 = self._start(gf, mu0, xi0, h, opts)
            run = self._b.start(gf, mu0, z0)
        else:
            z0 = self._b.call("guess", xi0, gf, mu0, np.array(inputs.hv(h, 0)))[0]
            run = self._b.start(gf, mu0, z0, inputs)
        parts, k, iters, err = [], 0, 0, None
        found = 0
        while k < steps:
            cap = chunk if cap_total is None else min(chunk, cap_total - found)
            if cap < 1:
                break
            done, ks, ts, gs, ps, st = self._b.advance_sections(run, h, steps - k, cap, opts)
            z1 = (self._restart(st, gf, mu0, h, z0, opts) if k == 0 and inputs is None
                  else None)
            if z1 is not None:
                run = self._b.start(gf, mu0, z1)
                done, ks, ts, gs, ps, st = self._b.advance_sections(run, h, steps - k, cap,
                                                                    opts)
            parts.append((ks, ts, gs, ps))
            k, found, iters = k + done, found + len(ts), iters + int(st["total_iterations"])
            if st["code"] != abi.OK:
                hint = ""
                if st["code"] == abi.DOMAIN and st["iterations"] == 0:
                    hint = self._domain_hint(gf, mu0, xi0, h)
                err = _error(st["code"], st["step"], st["step"] * h, st["residual"],
                             st["iterations"], hint)
                break
        n = self.n
        cat = lambda i, shape: (np.concatenate([q[i] for q in parts]) if parts  # noqa: E731
                                else np.zeros(shape))
        gs = cat(2, (0, n * n)).reshape(-1, n, n).transpose(0, 2, 1)
        t = cat(1, (0,))
        if inputs is not None and inputs.t0:
            t = inputs.t0 + t
        out = SectionCrossings(t=t, g=np.ascontiguousarray(gs),
                               mu=cat(3, (0, self.d)).reshape(-1, self.d),
                               step=cat(0, (0,)).astype(np.int64), h=h, steps=k,
                               partial=err is not None, error=err, newton_iterations=iters)
        if err is not None:
            err.partial = out
        return out
