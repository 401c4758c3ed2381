"""RunOutputs: the Integrator's run methods that return ensembles, record rows or section
crossings (simulate_batch, record, stream_record, record_batch, sections, sections_batch),
thin fronts over the run engine's outputs (hpgen.runtime.states, .records, .sections).

Conventions as in hpgen.runtime.integrator: g an (n, n) group element, momenta and velocities
length-d body-frame vectors, h != 0 in the model's time unit (h < 0 runs backwards).
"""
from __future__ import annotations

from . import records, sections, states
from .engine import Engine, RunArgs
from .newton import NewtonOptions
from .trajectory import SectionCrossings


class RunOutputs:
    """The ensemble, record and section runs of a loaded module. Its interface to the class
    that holds it (hpgen.runtime.integrator.Integrator): the attribute ``engine``, the run
    engine every method runs on; nothing else is read."""
    engine: Engine

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
            raised for a failed run). Each is made when first looked at
            (hpgen.runtime.trajectory_list.LazyList, a list).

        Raises
        ------
        ModelError
            A bad argument, or the Python backend.
        """
        return states.simulate_batch(self.engine, RunArgs(g0, h, steps, xi0, mu0, every,
                                                          newton, u, params, t0),
                                     threads, progress, lanes)

    def record(self, g0, h, steps, xi0=None, mu0=None, every=1, *,
               newton: NewtonOptions | None = None, u=None, params=None, t0=0.0):
        """Run ``steps`` steps keeping only the scene's record row every ``every`` steps.

        The row (``record_names``: the scene's g, mu, xi, energy, momentum, defect and
        expressions) is evaluated inside the C loop; when neither the step nor the row use
        g, g is not reconstructed. The states are bitwise those of ``simulate``.

        Parameters
        ----------
        g0, h, steps, xi0, mu0, newton, u, params, t0
            As for ``simulate``: g0 (n, n) on the group, h != 0 in the model's time unit,
            steps >= 0, exactly one of xi0 / mu0 (d,); Newton settings; an open module's
            inputs, runtime parameters and start time.
        every : int, optional
            Record interval in steps, >= 1 (default 1); record 0 is the initial state.

        Returns
        -------
        Records
            ``t`` (K,) and one array per record name, K = steps // every + 1: g (K, n, n);
            mu, xi, momentum (K, d); energy, defect, expressions (K,). ``rec["energy"]``,
            ``rec.save(path)``.

        Raises
        ------
        ModelError
            A bad argument.
        ConvergenceError, DomainError, RecordError
            A step failed, or a recorded value is not finite (``RecordError`` names the
            entries); ``.partial`` holds the records up to the failure.
        KeyboardInterrupt
            Ctrl-C (taken between slices of bounded wall time); ``.partial`` holds the
            records of the steps done (partial=True).
        """
        return records.record(self.engine, RunArgs(g0, h, steps, xi0, mu0, every, newton, u,
                                                   params, t0))

    def stream_record(self, g0, h, steps, xi0=None, mu0=None, every=1, chunk=100_000, *,
                      newton: NewtonOptions | None = None, u=None, params=None, t0=0.0):
        """Like ``record`` in chunks of at most ``chunk`` steps (bounded memory): yields one
        Records per chunk (the first starts with record 0; ``t`` is global). A failure raises
        ConvergenceError / DomainError / RecordError with ``.partial`` the failing chunk's
        records. u, params, t0: as in ``simulate``."""
        return records.stream_record(self.engine, RunArgs(g0, h, steps, xi0, mu0, every,
                                                          newton, u, params, t0), chunk)

    def record_batch(self, g0, h, steps, xi0=None, mu0=None, every=1, threads=None, *,
                     newton: NewtonOptions | None = None, u=None, params=None, t0=0.0,
                     progress=None) -> list:
        """``record`` for an ensemble (starts as in ``simulate_batch``), in C over ``threads``
        threads (default: the CPU count); each run's rows are bitwise those of ``record`` on
        its own. Returns B Records; a failed run's Records is partial with ``.error`` set
        (nothing is raised). u, params, t0 and progress: as for ``simulate_batch`` (a params
        value with a leading axis of length B is a sweep: run b takes entry b)."""
        return records.record_batch(self.engine, RunArgs(g0, h, steps, xi0, mu0, every,
                                                         newton, u, params, t0),
                                    threads, progress)

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
        return sections.sections(self.engine, RunArgs(g0, h, steps, xi0, mu0, 1, newton, u,
                                                      params, t0), max_crossings, chunk, every_t)

    def sections_batch(self, g0, h, steps, xi0=None, mu0=None, max_crossings=None,
                       threads=None, chunk=100_000, *,
                       newton: NewtonOptions | None = None, u=None, params=None,
                       t0=0.0) -> list:
        """``sections`` for B initial states (g0 (n, n) shared or (B, n, n); xi0 or mu0
        (B, d)), the runs spread over ``threads`` threads (default: the CPU count); each
        result is bitwise that of ``sections`` on its own. A failed run's SectionCrossings
        is partial with ``.error`` set (nothing is raised). u, params, t0: as for
        ``simulate_batch`` (a params value with a leading axis of length B is a sweep)."""
        return sections.sections_batch(self.engine, RunArgs(g0, h, steps, xi0, mu0, 1, newton,
                                                            u, params, t0),
                                       max_crossings, threads, chunk)
