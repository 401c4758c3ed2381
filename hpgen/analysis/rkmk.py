"""The continuous equations of a model (for reference solutions) and an explicit RKMK-RK4
scheme on them: a deliberately non-variational integrator, so that ``hpgen check`` can fail.

Continuous equations (docs/numerics.md sec. 9, the paper's eq. lthp), built generically with CasADi:

    g' = g xi,   mu' = ad*_xi mu + g dl/dg + f,   mu = dl/dxi(g, xi),

with ad*_xi mu = ad(xi)^T mu (``group.ad(x)`` is the d x d matrix of ad_x y = [x^, y^]^vee),
<g dl/dg, eta> = d/de l(g (I + e eta^), xi) at e = 0 (AD of l at eps = 0), and xi from mu by
Newton on the Legendre map (d^2l/dxi^2 as the Newton matrix). The state is (g, mu): g an
n x n matrix, mu the body momentum in g* (d-vector, the pairing is the dot product).
For an open model (forces, inputs, runtime parameters, time; math.md sec. 9) l = l(g, xi, t)
and f = f(g, xi, t, u, params) is the left-trivialized generalized force, with u and params
fixed when the equations are built; the point evaluations then take the time t.

RKMK-RK4 (Munthe-Kaas): classical RK4 on the algebra chart g = g_k exp(Theta), Theta' =
dexp^{-1}_{-Theta} xi (the paper's eq. liealgebradeq with tau = exp, hpgen's
``group.dtau_inv("exp", .)``) together with RK4 on mu in the vector space g*:

    Theta_i = h sum_j a_ij K_j,  mu_i = mu_k + h sum_j a_ij M_j,  G_i = g_k exp(Theta_i),
    xi_i = (dl/dxi)^{-1}(G_i, mu_i),  K_i = dexp^{-1}_{-Theta_i} xi_i,
    M_i = ad*_{xi_i} mu_i + G_i dl/dg(G_i, xi_i),
    g_{k+1} = g_k exp(h sum_i b_i K_i),  mu_{k+1} = mu_k + h sum_i b_i M_i.

It is explicit (the Legendre inverse is a CasADi ``rootfinder``, differentiated by the
implicit function theorem), order 4, keeps g on the group, and is not symplectic. Its
Jacobian in the left-trivialized chart (delta, dmu) -> (g exp(delta^), mu + dmu), see
``hpgen.analysis.symplectic``, is taken by CasADi AD of the step: the input g is replaced by
g (I + delta^) (same first derivative as g exp(delta^)) and differentiated at delta = 0.
"""
from __future__ import annotations

import casadi as ca
import numpy as np
from scipy.integrate import solve_ivp

from ..derive.lagrangian import lagrangian_function
from ..errors import ConvergenceError, DomainError

RK4_A = ((0.0, 0.0, 0.0, 0.0), (0.5, 0.0, 0.0, 0.0), (0.0, 0.5, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0))
RK4_B = (1 / 6, 1 / 3, 1 / 3, 1 / 6)
NEWTON_TOL = 1e-15
NEWTON_MAXIT = 50


def _np(x):
    return np.array(ca.DM(x).full())


class ContinuousEquations:
    """CasADi functions of the model's continuous equations, evaluated on numpy arrays.

    g is an (n, n) array, xi/mu (d,) arrays. Functions: legendre(g, xi), hessian(g, xi),
    rhs(g, xi, mu) -> (g', mu'), energy(g, xi), momentum(g, p) (spatial momentum
    Ad*_{g^-1} p), defect(g) (distance of g from the group), velocity(g, mu). For an open
    model (model.open_system) legendre, energy, velocity, rhs and reference take the time t
    (keyword, default 0); ``params`` (P, default Model.runtime_defaults) is fixed here, the
    inputs ``u`` (m, default 0) are the attribute ``u`` (set it to change them; the CasADi
    functions take (t, u) after their state arguments); applied(g, xi, t) is the force f;
    reference also takes inputs held piecewise. flow_jacobian and RKMK4 are for closed models.
    """

    def __init__(self, model, u=None, params=None):
        self.model, self.group = model, model.group
        grp, n, d = model.group, model.group.n, model.group.d
        self.n, self.d = n, d
        g, xi, mu, eps = (ca.SX.sym("g", n, n), ca.SX.sym("xi", d), ca.SX.sym("mu", d),
                          ca.SX.sym("eps", d))
        self.open = model.open_system
        t = ca.SX.sym("t", 1)
        if self.open:
            from ..derive.lagrangian import open_functions
            lag_f, force_f = open_functions(model)
            P = model.runtime_defaults if params is None else params
            P = ca.DM(np.asarray(P, float).reshape(-1, 1))
            U = ca.SX.sym("u", len(model.inputs))
            self.u = np.zeros(len(model.inputs)) if u is None else \
                np.asarray(u, float).reshape(-1)
            self.lag = lambda G, X: lag_f(G, X, t, P)  # noqa: E731
            applied = force_f(g, xi, t, U, P)
            targs = [t, U]
        else:
            self.lag = lagrangian_function(model)
            applied, targs = ca.SX.zeros(d), []
        L = self.lag(g, xi)
        leg = ca.gradient(L, xi)
        hess = ca.jacobian(leg, xi)
        force = ca.gradient(self.lag(ca.mtimes(g, ca.SX.eye(n) + grp.hat(eps)), xi), eps)
        force = ca.substitute(force, eps, ca.SX.zeros(d))          # g dl/dg, left-trivialized
        mudot = ca.mtimes(grp.ad(xi).T, mu) + force                  # ad*_xi mu + g dl/dg
        if self.open:
            mudot = mudot + applied                                  # + f (math.md sec. 9)
        gdot = ca.mtimes(g, grp.hat(xi))
        F = ca.Function
        self._leg = F("legendre", [g, xi] + targs, [leg])
        self._newton = F("newton", [g, xi, mu] + targs, [leg - mu, hess])
        self._rhs = F("rhs", [g, xi, mu] + targs, [gdot, mudot])
        self._energy = F("energy", [g, xi] + targs, [ca.dot(leg, xi) - L])
        self._applied = F("applied", [g, xi] + targs, [applied])
        p = ca.SX.sym("p", d)
        self._momentum = F("momentum", [g, p], [grp.momentum_map(g, p)])
        self._defect = F("defect", [g], [grp.group_defect(g)])
        # partial derivatives for the variational equations (exact flow Jacobians)
        gv = ca.reshape(g, n * n, 1)
        self._lin = F("lin", [g, xi, mu] + targs, [ca.jacobian(ca.vertcat(ca.reshape(gdot, n * n, 1),
                                                                      mudot), v)
                                           for v in (gv, xi, mu)] + [ca.jacobian(leg, gv), hess])
        # symbolic pieces reused by RKMK-RK4
        self.sx = {"g": g, "xi": xi, "mu": mu, "leg": leg, "mudot": mudot}

    # ---- point evaluations -------------------------------------------------------------
    def _t(self, t) -> tuple:
        return (float(t), self.u) if self.open else ()

    def legendre(self, g, xi, t=0.0):
        return _np(self._leg(g, xi, *self._t(t))).ravel()

    def energy(self, g, xi, t=0.0) -> float:
        return float(self._energy(g, xi, *self._t(t)))

    def momentum(self, g, p):
        return _np(self._momentum(g, p)).ravel()

    def applied(self, g, xi, t=0.0):
        """The applied force f(g, xi, t) in g* (body frame; zeros for a closed model)."""
        return _np(self._applied(g, xi, *self._t(t))).ravel()

    def defect(self, g) -> float:
        return float(self._defect(g))

    def velocity(self, g, mu, xi=None, t=0.0):
        """xi with dl/dxi(g, xi) = mu, Newton from ``xi`` (default 0) to round-off."""
        xi = np.zeros(self.d) if xi is None else np.array(xi, dtype=float)
        prev = np.inf
        for it in range(1, NEWTON_MAXIT + 1):
            r, H = self._newton(g, xi, mu, *self._t(t))
            dx = np.linalg.solve(_np(H), _np(r).ravel())
            xi = xi - dx
            dn, scale = np.abs(dx).max(), 1.0 + np.abs(xi).max()
            if dn <= NEWTON_TOL * scale or (dn >= prev and dn <= 1e-12 * scale):
                return xi
            prev = dn
        raise ConvergenceError("inverting the Legendre transform (reference equations)",
                               step=0, time=0.0, residual=float(np.abs(r).max()),
                               iterations=NEWTON_MAXIT)

    def rhs(self, g, mu, xi, t=0.0):
        gd, md = self._rhs(g, xi, mu, *self._t(t))
        return _np(gd), _np(md).ravel()

    # ---- reference solutions -----------------------------------------------------------
    def reference(self, g0, mu0, times, rtol=1e-12, t0=0.0, u_rows=None, u_h=None):
        """(g(t), mu(t)) at ``times`` (measured from t0, the time of (g0, mu0)) from DOP853
        with rtol = atol = ``rtol`` on the state (g row-major, mu); returns arrays (K, n, n)
        and (K, d). ``u_rows`` (J, m) with ``u_h`` > 0: the inputs held piecewise, row j on
        [j u_h, (j + 1) u_h) (the last row after); DOP853 restarts at every such boundary,
        so each piece is smooth."""
        n = self.n
        state = {"xi": self.velocity(g0, mu0, t=t0)}

        def f(t, y):
            g, mu = y[:n * n].reshape(n, n), y[n * n:]
            xi = state["xi"] = self.velocity(g, mu, state["xi"], t=t0 + t)
            gd, md = self.rhs(g, mu, xi, t=t0 + t)
            return np.concatenate([gd.ravel(), md])

        times = np.atleast_1d(np.asarray(times, dtype=float))
        y0 = np.concatenate([np.asarray(g0, float).ravel(), np.asarray(mu0, float)])
        end = float(times[-1])
        if u_rows is None:
            pieces = [(0.0, end, None)]
        else:
            u_rows = np.asarray(u_rows, dtype=float).reshape(len(u_rows), -1)
            J = min(len(u_rows), max(1, int(np.ceil(end / u_h - 1e-9))))
            edges = [j * u_h for j in range(J)] + [end]
            pieces = [(edges[j], max(edges[j + 1], edges[j]), u_rows[j]) for j in range(J)]
        out = np.empty((len(times), len(y0)))
        kept = 0
        saved_u = getattr(self, "u", None)
        try:
            for a, b, row in pieces:
                if row is not None:
                    self.u = row
                inside = np.minimum(times[kept:][times[kept:] <= b + 1e-12 * max(1.0, abs(b))],
                                    b)
                if b > a:
                    te = np.unique(np.r_[inside, b])
                    sol = solve_ivp(f, (a, b), y0, method="DOP853", rtol=rtol, atol=rtol,
                                    t_eval=te)
                    if not sol.success:
                        raise ConvergenceError(f"reference solution (DOP853): {sol.message}",
                                               step=0, time=0.0, residual=float("nan"),
                                               iterations=0)
                    Y = sol.y.T
                    out[kept:kept + len(inside)] = Y[np.searchsorted(te, inside)]
                    y0 = Y[-1]
                elif len(inside):
                    out[kept:kept + len(inside)] = y0
                kept += len(inside)
        finally:
            if saved_u is not None:
                self.u = saved_u
        return out[:, :n * n].reshape(-1, n, n), out[:, n * n:]

    def flow_jacobian(self, g0, mu0, T, rtol=1e-13):
        """(g(T), mu(T), Phi') for the exact flow over time T, Phi' the 2d x 2d derivative in
        the left-trivialized chart (variational equations integrated along, DOP853)."""
        n, d, nn = self.n, self.d, self.n * self.n
        B = hat_basis(self.group)
        Y0 = np.zeros((nn + d, 2 * d))
        for k in range(d):      # delta_k -> dg = g0 e_k^, dmu = 0;  dmu_k -> (0, e_k)
            Y0[:nn, k] = (np.asarray(g0) @ B[k]).ravel(order="F")
            Y0[nn + k, d + k] = 1.0
        state = {"xi": self.velocity(g0, mu0)}

        def f(t, y):
            g, mu = y[:nn].reshape(n, n, order="F"), y[nn:nn + d]
            Y = y[nn + d:].reshape(nn + d, 2 * d, order="F")
            xi = state["xi"] = self.velocity(g, mu, state["xi"])
            gd, md = self.rhs(g, mu, xi)
            Rg, Rx, Rm, Lg, H = (_np(a) for a in self._lin(g, xi, mu))
            dxi_dy = np.linalg.solve(H, np.hstack([-Lg, np.eye(d)]))  # xi(g, mu) implicit
            A = np.hstack([Rg, Rm]) + Rx @ dxi_dy
            return np.concatenate([gd.ravel(order="F"), md, (A @ Y).ravel(order="F")])

        y0 = np.concatenate([np.asarray(g0, float).ravel(order="F"), np.asarray(mu0, float),
                             Y0.ravel(order="F")])
        sol = solve_ivp(f, (0.0, float(T)), y0, method="DOP853", rtol=rtol, atol=rtol)
        y = sol.y[:, -1]
        g1, mu1 = y[:nn].reshape(n, n, order="F"), y[nn:nn + d]
        Y = y[nn + d:].reshape(nn + d, 2 * d, order="F")
        return g1, mu1, chart_jacobian(self.group, g1, Y[:nn], Y[nn:])


def hat_basis(group):
    """(d, n, n) array of the matrices hat(e_k)."""
    v = ca.SX.sym("v", group.d)
    hat = ca.Function("hat", [v], [group.hat(v)])
    return np.array([_np(hat(np.eye(group.d)[k])) for k in range(group.d)])


def chart_jacobian(group, g1, dG, dP):
    """Stack [eta; nu] from ambient derivatives: dG (n*n, m) column-major rows of d g1, dP
    (d, m). eta = vee(g1^{-1} dG), the orthogonal (Frobenius) projection onto the algebra."""
    B = hat_basis(group)
    n, d = group.n, group.d
    Bm = np.stack([b.ravel() for b in B], axis=1)                   # (n*n, d), row-major
    cols = [np.linalg.solve(g1, dG[:, j].reshape(n, n, order="F")).ravel()
            for j in range(dG.shape[1])]
    eta = np.linalg.lstsq(Bm, np.array(cols).T, rcond=None)[0] if cols else np.zeros((d, 0))
    return np.vstack([eta, dP])


class RKMK4:
    """Explicit RKMK-RK4 with tau = exp on the model's continuous equations.

    step(g, mu, h) -> (g1, mu1); simulate(g0, mu0, h, steps) -> (g (K, n, n), mu (K, d));
    map_jacobian(g, mu, h) -> (Phi' (2d, 2d), g1, mu1) by CasADi AD.
    """
    name = "rkmk-rk4"
    order = 4

    def __init__(self, model, equations: ContinuousEquations | None = None):
        eq = equations or ContinuousEquations(model)
        self.eq, self.group = eq, model.group
        grp, n, d = model.group, eq.n, eq.d
        sx = eq.sx
        res = ca.Function("legres", [sx["xi"], sx["g"], sx["mu"]], [sx["leg"] - sx["mu"]])
        xi_of = ca.rootfinder("xi_of", "newton", res,
                              {"abstol": 1e-14, "abstolStep": 1e-16, "max_iter": NEWTON_MAXIT,
                               "error_on_fail": False})
        mudot = ca.Function("mudot", [sx["g"], sx["xi"], sx["mu"]], [sx["mudot"]])
        x = ca.SX.sym("x", d)
        expm = ca.Function("expm", [x], [grp.tau("exp", x)])
        dexpinv = ca.Function("dexpinv", [x], [grp.dtau_inv("exp", x)])
        margin = ca.Function("margin", [x], [grp.tau_margin("exp", x)])
        hat = ca.Function("hat", [x], [grp.hat(x)])
        G, D, P, H = ca.MX.sym("g", n, n), ca.MX.sym("delta", d), ca.MX.sym("mu", d), \
            ca.MX.sym("h")
        g0 = ca.mtimes(G, ca.MX.eye(n) + hat(D))
        K, M, xi, margins = [], [], ca.MX.zeros(d), []
        for i, row in enumerate(RK4_A):
            Th = H * sum((a * k for a, k in zip(row, K) if a), ca.MX.zeros(d))
            margins.append(margin(Th))
            mu_i = P + H * sum((a * m for a, m in zip(row, M) if a), ca.MX.zeros(d))
            Gi = ca.mtimes(g0, expm(Th))
            xi = xi_of(xi, Gi, mu_i)                     # previous stage's xi as the guess
            K.append(ca.mtimes(dexpinv(-Th), xi))
            M.append(mudot(Gi, xi, mu_i))
        chart = H * sum((b * k for b, k in zip(RK4_B, K)), ca.MX.zeros(d))
        margins.append(margin(chart))
        g1 = ca.mtimes(g0, expm(chart))
        p1 = P + H * sum((b * m for b, m in zip(RK4_B, M)), ca.MX.zeros(d))
        U = ca.vertcat(ca.reshape(g1, n * n, 1), p1)
        S = ca.vertcat(D, P)
        # exp is accurate on its domain (|omega| < pi, hpgen.groups.series): the step reports
        # the smallest margin of its chart arguments
        self._step = ca.Function("rkmk4", [G, D, P, H], [g1, p1, ca.mmin(ca.vertcat(*margins))])
        self._jac = ca.Function("rkmk4_jac", [G, D, P, H], [g1, p1, ca.jacobian(U, S)])

    def step(self, g, mu, h):
        """(g1, mu1); raises DomainError when a chart argument leaves exp's domain."""
        g1, p1, m = self._step(g, np.zeros(self.eq.d), mu, h)
        if not float(m) > 0.0:
            raise DomainError("RKMK-RK4: a chart argument h Theta left exp's domain "
                              "(|omega| < pi)", step=0, time=0.0,
                              residual=float("nan"), iterations=0)
        return _np(g1), _np(p1).ravel()

    def simulate(self, g0, mu0, h, steps):
        g, mu = np.array(g0, dtype=float), np.array(mu0, dtype=float)
        gs, mus = [g], [mu]
        for _ in range(steps):
            try:
                g, mu = self.step(g, mu, h)
            except DomainError as e:
                raise DomainError(e.reason, step=len(gs) - 1, time=(len(gs) - 1) * h,
                                  residual=float("nan"), iterations=0) from None
            if not (np.isfinite(g).all() and np.isfinite(mu).all()):
                raise ConvergenceError("RKMK-RK4 produced non-finite values", step=len(gs) - 1,
                                       time=(len(gs) - 1) * h, residual=float("nan"),
                                       iterations=0)
            gs.append(g)
            mus.append(mu)
        return np.array(gs), np.array(mus)

    def map_jacobian(self, g, mu, h):
        g1, p1, J = (_np(a) for a in self._jac(g, np.zeros(self.eq.d), mu, h))
        nn = self.eq.n ** 2
        return chart_jacobian(self.group, g1, J[:nn], J[nn:]), g1, p1.ravel()
