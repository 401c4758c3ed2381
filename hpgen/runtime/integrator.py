"""Integrator: the public API of a loaded module, the same for the C and Python backends; a
thin front whose methods call the run engine (hpgen.runtime.engine) and its outputs. Here:
state maps, step, linearize, simulate and stream; the ensemble, record and section runs are
RunOutputs' (hpgen.runtime.outputs), which Integrator derives from.

Conventions: g is an (n, n) group element (array-like), momenta p/mu and velocities xi are
length-d vectors (body frame; a scalar for d = 1), h != 0 is the step in the model's time unit
(h < 0 runs backwards: the schemes are defined for either sign; a symmetric step steps back
exactly, step(g1, p1, -h) = (g, p) to round-off, which needs rkmk truncated, see
hpgen.tableaus.composition.check_base). Internally and
across the C boundary matrices are flat column-major (``g.ravel(order="F")``).
Newton settings: every stepping method takes ``newton=NewtonOptions(...)`` (None: the
defaults, tol = 1e-14, maxit = 50 (hpgen.abi), the predictor extrapolating the last
solutions; see hpgen.runtime.newton). ``simplified`` (reuse the Jacobian's inverse across
iterations and steps) left None means: for runs, True when the Jacobian kernel costs more
than SIMPLIFIED_RATIO (hpgen.runtime.engine) times the residual kernel (CasADi instruction
counts in meta.json); for ``step`` (a cold start), full Newton.
"""
from __future__ import annotations

import numpy as np

from . import linearize as _linearize, records, states
from .engine import Engine, RunArgs
from .initial import GroupElements
from .newton import NewtonOptions
from .outputs import RunOutputs
from .prologue import Prologue
from .trajectory import Trajectory


class Integrator(RunOutputs):
    """A loaded generated module. Attributes: meta (dict from meta.json), backend ("c" or
    "python"), n, d, nz, module_dir (the directory it was loaded from, or None), engine (the
    run engine behind every run method, hpgen.runtime.engine: the declared interface of the
    modules built on it), fast_path (simulate's fast path on the C backend, else None)."""

    def __init__(self, meta: dict, backend, module_dir=None, composition=None):
        self.meta, self.module_dir = meta, module_dir
        #: the composition (hpgen.tableaus.composition.Composition) whose composed step every
        #: run takes (the backend's runs carry its fractions), None for the plain step
        self.composition = composition
        self.backend = backend.name
        self.n, self.d, self.nz = meta["n"], meta["d"], meta["nz"]
        #: an open module's step vector (meta.json "open"), None when closed
        self.open = meta.get("open")
        self.engine = Engine(backend, meta, owner=self)
        #: simulate's fast path (the C backend; hpgen.runtime.prologue)
        self.fast_path = (Prologue(self.engine) if self.backend == "c" and composition is None
                          else None)

    def __repr__(self):
        comp = "" if self.composition is None else f" compose={self.composition.name}"
        return f"<hpgen Integrator {self.meta['module']} backend={self.backend}{comp}>"

    @property
    def group(self) -> GroupElements:
        """Constructors of initial group elements, as the model file's ``initial.g``:
        ``group.from_rotvec(rotvec, position=None)``, ``group.from_quat([w, x, y, z],
        position=None)`` (SO3, SE3; scalar first), and ``group.as_quat(g)`` /
        ``group.as_rotvec(g)`` reading attitudes back;
        ``group.from_angle_position(angle, position=None)`` (SO2, SE2),
        ``group.from_position(position)`` (R<k>, SE2, SE3), ``group.identity()`` and
        ``group.product(*factor_elements)``; see hpgen.runtime.initial."""
        return GroupElements(self.meta["group"])

    def kernel(self, name, *args):
        """Evaluate one kernel on flat column-major arrays; returns its outputs (a list)."""
        return self.engine.backend.call(name, *args)

    @property
    def simplified_default(self) -> bool:
        """True when simplified Newton pays: J costs > SIMPLIFIED_RATIO residuals (a sparse J:
        False, see Engine.simplified_default)."""
        return self.engine.simplified_default

    # ---- state maps (hpgen.runtime.state_maps) ------------------------------------------
    def legendre(self, g, xi, *, t=0.0, params=None) -> np.ndarray:
        """mu = dl/dxi (g, xi) (at time t, with the runtime parameters ``params``, for an
        open module)."""
        return self.engine.maps.legendre(g, xi, t=t, params=params)

    def velocity(self, g, mu, *, newton: NewtonOptions | None = None, t=0.0, params=None):
        """xi with legendre(g, xi) = mu: full Newton from xi = 0 with the hessian kernel
        (newton: its tol and maxit)."""
        return self.engine.maps.velocity(g, mu, newton=newton, t=t, params=params)

    def observe(self, g, mu, *, t=None, inputs=None) -> dict:
        """Observables of K records, g (K, n, n), mu (K, d) node momenta: arrays xi (K, d)
        (Legendre inverse), energy (K,), momentum (K, d) (spatial), defect (K,). One C call
        (kernel observe) when l is quadratic in xi (meta legendre_quadratic: its one Newton
        step from xi = 0 is exact); otherwise xi and energy are refined record by record with
        ``velocity`` (Newton, the singular-Legendre check included). An open module
        evaluates l at the records' times ``t`` (K,) with the run's ``inputs`` (StepInputs:
        its runtime parameters), record by record."""
        return self.engine.maps.observe(g, mu, t=t, inputs=inputs)

    def energy(self, g, mu, *, t=0.0, params=None) -> float:
        """Energy <dl/dxi, xi> - l at (g, xi = velocity(g, mu)) (at time t, with ``params``,
        for an open module)."""
        return self.engine.maps.energy(g, mu, t=t, params=params)

    def momentum(self, g, mu) -> np.ndarray:
        """Spatial momentum Ad*_{g^{-1}} mu."""
        return self.engine.maps.momentum(g, mu)

    def defect(self, g) -> float:
        """Distance of g from the group (0 on the group)."""
        return self.engine.maps.defect(g)

    @property
    def record_names(self) -> tuple:
        """What this module's record row holds (the scene's ``record:`` list, in order)."""
        return records.record_names(self.meta)

    # ---- stepping and runs (hpgen.runtime.engine) -----------------------------------------
    def step(self, g, p, h, z=None, *, newton: NewtonOptions | None = None, u=None,
             params=None, t=0.0):
        """One step (g_k, p_k) -> (g_(k+1), p_(k+1)).

        Parameters
        ----------
        g : array_like, shape (n, n)
            Group element g_k.
        p : array_like, shape (d,)
            Node momentum p_k (body frame).
        h : float
            Step size, != 0, in the model's time unit (h < 0 steps backwards).
        z : array_like, shape (nz,), optional
            Newton start (``integ.nz`` unknowns); default: the guess kernel at the velocity
            of (g, p), by continuation in h when that start fails (closed models).
        newton : hpgen.runtime.newton.NewtonOptions or None, optional
            Newton settings (tol 1e-14, maxit 50); here full Newton unless
            ``newton.simplified`` is True (a cold start).
        u : array_like, shape (m,), optional
            Control inputs of a model with ``inputs:`` (required there), held over the step.
        params : dict, optional
            Overrides of the model's ``runtime_parameters`` (defaults: the model file's
            values); no recompilation.
        t : float, optional
            The step's start time t_k (default 0).

        Returns
        -------
        g1 : ndarray, shape (n, n)
        p1 : ndarray, shape (d,)

        Raises
        ------
        ConvergenceError, DomainError
            Newton failed, or the solution left the chart's domain (step 0, t = 0).

        A composed integrator (``composition``) takes its substeps S(gamma_i h) one after the
        other, each Newton from its own start (``z`` is not used).
        """
        if self.composition is None:
            return self.engine.step(g, p, h, z, newton, u, params, t)
        # the composed step: its substeps one after the other, each from its own start
        c = 0.0
        for gi in self.composition.gammas:
            g, p = self.engine.step(g, p, gi * h, None, newton, u, params, t + c * h)
            c += gi
        return g, p

    def linearize(self, traj, *, u=None, params=None, t0=None, wrt=None,
                  newton: NewtonOptions | None = None):
        """A (K, 2d, 2d): A[k] = d(eta_{k+1}, dp_{k+1}) / d(eta_k, dp_k) along ``traj`` (this
        module's ``simulate(..., every=1)``), perturbations g -> g tau(eta), p -> p + dp; by
        the implicit function theorem at each converged step (hpgen.runtime.linearize).
        newton: the Newton settings recovering each step's solution (as simulate's).

        An open module (forces, inputs, runtime parameters or t) takes simulate's u, params
        and t0 (default: the trajectory's first time) and returns (A, B), B (K, 2d, m) =
        d(eta_{k+1}, dp_{k+1}) / d u_k, or with wrt="params" P (K, 2d, n_runtime_params).
        A closed module takes none of u, params, t0, wrt."""
        return _linearize.along(self.engine, traj, newton, u, params, t0, wrt)

    def casadi_step(self):
        """casadi.Function step(g, p, h, z) -> (F, g1, p1) (an open module's:
        step(g, p, u, params, h, z, t)): this module's residual and explicit update as CasADi
        expressions, for optimal control (compile-time stack: needs casadi;
        hpgen.derive.export.module_casadi_step)."""
        from ..derive.export import module_casadi_step    # the compile side (casadi)
        return module_casadi_step(self.module_dir, self.meta,
                                  lambda *a: self.kernel("residual", *a))

    def simulate(self, g0, h, steps, xi0=None, mu0=None, every=1, *,
                 newton: NewtonOptions | None = None, u=None, params=None,
                 t0=0.0) -> Trajectory:
        """Run ``steps`` steps of size h and keep every ``every``-th state.

        The C backend runs all steps in one call.

        Parameters
        ----------
        g0 : array_like, shape (n, n)
            Initial group element, on the group to 1e-10 (n = ``integ.n``).
        h : float
            Step size, != 0, in the model's time unit (h < 0 runs backwards).
        steps : int
            Number of steps, >= 0.
        xi0 : array_like, shape (d,), optional
            Initial body velocity (d = ``integ.d``); p_0 = dl/dxi(g0, xi0).
        mu0 : array_like, shape (d,), optional
            Initial body momentum (node momentum p_0). Exactly one of xi0 and mu0.
        every : int, optional
            Record interval in steps, >= 1 (default 1). Record k is the state after step
            k*every; the last step is recorded only if ``steps % every == 0``.
        newton : hpgen.runtime.newton.NewtonOptions or None, optional
            Newton settings: tol (1e-14: ||dz|| <= tol (1 + ||z||)), maxit (50), simplified
            (None: keep J^{-1} across iterations and steps when the Jacobian kernel costs more
            than 4 residuals, docs/numerics.md sec. 8), predictor (True: start each step from
            the extrapolation of the last solutions). None: all defaults.
        u : array_like, shape (m,) or (steps, m), optional
            Control inputs of a model with ``inputs:`` (required there): one row held for
            every step, or row k held over step k.
        params : dict, optional
            Overrides of the model's ``runtime_parameters`` (defaults: the model file's
            values); no recompilation.
        t0 : float, optional
            Start time (default 0): record k is at t0 + k every h.

        Returns
        -------
        Trajectory
            ``t`` (K,), ``g`` (K, n, n), ``mu`` (K, d) node momenta, K = steps // every + 1;
            ``energy()``, ``momentum()``, ``xi()``, ``defect()``, ``save(path)``.

        Raises
        ------
        ArgumentError
            A bad argument (shape, value, g0 off the group, both or neither of xi0/mu0).
        ConvergenceError, DomainError
            A step failed; ``.partial`` is the Trajectory so far (partial=True).
        KeyboardInterrupt
            Ctrl-C (a long run is advanced in slices of bounded wall time and checks for it
            between them); ``.partial`` is the Trajectory of the steps done (partial=True).
        """
        if self.fast_path is not None:
            traj = self.fast_path.simulate(g0, h, steps, xi0, mu0, every, newton, t0, u, params)
            if traj is not None:
                return traj
        return states.simulate(self.engine, RunArgs(g0, h, steps, xi0, mu0, every, newton, u,
                                                    params, t0))

    def stream(self, g0, h, steps, xi0=None, mu0=None, every=1, chunk=100_000, *,
               newton: NewtonOptions | None = None, u=None, params=None, t0=0.0):
        """``simulate`` in chunks of at most ``chunk`` steps (bounded memory on long runs).

        The states are bitwise those of ``simulate``: the run, its Newton memory and
        predictor carry over between chunks.

        Parameters
        ----------
        g0, h, steps, xi0, mu0
            As for ``simulate``: g0 (n, n) on the group, h != 0 in the model's time unit,
            steps >= 0, exactly one of xi0 / mu0 (d,).
        every : int, optional
            Record interval in steps, >= 1 (default 1).
        chunk : int, optional
            Steps per chunk (one C call each), >= 1 (default 100,000).
        newton : NewtonOptions or None, optional
            Newton settings, as for ``simulate``.
        u, params, t0
            As for ``simulate`` (an open module's inputs, runtime parameters, start time).

        Yields
        ------
        Trajectory
            One per chunk; the first starts with step 0, ``t`` is global.

        Raises
        ------
        ModelError
            A bad argument.
        ConvergenceError, DomainError
            A step failed; ``.partial`` holds the records of the failing chunk.
        """
        return states.stream(self.engine, RunArgs(g0, h, steps, xi0, mu0, every, newton, u,
                                                  params, t0), chunk)
