"""Fasso's kinetic splitting (the ``-fasso`` variants of the splitting catalog).

An asymmetric body's kinetic energy T = sum_i pi_i^2 / (2 D_i) is split as
T = T_sym + T_r, T_sym = |pi|^2 / (2 D_s) + (1/D_a - 1/D_s) pi_a^2 / 2 (a symmetric top,
exact flow: two commuting rotations), T_r = (1/D_b - 1/D_s) pi_b^2 / 2 (one rotation about
b), {b, s} the pair of moments closest in 1/D (hpgen.splitting.structure._fasso_axes).

- The catalog: every table has its variant, same coefficients, kinetic "fasso".
- The pair chosen and the decomposition T_sym + T_r = T (to round-off).
- The schedule: per stage the remainder rotation, the symmetric top, the remainder rotation.
- (Measured orders against the exact free rigid body: test_splitting_compositions; the
  symplectic check with linearize: test_splitting.)
- The guarantees of every splitting scheme, on the heavy top (SO3) and the underwater vehicle
  (SE3): C and Python bitwise equal (also the two-body chain, SO3 x SO3), the symmetric
  potential's momentum to 1e-12 relative,
  the group to 1e-13, lanes bitwise equal to simulate.
- The error constant on the heavy top (I = (1, 5, 6), remainder |1/6 - 1/5| = 1/30): at
  equal h split4-blanes-moan-fasso's error is at most 1/10 of split4-blanes-moan's.
- A symmetric body: the variant is the exact free flow, the same step as the DLM table's.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.splitting import SPLITTING_NAMES, get_splitting
from hpgen.splitting.coefficients import FASSO, TABLE_NAMES
from hpgen.splitting.structure import _fasso_axes

HEAVY_TOP, FREE_BODY = EXAMPLES / "heavy_top.yaml", EXAMPLES / "free_rigid_body.yaml"
UNDERWATER = EXAMPLES / "underwater_vehicle.yaml"
TOP = "split4-blanes-moan-fasso"


def _start(path):
    from hpgen.model import load_model
    sc = load_model(path).scene
    return np.array(sc.g0, dtype=float), sc.xi0, sc.mu0


def test_catalog_has_a_fasso_variant_of_every_table():
    assert SPLITTING_NAMES == TABLE_NAMES + tuple(n + FASSO for n in TABLE_NAMES)
    for name in TABLE_NAMES:
        base, var = get_splitting(name), get_splitting(name + FASSO)
        assert base.kinetic == "dlm" and var.kinetic == "fasso"
        assert (var.halves, var.gammas, var.order, var.adjoint_first) == \
            (base.halves, base.gammas, base.order, base.adjoint_first)


@pytest.mark.parametrize("moments,expected", [((1.0, 5.0, 6.0), (0, 2, 1)),
                                              ((6.0, 1.0, 5.0), (1, 0, 2)),
                                              ((1.0, 1.2, 9.0), (2, 1, 0))])
def test_pair_and_decomposition(moments, expected):
    a, b, s = _fasso_axes(moments)
    assert (a, b, s) == expected
    D = np.array(moments)
    rng = np.random.default_rng(1)
    for pi in rng.normal(size=(5, 3)):
        T = 0.5 * np.sum(pi ** 2 / D)
        Tsym = 0.5 * (pi @ pi / D[s] + (1 / D[a] - 1 / D[s]) * pi[a] ** 2)
        Tr = 0.5 * (1 / D[b] - 1 / D[s]) * pi[b] ** 2
        assert abs(Tsym + Tr - T) <= 4e-16 * T
    # the remainder is the smallest of the three choices of pair
    inv = 1 / D
    assert abs(inv[b] - inv[s]) == min(abs(inv[i] - inv[j]) for i, j in ((0, 1), (0, 2), (1, 2)))


def test_schedule_per_stage():
    from hpgen.derive.lagrangian import lagrangian_function
    from hpgen.model import load_model
    from hpgen.splitting.flows import schedule
    from hpgen.splitting.structure import recognise
    model = load_model(HEAVY_TOP)
    st = recognise(model, lagrangian_function(model))
    assert st.factors[0].fasso == (0, 2, 1)     # I = (1, 5, 6) as ordered by the structure
    s = get_splitting("split6-kahan-li-fasso")
    ops = schedule(st, s, True)
    g = s.gammas[0]
    assert ops[:5] == [("kick", -1, 0, g / 2), ("frem", 0, 2, g / 2), ("fsym", 0, 0, g),
                       ("frem", 0, 2, g / 2), ("kick", -1, 0, g / 2 + s.gammas[1] / 2)]
    assert [sum(o[0] == k for o in ops) for k in ("kick", "frem", "fsym", "rot")] == \
        [10, 18, 9, 0]
    # two bodies: between two kicks each body's remainder / top / remainder, the top merged
    model = load_model(EXAMPLES / "double_body_chain.yaml")
    st = recognise(model, lagrangian_function(model))
    ops = schedule(st, get_splitting("split2-fasso"), True)
    assert [o[:2] for o in ops] == [("kick", -1)] + [
        (kind, k) for k in (0, 1) for kind in ("frem", "fsym", "frem")] + [("kick", -1)]
    assert ops[2][3] == 1.0 and ops[1][3] == 0.5


@pytest.mark.parametrize("path,name", [(HEAVY_TOP, TOP), (UNDERWATER, "split2-fasso"),
                                       (EXAMPLES / "double_body_chain.yaml", "split2-fasso")])
def test_backends_bitwise_equal(compile_model, path, name):
    g0, xi0, mu0 = _start(path)
    runs = [compile_model(path, tableau=name, backend=b).simulate(g0, 0.02, 200, xi0=xi0,
                                                                  mu0=mu0, every=10)
            for b in ("c", "python")]
    assert np.array_equal(runs[0].g, runs[1].g) and np.array_equal(runs[0].mu, runs[1].mu)


@pytest.mark.parametrize("path,name", [(HEAVY_TOP, TOP), (UNDERWATER, "split2-fasso")])
def test_symmetric_momentum_and_group_kept(compile_model, path, name):
    integ = compile_model(path, tableau=name)
    g0, xi0, mu0 = _start(path)
    tr = integ.simulate(g0, 0.05, 2000, xi0=xi0, mu0=mu0, every=20)
    if path == UNDERWATER:             # left-invariant: the whole spatial momentum
        m = np.array([integ.momentum(g, p) for g, p in zip(tr.g, tr.mu)])
        reach = np.abs(tr.g[:, :3, 3]).max() * np.abs(tr.mu).max()
        change, scale = np.abs(m - m[0]).max(), max(np.abs(m).max(), reach)
    else:                              # rotations about the vertical: e3 . R p
        v = np.array([(g @ p)[2] for g, p in zip(tr.g, tr.mu)])
        change, scale = np.abs(v - v[0]).max(), np.abs(tr.mu).max()
    assert change <= 1e-12 * max(1.0, scale), change
    assert max(integ.defect(g) for g in tr.g) <= 1e-13


def test_lanes_bitwise(compile_model):
    integ = compile_model(HEAVY_TOP, tableau=TOP)
    assert integ.engine.backend.lanes > 0
    g0, xi0, _ = _start(HEAVY_TOP)
    mu = integ.legendre(g0, xi0)
    mus = np.array([mu * (1.0 + 0.01 * k) for k in range(11)])
    for threads in (1, 2):
        batch = integ.simulate_batch(g0, 0.05, 60, mu0=mus, every=7, threads=threads)
        for b in (0, 5, 10):
            one = integ.simulate(g0, 0.05, 60, mu0=mus[b], every=7)
            assert one.newton_iterations == 0 == one.jacobians
            assert np.array_equal(batch[b].g, one.g) and np.array_equal(batch[b].mu, one.mu)


def test_error_constant_on_the_heavy_top(compile_model):
    g0, xi0, _ = _start(HEAVY_TOP)
    T = 2.0
    ref = compile_model(HEAVY_TOP, tableau="split8-kahan-li").simulate(
        g0, 0.01, round(T / 0.01), xi0=xi0, every=round(T / 0.01))
    errs = {}
    for name in ("split4-blanes-moan", TOP):
        tr = compile_model(HEAVY_TOP, tableau=name).simulate(g0, 0.1, 20, xi0=xi0, every=20)
        errs[name] = max(np.abs(tr.g[-1] - ref.g[-1]).max(),
                         np.abs(tr.mu[-1] - ref.mu[-1]).max())
    assert errs[TOP] <= errs["split4-blanes-moan"] / 10, errs


def test_symmetric_body_is_the_exact_free_flow(compile_model):
    text = "name: symbody\ngroup: SO3\nlagrangian: 0.5*(2.0*xi[0]**2 + 0.5*xi[1]**2 + " \
           "2.0*xi[2]**2)\n"
    p0 = np.array([0.3, 4.0, -0.7])
    a, b = (compile_model(text, tableau=n).simulate(np.eye(3), 0.5, 40, mu0=p0, every=40)
            for n in ("split2", "split2-fasso"))
    assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
