"""Initial group elements from a rotation vector, an angle and a position: the constructors of
a model file's ``initial.g`` ({rotvec: [3]} on SO3/SE3, {angle: a} on SO2/SE2, position: [k]
on SE2/SE3/R<k>), shared by the model loader (hpgen.model.scene, which validates the YAML
first) and the Python API (``Integrator.group``). numpy and the standard library only.

Conventions (hpgen.groups.catalog): SO<k> is the k x k rotation R; SE<k> the (k+1) x (k+1)
matrix [[R, x], [0, 1]]; R<k> is [[I, x], [0, 1]]; a product "[A, B, ...]" is the
block-diagonal matrix of its factors' elements. Rotations: Rodrigues' formula
exp(w^) = I + sin t K + (1 - cos t) K^2 (t = |w|, K = (w/t)^), and [[c, -s], [s, c]] for an
angle a (c = cos a, s = sin a).
"""
from __future__ import annotations

import math
import re

import numpy as np

from ..errors import ArgumentError

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


class GroupElements:
    """Constructors of elements of a module's group (``Integrator.group``), the same as the
    model file's ``initial.g`` forms. Each returns an (n, n) float array; a bad argument is an
    ArgumentError naming it. Attributes: name (e.g. "SO3", "[SO3, R3]"), n, factors."""

    def __init__(self, name: str):
        self.name = name
        self.factors = tuple(factor_names(name))
        self._layouts = [factor_layout(f) for f in self.factors]
        self.n = sum(lay[0] for lay in self._layouts)

    def __repr__(self):
        return f"<hpgen group {self.name}>"

    def identity(self) -> np.ndarray:
        return np.eye(self.n)

    def _single(self, what):
        if len(self.factors) != 1:
            raise ArgumentError(f"{what} builds one factor; for the product {self.name} build "
                                "each factor's element and join them with product(...)",
                                field=what)
        return self.factors[0], self._layouts[0]

    @staticmethod
    def _vector(x, k, field):
        a = np.asarray(x)
        if np.iscomplexobj(a) or a.shape != (k,) or a.dtype == object:
            raise ArgumentError(f"expected {k} real numbers, got {x!r}", field=field)
        a = a.astype(np.float64)
        if not np.isfinite(a).all():
            raise ArgumentError(f"expected {k} finite numbers, got {x!r}", field=field)
        return a

    def _position(self, name, layout, position):
        if position is None:
            return None
        if layout[2] is None:
            raise ArgumentError(f"{name} has no translation part", field="position")
        a, b = layout[2]
        return self._vector(position, b - a, "position")

    def from_rotvec(self, rotvec, position=None) -> np.ndarray:
        """SO3 / SE3: rotation exp(rotvec^) (model file ``{rotvec: [3], position: [3]}``)."""
        name, lay = self._single("from_rotvec")
        if lay[1] is None or lay[1][1] - lay[1][0] != 3:
            raise ArgumentError(f"{name} takes from_angle_position(angle, ...), not a rotation "
                                "vector" if lay[1] else f"{name} has no rotation part",
                                field="rotvec")
        R = rotation_from_rotvec(self._vector(rotvec, 3, "rotvec"))
        return compose(lay[0], lay[1], lay[2], R, self._position(name, lay, position))

    def from_angle_position(self, angle, position=None) -> np.ndarray:
        """SO2 / SE2: rotation by ``angle`` and translation ``position`` (SE2; model file
        ``{angle: a, position: [2]}``)."""
        name, lay = self._single("from_angle_position")
        if lay[1] is None or lay[1][1] - lay[1][0] != 2:
            raise ArgumentError(f"{name} takes from_rotvec(rotvec, ...), not an angle"
                                if lay[1] else f"{name} has no rotation part", field="angle")
        a = self._vector([angle], 1, "angle")[0]
        return compose(lay[0], lay[1], lay[2], rotation_from_angle(a),
                       self._position(name, lay, position))

    def from_position(self, position) -> np.ndarray:
        """R<k>, SE2, SE3: the translation ``position`` with no rotation (model file
        ``{position: [k]}``)."""
        name, lay = self._single("from_position")
        return compose(lay[0], lay[1], lay[2], None, self._position(name, lay, position))

    def product(self, *elements) -> np.ndarray:
        """The block-diagonal element of a product group from one element per factor."""
        if len(elements) != len(self.factors):
            raise ArgumentError(f"expected {len(self.factors)} factor elements for "
                                f"{self.name}, got {len(elements)}", field="product")
        G, row = np.zeros((self.n, self.n)), 0
        for k, (e, lay) in enumerate(zip(elements, self._layouts)):
            m = lay[0]
            a = np.asarray(e)
            if np.iscomplexobj(a) or a.shape != (m, m):
                raise ArgumentError(f"factor {k} ({self.factors[k]}): expected a real {m} x {m} "
                                    f"matrix, got shape {a.shape}", field="product")
            G[row:row + m, row:row + m] = a
            row += m
        return G
