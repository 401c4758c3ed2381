"""A family's step kernels composed with mapped calls: a fixed number of MX operations
whatever N (hpgen.derive.family derives the functions; this module wires them).

Layout: the bodies' blocks of g are gathered into G (nb^2 x N, column k = vec(g_k)), the
momenta into P (db x N), body k's unknowns are column k of Z (nzb x N, the first nzb N
entries of z); each body function is called once through ``Function.map`` over the columns,
each joint function once per row-block text over its instances (the slot bodies' columns
gathered by one indexing operation each). The impulses sum_j Phi_{j,k}^T lambda_j reach the
bodies by static gathers (hpgen.derive.sparse_blocks.assemble, in the joints' order), the
joint forces' stage forces (hpgen.derive.family_joint_forces, one mapped call per
``joint:`` entry, an input of the body step) by products with constant selection matrices. The result is the StepEquations of
hpgen.derive.family.family_step (same unknowns, rows and outputs), used when every body
shares one Lagrangian and the node velocity is explicit; else None.
"""
from __future__ import annotations

import weakref

import casadi as ca
import numpy as np

from .action import StepEquations
from .sparse_blocks import Entries, assemble
from .family_calls import CALL


# f -> its MX wrapper, alive as long as f: every mapped call of one function object in a
# derivation shares one wrapper (and so its derivative functions), whatever was built before
_WRAPPED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def mapped(f, count: int):
    """``f`` (an SX function) called through an MX wrapper and mapped over ``count`` columns.
    The wrapper's directional derivatives are products with the callee's Jacobian
    (``jac_penalty`` 0), so the map's derivatives reuse one Jacobian function instead of
    an SX forward sweep per number of directions."""
    w = _WRAPPED.get(f)
    if w is None:
        args = [ca.MX.sym(f.name_in(i), f.sparsity_in(i)) for i in range(f.n_in())]
        # jac_penalty only: a never_inline wrapper would expand (the Python backend's SX
        # form) into a call of itself
        w = _WRAPPED[f] = ca.Function(f.name() + "_w", args, f.call(args), f.name_in(),
                                      f.name_out(), {"jac_penalty": 0})
    return w.map(count)


def _joint_maps(fun, K: int, rows: int):
    """The joint's rows as three functions of its slots' vec(g) and its index i: impulses
    Phi_s^T l, (phi, Phi_s(g1)^T nu), and sum_s Phi_s(g1) v_s."""
    nbb = fun.size1_in(0)
    gs = [ca.SX.sym(f"g{s}", nbb) for s in range(K)]
    i, lam = ca.SX.sym("i"), ca.SX.sym("l", rows)
    vs = [ca.SX.sym(f"v{s}", fun.size2_out(1)) for s in range(K)]
    out = fun(*gs, i)
    kicks = [ca.mtimes(out[1 + s].T, lam) for s in range(K)]
    hidden = ca.SX.zeros(rows)
    for s in range(K):
        hidden = hidden + ca.mtimes(out[1 + s], vs[s])
    name = fun.name()
    return (ca.Function(f"{name}_impulse", [*gs, i, lam], kicks, CALL),
            ca.Function(f"{name}_end", [*gs, i, lam], [out[0], *kicks], CALL),
            ca.Function(f"{name}_hidden", [*gs, i, *vs], [hidden], CALL))


def _selection(count: int, cols, N: int):
    """count x N constant: row r has a 1 in column cols[r]."""
    return ca.DM(ca.Sparsity.triplet(count, N, list(range(count)), list(cols)), 1.0)


def _at_columns(M, sp, cols) -> Entries:
    """The blocks of M (a map's output, one column block of pattern sp per instance) at the
    columns cols of a matrix with the blocks' rows: each instance's impulse on its body."""
    return Entries.blocks(M, sp, [(0, int(c)) for c in cols])


def mapped_step(model, funcs, G, P, h, z, xi_hat) -> StepEquations | None:
    """The family step over MX with mapped calls; funcs: hpgen.derive.family._functions;
    G (nb^2 x N), P (db x N), h (1), z (nz) and xi_hat (d) MX."""
    out = mapped_step_parts(model, funcs, G, P, h, z, xi_hat)
    return None if out is None else out[0]


def mapped_step_parts(model, funcs, G, P, h, z, xi_hat):
    """(mapped_step's StepEquations, its intermediates for the block-assembled Jacobian
    (hpgen.derive.family_jacobian): a dict of MX Z, Q, F, G1 (a splitting step's before its
    Newton-Schulz step), P1m, P1, V (columns per body), the
    joint groups and their slots' columns of G, G1, V and their nu (by group), the constants
    I, Hinv and the joint rows' order), or None. An open model's
    h is its step vector hv (hpgen.abi)."""
    from .family_velocity import hessian_inverse
    from .family_open import body_indices, with_env, split_step_vector
    body, lags, keys, steps, jfun, vel_funs = funcs
    hv = h
    h, _, e1 = split_step_vector(model, hv)
    N, db = model.family.count, body.d
    if len(steps) != 1 or not vel_funs or any(f is None for f in vel_funs.values()):
        return None              # no joints (no node velocity function): the composition
    (cls, st), = steps.items()
    nzb, I = st["nz"], body_indices(model, hv)     # the bodies' index inputs
    Z = ca.reshape(z[:nzb * N], nzb, N)
    joints = model.family.local.joints
    m = sum(len(j.rows) for j in joints)
    rowoff = np.cumsum([0] + [len(j.rows) for j in joints])
    groups: dict = {}
    for j, jt in enumerate(joints):
        groups.setdefault((jt.text, jt.index), []).append(j)
    kicks, ends = [], []             # the joints' impulses per slot into their bodies' columns
    plan = []
    for key, js in groups.items():
        first = joints[js[0]]
        k, rows = len(first.bodies), len(first.rows)
        fns = _joint_maps(jfun[key], k, rows)
        cols = [[joints[j].bodies[s] for j in js] for s in range(k)]
        Ij = ca.DM([joints[j].value for j in js]).T
        lam_idx = [int(z.numel() - 2 * m + rowoff[j] + r) for j in js for r in range(rows)]
        lam = ca.reshape(z[lam_idx], rows, len(js))
        nu = ca.reshape(z[[q + m for q in lam_idx]], rows, len(js))
        gs = [G[:, c] for c in cols]
        imp = mapped(fns[0], len(js))(*gs, Ij, lam)
        imp = [imp] if k == 1 else imp
        kicks += [_at_columns(imp[s], fns[0].sparsity_out(s), cols[s]) for s in range(k)]
        plan.append((key, js, fns, cols, Ij, nu, rows, gs))
    Q = P - assemble(kicks, (db, N))
    ext: tuple = ()                  # forces between bodies: the bodies' stage forces
    if st["JS"]:
        from .family_joint_forces import mapped_external_forces
        Fext, external = mapped_external_forces(st["JS"], Z, G, hv, N)
        ext = (Fext,)
    Fr = mapped(st["F"], N)(Z, G, Q, hv, I, *ext)
    if st.get("UR") is None:
        G1, P1m = mapped(st["U"], N)(Z, G, Q, hv, I, *ext)
        G1out = G1
    else:       # a splitting step: its Newton-Schulz step on the output g1 alone
        G1, P1m = mapped(st["UR"], N)(Z, G, Q, hv, I, *ext)
        G1out = mapped(st["NS"], N)(G1)
    phis, rows_of = [], []
    slots = {}                       # the slots' columns, each gathered once
    for key, js, fns, cols, Ij, nu, rows, gs in plan:
        slots[key] = {"G": gs, "G1": [G1[:, c] for c in cols], "nu": nu}
        out = mapped(fns[1], len(js))(*slots[key]["G1"], Ij, nu)
        phis.append(out[0] / h)
        ends += [_at_columns(out[1 + s], fns[1].sparsity_out(1 + s), cols[s])
                 for s in range(len(cols))]
        rows_of.append((js, rows))
    P1 = P1m - assemble(ends, (db, N))
    vel_fn, _, inverse = vel_funs[cls]
    Hinv = mapped(inverse, N)(I) if inverse is not None else ca.DM(np.hstack([
        np.array(hessian_inverse(model, vel_funs[cls], k, None)) for k in range(N)]))
    V = mapped(vel_fn, N)(*with_env([G1, P1, I, Hinv], e1))
    hidden = []
    for key, js, fns, cols, Ij, nu, rows, gs in plan:
        slots[key]["V"] = [V[:, c] for c in cols]
        hidden.append(mapped(fns[2], len(js))(*slots[key]["G1"], Ij, *slots[key]["V"]))
    # joint rows back in file order
    order = [(j, r) for js, rows in rows_of for j in js for r in range(rows)]
    perm = np.argsort([rowoff[j] + r for j, r in order], kind="stable")
    phi = ca.vertcat(*[ca.vec(x) for x in phis])[perm.tolist()]
    hid = ca.vertcat(*[ca.vec(x) for x in hidden])[perm.tolist()]
    margins = mapped(st["M"], N)(Z, hv)
    charts = mapped(st["C"], N)(Z, hv)
    guess = mapped(st["Z"], N)(ca.reshape(xi_hat, db, N), G, P, hv)
    eqs = StepEquations(z, (), ca.vertcat(ca.vec(Fr), phi, hid), G1out, ca.vec(P1),
                        ca.vertcat(ca.vec(guess), ca.MX.zeros(2 * m)), xi_hat,
                        ca.mmin(margins), ca.vec(charts))
    groups_out = [(key, js) for key, js in groups.items()]
    parts = {"z": z, "Z": Z, "G": G, "Q": Q, "F": Fr, "G1": G1, "P1m": P1m, "P1": P1, "V": V, "h": h, "hv": hv, "e1": e1, "I": I,
             "Hinv": Hinv, "groups": groups_out, "slots": slots, "rowoff": rowoff, "perm": perm, "m": m,
             "step": st, "velocity": vel_fn}
    if ext:
        parts.update(Fext=ext[0], external=external)
    return eqs, parts


def mapped_state_kernels(model, lags, keys, body, record_names, force=None,
                         pots=()) -> dict | None:
    """{kernel name: (Function over MX, input names, output names)} for legendre, hessian,
    energy, momentum, defect, observe, velocity_step and (when the scene records only g, mu,
    xi, energy, momentum, defect) record: one mapped call of a per-body function each, the
    sums and maxima over the bodies as reductions. None when the bodies do not share one
    Lagrangian. An open model's kernels of hpgen.abi.OPEN_EXTRA take its step vector hv as a
    last input ``h`` (their t is t_k); with ``force`` (the per-body force, hpgen.derive.
    family_open.body_force_function) the record may hold power and work, <f, xi> summed over
    the bodies; pots: the joint potentials' functions (family_potentials.potential_functions).
    """
    from ..abi import OPEN_EXTRA
    from .family_open import body_indices, index_symbol, with_env, open_layout, \
        split_step_vector
    if len(lags) != 1:
        return None
    (lag_in, _), = lags.values()
    n, d, N = model.group.n, model.group.d, model.family.count
    nb, db = body.n, body.d
    Gs, X, Ps = ca.SX.sym("g", nb, nb), ca.SX.sym("xi", db), ca.SX.sym("p", db)
    I = index_symbol(model)[0]
    lay = open_layout(model)
    E = None if lay is None else ca.SX.sym("e", 1 + lay[1])
    lval = lag_in(*with_env([Gs, X, I], E))
    mu = ca.gradient(lval, X)
    H = ca.jacobian(mu, X)
    vstep = X - ca.solve(H, mu - Ps)
    at0 = lambda e: ca.substitute(e, X, ca.SX.zeros(db))  # noqa: E731
    x0 = at0(vstep)
    # one more Newton step from x0: the solve of d2l/dxi2 (condition up to ~1e4 on chains
    # with frames at the pin) leaves ~1e-11 in xi, the refined residual round-off
    x0 = ca.substitute(vstep, X, x0)
    gvec = ca.vec(Gs)
    fa = ca.Function("body_legendre", with_env([gvec, X, I], E),
                     [mu, ca.densify(ca.vec(H)), ca.dot(mu, X) - lval], CALL)
    fb = ca.Function("body_observe", with_env([gvec, Ps, I], E), [
        body.momentum_map(Gs, Ps), x0, ca.substitute(ca.dot(mu, X) - lval, X, x0)], CALL)
    fd = ca.Function("body_defect", [gvec], [body.group_defect(Gs)], CALL)
    fv = ca.Function("body_velocity_step", with_env([gvec, Ps, X, I], E), [vstep], CALL)
    xi, p = ca.MX.sym("xi", d), ca.MX.sym("p", d)
    gcol = ca.reshape(ca.DM(ca.diagcat(*[ca.DM.ones(nb, nb)] * N).sparsity(), 1.0), n * n, 1)
    gv = ca.MX.sym("g", gcol.sparsity())      # g's block-diagonal nonzeros, body by body
    hcol = ca.reshape(ca.DM(ca.diagcat(*[ca.DM.ones(db, db)] * N).sparsity(), 1.0), d * d, 1)
    G = ca.reshape(ca.sparsity_cast(gv, ca.Sparsity.dense(gv.nnz(), 1)), nb * nb, N)
    Xm, Pm = ca.reshape(xi, db, N), ca.reshape(p, db, N)
    hv = None if lay is None else ca.MX.sym("h", 2 + lay[0] + lay[1])
    Im = ca.DM(np.arange(N)).T if hv is None else body_indices(model, hv)
    ek = None if hv is None else split_step_vector(model, hv)[1]
    mu_, H_, E_ = mapped(fa, N)(*with_env([G, Xm, Im], ek))
    m_, x0_, E0_ = mapped(fb, N)(*with_env([G, Pm, Im], ek))
    e_ = mapped(fd, N)(G)
    v_ = mapped(fv, N)(*with_env([G, Pm, Xm, Im], ek))
    if hv is not None:               # the momentum map without the mapped call's hv input
        fm = ca.Function("body_momentum_map", [gvec, Ps], [body.momentum_map(Gs, Ps)], CALL)
        m_ = mapped(fm, N)(G, Pm)
    energy, defect, E0 = ca.sum2(E_), ca.mmax(e_), ca.sum2(E0_)
    if pots:        # -l_j of the joint potentials
        from .family_potentials import mapped_potential
        lpot = mapped_potential(pots, G, ek)
        energy, E0 = energy - lpot, E0 - lpot
    items = {"g": gv, "mu": p, "xi": xi, "energy": energy, "momentum": ca.vec(m_),
             "defect": defect}
    if force is not None:            # <f, xi> at t_k, body by body
        Ef = ca.SX.sym("e", force.size1_in(3))
        fp = ca.Function("body_power", [gvec, X, I, Ef],
                         [ca.dot(force(gvec, X, I, Ef), X)], CALL)
        m = len(model.inputs)
        ef = ca.vertcat(hv[1], hv[2:2 + m], hv[2 + m:])
        power = ca.sum2(mapped(fp, N)(G, Xm, Im, ef))
        if model.family.local.force.joints:      # and the forces between bodies'
            from .family_joint_forces import joint_force_functions, mapped_joint_power
            power = power + mapped_joint_power(joint_force_functions(model, body), G, Xm, ef)
        items["power"] = items["work"] = power
    res = {"legendre": ([gv, xi], ("g", "xi"), [ca.vec(mu_)], ("mu",)),
           "hessian": ([gv, xi], ("g", "xi"),
                       [ca.sparsity_cast(ca.vec(H_), hcol.sparsity())], ("H",)),
           "energy": ([gv, xi], ("g", "xi"), [energy], ("E",)),
           "momentum": ([gv, p], ("g", "p"), [ca.vec(m_)], ("m",)),
           "defect": ([gv], ("g",), [defect], ("e",)),
           "observe": ([gv, p], ("g", "p"), [ca.vec(x0_), E0, ca.vec(m_), defect],
                       ("xi", "E", "m", "e")),
           "velocity_step": ([gv, p, xi], ("g", "p", "xi"), [ca.vec(v_)], ("xi1",))}
    if all(nm in items for nm in record_names):
        res["record"] = ([gv, p, xi], ("g", "p", "xi"),
                         [ca.vertcat(*[items[nm] for nm in record_names])], ("row",))
    if hv is not None:               # hpgen.abi: these kernels take hv last
        res = {name: ((ins + [hv], nin + ("h",), outs, nout) if name in OPEN_EXTRA
                      else (ins, nin, outs, nout))
               for name, (ins, nin, outs, nout) in res.items()}
    return {name: (ca.Function(name, ins, outs, list(nin), list(nout)), nin, nout)
            for name, (ins, nin, outs, nout) in res.items()}
