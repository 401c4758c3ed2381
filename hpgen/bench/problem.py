"""The benchmarked problem: a model's scene as an ODE y' = f(t, y) on the embedded state.

Conventions (shared by every method of the benchmark):
- y = (g flattened row-major (n*n entries), mu (d entries)), the state of
  ``ContinuousEquations.reference``; g is n x n, mu the body momentum (pairing: dot product).
- f(t, y) = (g xi^, ad*_xi mu + g dl/dg + f_ext) with xi = xi(g, mu, t) the inverse
  Legendre transform, f_ext the model's force (math.md sec. 9: + f in mu') at the time t,
  the inputs u (constant: the scene's u or the ``u`` given; held over every step alike) and
  the default runtime parameters; a closed model's f does not depend on t. Built
  on CasADi symbols from ``ContinuousEquations``' own functions (its Newton residual and
  Hessian d2l/dxi2, and its rhs), nothing re-derived. When d2l/dxi2 does not depend on xi (a
  kinetic energy quadratic in xi: every shipped example) one Newton step from xi = 0 is exact;
  otherwise NEWTON_UNROLL steps are unrolled and ``Problem.notes`` says so.
- error(y) = max(|g - g_ref|max, |mu - mu_ref|max) at the horizon T.
- energy E(y) = <dl/dxi, xi> - l(g, xi) at xi = xi(g, mu); energy drift of a run =
  max_j |E(y_j) - E(y0)| over its samples (each method says which samples it gives); NaN
  for a forced or time-dependent model, whose energy is not conserved (``conservative``).
- group defect: ContinuousEquations.defect(g) (|R^T R - I|max for SO3) at T.
- spatial momentum: Ad*_{g^-1} mu (the group's momentum map), per sample.
"""
from __future__ import annotations

import math
import numbers

import numpy as np

from ..errors import ModelError

NEWTON_UNROLL = 8


def load_model(path):
    """The validated model of a model file; ModelError (one line) when it cannot be read."""
    from ..api import read_model_text
    from ..model import load_model_text
    return load_model_text(read_model_text(path), filename=str(path))


def positive(x, field):
    """A finite float > 0 or ModelError naming ``field``."""
    if isinstance(x, bool) or not isinstance(x, numbers.Real) or not (
            math.isfinite(x) and x > 0):
        raise ModelError(f"expected a finite number > 0, got {x!r}", field=field)
    return float(x)


class Problem:
    """A model file's scene over [0, T] as an ODE on y. Attributes: path, model, eq
    (ContinuousEquations), n, d, ny, T, scene, g0, mu0, xi0 (None when the scene gives mu),
    y0, f (casadi.Function (t, y) -> f(t, y), dense), t_sym, y_sym, ydot_sym, u (the
    constant inputs, None without), conservative (energy conserved: not forced, no t), E0,
    notes (list of str). ``u``: the inputs (m,) (default: the scene's u, which must then be
    constant)."""

    def __init__(self, path, T=None, u=None):
        import casadi as ca
        from ..analysis.rkmk import ContinuousEquations

        self.path = str(path)
        self.model = model = load_model(path)
        if model.scene is None:
            raise ModelError("hpgen bench needs the model's scene (initial state, h)",
                             file=self.path, field="scene")
        self.scene = sc = model.scene
        self.u = self._inputs(model, u)
        self.T = positive(sc.steps * sc.h if T is None else T, "option T")
        self.eq = eq = ContinuousEquations(model, u=self.u)
        self.conservative = not (model.forced or model.time_dependent)
        n, d = eq.n, eq.d
        self.n, self.d, self.ny = n, d, n * n + d
        self.g0 = np.array(sc.g0, dtype=float)
        self.xi0 = None if sc.xi0 is None else np.array(sc.xi0, dtype=float)
        self.mu0 = (np.array(sc.mu0, dtype=float) if sc.mu0 is not None
                    else eq.legendre(self.g0, self.xi0))
        self.y0 = self.pack(self.g0, self.mu0)
        self.notes = []

        y, t = ca.SX.sym("y", self.ny), ca.SX.sym("t")
        self._targs = (t, ca.DM(np.asarray(eq.u, float).reshape(-1, 1))) if eq.open else ()
        g, mu = ca.reshape(y[:n * n], n, n).T, y[n * n:]
        xi = self._velocity_expr(ca, g, mu)
        gdot, mudot = eq._rhs(g, xi, mu, *self._targs)
        ydot = ca.densify(ca.vertcat(ca.reshape(gdot.T, n * n, 1), mudot))
        self.t_sym, self.y_sym, self.ydot_sym = t, y, ydot
        self.f = ca.Function("hpgen_bench_rhs", [t, y], [ydot])
        energy = eq._energy(g, xi, *self._targs)
        self._energy = ca.Function("energy", [y], [ca.substitute(energy, t, ca.SX(0.0))])
        self._momentum = ca.Function("momentum", [y], [eq._momentum(g, mu)])
        self.E0 = self.energy(self.y0[None])[0]

    def _velocity_expr(self, ca, g, mu):
        """xi(g, mu) as a CasADi expression, by Newton on ContinuousEquations' residual."""
        d = self.d
        probe = ca.SX.sym("xi", d)
        hess = self.eq._newton(g, probe, mu, *self._targs)[1]
        xi = ca.SX.zeros(d)
        steps = NEWTON_UNROLL if ca.depends_on(hess, probe) else 1
        if steps > 1:
            self.notes.append(f"d2l/dxi2 depends on xi: xi(g, mu) by {steps} unrolled "
                              "Newton steps in f")
        for _ in range(steps):
            r, H = self.eq._newton(g, xi, mu, *self._targs)
            xi = xi - ca.solve(H, r)
        return xi

    def _inputs(self, model, u):
        """The constant inputs (m,) of the bench: ``u``, else the scene's u; None without
        inputs. The peers integrate the forced equations with u fixed, and hpgen holds the
        same u over every step."""
        from ..runtime.args import _array
        from ..errors import ArgumentError
        m = len(model.inputs)
        if not m:
            if u is not None:
                raise ModelError("this model has no control inputs (inputs:), so it takes "
                                 "no u", field="option u")
            return None
        if u is None:
            spec = model.scene.u
            if spec is None:
                raise ModelError(f"the model has control inputs ({', '.join(model.inputs)}); "
                                 "give them as scene.u or with --u", file=self.path,
                                 field="scene.u")
            if spec.kind != "constant":
                raise ModelError("hpgen bench takes a constant u (m numbers; its peers "
                                 "integrate the forced equations with u fixed); give one with "
                                 "--u", file=self.path, field="scene.u")
            return np.array(spec.values, dtype=float)
        try:
            return _array(u, (m,), "u", f"the inputs ({', '.join(model.inputs)})")
        except ArgumentError as e:
            raise ModelError(e.message, field="option u") from None

    # ---- conversions and figures ------------------------------------------------------
    def pack(self, g, mu):
        """y (or (K, ny) from (K, n, n) and (K, d))."""
        g, mu = np.asarray(g, dtype=float), np.asarray(mu, dtype=float)
        return np.concatenate([g.reshape(g.shape[:-2] + (-1,)), mu], axis=-1)

    def unpack(self, y):
        y = np.asarray(y, dtype=float)
        nn = self.n * self.n
        return y[..., :nn].reshape(y.shape[:-1] + (self.n, self.n)), y[..., nn:]

    def _mapped(self, fun, Y):
        Y = np.atleast_2d(np.asarray(Y, dtype=float))
        return np.array(fun.map(len(Y))(Y.T)).T

    def energy(self, Y) -> np.ndarray:
        """(K,) energies of the states Y (K, ny)."""
        return self._mapped(self._energy, Y).reshape(-1)

    def momentum(self, Y) -> np.ndarray:
        """(K, d) spatial momenta Ad*_{g^-1} mu of the states Y (K, ny)."""
        return self._mapped(self._momentum, Y).reshape(-1, self.d)

    def energy_drift(self, Y) -> float:
        """max_j |E(Y_j) - E(y0)| (NaN when a state is not finite, or the energy is not
        conserved: a forced or time-dependent model)."""
        Y = np.atleast_2d(Y)
        if not self.conservative or not np.isfinite(Y).all():
            return math.nan
        return float(np.abs(self.energy(Y) - self.E0).max())

    def defect(self, y) -> float:
        if not np.isfinite(y).all():
            return math.nan
        return float(self.eq.defect(self.unpack(y)[0]))

    @staticmethod
    def error(y, y_ref) -> float:
        """max(|g - g_ref|max, |mu - mu_ref|max) = the max norm on y; NaN if not finite."""
        if y_ref is None or not np.isfinite(y).all():
            return math.nan
        return float(np.abs(np.asarray(y) - y_ref).max())

    # ---- reference ----------------------------------------------------------------------
    def exact_inertia(self):
        """The principal moments when the model is a free rigid body with a diagonal
        inertia (SO3, l = 1/2 xi.diag(I) xi + const), else None: then
        hpgen.analysis.exact gives the solution."""
        if self.model.group.name != "SO3" or not self.model.left_invariant or \
                self.model.open_system:
            return None
        import casadi as ca
        g, xi, mu = ca.SX.sym("g", 3, 3), ca.SX.sym("xi", 3), ca.SX.sym("mu", 3)
        r, H = self.eq._newton(g, xi, mu)
        if ca.depends_on(H, ca.vertcat(ca.vec(g), xi)):
            return None
        H = np.array(ca.evalf(H))
        if np.abs(H - np.diag(np.diag(H))).max() != 0.0 or not (np.diag(H) > 0).all():
            return None
        if np.abs(self.eq.legendre(np.eye(3), np.zeros(3))).max() != 0.0:
            return None      # a term linear in xi (gyroscopic): not Euler's equations
        return np.diag(H).copy()

    def reference(self, kind, rhs):
        """(y_ref at T, description). kind: 'auto' (exact if available, else DOP853),
        'exact', 'dop853' (rtol = atol = 1e-13 on f, ``rhs(t, y)``), 'none' -> (None, ...)."""
        if kind == "none":
            return None, "none (errors not computed)"
        inertia = self.exact_inertia()
        if kind == "exact" and inertia is None:
            raise ModelError("no exact solution is known for this model (only the free "
                             "rigid body with a diagonal inertia)", field="option reference")
        if kind in ("auto", "exact") and inertia is not None:
            from ..analysis.exact import free_rigid_body_attitude
            # times start at 0: attitude() takes its initial Euler angles at t[0] (with
            # t = [T] alone it returns a wrong R, hpgen 0.1.0)
            R, Pi = free_rigid_body_attitude(inertia, self.mu0, self.g0, [0.0, self.T])
            return self.pack(R[-1], Pi[-1]), ("exact (Jacobi elliptic functions, "
                                              "hpgen.analysis.exact)")
        from scipy.integrate import solve_ivp
        sol = solve_ivp(rhs, (0.0, self.T), self.y0, method="DOP853", rtol=1e-13, atol=1e-13)
        if not sol.success:
            raise ModelError(f"the DOP853 reference failed: {sol.message}",
                             field="option reference")
        return sol.y[:, -1].copy(), f"DOP853 rtol = atol = 1e-13 ({sol.nfev} f-evals)"
