"""A family model's ABI step kernels composed over MX (hpgen.derive.family derives the
per-body and per-joint functions; hpgen.derive.family_map maps them over the bodies).

The kernels keep their outputs' structural sparsity; their inputs are the contract's
(hpgen.abi): g flattened n*n column-major (block-diagonal for G^N), p (d), h.
"""
from __future__ import annotations

import casadi as ca

from ..groups import group_from_spec
from .family import CALL, _functions, block_diagonal_symbol, family_step
from .family_open import open_layout


def _body_maps(body, tau: str):
    """Per-body SX functions (call nodes) for the MX kernels: the chart point
    g tau(theta x), the perturbed element g (I + eta^), and vee(g_ref^{-1} g)."""
    G, R = ca.SX.sym("g", body.n, body.n), ca.SX.sym("gref", body.n, body.n)
    x, th, eta = ca.SX.sym("x", body.d), ca.SX.sym("theta"), ca.SX.sym("eta", body.d)
    return (ca.Function("body_chart_point", [ca.vec(G), x, th],
                        [ca.vec(ca.mtimes(G, body.tau(tau, th * x)))], CALL),
            ca.Function("body_perturbed", [ca.vec(G), eta],
                        [ca.vec(ca.mtimes(G, ca.SX.eye(body.n) + body.hat(eta)))], CALL),
            ca.Function("body_chart_of", [ca.vec(R), ca.vec(G)],
                        [body.vee(ca.mtimes(body.inverse(R), G))], CALL))


def _blocks(M, nb, N):
    return [ca.vec(M[k * nb:(k + 1) * nb, k * nb:(k + 1) * nb]) for k in range(N)]


def mx_step_kernels(model, tableau, tau: str, rkmk: str) -> dict:
    """{kernel name: (Function over MX, input names, output names)} for the step kernels of
    a family model (residual, jacobian, residual_jacobian, update, guess, margin,
    chart_point, update_p, step_partials; hpgen.abi's signatures, closed models). Composed
    over MX, the calls pass whole vectors and CasADi differentiates them through the
    callees' own Jacobians (``jac_penalty`` 0): the generated C has the per-body functions
    once and a few lines per call. Outputs keep their structural sparsity. On the mapped
    path J (jacobian, residual_jacobian) is assembled from per-body and per-joint blocks
    (hpgen.derive.family_jacobian), O(N) work, and so is a closed model's step_partials
    (hpgen.derive.family_partials)."""
    n, d = model.group.n, model.group.d
    body = group_from_spec(model.family.body)
    nb, N = body.n, model.family.count
    lay = open_layout(model)
    h = ca.MX.sym("h") if lay is None else ca.MX.sym("h", 2 + lay[0] + lay[1])
    gv, p = ca.MX.sym("g", n * n), ca.MX.sym("p", d)
    mapped = _mapped_kernels(model, tableau, tau, rkmk, gv, p, h)
    if mapped is not None:
        from .family_map import mapped_state_kernels
        from .record_kernel import record_names
        _, lags, keys, steps, _, _ = _functions(model, tableau, tau, rkmk)
        st = next(iter(steps.values()))
        state = mapped_state_kernels(model, lags, keys, body, record_names(model), st["force"],
                                     st["potentials"])
        return {**mapped, **(state or {})}
    g = ca.reshape(gv, n, n)
    eqs = family_step(model, tableau, tau, rkmk, g, p, h).eqs
    z, col = eqs.z, (lambda M: ca.reshape(M, M.numel(), 1))  # noqa: E731
    J = col(ca.jacobian(eqs.residual, z))
    g1 = col(eqs.g1)
    chart_fn, perturb, chart_of = _body_maps(body, tau)
    theta = ca.MX.sym("theta")
    db = body.d
    gth = ca.diagcat(*[ca.reshape(chart_fn(G, eqs.chart_step[k * db:(k + 1) * db], theta),
                                  nb, nb) for k, G in enumerate(_blocks(g, nb, N))])
    # step partials (hpgen.derive.linearize): s = (eta, dp), g -> g (I + eta^), p -> p + dp
    eta, dp = ca.MX.sym("eta", d), ca.MX.sym("dp", d)
    g_s = ca.diagcat(*[ca.reshape(perturb(G, eta[k * db:(k + 1) * db]), nb, nb)
                       for k, G in enumerate(_blocks(g, nb, N))])
    pert = family_step(model, tableau, tau, rkmk, g_s, p + dp, h, z=z).eqs
    g1ref = ca.MX.sym("g1ref", n * n)
    Y = ca.vertcat(*[chart_of(R, G) for R, G in zip(_blocks(ca.reshape(g1ref, n, n), nb, N),
                                                    _blocks(pert.g1, nb, N))], pert.p1)
    s = ca.vertcat(eta, dp)
    parts = _partials(pert.residual, Y, z, s, h, lay is not None)
    parts = ca.substitute(parts, [s, g1ref], [ca.MX.zeros(2 * d), ca.densify(g1)])
    return _step_kernels(eqs, z, gv, p, h, eqs.xi_hat, theta, J, g1, col(gth),
                         [col(e) for e in parts])


def _mapped_kernels(model, tableau, tau, rkmk, gv, p, h) -> dict | None:
    """mx_step_kernels' dict from mapped calls (hpgen.derive.family_map), or None when the
    family does not qualify (several Lagrangian classes, a node velocity that is not
    explicit)."""
    from .family_jacobian import residual_and_jacobian
    from .family_map import mapped, mapped_step, mapped_step_parts
    funcs = _functions(model, tableau, tau, rkmk)
    body, lags, keys, steps, jfun, vel_funs = funcs
    if len(steps) != 1 or any(f is None for f in vel_funs.values()):
        return None
    n, d, N = model.group.n, model.group.d, model.family.count
    nb, db = body.n, body.d
    gcol = ca.reshape(ca.DM(block_diagonal_symbol(model.group).sparsity(), 1.0), n * n, 1)
    spcol = gcol.sparsity()
    # g as its block-diagonal nonzeros (the kernels gather them from the contract's dense
    # n*n input): no kernel copies or reads g's N^2 zeros. Column-major, body k's vec(g_k)
    # are the nonzeros k nb^2 .. (k + 1) nb^2 - 1.
    gv = ca.MX.sym("g", spcol)
    G = ca.reshape(ca.sparsity_cast(gv, ca.Sparsity.dense(spcol.nnz(), 1)), nb * nb, N)
    P = ca.reshape(p, db, N)
    m = sum(len(j.rows) for j in model.family.local.joints)
    nzb = next(iter(steps.values()))["nz"]
    z = ca.MX.sym("z", nzb * N + (2 * m if m else 0))
    xi_hat = ca.MX.sym("xi_hat", d)
    out = mapped_step_parts(model, funcs, G, P, h, z, xi_hat)
    if out is None:
        return None
    eqs = out[0]
    col = lambda M: ca.reshape(M, M.numel(), 1)  # noqa: E731
    cast = lambda M: ca.sparsity_cast(ca.vec(M), spcol)  # noqa: E731  (nb^2 x N -> g's)
    F, J = residual_and_jacobian(model, funcs, eqs.residual, out[1])
    J = col(J)
    chart_fn, perturb, chart_of = _body_maps(body, tau)
    theta = ca.MX.sym("theta")
    gth = mapped(chart_fn, N)(G, ca.reshape(eqs.chart_step, db, N), theta)
    if model.open_system:            # the partials in the step vector too: casadi.jacobian
        eta, dp = ca.MX.sym("eta", d), ca.MX.sym("dp", d)
        G_s = mapped(perturb, N)(G, ca.reshape(eta, db, N))
        pert = mapped_step(model, funcs, G_s, P + ca.reshape(dp, db, N), h, z, xi_hat)
        G1ref = ca.MX.sym("g1ref", nb * nb, N)
        Y = ca.vertcat(ca.vec(mapped(chart_of, N)(G1ref, pert.g1)), pert.p1)
        s = ca.vertcat(eta, dp)
        parts = _partials(pert.residual, Y, z, s, h, True)
        parts = ca.substitute(parts, [s, G1ref], [ca.MX.zeros(2 * d), eqs.g1])
    else:                            # blockwise, like J (hpgen.derive.family_partials)
        from .family_partials import assembled_partials
        parts = assembled_partials(model, funcs, out[1])
    return _step_kernels(eqs, z, gv, p, h, xi_hat, theta, J, cast(eqs.g1), cast(gth),
                         [col(e) for e in parts], F)


def _partials(F, Y, z, s, hv, is_open: bool) -> list:
    """step_partials' outputs (hpgen.derive.linearize): dF/ds, dY/dz, dY/ds, and for an open
    model dF/dH, dY/dH in its step vector hv."""
    out = [ca.jacobian(F, s), ca.jacobian(Y, z), ca.jacobian(Y, s)]
    return out + [ca.jacobian(F, hv), ca.jacobian(Y, hv)] if is_open else out


def _step_kernels(eqs, z, gv, p, h, xi_hat, theta, J, g1, g_theta, partials,
                  F=None) -> dict:
    """{kernel name: (Function, input names, output names)} of the step kernels from the
    family's step equations over MX (hpgen.abi's signatures; g1, g_theta as the contract's
    flattened g, partials the step_partials outputs Fs, Yz, Ys; F: the residual beside J in
    residual_jacobian, the same values as eqs.residual, default eqs.residual)."""
    step_in = ([z, gv, p, h], ("z", "g", "p", "h"))
    out = {"residual": (step_in, [eqs.residual], ("F",)),
           "jacobian": (step_in, [J], ("J",)),
           "residual_jacobian": (step_in, [eqs.residual if F is None else F, J], ("F", "J")),
           "update": (step_in, [g1, eqs.p1], ("g1", "p1")),
           "guess": (([xi_hat, gv, p, h], ("xi", "g", "p", "h")), [eqs.guess], ("z0",)),
           "margin": (([z, h], ("z", "h")), [eqs.margin], ("m",)),
           "chart_point": (([z, gv, h, theta], ("z", "g", "h", "theta")), [g_theta],
                           ("g_theta",)),
           "update_p": (step_in, [eqs.p1], ("p1",)),
           "step_partials": (step_in, partials, ("Fs", "Yz", "Ys", "FH", "YH")[:len(partials)])}
    return {name: (ca.Function(name, list(ins), outs, list(nin), list(nout)), nin, nout)
            for name, ((ins, nin), outs, nout) in out.items()}
