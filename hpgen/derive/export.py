"""A compiled module's step as a CasADi function, for optimal control.

    casadi_step(module_dir, meta) -> casadi.Function
        step(g[n x n], p[d], h, z[nz]) -> (F[nz], g1[n x n], p1[d])

F is the step's residual (the stationarity conditions of one term of the discrete action,
F(z; g, p, h) = 0 defines the step) and (g1, p1) = (g_{k+1}, p_{k+1}) its explicit update, as
SX expressions: K steps go into ``casadi.Opti`` as the constraints F(z_k; g_k, p_k, h) = 0,
g_{k+1} = g1(z_k, ...), p_{k+1} = p1(z_k, ...) (the Function may be called on MX).

An open module (forces, inputs, runtime parameters or t; hpgen.abi's step vector
H = [h, t_k, u, params]) gives

        step(g[n x n], p[d], u[m], params[P], h, z[nz], t) -> (F[nz], g1[n x n], p1[d])

u the inputs held over the step, params the runtime parameters (flat, the model's order),
t the step's start time t_k (last: unused unless the model depends on t).

Compile-time stack (casadi): reached only through Integrator.casadi_step (which imports
``module_casadi_step`` lazily), never on the runtime path. The DiscreteStep is derived again
from the module's model.yaml and meta.json options (derive is deterministic); it is checked
against the module's own residual kernel at a sample point.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import ModelError

#: relative agreement required between the re-derived residual and the module's kernel
#: (the same SX algorithm evaluated by CasADi and by generated code: round-off only)
MATCH_RTOL = 1e-12


def casadi_step(step, residual_kernel=None, where="the module"):
    """The DiscreteStep ``step`` as casadi.Function (see the module docstring).
    residual_kernel: the module's compiled residual (z, g, p, h) -> [F], checked against
    the derivation (ModelError naming ``where`` when they differ)."""
    import casadi as ca
    n, d, nz = step.n, step.d, step.nz
    res = step.kernel("residual").function
    upd = step.kernel("update").function
    G, P, H, Z = ca.SX.sym("g", n, n), ca.SX.sym("p", d), ca.SX.sym("h"), ca.SX.sym("z", nz)
    gv = ca.reshape(G, n * n, 1)
    spec = step.open_spec
    if spec is None:
        ins, names, hv = [G, P, H, Z], ["g", "p", "h", "z"], H
    else:
        U, Q, T = ca.SX.sym("u", len(spec.inputs)), ca.SX.sym("params", spec.H - 2 - len(
            spec.inputs)), ca.SX.sym("t")
        ins, names, hv = [G, P, U, Q, H, Z, T], ["g", "p", "u", "params", "h", "z", "t"], \
            ca.vertcat(H, T, U, Q)
    g1, p1 = upd(Z, gv, P, hv)
    f = ca.Function("hpgen_step", ins, [res(Z, gv, P, hv), ca.reshape(g1, n, n), p1],
                    names, ["F", "g1", "p1"])
    if residual_kernel is not None:
        rng = np.random.default_rng(0)
        z, g, p = rng.standard_normal(nz) * 0.1, np.eye(n), rng.standard_normal(d)
        sample = np.concatenate([[0.01], rng.standard_normal(0 if spec is None else spec.H - 1)])
        args = [0.01] if spec is None else [sample[2:2 + len(spec.inputs)],
                                            sample[2 + len(spec.inputs):], 0.01]
        t = [] if spec is None else [sample[1]]
        ours = np.array(f(g, p, *args, z, *t)[0]).ravel()
        theirs = np.asarray(residual_kernel(z, g.ravel(order="F"), p, sample)[0])
        if not np.abs(ours - theirs).max() <= MATCH_RTOL * (1.0 + np.abs(theirs).max()):
            raise ModelError("the re-derived residual differs from the module's kernel; "
                             "regenerate the module with this hpgen", file=where)
    return f


def module_casadi_step(module_dir, meta, residual_kernel=None):
    """The step of a generated module as casadi.Function (see the module docstring): its
    ``model.yaml`` derived again with meta.json's options (tableau, tau, rkmk) and checked
    against ``residual_kernel`` (the module's compiled residual). ModelError naming the file
    for a bad model file, field casadi_step when module_dir is None."""
    if module_dir is None:
        raise ModelError("this Integrator was made without its module directory; load it "
                         "with hpgen.runtime.load", field="casadi_step")
    from ..model import load_model_text
    from ..model.loader import read_model_bytes
    from ..tableaus import resolve_tableau
    from . import derive
    from .checks import check_legendre
    path = str(Path(module_dir) / "model.yaml")
    try:
        text = read_model_bytes(path).decode("utf-8")
    except UnicodeDecodeError:
        raise ModelError("expected a UTF-8 text file", file=path) from None
    model = load_model_text(text, filename=path)
    o = meta["options"]
    try:
        step = derive(model, resolve_tableau(o["tableau"]), o["tau"], o["rkmk"])
        check_legendre(step, model)
    except ModelError as e:
        raise e.located(file=path) from None
    return casadi_step(step, residual_kernel, where=path)
