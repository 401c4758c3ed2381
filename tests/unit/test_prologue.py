"""simulate's Python prologue (argument checks, defect of g0, Legendre transform or its inverse,
guess) and the C backend's kernel calls: the fast paths give bitwise the results of the
straightforward code they replace, and keep every check.

- Integrator.velocity runs newton.newton (full Newton on arrays, no per-iterate conversions)
  for F = legendre - mu, J = hessian and keeps the singular-Legendre decision of the last
  Hessian: compared here with the reference (the generic list-based Newton loop newton.solve,
  with np.linalg.cond at every iterate) on
  random states of compiled models, both backends, and on scripted kernels reaching every
  branch (non-finite values, exactly singular or ill-conditioned Hessians, no convergence).
- CBackend.call copies the arguments into per-thread buffers of fixed address and copies the
  outputs out: nothing returned aliases them or an earlier result; bad arguments fail as before.
- CBackend.simulate writes step 0 and the steps into one pair of arrays: bitwise the generic
  start + advance + concatenate (_Backend.simulate), failures included.
No timing here (see the report of the change for the figures).
"""
from __future__ import annotations

import math
import threading

import numpy as np
import pytest

from conftest import FREE_BODY, HEAVY_TOP, SE3_BODY
from hpgen.errors import ArgumentError, ConvergenceError, ModelError
from hpgen.runtime import backends, newton
from hpgen.runtime.integrator import Integrator
from hpgen.runtime.state_maps import COND_MAX
from hpgen.runtime.engine import RunArgs
from hpgen.runtime.states import simulate as generic_simulate

from _toy_step import integrator as toy_integrator
from test_linearize_open import SPACECRAFT     # inputs, a runtime parameter, forces

#: l not quadratic in xi and d2l/dxi2 depending on g: several Newton iterates, a new Hessian
#: at each (the cond kept for the last Hessian must not carry over)
QUARTIC = """
name: quartic
group: SO3
lagrangian: 0.5*((2 + R[2,2])*xi[0]**2 + xi[1]**2 + 0.7*xi[2]**2) + 0.05*xi[0]**4 + 0.02*xi[1]**2*xi[2]**2 - R[2,2]
"""
MODELS = {"heavy_top": (HEAVY_TOP, dict(tableau="gauss2", tau="exp", rkmk="exact")),
          "free_body": (FREE_BODY, dict(tableau="gauss2", tau="cay", rkmk="exact")),
          "se3_body": (SE3_BODY, dict(tableau="stormer-verlet", tau="cay", rkmk="truncated")),
          "quartic": (QUARTIC, dict(tableau="stormer-verlet", tau="cay", rkmk="truncated"))}


def reference_newton(fun, z, tol, maxit):
    """newton.newton as it was: the generic Newton loop (newton.solve, full Newton, numpy's
    solver) with list conversions at every iterate: an independent reference."""
    z = np.array(z, dtype=np.float64)

    def both(zz, *_):
        F, J = fun(np.array(zz, dtype=np.float64))
        return (np.asarray(F, dtype=np.float64).tolist(),
                np.asarray(J, dtype=np.float64).ravel(order="F").tolist())

    code, zl, it, r, _ = newton.solve(newton.Kernels(len(z), None, None, both), z.tolist(),
                                      None, None, None,
                                      newton.NewtonOptions(tol, maxit, simplified=False),
                                      newton.NewtonMemory())
    return code, np.array(zl, dtype=np.float64), it, r


def reference_velocity(integ, g, mu, tol=newton.DEFAULT_TOL, maxit=newton.DEFAULT_MAXIT):
    """Integrator.velocity as it was: the generic Newton loop, np.linalg.cond of every
    Hessian."""
    gf, mu = integ.engine.maps.flat_g(g), integ.engine.maps.vector(mu, "mu")
    d = integ.d

    def fun(xi):
        F = integ.engine.backend.call("legendre", gf, xi)[0] - mu
        H = integ.engine.backend.call("hessian", gf, xi)[0].reshape(d, d, order="F")
        if np.isfinite(H).all():
            with np.errstate(all="ignore"):
                cond = float(np.linalg.cond(H)) if H.any() else math.inf
            if not cond <= COND_MAX:
                raise ModelError("the Legendre transform is singular at the initial state "
                                 f"(cond(d2l/dxi2) = {cond:.3g}); check the kinetic "
                                 "energy terms of the Lagrangian", field="scene.initial")
        return F, H

    with np.errstate(all="ignore"):
        code, xi, it, r = reference_newton(fun, np.zeros(d), tol, maxit)
    if code != newton.OK:
        raise ConvergenceError("inverting the Legendre transform (velocity from momentum): "
                               + {newton.NO_CONVERGENCE: "Newton did not converge",
                                  newton.NONFINITE: "Newton diverged: a non-finite value "
                                  "(or a singular Jacobian) appeared"}[code],
                               step=0, time=0.0, residual=r, iterations=it)
    return xi


def outcome(fn, *args, **kw):
    """('ok', bytes of the result) or (exception type, message, field, residual bits,
    iterations): equal outcomes are bitwise equal."""
    try:
        return "ok", np.asarray(fn(*args, **kw)).tobytes()
    except (ModelError, ArgumentError, ConvergenceError) as exc:
        r = getattr(exc, "residual", None)
        return (type(exc).__name__, str(exc), getattr(exc, "field", None),
                None if r is None else np.float64(r).tobytes(), getattr(exc, "iterations", None))


def rotation(v):
    t = np.linalg.norm(v)
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]]) / t
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


def random_g(rng, n):
    g = np.eye(n)
    g[:3, :3] = rotation(rng.normal(size=3))
    if n == 4:
        g[:3, 3] = rng.normal(size=3)
    return g


@pytest.fixture(scope="module", params=sorted(MODELS))
def compiled(request, compile_model):
    text, opts = MODELS[request.param]
    return {b: compile_model(text, backend=b, **opts) for b in ("c", "python")}


@pytest.mark.parametrize("backend", ["c", "python"])
def test_velocity_is_bitwise_the_reference_newton(compiled, backend):
    integ = compiled[backend]
    rng = np.random.default_rng(1)
    for scale in (1e-3, 1.0, 30.0):
        for _ in range(8):
            g, mu = random_g(rng, integ.n), scale * rng.normal(size=integ.d)
            assert outcome(integ.velocity, g, mu) == outcome(reference_velocity, integ, g, mu)
            for kw in ({"maxit": 1}, {"tol": 1e-3}):
                assert outcome(integ.velocity, g, mu, newton=newton.NewtonOptions(**kw)) == \
                    outcome(reference_velocity, integ, g, mu, **kw)
            with pytest.raises(ArgumentError, match="newton.maxit"):
                integ.velocity(g, mu, newton=newton.NewtonOptions(maxit=0))


@pytest.mark.parametrize("backend", ["c", "python"])
def test_initial_and_simulate_from_mu0_match_the_reference(compiled, backend):
    integ = compiled[backend]
    rng = np.random.default_rng(2)
    for _ in range(4):
        g, mu = random_g(rng, integ.n), rng.normal(size=integ.d)
        gf, mu0, xi0 = integ.engine.initial(g, None, mu)
        assert gf.tobytes() == g.ravel(order="F").tobytes()
        assert mu0.tobytes() == mu.tobytes()
        assert xi0.tobytes() == reference_velocity(integ, g, mu).tobytes()
        xi = rng.normal(size=integ.d)
        gf, mu0, xi0 = integ.engine.initial(g, xi, None)
        assert mu0.tobytes() == integ.legendre(g, xi).tobytes() and xi0.tobytes() == xi.tobytes()
    # the whole of simulate against its pieces, run through the generic backend driver
    g, mu = random_g(rng, integ.n), 0.5 * rng.normal(size=integ.d)
    h, steps, every = 0.01, 7, 2
    tr = integ.simulate(g, h, steps, mu0=mu, every=every)
    gf = g.ravel(order="F")
    z0 = integ.engine.backend.call("guess", reference_velocity(integ, g, mu), gf, mu,
                                   np.array([h]))[0]
    done, G, P, st = backends._Backend.simulate(integ.engine.backend, gf, mu, h, z0, steps, every,
                                                integ.engine.options(None))
    K = done // every + 1
    n = integ.n
    assert tr.g.tobytes() == np.ascontiguousarray(
        G[:K].reshape(K, n, n).transpose(0, 2, 1)).tobytes()
    assert tr.mu.tobytes() == P[:K].tobytes()
    assert tr.t.tobytes() == (0.0 + np.arange(K) * every * h).tobytes()
    assert tr.newton_iterations == st["total_iterations"] and tr.jacobians == st["jacobians"]


# ---- scripted kernels: every branch of the Newton written out ----------------------------
class _Scripted:
    """A backend whose legendre/hessian are Python functions of xi (d = 2, n = 1)."""
    name = "scripted"

    def __init__(self, legendre, hessian):
        self.legendre, self.hessian = legendre, hessian

    def call(self, name, g, xi):
        xi = np.asarray(xi, dtype=np.float64)
        with np.errstate(all="ignore"):
            out = self.legendre(xi) if name == "legendre" else self.hessian(xi)
        return [np.asarray(out, dtype=np.float64).ravel(order="F").copy()]


def _scripted(legendre, hessian):
    meta = {"n": 1, "d": 2, "nz": 2, "module": "scripted", "kernels": {}}
    return Integrator(meta, _Scripted(legendre, hessian))


A = np.array([[2.0, 0.3], [0.3, 1.0]])
SCRIPTS = {
    "quadratic": (lambda x: A @ x + 0.1, lambda x: A),
    "cubic": (lambda x: A @ x + 0.2 * x ** 3, lambda x: A + np.diag(0.6 * x ** 2)),
    "slow": (lambda x: np.arctan(x) * 3.0, lambda x: np.diag(3.0 / (1 + x ** 2))),
    "nan_F": (lambda x: A @ x + (np.nan if x.any() else 0.0), lambda x: A),
    "inf_H": (lambda x: A @ x, lambda x: A + (np.inf if x.any() else 0.0)),
    "nan_H_first": (lambda x: A @ x, lambda x: np.full((2, 2), np.nan)),
    "zero_H": (lambda x: A @ x, lambda x: np.zeros((2, 2))),
    "singular_H": (lambda x: A @ x, lambda x: np.ones((2, 2))),
    "ill_but_regular": (lambda x: A @ x, lambda x: np.diag([1.0, 1e-11])),
    "ill_singular": (lambda x: A @ x, lambda x: np.diag([1.0, 1e-13])),
    "becomes_singular": (lambda x: A @ x + 0.2 * x ** 3,
                         lambda x: A if not x.any() else np.diag([1.0, 0.0])),
    "huge_step": (lambda x: 1e-300 * x - 1.0, lambda x: 1e-300 * np.eye(2)),
}


@pytest.mark.parametrize("script", sorted(SCRIPTS))
def test_velocity_branches_match_the_reference(script):
    rng = np.random.default_rng(3)
    for mu in [np.array([0.7, -1.2]), np.zeros(2)] + [rng.normal(size=2) for _ in range(4)]:
        for kw in ({}, {"maxit": 3}, {"tol": 1e-6}):
            fast, ref = _scripted(*SCRIPTS[script]), _scripted(*SCRIPTS[script])
            g = np.eye(1)
            opts = newton.NewtonOptions(**kw)
            got = outcome(fast.velocity, g, mu, newton=opts)
            assert got == outcome(reference_velocity, ref, g, mu, **kw)
            assert got == outcome(fast.velocity, g, mu, newton=opts)      # with the kept cond


def test_kept_cond_is_per_hessian_and_per_integrator():
    ok, bad = SCRIPTS["quadratic"], SCRIPTS["singular_H"]
    it = _scripted(*ok)
    it.velocity(np.eye(1), [1.0, 2.0])
    it.engine.backend.hessian = bad[1]          # a new Hessian: checked again, refused
    with pytest.raises(ModelError):
        it.velocity(np.eye(1), [1.0, 2.0])
    it.engine.backend.hessian = ok[1]
    assert it.velocity(np.eye(1), [1.0, 2.0]).tobytes() == \
        reference_velocity(_scripted(*ok), np.eye(1), [1.0, 2.0]).tobytes()


@pytest.mark.parametrize("backend", ["c", "python"])
def test_singular_legendre_still_refused(backend):
    it = toy_integrator(backend, "singular")
    for _ in range(2):               # the second time from the kept cond
        with pytest.raises(ModelError) as info:
            it.velocity(np.eye(3), [1.0, 0.0, 0.0])
        assert info.value.field == "scene.initial" and "singular" in str(info.value)
        assert "cond(d2l/dxi2) = " in str(info.value)
        with pytest.raises(ModelError) as info:
            it.simulate(np.eye(3), 0.1, 3, mu0=[1.0, 0.0, 0.0])
        assert info.value.field == "scene.initial"
    assert it.simulate(np.eye(3), 0.1, 3, xi0=[1.0, 0.0, 0.0]).mu.shape == (4, 3)


# ---- the C backend's kernel calls ---------------------------------------------------------
@pytest.fixture(scope="module")
def cb():
    return toy_integrator("c").engine.backend


def test_kernel_outputs_are_fresh_arrays(cb):
    g, hv = np.eye(3).ravel(), np.array([0.1])
    a = cb.call("legendre", g, np.array([1.0, 2.0, 3.0]))[0]
    a_bytes = a.tobytes()
    b = cb.call("legendre", g, np.array([-4.0, 5.0, 0.5]))[0]
    assert a.tobytes() == a_bytes and not np.shares_memory(a, b)
    a[:] = 99.0                               # writing a result changes no later call
    assert cb.call("legendre", g, np.array([-4.0, 5.0, 0.5]))[0].tobytes() == b.tobytes()
    F, J = cb.call("residual_jacobian", np.array([0.1, 0.2, 0.3]), g, np.ones(3), hv)
    g1, p1 = cb.call("update", np.array([0.1, 0.2, 0.3]), g, np.ones(3), hv)
    outs = [a, b, F, J, g1, p1]
    assert all(o.flags.owndata and o.flags.writeable for o in outs)
    assert not any(np.shares_memory(x, y) for i, x in enumerate(outs) for y in outs[i + 1:])
    # inputs are read, never written
    z = np.array([0.1, 0.2, 0.3])
    cb.call("update", z, g, np.ones(3), hv)
    assert z.tolist() == [0.1, 0.2, 0.3] and g.tolist() == np.eye(3).ravel().tolist()
    # the run state: copies too
    run = cb.start(g, np.ones(3), z)
    s1, s2 = cb.state(run), cb.state(run)
    assert not any(np.shares_memory(x, y) for x, y in zip(s1[:3], s2[:3]))


def test_kernel_results_equal_fresh_buffers(cb):
    """Each call bitwise as with zeroed output arrays of its own (the former call path)."""
    rng = np.random.default_rng(4)
    for name, (ins, outs) in cb._sig.items():
        for _ in range(3):
            args = [rng.normal(size=s) for s in ins]
            fresh = [np.zeros(s) for s in outs]
            cb._fns[name](*[x.ctypes.data for x in args + fresh])
            got = cb.call(name, *args)
            assert [o.tobytes() for o in got] == [o.tobytes() for o in fresh], name


def test_kernel_argument_conversion_and_errors(cb):
    g, xi = np.eye(3), np.array([1.0, 2.0, 3.0])
    ref = cb.call("legendre", g.ravel(), xi)[0].tobytes()
    for gg, xx in ((g.ravel().tolist(), xi.tolist()), (g.ravel().astype(np.float32), xi),
                   (np.eye(3, dtype=int).ravel(), xi), (np.eye(6)[::2, ::2].ravel(), xi),
                   (np.ascontiguousarray(np.vstack([g.ravel()] * 2).T)[:, 1], xi[::1]),
                   (g.ravel(), np.array([1.0, 9.0, 2.0, 9.0, 3.0])[::2])):
        assert cb.call("legendre", gg, xx)[0].tobytes() == ref
    with pytest.raises(ValueError, match=r"legendre input 0: expected a flat array of 9"):
        cb.call("legendre", g, xi)                        # (3, 3): not flat
    with pytest.raises(ValueError, match=r"legendre input 1: expected a flat array of 3"):
        cb.call("legendre", g.ravel(), np.ones((1, 3)))
    with pytest.raises(ValueError, match=r"legendre input 1"):
        cb.call("legendre", g.ravel(), 1.0)
    with pytest.raises(TypeError, match=r"takes 2 arguments, got 1"):
        cb.call("legendre", g.ravel())
    with pytest.raises(KeyError):
        cb.call("no_such_kernel", g.ravel())


def test_kernel_calls_from_threads(cb):
    """The staging buffers are per thread: concurrent calls give the serial results."""
    rng = np.random.default_rng(5)
    g, hv = np.eye(3).ravel(), np.array([0.05])
    zs = [rng.normal(size=3) for _ in range(200)]
    want = [[o.tobytes() for o in cb.call("update", z, g, z, hv)] for z in zs]
    got = {}

    def work(i):
        for _ in range(20):
            for j, z in enumerate(zs):
                r = [o.tobytes() for o in cb.call("update", z, g, z, hv)]
                if r != want[j]:
                    got[i] = j
                    return

    assert not in_threads(work, 4) and not got


def in_threads(work, count) -> list:
    """Run work(0), ..., work(count - 1) in as many threads; the exceptions they raised."""
    errors = []

    def guarded(i):
        try:
            work(i)
        except Exception as exc:   # noqa: BLE001 - returned to the caller
            errors.append(exc)

    threads = [threading.Thread(target=guarded, args=(i,)) for i in range(count)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return errors


# ---- CBackend.simulate against the generic driver -----------------------------------------
@pytest.mark.parametrize("steps, every, maxit", [(0, 1, 50), (1, 1, 50), (5, 3, 50),
                                                 (2, 5, 50), (40, 4, 50), (10, 1, 1)])
def test_c_simulate_is_the_generic_driver(cb, steps, every, maxit):
    opts = newton.NewtonOptions(1e-14, maxit, True, True)
    g0, p0 = np.eye(3).ravel(), np.array([0.4, 0.1, 0.8])
    z0 = cb.call("guess", p0 / np.array([2.0, 1.0, 2.0 / 3.0]), g0, p0, np.array([0.1]))[0]
    a = cb.simulate(g0, p0, 0.1, z0, steps, every, opts)
    b = backends._Backend.simulate(cb, g0, p0, 0.1, z0, steps, every, opts)
    assert a[0] == b[0] and _bits(a[3]) == _bits(b[3])
    assert a[1].tobytes() == b[1].tobytes() and a[2].tobytes() == b[2].tobytes()
    assert a[1].shape == b[1].shape and a[2].shape == b[2].shape
    # advance in chunks (state queries for k) agrees with one call
    run = cb.start(g0, p0, z0)
    parts = [cb.advance(run, 0.1, k, every, opts) for k in (steps // 2, steps - steps // 2)]
    G = np.concatenate([g0.reshape(1, -1)] + [p[1] for p in parts])
    if all(p[3]["code"] == newton.OK for p in parts):
        assert G.tobytes() == a[1].tobytes()


def _bits(status: dict) -> dict:
    return {k: np.float64(v).tobytes() if isinstance(v, float) else v
            for k, v in status.items()}


def test_simulate_batch_setup_matches_single_runs():
    it = toy_integrator("c")
    rng = np.random.default_rng(6)
    mus = rng.normal(size=(5, 3))
    trs = it.simulate_batch(np.eye(3), 0.1, 6, mu0=mus, every=2, threads=2)
    for tr, mu in zip(trs, mus):
        one = it.simulate(np.eye(3), 0.1, 6, mu0=mu, every=2)
        assert tr.g.tobytes() == one.g.tobytes() and tr.mu.tobytes() == one.mu.tobytes()
        assert tr.t.tobytes() == one.t.tobytes()


# ---- simulate's fast path (hpgen.runtime.prologue) against the generic path ---------------
def _traj_bits(tr) -> tuple:
    """Everything a Trajectory holds, as bytes / values (equal: bitwise the same run)."""
    arrays = tuple((a.tobytes(), a.shape, a.dtype.str, a.flags.c_contiguous, a.flags.writeable)
                   for a in (tr.t, tr.g, tr.mu))
    inputs = None if tr.inputs is None else (tr.inputs.t0, tr.inputs.rows, tr.inputs.params)
    return arrays + (np.float64(tr.h).tobytes(), tr.every, tr.partial, tr.error,
                     tr.newton_iterations, tr.jacobians, tr.integrator, inputs, tr._obs)


def _run_outcome(fn, *args, **kw):
    """('ok', _traj_bits) or the exception's type, message, step, iterations, residual bits
    and its partial Trajectory's bits."""
    try:
        return "ok", _traj_bits(fn(*args, **kw))
    except Exception as exc:            # noqa: BLE001 - every exception is compared
        partial = getattr(exc, "partial", None)
        r = getattr(exc, "residual", None)
        return (type(exc).__name__, str(exc), getattr(exc, "step", None),
                getattr(exc, "iterations", None),
                None if r is None else np.float64(r).tobytes(),
                None if partial is None else _traj_bits(partial)[:-9])


def _generic(integ, g0, h, steps, xi0=None, mu0=None, every=1, *, newton=None, u=None,
             params=None, t0=0.0):
    return generic_simulate(integ.engine, RunArgs(g0, h, steps, xi0, mu0, every, newton, u,
                                                  params, t0))


def test_fast_simulate_is_the_generic_path(compiled):
    """Random starts (xi0 and mu0), several h, steps, every, Newton settings and t0: the fast
    path takes every call and gives bitwise the generic path's Trajectory."""
    integ = compiled["c"]
    rng = np.random.default_rng(11)
    settings = [None, newton.NewtonOptions(simplified=False),
                newton.NewtonOptions(tol=1e-10, predictor=False)]
    for trial in range(6):
        g0 = random_g(rng, integ.n)
        xi0 = 0.5 * rng.normal(size=integ.d)
        mu0 = integ.legendre(g0, xi0) + 0.01 * rng.normal(size=integ.d)
        for steps, every in ((0, 1), (1, 1), (7, 3), (12, 12)):
            h = [0.05, -0.1, 0.02][trial % 3]
            nw = settings[trial % 3]
            for start in ({"xi0": xi0}, {"mu0": mu0}, {"mu0": list(mu0)}):
                for t0 in (0.0, 1.25):
                    kw = dict(every=every, newton=nw, t0=t0, **start)
                    fast = integ.fast_path.simulate(g0, h, steps, start.get("xi0"),
                                                    start.get("mu0"), every, nw, t0)
                    assert fast is not None          # the common case takes the fast path
                    want = _run_outcome(_generic, integ, g0, h, steps, **kw)
                    assert _run_outcome(integ.simulate, g0, h, steps, **kw) == want
                    assert ("ok", _traj_bits(fast)) == want


def test_fast_simulate_failures_and_arguments_as_the_generic_path(compile_model):
    """A step failing after the first (partial trajectory), a first step that needs
    continuation or fails, and bad arguments: the same outcome as the generic path."""
    integ = compile_model(HEAVY_TOP, tableau="gauss2", tau="cay", rkmk="exact", backend="c")
    g0, xi0 = rotation(np.array([0.3, 0.2, 0.0])), [0.2, 1.0, 3.0]
    late = newton.NewtonOptions(maxit=4)
    out = _run_outcome(integ.simulate, g0, 0.3, 50, xi0=xi0, newton=late)
    assert out[0] == "ConvergenceError" and out[2] == 1           # step 1: after the start
    assert out == _run_outcome(_generic, integ, g0, 0.3, 50, xi0=xi0, newton=late)
    nan_g = np.where(np.eye(3) > 0, np.nan, g0)
    cases = [dict(h=h, steps=5, xi0=xi0) for h in (1.5, 3.0, 10.0, 50.0)] + [
        dict(h=0.1, steps=5, xi0=xi0, newton=newton.NewtonOptions(maxit=1)),
        dict(h=0.0, steps=3, xi0=xi0), dict(h=True, steps=3, xi0=xi0),
        dict(h=0.1, steps=-1, xi0=xi0), dict(h=0.1, steps=3.0, xi0=xi0),
        dict(h=0.1, steps=3, xi0=xi0, every=0), dict(h=0.1, steps=3),
        dict(h=0.1, steps=3, xi0=xi0, mu0=xi0), dict(h=0.1, steps=3, xi0=[1.0, 2.0]),
        dict(h=0.1, steps=3, xi0=[1.0, np.nan, 2.0]), dict(h=0.1, steps=3, xi0=[1e308] * 3),
        dict(h=0.1, steps=3, mu0=[1.0, np.inf, 0.0]), dict(h=0.1, steps=3, xi0=[1j, 0, 0]),
        dict(h=0.1, steps=3, xi0=xi0, newton="x"), dict(h=0.1, steps=3, xi0=xi0, t0=np.nan),
        dict(h=0.1, steps=3, xi0=xi0, newton=newton.NewtonOptions(tol=-1.0)),
        dict(h=0.1, steps=3, xi0=xi0, u=[1.0]), dict(h=0.1, steps=3, xi0=xi0, params={"a": 1}),
        dict(h=0.1, steps=2**62, xi0=xi0), dict(h=0.1, steps=3, xi0=xi0, t0=True),
        dict(h=np.float64(0.1), steps=np.int64(3), xi0=(0.2, 1, 3), t0=2),
        dict(h=1, steps=3, xi0=xi0), dict(h=0.1, steps=3, mu0=[0.0, 0.0, 0.0])]
    for kw in cases:
        for g in (g0, 2 * g0, g0[:2], nan_g, g0.tolist(), g0.astype(np.float32)):
            assert _run_outcome(integ.simulate, g, **kw) == _run_outcome(_generic, integ, g,
                                                                         **kw), (kw, g)


def test_fast_simulate_results_own_their_memory(compile_model):
    """The records come out of per-thread scratch rows: results of earlier calls are not
    changed by later ones (grown rows, runs longer than ROWS_MAX included), are read-only,
    and the shared record times cannot be made writeable."""
    from hpgen.runtime.prologue import ROWS_MAX
    integ = compile_model(FREE_BODY, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                          backend="c")
    rng = np.random.default_rng(3)
    kept = []
    for steps in (0, 3, 100, ROWS_MAX - 1, ROWS_MAX, ROWS_MAX + 5, 10, 2 * ROWS_MAX):
        g0, mu0 = random_g(rng, 3), rng.normal(size=3)
        tr = integ.simulate(g0, 0.05, steps, mu0=mu0)
        assert _traj_bits(tr) == _traj_bits(_generic(integ, g0, 0.05, steps, mu0=mu0))
        kept.append((tr, _traj_bits(tr)))
    for tr, bits in kept:
        assert _traj_bits(tr) == bits
        for a in (tr.t, tr.g, tr.mu):
            with pytest.raises(ValueError):
                a[0] = 0.0
        if len(tr) <= ROWS_MAX:             # times shared between calls: immutable
            with pytest.raises(ValueError):
                tr.t.flags.writeable = True


def test_fast_simulate_from_threads(compile_model):
    """Concurrent simulate calls (per-thread staging, shared plans) give the serial results."""
    integ = compile_model(HEAVY_TOP, tableau="gauss2", tau="cay", rkmk="exact", backend="c")
    rng = np.random.default_rng(5)
    starts = [(random_g(rng, 3), rng.normal(size=3), k % 2) for k in range(40)]

    def run(g0, v, mu):
        kw = {"mu0": v} if mu else {"xi0": v}
        return _traj_bits(integ.simulate(g0, 0.05, 20, every=4, **kw))[:-9]

    want = [run(*s) for s in starts]
    got = {}

    def work(j):
        for _ in range(5):
            for k in range(j, len(starts), 2):
                got.setdefault(k, set()).add(run(*starts[k]))

    assert not in_threads(work, 2)
    assert all(got[k] == {want[k]} for k in range(len(starts)))


def test_plans_are_keyed_by_type_and_identity(compile_model):
    """A plan is found again only for equal h, steps, every of the accepted types and the
    same newton object: h=1 (int) or True never reuses h=1.0's plan (the generic path checks
    them), and an equal but new NewtonOptions gets its own plan."""
    integ = compile_model(FREE_BODY, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                          backend="c")
    pro = integ.fast_path
    a = pro.plan(1.0, 3, 1, None)
    assert pro.plan(1.0, 3, 1, None) is a and pro.plan(np.float64(1.0), np.int64(3), 1, None) is a
    assert pro.plan(1, 3, 1, None) is None and pro.plan(True, 3, 1, None) is None
    assert pro.plan(1.0, True, 1, None) is None and pro.plan(0.0, 3, 1, None) is None
    o1, o2 = newton.NewtonOptions(maxit=7), newton.NewtonOptions(maxit=7)
    p1 = pro.plan(1.0, 3, 1, o1)
    assert pro.plan(1.0, 3, 1, o1) is p1 and pro.plan(1.0, 3, 1, o2) is not p1
    assert pro.plan(1.0, 3, 1, o2).opts == p1.opts
    for k in range(40):                    # the dict stays bounded
        pro.plan(0.01 * (k + 1), 3, 1, None)
    assert len(pro.plans) <= 32


def test_fast_simulate_of_an_open_module_is_the_generic_path(compile_model):
    """Inputs held or per step, runtime parameters, t0, xi0 / mu0 starts, a failing run and
    bad u / params: the fast path takes the valid calls and gives the generic path's
    Trajectory (its StepInputs included) or error."""
    integ = compile_model(SPACECRAFT, tableau="gauss2", tau="cay", rkmk="exact", backend="c")
    rng = np.random.default_rng(8)
    for steps in (0, 1, 9):
        g0 = random_g(rng, 3)
        xi0 = 0.5 * rng.normal(size=3)
        mu0 = integ.legendre(g0, xi0, params={"c": 0.3})
        per_step = (0.1 * rng.normal(size=(steps, 3)),) if steps else ()
        for u in (np.full(3, 0.2), [0.1, 0.0, -0.1]) + per_step:
            for params in (None, {"c": 0.3}):
                for t0 in (0.0, 2.5):
                    for start in ({"xi0": xi0}, {"mu0": mu0}):
                        kw = dict(every=2, u=u, params=params, t0=t0, **start)
                        fast = integ.fast_path.simulate(g0, 0.05, steps, start.get("xi0"),
                                                        start.get("mu0"), 2, None, t0, u,
                                                        params)
                        assert fast is not None
                        want = _run_outcome(_generic, integ, g0, 0.05, steps, **kw)
                        assert _run_outcome(integ.simulate, g0, 0.05, steps, **kw) == want
                        assert ("ok", _traj_bits(fast)) == want
                        assert (fast.inputs.t0, fast.inputs.rows, fast.inputs.params) == (
                            t0, [list(r) for r in np.atleast_2d(u)], [0.1 if params is None
                                                                     else 0.3])
    g0, xi0 = np.eye(3), [0.2, 1.0, 3.0]
    for kw in (dict(h=0.05, steps=4, u=[0.0] * 3), dict(h=50.0, steps=4, u=[0.0] * 3),
               dict(h=0.3, steps=30, u=[5.0, 5.0, 5.0], newton=newton.NewtonOptions(maxit=3)),
               dict(h=0.05, steps=4), dict(h=0.05, steps=4, u=[1.0, 2.0]),
               dict(h=0.05, steps=4, u=np.zeros((2, 3))), dict(h=0.05, steps=4, u=[np.nan] * 3),
               dict(h=0.05, steps=4, u=[0.0] * 3, params={"k": 1.0}),
               dict(h=0.05, steps=4, u=[0.0] * 3, params=[1.0]),
               dict(h=0.05, steps=4, u=[0.0] * 3, params={"c": np.inf}),
               dict(h=0.05, steps=4, u=[0.0] * 3, t0=np.nan)):
        assert _run_outcome(integ.simulate, g0, xi0=xi0, **kw) == _run_outcome(
            _generic, integ, g0, xi0=xi0, **kw), kw
