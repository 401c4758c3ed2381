"""The body step of a constrained family model under a splitting scheme: RATTLE with the
unconstrained flow replaced by the explicit splitting step (McLachlan, Modin, Verdier,
Wilkins, "Geometric generalisations of SHAKE and RATTLE", Found. Comput. Math. 2014).

For a body Lagrangian l_i = 1/2 xi.M xi - V_i(g_i) (hpgen.splitting.structure, recognised
on the body: recognise_lagrangian) the body's update from (g_i, p_i^+) (p_i^+ the node
momentum after the joints' impulses, hpgen.derive.family) is the basic splitting step

    S(h) = K(h/2) F(h) K(h/2)

(hpgen.splitting.flows: the kick of -V_i, the free flow, exact for a symmetric body, DLM
rotations or Fasso's split otherwise; each rotation block of g1 then taken one Newton-Schulz
step towards the rotations, a round-off change, _reorthogonalized): explicit, so the body has no unknowns (nz = 0) and
the family step's unknowns are the joints' multipliers lambda, nu alone. Symmetric and
symplectic on the constraint manifold, order 2; higher order by integrator.compose.

Only one-stage schemes (``split2``, ``split2-fasso``) are accepted: a composition inside the
step would need the constraints at its inner nodes, which the family step imposes only at
the step's ends. The model must be closed (no forces, inputs, runtime parameters or t).

The body step's chart step (chart_point's curve g tau(theta x), for the scene's Poincare
sections) would need the unknowns; it is zero here, and a model with ``scene.section`` is
refused.
"""
from __future__ import annotations

import casadi as ca
from ..errors import ModelError
from .action import StepEquations

FIELD = "integrator.tableau"


def check_split_family(model, scheme) -> None:
    """ModelError (integrator.tableau) unless ``scheme`` is a one-stage splitting scheme and
    ``model`` a closed family model."""
    if scheme.stages != 1:
        raise ModelError(f"{scheme.name} on a constrained model: the constraints are imposed "
                         "only at the step's ends; use split2 with integrator.compose "
                         "(suzuki4, yoshida4, kahan-li6) for higher order", field=FIELD)
    if model.open_system:
        raise ModelError(f"{scheme.name} on a constrained model needs a closed model (no "
                         "forces, control inputs, runtime parameters or t); use a VPRK "
                         "tableau", field=FIELD)
    if getattr(getattr(model, "scene", None), "section", None) is not None:
        raise ModelError(f"{scheme.name} on a constrained model does not locate the scene's "
                         "section crossings; use a VPRK tableau", field=FIELD)


def _breaking(model, cls) -> str:
    """The text of the first term of body class ``cls``'s sums that breaks the structure."""
    from ..splitting.structure import _term_breaking
    terms = model.family.local.bodies
    for j in cls:
        xs = sorted((s for s in terms[j].expr.free_symbols if str(s).startswith("xi_")),
                    key=str)
        t = _term_breaking(model, terms[j].expr, xs)
        if t:
            return t
    return ""


def split_body_step(model, scheme, body, lag, g, p, h, index, cls, c: int) -> tuple:
    """(eqs, g1_raw, newton_schulz): the body step S(h) of class ``cls`` (the sums it has;
    ``c`` its number) as StepEquations with no unknowns, its g1 before the Newton-Schulz
    step and that step as a map of SX matrices (g1 = newton_schulz(g1_raw)). lag(G, X) the
    body's l (SX, the index symbol ``index`` bound), g (nb x nb), p (db), h (1) SX symbols.
    ModelError when the body lacks the structure (naming the class and the term).

    The mapped family step (hpgen.derive.family_map) takes the Newton-Schulz step on g1
    alone: the joints' rows and end impulses read g1_raw, and the Jacobian blocks
    differentiate it (the step moves g1 by round-off and its derivative is the identity on
    the group's tangent vectors to round-off), so neither the residual nor J pays for it."""
    from ..splitting.flows import _force_function, composition, schedule
    from ..splitting.structure import recognise_lagrangian
    check_split_family(model, scheme)
    where = f"body class {c} (sums {', '.join(map(str, cls))}): "
    structure = recognise_lagrangian(body, lag, index, lambda: _breaking(model, cls), where)
    force = _force_function(body, lag, g)
    moving = ca.vertcat(ca.vec(g), index)
    kicks = bool(ca.depends_on(force, moving)) or bool(ca.DM(ca.evalf(force)).full().any())
    ops = schedule(structure, scheme, kicks)
    raw, p1 = composition(structure, body, force, g, ops, g, p, h)
    g1 = _reorthogonalized(structure, raw)
    z = ca.SX.sym("z", 0)
    return StepEquations(z=z, blocks=(), residual=ca.SX(0, 1), g1=g1, p1=p1,
                         guess=ca.SX(0, 1), xi_hat=ca.SX.sym("xi_hat", body.d),
                         margin=ca.SX(1.0), chart_step=ca.SX.zeros(body.d)), raw, \
        (lambda G: _reorthogonalized(structure, G))


def _reorthogonalized(structure, g1):
    """g1 with each rotation block R replaced by R (3 I - R^T R) / 2 (one Newton-Schulz step
    towards the nearest rotation: a change of O(|R^T R - I|), round-off here). A symmetric
    body's spin about its axis is constant on a chain (the joints exert no torque about it),
    so the step multiplies R by the same rounded rotation every step and R^T R - I grew
    linearly, about 1e-16 per step, without it."""
    g1 = ca.SX(g1)
    for fk in structure.factors:
        if fk.family in ("SO3", "SE3"):
            r = fk.row
            R = g1[r:r + 3, r:r + 3]
            g1[r:r + 3, r:r + 3] = 0.5 * ca.mtimes(R, 3 * ca.SX.eye(3) - ca.mtimes(R.T, R))
    return g1
