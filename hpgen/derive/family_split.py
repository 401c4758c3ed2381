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
the step's ends.

An open model (runtime parameters and t in l_i, a per-body force with the control inputs,
hpgen.derive.family_open) kicks with -dV_i(t, g_i) + f_i(g_i, t, u_k, params) at the kick's
time: t_k for the first kick, t_k + h for the last (the forced Stormer-Verlet's discrete
forces, h/2 at each node). A force that depends on xi would make the kick implicit and is
refused, as are forces between bodies (a kick of one body that reads its neighbours' g at
t_k + h) and an inertia that depends on a runtime parameter (the flows' moments are
numbers).

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
    ``model``'s forces are kicks: a per-body force of (g, t, u, params), not of xi, and no
    forces between bodies."""
    if scheme.stages != 1:
        raise ModelError(f"{scheme.name} on a constrained model: the constraints are imposed "
                         "only at the step's ends; use split2 with integrator.compose "
                         "(suzuki4, yoshida4, kahan-li6) for higher order", field=FIELD)
    force = getattr(model.family.local, "force", None) if model.open_system else None
    if force is not None and force.joints:
        raise ModelError(f"{scheme.name} on a constrained model takes a per-body force "
                         "(forces.body), not forces between bodies (forces.joint); use a "
                         "VPRK tableau", field=FIELD)
    for k, e in enumerate(force.exprs if force is not None else ()):
        if any(str(s).startswith("xi_") for s in e.free_symbols):
            texts = getattr(model, "forces_text", ())      # body 0's entries first
            text = texts[k].rsplit(" (", 1)[0] if k < len(texts) else str(e)
            text = text if len(text) <= 40 else text[:37] + "..."
            raise ModelError(f"{scheme.name} on a constrained model needs forces free of the "
                             f"velocity (a kick); forces.body[{k}] ({text}) depends on it; "
                             "use a VPRK tableau", field=FIELD)
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
    step and that step as a map of SX matrices (g1 = newton_schulz(g1_raw)). lag(G, X, e)
    the body's l (SX, the index symbol ``index`` bound; e = (t, params) of an open model,
    None when closed), g (nb x nb), p (db) SX symbols, h the step (1) or an open model's
    step vector hv = [h, t_k, u, params] (hpgen.derive.family_open). ModelError when the
    body lacks the structure (naming the class and the term) or a force is not a kick.

    The mapped family step (hpgen.derive.family_map) takes the Newton-Schulz step on g1
    alone: the joints' rows and end impulses read g1_raw, and the Jacobian blocks
    differentiate it (the step moves g1 by round-off and its derivative is the identity on
    the group's tangent vectors to round-off), so neither the residual nor J pays for it."""
    from ..splitting.flows import composition, schedule
    from ..splitting.structure import recognise_lagrangian
    check_split_family(model, scheme)
    where = f"body class {c} (sums {', '.join(map(str, cls))}): "
    if model.open_system:
        E = ca.SX.sym("e", 1 + len(model.runtime_symbols))
        structure = recognise_lagrangian(body, lambda G, X: lag(G, X, E),
                                         ca.vertcat(index, E), lambda: _breaking(model, cls),
                                         where)
        force, moving, h = _open_kick(model, scheme, body, lag, g, h, index)
    else:
        from ..splitting.flows import _force_function
        structure = recognise_lagrangian(body, lambda G, X: lag(G, X, None), index,
                                         lambda: _breaking(model, cls), where)
        force = _force_function(body, lambda G, X: lag(G, X, None), g)
        moving = ca.vertcat(ca.vec(g), index)
    kicks = bool(ca.depends_on(_kick_expr(force, g), moving)) or \
        bool(ca.DM(ca.evalf(_kick_expr(force, g))).full().any())
    ops = schedule(structure, scheme, kicks)
    raw, p1 = composition(structure, body, force, g, ops, g, p, h)
    g1 = _reorthogonalized(structure, raw)
    z = ca.SX.sym("z", 0)
    return StepEquations(z=z, blocks=(), residual=ca.SX(0, 1), g1=g1, p1=p1,
                         guess=ca.SX(0, 1), xi_hat=ca.SX.sym("xi_hat", body.d),
                         margin=ca.SX(1.0), chart_step=ca.SX.zeros(body.d)), raw, \
        (lambda G: _reorthogonalized(structure, G))


def _kick_expr(force, g):
    """The kick's force as an SX (an open model's callable at its first kick)."""
    return force(g, 0) if callable(force) else force


def _open_kick(model, scheme, body, lag, g, hv, index):
    """(force, moving, h) of an open model: force(G, j) the kick's force at the j-th kick
    (time t_k + kick_fractions[j] h: the step's two ends for split2), -dV(t) plus the body's
    force f(g, t, u_k, params) (the discrete Lagrange-d'Alembert force of Stormer-Verlet's
    two nodes, h/2 each); the symbols the force may depend on; the step h of hv."""
    from ..splitting.flows import _force_function, kick_fractions
    from .family_open import body_force_expression, split_step_vector
    h = split_step_vector(model, hv)[0]
    m = len(model.inputs)
    u, P = hv[2:2 + m], hv[2 + m:]
    t = ca.SX.sym("t")
    f = _force_function(body, lambda G, X: lag(G, X, ca.vertcat(t, P)), g)
    fb = body_force_expression(model, body)
    if fb is not None:       # inlined, not a call: the step's Jacobian sees the force's zeros
        f = f + ca.substitute(fb[1], fb[0], [ca.vec(g), ca.SX.zeros(body.d), index,
                                             ca.vertcat(t, u, P)])[0]
    times = kick_fractions(scheme)
    at = ca.vertcat(ca.vec(g), t)

    def force(G, j):
        return ca.substitute(f, at, ca.vertcat(ca.vec(G), hv[1] + times[j] * h))
    return force, ca.vertcat(ca.vec(g), index, hv), h


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
