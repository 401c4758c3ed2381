"""Step k of the discrete Hamilton-Pontryagin action sum (eq. hpsumfuture) and its
stationarity conditions, derived by CasADi's automatic differentiation.

Conventions (docs/numerics.md, sections 2, 3, 4, 7):
- Group variables are parametrized in the chart at g_k: G^i = g_k tau(h Theta^i),
  g_{k+1} = g_k tau(h xi_{k+1}). Their variations are right-multiplied algebra elements
  g_k (I + eta_0^), G^i (I + eps_i^), g_{k+1} (I + eta_1^); only first derivatives at 0 are
  needed, and there  tau^{-1}((I - eta^) tau(a) (I + eps^)) = a + dtau^{-1}_a(-eta)
  + dtau^{-1}_{-a}(eps), so no matrix logarithm is ever formed.
- RKMK constraint: R^j = Xi^j ("truncated", the paper's q = 0, order <= 2) or
  R^j = dtau^{-1}_{-h Theta^j} Xi^j ("exact", keeps the tableau's order). Theta and xi_{k+1}
  are independent symbols while differentiating; for "truncated" they are replaced by
  A Xi and b Xi only afterwards (substituting first would kill the constraint's variations).
- Stage multipliers are scaled, mu^i = h N^i, so that every unknown and equation is O(1).
- The state is (g_k, p_k) with p_k the node momentum (the discrete Legendre transform at
  t_k): p_k + ds_k/deta_0 = 0 and p_{k+1} = ds_k/deta_1.
- Forces (math.md sec. 9, the discrete Lagrange-d'Alembert principle): the virtual work
  sum_i h b_i <F_i, eps_i> is added to s_k with F_i = f(G^i, Xi^i, t_k + c_i h) built from
  the stage variables WITHOUT the variation (G^i = g_k tau(h Theta^i)): it is linear in eps_i,
  so d/deps_i at 0 gives exactly h b_i F_i and nothing else, and F is never differentiated
  as a gradient. The residual then depends on F(z), and its Jacobian (taken afterwards by
  CasADi) contains dF/dz, as Newton needs. The virtual work enters only the eps_i conditions
  ("b_i f_i + ..."), which every elimination below already carries: the common stage
  velocity and exact-RKMK eliminations keep working with forces. The reduced Euler-Poincare
  step does not (a force makes N^i != 0), so the caller passes reduced=False for a forced
  or time-dependent model.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca


@dataclass(frozen=True)
class StepEquations:
    """Residual, unknowns and explicit outputs of one step, as SX expressions."""
    z: object            # SX column of unknowns
    blocks: tuple        # ((label, start, stop), ...)
    residual: object     # SX column, same length as z
    g1: object           # SX n x n
    p1: object           # SX d
    guess: object        # SX column: z as a function of the velocity estimate xi_hat
    xi_hat: object       # SX d (input of guess)
    margin: object       # SX scalar: min over the step's tau arguments of the domain margin
    chart_step: object   # SX d: h xi_{k+1} as a function of z (g_{k+1} = g_k tau(chart_step))


def step_equations(group, lag, tableau, tau: str, rkmk: str, reduced: bool,
                   g, p, h, t=None, force=None) -> StepEquations:
    """Stationarity conditions of s_k for one step.

    group: hpgen.groups.LieGroup; lag: casadi.Function l(g, xi), or with ``t`` given a
    callable l(g, xi, t); g (n x n), p (d), h (1): SX symbols of the known state.
    reduced: l does not depend on g nor t and there is no force (Euler-Poincare step).
    t: SX t_k (None: l does not depend on time); force: None or a callable
    f(g, xi, t) -> SX d, the left-trivialized generalized force (inputs, parameters bound).
    """
    if t is None:
        lag2, lag = lag, (lambda G, X, tt: lag2(G, X))
        t = ca.SX(0)
    s, d = tableau.stages, group.d
    A, b, c = tableau.A, tableau.b, tableau.c
    exact = rkmk == "exact"
    sym = ca.SX.sym
    Xi = [sym(f"Xi{i + 1}", d) for i in range(s)]
    N = [sym(f"N{i + 1}", d) for i in range(s)]
    mu1 = sym("mu1", d)
    Th = [sym(f"Theta{i + 1}", d) for i in range(s)]
    xi1 = sym("xi1", d)
    eta0, eta1 = sym("eta0", d), sym("eta1", d)
    eps = [sym(f"eps{i + 1}", d) for i in range(s)]
    I_n = ca.SX.eye(group.n)

    def dti(x, v):
        return group.chart_product(tau, "dtau_inv", x, v)

    # chart[i] = tau^{-1}(g_k^{-1} G^i) to first order in the variations (= h Theta^i at 0)
    chart = [h * Th[i] + dti(h * Th[i], -eta0) + dti(-h * Th[i], eps[i]) for i in range(s)]
    # the exact constraint depends on G^j through Theta^j, so it is built on the varied chart
    R = [dti(-chart[j], Xi[j]) if exact else Xi[j] for j in range(s)]
    # s_k, eq. hpsumfuture, with the multipliers' constraint terms multiplied through by h
    action = ca.SX(0)
    for i in range(s):
        Gi0 = ca.mtimes(g, group.tau(tau, h * Th[i]))
        Gi = ca.mtimes([Gi0, I_n + group.hat(eps[i])])
        ti = t + c[i] * h
        action += h * b[i] * lag(Gi, Xi[i], ti)
        if force is not None:      # virtual work, linear in eps_i: F_i from unvaried stages
            action += h * b[i] * ca.dot(force(Gi0, Xi[i], ti), eps[i])
        action += ca.dot(h * N[i], chart[i] - h * sum((A[i][j] * R[j] for j in range(s)), ca.SX.zeros(d)))
    chart1 = h * xi1 + dti(h * xi1, -eta0) + dti(-h * xi1, eta1)
    action += ca.dot(mu1, chart1 - h * sum((b[j] * R[j] for j in range(s)), ca.SX.zeros(d)))

    zero = [eta0, eta1] + eps
    at0 = lambda e: ca.substitute(e, ca.vertcat(*zero), ca.SX.zeros(d * (2 + s)))  # noqa: E731
    grad = lambda v: at0(ca.gradient(action, v))  # noqa: E731

    eq_eps = [grad(eps[i]) / h for i in range(s)]                     # O(1): b_i f_i + ...
    eq_xi = [grad(Xi[i]) / (h * b[i]) for i in range(s)]              # Legendre conditions
    R0 = [at0(r) for r in R]
    eq_th = [Th[i] - sum((A[i][j] * R0[j] for j in range(s)), ca.SX.zeros(d)) for i in range(s)]
    eq_xi1 = xi1 - sum((b[j] * R0[j] for j in range(s)), ca.SX.zeros(d))
    eq_g0 = p + grad(eta0)                                            # p_k + ds_k/deta_0 = 0
    p1 = grad(eta1)                                                   # p_{k+1} = ds_k/deta_1
    g1 = ca.mtimes(g, group.tau(tau, h * xi1))

    xi_hat = sym("xi_hat", d)
    if reduced and not exact:
        # Euler-Poincare, q = 0: N^i = 0, all Xi^i equal (Legendre injective), mu_{k+1} =
        # dl/dxi(Xi): one unknown Xi in the algebra, equation eq. dlp.
        Xc = sym("Xi", d)
        mu_of = ca.gradient(lag(g, Xc, t), Xc)
        subs_from = ca.vertcat(*Xi, *N, mu1, *Th, xi1)
        subs_to = ca.vertcat(*[Xc] * s, ca.SX.zeros(d * s), mu_of,
                             *[c[i] * Xc for i in range(s)], Xc)
        sub = lambda e: ca.substitute(e, subs_from, subs_to)  # noqa: E731
        z, blocks = Xc, (("Xi", 0, d),)
        residual, g1, p1 = sub(eq_g0), sub(g1), sub(p1)
        taus = [sub(h * Th[i]) for i in range(s)] + [sub(h * xi1)]
        guess = xi_hat
        return _finish(group, tau, z, blocks, residual, g1, p1, guess, xi_hat, taus, h)

    if not exact:
        xs = sym("xs", d)
        dldxi = ca.gradient(lag(g, xs, t), xs)
        common = (_rows_proportional_to_b(A, b) and not ca.depends_on(dldxi, g)
                  and (not isinstance(t, ca.SX) or t.is_constant() or
                       not ca.depends_on(dldxi, t)))
        if common:
            return _common_velocity_step(group, lag, tau, tableau, Xi, N, Th, xi1, eq_eps, g,
                                         p, h, xi_hat, t)
        return _truncated_step(group, tau, tableau, Xi, N, mu1, Th, xi1, eq_xi, eq_eps, eq_g0,
                               g1, p1, xi_hat, h)

    if _invertible(A):
        # dl/dxi(G^j, Xi^j): eq_xi[j] at N = 0, mu_{k+1} = 0, taken from l directly (the
        # action's h b_j l differentiated and divided by h b_j is the same map)
        dl = [ca.gradient(lag(ca.mtimes(g, group.tau(tau, h * Th[j])), Xi[j], t + c[j] * h),
                          Xi[j]) for j in range(s)]
        return _exact_step(group, tau, tableau, Xi, N, mu1, Th, xi1, dl, eq_eps, eq_g0,
                           g1, p1, xi_hat, p, h)

    # Singular A (explicit first stage: Stormer-Verlet, Lobatto IIIA): the stage multipliers
    # stay unknowns, even for a left-invariant l: with the exact constraint R^j depends on
    # G^j, so the eps_j equations do not force N^j = 0.
    unknown_blocks = [(f"Xi{i + 1}", Xi[i]) for i in range(s)]
    unknown_blocks += [(f"N{i + 1}", N[i]) for i in range(s)]
    equations = list(eq_xi) + eq_eps
    unknown_blocks.append(("mu1", mu1))
    equations.append(eq_g0)
    unknown_blocks += [(f"Theta{i + 1}", Th[i]) for i in range(s)] + [("xi1", xi1)]
    equations += eq_th + [eq_xi1]
    residual = ca.vertcat(*equations)
    z = ca.vertcat(*[v for _, v in unknown_blocks])
    blocks, off = [], 0
    for label, v in unknown_blocks:
        blocks.append((label, off, off + v.numel()))
        off += v.numel()

    taus = [h * Th[i] for i in range(s)] + [h * xi1]

    guess_of = {f"Xi{i + 1}": xi_hat for i in range(s)}
    guess_of.update({f"N{i + 1}": ca.SX.zeros(d) for i in range(s)})
    guess_of.update({f"Theta{i + 1}": c[i] * xi_hat for i in range(s)})
    guess_of.update({"mu1": p, "xi1": xi_hat})
    guess = ca.vertcat(*[guess_of[label] for label, _ in unknown_blocks])
    return _finish(group, tau, z, tuple(blocks), residual, g1, p1, guess, xi_hat, taus, h)


def _truncated_step(group, tau, tableau, Xi, N, mu1, Th, xi1, eq_xi, eq_eps, eq_g0, g1, p1,
                    xi_hat, h):
    """q = 0 with a g-dependent l: eliminate everything but the stage velocities Xi^i.

    Theta^i = sum_j a_ij Xi^j and xi_{k+1} = sum_j b_j Xi^j are explicit, and the multipliers
    enter linearly through dtau^{-1} factors whose inverses dtau are closed forms:
        eps_i:  (dtau^{-1}_{-h Theta^i})^T N^i + b_i f_i = 0            -> N^i explicit
        eta_0:  p - h sum_i (dtau^{-1}_{h Theta^i})^T N^i
                  - (dtau^{-1}_{h xi_{k+1}})^T mu_{k+1} = 0             -> mu_{k+1} explicit
    leaving the s d Legendre conditions in Xi (instead of (2s + 1) d unknowns).

    """
    s, d, A, b = tableau.stages, group.d, tableau.A, tableau.b
    zero = ca.SX.zeros(d)
    theta = [sum((A[i][j] * Xi[j] for j in range(s)), zero) for i in range(s)]
    xi_next = sum((b[j] * Xi[j] for j in range(s)), zero)
    explicit = lambda e: ca.substitute(e, ca.vertcat(*Th, xi1), ca.vertcat(*theta, xi_next))  # noqa: E731
    N_of = []
    for i in range(s):
        rest = ca.substitute(explicit(eq_eps[i]), N[i], zero)     # b_i f_i
        N_of.append(-ca.mtimes(group.dtau(tau, -h * theta[i]).T, rest))
    with_N = lambda e: ca.substitute(explicit(e), ca.vertcat(*N), ca.vertcat(*N_of))  # noqa: E731
    rest0 = ca.substitute(with_N(eq_g0), mu1, zero)
    mu1_of = ca.mtimes(group.dtau(tau, h * xi_next).T, rest0)
    final = lambda e: ca.substitute(with_N(e), mu1, mu1_of)  # noqa: E731
    z = ca.vertcat(*Xi)
    blocks = tuple((f"Xi{i + 1}", i * d, (i + 1) * d) for i in range(s))
    residual = ca.vertcat(*[final(e) for e in eq_xi])
    taus = [h * t for t in theta] + [h * xi_next]
    guess = ca.vertcat(*[xi_hat] * s)
    return _finish(group, tau, z, blocks, residual, final(g1), final(p1), guess, xi_hat, taus, h)


def _common_velocity_step(group, lag, tau, tableau, Xi, N, Th, xi1, eq_eps, g, p, h, xi_hat,
                          t):
    """q = 0, rows of A multiples of b (a_ij = c_i b_j: Stormer-Verlet, the midpoint rule,
    symplectic Euler) and dl/dxi independent of g and t: d unknowns (forces allowed: they
    enter through f_i, the eps_i conditions).

    The Legendre conditions read dl/dxi(Xi^j) = sum_i (a_ij / b_j) h N^i + mu_{k+1}
    = sum_i c_i h N^i + mu_{k+1} =: M, the same for every j, so every Xi^j is one X
    (Legendre injective, as the reduced step assumes), Theta^i = c_i X, xi_{k+1} = X and
    M = dl/dxi(X). With D_a := (dtau^{-1}_a)^T, the eps_i conditions give
        h N^i = -h (dtau_{-h c_i X})^T b_i f_i(G^i, X)                       (explicit)
    and eta_0's condition p = sum_i D_{h c_i X} h N^i + D_{hX} mu_{k+1}, with
    mu_{k+1} = M - sum_i c_i h N^i, becomes the d equations in X
        p - D_{hX} M - sum_i (D_{h c_i X} - c_i D_{hX}) h N^i = 0,
    whose stage terms vanish identically for c_i = 1 and have D_0 = I for c_i = 0; likewise
    p_{k+1} = D_{-hX} mu_{k+1} = D_{-hX} (M - sum_{c_i != 1} c_i h N^i) + sum_{c_i = 1} h b_i f_i.
    For Stormer-Verlet (c = 0, 1) these are the paper's eqs. sv3 and sv5: a half kick, a
    d-unknown chart solve, a half kick, with the force taken at g_k and g_{k+1} only.
    """
    s, d = tableau.stages, group.d
    X = ca.SX.sym("Xi", d)
    c = [float(ci) for ci in tableau.c]
    at_X = lambda e: ca.substitute(e, ca.vertcat(*Xi, *Th, xi1),  # noqa: E731
                                   ca.vertcat(*[X] * s, *[ci * X for ci in c], X))
    M = ca.gradient(lag(g, X, t), X)
    residual, mu1, kick = p - group.dtau_inv_T_times(tau, h * X, M), M, ca.SX.zeros(d)
    for i in range(s):
        bf = at_X(ca.substitute(eq_eps[i], N[i], ca.SX.zeros(d)))        # b_i f_i(G^i, X)
        if c[i] == 1.0:
            kick += h * bf
            continue
        hN = -h * bf if c[i] == 0.0 else -h * ca.mtimes(group.dtau(tau, -c[i] * h * X).T, bf)
        D_i = ca.SX.eye(d) if c[i] == 0.0 else group.dtau_inv(tau, c[i] * h * X).T
        if c[i] == 0.0:
            residual -= hN
        else:
            residual -= ca.mtimes(D_i - c[i] * group.dtau_inv(tau, h * X).T, hN)
            mu1 = mu1 - c[i] * hN
    p1 = group.dtau_inv_T_times(tau, -h * X, mu1) + kick
    g1 = ca.mtimes(g, group.tau(tau, h * X))
    taus = [ci * h * X for ci in c] + [h * X]
    return _finish(group, tau, X, (("Xi", 0, d),), residual, g1, p1, xi_hat, xi_hat, taus, h)


def _rows_proportional_to_b(A, b) -> bool:
    """a_ij = c_i b_j for all i, j (exactly, as the catalog's rational entries give)."""
    return all(abs(A[i][j] * b[0] - A[i][0] * b[j]) <= 1e-15 * max(1.0, abs(A[i][0] * b[j]))
               for i in range(len(A)) for j in range(len(b)))


def _invertible(A) -> bool:
    import numpy as np
    M = np.array(A, dtype=float)
    return bool(abs(np.linalg.det(M)) > 1e-12 * max(1.0, np.abs(M).max()) ** len(M))


def _exact_step(group, tau, tableau, Xi, N, mu1, Th, xi1, dl, eq_eps, eq_g0, g1, p1,
                xi_hat, p, h):
    """Exact RKMK constraint with an invertible A (Gauss, Radau IIA, backward Euler):
    unknowns (Theta^1..s, mu_{k+1}), (s + 1) d instead of (3 s + 2) d.

    With K^j = R^j = dtau^{-1}_{-h Theta^j} Xi^j (the chart velocities):
        Theta equations  Theta = A K                 -> K = A^{-1} Theta
                         Xi^j = dtau_{-h Theta^j} K^j  (closed-form dtau: explicit)
        xi_{k+1} = sum_j b_j K^j                       (explicit)
        Xi^j equations   b_j dl/dxi(G^j, Xi^j) = (dtau^{-1}_{-h Theta^j})^T
                             (h sum_i a_ij N^i + b_j mu_{k+1})
                         -> h N = A^{-T} (b_j Lambda^j),  Lambda^j = dtau_{-h Theta^j}^T
                             (dl/dxi(G^j, Xi^j) - (dtau^{-1}_{-h Theta^j})^T mu_{k+1})
                             = dtau_{-h Theta^j}^T dl/dxi(G^j, Xi^j) - mu_{k+1}
    (dtau^T (dtau^{-1})^T = I: the mu_{k+1} term is not formed through the two products),
    leaving the eps_i (s d) and eta_0 (d) conditions. h N is formed without dividing by h.
    dtau and dtau^{-1} are applied through group.chart_product (closed forms where tabulated).
    dl: the s d-vectors dl/dxi(G^j, Xi^j) in Theta^j and the symbols Xi^j (forces do not
    enter the Xi^j conditions: their virtual work is linear in eps and taken at eps = 0).
    """
    import numpy as np
    s, d, A, b = tableau.stages, group.d, tableau.A, tableau.b
    zero = ca.SX.zeros(d)
    Ainv = np.linalg.inv(np.array(A, dtype=float))
    K = [sum((float(Ainv[j][i]) * Th[i] for i in range(s)), zero) for j in range(s)]
    Xi_of = [group.chart_product(tau, "dtau", -h * Th[j], K[j]) for j in range(s)]
    xi1_of = sum((b[j] * K[j] for j in range(s)), zero)
    explicit = lambda e: ca.substitute(e, ca.vertcat(*Xi, xi1), ca.vertcat(*Xi_of, xi1_of))  # noqa: E731
    lam = [b[j] * (group.chart_product(tau, "dtau", -h * Th[j], explicit(dl[j]),
                                       transposed=True) - mu1) for j in range(s)]
    hN = [sum((float(Ainv[j][i]) * lam[j] for j in range(s)), zero) for i in range(s)]
    final = lambda e: ca.substitute(explicit(e), ca.vertcat(*N), ca.vertcat(*hN) / h)  # noqa: E731
    z = ca.vertcat(*Th, mu1)
    blocks = tuple((f"Theta{i + 1}", i * d, (i + 1) * d) for i in range(s))
    blocks += (("mu1", s * d, (s + 1) * d),)
    residual = ca.vertcat(*[final(e) for e in eq_eps], final(eq_g0))
    taus = [h * t for t in Th] + [h * xi1_of]
    guess = ca.vertcat(*[c * xi_hat for c in tableau.c], p)
    return _finish(group, tau, z, blocks, residual, final(g1), final(p1), guess, xi_hat, taus, h)


def _finish(group, tau, z, blocks, residual, g1, p1, guess, xi_hat, taus, h):
    """taus: the step's chart arguments, the last one h xi_{k+1}."""
    margin = ca.SX(1.0)
    for x in taus:
        margin = ca.fmin(margin, group.tau_margin(tau, x))
        margin = ca.fmin(margin, group.tau_margin(tau, -x))
    return StepEquations(z, blocks, residual, g1, p1, guess, xi_hat, margin, taus[-1])
