"""Discrete optimal control on Lie groups with the HP step as constraints.

    plan = hpgen.ocp.rest_to_rest(integ, g0, gT, T, steps)

Rest-to-rest transfer of a forced model (``inputs:`` entering through ``forces:``) from g0 to
gT in time T = steps h, minimizing the discrete control effort sum_k |u_k|^2 h, with the
compiled scheme's step as equality constraints (discrete mechanics and optimal control:
Kobilarov & Marsden, "Discrete geometric optimal control on Lie groups", 2011). Solved by
IPOPT through ``casadi.Opti`` (CasADi ships IPOPT).

Transcription (math.md sec. 10's conventions). Variables per step k: the step's unknowns
z_k (nz), the chart increment eta_k of g_k, the node momentum p_k (d) and the input u_k (m,
held over step k). g_k = gref_k tau(eta_k), tau the module's chart and gref_k a fixed
reference: gref_0 = g0, gref_steps = gT, gref_k = g0 tau(k/steps eta_T) between, eta_T the
chart coordinates of g0^{-1} gT (Gauss-Newton on the n x n equation g0 tau(eta_T) = gT), so
that eta_0 = eta_steps = 0 pin the ends and eta = 0 is IPOPT's start. The
constraints of step k are ``Integrator.casadi_step``'s

    F(z_k; g_k, p_k, u_k, params, h, t_k) = 0                       (nz)
    vee(g_{k+1}^{-1} g1(z_k; ...) - e) = 0                          (d: g_{k+1} = g1 locally)
    p_{k+1} - p1(z_k; ...) = 0                                      (d)

and at rest at both ends p_0 = dl/dxi(g0, 0), p_steps = dl/dxi(gT, 0) (the Legendre kernel).
The second line is the right-trivialized output chart of ``linearize``: its derivative at
g_{k+1} = g1 is invertible, so the constraints are d independent equations; it has far
solutions too (e.g. a rotation by pi on SO3), so the plan is checked afterwards:
|g_{k+1} - g1(z_k)| <= CHECK_TOL at every step, else HpgenError. The planned
states satisfy the module's own step up to IPOPT's tolerance: ``integ.simulate(g0, h, steps,
mu0=plan.mu[0], u=plan.u)`` reproduces plan.g, plan.mu (tests/unit/test_ocp.py).

Compile-time stack: casadi (imported here, lazily by ``import hpgen.ocp``; never on the
runtime path).
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import ArgumentError, HpgenError


@dataclass(frozen=True)
class Plan:
    """An optimal rest-to-rest transfer.

    g (steps+1, n, n), mu (steps+1, d) node momenta, u (steps, m) inputs (u[k] held over
    step k), z (steps, nz) the steps' unknowns, t (steps+1,) times, h the step, cost
    sum |u_k|^2 h, iterations IPOPT's iteration count, seconds IPOPT's wall time,
    status IPOPT's return status."""
    g: np.ndarray
    mu: np.ndarray
    u: np.ndarray
    z: np.ndarray
    t: np.ndarray
    h: float
    cost: float
    iterations: int
    seconds: float
    status: str


def _group(integ):
    from .model import load_model_text
    path = Path(integ.module_dir) / "model.yaml"
    return load_model_text(path.read_text(), filename=str(path)).group


#: a plan's g_{k+1} must equal the step's update g1(z_k; ...) to this (max-norm)
CHECK_TOL = 1e-9


def _chart_coordinates(ca, tau_f, g0, gT, d, iterations=50):
    """eta with g0 tau(eta) = gT: Gauss-Newton on the n x n residual (zero only there)."""
    E = ca.SX.sym("e", d)
    r = ca.reshape(ca.mtimes(g0, tau_f(E)) - gT, -1, 1)
    fun = ca.Function("r", [E], [r, ca.jacobian(r, E)])
    eta = np.zeros(d)
    for _ in range(iterations):
        R, Jr = (np.array(a) for a in fun(eta))
        step = np.linalg.lstsq(Jr, -R.ravel(), rcond=None)[0]
        eta = eta + step
        if np.abs(step).max() <= 1e-15 * (1 + np.abs(eta).max()):
            break
    if not np.abs(np.array(fun(eta)[0])).max() <= 1e-12:
        raise ArgumentError("gT is not reachable from g0 in the module's chart (tau(eta) = "
                         "g0^{-1} gT has no solution near 0)", field="gT")
    return eta


def _check(integ, g0, gT, T, steps):
    if integ.open is None or not integ.open["inputs"]:
        raise ArgumentError("expected a model with control inputs (inputs: entering through "
                         "forces:)", field="integ")
    g0 = np.asarray(g0, dtype=np.float64)
    gT = np.asarray(gT, dtype=np.float64)
    for name, g in (("g0", g0), ("gT", gT)):
        if g.shape != (integ.n, integ.n) or not np.isfinite(g).all():
            raise ArgumentError(f"expected a finite {integ.n} x {integ.n} matrix, got shape "
                             f"{g.shape}", field=name)
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 2:
        raise ArgumentError(f"expected an integer number of steps >= 2, got {steps!r}",
                         field="steps")
    if not (isinstance(T, (int, float)) and np.isfinite(T) and T > 0):
        raise ArgumentError(f"expected a positive finite time T, got {T!r}", field="T")
    return g0, gT


def rest_to_rest(integ, g0, gT, T, steps, *, params=None, t0=0.0, tol=1e-12,
                 max_iter=200, print_level=0) -> Plan:
    """Minimum-effort rest-to-rest transfer g0 -> gT in time T with ``steps`` steps of
    ``integ`` (a compiled open module with inputs); see the module docstring.

    params: runtime parameter overrides (as simulate's); t0: start time; tol: IPOPT's tol
    and constr_viol_tol; max_iter, print_level: IPOPT's. Returns a Plan. Raises ArgumentError
    for bad arguments, HpgenError when IPOPT does not solve the problem."""
    import casadi as ca
    from .runtime.inputs import check_params
    g0, gT = _check(integ, g0, gT, T, steps)
    group, f = _group(integ), integ.casadi_step()
    n, d, nz, m = integ.n, integ.d, integ.nz, len(integ.open["inputs"])
    h, flat = float(T) / steps, check_params(integ.open, params)
    tau = integ.meta["options"]["tau"]
    # SX helpers called on the Opti's MX: g = gref tau(eta), the output chart at g_{k+1}
    R, E, G1 = ca.SX.sym("R", n, n), ca.SX.sym("eta", d), ca.SX.sym("G1", n, n)
    chart = ca.Function("chart", [R, E], [ca.mtimes(R, group.tau(tau, E))])
    gap = ca.Function("gap", [R, G1], [group.vee(ca.mtimes(group.inverse(R), G1) - ca.SX.eye(n))])
    eta_T = _chart_coordinates(ca, lambda e: group.tau(tau, e), g0, gT, d)
    rest = [integ.legendre(g, np.zeros(d), t=t, params=params)
            for g, t in ((g0, t0), (gT, t0 + T))]

    opti = ca.Opti()
    eta, P = opti.variable(d, steps + 1), opti.variable(d, steps + 1)
    U, Z = opti.variable(m, steps), opti.variable(nz, steps)
    ref = [g0] + [np.array(chart(g0, k / steps * eta_T)) for k in range(1, steps)] + [gT]
    G = [chart(ref[k], eta[:, k]) for k in range(steps + 1)]
    for k in range(steps):
        F, g1, p1 = f(G[k], P[:, k], U[:, k], flat, h, Z[:, k], t0 + k * h)
        opti.subject_to(F == 0)
        opti.subject_to(gap(G[k + 1], g1) == 0)
        opti.subject_to(P[:, k + 1] - p1 == 0)
    opti.subject_to(eta[:, 0] == 0)
    opti.subject_to(eta[:, steps] == 0)
    opti.subject_to(P[:, 0] == rest[0])
    opti.subject_to(P[:, steps] == rest[1])
    opti.minimize(h * ca.sumsqr(U))
    opti.set_initial(P, np.linspace(rest[0], rest[1], steps + 1).T)
    opti.solver("ipopt", {"print_time": False},
                {"tol": tol, "constr_viol_tol": tol, "max_iter": max_iter,
                 "print_level": print_level, "sb": "yes"})
    start = time.perf_counter()
    try:
        sol = opti.solve()
    except RuntimeError as exc:
        try:
            stats = opti.stats()
        except RuntimeError:      # the solver never started (e.g. its plugin did not load)
            raise HpgenError("CasADi could not start IPOPT: "
                             f"{str(exc).splitlines()[-1]}; install casadi >= 3.6.1, whose "
                             "wheels carry IPOPT and its libraries") from None
        raise HpgenError(f"IPOPT did not solve the transfer ({stats.get('return_status')},"
                               f" {stats.get('iter_count')} iterations): "
                               f"{str(exc).splitlines()[-1]}") from None
    seconds = time.perf_counter() - start
    stats = sol.stats()
    gk = ca.Function("g", [eta], G)
    etav = np.array(sol.value(eta)).reshape(d, steps + 1)
    g = np.array([np.array(x) for x in gk(etav)]).reshape(steps + 1, n, n)
    u = np.array(sol.value(U)).reshape(m, steps).T
    z = np.array(sol.value(Z)).reshape(nz, steps).T
    mu = np.array(sol.value(P)).reshape(d, steps + 1).T
    for k in range(steps):
        g1 = np.array(f(g[k], mu[k], u[k], flat, h, z[k], t0 + k * h)[1])
        if not np.abs(g1 - g[k + 1]).max() <= CHECK_TOL:
            raise HpgenError(f"IPOPT's plan is not the step at step {k} (|g_(k+1) - g1| = "
                             f"{np.abs(g1 - g[k + 1]).max():.1e}): a far solution of the "
                             "chart constraint; try more steps")
    return Plan(g=g, mu=mu, u=u, z=z,
                t=t0 + h * np.arange(steps + 1), h=h, cost=float(h * np.sum(u ** 2)),
                iterations=int(stats["iter_count"]), seconds=seconds,
                status=str(stats["return_status"]))
