"""Pinocchio as a peer on the chain: the same N-link chain as a ``pinocchio.Model`` built in
Python, stepped by RKMK4 (below) with Pinocchio's articulated-body algorithm
(``pinocchio.aba``) or its mass matrix for the accelerations and ``pinocchio.integrate`` (the
exponential map of each spherical joint) for the positions.

Model: joint i is a ``JointModelSpherical`` placed at its parent's bottom point ((0, 0, 0) in
the world for joint 0, (0, 0, -length) in the parent joint's frame otherwise), carrying a body
of mass ``mass``, centre (0, 0, -length/2) and rotational inertia diag(:func:`chain.
capsule_inertia`) about it; gravity (0, 0, -g). Pinocchio's configuration of a spherical joint is
its quaternion with the scalar LAST (x y z w), its velocity the angular velocity relative to
the parent in the joint's (child's) frame: :func:`to_pinocchio` / :func:`from_pinocchio`
convert from and to MuJoCo's order (scalar first), the only difference.

The step is RKMK4, classical RK4 in the exponential chart of each spherical joint centred
at the step's start q (Munthe-Kaas): with f(q, v) the joint accelerations, q (+) phi =
pinocchio.integrate(q, phi) = q exp(phi) per joint and dexpinv(phi) = J_r(phi)^-1 the inverse
right Jacobian of SO3 (the chart's velocity phi' = dexpinv(phi) v, v the body velocity),
    phi1 = 0,           v1 = v,            k1 = v1,                    a1 = f(q, v1)
    phi2 = h/2 k1,      v2 = v + h/2 a1,   k2 = dexpinv(phi2) v2,      a2 = f(q (+) phi2, v2)
    phi3 = h/2 k2,      v3 = v + h/2 a2,   k3 = dexpinv(phi3) v3,      a3 = f(q (+) phi3, v3)
    phi4 = h k3,        v4 = v + h a3,     k4 = dexpinv(phi4) v4,      a4 = f(q (+) phi4, v4)
    q+ = q (+) h (k1 + 2 k2 + 2 k3 + k4) / 6,    v+ = v + h (a1 + 2 a2 + 2 a3 + a4) / 6.
Order 4. (Without the dexpinv factors, combining the stage velocities as if they lived in
one chart, the scheme is only order 2 on ball joints.)
with q (+) w = pinocchio.integrate(q, w).

Accelerations f(q, v) (``dynamics``): ``"aba"``, Pinocchio's articulated-body algorithm (O(N));
or ``"crba"``, the joint-space mass matrix M (composite rigid bodies, ``pinocchio.crba``)
factored by Pinocchio's own Cholesky (``pinocchio.cholesky``, which follows the tree's
sparsity: dense for a chain, O(N^3)) with the bias forces from
``pinocchio.nonLinearEffects`` (MuJoCo's way). On long chains of these thin links ABA loses accuracy quickly with N
(its articulated inertias are eliminated joint by joint, and round-off in them grows from
link to link), while M, ill-conditioned as it is, still gives the accelerations to
cond(M) times round-off: check ``accelerations`` against the reference before trusting ABA
at a new N. Pinocchio's Python wheel offers no C-level time loop
(no rollout, and this build has neither its CasADi nor its CppAD bindings; ``abaInParallel``
batches independent states, not the stages of one trajectory), so the step loop is Python
around the C++ calls; :func:`run` also reports the time of the acceleration evaluations
alone (mostly C++: a lower bound of what a C loop would cost).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hpgen.errors import ArgumentError

from . import require
from .chain import ChainSpec, cross


def model(spec: ChainSpec):
    """The chain as a pinocchio.Model (see the module docstring)."""
    pin = require("pinocchio")
    m = pin.Model()
    parent = 0
    inertia = pin.Inertia(spec.mass, np.array([0.0, 0.0, -spec.length / 2]),
                          np.diag(spec.inertia))
    for i in range(spec.n):
        offset = np.zeros(3) if i == 0 else np.array([0.0, 0.0, -spec.length])
        joint = m.addJoint(parent, pin.JointModelSpherical(), pin.SE3(np.eye(3), offset),
                           f"ball{i}")
        m.appendBodyToJoint(joint, inertia, pin.SE3.Identity())
        parent = joint
    m.gravity = pin.Motion(np.array([0.0, 0.0, -spec.g]), np.zeros(3))
    return m


DYNAMICS = ("aba", "crba")


def accelerations(m, data, dynamics: str = "aba"):
    """The joint accelerations f(q, v) (no joint torques) of model ``m`` by ``dynamics``."""
    pin = require("pinocchio")
    if dynamics not in DYNAMICS:
        raise ArgumentError(f"expected one of {', '.join(DYNAMICS)}, got {dynamics!r}",
                            field="dynamics")
    if dynamics == "aba":
        tau = np.zeros(m.nv)
        return lambda q, v: pin.aba(m, data, q, v, tau).copy()

    def crba(q, v):
        pin.crba(m, data, q)
        pin.cholesky.decompose(m, data)
        return pin.cholesky.solve(m, data, -pin.nonLinearEffects(m, data, q, v))

    return crba


def to_pinocchio(qpos: np.ndarray) -> np.ndarray:
    """MuJoCo's ball-joint quaternions (w x y z per joint) -> Pinocchio's (x y z w)."""
    return np.roll(np.asarray(qpos, dtype=float).reshape(-1, 4), -1, axis=1).reshape(-1)


def from_pinocchio(q: np.ndarray) -> np.ndarray:
    """Pinocchio's spherical-joint quaternions (x y z w) -> MuJoCo's (w x y z)."""
    return np.roll(np.asarray(q, dtype=float).reshape(-1, 4), 1, axis=1).reshape(-1)


def dexpinv(phi: np.ndarray, w: np.ndarray) -> np.ndarray:
    """J_r(phi)^-1 w per row of phi, w (N,3): w + phi x w / 2 + c(t) phi x (phi x w) with
    t = |phi|, c = 1/t^2 - (1 + cos t) / (2 t sin t) (its series 1/12 + t^2/720 below 1e-3)."""
    t2 = np.einsum("ni,ni->n", phi, phi)
    t = np.sqrt(t2)
    if t.min() >= 1e-3:
        c = 1.0 / t2 - (1.0 + np.cos(t)) / (2.0 * t * np.sin(t))
    else:
        small = t < 1e-3
        safe = np.where(small, 1.0, t)
        c = np.where(small, 1.0 / 12.0 + t2 / 720.0,
                     1.0 / safe ** 2 - (1.0 + np.cos(safe)) / (2.0 * safe * np.sin(safe)))
    pw = cross(phi, w)
    return w + 0.5 * pw + c[:, None] * cross(phi, pw)


@dataclass(frozen=True)
class PinocchioRun:
    """An RKMK4 run: the final joint state in MuJoCo's convention, the energy (J; Pinocchio's
    computeMechanicalEnergy) at ``times``, the wall time of the step loop (s),
    ``dynamics_seconds`` the thread's CPU time of its 4 acceleration evaluations per step
    alone (from 100 evaluations at the start state), ``cpu_seconds`` the thread's CPU time of
    the step loop; ``stable`` False when a state or an energy is not finite (the run stops at the
    first such sample, ``steps`` says where)."""
    qpos: np.ndarray
    qvel: np.ndarray
    times: np.ndarray
    energy: np.ndarray
    seconds: float
    dynamics_seconds: float
    steps: int
    stable: bool
    cpu_seconds: float = float("nan")


def run(spec: ChainSpec, qpos, qvel, dt: float, steps: int, sample: int = 10,
        dynamics: str = "aba") -> PinocchioRun:
    """``steps`` RKMK4 steps of size dt from (qpos, qvel) (MuJoCo's convention) at t = 0,
    accelerations by ``dynamics``; the energy of every ``sample``-th state and of the last."""
    import time

    pin = require("pinocchio")
    for name, value in (("steps", steps), ("sample", sample)):
        if not isinstance(value, (int, np.integer)) or value < 1:
            raise ArgumentError(f"expected a positive integer, got {value!r}", field=name)
    if not (np.isfinite(dt) and dt > 0):
        raise ArgumentError(f"expected a positive time step, got {dt!r}", field="dt")
    m = model(spec)
    data = m.createData()
    f = accelerations(m, data, dynamics)
    integrate = pin.integrate
    q = to_pinocchio(qpos)
    v = np.array(qvel, dtype=float)
    q0, v0 = q.copy(), v.copy()
    h, h2, h6 = dt, dt / 2, dt / 6
    n = spec.n
    marks, energy = [0], [pin.computeMechanicalEnergy(m, data, q, v)]
    seconds = cpu = 0.0
    done = 0
    with np.errstate(all="ignore"):     # a blow-up is reported by ``stable``
        while done < steps:
            k = min(sample, steps - done)
            start, start_cpu = time.perf_counter(), time.thread_time()
            for _ in range(k):
                a1 = f(q, v)
                phi = h2 * v
                v2 = v + h2 * a1
                a2 = f(integrate(m, q, phi), v2)
                k2 = dexpinv(phi.reshape(n, 3), v2.reshape(n, 3)).reshape(-1)
                phi = h2 * k2
                v3 = v + h2 * a2
                a3 = f(integrate(m, q, phi), v3)
                k3 = dexpinv(phi.reshape(n, 3), v3.reshape(n, 3)).reshape(-1)
                phi = h * k3
                v4 = v + h * a3
                a4 = f(integrate(m, q, phi), v4)
                k4 = dexpinv(phi.reshape(n, 3), v4.reshape(n, 3)).reshape(-1)
                q = integrate(m, q, h6 * (v + 2.0 * (k2 + k3) + k4))
                v = v + h6 * (a1 + 2.0 * (a2 + a3) + a4)
            cpu += time.thread_time() - start_cpu
            seconds += time.perf_counter() - start
            done += k
            marks.append(done)
            energy.append(pin.computeMechanicalEnergy(m, data, q, v))
            if not (np.isfinite(energy[-1]) and np.isfinite(v).all()):
                break
    reps = 100
    start = time.thread_time()
    for _ in range(reps):
        f(q0, v0)
    dynamics_seconds = (time.thread_time() - start) / reps * 4 * done
    stable = bool(np.isfinite(energy[-1]) and np.isfinite(v).all())
    return PinocchioRun(from_pinocchio(q), v.copy(), dt * np.asarray(marks),
                        np.asarray(energy), seconds, dynamics_seconds, done, stable, cpu)
