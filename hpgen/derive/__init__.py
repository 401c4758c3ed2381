"""Stage 3: from a validated Model and integrator options to a DiscreteStep of CasADi kernels.

    derive(model, tableau, tau, rkmk) -> DiscreteStep

tableau: a hpgen.tableaus.ButcherTableau; tau: a chart map the model's group supports; rkmk:
an RKMK constraint (both registered in hpgen.schemes); a splitting scheme
(hpgen.splitting, in place of the tableau) gives the explicit step of hpgen.splitting.flows. A left-invariant Lagrangian (no g in
l) gives the reduced Euler-Poincare step, whose unknowns live in the algebra only.

An open model (Model.open_system: forces, control inputs, runtime parameters or t) packs
what a step needs besides (g, p) into its ``h`` input, the step vector
hv = [h, t_k, u (m), params (P)] of size H = 2 + m + P (hpgen.abi.step_vector_size): t_k the
step's start time, u the control inputs (constant over the step), params the runtime
parameters (Model.runtime_symbols order). The kernels that evaluate l but take no h
(hpgen.abi.OPEN_EXTRA: legendre, hessian, energy, observe, velocity_step, record) take hv
as a last input (their t is t_k). A closed model derives exactly the conservative kernels
(zero forces included), with H = 1.

A model with ``constraints:`` wraps the step in RATTLE-type node multipliers
(hpgen.derive.constraints, docs/numerics.md sec. 14): the unknowns gain the blocks ``lambda``
and ``nu`` (impulses h lambda_k, h nu_(k+1)) and, when d2l/dxi2 is not constant, ``v1``; the
reduced Euler-Poincare step is not used.

A family model (group G^N) whose Lagrangian sums and joints are local to their bodies
(hpgen.model.bodyterms; an open one's forces written per body, hpgen.derive.family.
family_local) is derived once per body and per joint (hpgen.derive.family): g is
block-diagonal, the step kernels are composed over MX from per-body and per-joint call
nodes, the other kernels over SX with calls, and every kernel keeps its outputs' structural
sparsity (the wrappers scatter them into the contract's dense arrays). ``expand=True``
derives such a model on the product group instead (the reference for comparisons). A
splitting scheme on a constrained family model is derived this way too, its body step the
explicit splitting step (hpgen.derive.family_split; the module is not ``explicit``: Newton
solves the joints' multipliers); unconstrained, a splitting scheme is the explicit step of
hpgen.splitting on the product group.
"""
from __future__ import annotations

import casadi as ca

from ..schemes import RKMK
from ..splitting import is_splitting, splitting_step
from ..splitting.flows import open_splitting_step
from .action import step_equations
from .constraints import constrain_step, constraint_function
from .family import block_diagonal_symbol, family_local, family_step
from .family_kernels import mx_step_kernels
from .lagrangian import lagrangian_function, open_functions, to_casadi
from .linearize import step_partials
from .record_kernel import record_row, velocity_step
from ..abi import OPEN_EXTRA
from .step import KERNEL_NAMES, DiscreteStep, Kernel, OpenSpec

__all__ = ["derive", "DiscreteStep", "Kernel", "KERNEL_NAMES"]


def _dense_flat(M):
    """Column-major flattening of an SX matrix into a dense column."""
    return ca.densify(ca.reshape(M, M.numel(), 1))


#: the step's Jacobian J = dF/dz stays sparse (the kernels' J output is the nz x nz matrix
#: with J's structural nonzeros, not the dense nz*nz column; the runtime factors it with a
#: sparse QR, hpgen.codegen.sparse) when nz is at least SPARSE_MIN_NZ and at most
#: SPARSE_MAX_DENSITY of its entries are structural nonzeros (the crossover of the pendulum
#: chain's step time, benchmarks/chain_linear_algebra.py: every shipped scene stays dense)
SPARSE_MIN_NZ = 32
SPARSE_MAX_DENSITY = 0.4


def sparse_jacobian(J, jacobian) -> bool:
    """Whether the J outputs stay sparse: ``jacobian`` "sparse" / "dense" forces it, None
    applies the rule above."""
    if jacobian in ("sparse", "dense"):
        return jacobian == "sparse"
    nz = J.size1()
    return nz >= SPARSE_MIN_NZ and J.nnz() <= SPARSE_MAX_DENSITY * nz * nz


def _column(M):
    """Column-major flattening of an SX matrix, its structural zeros kept."""
    return ca.reshape(M, M.numel(), 1)


def _forced_storage(f, k, nz, jacobian):
    """f (an MX kernel) with its output k, J as a column with structural zeros, returned as
    the nz x nz matrix of its nonzeros (jacobian "sparse") or densified ("dense")."""
    args = f.mx_in()
    outs = f.call(args)
    outs[k] = ca.reshape(outs[k], nz, nz) if jacobian == "sparse" else ca.densify(outs[k])
    return ca.Function(f.name(), args, outs, f.name_in(), f.name_out())


def section_function(model, g, p):
    """SX of the scene's Poincare section s(g, mu) at (g, p) (p the node momentum), or the
    constant 1 (never crosses) when the model's scene has no ``section``."""
    spec = getattr(getattr(model, "scene", None), "section", None)
    if spec is None:
        return ca.SX(1.0)
    mapping = {sym: p[k] for k, sym in enumerate(spec.mu_symbols)}
    for i, row in enumerate(spec.g_symbols):
        for j, sym in enumerate(row):
            mapping[sym] = g[i, j]
    return to_casadi(spec.expr, mapping)


def derive(model, tableau, tau: str, rkmk: str, jacobian=None,
           expand: bool = False) -> DiscreteStep:
    """The step of ``model``. jacobian: None, "sparse" or "dense" (sparse_jacobian; a family's
    mapped step kernels follow codegen's rule, hpgen.codegen.sparse). expand: derive a family
    model (group G^N) as one expression on the product group instead of once per body and
    joint (hpgen.derive.family); for comparisons."""
    group = model.group
    fam = None
    group.require_chart(tau)
    RKMK.check(rkmk, field="integrator.rkmk")
    n, d = group.n, group.d
    # a splitting scheme on a family: the constrained split (hpgen.derive.family_split,
    # Newton on the joints' multipliers only); unconstrained, the explicit product step
    split = is_splitting(tableau)
    local = not expand and (not split or bool(model.constraints)) and family_local(model) \
        and not (split and model.family.local.potentials)   # a split body step has no fext
    # a family's g is block-diagonal: its off-diagonal entries are structural zeros, so
    # products with g stay block by block (the kernels still take all n*n entries)
    g = block_diagonal_symbol(group) if local else ca.SX.sym("g", n, n)
    p = ca.SX.sym("p", d)
    is_open = model.open_system
    if is_open:
        m, nP = len(model.inputs), len(model.runtime_symbols)
        hv = ca.SX.sym("h", 2 + m + nP)           # [h, t_k, u, params]
        h, t, u, P = hv[0], hv[1], hv[2:2 + m], hv[2 + m:]
        reduced = model.left_invariant and not model.forced and not model.time_dependent \
            and not model.constraints
        fam = family_step(model, tableau, tau, rkmk, g, p, hv) if local else None
        if fam is not None:          # per body, t, u and params passed through
            eqs, lag, force = fam.eqs, fam.lag, fam.force
        else:
            lag_f, force_f = open_functions(model)
            lag_t = lambda G, X, tt: lag_f(G, X, tt, P)  # noqa: E731
            lag = lambda G, X: lag_f(G, X, t, P)  # noqa: E731  (at t_k: records, energy)
            force = (lambda G, X, tt: force_f(G, X, tt, u, P)) if model.forced else None
            if is_splitting(tableau) and (model.forced or model.inputs
                                          or model.time_dependent):
                reduced = False      # kicks at their own times (hpgen.splitting.flows)
                eqs, chart = open_splitting_step(model, tableau, lag_f, force_f, g, p, hv)
            elif is_splitting(tableau):
                reduced = False
                eqs, chart = splitting_step(model, tableau, lag, g, p, h, P)
            else:
                eqs = step_equations(group, lag_t, tableau, tau, rkmk, reduced, g, p, h, t,
                                     force)
            lag1 = lambda G, X: lag_f(G, X, t + h, P)  # noqa: E731  (at t_{k+1})
        extra = [("h", hv)]
    else:
        h = hv = ca.SX.sym("h", 1)
        extra = []
        fam = family_step(model, tableau, tau, rkmk, g, p, h) if local else None
        if fam is not None:          # derived once per body and per joint (call nodes)
            eqs, lag = fam.eqs, fam.lag
            reduced = model.left_invariant and not model.constraints
        else:
            lag = lag1 = lagrangian_function(model)
            reduced = model.left_invariant and not model.constraints
            if is_splitting(tableau):
                reduced = False
                eqs, chart = splitting_step(model, tableau, lag, g, p, h)
            else:
                eqs = step_equations(group, lag, tableau, tau, rkmk, reduced, g, p, h)
    if model.constraints and fam is None:
        eqs = constrain_step(eqs, group, constraint_function(model), lag1, g, p, h)
    z = eqs.z
    nz = z.numel()
    gcol = ca.reshape(g, n * n, 1)
    gf = ca.vertcat(*[gcol[k] for k in gcol.sparsity().row()]) if local else _dense_flat(g)
    gvec = ca.SX.sym("g", n * n)
    gsub = gvec[gcol.sparsity().row()] if local else gvec
    to_mat = lambda e: ca.substitute(e, gf, gsub)  # noqa: E731  (kernels take g flattened)

    xi = ca.SX.sym("xi", d)
    lval = lag(g, xi)
    mu = ca.gradient(lval, xi)
    hess = ca.jacobian(mu, xi)

    mx = mx_step_kernels(model, tableau, tau, rkmk) if local else {}

    def kernel(name, inputs, outputs):
        if name in mx:               # a family's step kernels, composed over MX
            f, names_in, names_out = mx[name]
            if jacobian is not None and "J" in names_out:
                f = _forced_storage(f, names_out.index("J"), nz, jacobian)
            return Kernel(name, f, tuple(names_in), tuple(names_out))
        outputs = outputs() if callable(outputs) else outputs
        if extra and name in OPEN_EXTRA:
            inputs = list(inputs) + extra
        names_in = tuple(nm for nm, _ in inputs)
        names_out = tuple(nm for nm, _ in outputs)
        # a J kept sparse (j_out) is the nz x nz matrix: codegen writes its CCS nonzeros
        outs = ca.cse([to_mat(e) if nm == "J" and e.size2() > 1 else dense(to_mat(e))
                       for nm, e in outputs])  # merge repeated subtrees
        f = ca.Function(name, [v for _, v in inputs], outs, list(names_in), list(names_out))
        return Kernel(name, f, names_in, names_out)

    # a family's kernels keep their outputs' structural sparsity (the C and Python wrappers
    # scatter the nonzeros into the dense arrays of the contract): block-diagonal Hessians
    # and banded Jacobians of N bodies are not written out entry by entry
    dense = ca.densify if fam is None else (lambda e: e)  # noqa: E731
    flat = _dense_flat if fam is None else _column

    def j_out(J):
        """J as the kernels return it: the nz x nz matrix of its structural nonzeros when it
        stays sparse (sparse_jacobian), else flattened column-major."""
        return J if sparse_jacobian(J, jacobian) else flat(J)

    vstep = fam.velocity if fam is not None else (
        lambda G, P, X: velocity_step(G, P, X, lag))  # noqa: E731
    # the Legendre inverse at a record: one Newton step from xi = 0, exact when l is quadratic
    # in xi (hessian free of xi: legendre_quadratic), the runtime's start otherwise
    at0 = lambda e: ca.substitute(e, xi, ca.SX.zeros(d))  # noqa: E731
    xi_obs = at0(vstep(g, p, xi))
    quadratic = fam.quadratic if fam is not None else not ca.depends_on(hess, xi)
    power = None
    if is_open and model.forced:     # the forces' power at a record (t = t_k, u of hv)
        power = lambda G, X: ca.dot(force(G, X, t), X)  # noqa: E731
    row, layout = record_row(model, group, g, p, xi, lag, power)
    # what the loop may skip: g_{k+1} is not computed when neither the step nor the row use g
    step_uses_g = bool(ca.depends_on(eqs.residual, gf) or ca.depends_on(eqs.p1, gf))
    theta = ca.SX.sym("theta", 1)
    if eqs.chart_step is None:       # a splitting's own curve (hpgen.splitting)
        chart_point = lambda: chart(theta)  # noqa: E731
    else:
        chart_point = lambda: ca.mtimes(g, group.tau(tau, theta * eqs.chart_step))  # noqa: E731
    kernels = (
        kernel("residual", [("z", z), ("g", gvec), ("p", p), ("h", hv)], [("F", eqs.residual)]),
        kernel("jacobian", [("z", z), ("g", gvec), ("p", p), ("h", hv)],
               lambda: [("J", j_out(ca.jacobian(eqs.residual, z)))]),
        # F and J in one pass (shared subexpressions): full Newton's iteration
        kernel("residual_jacobian", [("z", z), ("g", gvec), ("p", p), ("h", hv)],
               lambda: [("F", eqs.residual), ("J", j_out(ca.jacobian(eqs.residual, z)))]),
        kernel("update", [("z", z), ("g", gvec), ("p", p), ("h", hv)],
               [("g1", flat(eqs.g1)), ("p1", eqs.p1)]),
        kernel("guess", [("xi", eqs.xi_hat), ("g", gvec), ("p", p), ("h", hv)], [("z0", eqs.guess)]),
        kernel("legendre", [("g", gvec), ("xi", xi)], [("mu", mu)]),
        kernel("hessian", [("g", gvec), ("xi", xi)], [("H", flat(hess))]),
        kernel("energy", [("g", gvec), ("xi", xi)], [("E", ca.dot(mu, xi) - lval)]),
        kernel("momentum", [("g", gvec), ("p", p)], [("m", group.momentum_map(g, p))]),
        kernel("defect", [("g", gvec)], [("e", group.group_defect(g))]),
        kernel("margin", [("z", z), ("h", hv)], [("m", eqs.margin)]),
        kernel("section", [("g", gvec), ("p", p)], [("s", section_function(model, g, p))]),
        kernel("chart_point", [("z", z), ("g", gvec), ("h", hv), ("theta", theta)],
               lambda: [("g_theta", flat(chart_point()))]),
        kernel("observe", [("g", gvec), ("p", p)],
               [("xi", xi_obs), ("E", ca.substitute(ca.dot(mu, xi) - lval, xi, xi_obs)),
                ("m", group.momentum_map(g, p)), ("e", group.group_defect(g))]),
        kernel("update_p", [("z", z), ("g", gvec), ("p", p), ("h", hv)], [("p1", eqs.p1)]),
        kernel("velocity_step", [("g", gvec), ("p", p), ("xi", xi)],
               [("xi1", vstep(g, p, xi))]),
        kernel("record", [("g", gvec), ("p", p), ("xi", xi)], [("row", row)]),
        kernel("step_partials", [("z", z), ("g", gvec), ("p", p), ("h", hv)],
               lambda: [(nm, flat(e)) for nm, e in zip(("Fs", "Yz", "Ys", "FH", "YH"),
                   step_partials(group, g, p, z, eqs.residual, eqs.g1, eqs.p1,
                                 hv if is_open else None))]),
    )
    assert tuple(k.name for k in kernels) == KERNEL_NAMES
    return DiscreteStep(
        model_name=model.name, group_name=group.name, n=n, d=d, nz=nz,
        tableau_name=tableau.name, tableau_order=tableau.order, tau=tau, rkmk=rkmk,
        reduced=reduced, unknowns=eqs.blocks, kernels=kernels,
        section=getattr(getattr(getattr(model, "scene", None), "section", None), "text", None),
        open_spec=OpenSpec(model.inputs, model.runtime_parameters, model.runtime_defaults,
                           model.forced, model.time_dependent) if is_open else None,
        legendre_quadratic=quadratic, record_layout=layout, step_uses_g=step_uses_g,
        record_uses_g=bool(ca.depends_on(row, gf)), record_uses_xi=bool(ca.depends_on(row, xi)),
        explicit=split and fam is None)
