"""The step of a family model (group G^N) derived once per body and once per joint, composed
with CasADi call nodes.

For a body-separable Lagrangian l = sum_i l_i(g_i, xi_i; i) (hpgen.model.bodyterms: every sum
term local to its body, the body index i a numeric input) the unconstrained step of the product
group is N independent steps: body i's stage equations involve its own unknowns z_i, (g_i, p_i)
and h only (the chart maps and the action sum of a product split factor by factor). Each is
derived once as a SX Function of (z_i, g_i, p_i, h, i) with the options of
hpgen.derive.family_calls (a call node where it is used, differentiated through its own
Jacobian function, its derivative functions calls too). The step kernels
(hpgen.derive.family_kernels) compose the calls over MX, where a call passes whole vectors;
family_step composes them over SX as well (the SX kernels' and the tests' form). Bodies whose
Lagrangians differ (sums over different ranges) get one function per distinct set of sums
("class"). An open model (runtime parameters and t in the sums, a per-body force with the
control inputs) gives its body functions the environment (t, params) and its step functions the
step vector hv as their h (hpgen.derive.family_open); body i's force enters body i's step only.

Constraints (hpgen.derive.constraints, docs/numerics.md sec. 14) decompose by joint: with
joint j's rows phi_j(g_a, g_b, ...; i_j) and body-frame Jacobians Phi_{j,a},
    p_i^+ = p_i - sum_{j touching i} Phi_{j,i}(g)^T h lambda_j
    (body i's unconstrained step from (g_i, p_i^+))
    phi_j(g_{k+1}) / h = 0
    p_{i,k+1} = p_{i,k+1}^- - sum_{j touching i} Phi_{j,i}(g_{k+1})^T h nu_j
    Phi_j(g_{k+1}) v_{k+1} = 0,  v_{k+1} = xi(g_{k+1}, p_{k+1}) per body
where each joint's (phi_j, Phi_{j,a}, ...) is one call of the function of its row block's
text (rows with the loop variable i as a numeric input).

A splitting scheme (``tableau: split2`` on a constrained family, hpgen.derive.family_split)
makes the body step the explicit splitting step, with no unknowns: the step's unknowns are
then lambda and nu alone.

Unknowns, in this order: every body's step unknowns (body 0's blocks, body 1's, ...; the
block labels of the expanded step with the body as a suffix, "Xi1[3]"), then ``lambda`` and
``nu`` (all constraint rows, file order: the expanded step's blocks, so the multipliers'
readers work unchanged) and, when d2l/dxi2 depends on g or xi, ``v1`` (d, body by body; when
it is constant per body, possibly depending on i, the node velocity is explicit, its inverse
taken numerically per body as the expanded step does). The rows follow the same order. For a
chain the Jacobian is an arrow of blocks: block-diagonal in the bodies, each joint's rows
and columns touching two neighbouring bodies (all bodies first, then all joints: the
multiplier blocks stay contiguous in file order); a fill-reducing order keeps its sparse
factors O(N).
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..groups import group_from_spec
from .action import StepEquations, step_equations
from .family_open import with_env, body_force_function, body_index, index_symbol, \
    open_layout, product_force, split_step_vector
from .family_joint_forces import external_forces, force_components, \
    joint_force_functions, joint_stage_functions, stage_force, stage_function
from .family_velocity import hessian_inverse, momentum_functions, node_velocity, quadratic
from .family_potentials import inline_forces, potential_functions, product_potential
from .family_split import split_body_step
from .lagrangian import to_casadi
from ..splitting import is_splitting
from .family_calls import CALL


@dataclass(frozen=True)
class FamilyParts:
    """A family model's step (``eqs``, in the symbols g, p, h given to family_step) and the
    Lagrangian as a sum of per-body calls: lag(G, X) -> SX scalar for the product's G, X."""
    eqs: StepEquations
    lag: object
    velocity: object     # (g, p, xi) -> SX d: one Newton step of dl/dxi = p, body by body
    force: object = None  # (G, X, t) -> the product's force (per-body calls), or None
    quadratic: bool = False  # every body's d2l/dxi2 free of xi: ``velocity`` is exact


def _body_lagrangians(model, body):
    """{class key: (inline Function l(G, X, i[, e]), call Function)}, and the key of each
    body; e = (t, params) (open models: t the time, params Model.runtime_symbols' order)."""
    from ..model.symbols import TIME_SYMBOL
    terms = model.family.local.bodies
    N = model.family.count
    keys = [tuple(j for j, t in enumerate(terms) if t.start <= k < t.stop) for k in range(N)]
    G, X = ca.SX.sym("g", body.n, body.n), ca.SX.sym("xi", body.d)
    I, index, data = index_symbol(model)
    lay = open_layout(model)
    E = ca.SX.sym("e", 1 + lay[1]) if lay is not None else None
    env = {}
    if E is not None:
        env = {TIME_SYMBOL: E[0], **{s: E[1 + k] for k, s in enumerate(model.runtime_symbols)}}
    funs = {}
    for c, key in enumerate(sorted(set(keys))):
        expr = ca.SX(0)
        for j in key:
            t = terms[j]
            mapping = {sp_sym: X[int(str(sp_sym)[3:])] for sp_sym in t.expr.free_symbols
                       if str(sp_sym).startswith("xi_")}
            for s in t.expr.free_symbols:
                name = str(s)
                if name.startswith("g_"):
                    a, b = map(int, name[2:].split("_"))
                    mapping[s] = G[a, b]
            mapping[t.index] = index
            mapping.update({s: v for s, v in {**env, **data}.items()
                            if s in t.expr.free_symbols})
            expr = expr + to_casadi(t.expr, mapping)
        funs[key] = (ca.Function(f"l_body{c}", with_env([G, X, I], E), [expr]),
                     ca.Function(f"l_body{c}_call", with_env([G, X, I], E), [expr], CALL))
    return funs, keys


def _joint_functions(model, body):
    """{(text, index symbol): Function(g_slot0, ..., i) -> (phi, Phi_0, ...)} (call nodes)."""
    out = {}
    nb, db = body.n, body.d
    for jt in model.family.local.joints:
        key = (jt.text, jt.index)
        if key in out:
            continue
        K = len(jt.bodies)
        Gs = [ca.SX.sym(f"g{s}", nb, nb) for s in range(K)]
        I = ca.SX.sym("i")
        mapping = {}
        for r in jt.rows:
            for sym in r.free_symbols:
                name = str(sym)
                if name.startswith("g_"):
                    a, b = map(int, name[2:].split("_"))
                    mapping[sym] = Gs[a // nb][a % nb, b - (a // nb) * nb]
        if jt.index is not None:
            mapping[jt.index] = I
        phi = ca.vertcat(*[to_casadi(r, mapping) for r in jt.rows])
        etas = [ca.SX.sym(f"eta{s}", db) for s in range(K)]
        varied = ca.substitute(phi, ca.vertcat(*[ca.vec(G) for G in Gs]), ca.vertcat(*[
            ca.vec(ca.mtimes(G, ca.SX.eye(nb) + body.hat(e))) for G, e in zip(Gs, etas)]))
        Phis = [ca.substitute(ca.jacobian(varied, e), ca.vertcat(*etas), ca.SX.zeros(K * db))
                for e in etas]
        out[key] = ca.Function(f"joint{len(out)}", [*[ca.vec(G) for G in Gs], I],
                               [phi, *Phis], CALL)
    return out


def family_local(model) -> bool:
    """True when ``model`` is derived body by body: a family model whose Lagrangian sums and
    joints are local (hpgen.model.bodyterms); runtime parameters and t may enter the
    Lagrangian (not the joints), forces and control inputs only through a per-body force
    (``forces: {for: i, body: [...]}``, hpgen.model.family_forces); a sum over a few bodies'
    configurations is a joint potential (hpgen.derive.family_potentials). Otherwise it is
    expanded."""
    family = getattr(model, "family", None)
    if family is None or family.local is None:
        return False
    if model.open_system:
        if (model.forced or model.inputs) and family.local.force is None:
            return False
        for jt in family.local.joints:
            for r in jt.rows:
                if any(not str(s).startswith("g_") and s != jt.index for s in r.free_symbols):
                    return False
    return True


def block_diagonal_symbol(group):
    """An n x n SX of a product group's element: a symbol in each factor's diagonal block,
    structural zeros elsewhere."""
    blocks = [ca.SX.sym(f"g{k}", lay.n, lay.n) for k, lay in enumerate(group.factors)]
    return ca.diagcat(*blocks)


_LAST: list = []


def _functions(model, tableau, tau: str, rkmk: str):
    """(body group, lags, keys, steps, joint functions, node velocity functions): the
    per-body and per-joint functions, built once per (model, scheme) and shared by every
    kernel (one CasADi function each, so the generated code has each once)."""
    split = is_splitting(tableau)
    key = (tableau.name, tuple(tableau.halves) if split else tuple(map(tuple, tableau.A)),
           tau, rkmk)
    if _LAST and _LAST[0] is model and _LAST[1] == key:
        return _LAST[2]
    family = model.family
    body = group_from_spec(family.body)
    nb, db = body.n, body.d
    lags, keys = _body_lagrangians(model, body)
    reduced = model.left_invariant and not model.constraints and not model.time_dependent \
        and not model.forced

    # one body's step per class, derived once; its h input is the step vector of an open
    # model (hpgen.abi: [h, t_k, u, params])
    lay = open_layout(model)
    gb, pb = ca.SX.sym("g", nb, nb), ca.SX.sym("p", db)
    ib = index_symbol(model)[0]
    hb = ca.SX.sym("h", 1 if lay is None else 2 + lay[0] + lay[1])
    h_, _, _ = split_step_vector(model, hb)
    gbv = ca.vec(gb)
    fb = body_force_function(model, body)
    fs = body_force_function(model, body, inline=True)
    jpower = joint_force_functions(model, body) if lay is not None else []
    # with forces between bodies (joint potentials' included, hpgen.derive.
    # family_potentials), a body's step takes its external stage forces fext
    pots = potential_functions(model, body)
    pforces = [(f, pf) for _, f, pf in pots]
    jforces = jpower + pforces
    comps = force_components(model, pforces) if jforces else ()
    fx = ca.SX.sym("fext", tableau.stages * len(comps)) if jforces else None
    steps = {}
    for c, (cls, (lag_in, _)) in enumerate(sorted(lags.items())):
        raw = None       # a splitting step's g1 before its Newton-Schulz step
        if split:        # the explicit body step of a splitting scheme (no unknowns)
            e, raw, ns = split_body_step(
                model, tableau, body, lambda G, X, E, f=lag_in: f(*with_env([G, X, ib], E)),
                gb, pb, hb, ib, cls, c)
        elif lay is None:
            force = stage_force(None, fx, ib, None, None, db, comps) if jforces else None
            e = step_equations(body, lambda G, X, f=lag_in: f(G, X, ib), tableau, tau, rkmk,
                               reduced, gb, pb, hb, None, force)
        else:
            P, u = hb[2 + lay[0]:], hb[2:2 + lay[0]]
            force = None if fs is None else (
                lambda G, X, tt: fs(ca.vec(G), X, ib, ca.vertcat(tt, u, P)))
            if jforces:      # a body force of zeros (joint forces only) is left out
                own = fs if fs is not None and any(
                    e != 0 for e in model.family.local.force.exprs) else None
                force = stage_force(own, fx, ib, u, P, db, comps)
            e = step_equations(body, lambda G, X, tt, f=lag_in: f(G, X, ib, ca.vertcat(tt, P)),
                               tableau, tau, rkmk, reduced, gb, pb, h_, hb[1], force)
        args = [e.z, gbv, pb, hb, ib] + ([fx] if jforces else [])
        S = stage_function(e, body, tableau, tau, gb, hb, h_, f"body{c}_stages") \
            if jforces else None
        inline = (stage_function(e, body, tableau, tau, gb, hb, h_, f"body{c}_stages_inline",
                                 {}), inline_forces(pforces)) if pforces else None
        steps[cls] = dict(
            S=S, joint_forces=jforces, power_forces=jpower, FC=comps,
            JS=joint_stage_functions(model, tableau, S, jforces, comps, inline) if jforces
            else [],
            nz=e.z.numel(), blocks=e.blocks,
            F=ca.Function(f"body{c}_residual", args, [e.residual], CALL),
            U=ca.Function(f"body{c}_update", args, [ca.vec(e.g1), e.p1], CALL),
            # a splitting step's update before its Newton-Schulz step on g1 (UR), that step
            # (NS, of vec g1), for the mapped step (hpgen.derive.family_split); else None
            UR=None if raw is None else ca.Function(
                f"body{c}_update_raw", args, [ca.vec(raw), e.p1], CALL),
            NS=None if raw is None else ca.Function(
                f"body{c}_newton_schulz", [gbv], [ca.vec(ns(gb))], CALL),
            M=ca.Function(f"body{c}_margin", [e.z, hb], [e.margin], CALL),
            C=ca.Function(f"body{c}_chart", [e.z, hb], [e.chart_step], CALL),
            Z=ca.Function(f"body{c}_guess", [e.xi_hat, gbv, pb, hb], [e.guess], CALL),
            force=fb, potentials=pots)

    joints = family.local.joints
    jfun = _joint_functions(model, body) if joints else {}
    vel_funs = node_velocity(model, lags, body, lay) if joints else {}
    out = (body, lags, keys, steps, jfun, vel_funs)
    _LAST[:] = [model, key, out]
    return out


def family_step(model, tableau, tau: str, rkmk: str, g, p, h, z=None) -> FamilyParts:
    """The family step (module docstring) in g (n x n: SX, block-diagonal, or MX), p (d), h
    (1), for a model with family_local(model); z: the unknowns' symbol to use (else a new
    one, of the class of g). An open model's h is its step vector hv (hpgen.abi)."""
    S = ca.MX if isinstance(g, ca.MX) else ca.SX      # the composition's symbol class
    body, lags, keys, steps, jfun, vel_funs = _functions(model, tableau, tau, rkmk)
    hs, ek, e1 = split_step_vector(model, h)
    nb, db, N = body.n, body.d, model.family.count

    Gk = [g[k * nb:(k + 1) * nb, k * nb:(k + 1) * nb] for k in range(N)]
    pk = [p[k * db:(k + 1) * db] for k in range(N)]
    xi_hat = S.sym("xi_hat", N * db)
    index = [body_index(model, k, h) for k in range(N)]     # body k's index input
    joints = model.family.local.joints
    m = sum(len(j.rows) for j in joints)
    explicit = all(f is not None for f in vel_funs.values())
    nzb = sum(steps[keys[k]]["nz"] for k in range(N))
    # one symbol for all unknowns (an MX function's input must be a whole symbol)
    if z is None:
        z = S.sym("z", nzb + (2 * m + (0 if explicit else N * db) if joints else 0))
    zs, blocks, off = [], [], 0
    for k in range(N):
        st = steps[keys[k]]
        zs.append(z[off:off + st["nz"]])
        blocks += [(f"{lab}[{k}]", off + a, off + b) for lab, a, b in st["blocks"]]
        off += st["nz"]
    lam, nu = z[nzb:nzb + m], z[nzb + m:nzb + 2 * m]
    rows = np.cumsum([0] + [len(j.rows) for j in joints])
    impulse = [S.zeros(db) for _ in range(N)]        # sum_j Phi_{j,k}^T lambda_j
    for j, jt in enumerate(joints):
        out = jfun[(jt.text, jt.index)](*[ca.vec(Gk[b]) for b in jt.bodies], jt.value)
        for s, b in enumerate(jt.bodies):
            impulse[b] = impulse[b] + ca.mtimes(out[1 + s].T, lam[rows[j]:rows[j + 1]])
    res, g1s, p1s, margins, charts, guesses = [], [], [], [], [], []
    st0 = steps[keys[0]]
    fext = external_forces(model, tableau, st0, zs, Gk, h, S) if st0["joint_forces"] else []
    for k in range(N):
        st = steps[keys[k]]
        args = [zs[k], ca.vec(Gk[k]), pk[k] - impulse[k], h, index[k]] + fext[k:k + 1]
        res.append(st["F"](*args))
        g1v, p1 = st["U"](*args)
        g1s.append(ca.reshape(g1v, nb, nb))
        p1s.append(p1)
        margins.append(st["M"](zs[k], h))
        charts.append(st["C"](zs[k], h))
        guesses.append(st["Z"](xi_hat[k * db:(k + 1) * db], ca.vec(Gk[k]), pk[k], h))
    margin = margins[0]
    for mk in margins[1:]:
        margin = ca.fmin(margin, mk)
    g1 = ca.diagcat(*g1s)
    lag, velocity = _product_lagrangian(model, lags, keys, body, index, ek, st0["potentials"])
    force = product_force(st0["force"], model, h, nb, db, N, st0["power_forces"])
    if not joints:
        eqs = StepEquations(z, tuple(blocks), ca.vertcat(*res), g1, ca.vertcat(*p1s),
                            ca.vertcat(*guesses), xi_hat, margin, ca.vertcat(*charts))
        return FamilyParts(eqs, lag, velocity, force, quadratic(lags, body))

    nz = nzb
    blocks += [("lambda", nz, nz + m), ("nu", nz + m, nz + 2 * m)]
    phis, Phi1 = [], []
    kick = [S.zeros(db) for _ in range(N)]           # sum_j Phi_{j,k}(g1)^T nu_j
    for j, jt in enumerate(joints):
        out = jfun[(jt.text, jt.index)](*[ca.vec(g1s[b]) for b in jt.bodies], jt.value)
        phis.append(out[0] / hs)
        Phi1.append(out[1:])
        for s, b in enumerate(jt.bodies):
            kick[b] = kick[b] + ca.mtimes(out[1 + s].T, nu[rows[j]:rows[j + 1]])
    p1s = [p1s[k] - kick[k] for k in range(N)]
    if explicit:
        vel = [vel_funs[keys[k]][0](*with_env([ca.vec(g1s[k]), p1s[k], index[k],
                                               hessian_inverse(model, vel_funs[keys[k]], k,
                                                               index[k])], e1))
               for k in range(N)]
        extra_rows, extra_guess = [], []
    else:
        v1 = z[nz + 2 * m:]
        vel = [v1[k * db:(k + 1) * db] for k in range(N)]
        dl = momentum_functions(model, lags, body, e1 is not None and e1.numel())
        extra_rows = [dl[keys[k]](*with_env([g1s[k], vel[k], index[k]], e1)) - p1s[k]
                      for k in range(N)]
        extra_guess = [xi_hat]
        blocks.append(("v1", nz + 2 * m, nz + 2 * m + N * db))
    hidden = []
    for j, jt in enumerate(joints):
        hidden.append(sum((ca.mtimes(Phi1[j][s], vel[b]) for s, b in enumerate(jt.bodies)),
                          S.zeros(len(jt.rows))))
    residual = ca.vertcat(*res, *phis, *hidden, *extra_rows)
    eqs = StepEquations(z, tuple(blocks), residual, g1,
                        ca.vertcat(*p1s), ca.vertcat(*guesses, S.zeros(2 * m), *extra_guess),
                        xi_hat, margin, ca.vertcat(*charts))
    return FamilyParts(eqs, lag, velocity, force, quadratic(lags, body))


def _product_lagrangian(model, lags, keys, body, index, ek=None, pots=()):
    """(lag, velocity): l(G, X) of the product as a sum of per-body calls, and one Newton step
    of dl/dxi = p from xi body by body (the Hessian of a separable l is block-diagonal);
    index: the bodies' index inputs (body_index); ek: an open model's (t_k, params), bound
    into both; pots: the joint potentials' functions (potential_functions)."""
    nb, db, N = body.n, body.d, len(index)
    G, X, P = ca.SX.sym("g", nb, nb), ca.SX.sym("xi", db), ca.SX.sym("p", db)
    I = index_symbol(model)[0]
    E = ca.SX.sym("e", ek.numel()) if ek is not None else None
    steps = {}
    for c, (key, (lag_in, _)) in enumerate(sorted(lags.items())):
        mu = ca.gradient(lag_in(*with_env([G, X, I], E)), X)
        steps[key] = ca.Function(f"body{c}_velocity_step", with_env([ca.vec(G), P, X, I], E),
                                 [X - ca.solve(ca.jacobian(mu, X), mu - P)], CALL)

    def lag(Gp, Xp):
        terms = [lags[keys[k]][1](*with_env([Gp[k * nb:(k + 1) * nb, k * nb:(k + 1) * nb],
                                          Xp[k * db:(k + 1) * db], index[k]], ek))
                 for k in range(N)]
        if pots:        # the joint potentials' terms
            return ca.sum1(ca.vertcat(*terms)) + product_potential(pots, body, Gp, ek)
        return ca.sum1(ca.vertcat(*terms))

    def velocity(Gp, Pp, Xp):
        return ca.vertcat(*[steps[keys[k]](*with_env([
            ca.vec(Gp[k * nb:(k + 1) * nb, k * nb:(k + 1) * nb]), Pp[k * db:(k + 1) * db],
            Xp[k * db:(k + 1) * db], index[k]], ek)) for k in range(N)])
    return lag, velocity
