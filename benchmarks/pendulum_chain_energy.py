"""Energy band of the N-link pendulum chain in hpgen's two model files of it (constrained
Stormer-Verlet, cay, truncated RKMK, C backend) against MuJoCo RK4 on the same chain
(hpgen.bench.multibody), in one process.

    PYTHONPATH=. python benchmarks/pendulum_chain_energy.py [--n 10] [--steps 100000]
        [--h 1e-3 [2e-3 ...]] [--frames pin centre] [--start random tilt60]
        [--charts cay:truncated exp:exact ...] [--mujoco yes|no] [--cache-dir DIR]

Models (``--frames``, hpgen.bench.multibody.hpgen_chain): ``pin`` examples/pendulum_chain.yaml
(frames at the pin when the chain hangs straight), ``centre`` examples/capsule_chain.yaml
(frames at the link centres). Starts (``--start``): ``random`` the benchmark's (hanging
straight down, joint rates qvel ~ N(0, 1), seed 0; ``randomS`` seed S), ``tiltD`` the straight chain released at
rest tilted by D degrees about the world x axis (chain.named_joint_state). The same joint
state is mapped to each model (hpgen_chain.to_hpgen). ``--charts TAU:RKMK ...`` compiles each
model once per chart map and RKMK variant (``hpgen list``; default: the model file's own) and
runs them one after another in the same process, every h of ``--h`` for each (``--steps`` steps
of each h, or ``--t`` simulated seconds).

Per (N, start) and model: hpgen runs ``steps`` steps of h (T = steps h), streamed; figures:
- band: max_k |E_k - E_0| over every node divided (1) by E_0 - V_rest (V_rest: the chain at
  rest; the energy above the minimum, independent of where the potential's zero is) and (2) by
  |E_0| with the potential zero at the pin (MuJoCo's own energy);
- drift: max |E_k - E_0| / (E_0 - V_rest) over the first and over the last tenth of the run,
  and the least-squares line through E_k - E_0 over the run: its rise over T, / (E_0 - V_rest);
- joints: the largest position and velocity gaps over every node (chain.constraint_residual);
- Newton iterations per step and wall and CPU time per step (the stream's calls alone,
  recording every node: hpgen_chain.run with every = 1); band x (CPU per step / h)^2 compares
  runs at equal cost (an order-2 band goes as h^2, the cost per simulated second as 1/h);
- cond H: the largest condition number of a link's 6 x 6 kinetic metric d2l/dxi2 (body
  inertia in the model's frame).
MuJoCo RK4 (its C rollout) runs the same T at dt = h and at equal cost per simulated second
(dt = h c_mujoco / c_hpgen, c the time per step: MuJoCo's from a 2000-step probe, hpgen's the
cheaper model's, at the first h), its energy every 10 steps (``--mujoco no``: not run). Speed
figures are ratios within one run.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hpgen.bench.multibody import chain, hpgen_chain  # noqa: E402


def kinetic_condition(spec, frames):
    """The largest condition number over the links of the 6 x 6 body inertia in the model's
    frames: diag(J, m) at the centre, moved along the link by (i + 1/2) b for the pin frames."""
    J, m = spec.inertia, spec.mass
    offsets = (np.arange(spec.n) + 0.5) * spec.length if frames == "pin" else np.zeros(spec.n)
    worst = 0.0
    for d in offsets:
        c = chain.hat(np.array([0.0, 0.0, -d]))
        H = np.block([[np.diag(J) + m * c.T @ c, m * c.T], [m * c, m * np.eye(3)]])
        worst = max(worst, float(np.linalg.cond(H)))
    return worst


def energy_figures(E, spec):
    """(band / (E0 - V_rest), band / |E0|, first tenth, last tenth, the fitted line's rise
    over the run / (E0 - V_rest)) of node energies E (equally spaced in time)."""
    E = np.asarray(E)
    dev = np.abs(E - E[0])
    above = E[0] - chain.rest_potential(spec)
    tenth = max(1, len(E) // 10)
    slope = np.polyfit(np.linspace(0.0, 1.0, len(E)), E - E[0], 1)[0]
    return (dev.max() / above, dev.max() / abs(E[0]), dev[:tenth].max() / above,
            dev[-tenth:].max() / above, slope / above)


def row(n, start, runner, dt, steps, c, figs, extra):
    b_rest, b_abs, first, last, rise = figs
    return (f"| {n} | {start} | {runner} | {dt:.3g} | {steps} | {1e6 * c:.1f} | "
            f"{b_rest:.2e} | {b_abs:.2e} | {first:.1e} / {last:.1e}; {rise:+.1e} | {extra} |")


def chart_option(text):
    """``TAU:RKMK`` (``cay:truncated``) as (tau, rkmk); ``model`` as (None, None)."""
    if text == "model":
        return None, None
    tau, sep, rkmk = text.partition(":")
    if not sep or not tau or not rkmk:
        raise argparse.ArgumentTypeError(f"expected TAU:RKMK or model, got {text!r}")
    return tau, rkmk


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[10])
    ap.add_argument("--steps", type=int, default=100_000)
    ap.add_argument("--t", type=float, default=None,
                    help="simulated seconds per run instead of --steps (steps = T / h)")
    ap.add_argument("--h", type=float, nargs="+", default=[1e-3])
    ap.add_argument("--frames", nargs="+", default=["pin", "centre"], choices=["pin", "centre"])
    ap.add_argument("--start", nargs="+", default=["random", "tilt60"])
    ap.add_argument("--charts", type=chart_option, nargs="+", default=[(None, None)],
                    help="TAU:RKMK per compiled module (default: the model file's)")
    ap.add_argument("--mujoco", choices=["yes", "no"], default="yes")
    ap.add_argument("--cache-dir", default=None, help="hpgen's build cache (default its own)")
    ap.add_argument("--newton", choices=["default", "full", "simplified"], default="default",
                    help="hpgen's Newton (default: the module's)")
    args = ap.parse_args(argv)
    import hpgen
    from hpgen.bench.multibody import mujoco_peer
    from hpgen.runtime.newton import NewtonOptions
    newton = None if args.newton == "default" else NewtonOptions(
        simplified=args.newton == "simplified")
    print("| N | start | runner | dt | steps | us/step | band / (E0 - V_rest) | band / abs(E0) "
          "| first / last tenth; line's rise | joints (pos / vel); it/step; cond H; "
          "CPU us/step; band x (CPU/h)^2 |")
    print("|---|---|---|---|---|---|---|---|---|---|", flush=True)
    for n in args.n:
        spec = chain.ChainSpec(n)
        integs = {}
        for frames in args.frames:
            for tau, rkmk in args.charts:
                t0 = time.perf_counter()
                try:
                    integs[frames, tau, rkmk] = hpgen.compile(
                        hpgen_chain.MODELS[frames], parameters={"N": n}, tau=tau, rkmk=rkmk,
                        cache_dir=args.cache_dir)
                except hpgen.HpgenError as exc:
                    print(f"compile N = {n} {frames} {tau}:{rkmk}: {type(exc).__name__}: "
                          f"{exc}", flush=True)
                    continue
                chart = f" {tau}:{rkmk}" if tau else ""
                print(f"compile N = {n} {frames}{chart}: {time.perf_counter() - t0:.1f} s",
                      flush=True)
        for start in args.start:
            qpos, qvel = chain.named_joint_state(spec, start)
            s0 = chain.from_joint(spec, qpos, qvel)
            costs = []
            for h in args.h:
                steps = args.steps if args.t is None else int(round(args.t / h))
                for (frames, tau, rkmk), integ in integs.items():
                    label = f"hpgen SV {frames}" + (f" {tau}:{rkmk}" if tau else "")
                    g0, xi0 = hpgen_chain.to_hpgen(spec, s0, frames)
                    try:
                        r = hpgen_chain.run(integ, spec, g0, xi0, h, steps, every=1,
                                            newton=newton, frames=frames)
                    except hpgen.HpgenError as exc:
                        print(f"| {n} | {start} | {label} | {h:.3g} | {steps} | "
                              f"{type(exc).__name__}: {exc} |", flush=True)
                        continue
                    c = r.seconds / steps
                    if h == args.h[0]:
                        costs.append(c)
                    figs = energy_figures(r.energy, spec)
                    c_cpu = r.cpu_seconds / steps
                    extra = (f"{r.gaps[0]:.1e} / {r.gaps[1]:.1e}; "
                             f"{r.iterations / steps:.2f}; "
                             f"{kinetic_condition(spec, frames):.1e}; {1e6 * c_cpu:.1f}; "
                             f"{figs[0] * (c_cpu / h) ** 2:.2e}")
                    print(row(n, start, label, h, steps, c, figs, extra), flush=True)
            if args.mujoco == "no" or not costs:
                continue
            h = args.h[0]
            T = args.steps * h if args.t is None else args.t
            probe = mujoco_peer.run(spec, qpos, qvel, h, 2000, "RK4")
            c_mj = probe.seconds / 2000
            for label, dt in (("equal dt", h), ("equal cost", h * c_mj / min(costs))):
                steps = int(round(T / dt))
                dt = T / steps
                run = mujoco_peer.run(spec, qpos, qvel, dt, steps, "RK4", sample=10)
                print(row(n, start, f"MuJoCo RK4 ({label})", dt, steps, run.seconds / steps,
                          energy_figures(run.energy, spec),
                          "-" if run.stable else "unstable"), flush=True)


if __name__ == "__main__":
    main()
