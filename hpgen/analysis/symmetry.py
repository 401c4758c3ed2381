"""Which spatial momenta a model's Lagrangian conserves (Noether), decided from the model.

The spatial momentum is J = Ad*_{g^{-1}} mu (coordinates dual to the algebra basis e_i, as
the ``momentum`` record). Left translation g -> exp(s v) g (v in the algebra) leaves the
left-trivialized velocity xi unchanged; if l(exp(s v) g, xi) = l(g, xi) for all s, g, xi,
then <J, v> is a constant of the motion (which the variational integrators keep up to
round-off). Whether l has that symmetry is decided from the model, not from a run: the rate

    D_i(g, xi) = d/ds l(exp(s e_i) g, xi) at s = 0 = sum_jk dl/dg_jk (hat(e_i) g)_jk

is evaluated (CasADi, from the model's Lagrangian) at d + SAMPLES random states (g = exp of
a random algebra element, xi random); the rate along v is sum_i v_i D_i, linear in v, so the
symmetric directions are the null space of the matrix of rows D(g_s, xi_s) / S_s, each row
scaled by S_s = max_i sum_jk |dl/dg_jk (hat(e_i) g_s)_jk| (the size of the terms that cancel).

Why the tolerance: along a symmetry the terms cancel exactly in exact arithmetic (on the
group: the random g is orthogonal to round-off), so the scaled rate is a few ulps (1e-16,
measured); along a non-symmetry it is a smooth function that is not identically zero, of
size O(1) at random states (heavy top, e_1: 0.3 to 1), and the singular values of the rows
off the null space are O(1). RTOL = 1e-9 sits between, with margins of 10^6 and more; the
SAMPLES extra states make a non-symmetry that vanishes at every sample by chance
negligibly rare.

With holonomic constraints phi(g) = 0, <J, v> is conserved when moreover the constraint set is
invariant: d/ds phi(exp(s v) g) = 0 at every g ON the constraints (a pin at the origin and a
rotation about it move phi's rows into each other, so the rate vanishes on phi = 0 only).
Those states are drawn by a random walk on the constraints from the scene's initial g (or the
identity): a random step in the null space of Phi(g) (the body-frame constraint Jacobian),
then Gauss-Newton back onto phi = 0 (|phi| <= PROJECT_TOL); each state adds the rows
d/ds phi_m(exp(s e_i) g), row m scaled by its largest entry, to the rows of l.
"""
from __future__ import annotations

import numpy as np

RTOL = 1e-9
SAMPLES = 6
#: the walk's states are accepted once max |phi| <= PROJECT_TOL (Gauss-Newton, <= 40 iterations)
PROJECT_TOL = 1e-13


def conserved_directions(model, samples: int = SAMPLES, seed: int = 0,
                         g0=None) -> np.ndarray:
    """(q, d) array: a basis of the directions v along which ``model``'s Lagrangian (and its
    constraint set, if any; g0: a state on the constraints, default the identity) is
    invariant under left translation (so <J, v> is conserved), in reduced row echelon form:
    a conserved component J_i is the row e_i; coefficients within RTOL of an integer are
    that integer. q = 0: nothing is conserved; q = d: l is left-invariant."""
    import casadi as ca

    from ..derive.lagrangian import lagrangian_function
    grp = model.group
    n, d = grp.n, grp.d
    g, xi, v = ca.SX.sym("g", n, n), ca.SX.sym("xi", d), ca.SX.sym("v", d)
    grad = ca.Function("dl_dg", [g, xi], [ca.gradient(lagrangian_function(model)(g, xi),
                                                      ca.vec(g))])
    expm = ca.Function("exp", [v], [grp.tau("exp", v)])
    hat = ca.Function("hat", [v], [grp.hat(v)])
    # hat(e_i) has nonzero rows only where e_i acts (a few, on a product group one factor's):
    # the terms dl/dg_jk (hat(e_i) g)_jk vanish off those rows, so only they are formed
    basis = []
    for e in np.eye(d):
        E = np.array(hat(e).full())
        rows_i = np.flatnonzero(np.abs(E).sum(axis=1))
        basis.append((rows_i, E[rows_i]))
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(d + samples):
        g0 = np.array(expm(rng.uniform(-1.0, 1.0, d)).full())
        G = np.array(grad(g0, rng.standard_normal(d)).full()).reshape(n, n, order="F")
        terms = [G[r] * (Er @ g0) for r, Er in basis]
        scale = max(np.abs(t).sum() for t in terms)
        rows.append([t.sum() / scale for t in terms] if scale > 0 else [0.0] * d)
    if model.constraints:
        rows += _constraint_rows(model, basis, g0, rng, d + samples)
    _, sv, vt = np.linalg.svd(np.array(rows))
    rank = int((sv > RTOL).sum())
    return _rref(vt[rank:])


def _constraint_rows(model, basis, g0, rng, count: int) -> list:
    """Rows d/ds phi_m(exp(s e_i) g) / max_i |.| at states g of a random walk on phi = 0 from
    g0 (module docstring), until there are at least ``count`` rows."""
    import casadi as ca

    from ..derive.constraints import body_jacobian, constraint_function
    grp = model.group
    n, d = grp.n, grp.d
    phi = constraint_function(model)
    G, v = ca.SX.sym("G", n, n), ca.SX.sym("v", d)
    jac = ca.Function("dphi_dg", [G], [ca.jacobian(phi(G), ca.vec(G))])
    Phi = ca.Function("Phi", [G], [body_jacobian(grp, phi, G)])
    expm = ca.Function("exp", [v], [grp.tau("exp", v)])
    g = np.eye(n) if g0 is None else np.array(g0, dtype=float).reshape(n, n)

    def onto(g):
        for _ in range(40):
            r = np.array(phi(g).full()).ravel()
            if np.abs(r).max() <= PROJECT_TOL * (1.0 + np.abs(g).max()):
                return g
            step = np.linalg.lstsq(np.array(Phi(g).full()), -r, rcond=None)[0]
            g = g @ np.array(expm(step).full())
        return None

    g = onto(g)
    rows: list = []
    if g is None:
        raise ValueError("the constraints' symmetry: no state on the constraints was found "
                         "from the initial g")
    scale = 0.5
    while len(rows) < count:
        P = np.array(Phi(g).full())
        eta = rng.standard_normal(d)
        eta -= np.linalg.lstsq(P, P @ eta, rcond=None)[0]
        new = onto(g @ np.array(expm(scale * eta / max(np.abs(eta).max(), 1e-300)).full()))
        if new is None:
            scale *= 0.5
            continue
        g = new
        D = np.array(jac(g).full())
        rates = np.array([D[:, (r[None, :] + n * np.arange(n)[:, None]).ravel()]
                          @ (Er @ g).ravel(order="F") for r, Er in basis]).T
        top = np.abs(rates).max(axis=1)
        rows += [row / t for row, t in zip(rates, top) if t > 0]
    return rows


def _rref(V: np.ndarray) -> np.ndarray:
    """Reduced row echelon form of the rows of V (partial pivoting), entries within RTOL of
    an integer snapped to it."""
    V = np.array(V, dtype=np.float64)
    q, d = V.shape
    r = 0
    for c in range(d):
        if r == q:
            break
        p = r + int(np.argmax(np.abs(V[r:, c])))
        if abs(V[p, c]) <= RTOL:
            continue
        V[[r, p]] = V[[p, r]]
        V[r] /= V[r, c]
        for i in range(q):
            if i != r:
                V[i] -= V[i, c] * V[r]
        r += 1
    near = np.abs(V - np.round(V)) <= RTOL
    V[near] = np.round(V[near])
    return V[:r] + 0.0


def describe(V: np.ndarray) -> list[str]:
    """Each direction v as the conserved quantity <J, v>: "J[2]", "J[2] + J[5]", ..."""
    out = []
    for v in V:
        parts = []
        for i in np.flatnonzero(v):
            c = v[i]
            coef = "" if abs(c) == 1 else f"{abs(c):.6g}*"
            parts.append(("- " if c < 0 else "+ ") + f"{coef}J[{i}]")
        s = " ".join(parts)
        out.append(s[2:] if s.startswith("+ ") else "-" + s[2:])
    return out
