"""The group catalog: R<n>, SO2, SO3, SE2, SE3 and direct products, registered in one place.

Matrix forms (n x n) and algebra coordinates (d):
- R<n>: g = [[I_n, x], [0, 1]], n+1 square; xi = v in R^n; hat(v) = [[0, v], [0, 0]].
- SO2:  g = R (2 x 2); xi = (omega,); hat = [[0, -omega], [omega, 0]].
- SO3:  g = R (3 x 3); xi = omega; hat(w) = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]].
- SE2:  g = [[R, x], [0, 1]] (3 x 3); xi = (omega, vx, vy), angular first.
- SE3:  g = [[R, x], [0, 1]] (4 x 4); xi = (omega, v), angular first.
- Products [G1, G2, ...]: g = blockdiag(g1, g2, ...), xi = (xi1, xi2, ...); every map acts
  factor by factor.
Adding a group is one new class here, one entry in ``_SIMPLE``, its chart functions in
``hpgen.groups.maps.GROUP_CHARTS`` and its name in the ``groups`` of the charts it supports
(``hpgen.schemes.TAU``).
"""
from __future__ import annotations

import re

import casadi as ca

from ..errors import ModelError
from ..schemes import charts_on
from .base import TAU_KINDS, FactorLayout, LieGroup
from . import maps


def so3_hat(w):
    return ca.vertcat(ca.horzcat(0, -w[2], w[1]), ca.horzcat(w[2], 0, -w[0]),
                      ca.horzcat(-w[1], w[0], 0))


def so3_vee(M):
    return ca.vertcat(M[2, 1], M[0, 2], M[1, 0])


def _affine(R, x):
    """[[R, x], [0, 1]] from a k x k block R and a k-vector x."""
    k = R.shape[0]
    return ca.vertcat(ca.horzcat(R, x), ca.horzcat(ca.SX.zeros(1, k), ca.SX.ones(1, 1)))


def _max_abs(M):
    return ca.mmax(ca.fabs(M))


class TabulatedCharts(LieGroup):
    """tau, dtau_inv, dtau and tau_margin from the ``GroupCharts`` of the group's family in
    ``hpgen.groups.maps.GROUP_CHARTS`` (and chart_product from ``maps.CHART_PRODUCTS``
    where closed forms are tabulated); the charts it supports from
    ``hpgen.schemes.TAU``."""
    family: str

    @property
    def tau_kinds(self) -> tuple[str, ...]:
        return charts_on(self.family)

    def _charts(self, kind) -> maps.GroupCharts:
        self.require_chart(kind)
        return maps.GROUP_CHARTS[self.family]

    def tau(self, kind, x):
        return self._charts(kind).tau(self, kind, x)

    def dtau_inv(self, kind, x):
        return self._charts(kind).dtau_inv(self, kind, x)

    def dtau(self, kind, x):
        return self._charts(kind).dtau(self, kind, x)

    def chart_product(self, kind, which, x, m, transposed=False):
        closed = maps.CHART_PRODUCTS.get((self.family, kind))
        if closed is None:
            return super().chart_product(kind, which, x, m, transposed)
        self.require_chart(kind)
        return closed[(which, transposed)](x, m)

    def tau_margin(self, kind, x):
        return self._charts(kind).margin(self, kind, x)


class Rn(TabulatedCharts):
    """Translations of R^n as (n+1) x (n+1) matrices; abelian, every tau is exact (I + x^)."""
    family = "R<n>"

    def __init__(self, k: int):
        self.k, self.n, self.d, self.name = k, k + 1, k, f"R{k}"
        self.translation_block = (0, k)

    def hat(self, v):
        return ca.vertcat(ca.horzcat(ca.SX.zeros(self.k, self.k), v), ca.SX.zeros(1, self.n))

    def vee(self, M):
        return M[0:self.k, self.k]

    def inverse(self, g):
        return _affine(ca.SX.eye(self.k), -g[0:self.k, self.k])

    def group_defect(self, g):
        return _max_abs(g - _affine(ca.SX.eye(self.k), g[0:self.k, self.k]))



class SO2(TabulatedCharts):
    family = "SO2"
    name, n, d = "SO2", 2, 1
    rotation_block = (0, 2)

    def hat(self, v):
        return ca.vertcat(ca.horzcat(0, -v[0]), ca.horzcat(v[0], 0))

    def vee(self, M):
        return ca.vertcat(M[1, 0])

    def inverse(self, g):
        return g.T

    def group_defect(self, g):
        return ca.fmax(_max_abs(ca.mtimes(g.T, g) - ca.SX.eye(2)), ca.fabs(ca.det(g) - 1))



class SO3(TabulatedCharts):
    family = "SO3"
    name, n, d = "SO3", 3, 3
    rotation_block = (0, 3)

    def hat(self, v):
        return so3_hat(v)

    def vee(self, M):
        return so3_vee(M)

    def inverse(self, g):
        return g.T

    def group_defect(self, g):
        return ca.fmax(_max_abs(ca.mtimes(g.T, g) - ca.SX.eye(3)), ca.fabs(ca.det(g) - 1))



class SE2(TabulatedCharts):
    family = "SE2"
    name, n, d = "SE2", 3, 3
    rotation_block = (0, 2)
    translation_block = (0, 2)

    def hat(self, v):
        return ca.vertcat(ca.horzcat(0, -v[0], v[1]), ca.horzcat(v[0], 0, v[2]),
                          ca.SX.zeros(1, 3))

    def vee(self, M):
        return ca.vertcat(M[1, 0], M[0, 2], M[1, 2])

    def inverse(self, g):
        R, x = g[0:2, 0:2], g[0:2, 2]
        return _affine(R.T, -ca.mtimes(R.T, x))

    def group_defect(self, g):
        R = g[0:2, 0:2]
        return ca.fmax(ca.fmax(_max_abs(ca.mtimes(R.T, R) - ca.SX.eye(2)), ca.fabs(ca.det(R) - 1)),
                       _max_abs(g[2, :] - ca.horzcat(0, 0, 1)))



class SE3(TabulatedCharts):
    family = "SE3"
    name, n, d = "SE3", 4, 6
    rotation_block = (0, 3)
    translation_block = (0, 3)

    def hat(self, v):
        return _affine(so3_hat(v[0:3]), v[3:6]) - ca.diag(ca.vertcat(0, 0, 0, 1))

    def vee(self, M):
        return ca.vertcat(so3_vee(M[0:3, 0:3]), M[0:3, 3])

    def inverse(self, g):
        R, x = g[0:3, 0:3], g[0:3, 3]
        return _affine(R.T, -ca.mtimes(R.T, x))

    def group_defect(self, g):
        R = g[0:3, 0:3]
        return ca.fmax(ca.fmax(_max_abs(ca.mtimes(R.T, R) - ca.SX.eye(3)), ca.fabs(ca.det(R) - 1)),
                       _max_abs(g[3, :] - ca.horzcat(0, 0, 0, 1)))



class ProductGroup(LieGroup):
    """Direct product; g block diagonal, xi concatenated, every map factor by factor."""

    def __init__(self, factors: list[LieGroup]):
        self.parts = tuple(factors)
        self.name = "[" + ", ".join(f.name for f in factors) + "]"
        self.n = sum(f.n for f in factors)
        self.d = sum(f.d for f in factors)
        self.tau_kinds = tuple(k for k in TAU_KINDS if all(f.supports(k) for f in factors))
        lay, row, off = [], 0, 0
        for f in factors:
            lay.append(FactorLayout(f.name, row, f.n, off, f.d))
            row, off = row + f.n, off + f.d
        self._layout = tuple(lay)

    @property
    def factors(self):
        return self._layout

    def _split_v(self, v):
        return [v[L.off:L.off + L.d] for L in self._layout]

    def _split_g(self, g):
        return [g[L.row:L.row + L.n, L.row:L.row + L.n] for L in self._layout]

    def hat(self, v):
        return ca.diagcat(*[f.hat(x) for f, x in zip(self.parts, self._split_v(v))])

    def vee(self, M):
        return ca.vertcat(*[f.vee(m) for f, m in zip(self.parts, self._split_g(M))])

    def inverse(self, g):
        return ca.diagcat(*[f.inverse(m) for f, m in zip(self.parts, self._split_g(g))])

    def group_defect(self, g):
        off_diag = g - ca.diagcat(*self._split_g(g))
        out = _max_abs(off_diag)
        for f, m in zip(self.parts, self._split_g(g)):
            out = ca.fmax(out, f.group_defect(m))
        return out

    def tau(self, kind, x):
        return ca.diagcat(*[f.tau(kind, v) for f, v in zip(self.parts, self._split_v(x))])

    def dtau_inv(self, kind, x):
        return ca.diagcat(*[f.dtau_inv(kind, v) for f, v in zip(self.parts, self._split_v(x))])

    def dtau(self, kind, x):
        return ca.diagcat(*[f.dtau(kind, v) for f, v in zip(self.parts, self._split_v(x))])

    def tau_margin(self, kind, x):
        out = ca.SX(1.0)
        for f, v in zip(self.parts, self._split_v(x)):
            out = ca.fmin(out, f.tau_margin(kind, v))
        return out


_SIMPLE = {"SO2": SO2, "SO3": SO3, "SE2": SE2, "SE3": SE3}
_RN = re.compile(r"R([1-9][0-9]{0,2})")
#: the group families, spelled as in hpgen.schemes.ChartMap.groups and maps.GROUP_CHARTS
GROUP_NAMES = ("R<n>", "SO2", "SO3", "SE2", "SE3")


def _one(spec) -> LieGroup:
    if not isinstance(spec, str):
        raise ModelError(f"expected a group name ({', '.join(GROUP_NAMES)}), got {spec!r}",
                         field="group")
    if spec in _SIMPLE:
        return _SIMPLE[spec]()
    m = _RN.fullmatch(spec)
    if m:
        return Rn(int(m.group(1)))
    if spec.startswith("R"):
        raise ModelError(f"malformed {spec!r}: expected R<n> with n an integer from 1 to 999, "
                         "e.g. R3", field="group")
    raise ModelError(f"unknown group {spec!r}: expected one of {', '.join(GROUP_NAMES)} "
                     "or a list of them", field="group")


def group_from_spec(spec) -> LieGroup:
    """A group from the model file's ``group`` field: a name or a non-empty list of names."""
    if isinstance(spec, list):
        if not spec:
            raise ModelError("expected a group name or a non-empty list of names", field="group")
        if len(spec) == 1:
            return _one(spec[0])
        return ProductGroup([_one(s) for s in spec])
    return _one(spec)
