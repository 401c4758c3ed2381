"""Hard case 2: a fast spin, |h omega| from 0.1 up to past the chart limits.

Free rigid body (I = (2, 1, 2/3)) spinning about its major axis with a small nutation:
Pi0 = (20, 0.5, 0.2), omega0 = Pi0 / I = (10, 0.5, 0.3), |omega0| = 10.02. One run per
(scheme, h) over one revolution, T = 2 pi / |omega0|, steps = max(1, round(T / h)), so the
outcome depends on |h omega0| only (a dimensionless scan); the nutation's share of |Pi| is
~3%, so the spin (the chart) dominates the error.

Charts: exp is injective for |h xi| < pi (margin pi - |h xi|); skew needs |h xi| < 1 and, on
a spin (p parallel to xi, p = sqrt(1 - |h xi|^2) I xi), has no solution at all for
|h omega| > 1/2; cay is defined everywhere, its rotation per step saturates below pi
(2 atan(|h xi| / 2)).

Error of a finished run: max over the records of max(rotation angle of R_ref^T R_k (rad),
|Pi_k - Pi_ref(t_k)| / |Pi0|), against the exact solution (Jacobi elliptic functions,
hpgen.analysis.exact, or DOP853 at rtol 1e-13 if absent).

Outcome of each run: "accurate" (finite, error <= 0.1), "coarse" (error > 0.1 but within
10x of what the scheme's order predicts from its own accurate run at |h omega| = 0.1,
e(hw) <= 10 e(0.1) (hw / 0.1)^p: the scheme's true solution at a step too coarse for 10%,
e.g. Cayley's known angle compression, rotation 2 atan(|h xi|/2) per step), "raised"
(ConvergenceError or its subclass DomainError, whose message, step, time, residual,
iterations and partial trajectory are checked), or "GARBAGE": non-finite output, or error
> 0.1 and more than 10x beyond the order's prediction, with no error raised (a spurious
Newton root or a wrong branch; measured before the chart margins were tightened:
gauss2/cay/exact at |h omega| = 3 rotated 0.04 rad instead of 3.0).

Pass criteria, per scheme:
- no GARBAGE row (the issue's requirement: never garbage silently);
- |h omega| = 0.1 is accurate (the error measure is not failing everything);
- the chart limit shows up as a DomainError: exp for |h omega| > pi, skew for
  |h omega| >= 0.75 (no solution beyond 1/2).
The table (h omega, steps, outcome, errors) is printed for every scheme.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import hpgen
from conftest import FREE_BODY
from hardcase_util import check_reported_failure, free_body_reference, rotation_angle

PI0 = np.array([20.0, 0.5, 0.2])
OMEGA = float(np.linalg.norm(PI0 / np.array([2.0, 1.0, 0.6666666666666666])))
REV = 2 * math.pi / OMEGA
HW = [0.1, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.1, 3.2, 4.0, 6.0]
GARBAGE = 0.1
ORDER = {"stormer-verlet": 2, "gauss2": 4}
SCHEMES = [("stormer-verlet", "cay", "truncated"), ("stormer-verlet", "exp", "truncated"),
           ("stormer-verlet", "skew", "truncated"), ("gauss2", "cay", "exact"),
           ("gauss2", "exp", "exact")]


def _run(integ, hw):
    h = hw / OMEGA
    steps = max(1, round(REV / h))
    try:
        tr = integ.simulate(g0=np.eye(3), mu0=PI0, h=h, steps=steps)
    except hpgen.ConvergenceError as err:
        return {"hw": hw, "steps": steps, "outcome": "raised", "error": err,
                "text": check_reported_failure(err, h)}
    if not (np.isfinite(tr.g).all() and np.isfinite(tr.mu).all()):
        return {"hw": hw, "steps": steps, "outcome": "GARBAGE", "text": "non-finite output"}
    R_ref, Pi_ref = free_body_reference(PI0, tr.t)
    e_pi = float(np.abs(tr.mu - Pi_ref).max() / np.linalg.norm(PI0))
    e_R = max(rotation_angle(a, b) for a, b in zip(R_ref, tr.g))
    err = max(e_pi, e_R)
    return {"hw": hw, "steps": steps, "outcome": "accurate" if err <= GARBAGE else "GARBAGE",
            "err": err, "text": f"attitude {e_R:.2e} rad, |dPi|/|Pi| {e_pi:.2e}"}


@pytest.mark.parametrize("tableau,tau,rkmk", SCHEMES, ids=["-".join(s) for s in SCHEMES])
def test_fast_spin_accurate_or_reported(compile_model, tableau, tau, rkmk):
    """Every run over one revolution is accurate (error <= 0.1) or raises a reported
    ConvergenceError / DomainError; never finite garbage without an error (module
    docstring)."""
    integ = compile_model(FREE_BODY, tableau=tableau, tau=tau, rkmk=rkmk)
    rows = [_run(integ, hw) for hw in HW]
    print(f"\n[fast spin] {tableau}/{tau}/{rkmk}, |omega0| = {OMEGA:.4f}, one revolution "
          f"T = {REV:.4f}")
    print(f"  {'h*omega':>7} {'steps':>5}  {'outcome':<9} details")
    assert rows[0]["outcome"] == "accurate"
    for r in rows[1:]:
        predicted = rows[0]["err"] * (r["hw"] / rows[0]["hw"]) ** ORDER[tableau]
        if r["outcome"] == "GARBAGE" and "err" in r and r["err"] <= 10 * predicted:
            r["outcome"], r["text"] = "coarse", r["text"] + f" (order predicts {predicted:.2e})"
    for r in rows:
        print(f"  {r['hw']:7.2f} {r['steps']:5d}  {r['outcome']:<9} {r['text']}")
    garbage = [(r["hw"], r["text"]) for r in rows if r["outcome"] == "GARBAGE"]
    limit = {"exp": math.pi, "skew": 0.5}.get(tau)
    if limit is not None:
        for r in rows:
            if r["hw"] > limit * 1.01 and r["hw"] >= 0.75:
                assert r["outcome"] == "raised" and isinstance(r["error"], hpgen.DomainError), r
                assert "domain" in str(r["error"])
    assert not garbage, (f"{tableau}/{tau}/{rkmk} returned garbage (error > {GARBAGE}) "
                         f"without raising at h*omega = {garbage}")
