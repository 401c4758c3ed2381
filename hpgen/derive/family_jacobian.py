"""The Newton matrix J = dF/dz of a family's mapped step (hpgen.derive.family_map) assembled
from per-body and per-joint Jacobian blocks, with O(N) work and memory.

Each block is one SX function (derived once, its Jacobians by CasADi's SX AD) mapped over
the bodies or a joint group's instances; its outputs are placed into sparse N-sized matrices
by static nonzero indexing, and the chain rule through the step's intermediates is a few
sparse matrix products whose patterns CasADi fixes when the kernel is built. With
z = (Z, lambda, nu) (body unknowns, joint multipliers at the start and at the end of the
step), per body k

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

(Z-blocks block-diagonal over the bodies). The result equals casadi.jacobian of the mapped
residual to round-off, with work and memory proportional to the blocks' nonzeros instead of
CasADi's directional derivatives of the whole mapped step.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

CALL = {"never_inline": True, "jac_penalty": 0}


def _jacobian_function(f, pairs, name):
    """SX Function of f's inputs -> [d out_o / d in_i for (o, i) in pairs] (CasADi's SX AD
    on f's own expression graph, one factory per block, inlined into one function)."""
    args = [ca.SX.sym(f"a{i}", f.sparsity_in(i)) for i in range(f.n_in())]
    outs = [f.factory(f"{name}_{o}_{i}", f.name_in(),
                      [f"jac:{f.name_out(o)}:{f.name_in(i)}"])(*args) for o, i in pairs]
    return ca.Function(name, args, outs, CALL)


def _place(M, sp_blk, places, shape):
    """Sparse MX of ``shape``: the sum of the blocks B_t of M (M = [B_0, B_1, ...], each of
    pattern sp_blk, as a map's output) at the offsets places[t] = (row, col). Blocks at the
    same offset (a body in the same slot of two joints of one group) go to separate layers,
    each a static gather and a sparsity cast."""
    e = sp_blk.nnz()
    br, bc = np.asarray(sp_blk.row()), np.asarray(sp_blk.get_col())
    layers: list = []
    for t, at in enumerate(places):
        for layer in layers:
            if at not in layer:
                layer[at] = t
                break
        else:
            layers.append({at: t})
    out = ca.MX(*shape)
    for layer in layers:
        ts = list(layer.values())
        rows = np.concatenate([places[t][0] + br for t in ts])
        cols = np.concatenate([places[t][1] + bc for t in ts])
        src = np.concatenate([np.arange(t * e, (t + 1) * e) for t in ts])
        order = np.lexsort((rows, cols))            # the pattern's nonzeros in CCS order
        sp = ca.Sparsity.triplet(shape[0], shape[1], rows.tolist(), cols.tolist())
        out = out + ca.sparsity_cast(M.nz[src[order].tolist()], sp)
    return out


def _joint_jacobians(fun, K: int, rows: int):
    """(old, new) SX functions of a joint's row-block function ``fun`` (vec g per slot, i) ->
    (phi, Phi_s): old(g_s.., i) -> Phi_s^T per slot; new(g1_s.., i, nu, V_s..) ->
    dphi/dg1_s per s, d(Phi_s^T nu)/dg1_t per (s, t), Phi_s^T per s, d(sum_s Phi_s V_s)/dg1_s
    per s, Phi_s per s."""
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
    outs = (list(dphi) + [kick[s][t] for s in range(K) for t in range(K)]
            + [out[1 + s].T for s in range(K)] + hid + [out[1 + s] for s in range(K)])
    new = ca.Function(f"{fun.name()}_end_blocks", [*gs, i, nu, *vs], outs, CALL)
    return old, new


def assembled_jacobian(model, funcs, parts) -> ca.MX:
    """J (nz x nz, sparse MX) of the mapped step whose intermediates are ``parts``
    (hpgen.derive.family_map.mapped_step_parts); funcs: hpgen.derive.family._functions."""
    body, _, _, _, jfun, _ = funcs
    joints = model.family.local.joints
    N, db, nb2 = model.family.count, body.d, body.n * body.n
    Z, G, Q, G1, P1, V = (parts[k] for k in ("Z", "G", "Q", "G1", "P1", "V"))
    h, I, Hinv, m, rowoff = parts["h"], parts["I"], parts["Hinv"], parts["m"], parts["rowoff"]
    st = parts["step"]
    nzb = st["nz"]
    zc = nzb * N
    bf = _jacobian_function(st["F"], [(0, 0), (0, 2)], f"{st['F'].name()}_blocks")
    bu = _jacobian_function(st["U"], [(0, 0), (0, 2), (1, 0), (1, 2)],
                            f"{st['U'].name()}_blocks")
    hv = parts["hv"]              # the step vector of an open model, else h
    outs = [*bf.map(N)(Z, G, Q, hv, I), *bu.map(N)(Z, G, Q, hv, I)]
    sps = [bf.sparsity_out(0), bf.sparsity_out(1), *[bu.sparsity_out(k) for k in range(4)]]

    def diag(k, a, b):
        # block t at (t a, t b): the map's nonzeros are already in the CCS order
        return ca.sparsity_cast(outs[k], ca.diagcat(*[sps[k]] * N))
    FZ, FQ = diag(0, nzb, nzb), diag(1, nzb, db)
    GZ, GQ = diag(2, nb2, nzb), diag(3, nb2, db)
    PZ, PQ = diag(4, db, nzb), diag(5, db, db)
    vj = _jacobian_function(parts["velocity"], [(0, 0), (0, 1)], "body_velocity_blocks")
    VG, VP = vj.map(N)(G1, P1, I, Hinv, *([] if parts["e1"] is None else [parts["e1"]]))
    VG = ca.sparsity_cast(VG, ca.diagcat(*[vj.sparsity_out(0)] * N))
    VP = ca.sparsity_cast(VP, ca.diagcat(*[vj.sparsity_out(1)] * N))

    A, B = ca.MX(db * N, m), ca.MX(db * N, m)
    Kg = ca.MX(db * N, nb2 * N)
    Pg, Hg, Hv = ca.MX(m, nb2 * N), ca.MX(m, nb2 * N), ca.MX(m, db * N)
    for key, js in parts["groups"]:
        first = joints[js[0]]
        K, rows = len(first.bodies), len(first.rows)
        old, new = _joint_jacobians(jfun[key], K, rows)
        cols = [[joints[j].bodies[s] for j in js] for s in range(K)]
        Ij = ca.DM([joints[j].value for j in js]).T
        nu_idx = [zc + m + int(rowoff[j]) + r for j in js for r in range(rows)]
        nu = ca.reshape(parts["z"][nu_idx], rows, len(js))
        o_old = old.map(len(js))(*[G[:, c] for c in cols], Ij)
        o_old = [o_old] if K == 1 else o_old
        o_new = new.map(len(js))(*[G1[:, c] for c in cols], Ij, nu, *[V[:, c] for c in cols])
        at = [int(rowoff[j]) for j in js]

        def put(M, k, f, rb, cb, shape):
            return _place(M, f.sparsity_out(k), list(zip(rb, cb)), shape)
        for s in range(K):
            bs = cols[s]
            A = A + put(o_old[s], s, old, [b * db for b in bs], at, (db * N, m))
            Pg = Pg + put(o_new[s], s, new, at, [b * nb2 for b in bs], (m, nb2 * N))
            for t in range(K):
                k = K + s * K + t
                Kg = Kg + put(o_new[k], k, new, [b * db for b in bs],
                              [b * nb2 for b in cols[t]], (db * N, nb2 * N))
            k = K + K * K + s
            B = B + put(o_new[k], k, new, [b * db for b in bs], at, (db * N, m))
            k = 2 * K + K * K + s
            Hg = Hg + put(o_new[k], k, new, at, [b * nb2 for b in bs], (m, nb2 * N))
            k = 3 * K + K * K + s
            Hv = Hv + put(o_new[k], k, new, at, [b * db for b in bs], (m, db * N))

    dG1 = ca.horzcat(GZ, -ca.mtimes(GQ, A), ca.MX(nb2 * N, m))
    dP1 = (ca.horzcat(PZ, -ca.mtimes(PQ, A), ca.MX(db * N, m)) - ca.mtimes(Kg, dG1)
           - ca.horzcat(ca.MX(db * N, zc + m), B))
    dV = ca.mtimes(VG, dG1) + ca.mtimes(VP, dP1)
    dF = ca.horzcat(FZ, -ca.mtimes(FQ, A), ca.MX(zc, m))
    dphi = ca.mtimes(Pg, dG1) / h
    dhid = ca.mtimes(Hg, dG1) + ca.mtimes(Hv, dV)
    return ca.vertcat(dF, dphi, dhid)
