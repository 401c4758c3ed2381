"""Structure-preserving peers in C for rigid-body scenes: what a person who
integrates rigid bodies for a living would try instead of hpgen.

Families (names in hpgen.bench.peers.PEERS, the CSV ``family`` column):
- ``splitting-2``, ``splitting-4``, ``splitting-6``: the explicit symplectic splitting of
  Dullweber, Leimkuhler & McLachlan (1997), free body as exact rotations about the principal
  axes, the potential as kicks (order 2), composed by Yoshida's triple jump (order 4) and by
  Kahan & Li's 9-stage s9odr6a (order 6).
- ``RATTLE``: RATTLE on the embedded rotation matrix = Moser-Veselov with potential kicks
  (order 2).
All in rigid.c (next to this file, plain C, compiled at bench time by hpgen.runtime.build with
its flags, cached by the source's sha256), on the bench's state y = (R row-major, Pi).

They apply to an SO3 model whose Lagrangian is l = 1/2 xi.diag(I) xi - m.Gamma + const,
Gamma = R^T e3 = (R[2,0], R[2,1], R[2,2]) (heavy top: m = Mg chi; free body: m = 0):
``rigid_parameters`` reads I and m off the model's own Lagrangian (CasADi), or returns None.
"""
from __future__ import annotations

import ctypes
import time
from pathlib import Path

import numpy as np

SOURCE = "rigid.c"
#: composition coefficients of the basic (order 2, symmetric) splitting step
_Y4 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))
_KL6 = (0.39216144400731413927925056, 0.33259913678935943859974864,
        -0.70624617255763935980996482, 0.08221359629355080023149045,
        0.79854399093482996339895035)
COMPOSITIONS = {
    "splitting-2": (1.0,),
    "splitting-4": (_Y4, 1.0 - 2.0 * _Y4, _Y4),
    "splitting-6": _KL6 + _KL6[-2::-1],
}
ORDERS = {"splitting-2": 2, "splitting-4": 4, "splitting-6": 6, "RATTLE": 2}
FAMILIES = tuple(ORDERS)
METHODS = {"splitting-2": "DLM splitting, order 2 (C)",
           "splitting-4": "DLM splitting, Yoshida order 4 (C)",
           "splitting-6": "DLM splitting, Kahan-Li order 6 (C)",
           "RATTLE": "RATTLE / Moser-Veselov (C)"}


def rigid_parameters(eq):
    """(inertia (3,), m (3,)) when ``eq`` (hpgen.analysis.rkmk.ContinuousEquations) is an SO3
    body with l = 1/2 xi.diag(inertia) xi - m.(R^T e3) + const, else None. Checked
    symbolically on the model's Lagrangian: the Hessian in xi is constant, diagonal and
    positive, l(R, xi) - l(R, 0) is the kinetic energy alone, and l(R, 0) is affine in R with
    a gradient on the third row only."""
    import casadi as ca
    if eq.model.group.name != "SO3" or eq.model.open_system:     # forces, inputs, t
        return None
    g, xi = ca.SX.sym("g", 3, 3), ca.SX.sym("xi", 3)
    L = eq.lag(g, xi)
    H = ca.hessian(L, xi)[0]
    if ca.depends_on(H, ca.vertcat(ca.vec(g), xi)):
        return None
    H = np.array(ca.evalf(H))
    inertia = np.diag(H).copy()
    if np.abs(H - np.diag(inertia)).max() != 0.0 or not (inertia > 0).all():
        return None
    L0 = ca.substitute(L, xi, ca.SX.zeros(3))
    kin = L - L0 - 0.5 * ca.dot(xi, ca.mtimes(ca.SX(H), xi))
    grad = ca.gradient(L0, ca.vec(g))
    if ca.depends_on(grad, ca.vec(g)):
        return None
    G = np.array(ca.evalf(grad)).reshape(3, 3, order="F")       # dL0/dg[i, j]
    if np.abs(G[:2]).max() != 0.0:
        return None
    # the kinetic remainder must vanish: check it at a few points (it is polynomial)
    fk = ca.Function("kin", [g, xi], [kin])
    rng = np.random.default_rng(0)
    for _ in range(3):
        if abs(float(fk(rng.normal(size=(3, 3)), rng.normal(size=3)))) > 1e-12:
            return None
    return inertia, 0.0 - G[2]          # (0.0 - x: no negative zeros)


class RigidPeers:
    """Loaded rigid.c for one body. ``run(family, y0, h, steps, every)`` ->
    (records (K, 12) or None, last state, steps done, Newton iterations (RATTLE) or 0).
    ``setup_s``: build + load seconds."""

    def __init__(self, inertia, m, cache_dir=None, cc=None):
        from .crk4 import build
        t0 = time.perf_counter()
        self.inertia = np.ascontiguousarray(inertia, dtype=np.float64)
        self.m = np.ascontiguousarray(m, dtype=np.float64)
        self.source = (Path(__file__).parent / SOURCE).read_text()
        self.path = build(self.source, cache_dir, cc, prefix="bench-rigid")
        lib = self.lib = ctypes.CDLL(str(self.path))
        P, D, L = ctypes.c_void_p, ctypes.c_double, ctypes.c_long
        lib.hpgen_rigid_split.argtypes = [P, P, P, P, L, D, L, L, P]
        lib.hpgen_rigid_split.restype = L
        lib.hpgen_rigid_rattle.argtypes = [P, P, P, D, L, L, P, P]
        lib.hpgen_rigid_rattle.restype = L
        self._coef = {k: np.array(v, dtype=np.float64) for k, v in COMPOSITIONS.items()}
        # the constant arguments' addresses, taken once (the arrays live as long as self):
        # a run's Python cost is then one state copy and the call
        self._body = (self.inertia.ctypes.data, self.m.ctypes.data)
        self._coef_arg = {k: (c.ctypes.data, len(c)) for k, c in self._coef.items()}
        self.setup_s = time.perf_counter() - t0

    def run(self, family, y0, h, steps, every=None):
        y = np.array(y0, dtype=np.float64)
        rec = np.empty((steps // every + 1, 12)) if every else None
        rp = None if rec is None else rec.ctypes.data
        its = ctypes.c_long(0)
        if family == "RATTLE":
            done = self.lib.hpgen_rigid_rattle(y.ctypes.data, *self._body, float(h),
                                               int(steps), int(every or 1), rp,
                                               ctypes.byref(its))
        else:
            done = self.lib.hpgen_rigid_split(y.ctypes.data, *self._body,
                                              *self._coef_arg[family], float(h), int(steps),
                                              int(every or 1), rp)
        if rec is not None:
            rec = rec[:done // (every or 1) + 1]
        return rec, y, int(done), int(its.value)


def rigid_points(pb, y_ref, rigid, family, hs, timing, samples):
    """Bench points of one family over the step grid ``hs`` (as RK4-C: one C call per run,
    the ctypes call inside the timed call)."""
    from .measure import Point, fixed_note, measure, steps_for
    out = []
    for h in hs:
        steps, hu = steps_for(pb.T, h)
        every = max(1, steps // samples)
        t_rec = np.arange(steps // every + 1) * every * hu
        p = Point(METHODS[family], family, "peer", "h", hu, setup_s=rigid.setup_s)

        def sampled(hu=hu, steps=steps, every=every, t_rec=t_rec):
            rec = rigid.run(family, pb.y0, hu, steps, every)[0]
            return t_rec[:len(rec)], rec

        def timed(hu=hu, steps=steps):
            _, y, done, its = rigid.run(family, pb.y0, hu, steps)
            info = {"steps": steps}
            if family == "RATTLE":
                info["notes"] = [f"Newton it/step {its / max(done, 1):.2f}"]
            return (y if done == steps else np.full(pb.ny, np.nan)), info
        p.notes += fixed_note(h, hu)
        out.append(measure(pb, y_ref, p, timing, timed, sampled))
    return out
