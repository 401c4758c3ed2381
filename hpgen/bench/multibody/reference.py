"""An independent reference solution of the ball-jointed chain: its equations of motion in
reduced coordinates integrated by SciPy's DOP853 at tight tolerances.

Derivation (Newton-Euler, the joints eliminated from the state; conventions of
:mod:`hpgen.bench.multibody.chain`: link frame at the centre of mass, top point a, bottom
point -a, r_i = R_i a in the world):

State: per link the world quaternion Q_i (body -> world, scalar first) and the body angular
velocity omega_i; 7N numbers. The centres of mass are not integrated: the joints give
x_i = -r_i - 2 sum_(k<i) r_k, so the position constraints hold at every time by construction
and the velocity constraints too (v_i from omega, :func:`chain.velocities`). Kinematics:
dQ_i/dt = Q_i (x) (0, omega_i) / 2.

Dynamics: F_i is the force (world) that link i-1 (the world for i = 0) exerts on link i at
link i's top point; link i feels F_i at its top and -F_(i+1) at its bottom (F_N = 0).
  Newton (world):  m x_i'' = F_i - F_(i+1) - m g e3
  Euler (body):    J omega_i' + omega_i x J omega_i = a x R_i^T (F_i + F_(i+1))
The joints at the acceleration level (the second time derivative of
x_i + R_i a = x_(i-1) - R_(i-1) a, using d^2(R c)/dt^2 = R (omega' x c + omega x (omega x c))):
  x_i'' - R_i a^ omega_i' - x_(i-1)'' - R_(i-1) a^ omega_(i-1)'
      = -R_i omega_i x (omega_i x a) - R_(i-1) omega_(i-1) x (omega_(i-1) x a)
(the terms of i-1 absent for i = 0, where the top point is fixed). These 9N linear equations
in (x_i'', omega_i', F_i) couple only neighbouring links: ordered link by link the matrix is
banded (17 sub- and super-diagonals) and LAPACK's banded solver (scipy.linalg.solve_banded)
solves it in O(N). Only omega' is kept; x'' and the joint forces F are by-products. No
Baumgarte terms are needed since positions are never integrated; the only drift is of the
quaternions' norm (R is computed from Q / |Q|), which :func:`solve` reports.

An optional load(t, R) adds external forces (world, at the centres) and torques (body) to
the right sides of Newton's and Euler's equations (a forced chain).

Nothing here comes from MuJoCo, Pinocchio or hpgen's derivation.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hpgen.errors import HpgenError

from .chain import (
    ChainSpec,
    ChainState,
    cross,
    from_joint,
    from_rotations,
    hat,
    matrix_to_quat,
    quat_to_matrix,
)

BAND = 17


class ChainDynamics:
    """The chain's vector field y' = f(y) on y = (Q (N,4) row-major, omega (N,3)).

    :meth:`accelerations` gives (x'', omega', F) for rotations and angular velocities."""

    def __init__(self, spec: ChainSpec, load=None):
        from scipy.linalg import solve_banded

        self.load = load

        self._solve_banded = solve_banded
        self.spec = spec
        n = spec.n
        self.size = 9 * n
        self.J = spec.inertia
        self.a = spec.a
        self.ahat = hat(self.a)
        ab = np.zeros((2 * BAND + 1, self.size))
        eye = np.eye(3)
        for i in range(n):
            row, col = 9 * i, 9 * i
            self._put(ab, row, col, spec.mass * eye)              # Newton: m x_i''
            self._put(ab, row, col + 6, -eye)                     # - F_i
            if i + 1 < n:
                self._put(ab, row, col + 15, eye)                 # + F_(i+1)
            self._put(ab, row + 3, col + 3, np.diag(self.J))     # Euler: J omega_i'
            self._put(ab, row + 6, col, eye)                      # joint: x_i''
            if i > 0:
                self._put(ab, row + 6, col - 9, -eye)             # - x_(i-1)''
        self.template = ab

        def block_index(row0, col0):
            r = row0[:, None, None] + np.arange(3)[None, :, None]
            c = col0[:, None, None] + np.arange(3)[None, None, :]
            r, c = np.broadcast_arrays(r, c)
            return (BAND + r - c, c)

        links = np.arange(n)
        self.ix_euler_f = block_index(9 * links + 3, 9 * links + 6)
        self.ix_euler_fnext = block_index(9 * links[:-1] + 3, 9 * links[:-1] + 15)
        self.ix_joint_w = block_index(9 * links + 6, 9 * links + 3)
        self.ix_joint_wprev = block_index(9 * links[1:] + 6, 9 * links[1:] - 6)

    @staticmethod
    def _put(ab, row, col, block):
        for r in range(3):
            for c in range(3):
                ab[BAND + row + r - col - c, col + c] = block[r, c]

    def accelerations(self, R: np.ndarray, omega: np.ndarray, t: float = 0.0):
        """(x'' (N,3) world, omega' (N,3) body, F (N,3) world joint forces); with a load, its
        force (world) and torque (body) at time t added to Newton's and Euler's sides."""
        spec, n = self.spec, self.spec.n
        ab = self.template.copy()
        lever_force = -self.ahat @ np.swapaxes(R, 1, 2)        # -a^ R_i^T
        lever_acc = -R @ self.ahat                             # -R_i a^
        ab[self.ix_euler_f] = lever_force
        ab[self.ix_euler_fnext] = lever_force[:-1]
        ab[self.ix_joint_w] = lever_acc
        ab[self.ix_joint_wprev] = lever_acc[:-1]
        Jw = self.J * omega
        centripetal = np.einsum("nij,nj->ni", R, cross(omega, cross(omega, self.a)))
        rhs = np.empty((n, 9))
        rhs[:, 0:3] = [0.0, 0.0, -spec.mass * spec.g]
        rhs[:, 3:6] = -cross(omega, Jw)
        rhs[:, 6:9] = -centripetal
        rhs[1:, 6:9] -= centripetal[:-1]
        if self.load is not None:
            force, torque = self.load(t, R)
            rhs[:, 0:3] += force
            rhs[:, 3:6] += torque
        sol = self._solve_banded((BAND, BAND), ab, rhs.reshape(-1), overwrite_ab=True,
                           check_finite=False).reshape(n, 9)
        return sol[:, 0:3], sol[:, 3:6], sol[:, 6:9]

    def __call__(self, t: float, y: np.ndarray) -> np.ndarray:
        n = self.spec.n
        Q = y[:4 * n].reshape(n, 4)
        omega = y[4 * n:].reshape(n, 3)
        R = quat_to_matrix(Q)
        _, domega, _ = self.accelerations(R, omega, t)
        w, u = Q[:, :1], Q[:, 1:]
        dQ = 0.5 * np.concatenate([-np.sum(u * omega, axis=1, keepdims=True),
                                   w * omega + cross(u, omega)], axis=1)
        return np.concatenate([dQ.reshape(-1), domega.reshape(-1)])


@dataclass(frozen=True)
class ReferenceSolution:
    """The reference at the requested times: ``states[k]`` at ``times[k]``; ``nfev`` the
    vector-field evaluations; ``quat_drift`` the max | |Q_i| - 1 | over the output times."""
    times: np.ndarray
    states: tuple
    nfev: int
    quat_drift: float

    @property
    def final(self) -> ChainState:
        return self.states[-1]


def pack(spec: ChainSpec, state: ChainState) -> np.ndarray:
    """y = (world quaternions, body angular velocities) of a maximal-coordinate state."""
    return np.concatenate([matrix_to_quat(state.R).reshape(-1), np.ravel(state.omega)])


def unpack(spec: ChainSpec, y: np.ndarray) -> ChainState:
    n = spec.n
    return from_rotations(spec, quat_to_matrix(y[:4 * n].reshape(n, 4)),
                          y[4 * n:].reshape(n, 3))


def solve(spec: ChainSpec, qpos: np.ndarray, qvel: np.ndarray, times,
          rtol: float = 1e-13, atol: float = 1e-13, load=None) -> ReferenceSolution:
    """Integrate from joint coordinates (qpos, qvel) (MuJoCo's convention) at t = 0 to each
    of ``times`` (increasing, > 0) with DOP853 at (rtol, atol). ``load(t, R)`` -> (force
    (N,3) world at the centres, torque (N,3) body): external loads besides gravity."""
    from scipy.integrate import solve_ivp

    times = np.atleast_1d(np.asarray(times, dtype=float))
    y0 = pack(spec, from_joint(spec, qpos, qvel))
    sol = solve_ivp(ChainDynamics(spec, load), (0.0, float(times[-1])), y0, method="DOP853",
                    t_eval=times, rtol=rtol, atol=atol)
    if not sol.success:
        raise HpgenError(f"DOP853 failed on the {spec.n}-link chain: {sol.message}; "
                         "loosen rtol / atol")
    n = spec.n
    norms = np.linalg.norm(sol.y[:4 * n].T.reshape(len(times), n, 4), axis=2)
    states = tuple(unpack(spec, sol.y[:, k]) for k in range(len(times)))
    return ReferenceSolution(times, states, int(sol.nfev), float(np.abs(norms - 1).max()))
