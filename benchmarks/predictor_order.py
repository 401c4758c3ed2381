"""The Newton start of a step: the degree of the predictor's extrapolation,
and the previous step's collocation polynomial as the start of the next.

    python benchmarks/predictor_order.py [--quick]

1. Iterations and Jacobians per step by the predictor's degree. The run loop starts step k
   from G_k plus the polynomial through the last m offsets dz_j = z_j - G_j extrapolated one
   step (hpgen.runtime.loop.predict, hpgen/runtime/c/hpgen_runs.c hpgen_predict; m <= 6: quintic). Degree
   q < 5 is emulated on the Python backend by handing predict only the q + 1 newest offsets
   (the same coefficients as a build with PREDICTOR_HISTORY = q + 1); the iteration counts
   are those of the C backend (bitwise the same runs). Scenes: the heavy top (Gauss 2 and 3,
   Cayley, exact, T = 50) and the shipped closed examples at their scene's h and steps.
2. Start errors on the heavy top, Gauss s = 2, 3 / cay / exact: the distance max |z_start -
   z_k| of (a) the quadratic and (b) the quintic offset extrapolation, and (c) the collocation
   predictor: the previous step's collocation polynomial in the chart at g_{k-1},
   Y(theta) = h sum_l beta_l(theta) K^l (beta_l the integrated Lagrange basis at c, K = A^{-1}
   Theta the chart velocities), evaluated at the new stages theta = 1 + c_j and re-charted to
   g_k: Theta_new^j = cay^{-1}(cay(Y(1))^{-1} cay(Y(1 + c_j))) / h (SO3:
   cay^{-1}(R) = 2 vee(R - R^T) / (1 + tr R)); mu_{k+1} from (b). The solutions z_k are those
   of the shipped (quintic) run.
3. The stop's rate floor (hpgen.abi.THETA_FLOOR): the Lagrange top (examples/lagrange_top.yaml,
   h = 5e-4, 8e4 steps, Python backend with the printed ITERATE off so that
   hpgen.runtime.newton.solve reads the floor from its module) by predictor degree, with the
   shipped floor and with none: iterations per step and the drifts of its two momentum maps
   e3.(R p) and p[1], relative to |p0|.
"""
from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
HEAVY_TOP = ROOT / "examples" / "heavy_top.yaml"
EXAMPLES = ["free_rigid_body", "lagrange_top", "turntable", "double_body_chain"]
DEGREES = (2, 3, 4, 5)


def _start(pb):
    kw = {"g0": pb.g0}
    kw.update({"xi0": pb.xi0} if pb.xi0 is not None else {"mu0": pb.mu0})
    return kw


def counts_by_degree(integ, h, steps, kw) -> dict:
    """{q: (iterations per step, Jacobians per step)} of one run per predictor degree q."""
    from hpgen.runtime import loop
    shipped = loop.predict
    out = {}
    try:
        for q in DEGREES:
            loop.predict = lambda G, dz, q=q: shipped(G, dz[:q + 1])
            tr = integ.simulate(h=h, steps=steps, every=steps, **kw)
            out[q] = (tr.newton_iterations / steps, tr.jacobians / steps)
    finally:
        loop.predict = shipped
    return out


def table_degrees(quick: bool):
    import hpgen
    from hpgen.bench.problem import Problem
    print("| scene | scheme | h | steps | " + " | ".join(f"degree {q}: it, J per step"
                                                   for q in DEGREES) + " |")
    print("|---|---|---|---|" + "---|" * len(DEGREES))
    pb = Problem(HEAVY_TOP)
    T = 10.0 if quick else 50.0
    for tab, h in (("gauss2", 0.05), ("gauss2", 0.1), ("gauss3", 0.08), ("gauss3", 0.1)):
        integ = hpgen.compile(HEAVY_TOP, backend="python", tableau=tab, tau="cay",
                              rkmk="exact")
        steps = int(round(T / h))
        row = counts_by_degree(integ, h, steps, _start(pb))
        print(f"| heavy top | {tab}/cay/exact | {h} | {steps} | "
              + " | ".join(f"{i:.2f}, {j:.3f}" for i, j in row.values()) + " |", flush=True)
    for name in EXAMPLES:
        path = ROOT / "examples" / f"{name}.yaml"
        pb = Problem(path)
        sc = pb.scene
        integ = hpgen.compile(path, backend="python")
        steps = min(sc.steps, 500) if quick else sc.steps
        row = counts_by_degree(integ, sc.h, steps, _start(pb))
        o = integ.meta["options"]
        scheme = f"{o['tableau']}/{o['tau']}/{o['rkmk']}"
        print(f"| {name} | {scheme} | {sc.h} | {steps} | "
              + " | ".join(f"{i:.2f}, {j:.3f}" for i, j in row.values()) + " |", flush=True)


# ---- 2. the collocation predictor ---------------------------------------------------------

def _hat(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def _cay(x):
    X = _hat(x) / 2.0
    return np.linalg.solve(np.eye(3) - X, np.eye(3) + X)


def _cay_inv(R):
    return 2.0 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]) / (
        1.0 + np.trace(R))


def collocation_predictor(c, h):
    """z_{k-1} (Theta blocks first) -> the Theta blocks of the next step's start."""
    s = len(c)
    Linv = np.linalg.inv(np.vander(c, s, increasing=True))   # L_l(t) = sum_m Linv[m, l] t^m

    def beta(th):
        return np.array([sum(Linv[m, l] * th ** (m + 1) / (m + 1) for m in range(s))
                         for l in range(s)])
    A = np.array([beta(cj) for cj in c])

    def predict(z):
        K = np.linalg.solve(A, np.asarray(z[:3 * s]).reshape(s, 3))
        E = _cay(h * beta(1.0) @ K).T
        return np.concatenate([_cay_inv(E @ _cay(h * beta(1.0 + cj) @ K)) / h for cj in c])
    return predict


def table_collocation(quick: bool):
    import hpgen
    from hpgen.bench.problem import Problem
    from hpgen.runtime import loop
    from hpgen.runtime.newton import NewtonOptions
    from hpgen.tableaus.catalog import get_tableau
    print("\n| scheme | h | quadratic offsets | quintic offsets (shipped) | collocation "
          "(Theta) + quintic (mu) |")
    print("|---|---|---|---|---|")
    for tab, h in (("gauss2", 0.05), ("gauss3", 0.08), ("gauss3", 0.1)):
        integ = hpgen.compile(HEAVY_TOP, backend="python", tableau=tab, tau="cay",
                              rkmk="exact")
        b = integ.engine.backend
        kern = b._newton
        pb = Problem(HEAVY_TOP)
        gf = np.asarray(pb.g0, dtype=float).ravel(order="F")
        p0 = integ.kernel("legendre", gf, pb.xi0)[0]
        run = b.start(gf, p0, integ.kernel("guess", pb.xi0, gf, p0, [h])[0])
        steps = 60 if quick else 200
        Gs, zs = [], []
        for _ in range(steps):
            Gs.append(np.array(loop.predictor_base(kern, run.g, run.p, [h], False)))
            done, _, st = loop.advance(kern, run, h, 1, 1, NewtonOptions(simplified=True))
            assert done == 1, st
            zs.append(np.array(run.z))
        c = np.array([float(x) for x in get_tableau(tab).c])
        colloc = collocation_predictor(c, h)
        dz = [z - G for z, G in zip(zs, Gs)]
        e = {"quad": [], "quint": [], "colloc": []}
        for k in range(6, steps):
            quad = Gs[k] + (3.0 * (dz[k - 1] - dz[k - 2]) + dz[k - 3])
            quint = np.array(loop.predict(list(Gs[k]), [list(dz[k - 1 - i]) for i in range(6)]))
            col = np.concatenate([colloc(zs[k - 1]), quint[3 * len(c):]])
            for name, start in (("quad", quad), ("quint", quint), ("colloc", col)):
                e[name].append(np.abs(start - zs[k]).max())
        print(f"| {tab}/cay/exact | {h} | "
              + " | ".join(f"{statistics.median(e[n]):.1e} (max {max(e[n]):.1e})"
                           for n in ("quad", "quint", "colloc")) + " |", flush=True)


def table_floor(quick: bool):
    import hpgen
    from hpgen.abi import THETA_FLOOR
    from hpgen.runtime import loop, newton
    integ = hpgen.compile(ROOT / "examples" / "lagrange_top.yaml", backend="python")
    integ.engine.backend._newton.iterate = None
    steps = 20_000 if quick else 80_000
    e3, xi0 = np.array([0.0, 0.0, 1.0]), np.array([0.0, 150.0, -4.61538])
    shipped = loop.predict
    print(f"\n| degree | theta floor | it/step | e3.(R p) drift | p[1] drift |  (Lagrange top, "
          f"{steps} steps)\n|---|---|---|---|---|")
    try:
        for q in (2, 5):
            loop.predict = lambda G, dz, q=q: shipped(G, dz[:q + 1])
            for floor in (THETA_FLOOR, 0.0):
                newton.THETA_FLOOR = floor
                tr = integ.simulate(g0=np.eye(3), xi0=xi0, h=5e-4, steps=steps, every=10)
                n0 = np.linalg.norm(tr.mu[0])
                vert = np.einsum("i,kij,kj->k", e3, tr.g, tr.mu)
                print(f"| {q} | {floor} | {tr.newton_iterations / steps:.2f} | "
                      f"{np.abs(vert - vert[0]).max() / n0:.1e} | "
                      f"{np.abs(tr.mu[:, 1] - tr.mu[0, 1]).max() / n0:.1e} |", flush=True)
    finally:
        loop.predict, newton.THETA_FLOOR = shipped, THETA_FLOOR


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="shorter runs")
    a = ap.parse_args()
    table_degrees(a.quick)
    table_collocation(a.quick)
    table_floor(a.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
