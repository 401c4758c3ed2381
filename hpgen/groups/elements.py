"""Group elements as numpy arrays: the constructors of a model file's ``initial.g`` and of
``Integrator.group``, and the readers of attitudes (quaternion, rotation vector). numpy and the
standard library only: the runtime imports this module (no casadi, no sympy).

Conventions (hpgen.groups.catalog): SO<k> is the k x k rotation R; SE<k> the (k+1) x (k+1)
matrix [[R, x], [0, 1]]; R<k> is [[I, x], [0, 1]]; a product "[A, B, ...]" is the
block-diagonal matrix of its factors' elements.

- Rotation vector w: R = exp(w^) by Rodrigues' formula I + sin t K + (1 - cos t) K^2
  (t = |w|, K = (w/t)^), the rotation by the angle t about the axis w/t, right-handed.
- Angle a (SO2, SE2): R = [[c, -s], [s, c]], c = cos a, s = sin a.
- Quaternion q = [w, x, y, z], **scalar first** (Hamilton convention, as in Eigen's
  constructor and MuJoCo; SciPy's ``Rotation.from_quat`` is scalar last unless
  ``scalar_first=True``). q = [cos(t/2), sin(t/2) e] is the same rotation as the rotation
  vector t e: R(q) = exp((t e)^). q and -q are the same rotation. An input quaternion must be
  a unit quaternion within QUAT_TOL (| |q| - 1 | <= 1e-10, the tolerance of a rotation block
  in a model file); it is divided by its norm before use. Read back, quaternions are scaled
  to unit norm with w >= 0 (for w = 0, the first nonzero of x, y, z positive).
- Rotation vectors read back have angle |w| in [0, pi].
"""
from __future__ import annotations

import math
import re

import numpy as np

from ..errors import ArgumentError

#: largest accepted | |q| - 1 | of an input quaternion
QUAT_TOL = 1e-10

_R = re.compile(r"R([1-9][0-9]*)")
#: factor name -> (n, rotation block (rows a:b), translation block (rows a:b of the last column))
_FACTORS = {"SO2": (2, (0, 2), None), "SO3": (3, (0, 3), None),
            "SE2": (3, (0, 2), (0, 2)), "SE3": (4, (0, 3), (0, 3))}


def factor_layout(name: str):
    """(n, rotation block or None, translation block or None) of a non-product group."""
    m = _R.fullmatch(name)
    if m:
        k = int(m.group(1))
        return k + 1, None, (0, k)
    if name not in _FACTORS:
        raise ArgumentError(f"unknown group {name!r}", field="group")
    return _FACTORS[name]


def factor_names(group_name: str) -> list:
    """["SO3"] for "SO3"; the factors of a product "[SO3, R3]"."""
    name = group_name.strip()
    if name.startswith("[") and name.endswith("]"):
        return [f.strip() for f in name[1:-1].split(",")]
    return [name]


# ---- constructors --------------------------------------------------------------------------
def rotation_from_rotvec(w) -> np.ndarray:
    """The 3 x 3 rotation exp(w^) (Rodrigues; the identity for w = 0)."""
    w = np.asarray(w, dtype=np.float64)
    theta = math.hypot(*w)
    if theta == 0.0:
        return np.eye(3)
    u = w / theta
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return np.eye(3) + math.sin(theta) * K + (1 - math.cos(theta)) * (K @ K)


def rotation_from_angle(a) -> np.ndarray:
    """The 2 x 2 rotation by the angle a."""
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s], [s, c]])


def quat_norm_error(q) -> str | None:
    """None for a unit quaternion (within QUAT_TOL), else what is wrong, in words."""
    norm = math.sqrt(sum(float(x) * float(x) for x in q))
    if abs(norm - 1.0) <= QUAT_TOL:
        return None
    return (f"expected a unit quaternion [w, x, y, z] (scalar first), got norm {norm:.12g} "
            f"(tolerance {QUAT_TOL:g}); divide it by its norm")


def rotation_from_quat(q) -> np.ndarray:
    """The 3 x 3 rotation of the unit quaternion q = [w, x, y, z] (scalar first; the caller
    checks |q| = 1 with quat_norm_error; q is divided by its norm here)."""
    q = np.asarray(q, dtype=np.float64)
    w, x, y, z = q / math.sqrt(float(q @ q))
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def compose(n, rotation_block, translation_block, R=None, position=None) -> np.ndarray:
    """The n x n element with rotation block R and translation ``position`` (identity parts
    where None)."""
    G = np.eye(n)
    if R is not None:
        a, b = rotation_block
        G[a:b, a:b] = R
    if position is not None:
        a, b = translation_block
        G[a:b, n - 1] = position
    return G


# ---- readers -------------------------------------------------------------------------------
def quat_from_rotation(R) -> np.ndarray:
    """Unit quaternions [w, x, y, z] (scalar first, w >= 0) of rotations R (..., 3, 3), shape
    (..., 4); Shepperd's method (the largest of w, x, y, z is computed from the trace)."""
    R = np.asarray(R, dtype=np.float64)
    tr = np.trace(R, axis1=-2, axis2=-1)
    d = np.stack([tr, R[..., 0, 0], R[..., 1, 1], R[..., 2, 2]], axis=-1)
    k = np.argmax(d, axis=-1)
    q = np.empty(R.shape[:-2] + (4,))
    r = lambda i, j: R[..., i, j]                 # noqa: E731 (the entries of R, named)
    cand = [  # 4 q_k q = the k-th column of the symmetric matrix (4 q q^T)
        np.stack([1 + tr, r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1)], -1),
        np.stack([r(2, 1) - r(1, 2), 1 + 2 * r(0, 0) - tr, r(0, 1) + r(1, 0),
                  r(0, 2) + r(2, 0)], -1),
        np.stack([r(0, 2) - r(2, 0), r(0, 1) + r(1, 0), 1 + 2 * r(1, 1) - tr,
                  r(1, 2) + r(2, 1)], -1),
        np.stack([r(1, 0) - r(0, 1), r(0, 2) + r(2, 0), r(1, 2) + r(2, 1),
                  1 + 2 * r(2, 2) - tr], -1)]
    for i in range(4):
        q[k == i] = cand[i][k == i]
    q /= np.linalg.norm(q, axis=-1, keepdims=True)
    lead = np.where(q[..., :1] != 0, q[..., :1],
                    np.take_along_axis(q[..., 1:], np.argmax(q[..., 1:] != 0, -1)[..., None],
                                       -1))
    return np.where(lead < 0, -q, q)


def rotvec_from_rotation(R) -> np.ndarray:
    """Rotation vectors w (..., 3) with exp(w^) = R for rotations R (..., 3, 3), angle |w| in
    [0, pi]; from the quaternion (2 atan2(|v|, w) v / |v|, accurate near 0 and pi)."""
    q = quat_from_rotation(R)
    v = q[..., 1:]
    s = np.linalg.norm(v, axis=-1)
    angle = 2 * np.arctan2(s, q[..., 0])
    scale = np.where(s > 0, angle / np.where(s > 0, s, 1.0), 2.0)   # 2 v for tiny angles
    return v * scale[..., None]


def rotation_blocks(group_name: str, g, factor=None) -> np.ndarray:
    """The SO3 blocks R (..., 3, 3) of elements g (..., n, n) of ``group_name``: of the one
    factor with a 3 x 3 rotation (SO3, SE3), or of factor number ``factor`` of a product.
    ArgumentError when the group (or factor) has no 3 x 3 rotation, or a product has more
    than one and ``factor`` is not given."""
    names = factor_names(group_name)
    layouts = [factor_layout(f) for f in names]
    rows = np.cumsum([0] + [lay[0] for lay in layouts])
    spatial = [k for k, lay in enumerate(layouts) if lay[1] is not None
               and lay[1][1] - lay[1][0] == 3]
    if factor is None:
        if len(spatial) != 1:
            raise ArgumentError(f"{group_name} has {len(spatial) or 'no'} 3 x 3 rotation "
                                "factors" + ("; pass factor=k" if spatial else ""),
                                field="factor")
        factor = spatial[0]
    if not isinstance(factor, (int, np.integer)) or factor not in spatial:
        raise ArgumentError(f"expected the index of a factor with a 3 x 3 rotation "
                            f"({', '.join(map(str, spatial)) or 'none'} in {group_name}), "
                            f"got {factor!r}", field="factor")
    if g is None:
        raise ArgumentError("no group elements: record g (add g to the scene's record list)",
                            field="g")
    g = np.asarray(g, dtype=np.float64)
    n = int(rows[-1])
    if g.shape[-2:] != (n, n):
        raise ArgumentError(f"expected elements of shape (..., {n}, {n}), got {g.shape}",
                            field="g")
    a = int(rows[factor]) + layouts[factor][1][0]
    return g[..., a:a + 3, a:a + 3]
