"""The IR produced by the derive stage: one step of the discrete HP action sum, as CasADi
functions with a fixed calling convention, ready for code generation.

Calling convention of every kernel: inputs and outputs are dense column vectors of doubles;
matrices are flattened column-major (g.ravel(order="F")); h is a 1-vector.

    residual(z[nz], g[n*n], p[d], h[1])  -> F[nz]          stationarity conditions of s_k
    jacobian(z, g, p, h)                 -> J[nz*nz]       dF/dz, dense, column-major
    residual_jacobian(z, g, p, h)        -> F[nz], J[nz*nz] both in one evaluation
    update(z, g, p, h)                   -> g1[n*n], p1[d] (g_{k+1}, p_{k+1}), explicit
    guess(xi[d], g, p, h)                -> z0[nz]         Newton start from a velocity estimate
    legendre(g, xi)                      -> mu[d]          dl/dxi (Legendre transform)
    hessian(g, xi)                       -> H[d*d]         d^2 l / dxi^2
    energy(g, xi)                        -> E[1]           <dl/dxi, xi> - l
    momentum(g, p)                       -> m[d]           Ad*_{g^{-1}} p (spatial momentum)
    defect(g)                            -> e[1]           distance of g from the group
    margin(z, h)                         -> m[1]           > 0 while every tau argument of
                                                           the step is inside tau's domain
    section(g, p)                        -> s[1]           the scene's Poincare section
                                                           s(g, mu = p) (1 without one)
    chart_point(z, g, h, theta)          -> g_theta[n*n]   g tau(theta h xi_{k+1}(z)): the
                                                           step's chart curve, theta in [0, 1]
    observe(g, p)                        -> xi[d], E[1], m[d], e[1]   at a record: the
                                           Legendre inverse xi of p (one Newton step from 0:
                                           exact when legendre_quadratic), energy at that xi,
                                           spatial momentum, group defect
    update_p(z, g, p, h)                 -> p1[d]          p_{k+1} alone (update's p1): the
                                                           step when g is not needed
    velocity_step(g, p, xi)              -> xi1[d]         one Newton step of dl/dxi = p:
                                           xi - H^{-1}(dl/dxi(g, xi) - p); exact from xi = 0
                                           when legendre_quadratic
    record(g, p, xi)                     -> row[w]         the scene's record row
                                           (hpgen.derive.records; layout in record_layout)
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

KERNEL_NAMES = ("residual", "jacobian", "residual_jacobian", "update", "guess", "legendre",
                "hessian", "energy", "momentum", "defect", "margin", "section", "chart_point",
                "observe", "update_p", "velocity_step", "record")


@dataclass(frozen=True)
class Kernel:
    name: str                   # one of KERNEL_NAMES
    function: Any               # casadi.Function over SX, dense inputs/outputs as above
    inputs: tuple[str, ...]     # argument names, e.g. ("z", "g", "p", "h")
    outputs: tuple[str, ...]


@dataclass(frozen=True)
class DiscreteStep:
    """One step (g_k, p_k) -> (g_{k+1}, p_{k+1}) of a Lie group VPRK method.

    unknowns: ((label, start, stop), ...) the blocks of z, e.g. ("Xi1", 0, 3).
    reduced: True for the Euler-Poincare step of a left-invariant Lagrangian (no g in F).
    """
    model_name: str
    group_name: str
    n: int
    d: int
    nz: int
    tableau_name: str
    tableau_order: int
    tau: str
    rkmk: str
    reduced: bool
    unknowns: tuple
    kernels: tuple               # tuple[Kernel, ...], in KERNEL_NAMES order
    section: str | None = None   # the scene's Poincare section text (None: kernel section = 1)
    legendre_quadratic: bool = False   # d2l/dxi2 free of xi: observe's xi is exact
    record_layout: tuple = ()    # ((name, offset, shape), ...): see hpgen.derive.records
    step_uses_g: bool = True     # residual or update_p depend on g
    record_uses_g: bool = True   # the record row depends on g
    record_uses_xi: bool = True  # the record row depends on xi (velocity_step needed)

    @property
    def record_width(self) -> int:
        """w: the record row's length."""
        return sum(math.prod(shape) for _, _, shape in self.record_layout)

    def kernel(self, name: str) -> Kernel:
        for k in self.kernels:
            if k.name == name:
                return k
        raise KeyError(name)
