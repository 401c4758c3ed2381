"""The pointwise maps of a loaded module's state (``StateMaps``, behind Integrator's
legendre, velocity, observe, energy, momentum and defect): the Legendre transform and its
inverse (velocity from momentum, Newton with the singular-Legendre check), energy, spatial
momentum, the group defect and the observables of many records in one call. Conventions as
Integrator's (g (n, n), mu and xi length d, body frame); an open module evaluates l at a
time t with its runtime parameters.
"""
from __future__ import annotations

import math

import numpy as np

from .. import abi
from ..errors import ConvergenceError, ModelError
from . import newton as _newton
from .args import _array, newton_options
from .inputs import check_params, check_t0
from .newton import NewtonOptions

#: cond(d2l/dxi2) above which the Legendre transform is reported singular
COND_MAX = 1e12


class StateMaps:
    """The state maps of one loaded module on its kernel backend (hpgen.runtime.backends).

    Public methods take user arrays (checked: ArgumentError naming the field); ``flat_g``
    and ``vector`` are those checks; ``velocity_flat`` and ``lv`` are the unchecked forms
    the run engine uses on arrays it has checked already (g flat column-major)."""

    def __init__(self, backend, meta: dict):
        self.backend, self.meta = backend, meta
        self.n, self.d = meta["n"], meta["d"]
        #: an open module's step vector (meta.json "open"), None when closed
        self.open = meta.get("open")
        self._cond_last = None     # (bytes of the last Hessian checked, its cond) (_cond)

    def flat_g(self, g, field="g") -> np.ndarray:
        """g checked as an (n, n) matrix, flat column-major."""
        return _array(g, (self.n, self.n), field, "an n x n matrix").ravel(order="F")

    def vector(self, v, field) -> np.ndarray:
        """v checked as a vector of length d."""
        return _array(v, (self.d,), field, "a vector of length d")

    # ---- open modules (forces, inputs, runtime parameters, t; hpgen.runtime.inputs) ------
    def lv(self, t=0.0, params=None) -> tuple:
        """The extra argument of the kernels that evaluate l without h (abi.OPEN_EXTRA):
        () for a closed module, else (hv,) with hv = [0, t, 0 (m), params] (l takes no u)."""
        if self.open is None:
            return ()
        flat = params if isinstance(params, list) else check_params(self.open, params)
        return (np.array([0.0, float(t)] + [0.0] * len(self.open["inputs"]) + flat),)

    # ---- kernels ------------------------------------------------------------------------
    def legendre(self, g, xi, *, t=0.0, params=None) -> np.ndarray:
        """mu = dl/dxi (g, xi) (at time t, with the runtime parameters ``params``, for an
        open module)."""
        return self.backend.call("legendre", self.flat_g(g), self.vector(xi, "xi"),
                            *self.lv(check_t0(t), params))[0]

    def velocity(self, g, mu, *, newton: NewtonOptions | None = None, t=0.0, params=None):
        """xi with legendre(g, xi) = mu: full Newton from xi = 0 with the hessian kernel
        (newton: its tol and maxit)."""
        o = newton_options(newton, False, full=True)
        return self.velocity_flat(self.flat_g(g), self.vector(mu, "mu"), o.tol, o.maxit,
                              self.lv(check_t0(t), params))

    def _cond(self, Hf, H):
        """cond(H) of the Hessian H (Hf its flat column-major array), None when H has a
        non-finite entry (Newton reports those). Kept for the last H by its bytes: l
        quadratic in xi gives the same H at every Newton iterate, and the decision is a
        function of H alone."""
        key = Hf.tobytes()
        last = self._cond_last
        if last is not None and last[0] == key:
            return last[1]
        cond = None
        if np.isfinite(H).all():
            with np.errstate(all="ignore"):
                cond = float(np.linalg.cond(H)) if H.any() else math.inf
        self._cond_last = (key, cond)
        return cond

    def velocity_flat(self, gf, mu, tol=abi.DEFAULT_TOL, maxit=abi.DEFAULT_MAXIT, lv=()):
        """velocity from g flat column-major and mu, both checked: newton.newton on
        F = legendre - mu, J = hessian; every Hessian passes the singular-Legendre check
        first (_cond)."""
        d, call = self.d, self.backend.call

        def fun(xi):
            F = call("legendre", gf, xi, *lv)[0] - mu
            Hf = call("hessian", gf, xi, *lv)[0]
            H = Hf.reshape(d, d, order="F")
            cond = self._cond(Hf, H)          # None: H has a non-finite entry
            if cond is not None and not cond <= COND_MAX:
                raise ModelError("the Legendre transform is singular at the initial state "
                                 f"(cond(d2l/dxi2) = {cond:.3g}); check the kinetic "
                                 "energy terms of the Lagrangian", field="scene.initial")
            return F, H

        code, xi, it, r = _newton.newton(fun, np.zeros(d), tol, maxit)
        if code != abi.OK:
            raise ConvergenceError("inverting the Legendre transform (velocity from momentum): "
                                   + abi.MESSAGES[code], step=0, time=0.0, residual=r,
                                   iterations=it)
        return xi

    def observe(self, g, mu, *, t=None, inputs=None) -> dict:
        """Observables of K records (xi, energy, momentum, defect): see Integrator.observe."""
        g = np.asarray(g, dtype=np.float64).reshape(-1, self.n, self.n)
        mu = np.asarray(mu, dtype=np.float64).reshape(-1, self.d)
        K = len(mu)
        gf = np.ascontiguousarray(g.transpose(0, 2, 1)).reshape(K, self.n * self.n)
        if self.open is None:
            done, xi, E, m, e = self.backend.observe(gf, mu)
            exact = bool(self.meta.get("legendre_quadratic"))
        else:
            done, exact = 0, False
            xi, E, m, e = np.zeros((K, self.d)), np.zeros(K), np.zeros((K, self.d)), np.zeros(K)
            params = inputs.params if inputs is not None else check_params(self.open, None)
            t = np.zeros(K) if t is None else np.asarray(t, dtype=np.float64)
        for k in range(0 if not exact else done, K):
            lv = () if self.open is None else self.lv(t[k], params)
            xi[k] = self.velocity_flat(gf[k], mu[k], lv=lv)
            E[k] = self.backend.call("energy", gf[k], xi[k], *lv)[0][0]
            if k >= done:
                m[k] = self.backend.call("momentum", gf[k], mu[k])[0]
                e[k] = self.backend.call("defect", gf[k])[0][0]
        return {"xi": xi, "energy": E, "momentum": m, "defect": e}

    def energy(self, g, mu, *, t=0.0, params=None) -> float:
        """Energy <dl/dxi, xi> - l at (g, xi = velocity(g, mu)) (at time t, with ``params``,
        for an open module)."""
        lv = self.lv(check_t0(t), params)
        return float(self.backend.call("energy", self.flat_g(g),
                                  self.velocity_flat(self.flat_g(g), self.vector(mu, "mu"), lv=lv),
                                  *lv)[0][0])

    def momentum(self, g, mu) -> np.ndarray:
        """Spatial momentum Ad*_{g^{-1}} mu."""
        return self.backend.call("momentum", self.flat_g(g), self.vector(mu, "mu"))[0]

    def defect(self, g) -> float:
        """Distance of g from the group (0 on the group)."""
        return float(self.backend.call("defect", self.flat_g(g))[0][0])
