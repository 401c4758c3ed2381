"""``hpgen check``: structure and accuracy figures of one integrator on a model's scene.

    report = run_check("examples/heavy_top.yaml", tableau="gauss2", tau="exp", rkmk="exact")
    print(format_report(report)); write_json(report, "check.json")   # hpgen.analysis.check_report

Scheme: ``"hpgen"`` (the compiled VPRK scheme for tableau/tau/rkmk, model defaults for None)
or ``"rkmk-rk4"`` (explicit RKMK-RK4 on the continuous equations, hpgen.analysis.rkmk, not
symplectic: the check must fail on it). The initial state is the model's scene (g0 and xi0 or
mu0); h and steps default to the scene's. States are (g, p), p the node momentum
(docs/numerics.md sec. 4), compared with mu(t) = dl/dxi of the reference.

Figures (the keys of the JSON report):
- ``order``: {expected, why, horizon T, h: [h, h/2, h/4], error: [3], observed: [2], floor,
  refined: {h, error, observed}, asymptotic_h, status}:
  error = max(|g_N - g(T)|, |p_N - mu(T)|) against DOP853 at rtol = atol = 1e-12 on the
  continuous equations (docs/numerics.md sec. 9); observed = log2 of
  successive error ratios, the last is the estimate. T = ``order_horizon`` (default
  min(1, steps h)) rounded to whole steps of h. floor: the finest error is below 1e-10, where
  the reference's own error (about 1e-12) may spoil the estimate. expected: see
  ``expected_order`` (hpgen.analysis.check_order; it depends on the model: a left-invariant
  l makes every q = 0 and every variational Euler step order 2). When the observed orders do not yet agree with it (within
  ORDER_TOL), h keeps being halved (``refined``: every level, from h) until two successive
  orders agree, the errors reach the floor or a run would exceed REFINE_MAX_STEPS steps;
  asymptotic_h is the largest h from which they agree (None if not reached) and status
  ``asymptotic`` | ``floor`` | ``not reached``. Informative: the order is not a pass
  criterion (a pre-asymptotic slope is no structure fault).
- ``energy``: {initial, max_error = max_k |E_k - E_0|, relative_max_error, drift_slope}
  over the run of ``steps`` steps at h; drift_slope is the slope of the least-squares line
  through (t_k, E_k - E_0), per unit time.
- ``momentum``: {initial, max_change (per component max_k |m_k - m_0|), left_invariant},
  m_k = Ad*_{g_k^{-1}} p_k the spatial momentum.
- ``group_defect``: {max}: max_k of the group's distance of g_k from G (|R^T R - I|, ...).
- ``symplectic``: {defect (max absolute), relative (max), tolerance, states: [{t, absolute,
  relative, jacobian_norm, cond_J, kernel_mismatch}], form}: the defect
  max |Phi'^T Omega(p_1) Phi' - Omega(p_0)| of the one-step map's Jacobian in the
  left-trivialized chart (hpgen.analysis.symplectic), at ``n_states`` states along the run.
- a forced model (``forces``; the file's runtime parameters, t0 = 0; the inputs u from
  ``controls``, else the scene's u, else u = 0, held over the steps of h: the runs with
  h / 2^k hold the same piecewise-constant u(t), and DOP853 restarts at its jumps):
  ``energy`` is the energy-work balance (E - W) - E_0 (``balance`` true), W the forces'
  work by the node rule of hpgen.runtime.work; ``momentum.max_change`` for a left-invariant
  l is the forced momentum balance max |m_k - m_0 - int_0^t Ad*_{g^-1} f dt| (``balance``
  true; the discrete identity with the stage sum is exact, the node quadrature makes it
  the scheme's order: informative, not a pass criterion); ``symplectic`` has no states
  (None: a forced flow is not symplectic). A model that is open without forces (t,
  runtime parameters) is checked as a closed one, the step vector at the state's time.
- ``constraints`` (None unconstrained; hpgen.analysis.constrained): {position, velocity,
  tolerance, count}: max_k |phi(g_k)| and max_k |Phi(g_k) xi_k| over the run of ``count``
  constraint rows. A constrained model's order is measured by self-convergence (the
  differences of successive halvings; ``order.reference`` says so), its symplecticity
  defect on the tangent space of the constraint manifold (``symplectic.on_manifold``), its
  momentum map not checked (constraints break the symmetry in general).
- ``symmetry`` (None unless the step is composed, ``compose`` or integrator.compose):
  {defect, tolerance}: the base step's max |S(-h_i) S(h_i) x - x| / (1 + |p|) over the
  substep sizes h_i at the symplecticity states (hpgen.analysis.check_schemes); the
  composed step's Jacobian is the product of the substeps', its expected order the
  composition's.
- ``inputs``: None without control inputs, else {names, kind (constant, expressions, table,
  zero), source (scene.u, --u, the default u = 0)}.
- ``checks``: {symplectic, group, momentum (None unless l is left-invariant), symmetric
  (a composed step), constraints (a constrained model)} booleans;
  ``passed``: all of them that apply. Also model, file, group, scheme, integrator, h,
  steps, duration, hpgen_version, seconds.

Pass criteria and why:
- symplectic: relative <= SYMPLECTIC_RTOL * max(1, cond_J / 100). Round-off model: Phi' comes
  from an LU solve with dF/dz, so its relative error is a few eps * cond(dF/dz); the defect
  sums products of two Phi' entries with Omega, so defect / (|Phi'|^2 |Omega|) ~ a few
  eps cond(J). Measured with ``hpgen check --h 0.1`` (4 states): 1.05e-15 (free body
  gauss2/exp/exact), 2.83e-15 (free body gauss3/cay/exact), 1.45e-15 (underwater vehicle
  gauss2/cay/exact); the bound (1e-12 times cond_J / 100 when larger) leaves a margin above
  10^3, while a non-symplectic 4th order method shows h^5-size defects (RKMK-RK4 at
  h = 0.1: 2.31e-6 relative on the heavy top).
- group: max defect <= GROUP_TOL = 1e-10 (the runtime's bound for an initial g).
- momentum (left-invariant l only): max change <= MOMENTUM_RTOL (1e-10) * max(1, |m_0|).
- constraints: both residuals <= CONSTRAINT_TOL (1e-12); symmetric: defect <= SYMMETRY_TOL
  (1e-12), round-off of two Newton solves at 1e-14 (a non-symmetric base, e.g. Stormer-Verlet
  with the exact RKMK constraint on the heavy top, leaves O(h^4): 4e-6 at h = 0.05).
Exit status of the CLI: 0 all pass, 3 a check failed (2 bad input, 1 other failures).
"""
from __future__ import annotations

import math
import time

import numpy as np

from .. import __version__
from ..errors import ModelError
from .check_order import order_study, scheme_order
from .check_schemes import SYMMETRY_TOL, _Hpgen, _load, _Rkmk
from .constrained import CONSTRAINT_TOL
from .rkmk import ContinuousEquations
from .symplectic import ad_matrices, defect_along

SYMPLECTIC_RTOL = 1e-12
GROUP_TOL = 1e-10
MOMENTUM_RTOL = 1e-10
SCHEMES = ("hpgen", "rkmk-rk4")
FORM = "omega((eta_a,nu_a),(eta_b,nu_b)) = <nu_b,eta_a> - <nu_a,eta_b> + <p,[eta_a,eta_b]>"


def _positive(x, name):
    if x is None or not (isinstance(x, (int, float)) and math.isfinite(x) and x > 0):
        raise ModelError(f"expected a finite number > 0, got {x!r}", field=f"option {name}")
    return float(x)


def run_check(path, *, scheme="hpgen", tableau=None, tau=None, rkmk=None, h=None, steps=None,
              backend="c", cache_dir=None, order_horizon=None, n_states=4,
              controls=None, compose=None, parameters=None) -> dict:
    """Run every check on the model file ``path``; returns the report (see module doc).
    ``controls``: the inputs u of a model with inputs (hpgen.model.controls.ControlSpec;
    default the scene's u, else u = 0); ``compose``: a composition of the compiled step
    (hpgen.tableaus.composition; default the model's integrator.compose); ``parameters``:
    new values of the file's parameters ({"N": 3}: a family's body count), as compile's."""
    t_start = time.perf_counter()
    if scheme not in SCHEMES:
        raise ModelError(f"expected one of {', '.join(SCHEMES)}, got {scheme!r}",
                         field="option scheme")
    model = _load(path, parameters)
    sc = model.scene
    if sc is None:
        raise ModelError("hpgen check needs the model's scene (initial state)", file=str(path),
                         field="scene")
    constrained = bool(getattr(model, "constraints", ()))
    if scheme != "hpgen" and (constrained or compose is not None):
        raise ModelError("the rkmk-rk4 scheme of hpgen check runs unconstrained, uncomposed "
                         "models only", file=str(path), field="option scheme")
    if model.open_system and scheme != "hpgen":
        raise ModelError("the rkmk-rk4 scheme of hpgen check runs closed models only (no "
                         "forces, inputs, runtime parameters or t)", file=str(path),
                         field="option scheme")
    h = _positive(sc.h if h is None else h, "h")
    steps = sc.steps if steps is None else steps
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 1:
        raise ModelError(f"expected an integer >= 1, got {steps!r}", field="option steps")
    eq = ContinuousEquations(model)
    controls = sc.u if controls is None else controls
    g0 = np.array(sc.g0, dtype=float)
    mu0 = (np.array(sc.mu0, dtype=float) if sc.mu0 is not None
           else eq.legendre(g0, np.array(sc.xi0, dtype=float)))
    sch = (_Hpgen(path, model, tableau, tau, rkmk, backend, cache_dir, compose, parameters)
           if scheme == "hpgen" else _Rkmk(model, eq))
    manifold = None
    if constrained:
        from .constrained import ManifoldCheck
        manifold = ManifoldCheck(model)

    # observed order against DOP853
    T = _positive(min(1.0, steps * h) if order_horizon is None else order_horizon,
                  "order_horizon")
    n_o = max(1, round(T / h))
    # u held over the steps of h (rows U); a run with h / 2^k holds row j over its steps
    # j 2^k .. (j + 1) 2^k - 1: the same piecewise-constant u(t), jumps on every grid
    U = None if controls is None or not model.inputs else \
        np.atleast_2d(controls.rows(h, max(steps, n_o)))

    def u_of(k, N):
        return None if U is None else (U[0] if len(U) == 1 else
                                       np.repeat(U, 2 ** k, axis=0)[:N])
    expected, why = scheme_order(sch, model, scheme)
    order = order_study(sch, eq, g0, mu0, h, n_o, u_of, U, constrained=constrained,
                        expected=expected, why=why)

    # the run at h: energy (a forced model: E - W), momentum map (forced: its balance with
    # the spatial impulse), group defect
    g, mu = sch.simulate(g0, mu0, h, steps, u=u_of(0, steps))
    t = np.arange(len(g)) * h
    E, xi, f = [], None, []
    for gk, mk, tk in zip(g, mu, t):
        xi = eq.velocity(gk, mk, xi, t=tk) if model.open_system else eq.velocity(gk, mk, xi)
        E.append(eq.energy(gk, xi, t=tk) if model.open_system else eq.energy(gk, xi))
        if model.forced:
            if U is not None:     # the input of the step that ends at node k (u_0 at 0)
                eq.u = U[min(max(len(f) - 1, 0), len(U) - 1)]
            f.append(eq.applied(gk, xi, t=tk))
    m = np.array([eq.momentum(gk, mk) for gk, mk in zip(g, mu)])
    dE, dm = np.array(E) - E[0], m - m[0]
    if model.forced:
        from ..runtime.work import WorkSum
        xis = [eq.velocity(gk, mk, t=tk) for gk, mk, tk in zip(g, mu, t)]
        power = np.einsum("ki,ki->k", np.array(f), np.array(xis))
        dE = dE - WorkSum(h).add(power)                 # (E - W) - E_0
        spatial = np.array([eq.momentum(gk, fk) for gk, fk in zip(g, f)])
        if model.left_invariant:   # else l's own g-dependence moves m too: no balance
            dm = dm - np.stack([WorkSum(h).add(spatial[:, i]) for i in range(len(m[0]))],
                               axis=1)
    slope = float(np.polyfit(t, dE, 1)[0]) if len(t) > 1 else 0.0
    dm = np.abs(dm).max(axis=0)
    gdef = max(eq.defect(gk) for gk in g)
    cons = None
    if manifold is not None:
        res = np.array([manifold.residuals(gk, eq.velocity(gk, mk, t=tk) if model.open_system
                                           else eq.velocity(gk, mk))
                        for gk, mk, tk in zip(g, mu, t)])
        cons = {"position": float(res[:, 0].max()), "velocity": float(res[:, 1].max()),
                "tolerance": CONSTRAINT_TOL, "count": manifold.m}

    # symplecticity defect at a few states of the run (a forced flow is not symplectic)
    states = []
    if not model.forced:
        idx = sorted(set(np.linspace(0, len(g) - 1, max(1, n_states)).round().astype(int)))
        ad = ad_matrices(model.group)
        for i in idx:
            on_m = None if manifold is None else manifold.tangent_basis(
                g[i], mu[i], eq.velocity(g[i], mu[i], t=float(t[i])) if model.open_system
                else eq.velocity(g[i], mu[i]), t=float(t[i]))
            rec = defect_along(lambda G, P, H: sch.map_jacobian(G, P, H, t=float(t[i])), ad,
                               [(g[i], mu[i])], h, tangent=on_m)[0]
            rec.update(t=float(t[i]), **sch.extra)
            states.append(rec)
    # a composed step: its base step's symmetry S(-h) o S(h) = id, which the composition's
    # order needs, at the same states
    symmetry = None
    if getattr(sch, "composition", None) is not None:
        idx = sorted(set(np.linspace(0, len(g) - 1, max(1, n_states)).round().astype(int)))
        symmetry = {"defect": max(sch.symmetry_defect(g[i], mu[i], h, t=float(t[i]))
                                  for i in idx), "tolerance": SYMMETRY_TOL}
    sym_abs = max((s["absolute"] for s in states), default=None)
    sym_rel = max((s["relative"] for s in states), default=None)
    tol = SYMPLECTIC_RTOL * max(1.0, max((s["cond_J"] for s in states), default=0) / 100.0)

    checks = {"symplectic": None if model.forced else bool(sym_rel <= tol),
              "group": bool(gdef <= GROUP_TOL),
              "momentum": (bool(dm.max() <= MOMENTUM_RTOL * max(1.0, np.abs(m[0]).max()))
                           if model.left_invariant and not model.forced and not constrained
                           else None),
              "symmetric": None if symmetry is None else bool(
                  symmetry["defect"] <= SYMMETRY_TOL),
              "constraints": None if cons is None else bool(
                  max(cons["position"], cons["velocity"]) <= CONSTRAINT_TOL)}
    return {
        "hpgen_version": __version__, "model": model.name, "file": str(path),
        "group": model.group.name, "scheme": scheme, "integrator": sch.info,
        "h": h, "steps": steps, "duration": steps * h,
        "order": order,
        "energy": {"initial": float(E[0]), "max_error": float(np.abs(dE).max()),
                   "relative_max_error": float(np.abs(dE).max() / max(abs(E[0]), 1e-300)),
                   "drift_slope": slope, "balance": bool(model.forced)},
        "momentum": {"initial": m[0].tolist(), "max_change": dm.tolist(),
                     "left_invariant": bool(model.left_invariant),
                     "balance": bool(model.forced and model.left_invariant)},
        "group_defect": {"max": float(gdef)},
        "symplectic": {"defect": sym_abs, "relative": sym_rel, "tolerance": tol,
                       "states": states, "form": FORM, "on_manifold": constrained},
        "constraints": cons,
        "symmetry": symmetry,
        "checks": checks,
        "inputs": None if not model.inputs else {
            "names": list(model.inputs),
            "kind": "zero" if U is None else controls.kind,
            "source": "the default u = 0" if U is None else
            ("--u" if controls.where[1].startswith("option") else controls.where[1])},
        "passed": all(v for v in checks.values() if v is not None),
        "seconds": time.perf_counter() - t_start,
    }
