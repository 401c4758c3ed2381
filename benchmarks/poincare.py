"""Poincare sections of the underwater vehicle: variational Euler (hpgen) against RK4.

    python benchmarks/poincare.py [--quick] [--states N] [--T T] [--tableau euler-forward]

Kirchhoff's equations for mu = (Pi, P) (docs/numerics.md sec. 11), I = (2, 1, 2/3), M = (1, 1.5, 3):
    Pi' = Pi x Omega + P x v,  P' = P x Omega,  Omega = Pi / I,  v = P / M,
H = 1/2 Pi.Omega + 1/2 P.v, Casimirs |P|^2 and Pi.P. All initial states lie on the level
set of H and both Casimirs through (Pi0; P0) = (0.3, 1, 0.2; 1, 0, 0.5) (a chaotic set):
that state itself plus states placed on the section P3 = 0 (P3' > 0) on a grid of
(atan2(P2, P1), Pi3). Section points: upward zero crossings of P3 between recorded samples
(every step), linearly interpolated; plotted as (atan2(P2, P1), Pi3).

Methods, each at h = 0.025 and h = 0.05:
- VE: hpgen's variational Euler (``--tableau``, default euler-forward) with the Cayley map
  on SE3, compiled from examples/underwater_vehicle.yaml. l is left-invariant, so hpgen
  emits the reduced Euler-Poincare step (one algebra unknown); the section only needs the
  node momenta p_k = mu. For a left-invariant l the momentum updates of euler-forward,
  euler-backward and stormer-verlet coincide (the paper's eq. dlp; measured: identical to
  the last digit), and the scheme is of order 2 (observed 2.00 in (g, p) at T = 1), as the
  paper's Fig. 1 caption says ("second-order accurate variational Euler").
- RK4: the classical Runge-Kutta method on the 6-dim equations above, plain NumPy,
  vectorized over the states.
- Benchmark: SciPy DOP853 at rtol 1e-10 (atol 1e-12), all states stacked, crossings refined
  by Newton's method on its dense output.

Writes docs/figures/underwater_poincare.png and benchmarks/out/poincare.npz, and prints
the energy and Casimir drift of each method (max |X - X0| over the run, max over the first
and last tenth of the run, slope of a linear fit times T). Two worker processes.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "underwater_vehicle.yaml"
FIGURE = ROOT / "docs" / "figures" / "underwater_poincare.png"
OUT = ROOT / "benchmarks" / "out"

INERTIA = np.array([2.0, 1.0, 2.0 / 3.0])
MASS = np.array([1.0, 1.5, 3.0])
Y0 = np.array([0.3, 1.0, 0.2, 1.0, 0.0, 0.5])       # (Pi0; P0)
WEIGHTS = np.concatenate([1.0 / INERTIA, 1.0 / MASS])


# ---- the equations ---------------------------------------------------------------------
def _tensor():
    """T (6, 36) with y' = T (y outer y).ravel(): the equations are quadratic in y."""
    eps = np.zeros((3, 3, 3))
    eps[0, 1, 2] = eps[1, 2, 0] = eps[2, 0, 1] = 1.0
    eps[0, 2, 1] = eps[2, 1, 0] = eps[1, 0, 2] = -1.0
    T = np.zeros((6, 6, 6))
    T[:3, :3, :3] = eps / INERTIA[None, None, :]             # Pi x Omega
    T[:3, 3:, 3:] = eps / MASS[None, None, :]                # P x v
    T[3:, 3:, :3] = eps / INERTIA[None, None, :]             # P x Omega
    return T.reshape(6, 36)


TENSOR = _tensor()


def rhs(y):
    """y' for y of shape (6,) or (6, N) (states in columns)."""
    y = np.asarray(y, dtype=float)
    if y.ndim == 1:
        return TENSOR @ np.outer(y, y).ravel()
    return TENSOR @ (y[:, None, :] * y[None, :, :]).reshape(36, -1)


def hamiltonian(y):
    """H for y of shape (..., 6)."""
    return 0.5 * np.sum(np.asarray(y) ** 2 * WEIGHTS, axis=-1)


def casimirs(y):
    """(|P|^2, Pi.P) for y of shape (..., 6)."""
    y = np.asarray(y)
    return np.sum(y[..., 3:] ** 2, axis=-1), np.sum(y[..., :3] * y[..., 3:], axis=-1)


# ---- initial states on one level set ----------------------------------------------------
def state_on_section(theta, pi3, H0=None, C1=None, C2=None):
    """The state with P3 = 0, atan2(P2, P1) = theta, Pi3 = pi3, P3' > 0 on the level set
    (H, |P|^2, Pi.P) = (H0, C1, C2) (default: that of Y0), or None if there is none.

    P = sqrt(C1) (cos theta, sin theta, 0); Pi = c e_theta + s e_perp + pi3 e3 with
    c = C2 / sqrt(C1) (the Casimir Pi.P) and s from H = H0 (a quadratic); P3' =
    P1 Omega2 - P2 Omega1 grows with s, so the larger root is the one with P3' > 0.
    """
    if H0 is None:
        H0 = hamiltonian(Y0)
        C1, C2 = casimirs(Y0)
    r = np.sqrt(C1)
    c, e_t, e_p = C2 / r, np.array([np.cos(theta), np.sin(theta), 0.0]), \
        np.array([-np.sin(theta), np.cos(theta), 0.0])
    w = 1.0 / INERTIA
    a = 0.5 * np.sum(w * e_p ** 2)
    b = np.sum(w * c * e_t * e_p)
    c0 = 0.5 * np.sum(w * (c * e_t) ** 2) + 0.5 * w[2] * pi3 ** 2 + \
        0.5 * C1 * np.sum(e_t[:2] ** 2 / MASS[:2]) - H0
    disc = b * b - 4 * a * c0
    if disc < 0:
        return None
    s = (-b + np.sqrt(disc)) / (2 * a)
    y = np.concatenate([c * e_t + s * e_p + np.array([0.0, 0.0, pi3]), r * e_t])
    if rhs(y)[5] <= 0:
        return None
    return y


def initial_states(n):
    """Y0 and n - 1 states on the section P3 = 0 of the level set of Y0, on a grid of
    (theta, Pi3) clipped to the accessible region; (n, 6)."""
    states = [Y0]
    thetas = np.linspace(-np.pi, np.pi, 25)[:-1]
    pis = np.linspace(-1.0, 1.0, 21)
    cands = [y for p in pis for th in thetas if (y := state_on_section(th, p)) is not None]
    if n > 1:
        pick = np.linspace(0, len(cands) - 1, n - 1).round().astype(int)
        # interleave the grid (Pi3-major) so that every n covers the whole region
        states += [cands[i] for i in pick]
    return np.array(states[:n])


# ---- sections ---------------------------------------------------------------------------
def crossings(y, t):
    """Upward zero crossings of P3 between consecutive samples: (theta, Pi3, t) arrays.

    y (K, 6) samples at times t (K,). Linear interpolation between the bracketing samples.
    """
    p3 = y[:, 5]
    k = np.nonzero((p3[:-1] < 0) & (p3[1:] >= 0))[0]
    a = (p3[k] / (p3[k] - p3[k + 1]))[:, None]
    z = (1 - a) * y[k] + a * y[k + 1]
    tc = (1 - a[:, 0]) * t[k] + a[:, 0] * t[k + 1]
    return np.arctan2(z[:, 4], z[:, 3]), z[:, 2], tc


def drift(t, x):
    """Drift figures of a series x(t) (one state): max |x - x0|, max over the first and the
    last tenth, and the slope of a least-squares line times the duration."""
    e = x - x[0]
    tenth = max(1, len(e) // 10)
    slope = np.polyfit(t, e, 1)[0] if len(t) > 2 else 0.0
    return np.array([np.abs(e).max(), np.abs(e[:tenth]).max(), np.abs(e[-tenth:]).max(),
                     slope * (t[-1] - t[0])])


def invariants(y):
    """(K, 3) H, |P|^2, Pi.P."""
    return np.stack([hamiltonian(y), *casimirs(y)], axis=-1)


def run_rk4(states, h, T, every_inv=10, chunk=20000):
    """Classical RK4 on all states at once. Returns (sections per state, times of the
    invariant samples, invariants (K, N, 3))."""
    y = np.array(states, dtype=float).T.copy()            # (6, N)
    N = y.shape[1]
    steps = int(round(T / h))
    secs = [[] for _ in range(N)]
    inv_t, inv = [0.0], [invariants(y.T)]
    done = 0
    while done < steps:
        n = min(chunk, steps - done)
        rec = np.empty((n + 1, 6, N))
        rec[0] = y
        for k in range(n):
            k1 = rhs(y)
            k2 = rhs(y + (0.5 * h) * k1)
            k3 = rhs(y + (0.5 * h) * k2)
            k4 = rhs(y + h * k3)
            y = y + (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4)
            rec[k + 1] = y
        t = (done + np.arange(n + 1)) * h
        for j in range(N):
            secs[j].append(np.stack(crossings(rec[:, :, j], t), axis=-1))
        sel = np.arange(every_inv, n + 1, every_inv) if every_inv <= n else np.array([n])
        inv_t.extend(t[sel])
        inv.extend(invariants(rec[sel].transpose(0, 2, 1)))
        done += n
    return [np.concatenate(s) for s in secs], np.array(inv_t), np.array(inv)


def compile_ve(tableau="euler-forward", cache_dir=None):
    import hpgen
    return hpgen.compile(MODEL, tableau=tableau, tau="cay", rkmk="truncated", backend="c",
                         cache_dir=cache_dir)


def run_ve(states, h, T, tableau="euler-forward", every_inv=10, cache_dir=None):
    """hpgen's variational Euler, one simulate call per state, every step recorded."""
    integ = compile_ve(tableau, cache_dir)
    steps = int(round(T / h))
    secs, inv = [], []
    t = np.arange(steps + 1) * h
    for y0 in states:
        tr = integ.simulate(g0=np.eye(4), mu0=y0, h=h, steps=steps, every=1)
        secs.append(np.stack(crossings(tr.mu, t), axis=-1))
        inv.append(invariants(tr.mu[::every_inv]))
    return secs, t[::every_inv], np.array(inv).transpose(1, 0, 2)


def run_dop853(states, T, rtol=1e-10, atol=1e-12, chunk=250.0, grid=0.01):
    """Benchmark: DOP853 on the stacked states; crossings found on a grid of the dense
    output and refined by two Newton steps on P3(t) (P3' from the equations)."""
    from scipy.integrate import solve_ivp
    N = len(states)
    y = np.array(states, dtype=float).T.ravel()            # (6 N,), component-major
    fun = lambda t, z: rhs(z.reshape(6, N)).ravel()        # noqa: E731
    secs = [[] for _ in range(N)]
    inv_t, inv = [0.0], [invariants(np.array(states))]
    t0 = 0.0
    while t0 < T - 1e-9:
        t1 = min(T, t0 + chunk)
        sol = solve_ivp(fun, (t0, t1), y, method="DOP853", rtol=rtol, atol=atol,
                        dense_output=True)
        assert sol.success, sol.message
        tg = np.linspace(t0, t1, int(round((t1 - t0) / grid)) + 1)
        Z = sol.sol(tg).reshape(6, N, -1)
        for j in range(N):
            p3 = Z[5, j]
            k = np.nonzero((p3[:-1] < 0) & (p3[1:] >= 0))[0]
            tc = tg[k] + (tg[k + 1] - tg[k]) * p3[k] / (p3[k] - p3[k + 1])
            for _ in range(2):
                if len(tc) == 0:
                    break
                zc = sol.sol(tc).reshape(6, N, -1)[:, j, :]
                tc = tc - zc[5] / rhs(zc)[5]
            if len(tc):
                zc = sol.sol(tc).reshape(6, N, -1)[:, j, :]
                secs[j].append(np.stack([np.arctan2(zc[4], zc[3]), zc[2], tc], axis=-1))
        sel = tg[10::10]
        inv_t.extend(sel)
        inv.extend(invariants(sol.sol(sel).reshape(6, N, -1).transpose(2, 1, 0)))
        y, t0 = sol.y[:, -1], t1
    return ([np.concatenate(s) if s else np.zeros((0, 3)) for s in secs], np.array(inv_t),
            np.array(inv))


# ---- driver -----------------------------------------------------------------------------
def _task(args):
    kind, h, states, T, tableau = args
    t0 = time.perf_counter()
    if kind == "VE":
        out = run_ve(states, h, T, tableau)
    elif kind == "RK4":
        out = run_rk4(states, h, T)
    else:
        out = run_dop853(states, T)
    return kind, h, out, time.perf_counter() - t0


def drift_table(results, T):
    """Rows (method, h, quantity, median and max over states of the drift figures)."""
    rows = []
    for (kind, h), (_, t, inv) in results.items():
        for q, name in enumerate(("H", "P.P", "Pi.P")):
            d = np.array([drift(t, inv[:, j, q]) for j in range(inv.shape[1])])
            rows.append((kind, h, name, d))
    return rows


def plot(results, states, T, path, tableau):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 3, figsize=(13.5, 8.2), sharex=False, sharey=False)
    panels = [(axes[0, 0], ("DOP853", None), "benchmark: DOP853, rtol 1e-10"),
              (axes[0, 1], ("VE", 0.025), "VE (hpgen), h = 0.025"),
              (axes[0, 2], ("RK4", 0.025), "RK4, h = 0.025"),
              (axes[1, 1], ("VE", 0.05), "VE (hpgen), h = 0.05"),
              (axes[1, 2], ("RK4", 0.05), "RK4, h = 0.05")]
    colors = plt.cm.turbo(np.linspace(0.05, 0.95, len(states)))
    for ax, key, title in panels:
        secs = results[key][0]
        npts = 0
        for j, s in enumerate(secs):
            ax.scatter(s[:, 0], s[:, 1], s=1.2, color=colors[j], marker=".", linewidths=0,
                       rasterized=True)
            npts += len(s)
        ax.set_title(f"{title} ({npts} points)", fontsize=10)
        ax.set_xlim(-np.pi, np.pi)
        ax.set_ylim(-1.0, 1.0)
        ax.set_xlabel("atan2(P2, P1)")
        ax.set_ylabel("Pi3")
    ax = axes[1, 0]
    styles = {("DOP853", None): ("k", "-"), ("VE", 0.025): ("tab:blue", "-"),
              ("VE", 0.05): ("tab:blue", "--"), ("RK4", 0.025): ("tab:red", "-"),
              ("RK4", 0.05): ("tab:red", "--")}
    for key, (c, ls) in styles.items():
        _, t, inv = results[key]
        dH = np.abs(inv[:, :, 0] - inv[0, :, 0]).max(axis=1)      # max over states
        dH = np.maximum.accumulate(dH)
        lab = "DOP853" if key[1] is None else f"{key[0]} h = {key[1]}"
        ax.loglog(t[1:], dH[1:], color=c, ls=ls, label=lab, lw=1.2)
    ax.set_xlabel("t")
    ax.set_ylabel("running max over states of |H - H0|")
    ax.set_ylim(1e-15, 10.0)
    lines = []
    for key in (("RK4", 0.05), ("VE", 0.05)):
        inv = results[key][2]
        dH, dC = (np.abs(inv[-1, :, q] - inv[0, :, q]).max() for q in (0, 1))
        dC2 = np.abs(inv[:, :, 1:] - inv[0, :, 1:]).max()
        lines.append(f"{key[0]} h = 0.05, t = {T:g}: |dH| {dH:.1e}, |d|P|^2| {dC:.1e}"
                     if key[0] == "RK4" else
                     f"{key[0]} h = 0.05: max |dCasimirs| {dC2:.1e}")
    ax.text(0.98, 0.02, "\n".join(lines), transform=ax.transAxes, ha="right", va="bottom",
            fontsize=7.5, bbox=dict(facecolor="white", edgecolor="0.7", alpha=0.9))
    ax.set_title("energy error (RK4 drifts ~ t, VE bounded)", fontsize=10)
    ax.legend(fontsize=8, loc="upper left", ncol=2)
    ax.grid(True, which="major", alpha=0.3)
    fig.suptitle(f"Underwater vehicle, P3 = 0 section (P3' > 0), {len(states)} states on "
                 f"one energy and Casimir level, T = {T:g}; VE = {tableau}, Cayley",
                 fontsize=11)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="8 states, T = 500 (default 32, 5000)")
    ap.add_argument("--states", type=int, default=None)
    ap.add_argument("--T", type=float, default=None)
    ap.add_argument("--tableau", default="euler-forward",
                    choices=["euler-forward", "euler-backward"])
    ap.add_argument("--figure", type=Path, default=FIGURE)
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args(argv)
    n = a.states or (8 if a.quick else 32)
    T = a.T or (500.0 if a.quick else 5000.0)
    states = initial_states(n)
    t_start = time.perf_counter()
    compile_ve(a.tableau)                      # build once, before the workers fork
    tasks = [("DOP853", None, states, T, a.tableau)] + \
        [(k, h, states, T, a.tableau) for k in ("VE", "RK4") for h in (0.025, 0.05)]
    results, seconds = {}, {}
    with ProcessPoolExecutor(max_workers=a.workers) as ex:
        for kind, h, out, sec in ex.map(_task, tasks):
            results[(kind, h)] = out
            seconds[(kind, h)] = sec
    OUT.mkdir(parents=True, exist_ok=True)
    np.savez_compressed(OUT / "poincare.npz", states=states, T=T, **{
        f"{k}_{h}_sections_{j}": s for (k, h), (secs, _, _) in results.items()
        for j, s in enumerate(secs)}, **{
        f"{k}_{h}_invariants": inv for (k, h), (_, _, inv) in results.items()})
    plot(results, states, T, a.figure, a.tableau)
    print(f"{n} states, T = {T:g}; VE = {a.tableau} + Cayley (hpgen, reduced EP step)")
    print("drift of X over the run, per state: median (max) over the states")
    print("| method | h | X | max abs(X - X0) | first tenth | last tenth | slope * T | "
          "section points | seconds |")
    print("|---|---|---|---|---|---|---|---|---|")
    for kind, h, name, d in drift_table(results, T):
        med, mx = np.median(d, axis=0), np.max(np.abs(d), axis=0)
        npts = sum(len(s) for s in results[(kind, h)][0])
        cells = " | ".join(f"{m:.2e} ({x:.1e})" for m, x in zip(med, mx))
        print(f"| {kind} | {'-' if h is None else h} | {name} | {cells} | {npts} | "
              f"{seconds[(kind, h)]:.1f} |")
    print(f"figure: {a.figure} ({os.path.getsize(a.figure) / 1024:.0f} KB); data: "
          f"{OUT / 'poincare.npz'}; wall time {time.perf_counter() - t_start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
