"""Shared helpers of tests/hard_cases (issue 5): model texts, so(3)/se(3) tools written from
the textbook formulas (no hpgen import), the exact free rigid body, error measures.

Independent of hpgen on purpose: dexp^{-1} is formed as the inverse of phi_1(ad_x) =
(e^{ad_x} - I) / ad_x, computed with scipy.linalg.expm on the augmented matrix
[[ad_x, I], [0, 0]] (no branch, no series in s = |omega|^2), so it can judge hpgen's
Taylor/exact branches at their switch point.
"""
from __future__ import annotations

import numpy as np

import hpgen
from scipy.linalg import expm

from reference import SO3Problem, reference

FREE_INERTIA = np.array([2.0, 1.0, 0.6666666666666666])   # tests/conftest.py FREE_BODY

# A stiff spring in the plane: g = [[I, x], [0, 1]] in R2 (3 x 3), xi the velocity,
# omega = sqrt(k) = 100.
SPRING = """
name: spring
group: R2
parameters: {k: 10000.0}
lagrangian: 0.5*(xi[0]**2 + xi[1]**2) - 0.5*k*(x[0]**2 + x[1]**2)
"""
SPRING_OMEGA = 100.0

# The heavy top of tests/conftest.py with a stiff potential: Mg = 1e4, so the small
# oscillations about the hanging equilibrium have omega = sqrt(Mg / I_1) = 100 (axis 1).
STIFF_TOP = """
name: stifftop
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 10000.0, chi: [0.0, 0.0, 1.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*(R[2,0]*chi[0] + R[2,1]*chi[1] + R[2,2]*chi[2])
"""
STIFF_TOP_OMEGA = 100.0


def hat3(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]],
                    dtype=np.result_type(w, float))


def ad_matrix(x):
    """Matrix of y -> ad_x y: so(3) (d = 3) or se(3) with x = (omega, v) (d = 6)."""
    x = np.asarray(x)
    if x.shape == (3,):
        return hat3(x)
    W, V = hat3(x[:3]), hat3(x[3:])
    A = np.zeros((6, 6), dtype=np.result_type(x, float))
    A[:3, :3], A[3:, :3], A[3:, 3:] = W, V, W
    return A


def dexp_inv(x):
    """dexp^{-1}_x = phi_1(ad_x)^{-1}, phi_1(z) = (e^z - 1)/z, via expm (analytic in x, so
    complex-step differentiable)."""
    A = ad_matrix(x)
    d = A.shape[0]
    B = np.zeros((2 * d, 2 * d), dtype=A.dtype)
    B[:d, :d], B[:d, d:] = A, np.eye(d)
    return np.linalg.inv(expm(B)[:d, d:])


def group_exp(x):
    """exp of x^ in SO(3) (3 x 3) or SE(3) (4 x 4, x = (omega, v))."""
    x = np.asarray(x, float)
    if x.shape == (3,):
        return expm(hat3(x))
    X = np.zeros((4, 4))
    X[:3, :3], X[:3, 3] = hat3(x[:3]), x[3:]
    return expm(X)


def rotation_angle(A, B):
    """Angle (rad) of the rotation A^T B, A and B in SO(3) (robust near 0 and pi)."""
    C = A.T @ B
    s = 0.5 * np.linalg.norm([C[2, 1] - C[1, 2], C[0, 2] - C[2, 0], C[1, 0] - C[0, 1]])
    c = 0.5 * (np.trace(C) - 1.0)
    return float(np.arctan2(s, c))


def free_body_reference(pi0, t, R0=None):
    """Exact (R(t), Pi(t)) of the free rigid body with FREE_INERTIA: hpgen.analysis.exact
    (Jacobi elliptic functions) when present, else DOP853 at rtol 1e-13 (tests/reference.py)."""
    R0 = np.eye(3) if R0 is None else np.asarray(R0, float)
    t = np.atleast_1d(np.asarray(t, float))
    try:
        from hpgen.analysis.exact import free_rigid_body_attitude
    except ImportError:
        free_rigid_body_attitude = None
    if free_rigid_body_attitude is not None:
        R, Pi = free_rigid_body_attitude(FREE_INERTIA, pi0, R0, t)
        return np.asarray(R), np.asarray(Pi)
    if t[0] != 0.0:
        raise ValueError("the DOP853 fallback needs t[0] = 0")
    return reference(SO3Problem(FREE_INERTIA), R0, pi0, t, rtol=1e-13)


def envelope_drift(t, err):
    """(max |err| over the first tenth, over the last tenth, slope of a linear fit)."""
    tenth = max(1, len(err) // 10)
    first, last = np.abs(err[:tenth]).max(), np.abs(err[-tenth:]).max()
    slope = np.polyfit(t, err, 1)[0]
    return float(first), float(last), float(slope)


def check_reported_failure(err, h, every=1):
    """A ConvergenceError must say where (step, time = step * h), how bad (residual) and
    how long (iterations), in one line telling what to do; its partial trajectory holds
    the records computed before the failure, all finite. Returns a short summary."""
    msg = str(err)
    assert "\n" not in msg
    assert msg.startswith(f"step {err.step} (t = ") and "try a smaller h" in msg, msg
    # a DomainError may be raised before any Newton iteration (the start is outside the chart)
    assert err.step >= 0 and (err.iterations >= 1 or isinstance(err, hpgen.DomainError))
    assert err.time == err.step * h
    part = err.partial
    assert part is not None and part.partial and len(part) == err.step // every + 1
    assert np.isfinite(part.g).all() and np.isfinite(part.mu).all()
    return f"{type(err).__name__} at step {err.step}, res {err.residual:.1e}, it {err.iterations}"
