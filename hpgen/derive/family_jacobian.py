"""The Newton matrix J = dF/dz of a family's mapped step (hpgen.derive.family_map) assembled
from per-body and per-joint Jacobian blocks, with O(N) work and memory.

Each block is one SX function (derived once, its Jacobians by CasADi's SX AD) mapped over
the bodies or a joint group's instances. The chain rule through the step's intermediates is
carried out on the blocks (hpgen.derive.sparse_blocks): every product of a block-diagonal or
per-joint factor with an intermediate is one mapped SX function of small dense blocks (the
intermediate's rows gathered per body or joint), and every sum is a static gather of the
terms' nonzeros, so the generated code has no generic sparse product, projection or
transpose of N-sized matrices. With z = (Z, lambda, nu) (body unknowns, joint multipliers
at the start and at the end of the step), per body k

    Q_k = P_k - sum_j Phi_{j,k}(g)^T lambda_j                      (impulses)
    F_k, g1_k, P1m_k = body step(Z_k, g_k, Q_k)
    P1_k = P1m_k - sum_j Phi_{j,k}(g1)^T nu_j,  V_k = velocity(g1_k, P1_k)
    rows: F_k; phi_j(g1) / h; sum_s Phi_{j,s}(g1) V_s (hidden constraints)

so that, with A = [Phi_{j,k}(g)^T] (d N x m), B = [Phi_{j,k}(g1)^T] and K = d(sum_j
Phi_{j,k}(g1)^T nu_j)/d g1,

    dQ/dz  = [0, -A, 0]
    dg1/dz = [g1_Z, g1_Q dQ/dz], dP1/dz = [P1m_Z, P1m_Q dQ/dz] - K dg1/dz - [0, 0, B]
    dV/dz  = V_g dg1/dz + V_P dP1/dz
    J = [F_Z, F_Q dQ/dz; dphi/dg1 dg1/dz / h; dhid/dg1 dg1/dz + dhid/dV dV/dz]

(Z-blocks block-diagonal over the bodies). With forces between bodies the body step also
takes its stage forces Fext(Z) (hpgen.derive.family_joint_forces.external_force_terms adds
F_fext, g1_fext, P1m_fext times dFext/dz to J, dg1/dz, dP1/dz). A splitting step (no body
unknowns) composes the hidden rows' dhid/dV dV = Phi_s (V_g dg1 + V_P dP1) inside the joints'
functions (Phi_s V_g added to dhid/dg1_s, Phi_s V_P times dP1; an open model's environment e1
at the step's end, an input of V, is one more input of those functions, shared by the
slots), so that dV is not formed: the hidden rows' last blocks multiply dW/dz, with W = V
(W = P1 in a splitting step). The result equals casadi.jacobian of the mapped residual to
round-off, with work and memory proportional to the blocks' nonzeros instead of
CasADi's directional derivatives of the whole mapped step. In the fused F and J
(residual_and_jacobian) the body step's forward values come from the blocks' own calls.
"""
from __future__ import annotations

import casadi as ca

from .sparse_blocks import Entries, Sum, assemble, block_products
from .family_calls import CALL


def _jacobian_function(f, pairs, name, nominal=()):
    """SX Function of f's inputs -> [d out_o / d in_i for (o, i) in pairs] and then f's
    outputs ``nominal`` (indices of column outputs; CasADi's SX AD on f's own expression
    graph). The blocks of the column outputs come from one factory, so that they share f's
    forward evaluation and their common subexpressions (the nominal outputs are that
    evaluation's, the same expressions as f's); a matrix output's blocks one factory each
    (CasADi's factory refuses several for a matrix)."""
    args = [ca.SX.sym(f"a{i}", f.sparsity_in(i)) for i in range(f.n_in())]
    groups: dict = {}
    for o, i in pairs:
        groups.setdefault(("c",) if f.size2_out(o) == 1 else (o, i), []).append((o, i))
    if nominal:
        groups.setdefault(("c",), [])
    blocks = {}
    for key, group in groups.items():
        extra = [("nom", o) for o in nominal] if key == ("c",) else []
        names = [f"jac:{f.name_out(o)}:{f.name_in(i)}" for o, i in group]
        jf = f.factory(f"{name}_{'_'.join(map(str, key))}", f.name_in(),
                       names + [f.name_out(o) for _, o in extra])
        out = jf(*args)
        blocks.update(zip(group + extra, [out] if len(group + extra) == 1 else out))
    return ca.Function(name, args, [blocks[pair] for pair in pairs]
                       + [blocks[("nom", o)] for o in nominal], CALL)


def _joint_jacobians(fun, K: int, rows: int, vel=None):
    """(old, new) SX functions of a joint's row-block function ``fun`` (vec g per slot, i) ->
    (phi, Phi_s): old(g_s.., i) -> Phi_s^T per slot; new(g1_s.., i, nu, V_s..) ->
    dphi/dg1_s per s, d(Phi_s^T nu)/dg1_t per (s, t), -Phi_s^T per s, d(sum_s Phi_s V_s)/dg1_s
    per s, Phi_s per s. With ``vel`` (the bodies' velocity blocks, (V_g, V_P) of (g1, P1, i,
    Hinv[, e1])) new also takes P1_s.., i_s.., Hinv_s.. (and an open model's environment e1,
    one input shared by the slots) and composes the hidden rows through V:
    d(sum_s Phi_s V_s)/dg1_s + Phi_s V_g,s per s and Phi_s V_P,s (instead of Phi_s) per s."""
    nbb, db = fun.size1_in(0), fun.size2_out(1)
    jf = _jacobian_function(fun, [(0, s) for s in range(K)]
                            + [(1 + s, t) for s in range(K) for t in range(K)],
                            f"{fun.name()}_blocks")
    gs = [ca.SX.sym(f"g{s}", nbb) for s in range(K)]
    i = ca.SX.sym("i")
    out = fun(*gs, i)
    old = ca.Function(f"{fun.name()}_force_blocks", [*gs, i],
                      [out[1 + s].T for s in range(K)], CALL)
    nu = ca.SX.sym("nu", rows)
    vs = [ca.SX.sym(f"v{s}", db) for s in range(K)]
    jac = jf(*gs, i)
    dphi, dPhi = jac[:K], jac[K:]
    # dPhi[s K + t]: d vec(Phi_s) / d g1_t, vec column-major: row r + rows c is Phi_s[r, c]
    kick = [[ca.vertcat(*[ca.mtimes(nu.T, dPhi[s * K + t][c * rows:(c + 1) * rows, :])
                          for c in range(db)]) for t in range(K)] for s in range(K)]
    hid = [sum((vs[s][c] * dPhi[s * K + t][c * rows:(c + 1) * rows, :]
                for s in range(K) for c in range(db)), ca.SX(rows, nbb)) for t in range(K)]
    last, extra, env = [out[1 + s] for s in range(K)], [], []
    if vel is not None:
        extra = [ca.SX.sym(f"{a}{s}", vel.sparsity_in(q)) for q, a in ((1, "p"), (2, "i"),
                                                                      (3, "hinv"))
                 for s in range(K)]
        env = [ca.SX.sym("e1", vel.sparsity_in(4))] if vel.n_in() > 4 else []
        for s in range(K):
            vg, vp = vel(gs[s], *extra[s::K], *env)
            hid[s] = hid[s] + ca.mtimes(out[1 + s], vg)
            last[s] = ca.mtimes(out[1 + s], vp)
    outs = (list(dphi) + [kick[s][t] for s in range(K) for t in range(K)]
            + [-out[1 + s].T for s in range(K)] + hid + last)
    new = ca.Function(f"{fun.name()}_end_blocks", [*gs, i, nu, *vs, *extra, *env], outs, CALL)
    return old, new


def assembled_jacobian(model, funcs, parts) -> ca.MX:
    """J (nz x nz, sparse MX) of the mapped step whose intermediates are ``parts``
    (hpgen.derive.family_map.mapped_step_parts); funcs: hpgen.derive.family._functions."""
    J, old, new = _assembly(model, funcs, parts)
    return ca.graph_substitute([J], old[1:], new[1:])[0]


def residual_and_jacobian(model, funcs, residual, parts) -> tuple:
    """(F, J): the mapped step's ``residual`` (its StepEquations') and assembled_jacobian,
    with the body step's forward values (F, g1, P1m) taken from the Jacobian blocks' calls,
    which evaluate them anyway: the same expressions, one evaluation per body instead of
    two."""
    J, old, new = _assembly(model, funcs, parts)
    F, J = ca.graph_substitute([residual, J], old, new)
    return F, J


def _assembly(model, funcs, parts, with_s: bool = False):
    """(J, [F, G1, P1m] of parts, the same values from the blocks' calls); ``with_s``: the
    columns (z, eta, dp) (hpgen.derive.family_partials), and dG1, dP1 (Sums) after those."""
    body, _, _, _, jfun, _ = funcs
    joints = model.family.local.joints
    N, db, nb2 = model.family.count, body.d, body.n * body.n
    Z, G, Q, G1, P1, V = (parts[k] for k in ("Z", "G", "Q", "G1", "P1", "V"))
    h, I, Hinv, m, rowoff = parts["h"], parts["I"], parts["Hinv"], parts["m"], parts["rowoff"]
    st = parts["step"]
    nzb = st["nz"]
    zc = nzb * N
    sx = "_s" if with_s else ""     # with s: the body step's blocks in g too (appended)
    bf = _jacobian_function(st["F"], [(0, 0), (0, 2)] + [(0, 1)] * with_s,
                            f"{st['F'].name()}_blocks{sx}", (0,))
    # a splitting step's G1 is its g1 before the Newton-Schulz step (hpgen.derive.family_split)
    bu = _jacobian_function(st["U"] if st.get("UR") is None else st["UR"],
                            [(0, 0), (0, 2), (1, 0), (1, 2)] + [(0, 1), (1, 1)] * with_s,
                            f"{st['U'].name()}_blocks{sx}", (0, 1))
    hv = parts["hv"]              # the step vector of an open model, else h
    ext = (parts["Fext"],) if "Fext" in parts else ()  # forces between bodies
    of, ou = bf.map(N)(Z, G, Q, hv, I, *ext), bu.map(N)(Z, G, Q, hv, I, *ext)
    nf, nu_ = 2 + with_s, 4 + 2 * with_s
    outs = [*of[:nf], *ou[:nu_]]
    forward = ([parts["F"], parts["G1"], parts["P1m"]], [of[nf], ou[nu_], ou[nu_ + 1]])
    sp = [bf.sparsity_out(k) for k in range(nf)] + [bu.sparsity_out(k) for k in range(nu_)]
    if with_s:                        # outs: F_Z, F_Q, g1_Z, g1_Q, P1m_Z, P1m_Q, F_g, g1_g, P1m_g
        outs, sp = ([v[0], v[1], v[3], v[4], v[5], v[6], v[2], v[7], v[8]] for v in (outs, sp))

    def diag(k):
        # body t's block at (t a, t b): the map's nonzeros are already in the CCS order
        return Entries.of(ca.sparsity_cast(outs[k], ca.diagcat(*[sp[k]] * N)))
    vj = _jacobian_function(parts["velocity"], [(0, 0), (0, 1)], "body_velocity_blocks")
    # a splitting step (no unknowns per body): the hidden rows compose Phi V_P in the joints'
    # functions and read dP1, so that dV is not formed (an open model's e1 passed through)
    fold = st.get("UR") is not None and nzb == 0
    env = [] if parts["e1"] is None else [parts["e1"]]   # one column, repeated by the maps

    def body_cols(M, cols):           # the columns of body blocks cols of M (w columns each)
        w = M.size2() // N
        return M[:, [c * w + q for c in cols for q in range(w)]]

    def brows(u, w):                  # body u's rows in a matrix of w rows per body
        return range(u * w, (u + 1) * w)

    def per_body(M, sp, w_out, w_in):
        return [(M, sp)], [(brows(u, w_out), [brows(u, w_in)]) for u in range(N)]

    nzc = zc + 2 * m                                      # the columns of J
    ncol = nzc + 2 * N * db if with_s else nzc
    tA, tB = [], []
    kg, pg, hg, hw = [], [], [], []     # (xs, entities) of the joints' products
    for key, js in parts["groups"]:
        first = joints[js[0]]
        K, rows = len(first.bodies), len(first.rows)
        old, new = _joint_jacobians(jfun[key], K, rows, vj if fold else None)
        cols = [[joints[j].bodies[s] for j in js] for s in range(K)]
        Ij = ca.DM([joints[j].value for j in js]).T
        sl = parts["slots"][key]
        o_old = old.map(len(js))(*sl["G"], Ij)
        o_old = [o_old] if K == 1 else o_old
        extra = ([body_cols(M, c) for M in (P1, I, Hinv) for c in cols] + env if fold else [])
        o_new = new.map(len(js))(*sl["G1"], Ij, sl["nu"], *sl["V"], *extra)
        at = [int(rowoff[j]) for j in js]
        jrows = [range(a, a + rows) for a in at]

        def out(k):
            return (o_new[k], new.sparsity_out(k))
        for s in range(K):
            bs = cols[s]
            tA.append(Entries.blocks(o_old[s], old.sparsity_out(s),
                                     [(b * db, a) for b, a in zip(bs, at)]))
            k = K + K * K + s
            tB.append(Entries.blocks(o_new[k], new.sparsity_out(k),
                                     [(b * db, zc + m + a) for b, a in zip(bs, at)]))
            # d(Phi_s^T nu)/d g1 of the joint's bodies, into body b(j, s)'s rows of dP1
            kg.append(([out(K + s * K + t) for t in range(K)],
                       [(brows(cols[s][e], db), [brows(cols[t][e], nb2) for t in range(K)])
                        for e in range(len(js))]))

        def of_slots(w):              # each joint's rows from its slots' body rows
            return [(jrows[e], [brows(cols[s][e], w) for s in range(K)])
                    for e in range(len(js))]
        pg.append(([out(s) for s in range(K)], of_slots(nb2)))
        hg.append(([out(2 * K + K * K + s) for s in range(K)], of_slots(nb2)))
        hw.append(([out(3 * K + K * K + s) for s in range(K)], of_slots(db)))
    A = Sum(tA, (db * N, m))

    def times_A(k, w):                # -(X_body A) at the lambda columns; A's rows per body
        t = block_products(*per_body(outs[k], sp[k], w, db), A,  # gathered once (cache)
                           f"{st['F'].name()}_dA{k}{sx}", cache, scale=-1.0)
        return t.shifted(0, zc)

    # the chain rule: block products (mapped SX) and sums of Entries (static gathers; the
    # intermediates as Sum, read by the products' gathers without being materialized)
    cache: dict = {}
    tE: tuple = ([], [], [])           # the joint forces' terms in F, dg1, dP1
    if ext:
        from .family_joint_forces import external_force_terms
        tE = external_force_terms(parts, N, nzc)
    if with_s:                         # the terms in the columns s (eta, dp)
        from .family_partials import s_terms
        tS = s_terms(model, funcs, parts, outs[6:], sp[6:], outs[1::2][:3], sp[1::2][:3],
                     nzc, cache)
        tE = tuple(a + b for a, b in zip(tE, tS))
    dG1 = Sum([diag(2), times_A(3, nb2), *tE[1]], (nb2 * N, ncol))
    tKg = [block_products(xs, ents, dG1, f"joint_kick_dg{q}{sx}", cache, scale=-1.0)
           for q, (xs, ents) in enumerate(kg)]
    dP1 = Sum([diag(4), times_A(5, db), *tKg, *tB, *tE[2]], (db * N, ncol))
    # with s, the rows of F in the columns s alone (Fs; their z columns are J's kernel's)
    dG1r, dP1r = (dG1.columns_from(nzc), dP1.columns_from(nzc)) if with_s else (dG1, dP1)
    if fold:                         # the joints' last blocks are Phi V_P: W = P1
        dW = dP1r
    else:                            # W = V
        vg, vp = vj.map(N)(G1, P1, I, Hinv, *env)
        dW = Sum([block_products(*per_body(vg, vj.sparsity_out(0), db, nb2), dG1r,
                                 f"vel_dg{sx}"),
                  block_products(*per_body(vp, vj.sparsity_out(1), db, db), dP1r,
                                 f"vel_dp{sx}")], (db * N, ncol))

    def joint_rows(plan, Y, what, row0, scale=None):
        ts = [block_products(xs, ents, Y, f"joint_{what}{q}{sx}", cache, scale) for q, (xs, ents)
              in enumerate(plan)]
        return [t.shifted(row0, 0) for t in ts]
    dphi = joint_rows(pg, dG1r, "phi", zc, h)
    body = ([t.columns_from(nzc) for t in tE[0]] if with_s
            else [diag(0), times_A(1, nzb), *tE[0]])
    J = assemble([*body, *dphi, *joint_rows(hg, dG1r, "hg", zc + m),
                  *joint_rows(hw, dW, "hv", zc + m)], (nzc, ncol))
    return (J, *forward, dG1, dP1) if with_s else (J, *forward)
