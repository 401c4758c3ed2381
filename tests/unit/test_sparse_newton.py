"""The sparse Newton matrix (compile option jacobian="sparse"; hpgen.derive.sparse_jacobian,
hpgen.codegen.sparse, the sparse QR of hpgen/runtime/c/hpgen_linalg.c, hpgen.runtime.sparse)
against the dense one on the pendulum chain, C and Python backends.

Tolerances: both storages solve the same Newton equations to Newton's stop (|dz| <= 1e-14
(1 + |z|), or a simplified-Newton error estimate 100 times below that), so two runs differ by
a few 1e-14 per step; over 500 steps of a (locally) non-expanding flow that sums to at most
500 * 1e-13 = 5e-11, the bound used. A wrong factorization (a wrong pattern, a lost column)
gives O(h) = O(1e-3) differences at the first step.
"""
from __future__ import annotations

import dataclasses

import casadi as ca
import numpy as np
import pytest

import hpgen
from hpgen.abi import STATIC_PIVOT_TOL
from hpgen.api import read_model_text
from hpgen.codegen.static_lu import static_lu
from hpgen.derive import SPARSE_MIN_NZ, sparse_jacobian
from hpgen.model import load_model_text
from hpgen.model.overrides import apply_overrides
from hpgen.runtime.newton import NewtonOptions
from hpgen.runtime.sparse import SparseFactors, sparse_solver

from conftest import EXAMPLES

CHAIN = EXAMPLES / "pendulum_chain.yaml"
STEPS = 500
TOL = STEPS * 1e-13
NS = [2, pytest.param(3, marks=pytest.mark.slow)]


def chain_scene(n):
    text = apply_overrides(read_model_text(str(CHAIN)), {"N": n}, file=str(CHAIN))
    return load_model_text(text, filename=str(CHAIN)).scene


@pytest.fixture(scope="module")
def chain(cache_dir):
    """chain(n, storage, backend) -> Integrator of the N-link chain (cached per module)."""
    made = {}

    def get(n, storage, backend="c", cflags=None):
        key = (n, storage, backend, cflags)
        if key not in made:
            made[key] = hpgen.compile(CHAIN, parameters={"N": n}, jacobian=storage,
                                      backend=backend, cache_dir=cache_dir, cflags=cflags)
        return made[key]
    return get


def float_arrays(obj):
    """The float arrays of a run's result (dataclass fields, tuples, lists, dicts), in order."""
    if isinstance(obj, np.ndarray):
        return [obj] if obj.dtype.kind == "f" else []
    if dataclasses.is_dataclass(obj):
        return [a for f in dataclasses.fields(obj) if f.compare
                for a in float_arrays(getattr(obj, f.name))]
    if isinstance(obj, dict):
        return [a for k in sorted(obj, key=str) for a in float_arrays(obj[k])]
    if isinstance(obj, (list, tuple)):
        return [a for x in obj for a in float_arrays(x)]
    return []


def max_deviation(a, b) -> float:
    xs, ys = float_arrays(a), float_arrays(b)
    assert len(xs) == len(ys) and xs
    dev = 0.0
    for x, y in zip(xs, ys):
        assert x.shape == y.shape
        assert np.isfinite(x).all() and np.isfinite(y).all()
        if x.size:
            dev = max(dev, float(np.abs(x - y).max()))
    return dev


# ---- the rule -------------------------------------------------------------------------------

def test_rule_keeps_small_or_dense_steps_dense():
    banded = ca.SX(ca.Sparsity.banded(SPARSE_MIN_NZ, 2))
    assert sparse_jacobian(banded, None)
    assert not sparse_jacobian(ca.SX(ca.Sparsity.banded(SPARSE_MIN_NZ - 1, 2)), None)
    assert not sparse_jacobian(ca.SX(ca.Sparsity.dense(SPARSE_MIN_NZ, SPARSE_MIN_NZ)), None)
    assert sparse_jacobian(ca.SX(ca.Sparsity.dense(4, 4)), "sparse")
    assert not sparse_jacobian(banded, "dense")


def test_unknown_storage_is_refused():
    with pytest.raises(hpgen.ModelError, match="option jacobian"):
        hpgen.compile(CHAIN, jacobian="banded")


def test_sparse_module_layout(chain):
    dense, sparse = chain(2, None), chain(2, "sparse")
    assert dense.meta["jacobian"] == {"storage": "dense"}   # the rule: nz = 24 stays dense
    jac = sparse.meta["jacobian"]
    assert jac["storage"] == "sparse"
    nz = sparse.meta["nz"]
    assert len(jac["colind"]) == nz + 1 and jac["colind"][-1] == len(jac["row"]) < nz * nz // 2
    c_dense = (dense.module_dir / "kernels.c").read_text()
    c_sparse = (sparse.module_dir / "kernels.c").read_text()
    assert "#define HPGEN_SPARSE 0" in c_dense and "casadi_qr" not in c_dense
    assert "#define HPGEN_SPARSE 1" in c_sparse and "hpgen_sp_pc[]" in c_sparse
    # the public jacobian kernel stays dense column-major, zero outside the pattern
    sc = chain_scene(2)
    g = np.asarray(sc.g0, dtype=float).ravel(order="F")
    p = dense.legendre(sc.g0, sc.xi0)
    z = np.linspace(-0.3, 0.4, nz)
    J = dense.kernel("jacobian", z, g, p, [sc.h])[0]
    mask = np.zeros(nz * nz, dtype=bool)
    for c in range(nz):
        mask[np.asarray(jac["row"][jac["colind"][c]:jac["colind"][c + 1]]) + c * nz] = True
    assert not J[~mask].any()
    for backend in ("c", "python"):
        Js = chain(2, "sparse", backend).kernel("jacobian", z, g, p, [sc.h])[0]
        np.testing.assert_allclose(Js, J, rtol=0, atol=1e-14 * np.abs(J).max())


def test_loader_refuses_a_bad_pattern(chain, tmp_path):
    import json
    from hpgen.runtime import read_meta
    meta = json.loads((chain(2, "sparse").module_dir / "meta.json").read_text())
    read_meta(chain(2, "sparse").module_dir)
    nz = meta["nz"]
    for bad in ({"storage": "banded"}, {"storage": "sparse", "colind": [0] * nz, "row": []},
                dict(meta["jacobian"], row=[nz] + meta["jacobian"]["row"][1:])):
        (tmp_path / "meta.json").write_text(json.dumps(dict(meta, jacobian=bad)))
        with pytest.raises(hpgen.ModelError, match="jacobian") as info:
            read_meta(tmp_path)
        assert "\n" not in str(info.value)


# ---- the runs -------------------------------------------------------------------------------

@pytest.mark.parametrize("n", NS)
@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("simplified", [False, True])
def test_sparse_agrees_with_dense(chain, n, backend, simplified):
    sc = chain_scene(n)
    opts = NewtonOptions(simplified=simplified)
    ref = chain(n, "dense").simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, newton=opts)
    run = chain(n, "sparse", backend).simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, newton=opts)
    assert run.error is None and len(run.t) == STEPS + 1
    assert max_deviation(run.g, ref.g) <= TOL and max_deviation(run.mu, ref.mu) <= TOL
    # the same Newton, plus the sparse path's rate-based stop (hpgen_sparse_converged): it
    # ends at the round-off floor without waiting for |dz| to stagnate, never later
    assert run.newton_iterations <= 1.05 * ref.newton_iterations
    assert run.newton_iterations >= 0.5 * ref.newton_iterations
    if simplified:
        assert run.jacobians < 0.5 * run.newton_iterations     # the factors are reused


def run_kinds(integ, sc):
    g0, h, x0 = sc.g0, sc.h, {"xi0": sc.xi0}
    batch = {"xi0": np.stack([np.asarray(sc.xi0) * (1 + 0.01 * b) for b in range(3)])}
    kinds = {
        "step": lambda: integ.step(g0, integ.legendre(g0, sc.xi0), h),
        "record": lambda: integ.record(g0, h, 60, every=3, **x0),
        "stream": lambda: list(integ.stream(g0, h, 60, every=3, chunk=17, **x0)),
        "backward": lambda: integ.simulate(g0, -h, 60, every=3, **x0),
        "linearize": lambda: integ.linearize(integ.simulate(g0, h, 8, **x0)),
    }
    if getattr(sc, "section_every_t", None) is not None:
        kinds["stroboscopic"] = lambda: integ.sections(g0, h, 300, every_t=sc.section_every_t,
                                                       **x0)
    if integ.backend == "c":
        kinds["simulate_batch"] = lambda: integ.simulate_batch(g0, h, 60, every=3, threads=2,
                                                               **batch)
        kinds["record_batch"] = lambda: integ.record_batch(g0, h, 60, every=3, threads=2,
                                                           **batch)
    return kinds


@pytest.mark.parametrize("backend", ["c", "python"])
def test_every_run_kind_on_a_sparse_module(chain, backend):
    sc = chain_scene(2)
    ref = run_kinds(chain(2, "dense"), sc)
    got = run_kinds(chain(2, "sparse", backend), sc)
    assert set(got) <= set(ref)
    for kind, run in got.items():
        assert max_deviation(run(), ref[kind]()) <= TOL, kind


@pytest.mark.parametrize("simplified", [False, True])
def test_qr_takes_over_where_a_static_pivot_fails(chain, simplified):
    """Built with a pivot threshold no pivot passes, every J of the run goes to the QR: the
    same run to round-off, by other operations than the static LU's."""
    sc = chain_scene(2)
    opts = NewtonOptions(simplified=simplified)
    ref = chain(2, "dense").simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, newton=opts)
    lu = chain(2, "sparse").simulate(sc.g0, sc.h, STEPS, xi0=sc.xi0, newton=opts)
    qr = chain(2, "sparse", cflags=("-DHPGEN_STATIC_PIVOT_TOL=1e300",)).simulate(
        sc.g0, sc.h, STEPS, xi0=sc.xi0, newton=opts)
    assert max_deviation(qr.g, ref.g) <= TOL and max_deviation(qr.mu, ref.mu) <= TOL
    assert not np.array_equal(qr.g, lu.g)


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("simplified", [False, True])
def test_singular_jacobian_is_a_convergence_error(chain, backend, simplified):
    """At g = 0 the constraint rows of J vanish: J is singular, F finite. The step fails as
    Newton's NONFINITE (a singular Jacobian) after one iterate, with a finite residual."""
    sc = chain_scene(2)
    integ = chain(2, "sparse", backend)
    p = integ.legendre(sc.g0, sc.xi0)
    with pytest.raises(hpgen.ConvergenceError, match="singular Jacobian") as info:
        integ.step(np.zeros_like(np.asarray(sc.g0, dtype=float)), p, sc.h,
                   newton=NewtonOptions(simplified=simplified))
    assert info.value.iterations == 1 and np.isfinite(info.value.residual)


# ---- the Python backend's solver ----------------------------------------------------------

def ccs(M):
    """(colind, row) of the nonzeros of M."""
    colind, row = [0], []
    for c in range(M.shape[1]):
        row += np.flatnonzero(M[:, c]).tolist()
        colind.append(len(row))
    return colind, row


def kkt(rng, nb=4, nc=2):
    """An unsymmetric saddle-point matrix [[A, B], [C, 0]] (zero diagonal block)."""
    M = np.zeros((nb + nc, nb + nc))
    M[:nb, :nb] = np.eye(nb) * 3 + 0.3 * rng.standard_normal((nb, nb))
    M[:nb, nb:] = rng.standard_normal((nb, nc))
    M[nb:, :nb] = rng.standard_normal((nc, nb))
    M[np.abs(M) < 0.2] = 0.0
    return M


def test_python_sparse_solver():
    rng = np.random.default_rng(3)
    M = kkt(rng)
    n = M.shape[0]
    lin = sparse_solver(n, *ccs(M))
    F = rng.standard_normal(n)
    J = M.ravel(order="F").tolist()
    dz, kept = lin.factor_solve(J, F.tolist(), True)
    ref = np.linalg.solve(M, F)
    np.testing.assert_allclose(dz, ref, rtol=0, atol=1e-13 * np.abs(ref).max())
    np.testing.assert_allclose(lin.apply(kept, F.tolist()), dz, rtol=0, atol=1e-15)
    # a kept factorization saved as its nonzeros (a checkpoint) gives the same solve
    assert isinstance(kept, SparseFactors)
    assert lin.apply(tuple(kept), F.tolist()) == lin.apply(kept, F.tolist())
    assert lin.factor_solve(J, F.tolist(), False)[1] is None
    # singular: a constraint row zero in value (the pattern keeps it), or a multiple of
    # another (the elimination leaves a pivot at round-off, or zero)
    S = M.copy()
    S[-1, :] = 0.0
    assert lin.factor_solve(S.ravel(order="F").tolist(), F.tolist(), True) is None
    S = M.copy()
    S[-1, :] = 3.0 * S[-2, :]
    assert sparse_solver(n, *ccs(S)).factor_solve(S.ravel(order="F").tolist(), F.tolist(),
                                                  True) is None
    bad = list(J)
    bad[0] = np.nan
    assert lin.factor_solve(bad, F.tolist(), True) is None


# ---- the static LU's analysis (hpgen.codegen.static_lu) -----------------------------------

def slu_factor(lu, jnz, n):
    """hpgen_slu_factor of hpgen_linalg.c (the runtime's left-looking loop), operation for
    operation: the values X, or None at a failed pivot."""
    X = np.zeros(lu.nnz)
    X[list(lu.jmap)] = jnz
    x = np.zeros(n)
    for t in range(n):
        c0, c1, dt = lu.colptr[t], lu.colptr[t + 1], lu.diag[t]
        x[list(lu.row[c0:c1])] = X[c0:c1]
        cmax = np.abs(X[c0:c1]).max()
        for q in range(c0, dt):
            k = lu.row[q]
            X[q], x[k] = x[k], 0.0
            for s in range(lu.diag[k] + 1, lu.colptr[k + 1]):
                x[lu.row[s]] -= X[s] * X[q]
        d, x[t] = x[t], 0.0
        if not (abs(d) > STATIC_PIVOT_TOL * cmax and np.isfinite(d)):
            return None
        r = 1.0 / d
        X[dt] = r
        for q in range(dt + 1, c1):
            X[q], x[lu.row[q]] = x[lu.row[q]] * r, 0.0
    return X


def slu_solve(lu, X, b, n):
    """hpgen_slu_solve of hpgen_linalg.c."""
    y = np.asarray(b, dtype=float)[list(lu.perm)]
    for t in range(n):
        for s in range(lu.diag[t] + 1, lu.colptr[t + 1]):
            y[lu.row[s]] -= X[s] * y[t]
    for t in range(n - 1, -1, -1):
        y[t] *= X[lu.diag[t]]
        for s in range(lu.colptr[t], lu.diag[t]):
            y[lu.row[s]] -= X[s] * y[t]
    out = np.zeros(n)
    out[list(lu.perm)] = y
    return out


def test_static_lu_orders_multipliers_after_their_bodies():
    rng = np.random.default_rng(5)
    for trial in range(5):
        M = kkt(rng, nb=6, nc=3)
        n = M.shape[0]
        colind, row = ccs(M)
        lu = static_lu(n, colind, row)
        pos = {v: t for t, v in enumerate(lu.perm)}
        for k in range(6, n):                       # a multiplier after every body it joins
            joined = set(np.flatnonzero(M[k])) | set(np.flatnonzero(M[:, k]))
            assert all(pos[b] < pos[k] for b in joined)
        jnz = np.concatenate([M[row[colind[c]:colind[c + 1]], c] for c in range(n)])
        X = slu_factor(lu, jnz, n)
        F = rng.standard_normal(n)
        ref = np.linalg.solve(M, F)
        np.testing.assert_allclose(slu_solve(lu, X, F, n), ref, rtol=0,
                                   atol=1e-12 * np.abs(ref).max())


def test_static_lu_of_the_chain_is_banded(chain):
    """The chain's order keeps L + U within a constant band of nonzeros per unknown, and the
    factorization of the module's J solves J dz = F."""
    integ = chain(2, "sparse", "python")
    jac, nz = integ.meta["jacobian"], integ.meta["nz"]
    lu = static_lu(nz, jac["colind"], jac["row"])
    assert lu is not None and lu.nnz <= 1.5 * len(jac["row"])
    sc = chain_scene(2)
    g = np.asarray(sc.g0, dtype=float).ravel(order="F")
    p = integ.legendre(sc.g0, sc.xi0)
    z = integ.kernel("guess", sc.xi0, g, p, [sc.h])[0]
    J = integ.kernel("jacobian", z, g, p, [sc.h])[0].reshape(nz, nz, order="F")
    jnz = np.concatenate([J[jac["row"][jac["colind"][c]:jac["colind"][c + 1]], c]
                          for c in range(nz)])
    X = slu_factor(lu, jnz, nz)
    F = np.linspace(-1.0, 1.0, nz)
    ref = np.linalg.solve(J, F)
    np.testing.assert_allclose(slu_solve(lu, X, F, nz), ref, rtol=0,
                               atol=1e-11 * np.abs(ref).max())


@pytest.mark.parametrize("backend", ["c", "python"])
def test_a_small_step_forced_sparse(cache_dir, backend):
    """jacobian="sparse" on a small step (the heavy top, Gauss 2: nz = 9, below every printed
    dense solver's limit): the sparse path, the same run to round-off."""
    top = EXAMPLES / "heavy_top.yaml"
    sc = load_model_text(read_model_text(str(top)), filename=str(top)).scene
    runs = {}
    for storage in ("dense", "sparse"):
        integ = hpgen.compile(top, tableau="gauss2", jacobian=storage, backend=backend,
                              cache_dir=cache_dir)
        assert integ.meta["jacobian"]["storage"] == storage
        kw = {"xi0": sc.xi0} if sc.xi0 is not None else {"mu0": sc.mu0}
        runs[storage] = integ.simulate(sc.g0, sc.h, STEPS, **kw)
    assert runs["sparse"].error is None
    assert max_deviation(runs["sparse"].g, runs["dense"].g) <= TOL
    assert max_deviation(runs["sparse"].mu, runs["dense"].mu) <= TOL


@pytest.mark.parametrize("backend", ["c", "python"])
def test_every_run_kind_on_an_open_model_forced_sparse(cache_dir, backend):
    """The driven pendulum (forces in t, a runtime parameter, a stroboscopic section; Gauss 2,
    nz = 3) with a sparse Newton matrix: every run kind as with the dense one, to round-off."""
    path = EXAMPLES / "driven_pendulum.yaml"
    sc = load_model_text(read_model_text(str(path)), filename=str(path)).scene
    dense = hpgen.compile(path, jacobian="dense", cache_dir=cache_dir)
    sparse = hpgen.compile(path, jacobian="sparse", backend=backend, cache_dir=cache_dir)
    assert sparse.meta["jacobian"]["storage"] == "sparse" and sparse.meta["nz"] == 3
    ref, got = run_kinds(dense, sc), run_kinds(sparse, sc)
    assert "stroboscopic" in got and set(got) <= set(ref)
    for kind, run in got.items():
        assert max_deviation(run(), ref[kind]()) <= TOL, kind


def test_storage_from_the_j_outputs():
    """The nz x nz J output is sparse by choice; an nz*nz column with structural zeros (a
    derivation that keeps its outputs' structure) is sparse when the rule says so."""
    from types import SimpleNamespace
    from hpgen.codegen.sparse import jacobian_sparsity

    def step(J, nz):
        z = ca.SX.sym("z", nz)
        fs = {"jacobian": ca.Function("j", [z], [J]),
              "residual_jacobian": ca.Function("rj", [z], [z, J])}
        return SimpleNamespace(nz=nz, kernel=lambda name: SimpleNamespace(function=fs[name]))
    for nz in (3, SPARSE_MIN_NZ - 1, SPARSE_MIN_NZ):
        sp = ca.Sparsity.banded(nz, 1)
        assert jacobian_sparsity(step(ca.SX(sp), nz)) == sp
        col = jacobian_sparsity(step(ca.reshape(ca.SX(sp), nz * nz, 1), nz))
        assert (col == sp) if nz >= SPARSE_MIN_NZ else col is None
        assert jacobian_sparsity(step(ca.SX(ca.Sparsity.dense(nz * nz, 1)), nz)) is None

