"""The first step's Newton start, and what to say when none lies inside the chart
(``FirstStep``; the run engine's and Integrator.step's start).

The guess kernel builds the start from the continuous velocity xi0 (an open module's at
step 0's step vector [h, t0, u_0, params]). Every later step starts from the predictor,
which extrapolates the last solutions inside the run loop (hpgen_run_step in C, its mirror
hpgen.runtime.loop: ``predictor_base`` and ``predict``); a run's first step is the one
whose start is made here. When that start lies outside tau's domain although the discrete
step exists inside it (the discrete |h xi| is smaller than the continuous one), the first
step is solved by continuation in h; a run whose first step failed from its start is retried
from there (``restart``). When no start is found, ``domain_hint`` names the chart's limit
and the largest |h| whose first step solves. Continuation is for closed modules only (an
open module's step vector carries t, u, params). An explicit step (meta "explicit", a
splitting scheme) has no Newton start: its unknown is p_k, the start is mu0 (the value of its
guess kernel) and there is nothing to retry.
"""
from __future__ import annotations

import math

import numpy as np

from .. import abi
from ..errors import ConvergenceError
from ..schemes import TAU
from .newton import NewtonOptions


class FirstStep:
    """The first step's start of one module: ``start`` (the Newton start of a run's first
    step), ``restart`` (the second try after a first step that failed from it) and
    ``domain_hint`` (the message when no start lies inside the chart). backend: the kernel
    backend (hpgen.runtime.backends); velocity(gf, mu) -> xi the Legendre inverse
    (StateMaps.velocity_flat)."""

    def __init__(self, backend, meta: dict, velocity):
        self.backend, self.meta, self.velocity = backend, meta, velocity
        self.open = meta.get("open")
        self.explicit = meta.get("explicit") is True

    def start(self, gf, mu0, xi0, h, opts=None, inputs=None):
        """The Newton start of a run's first step from (g0 flat, mu0, xi0): a closed
        module's by ``closed_start``, an open module's the guess kernel at step 0's step
        vector (``inputs``: its StepInputs); an explicit step's mu0."""
        if self.explicit:
            return np.array(mu0, dtype=np.float64)
        if inputs is None:
            return self.closed_start(gf, mu0, xi0, h, opts)
        return self.backend.call("guess", xi0, gf, mu0, np.array(inputs.hv(h, 0)))[0]

    def _inside(self, z, h) -> bool:
        return bool(self.backend.call("margin", z, np.array([h]))[0][0] > 0.0)

    def _largest_h(self, gf, mu0, xi0, h) -> float:
        """The largest |h'| <= |h| (sign of h, by bisection to 2^-40 relative) whose guess
        start lies inside the chart, 0.0 if none does."""
        call, lo, hi = self.backend.call, 0.0, h
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            if self._inside(call("guess", xi0, gf, mu0, np.array([mid]))[0], mid):
                lo = mid
            else:
                hi = mid
        return lo

    def _continued(self, gf, mu0, xi0, h, opts=None):
        """(t, z): the first step solved at h' = t h by continuation: from the largest h'
        whose guess start lies inside the chart (times 0.9, halved until its step solves
        from the guess), h' grows towards h, each solve (full Newton, the run's tol and
        maxit) from the solution before; t = 1.0 when it reached h, 0.0 when not even the
        first h' solved."""
        call = self.backend.call
        t = self._largest_h(gf, mu0, xi0, h) / h * 0.9
        if not t > 0.0:
            return 0.0, None
        base = opts or NewtonOptions()      # the run's tol and maxit, full Newton
        opts = NewtonOptions(base.tol, base.maxit, False, False)
        for _ in range(20):          # a first h' whose step solves from its guess
            hv = np.array([t * h])
            code, _, _, z, _, _ = self.backend.step(gf, mu0, hv,
                                                    call("guess", xi0, gf, mu0, hv)[0], opts)
            if code == abi.OK:
                break
            t *= 0.5
        else:
            return 0.0, None
        dt = t
        for _ in range(200):
            if t == 1.0 or dt < 1e-6:
                break
            tn = min(1.0, t + dt)
            c, _, _, zn, _, _ = self.backend.step(gf, mu0, np.array([tn * h]), z, opts)
            if c == abi.OK:
                t, z, dt = tn, zn, 1.5 * dt
            else:
                dt *= 0.5
        return t, z

    def closed_start(self, gf, mu0, xi0, h, opts=None):
        """Newton start of the first step: the guess kernel's (built from the continuous
        velocity xi0). When that start lies outside the chart although the step may exist
        (the discrete |h xi| is smaller than the continuous one: Stormer-Verlet/Cayley at
        h |xi0| = 2.2-3.3 has steps inside the chart), the step is solved by continuation in
        h (_continued) and its solution at h is the start; when the continuation does not
        reach h, the guess (the run then reports the start as a DomainError)."""
        z0 = self.backend.call("guess", xi0, gf, mu0, np.array([h]))[0]
        if self._inside(z0, h):
            return z0
        t, z = self._continued(gf, mu0, xi0, h, opts)
        return z if t == 1.0 else z0

    def restart(self, st, gf, mu0, h, z0, opts):
        """The start of a second try when the run's first step failed from z0 (Newton
        diverged, or converged outside the chart): the first step solved by continuation in
        h (_continued), or None when that does not reach h or gives z0 again."""
        if (st["code"] in (abi.OK, abi.RECORD) or st["step"] != 0 or self.open
                or self.explicit):
            return None
        try:
            xi0 = self.velocity(gf, mu0)
        except ConvergenceError:
            return None
        t, z = self._continued(gf, mu0, xi0, h, opts)
        return z if t == 1.0 and not np.array_equal(z, z0) else None

    def domain_hint(self, gf, mu0, xi0, h) -> str:
        """What the chart needs when the first step's start lies outside it: tau's limit on
        the rotation part omega of h xi, |omega| at the start, and the largest |h| for which
        the first step was solved inside the chart (by continuation)."""
        tau = self.meta["options"]["tau"]
        chart = TAU.get(tau)
        limit = f"{tau} needs {chart.domain}"
        if self.open:          # the kernels' step vector carries t, u, params: not searched
            return limit
        try:
            if xi0 is None:
                xi0 = self.velocity(np.asarray(gf, dtype=np.float64).ravel(),
                                     np.asarray(mu0, dtype=np.float64).ravel())
            hs = abs(self._largest_h(gf, mu0, xi0, h))
            t, _ = self._continued(gf, mu0, xi0, h)
        except ConvergenceError:
            return limit
        if not hs > 0.0:
            return limit
        size = (f"the start has |omega| = {chart.radius * abs(h) / hs:.3g} (|xi| = "
                f"{chart.radius / hs:.3g})" if chart.radius < math.inf
                else "the start is outside")
        solved = abs(t * h)
        take = (f"the first step solves inside the chart up to |h| = {solved:.3g}: take |h| < "
                f"{solved:.3g}" if solved > 0.0 else f"take |h| < {hs:.3g}")
        return f"{limit} (omega: the rotation part of h xi): {size}; {take}"
