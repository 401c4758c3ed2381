"""A hand-built DiscreteStep for codegen/runtime tests (no derive stage needed).

Free rigid body on SO(3), Cayley Euler-Poincare step, unknown z = xi (nz = 3):
  F(z) = (dcay^{-1}_{hz})^T I z - p,   dcay^{-1}_x = 1 - x^/2 + x x^T/4
  g1 = g cay(h z),  cay(x) = 1 + 4/(4 + |x|^2) (x^ + x^ x^/2),  p1 = (dcay^{-1}_{-hz})^T I z
  legendre = I xi, hessian = diag(I) (a sparse output on purpose), energy = xi.I xi/2,
  momentum = g p, defect = max|g^T g - 1|, margin = 1 (or a callable(z, h)), guess = xi,
  update_p = p1, velocity_step = xi - (I xi - p)/I, record row = (g, mu, energy),
  step_partials = (J, and the state partials of hpgen.derive.linearize).
"""
from __future__ import annotations

import atexit
import functools
import shutil
import tempfile
from pathlib import Path

import casadi as ca

from hpgen.derive.linearize import step_partials
from hpgen.derive.step import DiscreteStep, Kernel
from hpgen.groups.catalog import group_from_spec

INERTIA = (2.0, 1.0, 2.0 / 3.0)
HASH = "0123456789abcdef" * 4


def hat(x):
    return ca.vertcat(ca.horzcat(0, -x[2], x[1]), ca.horzcat(x[2], 0, -x[0]),
                      ca.horzcat(-x[1], x[0], 0))


def dcayinv(x):
    return ca.SX.eye(3) - hat(x) / 2 + ca.mtimes(x, x.T) / 4


def cay(x):
    X = hat(x)
    return ca.SX.eye(3) + 4 / (4 + ca.dot(x, x)) * (X + ca.mtimes(X, X) / 2)


def toy_step(margin=None, name="free_rigid_body", inertia=INERTIA) -> DiscreteStep:
    z, g, p, h, xi, th = (ca.SX.sym(s, k) for s, k in (("z", 3), ("g", 9), ("p", 3), ("h", 1),
                                                        ("xi", 3), ("theta", 1)))
    inertia = ca.SX(list(inertia))
    G = ca.reshape(g, 3, 3)
    Iz = inertia * z
    F = ca.mtimes(dcayinv(h * z).T, Iz) - p
    Gx = ca.reshape(g, 3, 3)
    defs = {
        "residual": ((z, g, p, h), ("z", "g", "p", "h"), [F], ("F",)),
        "jacobian": ((z, g, p, h), ("z", "g", "p", "h"), [ca.vec(ca.jacobian(F, z))], ("J",)),
        "residual_jacobian": ((z, g, p, h), ("z", "g", "p", "h"),
                              [F, ca.vec(ca.jacobian(F, z))], ("F", "J")),
        "update": ((z, g, p, h), ("z", "g", "p", "h"),
                   [ca.vec(ca.mtimes(G, cay(h * z))), ca.mtimes(dcayinv(-h * z).T, Iz)],
                   ("g1", "p1")),
        "guess": ((xi, g, p, h), ("xi", "g", "p", "h"), [xi], ("z0",)),
        "legendre": ((g, xi), ("g", "xi"), [inertia * xi], ("mu",)),
        "hessian": ((g, xi), ("g", "xi"), [ca.vec(ca.diag(inertia))], ("H",)),
        "energy": ((g, xi), ("g", "xi"), [ca.dot(xi, inertia * xi) / 2], ("E",)),
        "momentum": ((g, p), ("g", "p"), [ca.mtimes(Gx, p)], ("m",)),
        "defect": ((g,), ("g",), [ca.mmax(ca.fabs(ca.mtimes(Gx.T, Gx) - ca.SX.eye(3)))],
                   ("e",)),
        "margin": ((z, h), ("z", "h"), [ca.SX(1.0) if margin is None else margin(z, h)],
                   ("m",)),
        "section": ((g, p), ("g", "p"), [p[2]], ("s",)),
        "chart_point": ((z, g, h, th), ("z", "g", "h", "theta"),
                        [ca.vec(ca.mtimes(G, cay(th * h * z)))], ("g_theta",)),
        "observe": ((g, p), ("g", "p"),
                    [p / inertia, ca.dot(p, p / inertia) / 2, ca.mtimes(Gx, p),
                     ca.mmax(ca.fabs(ca.mtimes(Gx.T, Gx) - ca.SX.eye(3)))],
                    ("xi", "E", "m", "e")),
        "update_p": ((z, g, p, h), ("z", "g", "p", "h"), [ca.mtimes(dcayinv(-h * z).T, Iz)],
                     ("p1",)),
        "velocity_step": ((g, p, xi), ("g", "p", "xi"), [xi - (inertia * xi - p) / inertia],
                          ("xi1",)),
        # record: (g, mu, energy)
        "record": ((g, p, xi), ("g", "p", "xi"), [ca.vertcat(g, p, ca.dot(xi, inertia * xi) / 2)],
                   ("row",)),
        "step_partials": ((z, g, p, h), ("z", "g", "p", "h"),
                          [ca.vec(e) for e in step_partials(
                              group_from_spec("SO3"), G, p, z, F, ca.mtimes(G, cay(h * z)),
                              ca.mtimes(dcayinv(-h * z).T, Iz))],
                          ("Fs", "Yz", "Ys")),
    }
    kernels = tuple(Kernel(k, ca.Function(k, list(a), outs, list(an), list(on)), an, on)
                    for k, (a, an, outs, on) in defs.items())
    return DiscreteStep(model_name=name, group_name="SO3", n=3, d=3, nz=3,
                        tableau_name="euler-poincare", tableau_order=2, tau="cay",
                        rkmk="exact", reduced=True, unknowns=(("xi", 0, 3),), kernels=kernels,
                        legendre_quadratic=True,
                        record_layout=(("g", 0, (3, 3)), ("mu", 9, (3,)), ("energy", 12, ())),
                        step_uses_g=False, record_uses_g=True, record_uses_xi=True)


def toy_info(module="toy_rb", backend="c", **kw) -> dict:
    info = {"module": module, "model_name": "free_rigid_body",
            "model_source": "name: free_rigid_body\ngroup: SO3\n",
            "options": {"tableau": "euler-poincare", "tau": "cay", "rkmk": "exact"},
            "hash": HASH, "backend": backend}
    info.update(kw)
    return info


def write_module(gm, parent: Path) -> Path:
    """Write a GeneratedModule under parent/<name>/ and return that directory."""
    out = Path(parent) / gm.name
    out.mkdir(parents=True, exist_ok=True)
    for rel, text in gm.files:
        (out / rel).write_text(text)
    return out


_TMP = Path(tempfile.mkdtemp(prefix="hpgen_test_"))
atexit.register(shutil.rmtree, _TMP, True)


@functools.lru_cache(maxsize=None)
def emitted(variant: str = "plain"):
    """(step, GeneratedModule) of a toy variant: 'plain', 'domain' (margin = 0.12 - h|z|)
    or 'singular' (inertia (2, 1, 0): singular Legendre transform)."""
    from hpgen.codegen import emit
    step = {"plain": lambda: toy_step(),
            "domain": lambda: toy_step(margin=lambda z, h: 0.12 - h * ca.sqrt(ca.dot(z, z))),
            "singular": lambda: toy_step(inertia=(2.0, 1.0, 0.0))}[variant]()
    return step, emit(step, toy_info(module=f"toy_{variant}"))


@functools.lru_cache(maxsize=None)
def module_dir(variant: str = "plain") -> Path:
    """The emitted toy module written to a per-session temp dir (shared by test modules)."""
    return write_module(emitted(variant)[1], _TMP / "pkgs")


@functools.lru_cache(maxsize=None)
def integrator(backend: str, variant: str = "plain"):
    from hpgen.runtime import load
    return load(module_dir(variant), backend=backend)
