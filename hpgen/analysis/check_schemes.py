"""The schemes ``hpgen check`` runs (hpgen.analysis.check): ``_Hpgen`` the compiled VPRK
scheme (plain or composed) and ``_Rkmk`` explicit RKMK-RK4, each with simulate(g0, mu0, h,
steps, every, u) -> (g, mu) and map_jacobian(g, p, h, t) -> (Phi', g1, p1); ``_load`` the
model file with parameter overrides.

A composed step S(gamma_s h) o ... o S(gamma_1 h) has the composition's order only when its
base step S is symmetric, S(-h) o S(h) = id (Hairer, Lubich, Wanner, sec. V.3).
``_Hpgen.symmetry_defect`` measures it at a state: max(|g_2 - g|, |p_2 - p|) / (1 + |p|)
after S(h) then S(-h), both by full Newton (tolerance 1e-14 relative); a symmetric step
leaves round-off, the two solves' 1e-14 times the step's amplification, below SYMMETRY_TOL.
"""
from __future__ import annotations

import numpy as np

from ..schemes import is_splitting
from .rkmk import RKMK4
from .symplectic import GeneratedMap, converged_step

#: the largest symmetry defect of a symmetric base step (round-off; see the module docstring)
SYMMETRY_TOL = 1e-12


def _load(path, parameters=None):
    from ..api import read_model_text
    from ..model import load_model_text
    from ..model.overrides import apply_overrides
    text = apply_overrides(read_model_text(path), dict(parameters or ()), file=str(path))
    return load_model_text(text, filename=str(path))


class _Hpgen:
    """The compiled scheme: simulate with the runtime, Jacobian by implicit differentiation."""

    def __init__(self, path, model, tableau, tau, rkmk, backend, cache_dir, compose=None,
                 parameters=None):
        from ..api import build
        # the compile's own result: its resolved options and DiscreteStep (derived once,
        # on a cache hit only when asked for here)
        compiled = build(path, tableau=tableau, tau=tau, rkmk=rkmk, backend=backend,
                         cache_dir=cache_dir, compose=compose, parameters=parameters)
        self.integ = compiled.load()
        d = compiled.derivation
        tab, self.tau, self.rkmk = d.tableau, d.tau, d.rkmk
        self.map = GeneratedMap(self.integ, d.step, model.group)
        self.order = tab.order if self.rkmk == "exact" else min(tab.order, 2)
        self.splitting = is_splitting(tab)
        if self.splitting:            # explicit composition: its own order, no chart, no RKMK
            self.order = tab.order
        #: the composition in effect (--compose, else the model's integrator.compose)
        self.composition = self.integ.composition
        self.info = {"tableau": tab.name, "tau": self.tau, "rkmk": self.rkmk,
                     "backend": backend, "module": self.integ.meta.get("module"),
                     "compose": None if self.composition is None else self.composition.name}
        op = self.integ.open          # an open model: the file's params, t0 = 0
        self.u = None if op is None or not op["inputs"] else np.zeros(len(op["inputs"]))
        self.defaults = [] if op is None else [float(v) for v in op["defaults"]]

    def simulate(self, g0, mu0, h, steps, every=1, u=None):
        u = self.u if u is None else u
        tr = self.integ.simulate(g0=g0, mu0=mu0, h=h, steps=steps, every=every, u=u)
        return tr.g, tr.mu

    def map_jacobian(self, g, p, h, t=0.0):
        """(Phi', g1, p1) of one step; a composed step's Phi' = Phi'_s ... Phi'_1 over its
        substeps S(gamma_i h) (each at its own start and time), cond_J and
        kernel_mismatch the largest over them."""
        gammas = (1.0,) if self.composition is None else self.composition.gammas
        Phi, c, extra = None, 0.0, {"cond_J": 0.0, "kernel_mismatch": 0.0}
        for gi in gammas:
            hv = None if self.integ.open is None else \
                [gi * h, t + c * h, *([] if self.u is None else self.u), *self.defaults]
            Pi, g, p = self.map.map_jacobian(g, p, gi * h, hv=hv)
            Phi = Pi if Phi is None else Pi @ Phi
            extra = {k: max(v, self.map.last[k]) for k, v in extra.items()}
            c += gi
        self.extra = extra
        return Phi, g, p

    def symmetry_defect(self, g, p, h, t=0.0) -> float:
        """max over the composition's substep sizes gamma_i h of the base step's
        symmetry defect at (g, p) (module docstring); the plain step's at h."""
        gammas = (1.0,) if self.composition is None else self.composition.gammas
        worst = 0.0
        for hi in sorted({abs(gi) * h for gi in gammas}):
            hv1 = hv2 = None
            if self.integ.open is not None:
                u = [] if self.u is None else list(self.u)
                hv1, hv2 = [hi, t, *u, *self.defaults], [-hi, t + hi, *u, *self.defaults]
            _, g1, p1 = converged_step(self.integ, g, p, hi, hv=hv1)
            _, g2, p2 = converged_step(self.integ, g1, p1, -hi, hv=hv2)
            worst = max(worst, float(max(np.abs(g2 - g).max(), np.abs(p2 - p).max())
                                     / (1.0 + np.abs(p).max())))
        return worst


class _Rkmk:
    def __init__(self, model, eq):
        self.rk = RKMK4(model, eq)
        self.order = RKMK4.order
        self.info = {"name": "rkmk-rk4", "tau": "exp"}
        self.extra = {"cond_J": 1.0, "kernel_mismatch": 0.0}

    def simulate(self, g0, mu0, h, steps, every=1, u=None):
        g, mu = self.rk.simulate(g0, mu0, h, steps)
        return g[::every], mu[::every]

    def map_jacobian(self, g, p, h, t=0.0):
        return self.rk.map_jacobian(g, p, h)
