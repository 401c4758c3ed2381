"""The static LU's generated factorization (hpgen.codegen.lu_code): its pivots replayed in
Python give the runtime loop's factors bit for bit, its loops are exact repetitions, its code
does not grow with the chain's length, and the compiled module's runs equal those of the
same kernels.c built with the runtime's loop (-DHPGEN_SLU_LOOP)."""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.abi import STATIC_PIVOT_TOL
from hpgen.codegen import lu_code
from hpgen.codegen.static_lu import static_lu

from conftest import EXAMPLES
from test_sparse_newton import ccs, chain_scene, kkt, slu_solve
from test_sparse_newton import slu_factor as loop_factor


def chain_kkt(rng, n_bodies, d=6, m=3):
    """A chain's RATTLE-like Newton matrix: body blocks (d x d, dense) coupled to their
    neighbours, joint rows (m per joint, zero diagonal block) on bodies i - 1 and i, the
    first joint pinning body 0."""
    nb, nc = d * n_bodies, m * n_bodies
    M = np.zeros((nb + nc, nb + nc))
    for i in range(n_bodies):
        b = slice(d * i, d * (i + 1))
        M[b, b] = np.eye(d) * 3 + 0.3 * rng.standard_normal((d, d))
        rows = slice(nb + m * i, nb + m * (i + 1))
        for j in [i - 1, i] if i else [i]:
            bj = slice(d * j, d * (j + 1))
            M[rows, bj] = rng.standard_normal((m, d))
            M[bj, rows] = rng.standard_normal((d, m))
        if i:
            M[b, d * (i - 1):d * i] = 0.1 * rng.standard_normal((d, d))
    return M


def replay(lu, jnz, n):
    """The generated program's arithmetic in its order (pivots of lu_code.pivots, right-
    looking), on J's nonzeros: the values X, or None at a failed pivot."""
    X = np.zeros(lu.nnz)
    X[list(lu.jmap)] = jnz
    cm = np.array([np.abs(X[lu.colptr[t]:lu.colptr[t + 1]]).max() for t in range(n)])
    for st in lu_code.pivots(lu):
        d = X[st.diag]
        if not (abs(d) > STATIC_PIVOT_TOL * cm[st.k] and np.isfinite(d)):
            return None
        r = 1.0 / d
        X[st.diag] = r
        lo = [X[q] * r for q in st.lower]
        up = [X[q] for q in st.upper]
        X[list(st.lower)] = lo
        for t, a, b in st.ops:
            X[t] -= lo[a] * up[b]
    return X


def jnz_of(M, colind, row):
    return np.concatenate([M[row[colind[c]:colind[c + 1]], c] for c in range(M.shape[1])])


@pytest.mark.parametrize("make", ["kkt", "chain"])
def test_generated_pivots_are_the_loop_bit_for_bit(make):
    rng = np.random.default_rng(11)
    for trial in range(4):
        M = kkt(rng, nb=8, nc=4) if make == "kkt" else chain_kkt(rng, 5)
        n = M.shape[0]
        colind, row = ccs(M)
        lu = static_lu(n, colind, row)
        jnz = jnz_of(M, colind, row)
        X_loop, X_gen = loop_factor(lu, jnz, n), replay(lu, jnz, n)
        assert X_loop is not None and X_gen is not None
        np.testing.assert_array_equal(X_gen, X_loop)
        F = rng.standard_normal(n)
        ref = np.linalg.solve(M, F)
        np.testing.assert_allclose(slu_solve(lu, X_gen, F, n), ref, rtol=0,
                                   atol=1e-12 * np.abs(ref).max())


def test_runs_repeat_exactly_and_cover_every_pivot():
    rng = np.random.default_rng(2)
    M = chain_kkt(rng, 24)
    colind, row = ccs(M)
    lu = static_lu(M.shape[0], colind, row)
    steps = lu_code.pivots(lu)
    plan = lu_code.runs(steps)
    assert [t for t, _, _ in plan] == list(np.cumsum([0] + [p * m for _, p, m in plan])[:-1])
    assert sum(p * m for _, p, m in plan) == len(steps)
    assert any(m > 2 for _, _, m in plan)
    for t, p, m in plan:
        blocks = [np.array(lu_code._block(steps, t + i * p, p)) for i in range(m)]
        for i in range(1, m):
            assert [s.shape for s in steps[t + i * p:t + (i + 1) * p]] == \
                [s.shape for s in steps[t:t + p]]
            np.testing.assert_array_equal(blocks[i] - blocks[i - 1], blocks[1] - blocks[0])


def test_code_does_not_grow_with_the_chain():
    rng = np.random.default_rng(4)
    sizes = []
    for n_bodies in (16, 32, 64):
        M = chain_kkt(rng, n_bodies)
        colind, row = ccs(M)
        lu = static_lu(M.shape[0], colind, row)
        code = lu_code.factor_code(lu)
        assert code is not None
        sizes.append(code.count("-="))
    assert sizes[0] == sizes[1] == sizes[2]


def test_module_runs_equal_the_loop_build(cache_dir):
    """The compiled chain's runs with the generated factorization and with the runtime's
    loop (the same kernels.c, -DHPGEN_SLU_LOOP): the same states bit for bit."""
    chain = EXAMPLES / "pendulum_chain.yaml"
    sc = chain_scene(3)
    runs = []
    for cflags in ((), ("-DHPGEN_SLU_LOOP",)):
        integ = hpgen.compile(chain, parameters={"N": 3}, jacobian="sparse",
                              cache_dir=cache_dir, cflags=cflags)
        assert "HPGEN_SLU_GENERATED 1" in (integ.module_dir / "kernels.c").read_text()
        runs.append(integ.simulate(sc.g0, sc.h, 300, xi0=sc.xi0))
    np.testing.assert_array_equal(runs[0].g, runs[1].g)
    np.testing.assert_array_equal(runs[0].mu, runs[1].mu)


def test_code_beyond_the_cap_keeps_the_loop(monkeypatch):
    """A pattern whose code would exceed MAX_EMITTED_OPS gets none (the runtime's loop)."""
    M = chain_kkt(np.random.default_rng(6), 8)
    colind, row = ccs(M)
    lu = static_lu(M.shape[0], colind, row)
    assert lu_code.factor_code(lu) is not None
    monkeypatch.setattr(lu_code, "MAX_EMITTED_OPS", 10)
    assert lu_code.factor_code(lu) is None
