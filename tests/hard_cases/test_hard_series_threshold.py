"""Hard case 3: xi exactly 0, and a tau argument exactly at s = |omega|^2 = S0 = 1.0, where
exp and dexp^{-1} used to switch from a Taylor polynomial to the closed form (hpgen/groups/
series.py is now branch-free: half-angle polynomials on the whole chart domain; the points
are kept so that any future switch there must stay continuous), on SO3 and SE3, with the C
and the Python backends.

Models (all tau = exp), chosen so that every place where the chart's series enter is hit:
- SO3 reduced:  free rigid body, stormer-verlet/exp/truncated (unknown Xi; tau argument
                h Xi: in the residual dexp^{-1}_{h Xi}, in the update exp(h Xi) and
                dexp^{-1}_{-h Xi});
- SO3 full:     heavy top, midpoint/exp/exact (unknowns Xi1, N1, mu1, Theta1, xi1; tau
                arguments h Theta1 (dexp^{-1}_{+-h Theta1}, and dexp^{-1}_{-chart} in the
                exact RKMK constraint, differentiated in the variations, so its s-derivative
                enters the residual) and h xi1);
- SE3 reduced:  underwater vehicle, midpoint/exp/truncated (h Xi, and h Xi / 2 in the
                margin);
- SE3 full:     tests/conftest.py SE3_BODY (potential in R and x), midpoint/exp/exact.

Placing s exactly on S0: h = 1 and the omega part of the argument a * u, u = (0.36, 0.48,
0.8), whose squares sum to exactly 1.0 in floating point in any order; "below" and "above"
are a = 1 -+ 2^-50 (s = 1 -+ 1.8e-15, a few ulps).

Pass criteria:
- every kernel output (residual, jacobian, update, margin) is finite at xi = 0 and at the
  three points around S0;
- continuity across S0: outputs at s = S0 - 1.8e-15, S0 and S0 + 1.8e-15 differ by at most
  1e-13 of their size (the inputs differ by 1e-15; the polynomials are accurate to 2^-54
  there, series.py) -- for the residual, the Jacobian and the update alike, since Newton uses the
  Jacobian and the exact RKMK residual contains the series' derivatives;
- reduced steps against an independent dexp^{-1} = phi_1(ad_x)^{-1} (scipy expm, no
  branch): residual, update to 1e-14 relative, Jacobian against the complex-step
  derivative of the independent residual to 1e-13 relative, at xi = 0 and around S0;
- the Jacobian at xi = 0 against central differences of the residual (1e-7 relative) and
  against the independent complex-step Jacobian (reduced, 1e-13);
- a step from rest (xi0 = 0): reduced: g1 = g0 and p1 = 0 exactly (the solution is Xi = 0);
  with a potential: within the scheme's local error of a DOP853 reference (bound below);
- the step map (Newton solution + update) is smooth across S0: h is tuned (Brent) so that
  the solution's rotation per step |h omega_{k+1}| is 1 (and, for the exact-RKMK models,
  2: the midpoint stage argument h Theta1 = h xi1 / 2 on S0); steps at h* (1 + j 1e-10),
  j = -3..3, have second differences below 1e-13 of the output's size, and C and Python
  agree to 1e-12.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import brentq

from conftest import EXAMPLES, FREE_BODY, HEAVY_TOP, SE3_BODY
from hardcase_util import dexp_inv, group_exp, rotation_angle
from reference import SE3Problem, SO3Problem, reference

U = np.array([0.36, 0.48, 0.8])
assert U[0] * U[0] + U[1] * U[1] + U[2] * U[2] == 1.0
BELOW, ABOVE = 1.0 - 2.0**-50, 1.0 + 2.0**-50

MODELS = {
    "SO3-reduced": (FREE_BODY, dict(tableau="stormer-verlet", tau="exp", rkmk="truncated")),
    "SO3-full": (HEAVY_TOP, dict(tableau="midpoint", tau="exp", rkmk="exact")),
    "SE3-reduced": (EXAMPLES / "underwater_vehicle.yaml",
                    dict(tableau="midpoint", tau="exp", rkmk="truncated")),
    "SE3-full": (SE3_BODY, dict(tableau="midpoint", tau="exp", rkmk="exact")),
}
#: the diagonal inertia of the reduced (left-invariant) models: mu = INERTIA * xi
INERTIA = {"SO3-reduced": np.array([2.0, 1.0, 0.6666666666666666]),
           "SE3-reduced": np.array([2.0, 1.0, 0.6666666666666666, 1.0, 1.5, 3.0])}
#: initial velocities for the step-continuity scan (|omega| ~ 1 to 3)
XI_SCAN = {"SO3-reduced": [0.5, 0.6, -0.6], "SO3-full": [2.0, 1.5, -1.0],
           "SE3-reduced": [0.15, 1.0, 0.3, 1.0, 0.0, 0.5 / 3],
           "SE3-full": [2.0, 1.5, -1.0, 0.5, 0.3, -0.2]}
BACKENDS = ("c", "python")
KERNEL_OUT = ("F", "J", "g1", "p1", "margin")


def _integ(compile_model, name, backend="c"):
    text, opts = MODELS[name]
    return compile_model(text, backend=backend, **opts)


def _state(integ, seed=11):
    """A generic (g, p): g off the identity (rotation and, on SE3, translation)."""
    rng = np.random.default_rng(seed)
    g = group_exp(rng.normal(size=integ.d) * 0.7)
    return g, rng.normal(size=integ.d)


def _kernels(integ, z, g, p, h):
    hv, gf = np.array([h]), g.ravel(order="F")
    F = integ.kernel("residual", z, gf, p, hv)[0]
    J = integ.kernel("jacobian", z, gf, p, hv)[0].reshape(integ.nz, integ.nz, order="F")
    g1, p1 = integ.kernel("update", z, gf, p, hv)
    m = integ.kernel("margin", z, hv)[0]
    return {"F": F, "J": J, "g1": g1, "p1": p1, "margin": m}


def _slots(integ):
    """{description: (block start, scale)}: where to write a * U so that a tau argument of
    the step (h = 1) has omega part exactly a * U."""
    blocks = {label: (start, stop) for label, start, stop in integ.meta["unknowns"]}
    out = {}
    if "Xi" in blocks:                              # reduced: xi_{k+1} = Xi
        out["h Xi (xi_k+1)"] = (blocks["Xi"][0], 1.0)
        if integ.meta["options"]["tableau"] == "midpoint":
            out["h Xi / 2 (stage)"] = (blocks["Xi"][0], 2.0)
    for label in ("Theta1", "xi1"):
        if label in blocks:
            out[f"h {label}"] = (blocks[label][0], 1.0)
    assert out, integ.meta["unknowns"]
    return out


def _z_on(integ, base, slot, a):
    start, scale = slot
    z = base.copy()
    z[start:start + 3] = (scale * a) * U
    return z


def _reduced_reference(name, z, g, p, h):
    """Independent F, J (complex step), g1, p1 of the reduced truncated step:
    F = p - (dexp^{-1}_{h Xi})^T I Xi, g1 = g exp(h Xi), p1 = (dexp^{-1}_{-h Xi})^T I Xi."""
    I = INERTIA[name]

    def F(X):
        return p - dexp_inv(h * X).T @ (I * X)
    d = len(z)
    J = np.zeros((d, d))
    for j in range(d):
        e = np.zeros(d, complex)
        e[j] = 1e-30j
        J[:, j] = F(z + e).imag / 1e-30
    n = g.shape[0]
    g1 = (g @ group_exp(h * z)).ravel(order="F")
    p1 = dexp_inv(-h * z).T @ (I * z)
    assert n in (3, 4)
    return {"F": F(z.astype(complex)).real, "J": J, "g1": g1, "p1": p1}


def _rel(a, b):
    scale = max(np.abs(a).max(), np.abs(b).max(), 1e-300)
    return float(np.abs(a - b).max() / scale)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", list(MODELS))
def test_kernels_at_xi_zero(compile_model, name, backend):
    """z = 0 (every velocity unknown exactly 0): all kernels finite; the Jacobian equals
    central differences of the residual (1e-7: O(eps^2) truncation + 1e-10 round-off);
    reduced steps equal the independent formulas (1e-14, J 1e-13)."""
    integ = _integ(compile_model, name, backend)
    g, p = _state(integ)
    z = np.zeros(integ.nz)
    for h in (0.1, 1.0):
        out = _kernels(integ, z, g, p, h)
        for k, v in out.items():
            assert np.isfinite(v).all(), (name, backend, h, k)
        # Jacobian against central differences of the residual
        eps = 1e-6
        Jfd = np.zeros_like(out["J"])
        for j in range(integ.nz):
            dz = np.zeros(integ.nz)
            dz[j] = eps
            Jfd[:, j] = (_kernels(integ, z + dz, g, p, h)["F"]
                         - _kernels(integ, z - dz, g, p, h)["F"]) / (2 * eps)
        e_fd = _rel(out["J"], Jfd)
        line = f"[xi = 0] {name} {backend} h={h}: J vs central differences {e_fd:.1e}"
        assert e_fd < 1e-7
        if name in INERTIA:
            ref = _reduced_reference(name, z, g, p, h)
            errs = {k: _rel(out[k], ref[k]) for k in ("F", "J", "g1", "p1")}
            line += ", vs independent: " + ", ".join(f"{k} {v:.1e}" for k, v in errs.items())
            assert max(errs["F"], errs["g1"], errs["p1"]) <= 1e-14 and errs["J"] <= 1e-13
        print("\n" + line, end="")


@pytest.mark.parametrize("name", list(MODELS))
def test_step_from_rest(compile_model, name):
    """Reduced: p0 = 0 is a fixed point (Xi = 0): g1 = g0, p1 = 0 exactly. Full models:
    10 steps of h = 0.01 from rest against DOP853 (rtol 1e-13): the schemes are order 2, the
    measured error is ~1e-7 (|p| ~ 0.01 after 10 steps); bound 1e-5 relative to the force
    scale (a wrong series value at xi = 0, e.g. NaN * 0 or a wrong constant term, shows up
    at O(h) = 1e-2)."""
    integ = _integ(compile_model, name)
    g0, _ = _state(integ)
    if name in INERTIA:
        g1, p1 = integ.step(g0, np.zeros(integ.d), 0.1)
        tr = integ.simulate(g0=g0, mu0=np.zeros(integ.d), h=0.1, steps=100)
        print(f"\n[rest] {name}: |g1 - g0| {np.abs(g1 - g0).max():.1e}, |p1| "
              f"{np.abs(p1).max():.1e}, 100 steps |g - g0| {np.abs(tr.g - g0).max():.1e}")
        assert np.array_equal(g1, g0) and not p1.any()
        assert np.array_equal(tr.g, np.broadcast_to(g0, tr.g.shape)) and not tr.mu.any()
        return
    h, steps = 0.01, 10
    tr = integ.simulate(g0=g0, xi0=np.zeros(integ.d), h=h, steps=steps)
    prob = (SO3Problem([1.0, 5.0, 6.0], Mg=1.0) if integ.d == 3 else
            SE3Problem([2.0, 1.0, 0.6666666666666666], [1.0, 1.5, 3.0], Mg=0.5, k=0.3))
    g_ref, p_ref = reference(prob, g0, np.zeros(integ.d), tr.t, rtol=1e-13)
    f0 = np.abs(prob.force(g0)).max()
    e_g, e_p = np.abs(tr.g - g_ref).max(), np.abs(tr.mu - p_ref).max() / f0
    print(f"\n[rest] {name}: {steps} steps of h={h} from xi = 0: |g - g_ref| {e_g:.2e}, "
          f"|p - p_ref| / |f| {e_p:.2e} (|p(T)| / |f| {np.abs(p_ref[-1]).max() / f0:.2e})")
    assert np.isfinite(tr.g).all() and np.isfinite(tr.mu).all()
    assert e_g < 1e-5 and e_p < 1e-5


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", list(MODELS))
def test_kernels_continuous_across_threshold(compile_model, name, backend):
    """Each tau argument put at s = S0 -+ 1.8e-15 and S0 exactly: kernels finite, and
    residual, Jacobian, update and margin continuous to 1e-13 relative (the inputs move by
    ~1e-15; the branches agree to 2^-54 by construction)."""
    integ = _integ(compile_model, name, backend)
    g, p = _state(integ)
    base = 0.3 * np.random.default_rng(5).normal(size=integ.nz)
    failures = []
    for slot_name, slot in _slots(integ).items():
        outs = {lab: _kernels(integ, _z_on(integ, base, slot, a), g, p, 1.0)
                for lab, a in (("below", BELOW), ("at", 1.0), ("above", ABOVE))}
        for lab, out in outs.items():
            for k, v in out.items():
                assert np.isfinite(v).all(), (name, backend, slot_name, lab, k)
        cells = []
        for k in KERNEL_OUT:
            jl = _rel(outs["at"][k], outs["below"][k])
            ja = _rel(outs["above"][k], outs["at"][k])
            jba = _rel(outs["above"][k], outs["below"][k])
            cells.append(f"{k} {jl:.1e}/{ja:.1e}/{jba:.1e}")
            if max(jl, ja) > 1e-13:
                failures.append(f"{slot_name}: {k} jumps by {max(jl, ja):.2e} (relative) at "
                                f"s = S0 exactly (below vs above: {jba:.1e})")
        print(f"\n[threshold] {name} {backend} {slot_name}: jump below->at / at->above / "
              f"below->above: " + "; ".join(cells), end="")
    assert not failures, f"{name} ({backend}): " + " | ".join(failures)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("name", list(INERTIA))
def test_reduced_kernels_match_independent_dexpinv_at_threshold(compile_model, name, backend):
    """Reduced steps around S0 against dexp^{-1} = phi_1(ad)^{-1} from scipy's expm (no
    branch): residual and update to 1e-14, Jacobian (complex step) to 1e-13 relative."""
    integ = _integ(compile_model, name, backend)
    g, p = _state(integ)
    base = 0.3 * np.random.default_rng(5).normal(size=integ.nz)
    worst = {}
    for slot_name, slot in _slots(integ).items():
        for lab, a in (("below", BELOW), ("at", 1.0), ("above", ABOVE)):
            z = _z_on(integ, base, slot, a)
            out, ref = _kernels(integ, z, g, p, 1.0), _reduced_reference(name, z, g, p, 1.0)
            errs = {k: _rel(out[k], ref[k]) for k in ("F", "J", "g1", "p1")}
            print(f"\n[threshold vs independent] {name} {backend} {slot_name} {lab}: "
                  + ", ".join(f"{k} {v:.1e}" for k, v in errs.items()), end="")
            for k, v in errs.items():
                worst[(slot_name, lab, k)] = v
    bad = {k: v for k, v in worst.items() if v > (1e-13 if k[2] == "J" else 1e-14)}
    assert not bad, f"{name} ({backend}) differs from the independent dexp^-1: {bad}"


@pytest.mark.parametrize("name", list(MODELS))
def test_step_smooth_across_threshold(compile_model, name):
    """Full steps (Newton + update) whose solution crosses S0: second differences in h
    below 1e-13 (round-off; a branch mismatch would show as a kink), C = Python to 1e-12."""
    c, py = _integ(compile_model, name, "c"), _integ(compile_model, name, "python")
    g0, _ = _state(c)
    xi0 = np.array(XI_SCAN[name], float)
    p0 = c.legendre(g0, xi0)
    w = np.linalg.norm(xi0[:3])

    def angle(h):
        g1, _ = c.step(g0, p0, h)
        return rotation_angle(g0[:3, :3], g1[:3, :3])
    # reduced truncated steps: the stage argument h Xi / 2 enters the margin only
    for target in ((1.0,) if name in INERTIA else (1.0, 2.0)):
        hstar = brentq(lambda h: angle(h) - target, 0.75 * target / w, 1.3 * target / w,
                       xtol=1e-15, rtol=1e-15)
        js = np.arange(-3, 4)
        hs = hstar * (1.0 + 1e-10 * js)
        rows = {}
        for lab, integ in (("c", c), ("python", py)):
            outs = [np.concatenate([a.ravel() for a in integ.step(g0, p0, h)]) for h in hs]
            rows[lab] = np.array(outs)
        scale = np.abs(rows["c"]).max()
        second = np.abs(rows["c"][2:] - 2 * rows["c"][1:-1] + rows["c"][:-2]).max() / scale
        first = np.abs(np.diff(rows["c"], axis=0)).max() / scale
        cvp = np.abs(rows["c"] - rows["python"]).max() / scale
        print(f"\n[step across S0] {name}: |h omega_k+1| = {target} at h* = {hstar:.15g}; "
              f"steps at h*(1 + j 1e-10), j = -3..3: first differences {first:.1e}, second "
              f"differences {second:.1e}, C vs Python {cvp:.1e}", end="")
        assert np.isfinite(rows["c"]).all() and np.isfinite(rows["python"]).all()
        assert second < 1e-13 and cvp < 1e-12
