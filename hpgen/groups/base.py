"""Matrix Lie groups as used by the derivation: the contract every catalog entry fulfils.

Conventions (all groups):
- An element g is an n x n matrix; the algebra has dimension d with coordinates xi in R^d;
  ``hat: R^d -> g`` and ``vee`` its inverse. The pairing of g* with g is the dot product.
- Symbolic methods take and return ``casadi.SX`` (column vectors d x 1, matrices n x n or d x d).
- ``dtau_inv(kind, x)`` returns the d x d matrix of y -> dtau^{-1}_x(y), the paper's inverse
  right-trivialized tangent (Definition def:dtauinverse); ``dtau(kind, x)`` its inverse.
- Removable singularities (sin t / t at t = 0, ...) are coded without a branch, as
  polynomials in the half angle accurate to 2^-54 on the chart domain |t| <= pi (see
  ``hpgen.groups.series``), so that no value or derivative is NaN at xi = 0.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from ..errors import ModelError
from ..schemes import TAU_CHOICES as TAU_KINDS  # noqa: F401  (re-exported by hpgen.groups)


@dataclass(frozen=True)
class FactorLayout:
    """Where factor k of a (product) group sits: rows/cols [row, row+n) of g, xi[off, off+d)."""
    name: str
    row: int
    n: int
    off: int
    d: int


class LieGroup:
    """Base class. Subclasses set name, n, d and implement hat, vee, inverse, tau, dtau_inv."""

    name: str
    n: int
    d: int
    #: chart maps this group supports, a subset of TAU_KINDS (from hpgen.schemes.TAU)
    tau_kinds: tuple[str, ...] = ()
    #: (start, stop) rows/cols of the rotation block R in g, or None (R^n)
    rotation_block: tuple[int, int] | None = None
    #: (start, stop) rows of the translation column x (last column of g), or None
    translation_block: tuple[int, int] | None = None

    # ---- structure -------------------------------------------------------------------
    @property
    def factors(self) -> tuple[FactorLayout, ...]:
        return (FactorLayout(self.name, 0, self.n, 0, self.d),)

    def hat(self, v):
        raise NotImplementedError

    def vee(self, M):
        raise NotImplementedError

    def inverse(self, g):
        raise NotImplementedError

    def identity(self):
        return ca.SX.eye(self.n)

    def Ad(self, g):
        """d x d matrix of Ad_g xi = vee(g xi^ g^{-1})."""
        ginv = self.inverse(g)
        cols = [self.vee(ca.mtimes([g, self.hat(e), ginv])) for e in _basis(self.d)]
        return ca.horzcat(*cols)

    def ad(self, x):
        """d x d matrix of ad_x y = vee(x^ y^ - y^ x^)."""
        X = self.hat(x)
        cols = [self.vee(ca.mtimes(X, self.hat(e)) - ca.mtimes(self.hat(e), X))
                for e in _basis(self.d)]
        return ca.horzcat(*cols)

    def momentum_map(self, g, p):
        """Spatial momentum Ad*_{g^{-1}} p (conserved for a left-invariant Lagrangian)."""
        return ca.mtimes(self.Ad(self.inverse(g)).T, p)

    def group_defect(self, g):
        """A scalar distance of the matrix g from the group (0 on the group), e.g. |R^T R - I|_max."""
        raise NotImplementedError

    # ---- chart maps --------------------------------------------------------------------
    def supports(self, kind: str) -> bool:
        return kind in self.tau_kinds

    def require_chart(self, kind: str) -> None:
        """ModelError on ``integrator.tau`` unless this group supports the chart ``kind``."""
        if kind not in self.tau_kinds:
            raise ModelError(f"tau = {kind} is not available on {self.name}; use one of "
                             f"{', '.join(self.tau_kinds)}", field="integrator.tau")

    def tau(self, kind: str, x):
        """n x n matrix tau(x^)."""
        raise NotImplementedError

    def dtau_inv(self, kind: str, x):
        """d x d matrix of y -> dtau^{-1}_x(y)."""
        raise NotImplementedError

    def dtau(self, kind: str, x):
        """d x d matrix of y -> dtau_x(y), the inverse of dtau_inv(kind, x)."""
        raise NotImplementedError

    def chart_product(self, kind: str, which: str, x, m, transposed: bool = False):
        """d-vector M m (M^T m if ``transposed``) with M = dtau_inv(kind, x) (``which`` =
        "dtau_inv") or dtau(kind, x) ("dtau"): what the derivation applies to velocities and
        momenta; a chart with a cheaper closed form overrides it."""
        M = self.dtau_inv(kind, x) if which == "dtau_inv" else self.dtau(kind, x)
        return ca.mtimes(M.T if transposed else M, m)

    def dtau_inv_T_times(self, kind: str, x, m):
        """d-vector (dtau^{-1}_x)^T m, the map the Stormer-Verlet family's step applies to a
        momentum: dtau_inv(kind, x).T m."""
        return self.chart_product(kind, "dtau_inv", x, m, transposed=True)

    def tau_margin(self, kind: str, x):
        """Scalar SX, > 0 while x is inside the domain where tau is a valid chart, else <= 0."""
        raise NotImplementedError


def _basis(d):
    for k in range(d):
        e = ca.DM.zeros(d, 1)
        e[k] = 1
        yield ca.SX(e)
