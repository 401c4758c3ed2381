"""hpgen's generated C against a hand-written C peer: Lie Stormer-Verlet, Cayley, q = 0, heavy top.

    python benchmarks/sv_vs_hand.py [--steps 1000000] [--repeats 5] [--native] [--h 0.01 0.05]

The hand-written step (benchmarks/hand_sv/heavy_top_sv.c: eqs. sv1-sv5 in hpgen's state
(g_k, p_k), a 3-unknown Newton with a closed-form 3x3 Jacobian and solve) and hpgen's module
(examples/heavy_top.yaml, tableau stormer-verlet, tau cay, rkmk truncated, backend c) are
compiled with the same flags (hpgen.runtime.build.DEFAULT_CFLAGS, plus -march=native for
both with --native) and run in the same process, each as one C call for all steps, from the
scene's initial state (R0 = exp((0.3, 0.2, 0)^), Omega0 = (0.2, 1, 3)). Timed runs record
only the end state; the medians of interleaved repeats are printed as ns/step with the ratio
generated / hand. Agreement: the max |dR| and |dp| between the two trajectories over the
first 1000 steps, over the whole run (sampled every 1000 steps; the top is chaotic, so a
long run separates at the rate the dynamics amplify round-off), and the one-step map from
identical states (hand step from hpgen's own (g_k, p_k)).

hpgen is compiled into a fresh cache directory, so the generated C is the current templates'.
The generated code is timed with its Newton defaults and with plain Newton
(newton=NewtonOptions(simplified=False, predictor=False)), which is what the hand-written
code does.
"""
from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from hpgen.runtime import NewtonOptions

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "hand_sv"))

import hand_sv  # noqa: E402

MODEL = ROOT / "examples" / "heavy_top.yaml"
INERTIA = np.array([1.0, 5.0, 6.0])        # must match examples/heavy_top.yaml and the C file


def rotvec(w):
    """exp(w^) (Rodrigues)."""
    w = np.asarray(w, dtype=float)
    t = np.linalg.norm(w)
    W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    if t == 0.0:
        return np.eye(3)
    return np.eye(3) + np.sin(t) / t * W + (1 - np.cos(t)) / t**2 * W @ W


def initial_state():
    return rotvec([0.3, 0.2, 0.0]), INERTIA * np.array([0.2, 1.0, 3.0])


def agreement(hand, integ, R0, p0, h, steps, gen_kw):
    """(max |dR|, max |dp|) over the first 1000 steps, over the whole run sampled every 1000
    steps, and of the one-step map at 100 states of the run."""
    n1 = min(1000, steps)
    R_h, p_h, _ = hand.simulate(R0, p0, h, n1)
    tr = integ.simulate(g0=R0, mu0=p0, h=h, steps=n1, **gen_kw)
    short = (np.abs(tr.g - R_h).max(), np.abs(tr.mu - p_h).max())
    every = 1000 if steps >= 1000 else 1
    R_h, p_h, _ = hand.simulate(R0, p0, h, steps, every)
    tr_long = integ.simulate(g0=R0, mu0=p0, h=h, steps=steps, every=every, **gen_kw)
    long = (np.abs(tr_long.g - R_h).max(), np.abs(tr_long.mu - p_h).max())
    dR1 = dp1 = 0.0
    for k in range(0, n1, max(1, n1 // 100)):
        R1, p1, _, _ = hand.step(tr.g[k], tr.mu[k], h)
        dR1 = max(dR1, np.abs(R1 - tr.g[k + 1]).max())
        dp1 = max(dp1, np.abs(p1 - tr.mu[k + 1]).max())
    return short, long, (dR1, dp1)


def timed(fn, steps):
    t0 = time.perf_counter()
    fn()
    return (time.perf_counter() - t0) / steps * 1e9


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=1_000_000)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--h", type=float, nargs="+", default=[0.01, 0.05])
    ap.add_argument("--native", action="store_true", help="add -march=native for both")
    a = ap.parse_args()

    import hpgen
    from hpgen.runtime.build import DEFAULT_CFLAGS
    extra = ["-march=native"] if a.native else []
    flags = list(DEFAULT_CFLAGS) + extra
    work = tempfile.mkdtemp(prefix="hpgen-sv-vs-hand-")
    hand = hand_sv.HandSV(hand_sv.build(work, flags))
    integ = hpgen.compile(MODEL, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                          backend="c", cflags=extra or None, cache_dir=work + "/cache")
    variants = {"generated": {},
                "generated, plain Newton": {"newton": NewtonOptions(simplified=False,
                                                                    predictor=False)}}
    R0, p0 = initial_state()
    print(f"flags: {' '.join(flags)}; {a.steps} steps, medians of {a.repeats} interleaved "
          f"repeats; hpgen unknowns nz = {integ.nz}, hand 3")
    print("| h | code | ns/step | generated / hand | Newton it/step | jacobians/step |")
    print("|---|---|---|---|---|---|")
    for h in a.h:
        runs = {"hand": lambda: hand.simulate(R0, p0, h, a.steps, a.steps)}
        for name, kw in variants.items():
            runs[name] = (lambda kw=kw: integ.simulate(g0=R0, mu0=p0, h=h, steps=a.steps,
                                                       every=a.steps, **kw))
        for fn in runs.values():              # warm up (library load, page faults)
            fn()
        times = {k: [] for k in runs}
        for _ in range(a.repeats):
            for k, fn in runs.items():
                times[k].append(timed(fn, a.steps))
        med = {k: statistics.median(v) for k, v in times.items()}
        its = {"hand": hand.simulate(R0, p0, h, a.steps, a.steps)[2] / a.steps}
        jac = {"hand": its["hand"]}
        for name, kw in variants.items():
            tr = integ.simulate(g0=R0, mu0=p0, h=h, steps=a.steps, every=a.steps, **kw)
            its[name] = tr.newton_iterations / a.steps
            jac[name] = getattr(tr, "jacobians", tr.newton_iterations) / a.steps
        for k in runs:
            print(f"| {h} | {k} | {med[k]:.0f} | {med[k] / med['hand']:.2f} | {its[k]:.2f} | "
                  f"{jac[k]:.2f} |")
        for name, kw in variants.items():
            short, long, one = agreement(hand, integ, R0, p0, h, a.steps, kw)
            print(f"|   | {name} vs hand: max |dR|, |dp| | first 1000 steps {short[0]:.1e}, "
                  f"{short[1]:.1e}; whole run {long[0]:.1e}, {long[1]:.1e}; one step "
                  f"{one[0]:.1e}, {one[1]:.1e} | | | |")


if __name__ == "__main__":
    main()
