"""Why a heavy-top Gauss step takes the iterations it takes (issue 14 item 3, the 30x DOP853
target): a run's steps replayed offline under other Newton starts and refresh policies.

    python benchmarks/archive/newton_replay.py [--scheme gauss3/cay/exact] [--h 0.08] [--T 10]

A Python-backend run of the heavy top (examples/heavy_top.yaml, its scene's start) records
each step's (g_k, p_k, h, Newton start, solution). The replay is simplified Newton as
hpgen.runtime.newton.solve does it (J^{-1} kept across steps, refreshed when the rate
|dz_k| / |dz_{k-1}| exceeds THETA_MAX, full Newton when a fresh J contracts poorly; the same
stopping tests), in numpy with the step's CasADi residual and Jacobian: its iteration counts
are within a few percent of the runtime's (printed beside), not bitwise. Printed:

1. Iterations and Jacobians per step when every start is moved toward the solution by a
   factor (1 = the shipped predictor): what any better predictor could at most save.
2. The same for other refresh policies; "cost" counts a refresh (J and its inverse) as
   REFRESH_COST iterations (perf, Gauss 3 on the C backend: a Jacobian evaluation is about
   19 residual calls, its LU and inverse 17, an iterate about 1.7 residual calls).
3. The contraction rate max |eig(I - M J(z_k))| of the kept inverse M at age a steps
   (stale), and of M linearly or quadratically extrapolated in k from earlier inverses.
"""
from __future__ import annotations

import argparse
import math
import statistics
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
HEAVY_TOP = ROOT / "examples" / "heavy_top.yaml"
REFRESH_COST = 20


def record_run(scheme, h, T):
    """(steps [(g, p, hv, start, solution)], the DiscreteStep, it/step, J/step)."""
    import hpgen
    from hpgen.bench.problem import Problem
    from hpgen.runtime import loop
    tab, tau, rkmk = scheme.split("/")
    pb = Problem(HEAVY_TOP)
    cm = hpgen.build(HEAVY_TOP, tableau=tab, tau=tau, rkmk=rkmk, backend="python")
    integ = cm.load()
    rec, shipped = [], loop.step_lists

    def spy(kern, g, p, hv, z, *a):
        out = shipped(kern, g, p, hv, z, *a)
        rec.append((list(g), list(p), list(hv), list(z), out[3]))
        return out
    steps = int(round(T / h))
    loop.step_lists = spy
    try:
        tr = integ.simulate(g0=pb.g0, xi0=pb.xi0, h=h, steps=steps, every=steps)
    finally:
        loop.step_lists = shipped
    return rec, cm.derivation.step, tr.newton_iterations / steps, tr.jacobians / steps


class Replay:
    """Simplified Newton on one recorded run, numpy and the step's CasADi functions."""

    def __init__(self, rec, step):
        from hpgen.abi import DEFAULT_TOL, ROUNDOFF_FLOOR, SIMPLIFIED_TOL, THETA_FLOOR
        self.rec, self.nz, self.theta_floor = rec, step.nz, THETA_FLOOR
        self.R = step.kernel("residual").function
        self.J = step.kernel("jacobian").function
        self.tol, self.floor, self.stol = DEFAULT_TOL, ROUNDOFF_FLOOR, SIMPLIFIED_TOL * DEFAULT_TOL

    def F(self, z, g, p, hv):
        return np.array(self.R(z, g, p, hv)).ravel()

    def Jm(self, z, g, p, hv):
        return np.array(self.J(z, g, p, hv)).reshape(self.nz, self.nz, order="F")

    def solve(self, z, g, p, hv, mem, refresh):
        """(iterations, Jacobians); refresh(it, dn, dprev, zn) -> True: J is stale."""
        dprev, it, jacs, full, fresh = math.inf, 0, 0, False, False
        while it < 50:
            it += 1
            if full or mem.get("M") is None:
                mem["M"] = np.linalg.inv(self.Jm(z, g, p, hv))
                jacs, fresh = jacs + 1, True
            dz = mem["M"] @ self.F(z, g, p, hv)
            z = z - dz
            dn, zn = np.abs(dz).max(), np.abs(z).max()
            if it > 1 and dn >= dprev and dn <= self.floor * (1 + zn):
                break
            if full:
                if dn <= self.tol * (1 + zn):
                    break
            else:
                th = dn / dprev
                te = max(th, self.theta_floor)
                if dn <= self.stol * (1 + zn) or (
                        it > 1 and te < 1 and te / (1 - te) * dn <= self.stol * (1 + zn)):
                    break
                if it > 1 and refresh(it, dn, dprev, zn):
                    if fresh:
                        full = True
                    else:
                        mem["M"] = None
            dprev = dn
        return it, jacs

    def run(self, refresh, factor=1.0):
        """(it/step, J/step) over the steps after the first, starts moved by factor."""
        mem, its, jacs = {}, 0, 0
        for g, p, hv, z0, zsol in self.rec[1:]:
            zsol = np.array(zsol)
            it, j = self.solve(zsol + factor * (np.array(z0) - zsol), g, p, hv, mem, refresh)
            its, jacs = its + it, jacs + j
        n = len(self.rec) - 1
        return its / n, jacs / n


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scheme", default="gauss3/cay/exact")
    ap.add_argument("--h", type=float, default=0.08)
    ap.add_argument("--T", type=float, default=10.0)
    a = ap.parse_args()
    from hpgen.abi import THETA_MAX
    rec, step, it_rt, j_rt = record_run(a.scheme, a.h, a.T)
    rp = Replay(rec, step)
    shipped = lambda it, dn, dp, zn: dn > THETA_MAX * dp            # noqa: E731
    print(f"# heavy top {a.scheme}, h = {a.h}, {len(rec)} steps; runtime: {it_rt:.2f} it/step, "
          f"{j_rt:.3f} J/step")
    print("\n| start error x | it/step | J/step |\n|---|---|---|")
    for f in (1.0, 0.1, 0.01, 1e-3, 1e-4, 1e-6):
        i, j = rp.run(shipped, f)
        print(f"| {f:g} | {i:.2f} | {j:.3f} |", flush=True)

    def remaining(it, dn, dp, zn):
        """iterations left at the current rate to the simplified stop"""
        return math.inf if dn >= dp else math.log(rp.stol * (1 + zn) / dn) / math.log(dn / dp)
    policies = [(f"rate > {THETA_MAX} (shipped)", shipped),
                ("rate > 0.5", lambda it, dn, dp, zn: dn > 0.5 * dp),
                ("rate > 0.2 from the 3rd iterate", lambda it, dn, dp, zn: it > 2 and dn > 0.2 * dp),
                ("iterations left at the rate > 8", lambda it, dn, dp, zn: remaining(it, dn, dp, zn) > 8),
                ("iterations left at the rate > 12", lambda it, dn, dp, zn: remaining(it, dn, dp, zn) > 12)]
    print(f"\n| refresh when | it/step | J/step | cost (J = {REFRESH_COST} it) |\n|---|---|---|---|")
    for name, pol in policies:
        i, j = rp.run(pol)
        print(f"| {name} | {i:.2f} | {j:.3f} | {i + REFRESH_COST * j:.2f} |", flush=True)

    Js = [rp.Jm(np.array(zs), g, p, hv) for g, p, hv, _, zs in rec]
    Ms = [np.linalg.inv(J) for J in Js]
    eye = np.eye(rp.nz)

    def rate(M, J):
        return float(np.abs(np.linalg.eigvals(eye - M @ J)).max())
    print("\n| age (steps) | stale M | M extrapolated linearly | quadratically |\n|---|---|---|---|")
    for age in (1, 2, 4, 8, 12):
        r = {"stale": [], "lin": [], "quad": []}
        for k in range(3 * age, len(rec)):
            m1, m2, m3 = Ms[k - age], Ms[k - 2 * age], Ms[k - 3 * age]
            r["stale"].append(rate(m1, Js[k]))
            r["lin"].append(rate(2 * m1 - m2, Js[k]))
            r["quad"].append(rate(3 * m1 - 3 * m2 + m3, Js[k]))
        print(f"| {age} | " + " | ".join(f"{statistics.median(v):.1e}" for v in r.values())
              + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
