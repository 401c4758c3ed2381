"""The horizon where structure pays: per scene, the time T* beyond which
the best hpgen scheme has a lower energy error AND a lower invariant error than RK4 in C and
than DOP853, all run at the same wall time per unit of simulated time (fixed cost).

    python benchmarks/horizon.py                 # default: up to 10^7 hpgen steps, ~10 min
    python benchmarks/horizon.py --quick         # small: a smoke test of the output (< 1 min)
    python benchmarks/horizon.py --scenes heavy_top,turntable --json out.json

Scenes (examples/*.yaml, the scene's initial state): heavy_top, free_rigid_body,
underwater_vehicle, turntable. Methods, all on one process, in C except DOP853:
- hpgen candidates (CANDIDATES: Stormer-Verlet/Cayley/truncated and Gauss 2/Cayley/exact),
  each at the scene's h, run by Integrator.stream_record (bounded memory);
- RK4 in C (hpgen.bench.crk4) at the step h_RK4 = h * c_RK4 / c_hpgen (c: measured seconds
  per step, minimum of 5 interleaved repeats of a calibration run of 2*10^5 steps, the
  same statistic for every method; the long runs' own wall times are reported beside, as
  the machine is shared and loads vary),
  so that its wall time per unit T equals the hpgen scheme's;
- SciPy DOP853 (the class, stepped in Python, f = the C vector field, atol = 1e-3 rtol) at
  the tightest rtol of DOP_RTOLS whose calibrated cost per unit T is at most the hpgen
  scheme's; when even the loosest (1e-3) costs more (the usual case: Python steps), at that
  loosest rtol, as far as --dop-budget seconds allow: then it is given MORE wall time per
  unit T than hpgen (the figure gives the ratio), so a T* against it is conservative;
- turntable only, two symmetric non-variational integrators at equal cost (as RK4; C,
  rk4.c.j2): the implicit midpoint rule on the embedded equations (it keeps every quadratic
  invariant of y' = f(y): here the energy 1/2 p.I^-1 p - w0 p.Gamma + Mg chi.Gamma and
  e3.(R p) are quadratic in y = (R, p), so it keeps both to round-off), and the Lie (RKMK,
  exponential chart) midpoint rule, which keeps R on SO(3) but neither invariant.
Wall times (the figure's "cost x": a method's wall time per unit T over the hpgen scheme's)
count the integrator calls only, not the error evaluation between chunks.
Every method runs from T = 0 to T_max = min(10^7, --budget / c_hpgen) hpgen steps (the
others: the same T_max, at their own h), in chunks; records about PER_SEGMENT times per
decade of T (see ``segments``).

Errors, as functions of T (the running maximum over the records up to T, so each curve is
non-decreasing): energy error max |E - E(0)|; invariant error max |J - J(0)|max, J the
conserved components of the spatial momentum Ad*_{g^-1} mu (INVARIANTS: all of them for
the free body and the underwater vehicle, e3.(R mu) for the heavy top and the turntable).
Errors below the round-off floor FLOOR_ULPS * eps * (1 + |quantity|) count as equal.

A peer that diverges (non-finite state: RK4 at a step beyond its stability at equal cost)
loses at every later checkpoint. T* against a peer: the smallest checkpoint T
(CHECKPOINTS_PER_DECADE per decade from T_MIN) from which on, at every later checkpoint
the peer reached, the hpgen scheme's energy error
and invariant error are both lower (or both at the floor). "<= T_MIN" when hpgen wins from
the start, "> T_end" when it never does; then, when the peer's energy error grows as a
power of T over its last decade, "(extrapolated T)" gives where that power law would reach
hpgen's bounded energy error (an estimate beyond the run, not a measurement). T* of a
scheme = the largest over RK4-C and DOP853; the best scheme is the one with the smallest
T*. The midpoint rules' T* are reported beside.

Output: one figure per scene (docs/figures/horizon_<scene>.png by default, --figures DIR):
energy and invariant error against T at fixed cost, T* marked; a Markdown table on stdout;
--json PATH: the numbers (per scene: methods with h, rtol, steps, wall s, cost per unit T,
checkpoints and errors; T* per scheme and peer).
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

SCENES = ("heavy_top", "free_rigid_body", "underwater_vehicle", "turntable")
CANDIDATES = (("stormer-verlet", "cay", "truncated"), ("gauss2", "cay", "exact"))
#: conserved components of the spatial momentum, per scene (None: all)
INVARIANTS = {"heavy_top": [2], "turntable": [2], "free_rigid_body": None,
              "underwater_vehicle": None}
#: the symmetric non-variational peers of the turntable (hpgen.bench.crk4, rk4.c.j2)
SYMMETRIC = (("midpoint", "implicit midpoint (C)"), ("lie-midpoint", "Lie midpoint (RKMK, C)"))
DOP_RTOLS = (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10)
MAX_STEPS = 10 ** 7
T_MIN = 1.0
CHECKPOINTS_PER_DECADE = 8
FLOOR_ULPS = 64
PER_SEGMENT = 2000        # records per decade of T (about), for the running maxima
REPEATS = 3


# ---- running maxima at checkpoints (bounded memory) -----------------------------------------
class Envelope:
    """Running maxima of (energy error, invariant error) sampled at the checkpoints."""

    def __init__(self, grid):
        self.grid = np.asarray(grid)
        self.E = np.full(len(grid), np.nan)
        self.J = np.full(len(grid), np.nan)
        self.mE = self.mJ = 0.0
        self.t_end = 0.0
        self.failed = False        # the run stopped (non-finite state, no convergence)

    def add(self, t, eE, eJ):
        """Records at times t (ascending, after the previous ones) with their errors."""
        if len(t) == 0:
            return
        if not (np.isfinite(eE).all() and np.isfinite(eJ).all()):
            bad = ~(np.isfinite(eE) & np.isfinite(eJ))
            k = int(np.argmax(bad))
            t, eE, eJ = t[:k], eE[:k], eJ[:k]
            self.failed = True
            if len(t) == 0:
                return
        cE = np.maximum.accumulate(np.r_[self.mE, eE])[1:]
        cJ = np.maximum.accumulate(np.r_[self.mJ, eJ])[1:]
        sel = (self.grid >= t[0]) & (self.grid <= t[-1] * (1 + 1e-12))
        # a checkpoint between two chunks takes the maximum up to the last record before it
        sel |= (self.grid > self.t_end) & (self.grid < t[0])
        idx = np.searchsorted(t, self.grid[sel] * (1 + 1e-12), side="right") - 1
        self.E[sel] = np.where(idx >= 0, cE[np.maximum(idx, 0)], self.mE)
        self.J[sel] = np.where(idx >= 0, cJ[np.maximum(idx, 0)], self.mJ)
        self.mE, self.mJ, self.t_end = cE[-1], cJ[-1], t[-1]


def checkpoints(T_end):
    k = int(math.floor(math.log10(T_end / T_MIN) * CHECKPOINTS_PER_DECADE + 1e-9))
    return T_MIN * 10.0 ** (np.arange(k + 1) / CHECKPOINTS_PER_DECADE)


class Scene:
    """A scene's problem, its C RK4 / midpoint, the error functions."""

    def __init__(self, name, cache_dir):
        from hpgen.bench.crk4 import CRK4
        from hpgen.bench.problem import Problem
        self.name = name
        self.pb = pb = Problem(ROOT / "examples" / f"{name}.yaml")
        self.crk4 = CRK4(pb, cache_dir)
        self.inv = INVARIANTS[name]
        self.J0 = self.invariant(pb.y0[None])[0]
        eps = np.finfo(float).eps
        self.floor_E = FLOOR_ULPS * eps * (1 + abs(pb.E0))
        self.floor_J = FLOOR_ULPS * eps * (1 + np.abs(self.J0).max())

    def invariant(self, Y):
        J = self.pb.momentum(Y)
        return J if self.inv is None else J[:, self.inv]

    def errors(self, Y):
        Y = np.atleast_2d(Y)
        ok = np.isfinite(Y).all(axis=1)
        eE = np.full(len(Y), np.nan)
        eJ = np.full(len(Y), np.nan)
        if ok.any():
            eE[ok] = np.abs(self.pb.energy(Y[ok]) - self.pb.E0)
            eJ[ok] = np.abs(self.invariant(Y[ok]) - self.J0).max(axis=1)
        return eE, eJ


def _min_time(fn, repeats=REPEATS):
    return _min_times([fn], repeats)[0]


def _min_times(fns, repeats=REPEATS):
    """Minimum seconds of each of ``fns`` over ``repeats`` interleaved rounds (so that a
    burst of load on the shared machine hits every method alike)."""
    best = [math.inf] * len(fns)
    for _ in range(repeats):
        for i, fn in enumerate(fns):
            t0 = time.perf_counter()
            fn()
            best[i] = min(best[i], time.perf_counter() - t0)
    return best


# ---- the runs --------------------------------------------------------------------------
def segments(h, steps):
    """[(steps, every)] covering ``steps`` steps of size h: one segment per decade of T
    (boundaries T_MIN 10^k), each recorded PER_SEGMENT times (about), so that the early
    checkpoints see as many records as the late ones. Each segment's steps are a multiple
    of its ``every`` (its last record is its last state); the total may exceed ``steps`` by
    less than one ``every`` of the last segment."""
    out, done, bound = [], 0, T_MIN
    while done < steps:
        end = min(steps, max(done + 1, int(round(bound / h))))
        n = end - done
        every = max(1, n // PER_SEGMENT)
        n = -(-n // every) * every
        out.append((n, every))
        done += n
        bound *= 10.0
    return out


def run_hpgen(sc, integ, h, steps, grid):
    """The hpgen scheme by Integrator.stream_record, segment after segment (each restarts
    from the last recorded (g, p): the state of the method)."""
    env = Envelope(grid)
    pb = sc.pb
    kw = {"g0": pb.g0, **({"xi0": pb.xi0} if pb.xi0 is not None else {"mu0": pb.mu0})}
    wall, k, first = 0.0, 0, True
    for n, every in segments(h, steps):
        it = integ.stream_record(h=h, steps=n, every=every, chunk=every * 1000, **kw)
        while True:
            t0 = time.perf_counter()
            try:
                rec = next(it)
            except StopIteration:
                break
            except Exception as e:            # a failed step: the curve stops there
                env.note = f"stopped: {str(e).splitlines()[0][:120]}"
                env.failed = True
                return env, wall + time.perf_counter() - t0
            finally:
                wall += time.perf_counter() - t0
            t, g, mu = rec.t + k * h, rec["g"], rec["mu"]
            if not first and t[0] == k * h:     # record 0 repeats the previous last state
                t, g, mu = t[1:], g[1:], mu[1:]
            first = False
            env.add(t, *sc.errors(pb.pack(g, mu)))
            kw = {"g0": rec["g"][-1], "mu0": rec["mu"][-1]}
        k += n
    env.steps = k
    return env, wall


def run_fixed(sc, kind, h, steps, grid):
    """RK4-C or a midpoint rule (C), segment after segment, in chunks of <= 1000 records."""
    env = Envelope(grid)
    y, k, its, wall = sc.pb.y0.copy(), 0, 0, 0.0
    env.add(np.array([0.0]), *sc.errors(y[None]))
    for n_seg, every in segments(h, steps):
        end = k + n_seg
        while k < end:
            n = min(every * 1000, end - k)
            t0 = time.perf_counter()
            if kind == "RK4-C":
                rec, y, done = sc.crk4.run(y, h, n, every)
            else:
                rec, y, done, it = sc.crk4.midpoint(y, h, n, every,
                                                    lie=kind == "lie-midpoint")
                its += it
            wall += time.perf_counter() - t0
            times = (k + every * np.arange(1, len(rec))) * h
            env.add(times, *sc.errors(rec[1:]))
            k += done
            if done < n:
                env.note = f"stopped at step {k} (non-finite or no convergence)"
                env.failed = True
                env.iterations, env.steps = its, k
                return env, wall
    env.iterations, env.steps = its, k
    return env, wall


def run_dop853(sc, rtol, T_end, grid, max_wall=None):
    from scipy.integrate import DOP853
    env = Envelope(grid)
    pb = sc.pb
    env.add(np.array([0.0]), *sc.errors(pb.y0[None]))
    sol = DOP853(sc.crk4.rhs, 0.0, pb.y0, T_end, rtol=rtol, atol=rtol * 1e-3)
    buf_t, buf_y, steps, wall = [], [], 0, 0.0
    while sol.status == "running":
        t0 = time.perf_counter()
        msg = sol.step()
        wall += time.perf_counter() - t0
        steps += 1
        buf_t.append(sol.t)
        buf_y.append(sol.y.copy())
        if len(buf_t) >= 2000 or sol.status != "running":
            env.add(np.array(buf_t), *sc.errors(np.array(buf_y)))
            buf_t, buf_y = [], []
        if sol.status == "failed":
            env.note = f"DOP853 failed: {msg}"
            env.failed = True
    if buf_t:
        env.add(np.array(buf_t), *sc.errors(np.array(buf_y)))
    env.steps = steps
    return env, wall


def dop853_cost(sc, rtol, T_cal):
    """Seconds per unit T of DOP853 at rtol over [0, T_cal] (minimum of repeats)."""
    from scipy.integrate import DOP853

    def go():
        s = DOP853(sc.crk4.rhs, 0.0, sc.pb.y0, T_cal, rtol=rtol, atol=rtol * 1e-3)
        while s.status == "running":
            s.step()
    return _min_time(go, 2) / T_cal


# ---- T* -------------------------------------------------------------------------------
def wins(sc, hp, peer):
    """Per checkpoint: True where hpgen's energy and invariant errors are both lower than
    the peer's (or at the floor); where the peer has no value: True when it failed before
    (diverged: it has no answer there), None when it was stopped by its budget."""
    out = []
    for a, b, c, d in zip(hp.E, peer.E, hp.J, peer.J):
        if not all(np.isfinite([a, c])):
            out.append(False)
        elif not all(np.isfinite([b, d])):
            out.append(True if peer.failed else None)
        else:
            okE = a < b or (a <= sc.floor_E and b <= sc.floor_E)
            okJ = c < d or (c <= sc.floor_J and d <= sc.floor_J)
            out.append(bool(okE and okJ))
    return out


def t_star(grid, w):
    """(T* or None if never, reached T) from the per-checkpoint wins (None = not reached):
    the first checkpoint from which every later reached checkpoint is a win."""
    reached = [i for i, x in enumerate(w) if x is not None]
    if not reached:
        return None, 0.0
    last = reached[-1]
    if not w[last]:
        return None, float(grid[last])
    j = last
    while j > 0 and (w[j - 1] is None or w[j - 1]):
        j -= 1
    while w[j] is None:
        j += 1
    return float(grid[j]), float(grid[last])


def extrapolate(grid, hp_E, peer_E):
    """When the peer's energy error grows as a power of T over the last decade it reached
    (slope > 0.5 in log-log) and is still below hpgen's, the T where that power law reaches
    hpgen's last energy error (an estimate beyond the run, labelled so), else None."""
    grid, hp_E, peer_E = (np.asarray(a, dtype=float) for a in (grid, hp_E, peer_E))
    ok = np.isfinite(peer_E) & (peer_E > 0)
    if ok.sum() < CHECKPOINTS_PER_DECADE + 1 or not np.isfinite(hp_E).all():
        return None
    i1 = np.flatnonzero(ok)[-1]
    i0 = i1 - CHECKPOINTS_PER_DECADE
    if not ok[i0] or peer_E[i1] >= hp_E[i1]:
        return None
    slope = math.log(peer_E[i1] / peer_E[i0]) / math.log(grid[i1] / grid[i0])
    if slope <= 0.5:
        return None
    return float(grid[i1] * (hp_E[i1] / peer_E[i1]) ** (1.0 / slope))


def fmt_tstar(T, reached):
    if T is None:
        return f"> {reached:.3g}"
    if T <= T_MIN * (1 + 1e-9):
        return f"<= {T_MIN:g}"
    return f"{T:.3g}"


# ---- one scene ------------------------------------------------------------------------
def scene_run(name, args, log):
    import hpgen
    sc = Scene(name, args.cache_dir)
    pb = sc.pb
    h = pb.scene.h
    kw = {"g0": pb.g0, **({"xi0": pb.xi0} if pb.xi0 is not None else {"mu0": pb.mu0})}
    cal = args.calibration
    out = {"scene": name, "h": h, "E0": float(pb.E0), "invariant": (
        "spatial momentum (all components)" if sc.inv is None else
        "e3.(R mu) (vertical spatial momentum)"), "schemes": {}}
    log(f"{name}:")
    for tab, tau, rkmk in args.candidates:
        sname = f"{tab}/{tau}/{rkmk}"
        t0 = time.perf_counter()
        integ = hpgen.build(pb.path, tableau=tab, tau=tau, rkmk=rkmk, backend="c",
                            cache_dir=args.cache_dir).load()
        build_s = time.perf_counter() - t0
        c_hp, c_rk4 = (t / cal for t in _min_times(
            [lambda: integ.simulate(h=h, steps=cal, every=cal, **kw),
             lambda: sc.crk4.run(pb.y0, h, cal)], 5))
        steps = int(min(args.max_steps, max(1000, args.budget / c_hp)))
        T_end = steps * h
        grid = checkpoints(T_end)
        log(f"  hpgen {sname}: {c_hp * 1e9:.0f} ns/step, RK4-C {c_rk4 * 1e9:.0f} ns/step "
            f"(minimum of 5 interleaved calibration runs; built in {build_s:.1f} s), "
            f"{steps} steps to T = {T_end:.4g}")
        methods = {}
        env, wall = run_hpgen(sc, integ, h, steps, grid)
        methods["hpgen " + sname] = _entry(env, wall, T_end, h=h, steps=steps)
        cost = c_hp / h                  # calibrated seconds per unit T of the hpgen scheme
        # RK4-C: equal cost per unit T
        h_rk = h * c_rk4 / c_hp          # c_rk4 / h_rk = c_hp / h: equal cost per unit T
        n_rk = int(round(T_end / h_rk))
        env_rk, wall_rk = run_fixed(sc, "RK4-C", T_end / n_rk, n_rk, grid)
        methods["RK4-C"] = _entry(env_rk, wall_rk, T_end, h=T_end / n_rk, steps=n_rk)
        log(f"    RK4-C h = {T_end / n_rk:.4g}: {wall_rk:.1f} s (hpgen {wall:.1f} s)")
        symmetric = {}
        if name == "turntable":
            for kind, label in SYMMETRIC:
                h_mp = h
                for _ in range(2):             # cost per step depends on h (iterations)
                    c_hp2, c_mp = (t / cal for t in _min_times(
                        [lambda: integ.simulate(h=h, steps=cal, every=cal, **kw),
                         lambda: sc.crk4.midpoint(pb.y0, h_mp, cal,
                                                  lie=kind == "lie-midpoint")], 5))
                    h_mp = h * c_mp / c_hp2
                n_mp = int(round(T_end / h_mp))
                env_mp, wall_mp = run_fixed(sc, kind, T_end / n_mp, n_mp, grid)
                methods[label] = _entry(env_mp, wall_mp, T_end, h=T_end / n_mp, steps=n_mp,
                                        iterations_per_step=env_mp.iterations / max(n_mp, 1))
                symmetric[label] = env_mp
                log(f"    {label} h = {T_end / n_mp:.4g}: {wall_mp:.1f} s")
        # DOP853: the loosest rtol whose cost per unit T is within hpgen's, else the
        # loosest, run as far as --dop-budget seconds allow (more wall time than hpgen's)
        T_cal = min(T_end, args.dop_calibration_T)
        rtol, c_dop = DOP_RTOLS[0], dop853_cost(sc, DOP_RTOLS[0], T_cal)
        for r in DOP_RTOLS[1:]:
            if c_dop > cost:
                break
            c = dop853_cost(sc, r, T_cal)
            if c > cost:
                break
            rtol, c_dop = r, c
        T_dop = T_end if c_dop <= cost else min(T_end, args.dop_budget / c_dop)
        env_d, wall_d = run_dop853(sc, rtol, T_dop, grid)
        methods["DOP853"] = _entry(env_d, wall_d, T_dop, rtol=rtol, steps=env_d.steps)
        log(f"    DOP853 rtol = {rtol:g} to T = {T_dop:.4g}: {wall_d:.1f} s")
        # T*
        hp = env
        ts = {}
        for peer, e in [("RK4-C", env_rk), ("DOP853", env_d)] + list(symmetric.items()):
            T, reached = t_star(grid, wins(sc, hp, e))
            ts[peer] = {"T_star": T, "reached": reached, "text": fmt_tstar(T, reached)}
            if T is None:
                est = extrapolate(grid, hp.E, e.E)
                ts[peer]["extrapolated"] = est
                if est is not None:
                    ts[peer]["text"] += f" (extrapolated {est:.2g})"
        worst = [ts[p]["T_star"] for p in ("RK4-C", "DOP853")]
        overall = None if None in worst else max(worst)
        reached = min(ts["RK4-C"]["reached"], ts["DOP853"]["reached"])
        out["schemes"][sname] = {"T_end": T_end, "checkpoints": grid.tolist(),
                                 "methods": methods, "T_star": ts,
                                 "T_star_overall": overall,
                                 "T_star_text": fmt_tstar(overall, reached)}
    best = min(out["schemes"], key=lambda s: (out["schemes"][s]["T_star_overall"] is None,
                                              out["schemes"][s]["T_star_overall"] or 0))
    out["best"] = best
    return out


def _entry(env, wall, T_reached, **kw):
    d = {"wall_s": wall, "T_end": T_reached, "cost_per_T": wall / T_reached,
         "energy_error": [None if not np.isfinite(x) else float(x) for x in env.E],
         "invariant_error": [None if not np.isfinite(x) else float(x) for x in env.J]}
    d.update({k: (float(v) if isinstance(v, (float, np.floating)) else v)
              for k, v in kw.items()})
    if hasattr(env, "note"):
        d["note"] = env.note
    d["failed"] = env.failed
    if env.failed:
        d["T_failed"] = float(env.t_end)
    return d


# ---- figure and table ------------------------------------------------------------------
def figure(res, path):
    """One row per hpgen candidate, each with its peers at its own cost: energy error (left)
    and invariant error (right) against T, T* marked."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    schemes = list(res["schemes"].items())
    fig, axes = plt.subplots(len(schemes), 2, figsize=(12, 4.3 * len(schemes)),
                             squeeze=False)
    styles = {"RK4-C": "--s", "DOP853": ":D", "implicit midpoint (C)": "-.v",
              "Lie midpoint (RKMK, C)": "-.^"}
    for row, (sname, sch) in zip(axes, schemes):
        grid = np.array(sch["checkpoints"])
        hp_cost = sch["methods"]["hpgen " + sname]["cost_per_T"]
        for ax, key, label in ((row[0], "energy_error", "energy error max |E - E(0)|"),
                               (row[1], "invariant_error", "invariant error")):
            for mname, m in sch["methods"].items():
                y = np.array([np.nan if v is None else v for v in m[key]], dtype=float)
                if mname.startswith("hpgen"):
                    ax.loglog(grid, y, "-o", ms=3, lw=2, label=f"{mname} (h = {m['h']:g})")
                    continue
                par = f"rtol = {m['rtol']:g}" if "rtol" in m else f"h = {m['h']:.3g}"
                if m.get("failed"):
                    par += f", diverged at T = {m['T_failed']:.3g}"
                ax.loglog(grid, y, styles.get(mname, "--"), ms=3,
                          label=f"{mname} ({par}, wall x{m['cost_per_T'] / hp_cost:.2f})")
            T = sch["T_star_overall"]
            if T is not None:
                ax.axvline(T, color="k", lw=0.8, ls="--")
            ax.set_xlabel("T (simulated time)")
            ax.set_ylabel(label + (f" ({res['invariant']})" if key == "invariant_error"
                                   else ""), fontsize=8)
            ax.grid(True, which="both", alpha=0.3)
        row[0].legend(fontsize=7)
        best = " (best)" if sname == res["best"] else ""
        row[0].set_title(f"hpgen {sname}{best}, {hp_cost * 1e6:.2g} us per unit T; "
                         f"T* = {sch['T_star_text']}", fontsize=9)
        row[1].set_title("wall x: the method's wall time per unit T / hpgen's (same run)",
                         fontsize=8)
    fig.suptitle(f"{res['scene']}: errors against T at fixed cost (peers at the hpgen "
                 "scheme's cost per unit T)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def table(results):
    rows = ["| scene | hpgen scheme (h) | T reached | T* vs RK4-C | T* vs DOP853 | T* | "
            "turntable: T* vs implicit / Lie midpoint |", "|---|---|---|---|---|---|---|"]
    for r in results:
        for sname, s in r["schemes"].items():
            mark = " (best)" if sname == r["best"] else ""
            ts = s["T_star"]
            mp = " / ".join(ts[label]["text"] for _, label in SYMMETRIC if label in ts) or "-"
            rows.append(f"| {r['scene']} | {sname} ({r['h']:g}){mark} | {s['T_end']:.4g} | "
                        f"{ts['RK4-C']['text']} | {ts['DOP853']['text']} | "
                        f"{s['T_star_text']} | {mp} |")
    return "\n".join(rows)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true",
                    help="small runs (2*10^4 hpgen steps, Stormer-Verlet only): a smoke test")
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--max-steps", type=int, default=MAX_STEPS)
    ap.add_argument("--budget", type=float, default=12.0,
                    help="seconds of hpgen run per scheme and scene (caps the steps)")
    ap.add_argument("--dop-budget", type=float, default=12.0,
                    help="seconds of DOP853 run per scheme and scene when it cannot be as "
                    "cheap as hpgen per unit T")
    ap.add_argument("--figures", default=str(ROOT / "docs" / "figures"))
    ap.add_argument("--json", help="write the numbers here")
    ap.add_argument("--cache-dir")
    ap.add_argument("--replot", help="only redraw the figures from this --json file")
    args = ap.parse_args(argv)
    if args.replot:
        figdir = Path(args.figures)
        figdir.mkdir(parents=True, exist_ok=True)
        for r in json.loads(Path(args.replot).read_text())["results"]:
            figure(r, figdir / f"horizon_{r['scene']}.png")
        return 0
    args.candidates = CANDIDATES
    args.calibration, args.dop_calibration_T = 200_000, 50.0
    if args.quick:
        args.max_steps, args.budget, args.dop_budget = min(args.max_steps, 20_000), 2.0, 1.0
        args.candidates = CANDIDATES[:1]
        args.calibration, args.dop_calibration_T = 2000, 5.0
    scenes = [s.strip() for s in args.scenes.split(",") if s.strip()]
    bad = [s for s in scenes if s not in SCENES]
    if bad:
        ap.error(f"--scenes: expected some of {', '.join(SCENES)}, got {', '.join(bad)}")
    figdir = Path(args.figures)
    figdir.mkdir(parents=True, exist_ok=True)

    def log(s):
        print(s, file=sys.stderr, flush=True)
    t0 = time.perf_counter()
    results = []
    for name in scenes:
        r = scene_run(name, args, log)
        path = figdir / f"horizon_{name}.png"
        figure(r, path)
        r["figure"] = str(path)
        results.append(r)
        log(f"  -> {path} ({time.perf_counter() - t0:.0f} s so far)")
    print(table(results))
    print(f"\n(total {time.perf_counter() - t0:.0f} s; command: python benchmarks/horizon.py "
          + " ".join(argv if argv is not None else sys.argv[1:]) + ")")
    if args.json:
        Path(args.json).write_text(json.dumps({"results": results, "quick": args.quick},
                                              indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
