"""A closed family model's step partials (kernel step_partials, hpgen.derive.linearize)
assembled from per-body and per-joint blocks, like its Newton matrix
(hpgen.derive.family_jacobian): O(N) code instead of casadi.jacobian of the perturbed
mapped step.

The chain rule of family_jacobian runs over the columns (z, eta, dp) instead of z, with
s = (eta, dp) entering at the step's inputs (g_k -> g_k (I + eta_k^), p_k -> p_k + dp_k) and
differentiated at s = 0:

    dG/ds   = [d vec(g_k eta_k^)/d eta_k, 0]                          (per body)
    dQ/ds   = [-sum_j d(Phi_{j,k}(g)^T lambda_j)/dg dG/ds, I]        (old-g kicks)
    dF_k, dg1_k, dP1m_k += (.)_g dG/ds + (.)_Q dQ/ds  (+ the joint forces' dFext/dg dG/ds)

and then dG1, dP1, dW and the rows exactly as for J (the joints' terms read dG1, dP1 over
all columns). The output chart is read at the nominal g1: Y_k = vee(g1_k^{-1} g1_k'), so
dY_k = C_k dG1_k with C_k = d vee(g1_k^{-1} X)/dX at X = g1_k (a splitting step: X its
Newton-Schulz step's output of G1, the chain rule through it inside C_k), and

    Fs = dF/d(eta, dp),  Yz = [C dG1/dz; dP1/dz],  Ys = [C dG1/ds; dP1/ds].

Open models keep casadi.jacobian (their partials in the step vector too).
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from .family_calls import CALL
from .family_joint_forces import body_fext_products
from .sparse_blocks import Entries, Sum, assemble, block_products


def _brows(u, w):
    return range(u * w, (u + 1) * w)


def _old_kicks(fun, K: int, rows: int):
    """SX function (g_s.., i, lambda) -> d(Phi_s(g)^T lambda)/dg_t per (s, t) of a joint's
    row-block function fun (vec g per slot, i) -> (phi, Phi_s)."""
    from .family_jacobian import _jacobian_function
    jf = _jacobian_function(fun, [(1 + s, t) for s in range(K) for t in range(K)],
                            f"{fun.name()}_old_blocks")
    gs = [ca.SX.sym(f"g{s}", fun.size1_in(0)) for s in range(K)]
    i, lam = ca.SX.sym("i"), ca.SX.sym("l", rows)
    dPhi = jf(*gs, i)
    dPhi = [dPhi] if K == 1 else dPhi
    db = fun.size2_out(1)
    # dPhi[s K + t]: d vec(Phi_s) / d g_t, vec column-major: row r + rows c is Phi_s[r, c]
    outs = [ca.vertcat(*[ca.mtimes(lam.T, dPhi[s * K + t][c * rows:(c + 1) * rows, :])
                         for c in range(db)]) for s in range(K) for t in range(K)]
    return ca.Function(f"{fun.name()}_old_kick_blocks", [*gs, i, lam], outs, CALL)


def s_terms(model, funcs, parts, xg, spg, xq, spq, nzc: int, cache: dict) -> tuple:
    """(F terms, dg1 terms, dP1m terms) in the columns s = (eta, dp) after the nzc columns
    of z: xg, spg the body step's (F, g1, P1m) blocks in g (maps' outputs and patterns),
    xq, spq those in Q."""
    body, _, _, _, jfun, _ = funcs
    N, db, nb = model.family.count, body.d, body.n
    nb2, d, st = nb * nb, body.d * N, parts["step"]
    nzb = st["nz"]
    ncol = nzc + 2 * d
    gs, eta = ca.SX.sym("g", nb2), ca.SX.sym("eta", db)
    pj = ca.Function("body_perturbed_jac", [gs], [ca.jacobian(
        ca.vec(ca.mtimes(ca.reshape(gs, nb, nb), body.hat(eta))), eta)], CALL)
    dG = Sum([Entries.blocks(pj.map(N)(parts["G"]), pj.sparsity_out(0),
                             [(k * nb2, nzc + k * db) for k in range(N)])], (nb2 * N, ncol))
    joints, z, m, rowoff = model.family.local.joints, parts["z"], parts["m"], parts["rowoff"]
    tQ = [Entries(ca.MX(ca.DM.ones(d, 1)), np.arange(d), nzc + d + np.arange(d))]
    for q, (key, js) in enumerate(parts["groups"]):
        K, rows = len(joints[js[0]].bodies), len(joints[js[0]].rows)
        fk = _old_kicks(jfun[key], K, rows)
        cols = [[joints[j].bodies[s] for j in js] for s in range(K)]
        Ij = ca.DM([joints[j].value for j in js]).T
        at = [int(z.numel() - 2 * m + rowoff[j] + r) for j in js for r in range(rows)]
        o = fk.map(len(js))(*parts["slots"][key]["G"], Ij, ca.reshape(z[at], rows, len(js)))
        o = [o] if K == 1 else o
        for s in range(K):
            xs = [(o[s * K + t], fk.sparsity_out(s * K + t)) for t in range(K)]
            ents = [(_brows(cols[s][e], db), [_brows(cols[t][e], nb2) for t in range(K)])
                    for e in range(len(js))]
            tQ.append(block_products(xs, ents, dG, f"joint_old_kick_dg{q}_{s}", cache,
                                     scale=-1.0))
    dQ = Sum(tQ, (d, ncol))

    def per_body(X, spX, Y, w_out, w_in, name):
        ents = [(_brows(u, w_out), [_brows(u, w_in)]) for u in range(N)]
        return block_products([(X, spX)], ents, Y, name, cache)
    widths = (nzb, nb2, db)
    out = tuple([per_body(xg[k], spg[k], dG, widths[k], nb2, f"body_ds_g{k}"),
                 per_body(xq[k], spq[k], dQ, widths[k], db, f"body_ds_q{k}")]
                for k in range(3))
    if "Fext" in parts:
        for k, t in enumerate(_external_s_terms(parts, N, dG, ncol, cache)):
            out[k].append(t)
    return out


def _external_s_terms(parts, N: int, dG, ncol: int, cache: dict) -> list:
    """The joint forces' terms (F, dg1, dP1m) in s: the body step's d(.)/dfext times
    dFext/dg dG/ds (hpgen.derive.family_joint_forces' stage forces, slot inputs (Z_t, G_t))."""
    from .family_jacobian import _jacobian_function
    Fext, hv = parts["Fext"], parts["hv"]
    w, nb2 = Fext.size1(), parts["G"].size1()
    terms = []
    for q, (fn, cols, args, Ij) in enumerate(parts["external"]):
        K = len(cols)
        pairs = [(s, 2 * t + 1) for s in range(K) for t in range(K)]
        jf = _jacobian_function(fn, pairs, f"{fn.name()}_g_blocks")
        o = jf.map(len(cols[0]))(*args, hv, Ij)
        o = [o] if len(pairs) == 1 else o
        for s in range(K):
            xs = [(o[s * K + t], jf.sparsity_out(s * K + t)) for t in range(K)]
            ents = [(_brows(cols[s][e], w), [_brows(cols[t][e], nb2) for t in range(K)])
                    for e in range(len(cols[0]))]
            terms.append(block_products(xs, ents, dG, f"joint_force_dg{q}_{s}", cache))
    D = Sum(terms, (w * N, ncol))
    return body_fext_products(parts, N, D, "fext_s", "body_fext_ds", cache)


def _chart_jacobian(body, st):
    """SX function vec G1 -> C = d vee(g1^{-1} X)/dX at X = g1 (db x nb^2), g1 = G1 or,
    in a splitting step, its Newton-Schulz step's output (X likewise of G1)."""
    nb = body.n
    X, R = ca.SX.sym("x", nb * nb), ca.SX.sym("r", nb * nb)
    out = (lambda v: v) if st.get("UR") is None else (lambda v: st["NS"](v))  # noqa: E731
    Y = body.vee(ca.mtimes(body.inverse(ca.reshape(R, nb, nb)), ca.reshape(out(X), nb, nb)))
    C = ca.substitute(ca.jacobian(Y, X), R, out(X))
    return ca.Function("body_chart_jac", [X], [C], CALL)


def assembled_partials(model, funcs, parts) -> list:
    """[Fs, Yz, Ys] (sparse MX) of the closed mapped step whose intermediates are ``parts``
    (hpgen.derive.family_map.mapped_step_parts)."""
    from .family_jacobian import _assembly
    body = funcs[0]
    N, db, nb2 = model.family.count, body.d, body.n * body.n
    J, old, new, dG1, dP1 = _assembly(model, funcs, parts, with_s=True)
    nzc, d = J.size1(), db * N
    cf = _chart_jacobian(body, parts["step"])
    tY = block_products([(cf.map(N)(parts["G1"]), cf.sparsity_out(0))],
                        [(_brows(u, db), [_brows(u, nb2)]) for u in range(N)], dG1,
                        "body_chart_dg")
    Ym = assemble([tY, *[t.shifted(d, 0) for t in dP1.terms]], (2 * d, J.size2()))
    outs = [J[:, nzc:], Ym[:, :nzc], Ym[:, nzc:]]
    return ca.graph_substitute(outs, old[1:], new[1:])
