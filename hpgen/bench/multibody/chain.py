"""The N-link 3-D pendulum chain of capsules with ball joints: parameters, state convention,
conversions from and to joint coordinates (MuJoCo's qpos / qvel), energy.

Physical model (SI units). N identical links, each a solid capsule of mass ``mass`` = 1 kg:
a cylinder of length ``length`` = 0.5 m between the two joint points and radius ``radius``
= 0.05 m, closed by two hemispheres of the same radius (so the capsule's total length is
length + 2 radius; the joints sit at the centres of the end caps' flat faces, i.e. on the
segment's end points). Uniform density, so the centre of mass is the segment's midpoint and
the inertia about it is diagonal in the link frame with :func:`capsule_inertia`'s values.
Gravity ``g`` = 9.81 m/s^2 along -z (world). No contact, no damping, no joint limits.

Link frame (body frame) of link i: origin at its centre of mass, z axis along the link
pointing from the bottom joint point to the top one. In the link frame the top joint point is
``a = (0, 0, +length/2)`` and the bottom one ``b = -a``. Link i hangs from its top point:
link 0's top point is pinned to the world origin by a ball joint, and the ball joint between
links i-1 and i joins the bottom point of i-1 to the top point of i. With every rotation the
identity the chain hangs straight down: x_i = (0, 0, -(i + 1/2) length).

State in maximal coordinates (:class:`ChainState`), for every link i:
- ``R[i]``: rotation body -> world (3 x 3, SO3), so a world vector is R[i] @ (body vector);
- ``x[i]``: centre of mass in the world frame (m);
- ``omega[i]``: angular velocity in the BODY frame, omega^ = R^T dR/dt (rad/s);
- ``v[i]``: velocity of the centre of mass in the WORLD frame, dx/dt (m/s). (The body-frame
  linear velocity of SE3 is R[i].T @ v[i].)
Constraints: x_0 + R_0 a = 0 and x_i + R_i a = x_(i-1) + R_(i-1) b (i >= 1), and their time
derivatives.

Energy: kinetic sum_i (m |v_i|^2 / 2 + omega_i . J omega_i / 2), potential sum_i m g z_i
(zero at the height of the pin, so every link below the pin has negative potential energy).

Joint coordinates (MuJoCo's convention for ball joints, which Pinocchio's spherical joint
shares up to the quaternion's component order): joint i carries the unit quaternion q_i
(scalar first, w x y z) of the rotation of link i relative to its parent, R_i = R_(i-1) R(q_i)
(R_(-1) = identity), and the angular velocity of link i relative to its parent expressed in
link i's frame, qvel_i = omega_i - R(q_i)^T omega_(i-1). Arrays ``qpos`` have 4N entries
(q_0, q_1, ...), ``qvel`` 3N.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hpgen.errors import ArgumentError


@dataclass(frozen=True)
class ChainSpec:
    """The chain's parameters (SI units); the defaults are the benchmark's chain."""
    n: int
    mass: float = 1.0
    length: float = 0.5
    radius: float = 0.05
    g: float = 9.81
    #: principal moments (Ixx, Iyy, Izz) about the centre of mass in the link frame, for a
    #: link that is not the capsule; None: the capsule's (:func:`capsule_inertia`)
    moments: tuple | None = None

    def __post_init__(self):
        if not isinstance(self.n, (int, np.integer)) or isinstance(self.n, bool) or self.n < 1:
            raise ArgumentError(f"expected a positive integer number of links, got {self.n!r}",
                                field="n")
        for name in ("mass", "length", "radius"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value > 0):
                raise ArgumentError(f"expected a positive finite number, got {value!r}",
                                    field=name)
        if self.moments is not None:
            J = np.asarray(self.moments, dtype=float)
            if J.shape != (3,) or not (np.isfinite(J).all() and (J > 0).all()):
                raise ArgumentError(f"expected three positive finite moments, got "
                                    f"{self.moments!r}", field="moments")

    @property
    def inertia(self) -> np.ndarray:
        """Principal moments (Ixx, Iyy, Izz) about the centre of mass in the link frame:
        ``moments`` when given, else the capsule's."""
        if self.moments is not None:
            return np.asarray(self.moments, dtype=float)
        return capsule_inertia(self.mass, self.length, self.radius)

    @property
    def a(self) -> np.ndarray:
        """The top joint point in the link frame (the bottom one is -a)."""
        return np.array([0.0, 0.0, 0.5 * self.length])


def capsule_inertia(mass: float, length: float, radius: float) -> np.ndarray:
    """Principal moments of inertia (kg m^2) of a solid uniform capsule about its centre of
    mass: a cylinder (length, radius) along z and two hemispheres, mass split by volume.

    A hemisphere of mass mh has (83/320) mh r^2 about a transverse axis through its own
    centroid, which lies 3r/8 from its flat face (parallel axis theorem to the capsule's
    centre at distance length/2 + 3r/8), and (2/5) mh r^2 about the axis."""
    r, h = radius, length
    v_cyl, v_sph = np.pi * r * r * h, 4.0 / 3.0 * np.pi * r ** 3
    m_cyl = mass * v_cyl / (v_cyl + v_sph)
    m_hemi = 0.5 * mass * v_sph / (v_cyl + v_sph)
    axial = 0.5 * m_cyl * r * r + 2.0 * 0.4 * m_hemi * r * r
    transverse = (m_cyl * (r * r / 4.0 + h * h / 12.0)
                  + 2.0 * m_hemi * (83.0 / 320.0 * r * r + (h / 2.0 + 3.0 * r / 8.0) ** 2))
    return np.array([transverse, transverse, axial])


@dataclass(frozen=True)
class ChainState:
    """Maximal coordinates of the chain (see the module docstring): R (N,3,3) body -> world,
    x (N,3) centres of mass (world), omega (N,3) body angular velocities, v (N,3) world
    linear velocities of the centres of mass."""
    R: np.ndarray
    x: np.ndarray
    omega: np.ndarray
    v: np.ndarray


def hat(w: np.ndarray) -> np.ndarray:
    """Skew matrices of the rows of w (..., 3) -> (..., 3, 3): hat(w) @ u = w x u."""
    w = np.asarray(w, dtype=float)
    out = np.zeros(w.shape[:-1] + (3, 3))
    out[..., 0, 1], out[..., 0, 2] = -w[..., 2], w[..., 1]
    out[..., 1, 0], out[..., 1, 2] = w[..., 2], -w[..., 0]
    out[..., 2, 0], out[..., 2, 1] = -w[..., 1], w[..., 0]
    return out


def cross(u: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Row-wise cross products of (N,3) arrays (np.cross's overhead dominates at these
    sizes)."""
    out = np.empty(np.broadcast_shapes(u.shape, w.shape))
    out[..., 0] = u[..., 1] * w[..., 2] - u[..., 2] * w[..., 1]
    out[..., 1] = u[..., 2] * w[..., 0] - u[..., 0] * w[..., 2]
    out[..., 2] = u[..., 0] * w[..., 1] - u[..., 1] * w[..., 0]
    return out


def quat_to_matrix(q: np.ndarray) -> np.ndarray:
    """Rotation matrices of quaternions (..., 4), scalar first; normalised first."""
    q = np.asarray(q, dtype=float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    out = np.empty(q.shape[:-1] + (3, 3))
    out[..., 0, 0] = 1 - 2 * (y * y + z * z)
    out[..., 0, 1] = 2 * (x * y - w * z)
    out[..., 0, 2] = 2 * (x * z + w * y)
    out[..., 1, 0] = 2 * (x * y + w * z)
    out[..., 1, 1] = 1 - 2 * (x * x + z * z)
    out[..., 1, 2] = 2 * (y * z - w * x)
    out[..., 2, 0] = 2 * (x * z - w * y)
    out[..., 2, 1] = 2 * (y * z + w * x)
    out[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return out


def matrix_to_quat(R: np.ndarray) -> np.ndarray:
    """Unit quaternions (scalar first, w >= 0) of rotation matrices (..., 3, 3) (Shepperd:
    the largest of w^2, x^2, y^2, z^2 is computed from the trace, the rest from it)."""
    R = np.asarray(R, dtype=float)
    flat = R.reshape(-1, 3, 3)
    out = np.empty((flat.shape[0], 4))
    for k, m in enumerate(flat):
        diag = np.array([m[0, 0] + m[1, 1] + m[2, 2], m[0, 0], m[1, 1], m[2, 2]])
        four = np.array([1 + diag[0], 1 + 2 * diag[1] - diag[0], 1 + 2 * diag[2] - diag[0],
                         1 + 2 * diag[3] - diag[0]])
        i = int(np.argmax(four))
        s = 2.0 * np.sqrt(four[i])     # 4 * the i-th component
        if i == 0:
            comp = [s / 4, (m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s]
        elif i == 1:
            comp = [(m[2, 1] - m[1, 2]) / s, s / 4, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s]
        elif i == 2:
            comp = [(m[0, 2] - m[2, 0]) / s, (m[0, 1] + m[1, 0]) / s, s / 4, (m[1, 2] + m[2, 1]) / s]
        else:
            comp = [(m[1, 0] - m[0, 1]) / s, (m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, s / 4]
        q = np.asarray(comp)
        out[k] = q if q[0] >= 0 else -q
    return out.reshape(R.shape[:-2] + (4,))


def positions(spec: ChainSpec, R: np.ndarray) -> np.ndarray:
    """Centres of mass (N,3) that the joints imply for the rotations R (N,3,3):
    x_i = -r_i - 2 sum_(k<i) r_k with r_k = R_k a (the top point relative to the centre)."""
    r = R @ spec.a
    return -r - 2.0 * (np.cumsum(r, axis=0) - r)


def velocities(spec: ChainSpec, R: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Centre-of-mass velocities (N,3, world) that the joints imply: dr_k/dt = w_k x r_k with
    w_k = R_k omega_k the world angular velocity, and x_i as in :func:`positions`."""
    r = R @ spec.a
    rdot = np.cross(np.einsum("nij,nj->ni", R, omega), r)
    return -rdot - 2.0 * (np.cumsum(rdot, axis=0) - rdot)


def from_rotations(spec: ChainSpec, R: np.ndarray, omega: np.ndarray) -> ChainState:
    """The maximal-coordinate state of link rotations R (N,3,3) and body angular velocities
    omega (N,3); positions and linear velocities follow from the joints."""
    R, omega = np.asarray(R, dtype=float), np.asarray(omega, dtype=float)
    return ChainState(R.copy(), positions(spec, R), omega.copy(), velocities(spec, R, omega))


def from_joint(spec: ChainSpec, qpos: np.ndarray, qvel: np.ndarray) -> ChainState:
    """Maximal coordinates from MuJoCo-convention joint coordinates (module docstring)."""
    n = spec.n
    qpos, qvel = np.asarray(qpos, dtype=float), np.asarray(qvel, dtype=float)
    if qpos.shape != (4 * n,) or qvel.shape != (3 * n,):
        raise ArgumentError(f"expected qpos of shape ({4 * n},) and qvel ({3 * n},), got "
                            f"{qpos.shape} and {qvel.shape}", field="qpos, qvel")
    rel = quat_to_matrix(qpos.reshape(n, 4))
    rel_w = qvel.reshape(n, 3)
    R, omega = np.empty((n, 3, 3)), np.empty((n, 3))
    for i in range(n):
        R[i] = rel[i] if i == 0 else R[i - 1] @ rel[i]
        omega[i] = rel_w[i] if i == 0 else rel[i].T @ omega[i - 1] + rel_w[i]
    return from_rotations(spec, R, omega)


def to_joint(spec: ChainSpec, state: ChainState) -> tuple[np.ndarray, np.ndarray]:
    """(qpos (4N,), qvel (3N,)) in MuJoCo's convention from maximal coordinates; x and v are
    not read (they are implied by R and omega on the constraint manifold)."""
    R, omega = np.asarray(state.R), np.asarray(state.omega)
    parent = np.concatenate([np.eye(3)[None], R[:-1]])
    rel = np.swapaxes(parent, 1, 2) @ R
    parent_w = np.concatenate([np.zeros((1, 3)), omega[:-1]])
    qvel = omega - np.einsum("nji,nj->ni", rel, parent_w)
    return matrix_to_quat(rel).reshape(-1), qvel.reshape(-1)


def energy(spec: ChainSpec, state: ChainState) -> tuple[float, float]:
    """(kinetic, potential) energy in J of a maximal-coordinate state."""
    m, J = spec.mass, spec.inertia
    kinetic = 0.5 * m * np.sum(state.v * state.v) + 0.5 * np.sum(J * state.omega ** 2)
    potential = m * spec.g * np.sum(state.x[:, 2])
    return float(kinetic), float(potential)


def rest_potential(spec: ChainSpec) -> float:
    """The potential energy of the chain hanging straight down at rest (its minimum)."""
    return -spec.mass * spec.g * spec.length * spec.n ** 2 / 2.0


def constraint_residual(spec: ChainSpec, state: ChainState) -> tuple[float, float]:
    """(position, velocity) residuals of the joints: the max-norm of the gaps between joined
    points and of their velocities, and of the rotations' distance from SO3 (|R^T R - I|)."""
    a = spec.a
    top = state.x + state.R @ a
    bottom = state.x - state.R @ a
    gaps = np.concatenate([top[:1], top[1:] - bottom[:-1]])
    orth = np.swapaxes(state.R, 1, 2) @ state.R - np.eye(3)
    w = np.einsum("nij,nj->ni", state.R, state.omega)
    r = state.R @ a
    top_v = state.v + np.cross(w, r)
    bottom_v = state.v - np.cross(w, r)
    gaps_v = np.concatenate([top_v[:1], top_v[1:] - bottom_v[:-1]])
    return (float(max(np.abs(gaps).max(), np.abs(orth).max())), float(np.abs(gaps_v).max()))


def initial_joint_state(spec: ChainSpec, seed: int = 0, angle: float = 0.0,
                        rate: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """A start in joint coordinates (qpos, qvel): every joint rotated about a random axis by
    a normal angle of standard deviation ``angle`` (rad), joint angular velocities (qvel)
    normal with standard deviation ``rate`` (rad/s), numpy's default_rng(seed). The
    benchmark's start is the default: hanging straight down, qvel ~ N(0, 1), seed 0."""
    rng = np.random.default_rng(seed)
    rotvec = angle * rng.standard_normal((spec.n, 3))
    theta = np.linalg.norm(rotvec, axis=1, keepdims=True)
    axis = rotvec / np.where(theta > 0, theta, 1.0)
    qpos = np.concatenate([np.cos(theta / 2), np.sin(theta / 2) * axis], axis=1)
    qvel = rate * rng.standard_normal(3 * spec.n)
    return qpos.reshape(-1), qvel


def tilted_joint_state(spec: ChainSpec, degrees: float) -> tuple[np.ndarray, np.ndarray]:
    """A start in joint coordinates (qpos, qvel): the straight chain rotated about the world
    x axis through the pin by ``degrees``, at rest (released from a tilt)."""
    if not np.isfinite(degrees):
        raise ArgumentError(f"expected a finite angle in degrees, got {degrees!r}",
                            field="degrees")
    half = 0.5 * np.radians(degrees)
    qpos = np.tile([1.0, 0.0, 0.0, 0.0], spec.n)
    qpos[:4] = [np.cos(half), np.sin(half), 0.0, 0.0]
    return qpos, np.zeros(3 * spec.n)


def named_joint_state(spec: ChainSpec, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(qpos, qvel) of a start's name: ``random`` the benchmark's (:func:`initial_joint_state`,
    seed 0), ``randomS`` the same with seed S, ``tiltD`` :func:`tilted_joint_state` at D
    degrees."""
    try:
        if name.startswith("random"):
            return initial_joint_state(spec, seed=int(name[6:] or 0))
        if name.startswith("tilt"):
            return tilted_joint_state(spec, float(name[4:]))
    except ValueError:
        pass
    raise ArgumentError(f"expected 'random', 'randomS' (seed S) or 'tiltD' (D in degrees), "
                        f"got {name!r}", field="start")


def trajectory_error(a: ChainState, b: ChainState) -> float:
    """Max-norm distance of two states in positions: centres of mass (m) and rotation
    matrix entries."""
    return float(max(np.abs(a.x - b.x).max(), np.abs(a.R - b.R).max()))
