"""Integrator: the public API of a loaded module, the same for the C and Python backends.

Conventions: g is an (n, n) group element (array-like), momenta p/mu and velocities xi are
length-d vectors (body frame; a scalar for d = 1), h != 0 is the step in the model's time unit
(h < 0 runs backwards: the schemes are defined for either sign, and a symmetric tableau with
exact RKMK steps back exactly, step(g1, p1, -h) = (g, p) to round-off). Internally and
across the C boundary matrices are flat column-major (``g.ravel(order="F")``).
Newton settings: every stepping method takes ``newton=NewtonOptions(...)`` (None: the
defaults, tol = 1e-14, maxit = 50 (hpgen.abi), a predictor extrapolating the last solutions,
quadratic once three exist; see hpgen.runtime.newton). ``simplified`` (reuse the Jacobian's
inverse across iterations and steps) left None means: for runs, True when the Jacobian kernel
costs more than SIMPLIFIED_RATIO times the residual kernel (CasADi instruction counts in
meta.json), where it is the faster choice (Gauss 2 exact: 7.5 residual evaluations and 0.14
Jacobians per step instead of 2.8 of each); for ``step`` (a cold start), full Newton.
"""
from __future__ import annotations

import numpy as np

from .. import abi
from ..errors import ArgumentError
from .args import _array, _error, _fits, _int, _positive, _step_size
from .initial import GroupElements
from .inputs import check_t0, step_inputs
from .newton import NewtonOptions
from .prologue import Prologue
from .batch import BatchMixin
from .first_step import FirstStepMixin
from .records import RecordsMixin
from .sections import SectionsMixin
from .state_maps import StateMapsMixin
from .trajectory import Trajectory

DEFECT_MAX = 1e-10
SIMPLIFIED_RATIO = 4.0

class Integrator(StateMapsMixin, BatchMixin, FirstStepMixin, SectionsMixin, RecordsMixin):
    """A loaded generated module. Attributes: meta (dict from meta.json), backend ("c" or
    "python"), n, d, nz, module_dir (the directory it was loaded from, or None)."""

    def __init__(self, meta: dict, backend, module_dir=None):
        self.meta, self._b, self.module_dir = meta, backend, module_dir
        self.backend = backend.name
        self.n, self.d, self.nz = meta["n"], meta["d"], meta["nz"]
        self._cond_last = None     # (bytes of the last Hessian checked, its cond) (_cond)
        #: an open module's step vector (meta.json "open", hpgen.abi), None when closed
        self.open = meta.get("open")
        #: simulate's fast path (the C backend; hpgen.runtime.prologue)
        self._prologue = Prologue(self, DEFECT_MAX) if self.backend == "c" else None

    def __repr__(self):
        return f"<hpgen Integrator {self.meta['module']} backend={self.backend}>"

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

    # ---- argument helpers -----------------------------------------------------------
    def _g(self, g, field="g"):
        return _array(g, (self.n, self.n), field, "an n x n matrix").ravel(order="F")

    def _v(self, v, field):
        return _array(v, (self.d,), field, "a vector of length d")

    def kernel(self, name, *args):
        """Evaluate one kernel on flat column-major arrays; returns its outputs (a list)."""
        return self._b.call(name, *args)

    # ---- stepping -----------------------------------------------------------------------
    @property
    def simplified_default(self) -> bool:
        """True when simplified Newton pays: J costs > SIMPLIFIED_RATIO residuals."""
        k = self.meta["kernels"]
        cost = [k[n].get("instructions", 0) for n in ("jacobian", "residual")]
        return cost[0] > SIMPLIFIED_RATIO * cost[1]

    def _options(self, newton: NewtonOptions | None, full: bool = False) -> NewtonOptions:
        """The checked Newton settings of a call, simplified resolved to a bool (None: full
        Newton when ``full``, else simplified_default). ArgumentError naming the field."""
        if newton is None:
            newton = NewtonOptions()
        elif not isinstance(newton, NewtonOptions):
            raise ArgumentError("expected hpgen.runtime.NewtonOptions(tol=, maxit=, "
                                f"simplified=, predictor=) or None, got "
                                f"{type(newton).__name__}", field="newton")
        simplified = newton.simplified
        if simplified is None:
            simplified = False if full else self.simplified_default
        return NewtonOptions(_positive(newton.tol, "newton.tol"),
                             _int(newton.maxit, "newton.maxit", 1), bool(simplified),
                             bool(newton.predictor))

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
        """
        gf, p = self._g(g), self._v(p, "p")
        h = _step_size(h)
        inputs = step_inputs(self.open, 1, u, params, t)
        hv = np.array([h] if inputs is None else inputs.hv(h, 0))
        xi = None
        opts = self._options(newton, full=True)
        xi = None
        if z is None:
            if inputs is None:
                xi = self._velocity(gf, p)
                z = self._start(gf, p, xi, h, opts)
            else:
                lv = () if inputs is None else self._lv(inputs.t0, inputs.params)
                z = self._b.call("guess", self._velocity(gf, p, lv=lv), gf, p, hv)[0]
        else:
            z = _array(z, (self.nz,), "z", "a vector of length nz")
        code, g1, p1, _, it, r = self._b.step(gf, p, hv, z, opts)
        z1 = None if xi is None else self._restart({"code": code, "step": 0}, gf, p, h, z,
                                                  opts)
        if z1 is not None:
            code, g1, p1, _, it, r = self._b.step(gf, p, hv, z1, opts)
        if code != abi.OK:
            hint = self._domain_hint(gf, p, xi, h) if xi is not None else ""
            raise _error(code, 0, 0.0, r, it, hint)
        return g1.reshape(self.n, self.n, order="F"), p1

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
        from .linearize import linearize, linearize_open
        if self.open is None:
            for name, v in (("u", u), ("params", params), ("t0", t0), ("wrt", wrt)):
                if v is not None:
                    raise ArgumentError("this model has no forces, inputs, runtime "
                                        f"parameters or t: linearize takes no {name}",
                                        field=name)
            return linearize(self, traj, self._options(newton))
        return linearize_open(self, traj, self._options(newton), u, params, t0, wrt)

    def casadi_step(self):
        """casadi.Function step(g, p, h, z) -> (F, g1, p1) (an open module's:
        step(g, p, u, params, h, z, t)): this module's residual and explicit update as CasADi
        expressions, for optimal control (compile-time stack: needs casadi;
        hpgen.api.casadi_step, hpgen.derive.export)."""
        from .. import api     # the compile side: it alone imports casadi (lazily)
        return api.casadi_step(self)

    def _initial(self, g0, xi0, mu0, lv=()):
        """(g0 flat, mu0, xi0) from g0 and exactly one of xi0 / mu0, checked; lv: the
        open module's extra argument of l at the start (_lv)."""
        g0 = _array(g0, (self.n, self.n), "g0", "an n x n matrix")
        if (xi0 is None) == (mu0 is None):
            raise ArgumentError("give exactly one of xi0 (velocity) and mu0 (momentum)",
                                field="xi0" if xi0 is not None else "mu0")
        gf = g0.ravel(order="F")      # g0 checked: the kernels take it as it is
        e = float(self._b.call("defect", gf)[0][0])
        if not e <= DEFECT_MAX:
            raise ArgumentError(f"g0 is not on the group (defect {e:.3g} > {DEFECT_MAX:g})",
                                field="initial g")
        if xi0 is not None:
            xi0 = self._v(xi0, "xi0")
            mu0 = self._b.call("legendre", gf, xi0, *lv)[0]
        else:
            mu0 = self._v(mu0, "mu0")
            xi0 = self._velocity(gf, mu0, lv=lv)
        return gf, mu0, xi0

    def _trajectory(self, done, g_rec, p_rec, st, h, every, inputs=None, t0=0.0):
        K = done // every + 1
        return self._records(np.asarray(g_rec)[:K], np.asarray(p_rec)[:K], st, h, every, t0,
                             inputs)

    def _records(self, g_rec, p_rec, st, h, every, t0, inputs=None):
        """Trajectory of flat column-major records starting at time t0; error set (and its
        .partial) when the status is a failure."""
        K, n = len(p_rec), self.n
        g = np.ascontiguousarray(g_rec.reshape(K, n, n).transpose(0, 2, 1))
        err = None
        if st["code"] != abi.OK:
            hint = ""
            if st["code"] == abi.DOMAIN and st["iterations"] == 0 and t0 == 0.0:
                hint = self._domain_hint(g_rec[0], p_rec[0], None, h)
            err = _error(st["code"], st["step"], st["step"] * h, st["residual"],
                         st["iterations"], hint)
        # t0 + (k every) h; arange(0, K every, every) is arange(K) * every, and adding
        # t0 = 0.0 to these non-negative numbers changes no bit
        t = np.arange(0, K * every, every) * h
        traj = Trajectory(t=t0 + t if t0 else t, g=g, mu=np.array(p_rec), h=h,
                          every=every, partial=err is not None, error=err,
                          newton_iterations=int(st["total_iterations"]),
                          jacobians=int(st["jacobians"]), integrator=self, inputs=inputs)
        if err is not None:
            err.partial = traj
        return traj

    def _prepare(self, g0, h, steps, xi0, mu0, every, newton, u=None, params=None, t0=0.0):
        """The checked arguments of a run and its start: (h, steps, every, options, g0 flat,
        mu0, Newton start z0 (_start), StepInputs or None (closed))."""
        h = _step_size(h)
        steps, every = _int(steps, "steps", 0), _int(every, "every", 1)
        opts = self._options(newton)
        inputs = step_inputs(self.open, steps, u, params, t0)
        if inputs is None:
            gf, mu0, xi0 = self._initial(g0, xi0, mu0)
            z0 = self._start(gf, mu0, xi0, h, opts)
        else:
            gf, mu0, xi0 = self._initial(g0, xi0, mu0, self._lv(inputs.t0, inputs.params))
            z0 = self._b.call("guess", xi0, gf, mu0, np.array(inputs.hv(h, 0)))[0]
        return h, steps, every, opts, gf, mu0, z0, inputs

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
        """
        if self._prologue is not None:
            traj = self._prologue.simulate(g0, h, steps, xi0, mu0, every, newton, t0, u,
                                           params)
            if traj is not None:
                return traj
        return self._simulate(g0, h, steps, xi0, mu0, every, newton, u, params, t0)

    def _simulate(self, g0, h, steps, xi0, mu0, every, newton, u, params, t0):
        """simulate's generic path (every module, backend and argument)."""
        h, steps, every, opts, gf, mu0, z0, inputs = self._prepare(
            g0, h, steps, xi0, mu0, every, newton, u, params, t0)
        _fits(steps // every + 1, self.n * self.n + self.d, "simulate")
        if inputs is None:
            done, g_rec, p_rec, st = self._b.simulate(gf, mu0, h, z0, steps, every, opts)
            z1 = self._restart(st, gf, mu0, h, z0, opts)
            if z1 is not None:
                done, g_rec, p_rec, st = self._b.simulate(gf, mu0, h, z1, steps, every, opts)
        else:
            done, g_rec, p_rec, st = self._b.simulate(gf, mu0, h, z0, steps, every, opts,
                                                      inputs)
        traj = self._trajectory(done, g_rec, p_rec, st, h, every, inputs, check_t0(t0))
        if traj.error is not None:
            raise traj.error
        return traj

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
        chunk = _int(chunk, "chunk", 1)
        h, steps, every, opts, gf, mu0, z0, inputs = self._prepare(
            g0, h, steps, xi0, mu0, every, newton, u, params, t0)
        run = self._b.start(gf, mu0, z0) if inputs is None else \
            self._b.start(gf, mu0, z0, inputs)
        t_start = check_t0(t0)
        k, first = 0, True
        while first or k < steps:
            todo = min(chunk, steps - k)
            done, g_rec, p_rec, st = self._b.advance(run, h, todo, every, opts)
            z1 = (self._restart(st, gf, mu0, h, z0, opts) if first and inputs is None
                  else None)
            if z1 is not None:
                run = self._b.start(gf, mu0, z1)
                done, g_rec, p_rec, st = self._b.advance(run, h, todo, every, opts)
            if first:
                g_rec = np.concatenate([gf.reshape(1, -1), g_rec])
                p_rec = np.concatenate([mu0.reshape(1, -1), p_rec])
            tc = (k // every + (0 if first else 1)) * every * h
            traj = self._records(g_rec, p_rec, st, h, every, t_start + tc if t_start else tc,
                                 inputs)
            if traj.error is not None:
                raise traj.error
            yield traj
            k += done
            first = False
