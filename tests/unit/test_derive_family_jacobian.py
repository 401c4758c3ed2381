"""The family step's Newton matrix assembled from per-body and per-joint blocks
(hpgen.derive.family_jacobian) against casadi.jacobian of the same mapped residual
(hpgen.derive.family_map): equal pattern, equal values to round-off at a random point, for
interior bodies too (N = 5), and an MX function whose size does not grow with N."""
from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from hpgen.derive.family import _functions
from hpgen.derive.family_jacobian import assembled_jacobian
from hpgen.derive.family_map import mapped_step_parts
from hpgen.model import load_model_text
from hpgen.tableaus import resolve_tableau
from tests.conftest import EXAMPLES

CHAIN = (EXAMPLES / "pendulum_chain.yaml").read_text()
CAPSULES = (EXAMPLES / "capsule_chain.yaml").read_text()     # symmetric links: split2


def functions(n: int, tab: str, rk: str, text: str = CHAIN):
    """(J assembled, J by casadi.jacobian) as Functions of (z, G, P, h)."""
    model = load_model_text(text.replace("{N: 2,", "{N: %d," % n))
    funcs = _functions(model, resolve_tableau(tab), "cay", rk)
    body, steps = funcs[0], funcs[3]
    nzb = next(iter(steps.values()))["nz"]
    m = sum(len(j.rows) for j in model.family.local.joints)
    G, P = ca.MX.sym("G", body.n * body.n, n), ca.MX.sym("P", body.d, n)
    h, z = ca.MX.sym("h"), ca.MX.sym("z", nzb * n + 2 * m)
    eqs, parts = mapped_step_parts(model, funcs, G, P, h, z, ca.MX.sym("xi", body.d * n))
    args = [z, G, P, h]
    return (ca.Function("assembled", args, [assembled_jacobian(model, funcs, parts)]),
            ca.Function("reference", args, [ca.jacobian(eqs.residual, z)]))


def point(n: int, nz: int, seed: int):
    rng = np.random.default_rng(seed)
    G = np.zeros((16, n))
    for k in range(n):
        w = rng.uniform(-0.5, 0.5, 3)
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        g = np.eye(4)
        g[:3, :3] = np.linalg.solve(np.eye(3) - W / 2, np.eye(3) + W / 2)
        g[:3, 3] = rng.uniform(-0.3, 0.3, 3)
        G[:, k] = g.ravel(order="F")
    return [0.3 * rng.standard_normal(nz), G, rng.standard_normal((6, n)), 0.01]


@pytest.mark.parametrize("tab,rk", [("stormer-verlet", "truncated"), ("gauss2", "exact")])
def test_assembled_jacobian_equals_casadi_jacobian(tab, rk):
    n = 5
    fa, fr = functions(n, tab, rk)
    assert fa.sparsity_out(0) == fr.sparsity_out(0)
    args = point(n, fa.size1_in(0), 11)
    A = np.array(ca.densify(fa(*args)))
    R = np.array(ca.densify(fr(*args)))
    assert np.abs(A - R).max() <= 1e-13 * (1.0 + np.abs(R).max())
    # the assembly's work array is a fraction of the directional sweeps'
    assert fa.sz_w() < 0.5 * fr.sz_w()


def test_split_jacobian_equals_casadi_jacobian():
    """split2 (no body unknowns): the hidden rows composed through Phi V_P in the joints'
    functions (no dV) give casadi.jacobian's J to round-off."""
    fa, fr = functions(5, "split2", "truncated", CAPSULES)
    assert fa.sparsity_out(0) == fr.sparsity_out(0)
    args = point(5, fa.size1_in(0), 11)
    A = np.array(ca.densify(fa(*args)))
    R = np.array(ca.densify(fr(*args)))
    assert np.abs(A - R).max() <= 1e-13 * (1.0 + np.abs(R).max())


def test_joint_blocks_fold_the_velocity_with_its_environment():
    """The joints' end blocks with the velocity folded in (hpgen.derive.family_jacobian.
    _joint_jacobians) at a velocity that reads an environment e1 (one input shared by the
    slots): the hidden rows' blocks are the total derivatives of sum_s Phi_s(g) V(g_s, p_s,
    i_s, Hinv_s, e1) in g_s and p_s, to round-off (a toy joint of two slots, random point)."""
    from hpgen.derive.family_jacobian import _jacobian_function, _joint_jacobians
    K, rows, db = 2, 2, 2
    gs, i = [ca.SX.sym(f"g{s}", 3) for s in range(K)], ca.SX.sym("i")
    Phi = [ca.vertcat(ca.horzcat(ca.cos(g[0]), g[1] * g[2]), ca.horzcat(i * g[2], ca.sin(g[1])))
           for g in gs]
    phi = ca.vertcat(gs[0][0] * gs[1][1] - ca.sin(gs[0][2]), gs[1][0] ** 2 + i)
    fun = ca.Function("toy", [*gs, i], [phi, *Phi])
    g, p, ib, hinv, e = (ca.SX.sym(a, n) for a, n in (("g", 3), ("p", db), ("ib", 1),
                                                        ("hinv", db * db), ("e", 2)))
    v = ca.mtimes(ca.reshape(hinv, db, db), p - ca.vertcat(e[0] * g[0] ** 2, ca.sin(e[1] * g[1])))
    vel = ca.Function("velocity", [g, p, ib, hinv, e], [v + ib * e[1]])
    _, new = _joint_jacobians(fun, K, rows, _jacobian_function(vel, [(0, 0), (0, 1)], "vb"))
    ps, ibs, hs = ([ca.SX.sym(f"{a}{s}", n) for s in range(K)]
                   for a, n in (("p", db), ("ib", 1), ("h", db * db)))
    vs = [vel(gs[s], ps[s], ibs[s], hs[s], e) for s in range(K)]
    H = sum((ca.mtimes(Phi[s], vs[s]) for s in range(K)), ca.SX(rows, 1))
    want = [ca.jacobian(H, x) for x in (*gs, *ps)]
    nu = ca.SX.sym("nu", rows)
    got = new(*gs, i, nu, *vs, *ps, *ibs, *hs, e)[2 * K + K * K:]
    x = [*gs, i, nu, *ps, *ibs, *hs, e]
    f = ca.Function("f", x, [ca.densify(y) for y in (*got, *want)])
    rng = np.random.default_rng(2)
    vals = [rng.standard_normal(a.numel()) for a in x]
    out = [np.array(y) for y in f(*vals)]
    for a, b in zip(out[:2 * K], out[2 * K:]):
        assert np.abs(b).max() > 0.1 and np.abs(a - b).max() <= 1e-14 * np.abs(b).max()


def test_assembled_jacobian_does_not_grow_with_the_bodies():
    sizes = [functions(n, "stormer-verlet", "truncated")[0].n_instructions() for n in (3, 6)]
    assert sizes[0] == sizes[1]


def test_entries_at_the_same_place_add_up():
    from hpgen.derive.sparse_blocks import Entries, assemble
    sp = ca.Sparsity.lower(2)
    vals = np.arange(1.0, 1.0 + 3 * sp.nnz())
    M = ca.MX.sym("M", ca.horzcat(*[ca.DM(sp, 1.0)] * 3).sparsity())
    places = [(0, 0), (2, 1), (0, 0)]
    extra = ca.MX.sym("e", 2)
    terms = [Entries.blocks(M, sp, places), Entries(extra, [3, 0], [0, 2])]
    f = ca.Function("f", [M, extra], [assemble(terms, (4, 3))])
    got = np.array(ca.densify(f(ca.DM(M.sparsity(), vals), [10.0, 20.0])))
    want = np.zeros((4, 3))
    for t, (r, c) in enumerate(places):
        block = np.array(ca.densify(ca.DM(sp, vals[3 * t:3 * t + 3])))
        want[r:r + 2, c:c + 2] += block
    want[3, 0] += 10.0
    want[0, 2] += 20.0
    assert np.array_equal(got, want)
    assert f.sparsity_out(0) == ca.Sparsity.triplet(4, 3, [0, 1, 1, 2, 3, 3, 3, 0],
                                                    [0, 0, 1, 1, 1, 2, 0, 2])


@pytest.mark.parametrize("last", [0, 3])
def test_block_products_equal_the_sparse_product(last):
    """sum_e sum_s X_{e,s} Y[rows] at out rows against the same product written with dense
    numpy matrices, at random values; overlapping output rows add up. Y's last entry in
    column 0 makes the slots of entity 2 share a column (one block over the union), in
    column 3 every entity's slots read disjoint columns (a block per slot)."""
    from hpgen.derive.sparse_blocks import _disjoint_slots, assemble, block_products
    rng = np.random.default_rng(3)
    spx = [ca.Sparsity.lower(3), ca.Sparsity.dense(3, 3)]
    ysp = ca.Sparsity.triplet(9, 5, [0, 1, 2, 3, 4, 6, 7, 8, 8], [0, 1, 1, 2, 2, 3, 4, last, 4])
    Y = ca.MX.sym("Y", ysp)
    E = 3
    Ms = [ca.MX.sym(f"M{s}", ca.horzcat(*[ca.DM(sp, 1.0)] * E).sparsity()) for s, sp in
          enumerate(spx)]
    body = [[0, 1], [1, 2], [2, 0]]                # entity e's slots: bodies of 3 rows
    out = [range(0, 3), range(3, 6), range(0, 3)]  # entities 0 and 2 share their rows
    ents = [(out[e], [range(3 * b, 3 * b + 3) for b in body[e]]) for e in range(E)]
    assert _disjoint_slots(Y, [ys for _, ys in ents]) == (last == 3)
    C = assemble([block_products(list(zip(Ms, spx)), ents, Y, "bp")], (6, 5))
    f = ca.Function("f", [*Ms, Y], [C])
    xv = [rng.standard_normal(M.nnz()) for M in Ms]
    yv = rng.standard_normal(ysp.nnz())
    got = np.array(ca.densify(f(*[ca.DM(M.sparsity(), v) for M, v in zip(Ms, xv)],
                                ca.DM(ysp, yv))))
    Yd = np.array(ca.densify(ca.DM(ysp, yv)))
    want = np.zeros((6, 5))
    for e in range(E):
        for s, sp in enumerate(spx):
            X = np.array(ca.densify(ca.DM(sp, xv[s][e * sp.nnz():(e + 1) * sp.nnz()])))
            want[list(out[e])] += X @ Yd[3 * body[e][s]:3 * body[e][s] + 3]
    assert np.abs(got - want).max() <= 1e-14 * np.abs(want).max()


def _called(f) -> set:
    """The names of the functions an MX Function calls (through maps: the mapped ones)."""
    names = set()
    for k in range(f.n_instructions()):
        if f.instruction_id(k) == ca.OP_CALL:
            g = f.instruction_MX(k).which_function()
            names.add(g.name())
            if g.has_function("f"):
                names.add(g.get_function("f").name())
    return names


@pytest.mark.parametrize("n", [2, 3, pytest.param(8, marks=pytest.mark.slow)])
@pytest.mark.parametrize("tab,rk", [("stormer-verlet", "truncated"), ("gauss2", "exact")])
def test_residual_and_jacobian_share_the_forward_evaluation(n, tab, rk):
    """F and J of residual_and_jacobian are the mapped residual and the assembled J bit for
    bit, and the body step's forward functions are not called beside their blocks'."""
    from hpgen.derive.family_jacobian import residual_and_jacobian
    model = load_model_text(CHAIN.replace("{N: 2,", "{N: %d," % n))
    funcs = _functions(model, resolve_tableau(tab), "cay", rk)
    body, steps = funcs[0], funcs[3]
    st = next(iter(steps.values()))
    m = sum(len(j.rows) for j in model.family.local.joints)
    G, P = ca.MX.sym("G", body.n * body.n, n), ca.MX.sym("P", body.d, n)
    h, z = ca.MX.sym("h"), ca.MX.sym("z", st["nz"] * n + 2 * m)
    eqs, parts = mapped_step_parts(model, funcs, G, P, h, z, ca.MX.sym("xi", body.d * n))
    args = [z, G, P, h]
    F, J = residual_and_jacobian(model, funcs, eqs.residual, parts)
    shared = ca.Function("shared", args, [F, J])
    alone = ca.Function("alone", args, [eqs.residual,
                                        assembled_jacobian(model, funcs, parts)])
    assert shared.sparsity_out(1) == alone.sparsity_out(1)
    x = point(n, z.numel(), 5)
    for a, b in zip(shared(*x), alone(*x)):
        assert np.array_equal(np.array(a.nonzeros()), np.array(b.nonzeros()))
    fwd = {st["F"].name() + "_w", st["U"].name() + "_w"}    # their mapped wrappers
    assert not fwd & _called(shared)
    assert fwd <= _called(ca.Function("residual", args, [eqs.residual]))


@pytest.mark.parametrize("scale", [None, -1.0, "h"])
def test_block_products_read_a_sum_in_place(scale):
    """block_products of Y given as a Sum (gathered from the terms' sources, repeated
    positions added, padding zeros where an entity has no entry) equal those of the same Y
    materialized, bit for bit, and the dense product; scale -1 negates, an MX divides."""
    from hpgen.derive.sparse_blocks import Entries, Sum, assemble, block_products
    rng = np.random.default_rng(7)
    spx = [ca.Sparsity.lower(3), ca.Sparsity.dense(3, 3)]
    E = 3
    Ms = [ca.MX.sym(f"M{s}", ca.horzcat(*[ca.DM(sp, 1.0)] * E).sparsity())
          for s, sp in enumerate(spx)]
    # Y (9 x 5) as a sum of two products' Entries and a block, positions overlapping
    a = ca.MX.sym("a", 6)
    b = ca.MX.sym("b", ca.horzcat(*[ca.DM(ca.Sparsity.diag(2), 1.0)] * 2).sparsity())
    terms = [Entries(a, [0, 1, 2, 4, 8, 3], [0, 1, 1, 2, 4, 0], [5, 0, 1, 2, 3, 4]),
             Entries.blocks(b, ca.Sparsity.diag(2), [(1, 1), (6, 3)]),
             Entries(a, [0, 7], [0, 4], [1, 2]).shifted(1, 0)]
    body = [[0, 1], [1, 2], [2, 0]]
    ents = [(range(3 * e, 3 * e + 3), [range(3 * q, 3 * q + 3) for q in body[e]])
            for e in range(E)]
    d = ca.MX.sym("d")
    sc = d if scale == "h" else scale
    Ysum = Sum(terms, (9, 5))
    Ymx = assemble(terms, (9, 5))
    assert Ysum.sparsity() == Ymx.sparsity()
    outs = [assemble([block_products(list(zip(Ms, spx)), ents, Y, "bp", scale=sc)], (9, 5))
            for Y in (Ysum, Ymx)]
    f = ca.Function("f", [*Ms, a, b, d], [*outs, Ymx])
    xv = [rng.standard_normal(M.nnz()) for M in Ms]
    vals = [*[ca.DM(M.sparsity(), v) for M, v in zip(Ms, xv)], rng.standard_normal(6),
            ca.DM(b.sparsity(), rng.standard_normal(b.nnz())), 0.37]
    got_sum, got_mx, Yv = f(*vals)
    assert np.array_equal(np.array(got_sum.nonzeros()), np.array(got_mx.nonzeros()))
    Yd = np.array(ca.densify(Yv))
    want = np.zeros((9, 5))
    for e in range(E):
        for s, sp in enumerate(spx):
            X = np.array(ca.densify(ca.DM(sp, xv[s][e * sp.nnz():(e + 1) * sp.nnz()])))
            want[3 * e:3 * e + 3] += X @ Yd[3 * body[e][s]:3 * body[e][s] + 3]
    want = -want if scale == -1.0 else want / 0.37 if scale == "h" else want
    assert np.abs(np.array(ca.densify(got_sum)) - want).max() <= 1e-14 * np.abs(want).max()
