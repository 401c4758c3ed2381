"""Symplecticity of a one-step map (g_k, p_k) -> (g_{k+1}, p_{k+1}) on T*G = G x g*.

Conventions:
- Left-trivialized chart at (g, p): (delta, dp) -> (g exp(delta^), p + dp). A tangent vector
  is (eta, nu) = (g^{-1} dg, dp) in R^d x R^d; a map's derivative in these charts is the
  2d x 2d matrix Phi' with input (delta, dp) and output (eta_1, nu_1), eta_1 =
  vee(g_1^{-1} dg_1) (Frobenius projection onto the algebra). Only first derivatives at
  delta = 0 enter, so g (I + delta^) is used in place of g exp(delta^).
- Canonical one-form theta_(g,p)(dg, dp) = <p, g^{-1} dg>; symplectic form omega = -d theta:

      omega((eta_a, nu_a), (eta_b, nu_b)) = <nu_b, eta_a> - <nu_a, eta_b> + <p, [eta_a, eta_b]>,

  [x, y] = ad_x y = vee(x^ y^ - y^ x^) (``group.ad``). The sign of the bracket term is
  BRACKET_SIGN = +1: d theta(X, Y) = X theta(Y) - Y theta(X) - theta([X, Y]) on the fields
  X = (g eta_a, nu_a), Y = (g eta_b, nu_b), whose bracket is (g [eta_a, eta_b], 0). Checked
  numerically: the exact free-rigid-body and heavy-top flows (variational equations at
  rtol 1e-13) preserve this form to ~1e-12 and violate the opposite sign at O(1)
  (tests/unit/test_symplectic.py); on R^n (ad = 0) it is dq ^ dp, Omega = [[0, I], [-I, 0]].
  A map given by a type-1 generating function s(g_0, g_1) with p_0 = -d_0 s, p_1 = d_1 s
  (hpgen's discrete Legendre transforms, docs/numerics.md sec. 4) pulls theta back to theta + ds,
  hence preserves d theta.
- In matrix form omega(a, b) = a^T Omega(p) b, Omega(p) = [[C(p), I], [-I, 0]] with
  C(p)_ij = <p, [e_i, e_j]>. Defect of Phi' from (g0, p0) to (g1, p1):
  max_ij |Phi'^T Omega(p1) Phi' - Omega(p0)|; ``relative`` divides it by
  |Phi'|_2^2 |Omega(p1)|_2, the size of the terms whose round-off it measures.

Jacobian of a generated step (``GeneratedMap``): the step solves F(z; g, p, h) = 0 and
applies the explicit update U(z, g, p, h) = (g1, p1). With s = (delta, dp),
dz/ds = -(dF/dz)^{-1} dF/ds and d(g1, p1)/ds = dU/ds + dU/dz dz/ds, composed by the one
implementation hpgen.runtime.linearize.implicit_derivative. Phi' is that of
``Integrator.linearize``: the generated ``jacobian`` and ``step_partials`` kernels of the
compiled module (C or Python backend) at the converged z. ``StepSensitivity`` rebuilds the
same partials at check time by CasADi AD of the DiscreteStep's residual and update in
ambient coordinates (g (I + delta^), then the Frobenius projection ``chart_jacobian``), an
independent route whose agreement is reported (``ad_mismatch``); never finite differences.
"""
from __future__ import annotations

import casadi as ca
import numpy as np

from ..errors import ConvergenceError
from ..runtime import newton as _newton
from ..runtime.linearize import implicit_derivative, partials_at
from .rkmk import _np, chart_jacobian

BRACKET_SIGN = +1


def ad_matrices(group):
    """(d, d, d) array: ad_matrices[i] is the matrix of ad_{e_i}."""
    x = ca.SX.sym("x", group.d)
    ad = ca.Function("ad", [x], [group.ad(x)])
    return np.array([_np(ad(np.eye(group.d)[i])) for i in range(group.d)])


def omega_matrix(ad_mats, p, sign=BRACKET_SIGN):
    """Omega(p) (2d x 2d) of the canonical form at momentum p: omega(a, b) = a^T Omega b."""
    d = len(p)
    C = np.array([ad_mats[i].T @ np.asarray(p, dtype=float) for i in range(d)])
    return np.block([[sign * C, np.eye(d)], [-np.eye(d), np.zeros((d, d))]])


def symplectic_defect(Phi, Omega0, Omega1):
    """(absolute, relative) defect of Phi' from Omega0 (at the start) to Omega1 (at the end)."""
    E = Phi.T @ Omega1 @ Phi - Omega0
    absolute = float(np.abs(E).max())
    scale = float(np.linalg.norm(Phi, 2) ** 2 * np.linalg.norm(Omega1, 2))
    return absolute, absolute / max(scale, np.finfo(float).tiny)


class StepSensitivity:
    """CasADi partial derivatives of a DiscreteStep's residual and update in the state.

    ``partials(z, g, p, h)`` -> (dF/ds (nz, 2d), dU/dz (n*n+d, nz), dU/ds (n*n+d, 2d),
    dF/dz (nz, nz) from CasADi (for cross-checking the generated kernel), g1 (n, n), p1 (d)).
    g is an (n, n) array; U stacks vec(g1) (column-major) and p1.
    """

    def __init__(self, step, group):
        self.step, self.group = step, group
        n, d, nz = step.n, step.d, step.nz
        res = step.kernel("residual").function
        upd = step.kernel("update").function
        H_size = 1 if getattr(step, "open_spec", None) is None else step.open_spec.H
        z, G, D, P, H = (ca.SX.sym("z", nz), ca.SX.sym("g", n, n), ca.SX.sym("delta", d),
                         ca.SX.sym("p", d), ca.SX.sym("h", H_size))
        gv = ca.reshape(ca.mtimes(G, ca.SX.eye(n) + group.hat(D)), n * n, 1)
        F = res(z, gv, P, H)
        g1, p1 = upd(z, gv, P, H)
        U = ca.vertcat(g1, p1)
        S = ca.vertcat(D, P)
        outs = [ca.jacobian(F, S), ca.jacobian(U, z), ca.jacobian(U, S), ca.jacobian(F, z),
                ca.reshape(g1, n, n), p1]
        outs = [ca.densify(ca.substitute(e, D, ca.SX.zeros(d))) for e in outs]
        self._f = ca.Function("step_partials", [z, G, P, H], outs)

    def partials(self, z, g, p, h):
        out = [_np(a) for a in self._f(z, g, p, h)]
        out[5] = out[5].ravel()
        return out


def converged_step(integ, g, p, h, z=None, newton=None, hv=None):
    """Newton on the compiled module's residual/jacobian kernels (as Integrator.step does),
    returning (z, g1 (n, n), p1). z: start (default the ``guess`` kernel). hv: an open
    module's step vector [h, t, u, params] (hpgen.abi; default [h], a closed module)."""
    n = integ.n
    gf = np.asarray(g, dtype=float).ravel(order="F")
    p = np.asarray(p, dtype=float)
    hv = np.array([float(h)] if hv is None else hv, dtype=float)
    if z is None:
        vel = (integ.velocity(g, p) if integ.open is None else
               integ.velocity(g, p, t=hv[1], params=list(hv[2 + len(integ.open["inputs"]):])))
        z = integ.kernel("guess", vel, gf, p, hv)[0]
    opts = integ.engine.options(newton, full=True)    # full Newton unless newton.simplified
    code, g1, p1, z, it, r, _ = _newton.step_core(integ.kernel, integ.nz, gf, p, hv, z, opts,
                                                  _newton.NewtonMemory())
    if code != _newton.OK:
        raise ConvergenceError("Newton did not converge in the symplecticity check", step=0,
                               time=0.0, residual=r, iterations=it)
    return z, g1.reshape(n, n, order="F"), p1


class GeneratedMap:
    """The one-step map of a compiled hpgen scheme and its Jacobian by implicit
    differentiation (see the module docstring)."""

    def __init__(self, integ, step, group):
        self.integ, self.group = integ, group
        self.sens = StepSensitivity(step, group)
        self.last = {}

    def map_jacobian(self, g, p, h, z=None, hv=None):
        """(Phi' (2d, 2d), g1, p1) from the generated kernels (``Integrator.linearize``'s
        partials); diagnostics of the last call in ``self.last``: cond_J (2-norm condition of
        dF/dz), kernel_mismatch (max |generated dF/dz - CasADi dF/dz| / max(1, max|dF/dz|)),
        update_mismatch (generated update vs CasADi), ad_mismatch (max |Phi' - Phi' by CasADi
        AD in ambient coordinates| / max(1, max|Phi'|)). hv: an open module's step vector
        (default [h])."""
        hv = np.array([float(h)] if hv is None else hv, dtype=float)
        z, g1, p1 = converged_step(self.integ, g, p, h, z, hv=hv)
        gf = np.asarray(g, dtype=float).ravel(order="F")
        J, Fs, Yz, Ys = partials_at(self.integ, z, gf, np.asarray(p, float), hv)
        Phi = implicit_derivative(J, Fs, Yz, Ys)
        dF_ds, dU_dz, dU_ds, J_ca, g1c, p1c = self.sens.partials(z, g, p, hv)
        dU = implicit_derivative(J_ca, dF_ds, dU_dz, dU_ds)
        nn = self.group.n ** 2
        Phi_ad = chart_jacobian(self.group, g1c, dU[:nn], dU[nn:])
        self.last = {
            "cond_J": float(np.linalg.cond(J)),
            "kernel_mismatch": float(np.abs(J - J_ca).max() / max(1.0, np.abs(J_ca).max())),
            "update_mismatch": float(max(np.abs(g1 - g1c).max(), np.abs(p1 - p1c).max())),
            "ad_mismatch": float(np.abs(Phi - Phi_ad).max() / max(1.0, np.abs(Phi).max())),
            "z": z,
        }
        return Phi, g1, p1


def defect_along(scheme_map, ad_mats, states, h, tangent=None):
    """Symplecticity defects of ``scheme_map(g, p, h) -> (Phi', g1, p1)`` at each (g, p) in
    ``states``; a list of dicts with absolute, relative, jacobian_norm. tangent: a basis
    (columns) of the constraint manifold's tangent space at the state (one state), the
    defect restricted to it (hpgen.analysis.constrained.manifold_defect)."""
    out = []
    for g, p in states:
        Phi, g1, p1 = scheme_map(g, p, h)
        if tangent is not None:
            from .constrained import manifold_defect
            a, r = manifold_defect(Phi, tangent, omega_matrix(ad_mats, p),
                                   omega_matrix(ad_mats, p1))
        else:
            a, r = symplectic_defect(Phi, omega_matrix(ad_mats, p), omega_matrix(ad_mats, p1))
        out.append({"absolute": a, "relative": r,
                    "jacobian_norm": float(np.linalg.norm(Phi, 2))})
    return out
