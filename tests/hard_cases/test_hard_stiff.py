"""Hard case 5: stiff potentials at increasing h (C backend).

A. Stiff spring in R2, l = 1/2 |xi|^2 - 1/2 k |x|^2, k = 1e4 (omega = 100), x0 = (1, 0),
   v0 = (0, 50), 1000 steps of stormer-verlet/cay/truncated (explicit in the force: on R2
   every tau is I + x^, so this is Stormer-Verlet). Linear theory: the amplification
   matrix has eigenvalues with lam + 1/lam = 2 - (omega h)^2, so
   - omega h < 2: |lam| = 1, stable; the energy error is bounded (it oscillates, growing
     like 1/(4 - (omega h)^2) as the limit nears, but does not grow in time);
   - omega h = 2: double eigenvalue -1, polynomial growth;
   - omega h > 2: |lam| = |b| + sqrt(b^2 - 1) > 1 with b = 1 - (omega h)^2 / 2: the
     state grows like |lam|^k. hpgen has no stability check; what happens is decided by
     overflow: if |lam|^1000 < ~1e300 the run ends with a finite, exponentially grown
     state (no error; the test asserts the energy error is > 1e6, i.e. huge), otherwise
     the state overflows and the step reports a ConvergenceError (non-finite) at step
     n* in [ln(1e300), ln(DBL_MAX)] / ln|lam| (+2): the test asserts which of the two
     happens, as predicted by |lam|, and where.
B. The same spring with midpoint/cay/truncated (implicit): energy conserved to 1e-12
   relative at every omega h, up to 10 (no stability limit; the contrast to A).
C. Stiff heavy top, Mg = 1e4, I = (1, 5, 6) (small oscillations about the hanging
   equilibrium: omega = sqrt(Mg / I_1) = 100), released from rest 0.5 rad off the
   hanging position, 2000 steps of midpoint/cay/truncated (implicit, nonlinear: Newton
   every step). Observed and asserted: for omega h <= 5 every run finishes with a bounded
   energy error (last tenth within 1.5x of the first); for omega h >= 10 Newton fails and
   the failure is reported as ConvergenceError ("Newton did not converge", 50 iterations,
   step, time = step h, partial trajectory up to the failed step) -- not hidden -- or as a
   DomainError for a converged root beyond Cayley's quarter turn. (omega h = 5 is the case
   the starts decide: before the retry of a failed predicted start it stopped at step 8
   with a false DomainError; with the retry it reached step 639, where Newton was still
   converging after 50 iterations, residual 5e-11; since the start G_k + extrapolated
   offsets z - G (issue 14) all 2000 steps run, 13.7 iterations a step.)
Each part prints its table (omega h, outcome, energy error).
"""
from __future__ import annotations

import math

import numpy as np

import hpgen
from hardcase_util import (SPRING, SPRING_OMEGA, STIFF_TOP, STIFF_TOP_OMEGA,
                           check_reported_failure, envelope_drift)
from reference import rotvec

WH = [0.1, 0.5, 1.0, 1.5, 1.9, 1.99, 2.0, 2.01, 2.1, 2.5, 4.0, 10.0]
N = 1000
K = SPRING_OMEGA**2
X0 = np.array([[1.0, 0.0, 1.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])   # x = (1, 0)
V0 = np.array([0.0, 50.0])
E0 = 0.5 * V0 @ V0 + 0.5 * K * 1.0


def _spring_energy_error(tr):
    x, p = tr.g[:, :2, 2], tr.mu
    with np.errstate(over="ignore", invalid="ignore"):
        E = 0.5 * np.sum(p**2, axis=1) + 0.5 * K * np.sum(x**2, axis=1)
    return np.abs(E / E0 - 1.0)


def _growth(wh):
    b = 1.0 - wh * wh / 2.0
    return abs(b) + math.sqrt(b * b - 1.0)


def test_spring_stormer_verlet_stability_limit(compile_model):
    """Part A: bounded energy error below omega h = 2; above it, exactly the outcome the
    growth factor |lam| predicts (finite and huge, or a reported non-finite failure at the
    predicted step)."""
    integ = compile_model(SPRING, tableau="stormer-verlet", tau="cay", rkmk="truncated")
    print(f"\n[stiff spring] stormer-verlet/cay/truncated, omega = {SPRING_OMEGA}, {N} steps")
    print(f"  {'omega h':>7}  {'|lam|':>7}  outcome")
    for wh in WH:
        h = wh / SPRING_OMEGA
        lam = _growth(wh) if wh > 2.0 else 1.0
        try:
            tr = integ.simulate(g0=X0, xi0=V0, h=h, steps=N)
        except hpgen.ConvergenceError as err:
            n_lo = math.log(1e300) / math.log(lam)
            n_hi = math.log(np.finfo(float).max) / math.log(lam) + 2
            part = _spring_energy_error(err.partial)
            print(f"  {wh:7.2f}  {lam:7.3f}  {check_reported_failure(err, h)}; predicted "
                  f"overflow at step {n_lo:.0f}..{n_hi:.0f}; energy error at step "
                  f"{err.step - 1}: {part[-1]:.1e}")
            assert wh > 2.0 and "non-finite" in str(err)
            assert n_hi <= N and n_lo <= err.step <= n_hi
            assert part[-1] > 1e100                   # the partial records show the blow-up
            continue
        dE = _spring_energy_error(tr)
        first, last, _ = envelope_drift(tr.t, dE)
        kind = "stable" if wh < 2.0 else ("marginal" if wh == 2.0 else "unstable")
        print(f"  {wh:7.2f}  {lam:7.3f}  finished ({kind}): max |dE|/E0 first tenth "
              f"{first:.3e}, last tenth {last:.3e}, max |x| {np.abs(tr.g[:, :2, 2]).max():.2e}")
        if wh < 2.0:
            assert np.isfinite(dE).all() and last <= 1.5 * first
            if wh <= 0.1:
                assert first < 2e-3                   # O((omega h)^2) at small omega h
        elif wh == 2.0:
            assert last > 10 * first                  # polynomial growth
        else:
            # finished without an error: only if the predicted growth stays below overflow
            assert lam**N < 1e300
            assert last > 1e6                         # huge (exponential growth), not hidden


def test_spring_midpoint_has_no_limit(compile_model):
    """Part B: the implicit midpoint rule conserves the spring's quadratic energy (1e-12
    relative) at every omega h up to 10."""
    integ = compile_model(SPRING, tableau="midpoint", tau="cay", rkmk="truncated")
    rows = []
    for wh in WH:
        tr = integ.simulate(g0=X0, xi0=V0, h=wh / SPRING_OMEGA, steps=N)
        rows.append((wh, float(_spring_energy_error(tr).max())))
    print("\n[stiff spring] midpoint/cay/truncated: max |dE|/E0 over 1000 steps: "
          + ", ".join(f"omega h {wh}: {e:.1e}" for wh, e in rows))
    assert all(e < 1e-12 for _, e in rows)


TOP_H = [1e-3, 5e-3, 0.01, 0.02, 0.03, 0.05, 0.1, 0.2]
I_TOP, MG = np.array([1.0, 5.0, 6.0]), 1e4


def test_stiff_heavy_top_newton_failure_reported(compile_model):
    """Part C: bounded energy error for omega h <= 5, a reported Newton failure
    (ConvergenceError with step, time, residual, iterations, partial) for omega h >= 10."""
    integ = compile_model(STIFF_TOP, tableau="midpoint", tau="cay", rkmk="truncated")
    R0 = rotvec([math.pi - 0.5, 0.0, 0.0])
    steps = 2000
    E_osc = MG * (1.0 - math.cos(0.5))              # E0 - E_min, the oscillation's energy
    print(f"\n[stiff top] Mg = {MG:g}, midpoint/cay/truncated, omega = {STIFF_TOP_OMEGA}, "
          f"{steps} steps from rest 0.5 rad off the hanging equilibrium")
    print(f"  {'h':>6} {'omega h':>7}  outcome")
    for h in TOP_H:
        wh = h * STIFF_TOP_OMEGA
        try:
            tr = integ.simulate(g0=R0, xi0=np.zeros(3), h=h, steps=steps)
        except hpgen.ConvergenceError as err:
            print(f"  {h:6.3f} {wh:7.2f}  {check_reported_failure(err, h)}: {err}")
            assert wh >= 10.0
            # Newton diverges, or (since the Cayley chart's margin is a quarter turn per step)
            # the step is refused as a DomainError: both are reported failures
            assert ("Newton did not converge" in str(err)
                    or (isinstance(err, hpgen.DomainError) and "domain" in str(err)))
            if not isinstance(err, hpgen.DomainError):     # a failed Newton used all it had
                assert err.iterations == 50 and err.residual > 0.0
            continue
        E = 0.5 * np.sum(tr.mu**2 / I_TOP, axis=1) + MG * tr.g[:, 2, 2]
        for k in (0, steps // 2, steps):           # hpgen's energy kernel agrees
            assert abs(integ.energy(tr.g[k], tr.mu[k]) - E[k]) <= 1e-9 * MG
        dE = np.abs(E - E[0]) / E_osc
        first, last, _ = envelope_drift(tr.t, dE)
        print(f"  {h:6.3f} {wh:7.2f}  finished: max |dE| / E_osc first tenth {first:.3e}, "
              f"last tenth {last:.3e}, Newton iterations per step "
              f"{tr.newton_iterations / steps:.1f}")
        assert wh <= 5.0
        assert last <= 1.5 * first and first < 0.5
