"""Forces between bodies of a family model (hpgen.model.joint_forces: ``forces.joint``) in the
per-body step: each joint force is one CasADi function of its bodies' stage states, its
outputs scattered to the bodies: called per joint and per stage in family_step's composition
(the SX form), mapped over the joints in the step kernels (the mapped form, below).

The discrete Lagrange-d'Alembert force of stage s (hpgen.derive.action) is evaluated at the
unvaried stage state (G^s = g_k tau(h Theta^s), Xi^s, t_k + c_s h). A body's step function
takes, besides its own force, an external stage force ``fext`` added to it; ``stage_function``
gives the body's stage states from its unknowns (the eliminations of hpgen.derive.action,
read off the unknowns' block labels), so that body b's fext is sum over the joints touching
b of the joint function at its bodies' stage states. The Jacobian couples the unknowns of
the bodies a joint force touches.

fext holds only the force components (indices into the body's d) that some joint force can
make nonzero (``force_components``: its expression is not identically 0), c of them per
stage, stage 0's c entries first (s c); the others are structural zeros of the body step.
A damper's couple (torque only) thus leaves the body step's terms in the linear force out:
they are most of its derivative code through the Gauss stages' dtau factors.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from .lagrangian import to_casadi
from .family_calls import CALL


def joint_force_functions(model, body) -> list:
    """[(Function(vec G_0, X_0, ..., vec G_(K-1), X_(K-1), i, e) -> (f_0, ..., f_(K-1)),
    JointForce), ...] of the model's joint forces, e = (t, u, params) as the body force's."""
    from ..model.symbols import TIME_SYMBOL
    bf = model.family.local.force
    if bf is None or not bf.joints:
        return []
    nb, db = body.n, body.d
    m, nP = len(model.inputs), len(model.runtime_symbols)
    out = []
    for c, jf in enumerate(bf.joints):
        K = len(jf.exprs)
        Gs = [ca.SX.sym(f"g{s}", nb, nb) for s in range(K)]
        Xs = [ca.SX.sym(f"xi{s}", db) for s in range(K)]
        I, E = ca.SX.sym("i"), ca.SX.sym("e", 1 + m + nP)
        mapping = {TIME_SYMBOL: E[0], jf.index: I,
                   **{s: E[1 + k] for k, s in enumerate(model.input_symbols)},
                   **{s: E[1 + m + k] for k, s in enumerate(model.runtime_symbols)}}
        for row in jf.exprs:
            for e in row:
                for sym in e.free_symbols:
                    name = str(sym)
                    if name.startswith("xi_"):
                        k = int(name[3:])
                        mapping[sym] = Xs[k // db][k % db]
                    elif name.startswith("g_"):
                        a, b = map(int, name[2:].split("_"))
                        mapping[sym] = Gs[a // nb][a % nb, b % nb]
        outs = [ca.vertcat(*[to_casadi(e, mapping) for e in row]) for row in jf.exprs]
        args = [v for G, X in zip(Gs, Xs) for v in (ca.vec(G), X)]
        out.append((ca.Function(f"joint_force{c}", [*args, I, E], outs, CALL), jf))
    return out


def force_components(model, potentials=()) -> tuple:
    """The components (0..d-1, ascending) of the body's force that some joint force of
    ``model`` or joint potential's force (``potentials``: hpgen.derive.family_potentials.
    potential_functions) can make nonzero (an expression not identically 0 in some
    slot); (0,) when none can."""
    bf = model.family.local.force
    found = {k for jf in (bf.joints if bf is not None else ()) for row in jf.exprs
             for k, e in enumerate(row) if e != 0}
    found |= {k for _, pf in potentials for row in pf.exprs
              for k, e in enumerate(row) if not e.is_zero()}
    return tuple(sorted(found)) or (0,)


def _environment(hv, m: int):
    """(h, t_k, u, params) of the step vector hv; a closed model's hv is h alone (a joint
    potential's force, hpgen.derive.family_potentials): t_k = 0, no u nor params."""
    if hv.numel() == 1:
        return hv[0], 0, ca.DM(0, 1), ca.DM(0, 1)
    return hv[0], hv[1], hv[2:2 + m], hv[2 + m:]


def stage_force(fb, fext, index, u, P, db: int, comps: tuple):
    """The body's stage force for hpgen.derive.action.step_equations: its own force ``fb``
    (or none) plus stage s's entries of ``fext`` at the components ``comps``
    (force_components); step_equations calls it once per stage, in order."""
    calls: list = []
    c = len(comps)

    def force(G, X, tt):
        s = len(calls)
        calls.append(s)
        own = 0 if fb is None else fb(ca.vec(G), X, index, ca.vertcat(tt, u, P))
        f = ca.SX.zeros(db)
        for j, k in enumerate(comps):
            f[k] = fext[s * c + j]
        return own + f
    return force


def stage_function(e, body, tableau, tau: str, g, hv, h, name: str, opts=CALL):
    """Function(z, vec g, hv) -> (vec G^s per column (n^2 x s), Xi^s per column (d x s)) of a
    body's step ``e`` (hpgen.derive.action.StepEquations) from its unknowns; ``opts`` the
    Function's options (a call node by default, {} to be inlined where it is called)."""
    s, d = tableau.stages, body.d
    A, c = np.array(tableau.A, dtype=float), [float(x) for x in tableau.c]
    blk = {lab: e.z[a:b] for lab, a, b in e.blocks}
    zero = ca.SX.zeros(d)
    if list(blk) == ["Xi"]:                                  # a common stage velocity
        X = [blk["Xi"]] * s
        Th = [ci * blk["Xi"] for ci in c]
    elif sorted(blk) == sorted([f"Theta{i + 1}" for i in range(s)] + ["mu1"]):   # exact, A^-1
        Th = [blk[f"Theta{i + 1}"] for i in range(s)]
        Ainv = np.linalg.inv(A)
        K = [sum((float(Ainv[j][i]) * Th[i] for i in range(s)), zero) for j in range(s)]
        X = [body.chart_product(tau, "dtau", -h * Th[j], K[j]) for j in range(s)]
    elif sorted(blk) == sorted(f"Xi{i + 1}" for i in range(s)):                  # truncated
        X = [blk[f"Xi{i + 1}"] for i in range(s)]
        Th = [sum((float(A[i][j]) * X[j] for j in range(s)), zero) for i in range(s)]
    else:                                                    # stage variables are unknowns
        X = [blk[f"Xi{i + 1}"] for i in range(s)]
        Th = [blk[f"Theta{i + 1}"] for i in range(s)]
    G = [ca.vec(ca.mtimes(g, body.tau(tau, h * t))) for t in Th]
    return ca.Function(name, [e.z, ca.vec(g), hv], [ca.horzcat(*G), ca.horzcat(*X)], opts)


def external_forces(model, tableau, st, zs, Gk, hv, S) -> list:
    """Body k's fext (s c) for k = 0..N-1 (module docstring): zs body k's unknowns, Gk its
    g block, hv the step vector, S the symbol class (SX or MX)."""
    comps = list(st["FC"])
    s, N, m = tableau.stages, len(zs), len(model.inputs)
    h, t, u, P = _environment(hv, m)
    states = [st["S"](zs[k], ca.vec(Gk[k]), hv) for k in range(N)]
    fext = [[S.zeros(len(comps)) for _ in range(s)] for _ in range(N)]
    for fun, jf in st["joint_forces"]:
        for i, bodies in jf.instances:
            for q in range(s):
                args = [v for b in bodies for v in (states[b][0][:, q], states[b][1][:, q])]
                out = fun(*args, i, ca.vertcat(t + float(tableau.c[q]) * h, u, P))
                out = [out] if len(bodies) == 1 else out
                for slot, b in enumerate(bodies):
                    fext[b][q] = fext[b][q] + out[slot][comps]
    return [ca.vertcat(*f) for f in fext]


def joint_power_force(model, funs, Gp, Xp, tt, hv, nb: int, db: int, N: int) -> list:
    """The joint forces at the product's (Gp, Xp) and time tt, per body (d each)."""
    m = len(model.inputs)
    u, P = hv[2:2 + m], hv[2 + m:]
    out = [0] * N
    for fun, jf in funs:
        for i, bodies in jf.instances:
            args = []
            for b in bodies:
                args += [ca.vec(Gp[b * nb:(b + 1) * nb, b * nb:(b + 1) * nb]),
                         Xp[b * db:(b + 1) * db]]
            res = fun(*args, i, ca.vertcat(tt, u, P))
            res = [res] if len(bodies) == 1 else res
            for slot, b in enumerate(bodies):
                out[b] = out[b] + res[slot]
    return out


# --- the mapped form (hpgen.derive.family_map, hpgen.derive.family_jacobian) -----------------
#
# Each joint force is folded with the stage states of its slot bodies into one SX function of
# the slots' unknowns and g blocks, (Z_0, vec g_0, ..., Z_(K-1), vec g_(K-1), hv, i) ->
# (fext_0, ..., fext_(K-1)) (s c each, module docstring), called once through a map
# over the joints of its range. Body b's fext is the sum over the joints and slots that hold b
# (products with constant selection matrices); its derivative d fext_b / d Z_t is one block
# per (joint, slot, slot), placed at (b's fext rows, t's unknowns) of dFext/dz, which enters J
# through the body step's own blocks dF/dfext, dg1/dfext, dp1/dfext (block products).


def joint_stage_functions(model, tableau, S, jforces, comps: tuple, inline=None) -> list:
    """[(Function(Z_0, vec g_0, ..., hv, i) -> (fext_0, ...), JointForce), ...]: the joint
    forces ``jforces`` (joint_force_functions) at the stage states that the body stage
    function ``S`` (stage_function) gives from each slot's unknowns, their components
    ``comps`` (force_components) per stage. ``inline``: None, or (the stage function
    without call-node options, {force Function: its inlinable copy}): those forces (joint
    potentials) are inlined with their stage states into one SX graph, whose Jacobian
    blocks are then symbolic instead of forward sweeps through the calls."""
    m = len(model.inputs)
    nzb, nb2, H, s = S.size1_in(0), S.size1_in(1), S.size1_in(2), tableau.stages
    out = []
    for c, (fun, jf) in enumerate(jforces):
        K = len(jf.exprs)
        Zs = [ca.SX.sym(f"z{k}", nzb) for k in range(K)]
        gs = [ca.SX.sym(f"g{k}", nb2) for k in range(K)]
        hv, i = ca.SX.sym("h", H), ca.SX.sym("i")
        _, t, u, P = _environment(hv, m)
        flat = inline is not None and fun in inline[1]
        if flat:
            fun = inline[1][fun]
        states = [(inline[0] if flat else S)(Z, g, hv) for Z, g in zip(Zs, gs)]
        rows: list = [[] for _ in range(K)]
        for q in range(s):
            args = [v for G, X in states for v in (G[:, q], X[:, q])]
            res = fun(*args, i, ca.vertcat(t + float(tableau.c[q]) * hv[0], u, P))
            for slot, f in enumerate([res] if K == 1 else res):
                rows[slot].append(f[list(comps)])
        ins = [v for Z, g in zip(Zs, gs) for v in (Z, g)]
        out.append((ca.Function(f"joint_force{c}_stages", [*ins, hv, i],
                                [ca.vertcat(*r) for r in rows], CALL), jf))
    return out


def _instance_args(jf, Z, G):
    """(cols, args, i): the slots' bodies per instance (cols[s][e]), the slots' columns of Z
    and G interleaved, and the joints' i (1 x instances)."""
    K = len(jf.exprs)
    cols = [[b[s] for _, b in jf.instances] for s in range(K)]
    return cols, [v for c in cols for v in (Z[:, c], G[:, c])], \
        ca.DM([i for i, _ in jf.instances]).T


def mapped_external_forces(stage_funs, Z, G, hv, N: int):
    """(Fext (s c x N), plan): every body's external stage forces from the mapped joint
    functions (joint_stage_functions) at the bodies' unknowns Z (nzb x N) and g blocks G;
    plan: [(Function, slot columns, slot arguments, i), ...] for external_force_terms."""
    from .family_map import _selection, mapped
    w = stage_funs[0][0].size1_out(0)
    total, plan = ca.MX.zeros(w, N), []
    for fn, jf in stage_funs:
        cols, args, Ij = _instance_args(jf, Z, G)
        res = mapped(fn, len(jf.instances))(*args, hv, Ij)
        for slot, f in enumerate([res] if len(cols) == 1 else res):
            total = total + ca.mtimes(f, _selection(len(jf.instances), cols[slot], N))
        plan.append((fn, cols, args, Ij))
    return total, plan


def external_force_terms(parts, N: int, nzc: int):
    """(F terms, dg1 terms, dp1 terms): the Entries that the joint forces add to J's body
    rows, to dg1/dz and to dP1/dz (hpgen.derive.family_jacobian), each a block product of
    the body step's d(.)/dfext with dFext/dz."""
    from .family_jacobian import _jacobian_function
    from .sparse_blocks import Entries, assemble
    st, Fext, hv = parts["step"], parts["Fext"], parts["hv"]
    nzb, w = st["nz"], Fext.size1()
    terms = []
    for fn, cols, args, Ij in parts["external"]:
        K = len(cols)
        pairs = [(s, 2 * t) for s in range(K) for t in range(K)]
        jf = _jacobian_function(fn, pairs, f"{fn.name()}_blocks")
        out = jf.map(len(cols[0]))(*args, hv, Ij)
        out = [out] if len(pairs) == 1 else out
        for k, (s, t2) in enumerate(pairs):
            places = [(a * w, b * nzb) for a, b in zip(cols[s], cols[t2 // 2])]
            terms.append(Entries.blocks(out[k], jf.sparsity_out(k), places))
    D = assemble(terms, (w * N, nzc))
    return tuple([t] for t in body_fext_products(parts, N, D, "fext", "body_fext_d"))


def body_fext_products(parts, N: int, D, tag: str, name: str, cache=None) -> list:
    """[F term, dg1 term, dP1m term]: the body step's d(F, g1, P1m)/dfext (SX Jacobian
    blocks named <step>_<tag>_blocks, mapped over the bodies) times D = dFext/d(columns),
    one block product each, named name + 0, 1, 2."""
    from .family_jacobian import _jacobian_function
    from .sparse_blocks import block_products
    st, Fext, w = parts["step"], parts["Fext"], parts["Fext"].size1()
    ins = (parts["Z"], parts["G"], parts["Q"], parts["hv"], parts["I"], Fext)
    bf = _jacobian_function(st["F"], [(0, 5)], f"{st['F'].name()}_{tag}_blocks")
    bu = _jacobian_function(st["U"], [(0, 5), (1, 5)], f"{st['U'].name()}_{tag}_blocks")
    outs = [bf.map(N)(*ins), *bu.map(N)(*ins)]
    sps = [bf.sparsity_out(0), *[bu.sparsity_out(k) for k in range(2)]]
    res = []
    for q, (M, sp) in enumerate(zip(outs, sps)):
        a = sp.size1()
        ents = [(range(u * a, (u + 1) * a), [range(u * w, (u + 1) * w)]) for u in range(N)]
        res.append(block_products([(M, sp)], ents, D, f"{name}{q}", cache))
    return res


def mapped_joint_power(jforces, G, X, ef):
    """The joint forces' power, the sum over the joints and slots of <f_s, xi_s>, at the
    bodies' G (nb^2 x N), X (d x N) and ef = (t, u, params) (MX); jforces:
    joint_force_functions."""
    from .family_map import mapped
    total = 0
    for fun, jf in jforces:
        K = len(jf.exprs)
        ins = [ca.SX.sym(f"a{k}", fun.sparsity_in(k)) for k in range(fun.n_in())]
        res = fun(*ins)
        res = [res] if K == 1 else res
        power = sum((ca.dot(res[s], ins[2 * s + 1]) for s in range(K)), ca.SX(0))
        fp = ca.Function(f"{fun.name()}_power", ins, [power], CALL)
        cols, args, Ij = _instance_args(jf, G, X)     # (G, X) per slot, as fun takes
        total = total + ca.sum2(mapped(fp, len(jf.instances))(*args, Ij, ef))
    return total
