"""The Python backend's Newton (hpgen.runtime.newton) against the C runtime's logic.

The straight-line linear algebra is checked bitwise against a loop-for-loop transcription of
hpgen/runtime/c/hpgen_linalg.c (hpgen_lu_factor_solve, hpgen_lu_inverse, hpgen_lu_apply); whole runs
of the Python backend are checked bitwise against the C backend for nz <= UNROLL_MAX: both
backends' kernels are bitwise equal (tests/unit/test_codegen.py) and the C is compiled with
-std=c99 (no contraction into fused multiply-adds), so the same operations in the same order
give the same doubles. If the C template's Newton or linear algebra changes, these tests
fail until hpgen/runtime/newton.py mirrors it again.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import HEAVY_TOP
from hpgen.abi import UNROLL_MAX
from hpgen.codegen import pylinear
from hpgen.runtime import newton
from reference import rotvec

from _toy_step import integrator, module_dir

NAN, INF = math.nan, math.inf


def bits(x):
    return np.asarray(x, dtype=np.float64).view(np.uint64)


def same_bits(a, b) -> bool:
    return np.array_equal(bits(a), bits(b))


# ---- a transcription of the C template's linear algebra, loop for loop ---------------------

def c_factor_solve(J, F, keep):
    """hpgen_lu_factor_solve (+ hpgen_lu_factor, hpgen_lu_solve, hpgen_lu_inverse): (dz, X)
    or None (the C returns 1)."""
    n = len(F)
    A, b = list(J), list(F)
    if n == 1:
        if not (A[0] != 0.0) or not math.isfinite(A[0]):
            return None
        r = 1.0 / A[0]
        return [b[0] * r], [r]
    if n == 2:
        a, c, bb, d = A
        det = a * d - bb * c
        x0, x1 = d * b[0] - bb * b[1], a * b[1] - c * b[0]
        if not (det != 0.0) or not math.isfinite(det):
            return None
        r = 1.0 / det
        return [x0 * r, x1 * r], [d * r, -c * r, -bb * r, a * r]
    if n == 3:
        j00, j10, j20, j01, j11, j21, j02, j12, j22 = A
        c00, c01, c02 = j11 * j22 - j12 * j21, j12 * j20 - j10 * j22, j10 * j21 - j11 * j20
        c10, c11, c12 = j02 * j21 - j01 * j22, j00 * j22 - j02 * j20, j01 * j20 - j00 * j21
        c20, c21, c22 = j01 * j12 - j02 * j11, j02 * j10 - j00 * j12, j00 * j11 - j01 * j10
        det = j00 * c00 + j01 * c01 + j02 * c02
        x = [c00 * b[0] + c10 * b[1] + c20 * b[2], c01 * b[0] + c11 * b[1] + c21 * b[2],
             c02 * b[0] + c12 * b[1] + c22 * b[2]]
        if not (det != 0.0) or not math.isfinite(det):
            return None
        r = 1.0 / det
        return [v * r for v in x], [c * r for c in (c00, c01, c02, c10, c11, c12, c20, c21,
                                                      c22)]
    if not all(math.isfinite(v) for v in A):
        return None
    LU, piv = list(A), [0] * n
    for k in range(n):
        pk, amax = k, abs(LU[k + k * n])
        for i in range(k + 1, n):
            a = abs(LU[i + k * n])
            if a > amax:
                amax, pk = a, i
        piv[k] = pk
        if amax == 0.0:
            return None
        if pk != k:
            for j in range(n):
                LU[k + j * n], LU[pk + j * n] = LU[pk + j * n], LU[k + j * n]
        r = 1.0 / LU[k + k * n]
        LU[k + k * n] = r
        for i in range(k + 1, n):
            LU[i + k * n] *= r
        for j in range(k + 1, n):
            a = LU[k + j * n]
            if a != 0.0:
                for i in range(k + 1, n):
                    LU[i + j * n] -= LU[i + k * n] * a
    for k in range(n):
        if piv[k] != k:
            b[k], b[piv[k]] = b[piv[k]], b[k]
    for k in range(n):
        for i in range(k + 1, n):
            b[i] -= LU[i + k * n] * b[k]
    for k in range(n - 1, -1, -1):
        s = b[k]
        for j in range(k + 1, n):
            s -= LU[k + j * n] * b[j]
        b[k] = s * LU[k + k * n]
    if not keep:
        return b, None
    X = [0.0] * (n * n)
    for j in range(n):
        X[j + j * n] = 1.0
    for k in range(n):
        if piv[k] != k:
            for j in range(n):
                X[k + j * n], X[piv[k] + j * n] = X[piv[k] + j * n], X[k + j * n]
    for k in range(n):
        for j in range(n):
            xk = X[k + j * n]
            if xk != 0.0:
                for i in range(k + 1, n):
                    X[i + j * n] -= LU[i + k * n] * xk
    for k in range(n - 1, -1, -1):
        for j in range(n):
            xk = X[k + j * n] * LU[k + k * n]
            X[k + j * n] = xk
            for i in range(k):
                X[i + j * n] -= LU[i + k * n] * xk
    if not all(math.isfinite(v) for v in X):
        return None
    return b, X


def c_apply(X, b):
    """hpgen_lu_apply: x_i = A_i0 b_0, then x_i += A_ij b_j."""
    n = len(b)
    x = [X[i] * b[0] for i in range(n)]
    for j in range(1, n):
        for i in range(n):
            x[i] += X[i + j * n] * b[j]
    return x


def c_norm(x):
    m = 0.0
    for v in x:
        a = abs(v)
        if a != a:
            return a
        if a > m:
            m = a
    return m


def printed_solver(n):
    """The straight-line solver a generated kernels.py carries for nz = n (LINEAR), built
    here from the same printed source."""
    ns = {"_isfinite": math.isfinite, f"_UNIT{n}": pylinear.unit_rows(n)}
    exec(compile(pylinear.linear_solver_source(n), f"<printed solver n={n}>", "exec"), ns)
    return newton.linear_solver(n, tuple(ns[f] for f in pylinear.FUNCTIONS))


def _matrices(n, rng):
    """Test matrices (column-major lists): dense, sparse (the zero-skips), needing pivots,
    permutations, badly scaled."""
    out = [rng.normal(size=(n, n)), rng.normal(size=(n, n)) * (rng.random((n, n)) < 0.6),
           np.triu(rng.normal(size=(n, n)))[::-1], np.eye(n)[rng.permutation(n)],
           rng.normal(size=(n, n)) * np.logspace(-150, 150, n)[:, None]]
    A = rng.normal(size=(n, n))
    A[0, 0] = 1e-300              # a tiny first pivot candidate
    out.append(A)
    return [np.asarray(m, dtype=np.float64).ravel(order="F").tolist() for m in out]


@pytest.mark.parametrize("n", range(1, UNROLL_MAX + 1))
def test_straight_line_solver_equals_c_loops_bitwise(n):
    rng = np.random.default_rng(n)
    lin = printed_solver(n)
    for J in _matrices(n, rng):
        F = rng.normal(size=n).tolist()
        z = rng.normal(size=n).tolist()
        for keep in (False, True):
            want, got = c_factor_solve(J, F, keep), lin.factor_solve(J, F, keep)
            if want is None:
                assert got is None
                continue
            assert got is not None and same_bits(got[0], want[0])
            if want[1] is None:
                assert got[1] is None
                continue
            assert same_bits(got[1], want[1])
            X = got[1]
            dz = c_apply(want[1], F)
            assert same_bits(lin.apply(X, F), dz)
            # the fused update and finish are the general path's numbers
            znew, dn, zn = lin.update(X, F, z)
            assert same_bits(znew, [a - b for a, b in zip(z, dz)])
            assert dn == c_norm(dz) and zn == c_norm(znew)
            znew, dn, zn = lin.finish(want[0], z)
            assert same_bits(znew, [a - b for a, b in zip(z, want[0])])
            assert dn == c_norm(want[0]) and zn == c_norm(znew)


@pytest.mark.parametrize("n", [1, 2, 3, 4, 9])
def test_singular_or_non_finite_jacobian_is_refused(n):
    lin = printed_solver(n)
    F = [1.0] * n
    zero_col = np.eye(n)
    zero_col[:, n - 1] = 0.0
    for J in (zero_col, np.full((n, n), np.inf), np.where(np.eye(n) > 0, np.nan, 1.0)):
        J = J.ravel(order="F").tolist()
        for keep in (False, True):
            assert c_factor_solve(J, F, keep) is None
            assert lin.factor_solve(J, F, keep) is None


@pytest.mark.parametrize("n", [3, 9])
def test_fused_update_declines_non_finite_values(n):
    lin = printed_solver(n)
    X = np.eye(n).ravel(order="F").tolist()
    z = [1.0] * n
    assert lin.update(X, [1.0] * (n - 1) + [NAN], z) is None
    assert lin.update(X, [INF] + [1.0] * (n - 1), z) is None
    assert lin.update(X, [1.0] * n, [INF] * n) is None
    assert lin.finish([1e308] * n, [-1e308] * n) is None       # z - dz overflows
    assert lin.finish([1e308] * n, [0.0] * n) is None          # finite, but the sums overflow


def test_numpy_solver_above_unroll_max_agrees_to_round_off():
    n = UNROLL_MAX + 5
    rng = np.random.default_rng(7)
    lin = newton.linear_solver(n)
    assert lin.update is None and lin.finish is None
    A = rng.normal(size=(n, n)) + n * np.eye(n)
    J, F = A.ravel(order="F").tolist(), rng.normal(size=n).tolist()
    want = c_factor_solve(J, F, True)
    for keep in (False, True):
        dz, X = lin.factor_solve(J, F, keep)
        assert (X is None) != keep
        np.testing.assert_allclose(dz, want[0], rtol=0, atol=1e-14 * np.abs(want[0]).max())
    np.testing.assert_allclose(np.asarray(X).ravel(order="F"), want[1], rtol=0,
                               atol=1e-14 * np.abs(want[1]).max())
    assert lin.factor_solve([0.0] * (n * n), F, True) is None


def test_solver_source_is_deterministic():
    raw = pylinear.linear_solver_source.__wrapped__
    for n in (1, 3, 4, 12):
        assert raw(n) == raw(n) == pylinear.linear_solver_source(n)
    with pytest.raises(ValueError):
        raw(pylinear.UNROLL_MAX + 1)
    assert UNROLL_MAX == pylinear.UNROLL_MAX


def test_generated_module_carries_its_solver():
    # kernels.py of a module with nz <= UNROLL_MAX holds LINEAR, printed from the source above
    import importlib.util
    spec = importlib.util.spec_from_file_location("_toy_kernels_linear",
                                                  module_dir() / "kernels.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert mod.NZ <= pylinear.UNROLL_MAX
    assert [f.__name__ for f in mod.LINEAR] == list(pylinear.FUNCTIONS)
    assert pylinear.linear_solver_source(mod.NZ) in (module_dir() / "kernels.py").read_text()


def test_norm_inf_and_all_finite_follow_c():
    for x in ([1.0, -3.0, 2.0], [0.0, -0.0], [1e308, 1e308, -1.0], [1.0, NAN, 5.0],
              [1.0, INF, NAN, 2.0], [-INF, 1.0], [5.0]):
        want = c_norm(x)
        got = newton.norm_inf(x)
        assert (got == want) or (math.isnan(got) and math.isnan(want)), x
        assert newton.all_finite(x) == all(math.isfinite(v) for v in x), x
    assert newton.norm_inf([]) == 0.0
    # a NaN after the maximum: max(map(abs, x)) alone would miss it
    assert math.isnan(newton.norm_inf([7.0, NAN]))


# ---- Newton on hand-made kernels: the non-finite paths ------------------------------------

def _kernels(residual, jacobian):
    kern = newton.Kernels(2, lambda z, *a: [residual(z)], lambda z, *a: [jacobian(z)])
    kern.linear = printed_solver(2)          # as a generated module with nz = 2 has it
    return kern


def _solve(kern, z, simplified=False, maxit=50):
    return newton.solve(kern, list(z), None, None, None,
                        newton.NewtonOptions(1e-14, maxit, simplified), newton.NewtonMemory())


def test_solve_converges_and_reports_like_c():
    # F(z) = (z0^2 - 2, z1 - 1): full Newton from (1, 0)
    kern = _kernels(lambda z: [z[0] * z[0] - 2.0, z[1] - 1.0],
                    lambda z: [2.0 * z[0], 0.0, 0.0, 1.0])
    code, z, it, r, jacs = _solve(kern, [1.0, 0.0])
    assert code == newton.OK and jacs == it and 4 <= it <= 7
    assert abs(z[0] - math.sqrt(2.0)) <= 4.5e-16 and z[1] == 1.0
    assert 0.0 < r < 1e-14          # |F| at the last iterate evaluated (before the last update)
    code, z2, it2, _, jacs2 = _solve(kern, [1.0, 0.0], simplified=True)
    assert code == newton.OK and abs(z2[0] - math.sqrt(2.0)) <= 4.5e-16 and jacs2 <= it2
    code, *_ = _solve(kern, [1.0, 0.0], maxit=2)
    assert code == newton.NO_CONVERGENCE


def test_solve_non_finite_and_singular_paths():
    calls = []

    def residual(z):
        calls.append(list(z))
        return [NAN, 1.0] if len(calls) == 2 else [z[0] - 1.0, z[1] - 2.0]
    kern = _kernels(residual, lambda z: [1.0, 0.0, 0.0, 1.0])
    code, z, it, r, jacs = _solve(kern, [3.0, 3.0])
    # the first iterate is the exact root of the linear F; the second F is NaN: stop there
    # with z unchanged and the residual NaN (as hpgen_newton)
    assert code == newton.NONFINITE and it == 2 and math.isnan(r) and z == [1.0, 2.0]
    kern = _kernels(lambda z: [z[0], z[1]], lambda z: [1.0, 2.0, 2.0, 4.0])      # det = 0
    code, z, it, r, jacs = _solve(kern, [3.0, 4.0])
    assert (code, z, it, r, jacs) == (newton.NONFINITE, [3.0, 4.0], 1, 4.0, 1)
    kern = _kernels(lambda z: [z[0], z[1]], lambda z: [INF, 0.0, 0.0, 1.0])
    assert _solve(kern, [3.0, 4.0])[0] == newton.NONFINITE
    # z - dz overflows: NONFINITE with the new z (C updates z before its norms)
    kern = _kernels(lambda z: [-1e308, -1e308], lambda z: [1e-10, 0.0, 0.0, 1e-10])
    code, z, it, r, jacs = _solve(kern, [1e308, 1e308])
    assert code == newton.NONFINITE and z == [INF, INF] and r == 1e308


# ---- the kernels' calling conventions -----------------------------------------------------

def test_raw_kernels_are_the_public_kernels_on_lists():
    it = integrator("python")
    raw, public = it.engine.backend._raw, it.engine.backend._kernels
    rng = np.random.default_rng(3)
    for name, (ins, outs) in it.engine.backend._sig.items():
        args = [rng.normal(size=s) * 0.3 for s in ins]
        want = public[name](*args)
        got = raw[name](*[a.tolist() for a in args])
        assert type(got) is list and len(got) == len(want) == len(outs)
        for g, w, s in zip(got, want, outs):
            assert type(g) is list and len(g) == s and all(type(v) is float for v in g)
            assert same_bits(g, w), name
        assert [type(w) for w in want] == [np.ndarray] * len(outs)
        # public kernels keep accepting lists, tuples and arrays alike
        again = public[name](*[tuple(a.tolist()) for a in args])
        assert all(same_bits(a, b) for a, b in zip(again, want))


def test_module_without_raw_kernels_still_runs(tmp_path):
    """A kernels.py printed before RAW existed: the backend wraps the public kernels."""
    import shutil

    from hpgen.runtime import load
    src = module_dir()
    dst = tmp_path / src.name
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns("_kernels*"))
    text = (dst / "kernels.py").read_text()
    cut = text.index("\nRAW = {")
    (dst / "kernels.py").write_text(text[:cut] + "\n")
    old = load(dst, backend="python")
    assert "\nRAW = {" not in (dst / "kernels.py").read_text()
    g0 = rotvec([0.3, 0.2, 0.0])
    a = old.simulate(g0, 0.1, 50, xi0=[0.3, 1.0, -0.4])
    b = integrator("python").simulate(g0, 0.1, 50, xi0=[0.3, 1.0, -0.4])
    assert same_bits(a.g, b.g) and same_bits(a.mu, b.mu)


def test_step_core_with_public_kernels_equals_backend_step():
    """newton.step_core(call, ...) (used by hpgen.analysis) on either backend's public
    kernels gives the Python backend's step."""
    g = rotvec([0.3, 0.2, 0.0]).ravel(order="F")
    p, hv = np.array([0.6, 1.0, -0.3]), np.array([0.1])
    opts = newton.NewtonOptions(1e-14, 50, simplified=False)
    py = integrator("python")
    z0 = py.kernel("guess", py.velocity(g.reshape(3, 3, order="F"), p), g, p, hv)[0]
    want = py.engine.backend.step(g, p, hv, z0, opts)
    for backend in ("python", "c"):
        it = integrator(backend)
        code, g1, p1, z, iters, r, jacs = newton.step_core(it.kernel, 3, g, p, hv, z0, opts,
                                                          newton.NewtonMemory())
        assert code == newton.OK and isinstance(g1, np.ndarray) and g1.shape == (9,)
        assert same_bits(g1, want[1]) and same_bits(p1, want[2]) and same_bits(z, want[3])
        assert iters == want[4] and jacs == iters


# ---- whole runs: Python backend == C backend, bit for bit ---------------------------------

def _runs_equal(c, py):
    assert same_bits(c.g, py.g) and same_bits(c.mu, py.mu)
    assert (c.newton_iterations, c.jacobians) == (py.newton_iterations, py.jacobians)


@pytest.mark.parametrize("simplified", [False, True])
def test_toy_python_run_is_bitwise_the_c_run(simplified):
    g0 = rotvec([0.3, 0.2, 0.0])
    runs = [integrator(b).simulate(g0, 0.1, 300, xi0=[0.3, 1.0, -0.4],
                                   newton=newton.NewtonOptions(simplified=simplified))
            for b in ("c", "python")]
    _runs_equal(*runs)


HEAVY = [("stormer-verlet", "cay", "truncated"), ("midpoint", "cay", "exact"),
         ("gauss2", "cay", "exact"), ("gauss2", "exp", "exact")]


@pytest.mark.parametrize("tableau,tau,rkmk", HEAVY, ids=["-".join(c) for c in HEAVY])
def test_heavy_top_python_run_is_bitwise_the_c_run(compile_model, tableau, tau, rkmk):
    g0, xi0 = rotvec([0.3, 0.2, 0.0]), [0.2, 1.0, 3.0]
    integ = {b: compile_model(HEAVY_TOP, tableau=tableau, tau=tau, rkmk=rkmk, backend=b)
             for b in ("c", "python")}
    assert integ["c"].nz <= UNROLL_MAX
    for simplified in (None, False, True):
        c, py = (integ[b].simulate(g0=g0, xi0=xi0, h=0.05, steps=200,
                                   newton=newton.NewtonOptions(simplified=simplified))
                 for b in ("c", "python"))
        _runs_equal(c, py)
    # chunks (stream) carry the Newton memory and the predictor like one call
    parts = list(integ["python"].stream(g0=g0, xi0=xi0, h=0.05, steps=200, chunk=37,
                                        newton=newton.NewtonOptions(simplified=True)))
    assert same_bits(np.concatenate([t.mu for t in parts]), py.mu)


def test_heavy_top_above_unroll_max_agrees_with_c(compile_model):
    """nz = 24 > UNROLL_MAX (Stormer-Verlet with the exact constraint): LAPACK's inverse and
    solve against the C LU, round-off apart (both Newtons stop at round-off: the states agree
    to a few ulps of |mu| ~ 20 per step, growing slowly)."""
    g0, xi0 = rotvec([0.3, 0.2, 0.0]), [0.2, 1.0, 3.0]
    runs = {}
    for b in ("c", "python"):
        integ = compile_model(HEAVY_TOP, tableau="stormer-verlet", tau="cay", rkmk="exact",
                              backend=b)
        runs[b] = integ.simulate(g0=g0, xi0=xi0, h=0.05, steps=200)
    assert integ.nz > UNROLL_MAX
    c, py = runs["c"], runs["python"]
    assert np.abs(c.g - py.g).max() < 1e-12
    assert np.abs(c.mu - py.mu).max() < 1e-12 * np.abs(c.mu).max()


def test_printed_kernels_compute_repeated_operations_once():
    """pysource: an operation CasADi repeats on the same operands (also with the operands of
    + and * swapped) is printed once, with bitwise the values CasADi computes."""
    import casadi as ca

    from hpgen.codegen.pysource import kernel_lines
    from hpgen.derive.step import Kernel
    from _toy_step import emitted

    x = ca.SX.sym("x", 3)
    a, b, c = x[0], x[1], x[2]
    outs = [ca.sin(a) * b, ca.sin(a) + c, a * b + c, b * a - c, (a + c) / 3.0, (c + a) * 3.0,
            a * b * 0.5, 0.5 * (b * a)]
    f = ca.Function("rep", [x], [ca.vertcat(*outs)], ["x"], ["y"])
    assert sum(f.instruction_id(k) == ca.OP_SIN for k in range(f.n_instructions())) == 2
    lines = kernel_lines(Kernel("rep", f, ("x",), ("y",)))
    fast = lines[:lines.index("except (ArithmeticError, ValueError):")]
    assert sum(line.count("_f_sin(") for line in fast) == 1
    assert sum(line.count(" * ") for line in fast) < sum(
        1 for k in range(f.n_instructions()) if f.instruction_id(k) == ca.OP_MUL)
    ns = {}
    exec(compile(emitted()[1].file("kernels.py"), "kernels.py", "exec"), ns)
    body = "\n".join("    " + line for line in lines)
    exec(compile(f"def k(x):\n{body}\n    return r0\n", "rep", "exec"), ns)
    for pt in ([0.3, -1.7, 2.5], [1e-300, 3.0, -0.0], [2.0, 1e300, 1e300]):
        want = np.array(f(ca.DM(pt)).full()).ravel()
        assert same_bits(ns["k"](pt), want), pt
