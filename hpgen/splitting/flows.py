"""One step of an explicit splitting scheme as CasADi SX: a composition of exact sub-flows.

For l = 1/2 xi.M xi - V(g) (hpgen.splitting.structure) the Hamiltonian in the body momentum
p = M xi is H = 1/2 p.M^{-1} p + V(g), and the state (g_k, p_k) is the same as the VPRK
schemes' (p_k the momentum at the node t_k). The exact sub-flows over a time t:

- kick: g fixed, p <- p + t f(g), f(g) = the left-trivialized derivative of l(g, 0) = -V(g)
  (d/de l(g (I + e eta^), 0) at e = 0 = f(g).eta; from CasADi); on an open model also the
  force f(g, t, u_k, params) (not of xi), both at the kick's time (kick_fractions,
  open_splitting_step);
- rotation about a principal axis a (SO3, SE3; moment D), the flow of (a.pi)^2 / (2 D):
  theta = t (a.pi) / D, Q = exp(theta a^), R <- R Q, pi <- Q^T pi (SE3: also P <- Q^T P,
  x fixed);
- drift: R^n x <- x + t M^{-1} p; SE3 x <- x + t R v, pi <- pi + t P x v, v = M_tr^{-1} P;
- SO2: R <- R rot(t p / I);
- free (a symmetric body, two equal moments D_a and the distinct D_c about a_c): the exact
  free flow, the commuting rotations R <- R exp(t pi^ / D_a) (pi fixed) and about a_c by
  t (a_c.pi)(1/D_c - 1/D_a);
- Fasso's split of an asymmetric body (the ``-fasso`` schemes; FactorKinetics.fasso = (a, b,
  s)): T_sym = |pi|^2 / (2 D_s) + (1/D_a - 1/D_s) pi_a^2 / 2, a symmetric top's exact flow
  as above ("fsym"), and T_r = (1/D_b - 1/D_s) pi_b^2 / 2, one rotation about b by
  t (b.pi)(1/D_b - 1/D_s) ("frem"); phi's kinetic part is T_r then T_sym, so the basic step's
  is T_r(t/2) T_sym(t) T_r(t/2).

The basic step S(t) = K(t/2) F(t) K(t/2) with the free flow's symmetric approximation
F(t) = product over factors of X1(t/2) X2(t/2) X3(t) X2(t/2) X1(t/2) (Dullweber, Leimkuhler,
McLachlan 1997; a symmetric body's exact free flow instead; SE3: D(t/2) [rotations] D(t/2))
is symmetric, symplectic, of order 2; a scheme
composes S(gamma_1 h) ... S(gamma_s h) (hpgen.splitting.coefficients). Adjacent sub-flows of
the same kind merge exactly (phi_a phi_b = phi_{a+b}: a kick leaves g fixed, a rotation
about a keeps a.pi), and kicks vanish where V is constant.

The step is exported in the VPRK step's contract (hpgen.abi): its unknown is z = p_k
(residual z - p, guess p: Newton ends at the first iterate with dz = 0 exactly), the update
is the composition from (g_k, p_k) and the chart curve of the sections output
g(theta) = the scheme's own step of size theta h from (g_k, z = p_k).
"""
from __future__ import annotations

import casadi as ca

from ..derive.action import StepEquations
from .structure import FactorKinetics, SplitStructure, recognise


def _force_function(group, lag, g):
    """f(g): the left-trivialized derivative of l(g, 0), an SX d-vector in the symbol g."""
    d, n = group.d, group.n
    eta = ca.SX.sym("eta", d)
    G = ca.mtimes(g, ca.SX.eye(n) + group.hat(eta))
    f = ca.gradient(lag(G, ca.SX.zeros(d)), eta)
    return ca.substitute(f, eta, ca.SX.zeros(d))


def _first_order(fk: FactorKinetics, k: int, c: float, kinetic: str = "dlm") -> list:
    """Factor k's kinetic sub-flows of phi(c h), in order, as (kind, factor, axis,
    coefficient): SE3's drift, then the rotations about the principal axes 1, 2, 3 (the
    largest moment last; ``kinetic`` "dlm") or Fasso's remainder rotation then his symmetric
    top ("fasso", an asymmetric body) or a symmetric body's exact free flow; R<n> its drift,
    SO2 its rotation."""
    if fk.family == "R":
        return [("drift", k, 0, c)]
    if fk.family == "SO2":
        return [("rot", k, 0, c)]
    if fk.symmetric_axis is not None:
        rots = [("free", k, 0, c)]
    elif kinetic == "fasso":
        rots = [("frem", k, fk.fasso[1], c), ("fsym", k, 0, c)]
    else:
        rots = [("rot", k, 0, c), ("rot", k, 1, c), ("rot", k, 2, c)]
    return ([("drift", k, 0, c)] if fk.family == "SE3" else []) + rots


def schedule(structure: SplitStructure, scheme, kicks: bool) -> list:
    """The sub-flows of ``scheme`` (SplittingScheme) in order, adjacent ones of the same
    kind merged: [(kind, factor, axis, coefficient of h)], kind in kick, rot, free, drift.
    phi(t) is the kick then every factor's first-order kinetic sub-flows, phi*(t) the same
    in reverse order; the halves alternate phi, phi* (phi* first when adjoint_first). With
    S(t) = phi(t/2) phi*(t/2) a symmetric composition's basic step is
    K(t/2) [X1(t/2) X2(t/2) X3(t) X2(t/2) X1(t/2)] K(t/2) once merged."""
    ops: list = []
    kick = [("kick", -1, 0)] if kicks else []
    for i, c in enumerate(scheme.halves):
        adjoint = (i % 2 == 1) != scheme.adjoint_first
        flows = [_first_order(fk, k, c, scheme.kinetic)
                 for k, fk in enumerate(structure.factors)]
        half = [op + (c,) for op in kick] + [op for f in flows for op in f]
        ops.extend(half[::-1] if adjoint else half)
    # between two kicks the factors' kinetic flows commute (they move disjoint parts of the
    # state): group them by factor, in order, so that a factor's flows about one axis meet
    grouped: list = []
    seg: list = []
    for op in ops + [None]:
        if op is None or op[0] == "kick":
            grouped.extend(sorted(seg, key=lambda o: o[1]))
            seg = []
            if op is not None:
                grouped.append(op)
        else:
            seg.append(op)
    ops = grouped
    merged: list = []
    for op in ops:
        if merged and merged[-1][:3] == op[:3]:
            merged[-1] = op[:3] + (merged[-1][3] + op[3],)
        else:
            merged.append(op)
    return merged


def kick_fractions(scheme) -> list:
    """The times of the kicks of ``scheme``'s schedule (with kicks) as fractions of h, in
    order: a half phi(c) kicks at its start, phi*(c) at its end (the kinetic flows advance
    t, the kicks do not), and the two kicks that schedule merges share their time."""
    out: list = []
    pos = 0.0
    for i, c in enumerate(scheme.halves):
        adjoint = (i % 2 == 1) != scheme.adjoint_first
        if adjoint:
            pos += c
        if not out or out[-1] != pos:
            out.append(pos)
        if not adjoint:
            pos += c
    return out


class _State:
    """The mutable SX state of the composition: per factor its rotation R (or None), its
    translation x (or None) and its momentum slice p."""

    def __init__(self, structure, g, p):
        self.structure = structure
        self.R, self.x, self.p = [], [], []
        for fk in structure.factors:
            blk = g[fk.row:fk.row + fk.n, fk.row:fk.row + fk.n]
            pk = p[fk.off:fk.off + fk.d]
            if fk.family == "R":
                self.R.append(None)
                self.x.append(blk[0:fk.d, fk.d])
            elif fk.family == "SE3":
                self.R.append(blk[0:3, 0:3])
                self.x.append(blk[0:3, 3])
            else:
                self.R.append(blk)
                self.x.append(None)
            self.p.append(pk)

    def g(self, n):
        out = ca.SX.zeros(n, n)
        for fk, R, x in zip(self.structure.factors, self.R, self.x):
            r = fk.row
            if fk.family == "R":
                out[r:r + fk.n, r:r + fk.n] = ca.SX.eye(fk.n)
                out[r:r + fk.d, r + fk.d] = x
            elif fk.family == "SE3":
                out[r:r + 3, r:r + 3] = R
                out[r:r + 3, r + 3] = x
                out[r + 3, r + 3] = 1.0
            else:
                out[r:r + fk.n, r:r + fk.n] = R
        return out

    def momentum(self):
        return ca.vertcat(*self.p)


def _axis_rotation(a, theta):
    """Q = exp(theta a^) for a unit axis a (3 floats); a coordinate axis +-e_i gives the
    plane rotation itself (no 1 - cos term)."""
    nz = [i for i in range(3) if a[i] != 0.0]
    c, s = ca.cos(theta), ca.sin(theta)
    Q = ca.SX.zeros(3, 3)
    if len(nz) == 1 and abs(a[nz[0]]) == 1.0:
        i = nz[0]
        j, k = (i + 1) % 3, (i + 2) % 3
        s = s if a[i] > 0 else -s
        Q[i, i] = 1.0
        Q[j, j], Q[k, k], Q[j, k], Q[k, j] = c, c, -s, s
        return Q
    A = ca.DM(list(a))
    ahat = ca.vertcat(ca.horzcat(0, -a[2], a[1]), ca.horzcat(a[2], 0, -a[0]),
                      ca.horzcat(-a[1], a[0], 0))
    return c * ca.SX.eye(3) + s * ca.SX(ahat) + (1 - c) * ca.SX(ca.mtimes(A, A.T))


def _rotate(st: _State, k: int, axis: int, t, rate=None):
    """The flow of rate (a.pi)^2 / 2 about principal axis a (rate 1/D_a unless given)."""
    fk = st.structure.factors[k]
    if fk.family == "SO2":
        phi = t * st.p[k][0] * (1.0 / fk.moments[0])
        c, s = ca.cos(phi), ca.sin(phi)
        R = st.R[k]
        st.R[k] = ca.horzcat(c * R[:, 0] + s * R[:, 1], -s * R[:, 0] + c * R[:, 1])
        return
    a = tuple(fk.axes[r][axis] for r in range(3))
    pi = st.p[k][0:3]
    api = sum((a[r] * pi[r] for r in range(3) if a[r] != 0.0), ca.SX(0))
    Q = _axis_rotation(a, t * api * (1.0 / fk.moments[axis] if rate is None else rate))
    st.R[k] = ca.mtimes(st.R[k], Q)
    parts = [ca.mtimes(Q.T, pi)]
    if fk.family == "SE3":
        parts.append(ca.mtimes(Q.T, st.p[k][3:6]))
    st.p[k] = ca.vertcat(*parts)


def _rodrigues(w):
    """exp(w^) for an SX 3-vector w, any |w|: I + sinc(t) w^ + ((1 - cos t)/t^2) w^2, t = |w|,
    the two coefficients from their Taylor series below t^2 = 1e-4 (error < 1e-20) and from
    sin, cos at a safe argument above (no NaN in values or derivatives at w = 0)."""
    t2 = ca.dot(w, w)
    small = t2 < 1e-4
    ts = ca.sqrt(ca.if_else(small, 1.0, t2))
    s1 = ca.if_else(small, 1 - t2 / 6 * (1 - t2 / 20 * (1 - t2 / 42)), ca.sin(ts) / ts)
    c1 = ca.if_else(small, 0.5 - t2 / 24 * (1 - t2 / 30 * (1 - t2 / 56)),
                    (1 - ca.cos(ts)) / (ts * ts))
    W = ca.vertcat(ca.horzcat(0, -w[2], w[1]), ca.horzcat(w[2], 0, -w[0]),
                   ca.horzcat(-w[1], w[0], 0))
    return ca.SX.eye(3) + s1 * W + c1 * ca.mtimes(W, W)


def _free(st: _State, k: int, t):
    """The exact free flow of a symmetric body (moments D_a = D_b, distinct D_c about axis
    a_c)."""
    fk = st.structure.factors[k]
    c = fk.symmetric_axis
    _symmetric_top(st, k, t, fk.moments[(c + 1) % 3], c)


def _symmetric_top(st: _State, k: int, t, Da: float, c: int):
    """The exact flow of H = |pi|^2 / (2 D_a) + (a_c.pi)^2 (1/D_c - 1/D_a) / 2, two
    commuting exact flows (|pi|^2 is a Casimir): the rotation by t pi / D_a (pi fixed) and
    the rotation about a_c."""
    fk = st.structure.factors[k]
    pi = st.p[k][0:3]
    Q = _rodrigues(t * (1.0 / Da) * pi)
    st.R[k] = ca.mtimes(st.R[k], Q)
    if fk.family == "SE3":
        st.p[k] = ca.vertcat(pi, ca.mtimes(Q.T, st.p[k][3:6]))
    rate = 1.0 / fk.moments[c] - 1.0 / Da
    if rate != 0.0:
        a = tuple(fk.axes[r][c] for r in range(3))
        api = sum((a[r] * pi[r] for r in range(3) if a[r] != 0.0), ca.SX(0))
        Q2 = _axis_rotation(a, t * api * rate)
        st.R[k] = ca.mtimes(st.R[k], Q2)
        parts = [ca.mtimes(Q2.T, pi)]
        if fk.family == "SE3":
            parts.append(ca.mtimes(Q2.T, st.p[k][3:6]))
        st.p[k] = ca.vertcat(*parts)


def _drift(st: _State, k: int, t):
    fk = st.structure.factors[k]
    Minv = ca.SX(ca.DM(list(map(list, fk.translation_inverse))))
    if fk.family == "R":
        st.x[k] = st.x[k] + t * ca.mtimes(Minv, st.p[k])
        return
    P = st.p[k][3:6]
    v = ca.mtimes(Minv, P)
    st.x[k] = st.x[k] + t * ca.mtimes(st.R[k], v)
    st.p[k] = ca.vertcat(st.p[k][0:3] + t * ca.cross(P, v), P)


def _kick(st: _State, group, force, gsym, t, j: int = 0):
    """p <- p + t f(g): ``force`` an SX in gsym, or (open models) a callable (G, j) -> f at
    the j-th kick of the composition (its time, kick_fractions)."""
    if callable(force):
        f = force(st.g(group.n), j)
    else:
        f = ca.substitute(force, ca.vec(gsym), ca.vec(st.g(group.n)))
    for k, fk in enumerate(st.structure.factors):
        st.p[k] = st.p[k] + t * f[fk.off:fk.off + fk.d]


def composition(structure, group, force, gsym, ops, g, p, h):
    """(g1, p1): the sub-flows ``ops`` (schedule) applied to (g, p) with step h (SX)."""
    st = _State(structure, g, p)
    j = 0
    for kind, k, axis, c in ops:
        t = c * h
        if kind == "kick":
            _kick(st, group, force, gsym, t, j)
            j += 1
        elif kind == "rot":
            _rotate(st, k, axis, t)
        elif kind == "free":
            _free(st, k, t)
        elif kind == "fsym":
            fk = structure.factors[k]
            _symmetric_top(st, k, t, fk.moments[fk.fasso[2]], fk.fasso[0])
        elif kind == "frem":
            fk = structure.factors[k]
            _rotate(st, k, axis, t, 1.0 / fk.moments[axis] - 1.0 / fk.moments[fk.fasso[2]])
        else:
            _drift(st, k, t)
    return st.g(group.n), st.momentum()


def splitting_step(model, scheme, lag, g, p, h, params=None):
    """(StepEquations, chart) of the splitting ``scheme`` (SplittingScheme) for ``model``
    with l = ``lag(g, xi)``; g (n x n), p (d), h (scalar): SX symbols of the state and step.
    chart(theta) -> SX n x n: the sections' chart curve (module docstring). ModelError when
    the model lacks the structure (hpgen.splitting.structure)."""
    structure = recognise(model, lag, params)
    group = model.group
    d = group.d
    force = _force_function(group, lag, g)
    moving = ca.vertcat(ca.vec(g), *([params] if params is not None else []))
    kicks = bool(ca.depends_on(force, moving)) or bool(ca.DM(ca.evalf(force)).full().any())
    ops = schedule(structure, scheme, kicks)
    g1, p1 = composition(structure, group, force, g, ops, g, p, h)
    z = ca.SX.sym("z", d)
    eqs = StepEquations(z=z, blocks=(("p", 0, d),), residual=z - p, g1=g1, p1=p1, guess=p,
                        xi_hat=ca.SX.sym("xi", d), margin=ca.SX(1.0), chart_step=None)

    def chart(theta):
        return composition(structure, group, force, g, ops, g, z, theta * h)[0]
    return eqs, chart


def open_splitting_step(model, scheme, lag_f, force_f, g, p, hv):
    """splitting_step for a model with forces, control inputs or t (hpgen.abi's step vector
    hv = [h, t_k, u, params]; lag_f(g, xi, t, params), force_f(g, xi, t, u, params):
    hpgen.derive.lagrangian.open_functions). Each kick adds -dV(t) + f(g, t, u_k, params) at
    its own time t_k + c h (kick_fractions: the step's two ends for split2, the forced
    Stormer-Verlet's discrete forces); f must not depend on xi (recognise)."""
    group = model.group
    m = len(model.inputs)
    h, P, u = hv[0], hv[2 + m:], hv[2:2 + m]
    t = ca.SX.sym("t")
    structure = recognise(model, lambda G, X: lag_f(G, X, t, P), ca.vertcat(P, t))
    f = _force_function(group, lambda G, X: lag_f(G, X, t, P), g) + \
        force_f(g, ca.SX.zeros(group.d), t, u, P)
    times = kick_fractions(scheme)
    at = ca.vertcat(ca.vec(g), t)

    def kick(step):
        return lambda G, j: ca.substitute(f, at, ca.vertcat(ca.vec(G), hv[1] + times[j] * step))
    kicks = bool(ca.depends_on(f, ca.vertcat(at, hv))) or bool(ca.DM(ca.evalf(f)).full().any())
    ops = schedule(structure, scheme, kicks)
    g1, p1 = composition(structure, group, kick(h), g, ops, g, p, h)
    z = ca.SX.sym("z", group.d)
    eqs = StepEquations(z=z, blocks=(("p", 0, group.d),), residual=z - p, g1=g1, p1=p1,
                        guess=p, xi_hat=ca.SX.sym("xi", group.d), margin=ca.SX(1.0),
                        chart_step=None)

    def chart(theta):
        return composition(structure, group, kick(theta * h), g, ops, g, z, theta * h)[0]
    return eqs, chart
