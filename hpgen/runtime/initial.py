"""``Integrator.group``: elements of a module's group from a rotation vector, an angle, a
quaternion and a position (the forms of a model file's ``initial.g``), and the attitudes of
elements as quaternions or rotation vectors. The constructors and their conventions (scalar-first
unit quaternions, Rodrigues' formula) live in hpgen.groups.elements, shared with the model
loader (hpgen.model.scene). numpy and the standard library only.
"""
from __future__ import annotations

import numpy as np

from ..errors import ArgumentError
from ..groups.elements import (compose, factor_layout, factor_names, quat_from_rotation,
                               quat_norm_error, rotation_blocks, rotation_from_angle,
                               rotation_from_quat, rotation_from_rotvec, rotvec_from_rotation)

__all__ = ["GroupElements", "compose", "factor_layout", "factor_names", "rotation_from_angle",
           "rotation_from_rotvec", "rotation_from_quat"]


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

    def from_quat(self, quat, position=None) -> np.ndarray:
        """SO3 / SE3: the rotation of the unit quaternion ``quat`` = [w, x, y, z], scalar
        first (hpgen.groups.elements; [cos(t/2), sin(t/2) e] is from_rotvec(t e)), and the
        translation ``position`` (SE3; model file ``{quat: [4], position: [3]}``). A
        quaternion whose norm is not 1 within 1e-10 is an ArgumentError."""
        name, lay = self._single("from_quat")
        if lay[1] is None or lay[1][1] - lay[1][0] != 3:
            raise ArgumentError(f"{name} takes from_angle_position(angle, ...), not a quaternion"
                                if lay[1] else f"{name} has no rotation part", field="quat")
        q = self._vector(quat, 4, "quat")
        problem = quat_norm_error(q)
        if problem:
            raise ArgumentError(problem, field="quat")
        return compose(lay[0], lay[1], lay[2], rotation_from_quat(q),
                       self._position(name, lay, position))

    def as_quat(self, g, factor=None) -> np.ndarray:
        """The attitudes of elements g (..., n, n) as unit quaternions (..., 4), [w, x, y, z]
        with w >= 0: of the SO3 block (SO3, SE3, or the one such factor of a product; else
        ``factor=k``)."""
        return quat_from_rotation(rotation_blocks(self.name, g, factor))

    def as_rotvec(self, g, factor=None) -> np.ndarray:
        """The attitudes of elements g (..., n, n) as rotation vectors (..., 3), angle in
        [0, pi] (the inverse of from_rotvec); the block as for as_quat."""
        return rotvec_from_rotation(rotation_blocks(self.name, g, factor))

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
