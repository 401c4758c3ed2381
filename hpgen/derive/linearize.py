"""The partial derivatives of one step in the state (kernel ``step_partials``).

The step solves F(z; g, p, h) = 0 for z and applies the explicit update U(z; g, p, h) =
(g_{k+1}, p_{k+1}). State perturbations (math.md sec. 10) are right-trivialized:

    g -> g tau(eta),  p -> p + dp,     s = (eta, dp) in R^d x R^d,

with tau the module's chart map. Every registered chart has tau(eta) = e + eta^ + O(|eta|^2),
so the first derivatives below (taken through g (e + eta^)) are those of every chart: the
linearization does not depend on which tau the module uses. The output state is read in the
same chart at the nominal g_{k+1}: eta_{k+1} = vee(g_{k+1}^{-1} dg_{k+1}) (the group's vee of
an algebra element), dp_{k+1}.

    step_partials(z, g, p, h) -> Fs[nz x 2d], Yz[2d x nz], Ys[2d x 2d]   (column-major)

Fs = dF/ds, Yz = d(eta_{k+1}, p_{k+1})/dz, Ys = d(eta_{k+1}, p_{k+1})/ds at s = 0. An open
module's kernel (step vector H = [h, t_k, u, params], hpgen.abi.OPEN_OUTPUTS) has two more
outputs, the partials in the step vector's entries:

    ... FH[nz x H] = dF/dH, YH[2d x H] = d(eta_{k+1}, p_{k+1})/dH

so that d Y / d u_k = YH_u - Yz J^{-1} FH_u (columns 2..2+m) and likewise for the runtime
parameters (columns 2+m..H); a closed module's kernel is unchanged. With the
converged z and J = dF/dz (the ``jacobian`` kernel), the implicit function theorem gives the
step's derivative A = Ys - Yz J^{-1} Fs (hpgen.runtime.linearize.implicit_derivative).
J is not an output here: a second copy of the Jacobian's code (the largest kernel) would
about double gcc's time on kernels.c, for a small part of linearize's time.
"""
from __future__ import annotations

import casadi as ca


def step_partials(group, g, p, z, residual, g1, p1, hv=None):
    """(Fs, Yz, Ys) as SX matrices at s = 0, from the step's SX residual (nz), g1 (n x n) and
    p1 (d) in the symbols g (n x n SX), p (d), z (nz); with the step vector symbol hv (an
    open module's H entries) also (FH, YH), the partials in hv."""
    n, d = group.n, group.d
    eta, dp = ca.SX.sym("eta", d), ca.SX.sym("dp", d)
    s = ca.vertcat(eta, dp)
    g_s = ca.mtimes(g, ca.SX.eye(n) + group.hat(eta))
    old = ca.vertcat(ca.reshape(g, n * n, 1), p)
    new = ca.vertcat(ca.reshape(g_s, n * n, 1), p + dp)
    F_s, g1_s, p1_s = ca.substitute([residual, g1, p1], [old], [new])
    # the output chart at the nominal g_{k+1}: g1ref is held fixed while differentiating
    g1ref = ca.SX.sym("g1ref", n, n)
    Y = ca.vertcat(group.vee(ca.mtimes(group.inverse(g1ref), g1_s)), p1_s)
    outs = [ca.jacobian(F_s, s), ca.jacobian(Y, z), ca.jacobian(Y, s)]
    if hv is not None:
        outs += [ca.jacobian(F_s, hv), ca.jacobian(Y, hv)]
    outs = ca.substitute(outs, [s], [ca.SX.zeros(2 * d)])
    return tuple(ca.substitute(outs, [ca.reshape(g1ref, n * n, 1)],
                               [ca.densify(ca.reshape(g1, n * n, 1))]))
