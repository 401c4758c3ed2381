"""Derivatives of the step along a trajectory (math.md sec. 10).

    Integrator.linearize(traj) -> A (K, 2d, 2d),  A[k] = d(eta_{k+1}, dp_{k+1}) / d(eta_k, dp_k)

Perturbations are right-trivialized in the module's chart: g_k -> g_k tau(eta_k),
p_k -> p_k + dp_k, and the output is read the same way at g_{k+1}. Every registered chart has
tau(eta) = e + eta^ + O(|eta|^2), so A is the same whichever tau the module uses (it is the
derivative in left-trivialized coordinates; ``hpgen check``'s canonical form
hpgen.analysis.symplectic.omega_matrix applies to it: A^T Omega(p_{k+1}) A = Omega(p_k) for a
conservative scheme). A's columns/rows are ordered (eta, dp), column-major in C.

How: at each step k the converged z_k solves F(z; g_k, p_k, h) = 0. The generated kernel
``step_partials`` (hpgen.derive.linearize) gives Fs = dF/ds, Yz = dY/dz, Ys = dY/ds at z_k
(Y = (eta_{k+1}, p_{k+1}), s = (eta_k, dp_k)), the ``jacobian`` kernel J = dF/dz, factored
once; the implicit function theorem gives A = Ys - Yz J^{-1} Fs
(``implicit_derivative``). No finite differences, no perturbed solves.

z_k is not stored in a Trajectory: each step's z_k is recovered by Newton from (g_k, p_k)
(the ``newton=`` settings; step 0 by full Newton from the guess kernel, step k > 0 from the
predictor through z_{k-1}, z_{k-2}, ... in C, from z_{k-1} in Python; C's simplified Newton
reuses J^{-1} at z_{k-1}, evaluated for the derivative anyway), and the step's output is
compared with the next record (``RECORD_RTOL``): a trajectory of another module, step size or
model is refused. The C backend runs the whole loop in ``hpgen_linearize`` (kernels.c); the
Python backend runs it here on the module's kernels.py. The two agree to round-off.

Open modules (forces, inputs, runtime parameters or t; the step vector
H = [h, t_k, u_k, params], hpgen.runtime.inputs):

    Integrator.linearize(traj, u=U) -> (A (K, 2d, 2d), B (K, 2d, m)),
        B[k] = d(eta_{k+1}, dp_{k+1}) / d u_k
    Integrator.linearize(traj, u=U, wrt="params") -> P (K, 2d, n_runtime_params),
        P[k] = d(eta_{k+1}, dp_{k+1}) / d params (the parameters held fixed over step k only)

from the open kernel's partials in the step vector (FH = dF/dH, YH = dY/dH):
B = YH_u - Yz J^{-1} FH_u, P = YH_par - Yz J^{-1} FH_par. u, params and t0 are simulate's
(u required for a model with inputs; t0 defaults to the trajectory's first time). The C
backend runs the loop in the open module's ``hpgen_linearize`` (the step vectors of all
steps passed as rows), the Python backend here (step k by full Newton from step k-1's
solution).

The functions take the module's run engine (hpgen.runtime.engine.Engine: its kernels,
backend, state maps and meta), as Integrator.linearize passes it. Runtime path only: numpy
and hpgen.runtime.
"""
from __future__ import annotations

import numpy as np

from .. import abi
from ..errors import ArgumentError
from .args import _error

#: the step recomputed from record k must reproduce record k+1 to this relative accuracy
#: (max-norm, relative to 1 + max|state|). simulate's own steps (simplified Newton, predictor
#: starts) and full Newton here agree to the Newton tolerance, ~1e-14; another scheme, step
#: size or model differs by its local error, orders of magnitude above 1e-9 for any step size
#: whose results are meant to be accurate.
RECORD_RTOL = 1e-9


def along(engine, traj, newton=None, u=None, params=None, t0=None, wrt=None, compose=()):
    """Integrator.linearize: ``linearize`` for a closed module (which takes none of u,
    params, t0, wrt: ArgumentError naming the one given), ``linearize_open`` for an open
    one, ``linearize_composed`` for a composed step (compose: its substep fractions);
    newton: the Newton settings (Engine.options resolves them)."""
    if engine.open is None:
        for name, v in (("u", u), ("params", params), ("t0", t0), ("wrt", wrt)):
            if v is not None:
                raise ArgumentError("this model has no forces, inputs, runtime "
                                    f"parameters or t: linearize takes no {name}",
                                    field=name)
        if compose:
            return linearize_composed(engine, traj, engine.options(newton), compose)
        return linearize(engine, traj, engine.options(newton))
    if compose:
        return linearize_composed(engine, traj, engine.options(newton), compose, u, params,
                                  t0, wrt)
    return linearize_open(engine, traj, engine.options(newton), u, params, t0, wrt)


def linearize_composed(engine, traj, opts, gammas, u=None, params=None, t0=None, wrt=None):
    """linearize / linearize_open of a composed step Phi(h) = S(gamma_s h) o ... o
    S(gamma_1 h): per step k the substeps from record k (each by Newton from the guess
    kernel, on either backend's step), and the chain rule over them,
    A = A_s ... A_1 and B = sum_i A_s ... A_(i+1) B_i (P likewise), A_i, B_i the implicit
    derivatives of substep i at its own state and h_i = gamma_i h (an open substep at time
    t_k + (gamma_1 + ... + gamma_(i-1)) h with input u_k). Raises as linearize."""
    if wrt not in WRT:
        raise ArgumentError(f"expected wrt=None, 'u' or 'params', got {wrt!r}", field="wrt")
    gf, p, h = _check_traj(engine, traj)
    K, s = len(gf) - 1, 2 * engine.d
    inputs, cols, lv = None, slice(0, 0), None
    if engine.open is not None:
        t0, inputs, cols = _open_inputs(engine, traj, K, u, params, t0, wrt)
        lv = engine.maps.lv(t0, inputs.params)
    A, B = np.zeros((K, s, s)), np.zeros((K, s, cols.stop - cols.start))
    dev = np.zeros(K)
    for k in range(K):
        g, pk = gf[k], p[k]
        c = 0.0
        for i, gi in enumerate(gammas):
            if inputs is None:
                hv = np.array([gi * h])
            else:
                hv = np.array(inputs.hv(h, k), dtype=np.float64)
                hv[0], hv[1] = gi * h, inputs.t0 + (k + c) * h
            xi = (engine.maps.velocity_flat(g, pk) if lv is None
                  else engine.maps.velocity_flat(g, pk, lv=lv))
            z = engine.kernel("guess", xi, g, pk, hv)[0]
            code, g1, p1, z, it, r = engine.backend.step(g, pk, hv, z, opts)
            if code != abi.OK:
                raise _error(code, k, k * h, r, it)
            if inputs is None:
                Ai = implicit_derivative(*partials_at(engine, z, g, pk, hv))
            else:
                J, Fs, Yz, Ys, FH, YH = open_partials_at(engine, z, g, pk, hv)
                D = implicit_derivative(J, np.hstack([Fs, FH[:, cols]]), Yz,
                                        np.hstack([Ys, YH[:, cols]]))
                Ai = D[:, :s]
                B[k] = Ai @ B[k] + D[:, s:]
            A[k] = Ai if i == 0 else Ai @ A[k]
            g, pk, c = np.asarray(g1).reshape(-1), np.asarray(p1).reshape(-1), c + gi
        dev[k] = max(np.abs(g - gf[k + 1]).max(), np.abs(pk - p[k + 1]).max())
    _check_dev(engine, gf, p, h, dev)
    if inputs is None:
        return A
    return B if wrt == "params" else (A, B)


def implicit_derivative(J, Fs, Yz, Ys):
    """Ys - Yz J^{-1} Fs: d Y / d s of the output Y(z(s), s) where F(z(s), s) = 0 (the implicit
    function theorem). J (nz, nz), Fs (nz, m), Yz (r, nz), Ys (r, m). The one implementation
    used by the Python backend and by hpgen.analysis.symplectic."""
    return Ys - Yz @ np.linalg.solve(J, Fs)


def partials_at(engine, z, gf, p, hv):
    """(J (nz, nz), Fs (nz, 2d), Yz (2d, nz), Ys (2d, 2d)) from the module's generated
    ``jacobian`` and ``step_partials`` kernels at z (flat column-major g, hv = [h]); engine:
    the run engine or an Integrator (``kernel``, ``nz``, ``d``)."""
    nz, s = engine.nz, 2 * engine.d
    J = engine.kernel("jacobian", z, gf, p, hv)[0]
    Fs, Yz, Ys = engine.kernel("step_partials", z, gf, p, hv)[:3]   # open: (FH, YH) too
    return (J.reshape(nz, nz, order="F"), Fs.reshape(nz, s, order="F"),
            Yz.reshape(s, nz, order="F"), Ys.reshape(s, s, order="F"))


def open_partials_at(engine, z, gf, p, hv):
    """(J, Fs, Yz, Ys, FH (nz, H), YH (2d, H)) of an open module at z (hv its step vector)."""
    nz, s, H = engine.nz, 2 * engine.d, len(hv)
    J = engine.kernel("jacobian", z, gf, p, hv)[0]
    Fs, Yz, Ys, FH, YH = engine.kernel("step_partials", z, gf, p, hv)
    return (J.reshape(nz, nz, order="F"), Fs.reshape(nz, s, order="F"),
            Yz.reshape(s, nz, order="F"), Ys.reshape(s, s, order="F"),
            FH.reshape(nz, H, order="F"), YH.reshape(s, H, order="F"))


def _check_traj(engine, traj):
    """(g records flat (K+1, n*n), p records (K+1, d), h) of ``traj``, checked."""
    n, d = engine.n, engine.d
    if not all(hasattr(traj, a) for a in ("g", "mu", "h", "every")):
        raise ArgumentError(f"expected a Trajectory from simulate, got {type(traj).__name__}",
                         field="traj")
    other = getattr(traj, "integrator", None)
    if other is not None and getattr(other, "meta", {}).get("hash") != engine.meta["hash"]:
        raise ArgumentError(f"the trajectory comes from module {other.meta.get('module')!r}, "
                         f"not {engine.meta['module']!r}", field="traj")
    if traj.every != 1:
        raise ArgumentError(f"expected a trajectory recorded at every step (every=1), got "
                         f"every={traj.every}", field="traj")
    g, mu = np.asarray(traj.g, dtype=np.float64), np.asarray(traj.mu, dtype=np.float64)
    if g.ndim != 3 or g.shape[1:] != (n, n) or mu.shape != (len(g), d) or len(g) < 2:
        raise ArgumentError(f"expected g of shape (K+1, {n}, {n}) and mu of shape (K+1, {d}) "
                         f"with K >= 1, got {g.shape} and {mu.shape}", field="traj")
    if not (np.isfinite(g).all() and np.isfinite(mu).all()):
        raise ArgumentError("the trajectory has non-finite entries", field="traj")
    gf = np.ascontiguousarray(g.transpose(0, 2, 1).reshape(len(g), n * n))
    return gf, np.array(mu, order="C"), float(traj.h)


def _python_loop(engine, gf, p, hv, z, opts):
    """The Python backend's twin of hpgen_linearize: (A (K, 2d, 2d), dev (K,), code, k)."""
    K, s = len(gf) - 1, 2 * engine.d
    A, dev = np.zeros((K, s, s)), np.zeros(K)
    for k in range(K):
        code, g1, p1, z, it, r = engine.backend.step(gf[k], p[k], hv, z, opts)
        if code != abi.OK:
            return A, dev, (code, it, r), k
        dev[k] = max(np.abs(g1 - gf[k + 1]).max(), np.abs(p1 - p[k + 1]).max())
        A[k] = implicit_derivative(*partials_at(engine, z, gf[k], p[k], hv))
    return A, dev, None, K


def linearize(engine, traj, opts):
    """A (K, 2d, 2d) along ``traj`` (K + 1 records of ``Integrator.simulate(..., every=1)``); see
    the module docstring. opts: resolved NewtonOptions (Engine.options). Raises
    ArgumentError (field traj) for a trajectory that is not this module's, ConvergenceError if a
    step's Newton fails."""
    gf, p, h = _check_traj(engine, traj)
    hv = np.array([h])
    g0 = gf[0].reshape(engine.n, engine.n, order="F")
    z0 = engine.kernel("guess", engine.maps.velocity(g0, p[0]), gf[0], p[0], hv)[0]
    loop = getattr(engine.backend, "linearize", None)
    if loop is not None:
        A, dev, err, done = loop(gf, p, hv[0], z0, opts)
    else:
        A, dev, err, done = _python_loop(engine, gf, p, hv, z0, opts)
    if err is not None:
        code, it, r = err
        raise _error(code, done, done * h, r, it)
    _check_dev(engine, gf, p, h, dev)
    return A


def _check_dev(engine, gf, p, h, dev):
    """Refuse records that are not this module's steps (dev[k]: step k's deviation)."""
    scale = 1.0 + max(np.abs(gf).max(), np.abs(p).max())
    bad = np.flatnonzero(~(dev <= RECORD_RTOL * scale))
    if bad.size:
        k = int(bad[0])
        raise ArgumentError(f"record {k + 1} is not this module's step from record {k} at "
                         f"h = {h!r} (deviation {dev[k]:.1e}); expected a trajectory "
                         f"simulated by {engine.meta['module']!r} with these inputs",
                         field="traj")


#: linearize's ``wrt`` choices of an open module: the control inputs (with A) or the runtime
#: parameters
WRT = (None, "u", "params")


def linearize_open(engine, traj, opts, u=None, params=None, t0=None, wrt=None):
    """Open module: (A, B) (wrt None or "u") or P (wrt "params") along ``traj``; see the
    module docstring. Raises ArgumentError for a bad trajectory, u, params, t0 or wrt,
    ConvergenceError if a step's Newton fails."""
    if wrt not in WRT:
        raise ArgumentError(f"expected wrt=None, 'u' or 'params', got {wrt!r}", field="wrt")
    gf, p, h = _check_traj(engine, traj)
    K = len(gf) - 1
    t0, inputs, cols = _open_inputs(engine, traj, K, u, params, t0, wrt)
    H = 2 + len(engine.open["inputs"]) + len(inputs.params)
    hv = np.array([inputs.hv(h, k) for k in range(K)], dtype=np.float64).reshape(K, H)
    z = engine.kernel("guess", engine.maps.velocity_flat(gf[0], p[0],
                                                       lv=engine.maps.lv(t0, inputs.params)),
                     gf[0], p[0], hv[0])[0]
    loop = getattr(engine.backend, "linearize_open", None)
    if loop is not None:
        A, B, dev, err, done = loop(gf, p, hv, cols, z, opts)
    else:
        A, B, dev, err, done = _python_open_loop(engine, gf, p, hv, cols, z, opts)
    if err is not None:
        code, it, r = err
        raise _error(code, done, done * h, r, it)
    _check_dev(engine, gf, p, h, dev)
    return B if wrt == "params" else (A, B)


def _open_inputs(engine, traj, K, u, params, t0, wrt):
    """(t0, the K steps' inputs, the columns of the step vector hv that B differentiates)
    of an open module: u's for wrt None or "u", the runtime parameters' for "params"."""
    from .inputs import step_inputs
    m = len(engine.open["inputs"])
    if t0 is None:
        t0 = float(np.asarray(traj.t, dtype=np.float64)[0]) if len(traj.t) else 0.0
    inputs = step_inputs(engine.open, K, u, params, t0)
    H = 2 + m + len(inputs.params)
    if wrt == "params" and H == 2 + m:
        raise ArgumentError("this model has no runtime parameters", field="wrt")
    return t0, inputs, (slice(2, 2 + m) if wrt != "params" else slice(2 + m, H))


def _python_open_loop(engine, gf, p, hv, cols, z, opts):
    """The Python backend's twin of an open module's hpgen_linearize: (A, B, dev, err,
    steps done)."""
    K, s = len(gf) - 1, 2 * engine.d
    A, B = np.zeros((K, s, s)), np.zeros((K, s, cols.stop - cols.start))
    dev = np.zeros(K)
    for k in range(K):
        code, g1, p1, z, it, r = engine.backend.step(gf[k], p[k], hv[k], z, opts)
        if code != abi.OK:
            return A, B, dev, (code, it, r), k
        dev[k] = max(np.abs(g1 - gf[k + 1]).max(), np.abs(p1 - p[k + 1]).max())
        J, Fs, Yz, Ys, FH, YH = open_partials_at(engine, z, gf[k], p[k], hv[k])
        D = implicit_derivative(J, np.hstack([Fs, FH[:, cols]]), Yz,
                                np.hstack([Ys, YH[:, cols]]))
        A[k], B[k] = D[:, :s], D[:, s:]
    return A, B, dev, None, K
