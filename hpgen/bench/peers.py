"""The peers a user would pick instead of hpgen, all on the Problem's y' = f(y).

Families (names used by --peers, the CSV ``family`` column and the comparisons):
A forced or time-dependent model's f depends on t (the continuous forced Euler-Poincare
equations with the inputs u constant, hpgen.bench.problem); every peer evaluates it at its
own stage times.
- ``DOP853``, ``RK45``: scipy.integrate.solve_ivp over a grid of rtol, atol = rtol *
  ATOL_FACTOR; f is the C vector field (hpgen.bench.crk4, via ctypes: the cheapest f Python
  can call). Samples: the accepted steps (solve_ivp without t_eval, no dense output).
- ``cvodes-bdf``, ``cvodes-adams``: casadi.integrator 'cvodes' (BDF with Newton and CasADi's
  AD Jacobian / Adams) over a grid of reltol, abstol = reltol * ATOL_FACTOR; f evaluated by
  CasADi's virtual machine. Samples: an output grid of ``samples`` intervals (CVODES
  interpolates there; its steps are the same).
- ``collocation``: casadi.integrator 'collocation', Gauss-Legendre points
  (collocation_scheme 'legendre', COLLOCATION_ORDER points: order 2 s), number of finite
  elements N = T/h over an h grid. Samples: an output grid of K equal intervals, K the
  largest divisor of N <= samples (so that output times are element boundaries).
- ``RK4-numpy``: classical RK4, the loop in NumPy, f = the C vector field (as SciPy's).
- ``RK4-C``: the same RK4 (same arithmetic, same order) emitted as C (hpgen.bench.crk4).
- ``splitting-2/4/6``, ``RATTLE``: hand-written C, rigid bodies only (hpgen.bench.rigid).
Fixed-step samples: every max(1, steps // samples)-th node and the final state.
"""
from __future__ import annotations

import time

import numpy as np

from .measure import Point, fixed_note, measure, steps_for, thin
from .rigid import FAMILIES

ATOL_FACTOR = 1e-3
COLLOCATION_ORDER = 2
CVODES_MAX_STEPS = 10 ** 7
#: the structure-preserving rigid-body peers (hpgen.bench.rigid): only for a body with
#: l = 1/2 xi.diag(I) xi - m.(R^T e3) (heavy top, free body); skipped with a note elsewhere
RIGID_PEERS = FAMILIES
PEERS = ("DOP853", "RK45", "cvodes-bdf", "cvodes-adams", "collocation", "RK4-numpy",
         "RK4-C") + RIGID_PEERS


def rk4_numpy(f, y0, h, steps, every=None):
    """(records or None, last state): the arithmetic of rk4.c.j2, in the same order;
    ``f(y, t)``, t_k = k h."""
    y = np.array(y0, dtype=float)
    hh, h6 = 0.5 * h, h / 6.0
    rec = [y] if every else None
    for k in range(1, steps + 1):
        t = (k - 1) * h
        k1 = f(y, t)
        k2 = f(y + hh * k1, t + hh)
        k3 = f(y + hh * k2, t + hh)
        k4 = f(y + h * k3, t + h)
        y = y + h6 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        if not np.isfinite(y).all():
            break
        if every and k % every == 0:
            rec.append(y)
    return (np.array(rec) if every else None), y


def rk4_points(pb, y_ref, crk4, hs, timing, samples, which):
    out = []
    for h in hs:
        steps, hu = steps_for(pb.T, h)
        every = max(1, steps // samples)
        t_rec = np.arange(steps // every + 1) * every * hu
        if which == "RK4-C":
            p = Point("RK4 (C, hpgen-emitted)", "RK4-C", "peer", "h", hu, setup_s=crk4.setup_s)

            def sampled(hu=hu, steps=steps, every=every, t_rec=t_rec):
                rec, _, done = crk4.run(pb.y0, hu, steps, every)
                return t_rec[:len(rec)], rec

            def timed(hu=hu, steps=steps):
                _, y, done = crk4.run(pb.y0, hu, steps)
                return y if done == steps else np.full(pb.ny, np.nan), {
                    "steps": steps, "f_evals": 4 * steps}
        else:
            p = Point("RK4 (NumPy)", "RK4-numpy", "peer", "h", hu, setup_s=crk4.setup_s)

            def sampled(hu=hu, steps=steps, every=every, t_rec=t_rec):
                rec, _ = rk4_numpy(crk4.f, pb.y0, hu, steps, every)
                return t_rec[:len(rec)], rec

            def timed(hu=hu, steps=steps):
                return rk4_numpy(crk4.f, pb.y0, hu, steps)[1], {"steps": steps,
                                                              "f_evals": 4 * steps}
        p.notes += fixed_note(h, hu)
        out.append(measure(pb, y_ref, p, timing, timed, sampled))
    return out


def scipy_points(pb, y_ref, crk4, method, rtols, timing, samples):
    from scipy.integrate import solve_ivp
    out = []
    for rtol in rtols:
        p = Point(f"SciPy {method}", method, "peer", "rtol", rtol, setup_s=crk4.setup_s)

        def timed(rtol=rtol):
            sol = solve_ivp(crk4.rhs, (0.0, pb.T), pb.y0, method=method, rtol=rtol,
                            atol=rtol * ATOL_FACTOR)
            if not sol.success:
                raise RuntimeError(f"solve_ivp {method}: {sol.message}")
            return sol.y[:, -1], {"steps": len(sol.t) - 1, "f_evals": int(sol.nfev),
                                  "samples": thin(sol.t, sol.y.T, samples)}
        p.notes.append(f"atol = {ATOL_FACTOR:g} rtol")
        out.append(measure(pb, y_ref, p, timing, timed))
    return out


def _casadi_integrator(pb, plugin, grid, opts):
    import casadi as ca
    return ca.integrator(f"bench_{plugin}", plugin,
                         {"t": pb.t_sym, "x": pb.y_sym, "ode": pb.ydot_sym}, 0.0, list(grid),
                         opts)


def cvodes_points(pb, y_ref, lmm, tols, timing, samples):
    out = []
    grid = np.linspace(0.0, pb.T, samples + 1)[1:]
    for tol in tols:
        p = Point(f"CasADi cvodes {lmm.upper()}", f"cvodes-{lmm}", "peer", "rtol", tol)
        opts = {"reltol": tol, "abstol": tol * ATOL_FACTOR, "linear_multistep_method": lmm,
                "max_num_steps": CVODES_MAX_STEPS}
        t0 = time.perf_counter()
        try:
            I_end = _casadi_integrator(pb, "cvodes", [pb.T], opts)
            I_grid = _casadi_integrator(pb, "cvodes", grid, opts)
        except RuntimeError as e:
            p.notes.append("failed: " + str(e).splitlines()[0][:160])
            out.append(p)
            continue
        p.setup_s = time.perf_counter() - t0

        def sampled(I_grid=I_grid):
            X = np.array(I_grid(x0=pb.y0)["xf"]).T
            return np.r_[0.0, grid], np.vstack([pb.y0, X])

        def timed(I_end=I_end):
            y = np.array(I_end(x0=pb.y0)["xf"]).ravel()
            st = I_end.stats()
            return y, {"steps": int(st.get("nsteps", 0)), "f_evals": int(st.get("nfevals", 0))}
        p.notes.append(f"abstol = {ATOL_FACTOR:g} reltol")
        out.append(measure(pb, y_ref, p, timing, timed, sampled))
    return out


def collocation_points(pb, y_ref, hs, timing, samples):
    out = []
    for h in hs:
        N, hu = steps_for(pb.T, h)
        K = max(k for k in range(1, min(N, samples) + 1) if N % k == 0)
        p = Point(f"CasADi collocation (Gauss-Legendre s={COLLOCATION_ORDER})", "collocation",
                  "peer", "h", hu)
        opts = {"collocation_scheme": "legendre", "interpolation_order": COLLOCATION_ORDER,
                "number_of_finite_elements": N}
        grid = np.linspace(0.0, pb.T, K + 1)[1:]
        t0 = time.perf_counter()
        try:
            I_end = _casadi_integrator(pb, "collocation", [pb.T], opts)
            p.setup_s = time.perf_counter() - t0
            I_grid = _casadi_integrator(pb, "collocation", grid, opts)
        except RuntimeError as e:
            p.notes.append("failed: " + str(e).splitlines()[0][:160])
            out.append(p)
            continue

        def sampled(I_grid=I_grid, grid=grid):
            X = np.array(I_grid(x0=pb.y0)["xf"]).T
            return np.r_[0.0, grid], np.vstack([pb.y0, X])

        def timed(I_end=I_end, N=N):
            return np.array(I_end(x0=pb.y0)["xf"]).ravel(), {"steps": N}
        p.notes += fixed_note(h, hu)
        out.append(measure(pb, y_ref, p, timing, timed, sampled))
    return out
