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
"""
from __future__ import annotations

import numpy as np

RTOL = 1e-9
SAMPLES = 6


def conserved_directions(model, samples: int = SAMPLES, seed: int = 0) -> np.ndarray:
    """(q, d) array: a basis of the directions v along which ``model``'s Lagrangian is
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
    basis = [np.array(hat(e).full()) for e in np.eye(d)]
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(d + samples):
        g0 = np.array(expm(rng.uniform(-1.0, 1.0, d)).full())
        G = np.array(grad(g0, rng.standard_normal(d)).full()).reshape(n, n, order="F")
        terms = [G * (E @ g0) for E in basis]
        scale = max(np.abs(t).sum() for t in terms)
        rows.append([t.sum() / scale for t in terms] if scale > 0 else [0.0] * d)
    _, sv, vt = np.linalg.svd(np.array(rows))
    rank = int((sv > RTOL).sum())
    return _rref(vt[rank:])


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
