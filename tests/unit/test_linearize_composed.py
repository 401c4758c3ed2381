"""Integrator.linearize on composed steps, and linearize's Newton starts
(hpgen.runtime.linearize, hpgen/runtime/c/hpgen_linearize.c).

- Composed step Phi(h) = S(gamma_s h) o ... o S(gamma_1 h) (suzuki4 on Stormer-Verlet cay/truncated, a symmetric step): the C call
  (chain rule over the substeps inside hpgen_linearize) equals the product of the substep
  partials built here from the kernels (each substep by full Newton from the guess kernel:
  A = A_s ... A_1, B = sum_i A_s ... A_(i+1) B_i) and the Python backend's loop.
  Tolerances: the runs' z agree bitwise between backends (nz = 3 <= UNROLL_MAX), so C and
  Python differ by the solve's round-off, cond(J) ulp |A| ~ 1e-14: 1e-12 relative; the
  reference's z differs from the run's by the Newton tolerance (1e-14 (1 + |z|)), which moves
  A by |dA/dz| 1e-14: 1e-11 relative.
- Newton starts: linearize takes each step as the run took it (the run's predictor, its
  Newton settings), so with simulate's settings it reproduces the records bit for bit
  (deviation 0.0 on both backends) with exactly the run's Newton iterations, fewer than
  (with the same full Newton) than starting every substep from the guess kernel; with other
  Newton settings (full Newton) the records are reproduced to the Newton tolerance and A
  agrees to 1e-11 relative.
(A composed constrained step: tests/property/test_linearize_constrained.py.)
"""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.runtime import linearize as lz
from hpgen.runtime.newton import NewtonOptions

TOP = """\
name: driven_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0}
inputs: [u0, u1, u2]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2,2]
forces: ["u0", "u1", "u2"]
"""
HEAVY_TOP = """\
name: heavy_top_plain
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2,2]
"""
H, STEPS = 0.05, 40
G0, XI0 = np.eye(3), np.array([0.2, 1.0, 3.0])
U = 0.1 * np.sin(H * np.arange(STEPS))[:, None] * np.array([1.0, -0.5, 0.3])
_INTEG = {}


def _integ(compile_model, text, backend, compose="suzuki4"):
    key = (text, backend, compose)
    if key not in _INTEG:
        _INTEG[key] = compile_model(text, backend=backend, tableau="stormer-verlet",
                                    tau="cay", rkmk="truncated", compose=compose)
    return _INTEG[key]


def _cold_product(integ, traj, k, u=None):
    """(A_k, B_k, Newton iterations) of composed step k from record k: each substep by full
    Newton from the guess kernel at its own state, the chain rule over the substep partials."""
    e, s = integ.engine, 2 * integ.d
    g, p = traj.g[k].ravel(order="F"), traj.mu[k]
    A, B, c, its = np.eye(s), np.zeros((s, 0 if u is None else u.shape[1])), 0.0, 0
    for gi in integ.composition.gammas:
        hv = np.array([gi * H] if u is None else [gi * H, (k + c) * H, *u[k]])
        xi = e.maps.velocity_flat(g, p) if u is None else e.maps.velocity_flat(
            g, p, lv=e.maps.lv(0.0, []))
        z = e.kernel("guess", xi, g, p, hv)[0]
        code, g1, p1, z, it, _ = e.backend.step(g, p, hv, z, NewtonOptions(simplified=False))
        assert code == 0
        its += it
        if u is None:
            Ai, Bi = lz.implicit_derivative(*lz.partials_at(e, z, g, p, hv)), B
        else:
            J, Fs, Yz, Ys, FH, YH = lz.open_partials_at(e, z, g, p, hv)
            D = lz.implicit_derivative(J, np.hstack([Fs, FH[:, 2:]]), Yz,
                                       np.hstack([Ys, YH[:, 2:]]))
            Ai, Bi = D[:, :s], D[:, s:]
        A, B = Ai @ A, Ai @ B + Bi
        g, p, c = np.asarray(g1).ravel(), np.asarray(p1).ravel(), c + gi
    return A, B, its


def _rel(X, Y):
    return np.abs(X - Y).max() / np.abs(Y).max()


def test_composed_open_linearize_is_the_substep_product_on_both_backends(compile_model):
    out = {}
    for b in ("c", "python"):
        integ = _integ(compile_model, TOP, b)
        traj = integ.simulate(G0, H, STEPS, xi0=XI0, u=U)
        (A, B), st = lz.along_with_status(integ.engine, traj, u=U)
        assert A.shape == (STEPS, 6, 6) and B.shape == (STEPS, 6, 3)
        assert st["deviation"] == 0.0 and st["total_iterations"] == traj.newton_iterations
        out[b] = A, B, traj
    (Ac, Bc, traj), (Ap, Bp, _) = out["c"], out["python"]
    assert _rel(Ap, Ac) < 1e-12 and _rel(Bp, Bc) < 1e-12
    integ = _integ(compile_model, TOP, "c")
    for k in (0, 1, 7, STEPS - 1):
        Ar, Br, _ = _cold_product(integ, traj, k, U)
        assert _rel(Ac[k], Ar) < 1e-11 and _rel(Bc[k], Br) < 1e-11, k
    # the parameters' derivative of a model without runtime parameters is refused
    with pytest.raises(Exception, match="no runtime parameters"):
        integ.linearize(traj, u=U, wrt="params")


@pytest.mark.parametrize("compose", ["suzuki4", None])
def test_linearize_takes_the_runs_steps_with_its_predictor(compile_model, compose):
    """The records reproduced bit for bit with the run's iterations (C and Python); full
    Newton instead of the run's simplified Newton: the records to the Newton tolerance, A to
    1e-11, and fewer iterations from the predictor than from the guess kernel."""
    A, full_its = {}, {}
    for b in ("c", "python"):
        integ = _integ(compile_model, HEAVY_TOP, b, compose)
        traj = integ.simulate(G0, H, STEPS, xi0=XI0)
        A[b], st = lz.along_with_status(integ.engine, traj)
        assert st["deviation"] == 0.0, b
        assert st["total_iterations"] == traj.newton_iterations, b
        full, st_full = lz.along_with_status(integ.engine, traj,
                                             newton=NewtonOptions(simplified=False))
        assert 0.0 <= st_full["deviation"] <= 1e-13 * (1 + np.abs(traj.mu).max())
        assert _rel(full, A[b]) < 1e-11
        full_its[b] = st_full["total_iterations"]
    assert _rel(A["python"], A["c"]) < 1e-12
    integ = _integ(compile_model, HEAVY_TOP, "c", compose)
    if compose is not None:
        # full Newton from the predictor against full Newton from the guess kernel
        cold = sum(_cold_product(integ, traj, k)[2] for k in range(STEPS))
        print(f"full Newton iterations over {STEPS} composed steps: from the predictor "
              f"{full_its['c']}, from the guess kernel {cold}")
        assert full_its["c"] == full_its["python"] < cold
