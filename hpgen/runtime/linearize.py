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

z_k is not stored in a Trajectory: it is recovered by taking the steps again exactly as the
run took them: the backend's run is started at record 0 with simulate's first Newton start,
inputs and composition, and step k is taken from record k by the run's own step (the
predictor through the previous solutions, the same Newton settings ``newton=``, full Newton
at step 0; a composed step's substeps with their own predictors). Records of a run with the
same settings are then reproduced bit for bit (C backend; the Python backend to the bits of
its run), so Newton does no more iterations than the run did, and each z_k is the run's
solution. The step's output is compared with the next record (``RECORD_RTOL``): a trajectory
of another module, step size or model is refused. The C backend runs the whole loop in
``hpgen_linearize`` (hpgen_linearize.c), the Python backend here on the module's kernels.py
(``_python_loop``). The two agree to round-off.

A composed step Phi(h) = S(gamma_s h) o ... o S(gamma_1 h) (integrator.compose) is
differentiated by the chain rule over its substeps, A = A_s ... A_1 and
B = sum_i A_s ... A_(i+1) B_i, A_i and B_i the implicit derivatives of substep i at its own
start, solution and step vector (an open substep at time t_k + (gamma_1 + ... +
gamma_(i-1)) h with input u_k), in the same C call.

Open modules (forces, inputs, runtime parameters or t; the step vector
H = [h, t_k, u_k, params], hpgen.runtime.inputs):

    Integrator.linearize(traj, u=U) -> (A (K, 2d, 2d), B (K, 2d, m)),
        B[k] = d(eta_{k+1}, dp_{k+1}) / d u_k
    Integrator.linearize(traj, u=U, wrt="params") -> P (K, 2d, n_runtime_params),
        P[k] = d(eta_{k+1}, dp_{k+1}) / d params (the parameters held fixed over step k only)

from the open kernel's partials in the step vector (FH = dF/dH, YH = dY/dH):
B = YH_u - Yz J^{-1} FH_u, P = YH_par - Yz J^{-1} FH_par. u, params and t0 are simulate's
(u required for a model with inputs; t0 defaults to the trajectory's first time).

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
#: (max-norm, relative to 1 + max|state|). Taken as the run took it, it reproduces the record
#: exactly; another Newton setting (newton=) moves it by the Newton tolerance, ~1e-14;
#: another scheme, step size or model differs by its local error, orders of magnitude above
#: 1e-9 for any step size whose results are meant to be accurate.
RECORD_RTOL = 1e-9


def along(engine, traj, newton=None, u=None, params=None, t0=None, wrt=None):
    """Integrator.linearize: A for a closed module (which takes none of u, params, t0, wrt:
    ArgumentError naming the one given), (A, B) or P for an open one (see the module
    docstring); newton: the Newton settings (Engine.options resolves them)."""
    return along_with_status(engine, traj, newton, u, params, t0, wrt)[0]


def along_with_status(engine, traj, newton=None, u=None, params=None, t0=None, wrt=None):
    """(along's result, the run's status dict over the K steps: Newton iterations,
    Jacobians (one per substep for the derivative included), and ``deviation`` the largest
    max-norm distance of a recomputed step from its record: 0.0 when the records are
    reproduced bit for bit). Raises ArgumentError for a bad
    trajectory, u, params, t0 or wrt, ConvergenceError if a step's Newton fails."""
    if engine.open is None:
        for name, v in (("u", u), ("params", params), ("t0", t0), ("wrt", wrt)):
            if v is not None:
                raise ArgumentError("this model has no forces, inputs, runtime "
                                    f"parameters or t: linearize takes no {name}",
                                    field=name)
    if wrt not in WRT:
        raise ArgumentError(f"expected wrt=None, 'u' or 'params', got {wrt!r}", field="wrt")
    opts = engine.options(newton)
    gf, p, h = _check_traj(engine, traj)
    K = len(gf) - 1
    inputs, cols, lv = None, slice(0, 0), ()
    if engine.open is not None:
        t0, inputs, cols = _open_inputs(engine, traj, K, u, params, t0, wrt)
        lv = engine.maps.lv(t0, inputs.params)
    # the run's first Newton start, as simulate makes it (FirstStep.start)
    g0 = gf[0].reshape(engine.n, engine.n, order="F")
    gf0, mu0, xi0 = engine.initial(g0, None, p[0], lv)
    z0 = engine.first_step.start(gf0, mu0, xi0, h, opts, inputs)
    run = engine.backend.start(gf[0], p[0], z0, inputs)
    if hasattr(engine.backend, "linearize"):
        A, B, dev, st, done = engine.backend.linearize(run, gf, p, h, cols, opts)
    else:
        A, B, dev, st, done = _python_loop(engine, run, gf, p, h, cols, opts)
    if st["code"] != abi.OK:
        raise _error(st["code"], done, done * h, st["residual"], st["iterations"])
    _check_dev(engine, gf, p, h, dev)
    st["deviation"] = float(dev.max(initial=0.0))
    if inputs is None:
        return A, st
    return (B if wrt == "params" else (A, B)), st


def _python_loop(engine, run, gf, p, h, cols, opts):
    """The Python backend's twin of hpgen_linearize: ``run`` (loop.Run at record 0) stepped
    from each record k as the run steps, the substeps' derivatives chained (module
    docstring): (A (K, 2d, 2d), B (K, 2d, nc), dev (K,), status, steps done)."""
    from .loop import new_status
    K, s, nc = len(gf) - 1, 2 * engine.d, cols.stop - cols.start
    A, B, dev = np.zeros((K, s, s)), np.zeros((K, s, nc)), np.zeros(K)
    st = new_status()
    start = [gf[0], p[0]]
    k = 0

    def after(i, hv):
        """The derivative of substep i at the run's solution, chained into A[k], B[k]."""
        g, pk = start
        z, hv = np.array(run.z, dtype=np.float64), np.array(hv, dtype=np.float64)
        if engine.open is None:
            Ai, Bi = implicit_derivative(*partials_at(engine, z, g, pk, hv)), B[k]
        else:
            J, Fs, Yz, Ys, FH, YH = open_partials_at(engine, z, g, pk, hv)
            D = implicit_derivative(J, np.hstack([Fs, FH[:, cols]]), Yz,
                                    np.hstack([Ys, YH[:, cols]]))
            Ai, Bi = D[:, :s], D[:, s:]
        st["jacobians"] += 1
        if not (np.isfinite(Ai).all() and np.isfinite(Bi).all()):
            return abi.NONFINITE
        A[k], B[k] = (Ai, Bi) if i == 0 else (Ai @ A[k], Ai @ B[k] + Bi)
        start[:] = np.array(run.g, dtype=np.float64), np.array(run.p, dtype=np.float64)
        return abi.OK

    for k in range(K):
        run.g, run.p = gf[k].tolist(), p[k].tolist()
        start[:] = gf[k], p[k]
        if engine.backend.run_step(run, h, opts, st, after) != abi.OK:
            return A, B, dev, st, k
        dev[k] = max(np.abs(np.array(run.g) - gf[k + 1]).max(),
                     np.abs(np.array(run.p) - p[k + 1]).max())
    st["step"] = K
    return A, B, dev, st, K


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
