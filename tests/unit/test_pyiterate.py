"""kernels.py ITERATE and ITERATE_FULL (hpgen.codegen.pyiterate): the Newton iterates with
the kernel, the linear algebra, z - dz and the tests fused into one printed function give
bitwise the numbers of the unfused path (the kernels, LINEAR's functions and the tests of
hpgen.runtime.newton.solve), hand back at a refresh of J and on NO_CONVERGENCE like it, and
decline (None) where the unfused path leaves its fast arithmetic. Whole runs with and
without them are bitwise equal (and equal to the C backend: test_newton_python.py).
"""
from __future__ import annotations

import importlib.util
import math

import numpy as np
import pytest

from conftest import HEAVY_TOP
from hpgen.abi import NO_CONVERGENCE, OK, REFRESH, ROUNDOFF_FLOOR, THETA_FLOOR, THETA_MAX
from hpgen.codegen import pyiterate
from hpgen.runtime import newton
from reference import rotvec

from _toy_step import emitted, module_dir

STOL = newton.SIMPLIFIED_TOL * newton.DEFAULT_TOL


def bits(x):
    return np.asarray(x, dtype=np.float64).view(np.uint64)


def load(path):
    spec = importlib.util.spec_from_file_location(f"_iter_{abs(hash(str(path)))}",
                                                  path / "kernels.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def unfused(mod, X, z, g, p, h, it, maxit, dprev, stol):
    """The iterates the way solve takes them without ITERATE: RAW residual, _lin_update,
    then its tests in its order; (code, z, it, dn, |F|) or None where _lin_update declines."""
    residual, update = mod.RAW["residual"], mod.LINEAR[2]
    while True:
        F = residual(z, g, p, h)[0]
        new = update(X, F, z)
        if new is None:
            return None
        z, dn, zn = new
        if it > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + zn):
            return OK, z, it, dn, newton.norm_inf(F)
        th = dn / dprev
        te = th if th > THETA_FLOOR else THETA_FLOOR
        if dn <= stol * (1.0 + zn):
            return OK, z, it, dn, newton.norm_inf(F)
        if it > 1 and te < 1.0 and te / (1.0 - te) * dn <= stol * (1.0 + zn):
            return OK, z, it, dn, newton.norm_inf(F)
        if it > 1 and dn > THETA_MAX * dprev:
            return REFRESH, z, it, dn, newton.norm_inf(F)
        if it >= maxit:
            return NO_CONVERGENCE, z, it, dn, newton.norm_inf(F)
        dprev, it = dn, it + 1


def _same(got, want):
    assert (got is None) == (want is None)
    if want is not None:
        assert got[0] == want[0] and got[2] == want[2]
        assert bits(got[1]).tolist() == bits(want[1]).tolist()
        assert bits([got[3], got[4]]).tolist() == bits([want[3], want[4]]).tolist()


def _cases(mod, nz, g, p, h, z0, rng):
    """ITERATE against the unfused iterates near a root z0: J^{-1} at z0 (converges), a
    scaled one (linear rate 0.3 > THETA_MAX: REFRESH), a maxit cap (NO_CONVERGENCE), a later
    start (it, dprev carried in), and J^{-1} blowing z up (None: the caller goes the general
    way)."""
    F, J = mod.RAW["residual_jacobian"](z0, g, p, h)
    _, X = mod.LINEAR[0](J, F, True)
    codes = set()
    for k in range(12):
        z = (np.asarray(z0) + rng.normal(size=nz) * 10.0 ** rng.uniform(-8, -2)).tolist()
        for Xk, it, maxit, dprev in ((X, 1, 50, math.inf), (tuple(0.7 * a for a in X), 1, 50,
                                     math.inf), (X, 1, 2, math.inf), (X, 3, 50, 1e-3),
                                     (tuple(1e300 * a for a in X), 1, 50, math.inf)):
            want = unfused(mod, Xk, z, g, p, h, it, maxit, dprev, STOL)
            got = mod.ITERATE(Xk, z, g, p, h, it, maxit, dprev, STOL)
            _same(got, want)
            codes.add(None if want is None else want[0])
    assert codes == {OK, REFRESH, NO_CONVERGENCE, None}


def test_toy_iterate_equals_unfused_path():
    mod = load(module_dir())
    assert mod.ITERATE is not None and mod.ITERATE.__name__ == pyiterate.FUNCTION
    rng = np.random.default_rng(1)
    g = rotvec([0.3, 0.2, 0.0]).ravel(order="F").tolist()
    _cases(mod, mod.NZ, g, [0.6, 1.0, -0.3], [0.1], [0.3, 0.5, -0.1], rng)


@pytest.mark.parametrize("tau", ["cay", "exp"])
def test_heavy_top_gauss2_iterate_and_runs(compile_model, tau):
    integ = compile_model(HEAVY_TOP, tableau="gauss2", tau=tau, rkmk="exact", backend="python")
    mod = load(integ.module_dir)
    kern = integ.engine.backend._newton
    assert kern.iterate is not None
    g0, xi0 = rotvec([0.3, 0.2, 0.0]), [0.2, 1.0, 3.0]
    runs = []
    for it, full in ((kern.iterate, kern.iterate_full), (None, None)):
        kern.iterate, kern.iterate_full = it, full
        for simplified in (None, True, False):
            runs.append(integ.simulate(g0=g0, xi0=xi0, h=0.05, steps=150,
                                       newton=newton.NewtonOptions(simplified=simplified)))
    for a, b in zip(runs[:3], runs[3:]):
        assert bits(a.g).tolist() == bits(b.g).tolist()
        assert bits(a.mu).tolist() == bits(b.mu).tolist()
        assert (a.newton_iterations, a.jacobians) == (b.newton_iterations, b.jacobians)
    g, p = g0.ravel(order="F").tolist(), runs[0].mu[-1].tolist()
    z0 = integ.kernel("guess", xi0, g, p, [0.05])[0].tolist()
    code, zstar, *_ = newton.solve(kern, z0, g, p, [0.05], newton.NewtonOptions(
        simplified=False), newton.NewtonMemory())
    assert code == OK
    _cases(mod, integ.nz, g, p, [0.05], zstar, np.random.default_rng(2))


def test_iterate_source_is_deterministic_and_refuses_other_kernels():
    step, _ = emitted()
    res = step.kernel("residual")
    assert pyiterate.iterate_source(res, 3) == pyiterate.iterate_source(res, 3)
    with pytest.raises(pyiterate.CodegenError):
        pyiterate.iterate_source(step.kernel("update"), 3)
    with pytest.raises(pyiterate.CodegenError):
        pyiterate.iterate_source(res, 4)


def test_solve_with_and_without_iterate_agree_on_every_path():
    """newton.solve from a kept J^{-1}: converging, refreshing J, capped by maxit, and with
    ITERATE declining (z blows up: the general path then reports NONFINITE as before); full
    Newton (ITERATE_FULL) converging and capped."""
    mod = load(module_dir())
    g = rotvec([0.3, 0.2, 0.0]).ravel(order="F").tolist()
    p, h, z0 = [0.6, 1.0, -0.3], [0.1], [0.3, 0.5, -0.1]
    F, J = mod.RAW["residual_jacobian"](z0, g, p, h)
    _, X = mod.LINEAR[0](J, F, True)
    fused = newton.Kernels.from_raw(mod.NZ, mod.RAW, mod.LINEAR, mod.ITERATE,
                                    mod.ITERATE_FULL)
    plain = newton.Kernels.from_raw(mod.NZ, mod.RAW, mod.LINEAR)
    assert None not in (fused.iterate, fused.iterate_full)
    assert plain.iterate is None and plain.iterate_full is None
    codes = set()
    for Xk, simplified in ((X, True), (tuple(0.7 * a for a in X), True),
                           (tuple(1e300 * a for a in X), True), (None, False)):
        for maxit in (2, 50):
            out = []
            for kern in (fused, plain):
                mem = newton.NewtonMemory()
                mem.lu = Xk
                res = newton.solve(kern, [0.35, 0.45, -0.05], g, p, h,
                                   newton.NewtonOptions(1e-14, maxit, simplified), mem)
                out.append((res, mem.lu))
            (a, lu_a), (b, lu_b) = out
            assert a[0] == b[0] and a[2] == b[2] and a[4] == b[4]
            assert bits(a[1]).tolist() == bits(b[1]).tolist()
            assert bits([a[3]]).tolist() == bits([b[3]]).tolist()
            assert (lu_a is None) == (lu_b is None)
            codes.add(a[0])
    assert codes == {OK, NO_CONVERGENCE, newton.NONFINITE}


def unfused_full(mod, z, g, p, h, maxit, tol):
    """Full Newton the way solve takes it without ITERATE_FULL: (code, z, it, |F|) or None
    where solve would leave the fast way (non-finite F, singular J, non-finite z)."""
    dprev = math.inf
    for it in range(1, maxit + 1):
        F, J = mod.RAW["residual_jacobian"](z, g, p, h)
        if not newton.all_finite(F):
            return None
        res = mod.LINEAR[0](J, F, False)
        if res is None:
            return None
        new = mod.LINEAR[3](res[0], z)
        if new is None:
            return None
        z, dn, zn = new
        if (it > 1 and dn >= dprev and dn <= ROUNDOFF_FLOOR * (1.0 + zn)) or \
                dn <= tol * (1.0 + zn):
            return OK, z, it, newton.norm_inf(F)
        dprev = dn
    return NO_CONVERGENCE, z, maxit, newton.norm_inf(F)


def test_toy_iterate_full_equals_unfused_path():
    mod = load(module_dir())
    assert mod.ITERATE_FULL.__name__ == pyiterate.FULL
    g = rotvec([0.3, 0.2, 0.0]).ravel(order="F").tolist()
    rng = np.random.default_rng(4)
    codes = set()
    for k in range(20):
        z = (rng.normal(size=3) * 10.0 ** rng.uniform(-3, 3)).tolist()
        for maxit in (1, 2, 50):
            want = unfused_full(mod, z, g, [0.6, 1.0, -0.3], [0.1], maxit, 1e-14)
            got = mod.ITERATE_FULL(z, g, [0.6, 1.0, -0.3], [0.1], 1, maxit, math.inf, 1e-14)
            assert (got is None) == (want is None)
            if want is not None:
                assert (got[0], got[2]) == (want[0], want[2])
                assert bits(got[1]).tolist() == bits(want[1]).tolist()
                assert bits([got[4]]).tolist() == bits([want[3]]).tolist()
            codes.add(None if want is None else want[0])
    assert {OK, NO_CONVERGENCE} <= codes
