"""Holonomic constraints (RATTLE-type Stormer-Verlet, docs/numerics.md "Holonomic
constraints") on the double spherical pendulum of tests/models/double_spherical_pendulum.yaml:
two links on [SE3, SE3], a ball joint pinning link 0 to the world origin and one between
the links, gravity -e3.

- phi(g_k) and the hidden constraint Phi(g_k) xi_k at every node to round-off: every step
  solves phi(g_(k+1)) = 0 and Phi xi = 0 by Newton to 1e-14 relative, and the rows are sums
  of O(1) products (|x| <= 1), so 1e-14 leaves a margin of ~10 ulps of accumulated rounding.
- the vertical spatial angular momentum e3 . sum_i (R_i pi_i + x_i x R_i P_i): l and phi are
  invariant under rotations about e3 through the origin, so the discrete Noether theorem
  keeps it to round-off (1e-12 relative to |p| over 10^4 steps, as the unconstrained tests).
- energy: bounded, no drift over 10^5 steps (symplectic on the constraint manifold).
- order 2 (2.0 +- 0.2) against an independent reference (hpgen.bench.multibody.reference:
  Newton-Euler in reduced coordinates with the joint forces at the acceleration level,
  DOP853 at rtol = atol = 1e-13).
- the multipliers (hpgen.analysis.reactions): lambda_K + nu_K approximates the continuous
  multiplier, minus the joints' reaction forces of the reference, to O(h^2).
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain, reference
from hpgen.groups.elements import rotation_from_rotvec as rotvec

MODEL = ROOT / "tests" / "models" / "double_spherical_pendulum.yaml"
J = np.array([1 / 48, 1 / 48, 0.002])
TOP, BOT = np.array([0.0, 0.0, 0.25]), np.array([0.0, 0.0, -0.25])
CHAIN = chain.ChainSpec(2, mass=1.0, length=0.5, g=9.81, moments=tuple(J))   # top, bot = +-a


def _admissible(spec, Rs, ws):
    """(x_i, v_i) (v_i body frame) putting links with rotations Rs and body angular
    velocities ws on the joints and their velocity form."""
    s = chain.from_rotations(spec, np.array(Rs), np.array(ws))
    return s.x, [R.T @ v for R, v in zip(s.R, s.v)]


def _initial():
    """An admissible, generic state: both links tilted and spinning."""
    Rs = [rotvec([0.6, -0.3, 0.2]), rotvec([-0.4, 0.8, 0.5])]
    ws = [np.array([1.0, -0.5, 2.0]), np.array([-1.5, 0.7, -1.0])]
    xs, vs = _admissible(CHAIN, Rs, ws)
    g0 = np.eye(8)
    g0[:3, :3], g0[:3, 3], g0[4:7, 4:7], g0[4:7, 7] = Rs[0], xs[0], Rs[1], xs[1]
    return Rs, ws, g0, np.concatenate([ws[0], vs[0], ws[1], vs[1]])


def _split(G):
    return G[:, :3, :3], G[:, :3, 3], G[:, 4:7, 4:7], G[:, 4:7, 7]


def _rv(R, v):
    return np.einsum("kij,kj->ki", R, v)


def constraint_residuals(G, P):
    """(max |phi(g_k)|, max |Phi(g_k) xi_k|) over the nodes; xi from p (l quadratic)."""
    R0, x0, R1, x1 = _split(G)
    phi = np.concatenate([x0 + _rv(R0, np.broadcast_to(TOP, x0.shape)),
                          x1 + _rv(R1, np.broadcast_to(TOP, x1.shape)) - x0
                          - _rv(R0, np.broadcast_to(BOT, x0.shape))], axis=1)
    w0, v0, w1, v1 = P[:, 0:3] / J, P[:, 3:6], P[:, 6:9] / J, P[:, 9:12]
    hidden = np.concatenate([_rv(R0, v0 + np.cross(w0, TOP)),
                             _rv(R1, v1 + np.cross(w1, TOP)) - _rv(R0, v0 + np.cross(w0, BOT))],
                            axis=1)
    return np.abs(phi).max(), np.abs(hidden).max()


def vertical_momentum(G, P):
    R0, x0, R1, x1 = _split(G)
    out = np.zeros(len(G))
    for R, x, p in ((R0, x0, P[:, 0:6]), (R1, x1, P[:, 6:12])):
        RP = _rv(R, p[:, 3:])
        out += (_rv(R, p[:, :3]) + np.cross(x, RP))[:, 2]
    return out


@pytest.mark.parametrize("backend", ["c", "python"])
def test_constraints_momentum_at_round_off(compile_model, backend):
    integ = compile_model(MODEL, backend=backend)
    _, _, g0, xi0 = _initial()
    steps = 10_000 if backend == "c" else 1000
    tr = integ.simulate(g0=g0, xi0=xi0, h=0.005, steps=steps, every=1)
    phi, hidden = constraint_residuals(tr.g, tr.mu)
    L = vertical_momentum(tr.g, tr.mu)
    drift = np.abs(L - L[0]).max() / np.abs(tr.mu).max()
    print(f"{backend}: |phi| {phi:.2e}, |Phi xi| {hidden:.2e}, e3.L drift {drift:.2e} "
          f"(e3.L = {L[0]:.3f})")
    assert phi < 1e-14
    assert hidden < 1e-13
    assert drift < 1e-12


@pytest.mark.slow
def test_constrained_energy_bounded_without_drift(compile_model):
    """10^5 steps at h = 0.01 (T = 1000, chaotic motion). Criterion as for the heavy top
    (tests/property/test_conservation.py): the envelope of the last tenth within 1.5x of the
    first tenth's, and a linear fit's slope times T below the oscillation size."""
    integ = compile_model(MODEL)
    _, _, g0, xi0 = _initial()
    tr = integ.simulate(g0=g0, xi0=xi0, h=0.01, steps=100_000, every=10)
    err = tr.energy() - tr.energy()[0]
    tenth = len(err) // 10
    first, last = np.abs(err[:tenth]).max(), np.abs(err[-tenth:]).max()
    slope = np.polyfit(tr.t, err, 1)[0]
    phi, hidden = constraint_residuals(tr.g, tr.mu)
    print(f"energy {tr.energy()[0]:.4f}: max error first tenth {first:.3e}, last tenth "
          f"{last:.3e}, slope*T {slope * tr.t[-1]:.3e}; |phi| {phi:.2e}, |Phi xi| {hidden:.2e}")
    assert last < 1.5 * first
    assert abs(slope) * tr.t[-1] < first
    assert phi < 1e-14 and hidden < 1e-13


def _reference_state(ref):
    Rr, wr, xr, ur = ref.R, ref.omega, ref.x, ref.v
    g = np.eye(8)
    g[:3, :3], g[:3, 3], g[4:7, 4:7], g[4:7, 7] = Rr[0], xr[0], Rr[1], xr[1]
    p = np.concatenate([J * wr[0], Rr[0].T @ ur[0], J * wr[1], Rr[1].T @ ur[1]])
    return g, p


@pytest.fixture(scope="module")
def reference_at_1():
    """The reference's ChainState at t = 1 from _initial()'s state."""
    Rs, ws, _, _ = _initial()
    qpos, qvel = chain.to_joint(CHAIN, chain.from_rotations(CHAIN, np.array(Rs), np.array(ws)))
    return reference.solve(CHAIN, qpos, qvel, [1.0]).final


@pytest.mark.slow
def test_constrained_sv_order_two(compile_model, reference_at_1):
    integ = compile_model(MODEL)
    _, _, g0, xi0 = _initial()
    gr, pr = _reference_state(reference_at_1)
    errs = []
    for h in (0.02, 0.01, 0.005):
        steps = int(round(1.0 / h))
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=steps, every=steps)
        errs.append(max(np.abs(tr.g[-1] - gr).max(), np.abs(tr.mu[-1] - pr).max()))
    rates = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    print("errors", errs, "rates", rates)
    assert np.all(np.abs(rates - 2.0) < 0.2)


@pytest.mark.slow
def test_multipliers_are_the_joint_reactions(compile_model, reference_at_1):
    from hpgen.analysis.reactions import reactions
    integ = compile_model(MODEL)
    _, _, g0, xi0 = _initial()
    ref = reference_at_1                            # joint forces on the child links at T = 1
    f = np.concatenate(reference.ChainDynamics(CHAIN).accelerations(ref.R, ref.omega)[2])
    errs = []
    for h in (0.01, 0.005):
        K = int(round(1.0 / h))
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=K + 1, every=1)
        lam, nu = reactions(integ, tr.g[K - 1:K + 1], tr.mu[K - 1:K + 1], h)
        errs.append(np.abs(lam[1] + nu[0] + f).max())      # lambda_K + nu_K = -f(T)
    rate = np.log2(errs[0] / errs[1])
    print(f"|lambda + nu + f| {errs}, rate {rate:.2f}, |f| {np.abs(f).max():.2f}")
    assert errs[1] < 1e-3 * np.abs(f).max()
    assert abs(rate - 2.0) < 0.2


FORCED_PENDULUM = """
name: pend_forced
group: SE3
parameters: {m: 1.0, J: [0.02, 0.02, 0.002], grav: 9.81, top: [0.0, 0.0, 0.25], c: 0.05}
runtime_parameters: [grav]
inputs: [u]
lagrangian: 0.5*(J[0]*xi[0]**2 + J[1]*xi[1]**2 + J[2]*xi[2]**2) + 0.5*m*(xi[3]**2 + xi[4]**2 + xi[5]**2) - m*grav*x[2]
forces: ["-c*xi[0]", "-c*xi[1]", "u", "0", "0", "0"]
constraints:
  - x + dot(R, top)
"""


def test_forced_open_model_keeps_the_constraint(compile_model):
    """Forces, a control input and a runtime parameter on a constrained model: the pin holds
    to round-off with and without the input; with the damping torque only (u = 0) the energy
    decreases monotonically."""
    integ = compile_model(FORCED_PENDULUM, backend="python")
    one = chain.ChainSpec(1, mass=1.0, length=0.5, g=9.81, moments=(0.02, 0.02, 0.002))
    R, w = rotvec([0.5, 0.2, 0.0]), np.array([1.0, 2.0, 0.5])
    xs, vs = _admissible(one, [R], [w])
    g0 = np.eye(4)
    g0[:3, :3], g0[:3, 3] = R, xs[0]
    xi0 = np.concatenate([w, vs[0]])
    for u in (0.0, 0.002):
        tr = integ.simulate(g0=g0, xi0=xi0, h=0.01, steps=500, u=[u], params={"grav": 5.0})
        phi = tr.g[:, :3, 3] + tr.g[:, :3, :3] @ TOP
        E = tr.energy()
        print(f"u = {u}: |phi| {np.abs(phi).max():.2e}, E {E[0]:.4f} -> {E[-1]:.4f}")
        assert np.abs(phi).max() < 1e-14
        if u == 0.0:
            assert np.all(np.diff(E[::50]) < 0)


@pytest.mark.slow
def test_yoshida_composition_of_constrained_sv_is_order_four(compile_model, reference_at_1):
    """Constrained SV is symmetric (step(h) then step(-h) is the identity to round-off), so
    the triple jump w1 h, w0 h, w1 h of its steps is order 4 on the constraint manifold."""
    integ = compile_model(MODEL)
    _, _, g0, xi0 = _initial()
    p0 = np.asarray(integ.kernel("legendre", g0.ravel(order="F"), xi0)[0])
    g1, p1 = integ.step(g0, p0, 0.05)
    g2, p2 = integ.step(g1, p1, -0.05)
    assert max(np.abs(g2 - g0).max(), np.abs(p2 - p0).max()) < 1e-14
    gr, pr = _reference_state(reference_at_1)
    w1 = 1 / (2 - 2 ** (1 / 3))
    errs = []
    for h in (0.02, 0.01, 0.005):
        g, p = g0, p0
        for _ in range(round(1.0 / h)):
            for w in (w1, 1 - 2 * w1, w1):
                g, p = integ.step(g, p, w * h)
        errs.append(max(np.abs(g - gr).max(), np.abs(p - pr).max()))
        phi, hidden = constraint_residuals(g[None], p[None])
        assert phi < 1e-14 and hidden < 1e-13
    rates = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    print("triple jump errors", errs, "rates", rates)
    assert abs(rates[-1] - 4.0) < 0.2 and rates[0] > 3.5


def _manifold_jacobian(model, g, p):
    """D(phi, Phi xi)(g, p) (2m x 2d) in the left-trivialized chart (g (I + delta^), p + dp),
    by CasADi AD; xi = H^-1 p with H = diag(J, m, m, m, J, m, m, m) (l quadratic, b = 0)."""
    import casadi as ca
    from hpgen.derive.constraints import body_jacobian, constraint_function
    group, d = model.group, model.group.d
    phi = constraint_function(model)
    delta, dp = ca.SX.sym("delta", d), ca.SX.sym("dp", d)
    G = ca.mtimes(ca.DM(g), ca.SX.eye(group.n) + group.hat(delta))
    Hinv = 1.0 / np.concatenate([J, np.ones(3), J, np.ones(3)])
    C = ca.vertcat(phi(G), ca.mtimes(body_jacobian(group, phi, G), ca.DM(Hinv) * (ca.DM(p) + dp)))
    s = ca.vertcat(delta, dp)
    D = ca.Function("D", [s], [ca.jacobian(C, s)])(np.zeros(2 * d))
    return np.array(D, dtype=float)


def test_step_is_symplectic_on_the_constraint_manifold(compile_model):
    """The linearized step A (integ.linearize) preserves the canonical form on tangent vectors
    of the constraint manifold {phi = 0, Phi xi = 0} (a basis T of the null space of its
    2m x 2d Jacobian): T^T (A^T Omega(p1) A - Omega(p0)) T = 0 to round-off.
    Off the manifold the map is not symplectic (RATTLE's projection): the full defect is O(1)."""
    from scipy.linalg import null_space
    from hpgen.analysis.symplectic import ad_matrices, omega_matrix
    from hpgen.model import load_model
    model = load_model(MODEL)
    integ = compile_model(MODEL)
    _, _, g0, xi0 = _initial()
    tr = integ.simulate(g0=g0, xi0=xi0, h=0.01, steps=20, every=1)
    A = integ.linearize(tr)
    ad = ad_matrices(model.group)
    worst, full = 0.0, 0.0
    for k in (0, 7, 19):
        T = null_space(_manifold_jacobian(model, tr.g[k], tr.mu[k]))
        assert T.shape[1] == 2 * (12 - 6)
        E = A[k].T @ omega_matrix(ad, tr.mu[k + 1]) @ A[k] - omega_matrix(ad, tr.mu[k])
        scale = np.linalg.norm(A[k], 2) ** 2 * np.linalg.norm(omega_matrix(ad, tr.mu[k + 1]), 2)
        worst = max(worst, np.abs(T.T @ E @ T).max() / scale)
        full = max(full, np.abs(E).max() / scale)
    print(f"symplectic defect on the manifold {worst:.2e}, on all of T*G {full:.2e}")
    assert worst < 1e-13
    assert full > 1e-6
