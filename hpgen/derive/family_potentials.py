"""Joint potentials of a family model (hpgen.model.bodyterms.JointPotential: a Lagrangian sum
whose term involves a few bodies' configurations and no velocity, e.g. a rod's bending and
twisting energy V(g_(i-1), g_i)), derived once per sum.

Conventions: l_j = sign * term is the sum's part of l (-V for a potential energy V), a
function of the K slots' g_s and the index i. Its force on slot s is the left-trivialized
gradient

    f_s = d/deta l_j(g_0, ..., g_s (I + eta^), ..., g_(K-1)) at eta = 0     (d entries),

a joint force (hpgen.derive.family_joint_forces) with the signature of joint_force_functions'
functions (the slots' xi and the environment e = (t, u, params) are inputs it ignores), so it
reaches the body steps as their external stage forces fext. Since l_j has no xi, the
discrete action's stage term h b_s l_j(G^s) varied at G^s (I + eps^) gives exactly
h b_s <f(G^s), eps> (hpgen.derive.action: the Lagrange-d'Alembert virtual work at the
unvaried stage states): the step is the expanded step of the same Lagrangian, not an
approximation of it. The energy (<dl/dxi, xi> - l) gets -l_j, the Legendre map nothing.

A potential's ``exprs`` (PotentialForce, as a JointForce's: K tuples of d entries, here the
SX force components) say which components can be nonzero (force_components). Each force
Function has an inlinable copy (PotentialForce.inline) that the mapped step's stage function
takes in place of the call (family_joint_forces.joint_stage_functions), so that its Jacobian
blocks are one symbolic SX graph. The functions are built once per model and scheme by their
caller (hpgen.derive.family._functions, which keeps them with the body steps) and passed to
the functions below: one CasADi function each in the generated code.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import casadi as ca

from .lagrangian import to_casadi
from .family_calls import CALL


@dataclass(frozen=True)
class PotentialForce:
    exprs: tuple                   # K tuples of d SX scalars: the slots' forces
    index: object                  # sympy Symbol of the sum variable
    instances: tuple               # ((i, (body, ...)), ...)
    #: the force Function's copy without call-node options (inlined where it is called)
    inline: object = field(default=None, compare=False, repr=False)


def inline_forces(pforces) -> dict:
    """{force Function: its inlinable copy} of ``pforces``, (force Function, PotentialForce)
    pairs of potential_functions."""
    return {f: pf.inline for f, pf in pforces}


def potential_functions(model, body) -> list:
    """[(energy Function(vec g_0, ..., vec g_(K-1), i[, e]) -> l_j, e = (t, params) when the
    model is open; force Function as joint_force_functions'; PotentialForce), ...] of the
    model's joint potentials, new CasADi functions on each call."""
    pots = model.family.local.potentials
    nb, db = body.n, body.d
    m, nP = len(model.inputs), len(model.runtime_symbols)
    out = []
    for c, pot in enumerate(pots):
        K = len(pot.instances[0][1]) if pot.instances else 1
        Gs = [ca.SX.sym(f"g{s}", nb, nb) for s in range(K)]
        Xs = [ca.SX.sym(f"xi{s}", db) for s in range(K)]
        I = ca.SX.sym("i")
        Ef = ca.SX.sym("e", 1 + m + nP)
        mapping = {pot.index: I, **{s: Ef[1 + m + k] for k, s in enumerate(model.runtime_symbols)}}
        for sym in pot.expr.free_symbols:
            name = str(sym)
            if name.startswith("g_"):
                a, b = map(int, name[2:].split("_"))
                mapping[sym] = Gs[a // nb][a % nb, b % nb]
        lj = to_casadi(pot.expr, mapping)
        etas = [ca.SX.sym(f"eta{s}", db) for s in range(K)]
        varied = ca.substitute(lj, ca.vertcat(*[ca.vec(G) for G in Gs]), ca.vertcat(*[
            ca.vec(ca.mtimes(G, ca.SX.eye(nb) + body.hat(e))) for G, e in zip(Gs, etas)]))
        zero = ca.SX.zeros(K * db)
        fs = [ca.substitute(ca.gradient(varied, e), ca.vertcat(*etas), zero) for e in etas]
        args = [v for G, X in zip(Gs, Xs) for v in (ca.vec(G), X)]
        force = ca.Function(f"potential_force{c}", [*args, I, Ef], fs, CALL)
        inline = ca.Function(f"potential_force{c}_inline", [*args, I, Ef], fs)
        gins = [ca.vec(G) for G in Gs]
        if model.open_system:
            Ee = ca.SX.sym("e", 1 + nP)
            le = ca.substitute(lj, Ef[1 + m:], Ee[1:])
            energy = ca.Function(f"potential{c}", [*gins, I, Ee], [le], CALL)
        else:
            energy = ca.Function(f"potential{c}", [*gins, I], [lj], CALL)
        exprs = tuple(tuple(f[k] for k in range(db)) for f in fs)
        out.append((energy, force, PotentialForce(exprs, pot.index, pot.instances, inline)))
    return out


def product_potential(pots, body, Gp, ek=None):
    """sum_j l_j of potential_functions' ``pots`` at the product's Gp (n x n) and the
    environment ek = (t, params) of an open model (else None): one call per instance."""
    nb = body.n
    total = 0
    for energy, _, pf in pots:
        for i, bodies in pf.instances:
            args = [ca.vec(Gp[b * nb:(b + 1) * nb, b * nb:(b + 1) * nb]) for b in bodies]
            total = total + energy(*args, i, *([] if ek is None else [ek]))
    return total


def mapped_potential(pots, G, ek=None):
    """sum_j l_j of potential_functions' ``pots`` at the bodies' G (nb^2 x N, MX) and ek
    (open models), one mapped call per potential."""
    from .family_map import mapped
    total = 0
    for energy, _, pf in pots:
        K = len(pf.exprs)
        cols = [[b[s] for _, b in pf.instances] for s in range(K)]
        Ij = ca.DM([i for i, _ in pf.instances]).T
        res = mapped(energy, len(pf.instances))(*[G[:, c] for c in cols], Ij,
                                                *([] if ek is None else [ek]))
        total = total + ca.sum2(res)
    return total
