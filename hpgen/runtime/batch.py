"""Ensembles: B independent runs in C over threads (Integrator mixin; uses the
Integrator's backend, ``_initial``, ``_options``, ``_lv`` and ``_trajectory``).

Each run's states are bitwise those of ``simulate`` on its own: the same starts (the guess
kernel at each member's velocity), the same Newton options, one C call per thread slice.
"""
from __future__ import annotations

import os

import numpy as np

from ..errors import ArgumentError
from .args import _fits, _int, _step_size
from .inputs import batch_inputs, check_t0
from .newton import NewtonOptions
from .progress import bar as progress_bar


class BatchMixin:
    """Integrator methods for ensembles (see the module docstring)."""

    def _prepare_batch(self, g0, h, steps, xi0, mu0, every, threads, newton, what,
                       u=None, params=None, t0=0.0):
        """The checked arguments of an ensemble run by the C backend (``what``: the method, for
        the error): (h, steps, every, options, threads, g0s flat, mu0s, Newton starts z0s,
        per-run StepInputs or None (closed))."""
        if self.backend != "c":
            raise ArgumentError(f"{what} needs the C backend", field="backend")
        h = _step_size(h)
        steps, every = _int(steps, "steps", 0), _int(every, "every", 1)
        opts = self._options(newton)
        init = xi0 if xi0 is not None else mu0
        B = len(init) if hasattr(init, "__len__") else None
        inputs = batch_inputs(self.open, B or 0, steps, u, params, t0) if B else None
        if inputs is None:
            starts = [(gf, m, self._start(gf, m, x, h, opts))
                      for gf, m, x in self._batch_starts(g0, xi0, mu0)]
        else:
            lvs = [self._lv(i.t0, i.params) for i in inputs]
            starts = [(gf, m, self._b.call("guess", x, gf, m, np.array(i.hv(h, 0)))[0])
                      for (gf, m, x), i in zip(self._batch_starts(g0, xi0, mu0, lvs), inputs)]
        threads = _int(threads if threads is not None else (os.cpu_count() or 1), "threads", 1)
        gs, ms, z0s = zip(*starts) if starts else ((), (), ())
        return h, steps, every, opts, threads, gs, ms, z0s, inputs

    def _batch_starts(self, g0, xi0, mu0, lvs=None) -> list:
        """[(g0 flat, mu0, xi0)] for a batch: g0 (n, n) shared or (B, n, n); xi0 or mu0
        (B, d), exactly one; each start checked as in simulate."""
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
        return [self._initial(G0[b], None if xi0 is None else xi0[b],
                              None if mu0 is None else mu0[b], () if lvs is None else lvs[b])
                for b in range(B)]

    def simulate_batch(self, g0, h, steps, xi0=None, mu0=None, every=1, threads=None, *,
                       newton: NewtonOptions | None = None, u=None, params=None,
                       t0=0.0, progress=None, lanes: bool = True) -> list:
        """An ensemble of B runs, in C over ``threads`` threads (C backend only).

        Each run's states are bitwise those of ``simulate`` on its own.

        Parameters
        ----------
        g0 : array_like, shape (n, n) or (B, n, n)
            Initial group element, shared or one per run.
        h : float
            Step size, != 0 (negative: backwards in time), in the model's time unit.
        steps : int
            Number of steps of every run, >= 0.
        xi0, mu0 : array_like, shape (B, d), optional
            Initial velocities or momenta, one row per run; exactly one of the two.
        every : int, optional
            Record interval in steps, >= 1 (default 1).
        threads : int or None, optional
            Worker threads, >= 1; None (default): the CPU count.
        progress : bool or None, optional
            A bar of the runs done on stderr; None (default): when stderr is a terminal.
        lanes : bool, optional
            True (default): step groups of L bodies together with the module's lane-wise
            kernels when it has them (small closed steps, full Newton; hpgen.codegen.lanes),
            the same states bit for bit; False: one body at a time (A/B measurement).
        newton : NewtonOptions or None, optional
            Newton settings, as for ``simulate``.
        u : array_like, optional
            As for ``simulate``, shared by the runs ((m,) or (steps, m)), or one per run:
            (B, m) constant, (B, steps, m) one row per step ((B, m) with B == steps is the
            shared (steps, m)).
        t0 : float, optional
            As for ``simulate`` (shared by the runs).
        params : dict, optional
            As for ``simulate``; a value may carry a leading axis of length B: run b takes
            entry b (a parameter sweep, no recompilation).

        Returns
        -------
        list of Trajectory
            B trajectories; a failed run's is partial with ``.error`` set (nothing is
            raised for a failed run).

        Raises
        ------
        ModelError
            A bad argument, or the Python backend.
        """
        h, steps, every, opts, threads, gs, ms, z0s, inputs = self._prepare_batch(
            g0, h, steps, xi0, mu0, every, threads, newton, "simulate_batch", u, params, t0)
        _fits(len(gs) * (steps // every + 1), self.n * self.n + self.d, "simulate_batch")
        with progress_bar(len(gs), "simulate_batch", "member", progress) as bar:
            done, g_rec, p_rec, sts = self._b.simulate_batch(gs, ms, h, z0s, steps, every,
                                                             opts, threads, inputs, bar,
                                                             lanes=bool(lanes))
        t0 = check_t0(t0)
        return [self._trajectory(int(done[b]), g_rec[b], p_rec[b], sts[b], h, every,
                                 None if inputs is None else inputs[b], t0)
                for b in range(len(gs))]
