"""Integrator.linearize on open modules (issue 12 item 1; hpgen.runtime.linearize).

- (A, B) = linearize(traj, u=U): A[k] = d(eta_{k+1}, dp_{k+1}) / d(eta_k, dp_k) and
  B[k] = d(eta_{k+1}, dp_{k+1}) / d u_k, and P = linearize(traj, u=U, wrt="params") =
  d(eta_{k+1}, dp_{k+1}) / d params, against central differences of ``step`` (state on the
  module's chart; u_k and params entries, eps = 1e-5) to 1e-7 relative, on SO3 (a spacecraft
  with body torques u and a runtime damping c), SE3 (a vehicle with a thrust input) and
  SO3 x SO3 (a coupled pair, an internal torque u and damping c), C and Python backends;
  B and P against CasADi's AD of casadi_step composed by the implicit function theorem to
  1e-12. Difference error as in test_linearize: truncation eps^2 |d^3 step|
  ~ 1e-10, round-off (Newton tolerance 1e-14 + ulp) / eps ~ 1e-9.
- C and Python agree to round-off (1e-13 relative).
- With zero forces (u = 0, c = 0) A is symplectic: A^T Omega(p_{k+1}) A = Omega(p_k) to 1e-12
  (hpgen check's form, hpgen.analysis.symplectic).
- Bad input: u missing, wrong shapes, wrt, another run's inputs: one-line ArgumentError.
"""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.analysis.rkmk import chart_jacobian
from hpgen.analysis.symplectic import ad_matrices, omega_matrix, symplectic_defect
from hpgen.errors import ArgumentError
from hpgen.model import load_model_text

from test_derive_forces import VEHICLE
from test_linearize import _tau

SPACECRAFT = """\
name: damped_spacecraft
group: SO3
parameters: {I: [1.0, 2.0, 3.0], c: 0.1}
runtime_parameters: [c]
inputs: [u0, u1, u2]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)
forces: ["u0 - c*xi[0]", "u1 - c*xi[1]*R[2, 2]", "u2 - c*xi[2]"]
"""
PAIR = """\
name: coupled_pair
group: [SO3, SO3]
parameters: {I0: [1.0, 2.0, 3.0], I1: [0.5, 0.7, 0.9], k: 2.0, c: 0.1}
runtime_parameters: [c]
inputs: [u]
lagrangian: >-
  0.5*(I0[0]*xi_0[0]**2 + I0[1]*xi_0[1]**2 + I0[2]*xi_0[2]**2)
  + 0.5*(I1[0]*xi_1[0]**2 + I1[1]*xi_1[1]**2 + I1[2]*xi_1[2]**2)
  + k*(R_0[2,0]*R_1[2,0] + R_0[2,1]*R_1[2,1] + R_0[2,2]*R_1[2,2])
forces: ["u - c*xi_0[0]", "0", "0", "-u", "0", "-c*xi_1[2]"]
"""
CASES = {"spacecraft": SPACECRAFT, "vehicle": VEHICLE, "pair": PAIR}
STEPS, H = 5, 0.05
_SETUP = {}


def _setup(name, backend, compile_model):
    """(model, integ, traj, U) of a short run with varying inputs."""
    key = (name, backend)
    if key not in _SETUP:
        model = load_model_text(CASES[name])
        integ = compile_model(CASES[name], tableau="gauss2", tau="cay", rkmk="exact",
                              backend=backend)
        m, d = len(model.inputs), model.group.d
        U = 0.3 * np.random.default_rng(1).standard_normal((STEPS, m))
        traj = integ.simulate(np.eye(model.group.n), H, STEPS, xi0=np.linspace(0.2, 0.7, d),
                              u=U, t0=0.5)
        _SETUP[key] = model, integ, traj, U
    return _SETUP[key]


def _fd(integ, model, traj, U, k, wrt, eps=1e-5):
    """Central differences of step k (start t_k) in the state (chart), u_k or params."""
    group, d = model.group, model.group.d
    tau = _tau(group, integ.meta["options"]["tau"])
    g, p, t, u = traj.g[k], traj.mu[k], traj.t[k], U[k]
    c = dict(zip(integ.open["runtime_parameters"] and ["c"], integ.open["defaults"]))
    g1, _ = integ.step(g, p, H, u=u, t=t)
    width = {"state": 2 * d, "u": len(u), "params": len(c)}[wrt]
    dG, dP = [], []
    for i in range(width):
        outs = []
        for s in (eps, -eps):
            if wrt == "state":
                e = np.zeros(2 * d)
                e[i] = s
                outs.append(integ.step(g @ tau(e[:d]), p + e[d:], H, u=u, t=t))
            elif wrt == "u":
                outs.append(integ.step(g, p, H, u=u + s * np.eye(len(u))[i], t=t))
            else:
                outs.append(integ.step(g, p, H, u=u, t=t, params={"c": c["c"] + s}))
        (ga, pa), (gb, pb) = outs
        dG.append((ga - gb).ravel(order="F") / (2 * eps))
        dP.append((pa - pb) / (2 * eps))
    return chart_jacobian(group, g1, np.array(dG).T, np.array(dP).T)


def _rel(a, b):
    return np.abs(a - b).max() / np.abs(b).max()


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("name", list(CASES))
def test_open_linearize_matches_central_differences(compile_model, name, backend):
    model, integ, traj, U = _setup(name, backend, compile_model)
    d, m = model.group.d, len(model.inputs)
    A, B = integ.linearize(traj, u=U)
    assert A.shape == (STEPS, 2 * d, 2 * d) and B.shape == (STEPS, 2 * d, m)
    P = integ.linearize(traj, u=U, wrt="params") if integ.open["defaults"] else None
    for k in (0, STEPS - 1):
        assert _rel(A[k], _fd(integ, model, traj, U, k, "state")) < 1e-7, (name, k)
        assert _rel(B[k], _fd(integ, model, traj, U, k, "u")) < 1e-7, (name, k)
        if P is not None:
            assert P.shape == (STEPS, 2 * d, 1)
            assert _rel(P[k], _fd(integ, model, traj, U, k, "params")) < 1e-7, (name, k)


@pytest.mark.parametrize("name", list(CASES))
def test_open_backends_agree(compile_model, name):
    _, ic, traj, U = _setup(name, "c", compile_model)
    _, ip, _, _ = _setup(name, "python", compile_model)
    for (a, b) in zip(ic.linearize(traj, u=U), ip.linearize(traj, u=U)):
        assert np.abs(a - b).max() <= 1e-13 * np.abs(a).max()


def test_unforced_open_step_is_symplectic(compile_model):
    """u = 0 and c = 0: the forced step is the conservative one, A preserves Omega."""
    model = load_model_text(SPACECRAFT)
    integ = compile_model(SPACECRAFT, tableau="gauss2", tau="cay", rkmk="exact")
    U, zero = np.zeros((8, 3)), {"c": 0.0}
    traj = integ.simulate(np.eye(3), 0.1, 8, xi0=[0.3, -1.0, 2.0], u=U, params=zero)
    A, B = integ.linearize(traj, u=U, params=zero)
    ad = ad_matrices(model.group)
    for k in range(len(A)):
        _, rel = symplectic_defect(A[k], omega_matrix(ad, traj.mu[k]),
                                   omega_matrix(ad, traj.mu[k + 1]))
        assert rel <= 1e-12, (k, rel)
    # and damping breaks it (the test can fail)
    traj = integ.simulate(np.eye(3), 0.1, 8, xi0=[0.3, -1.0, 2.0], u=U, params={"c": 0.5})
    A, _ = integ.linearize(traj, u=U, params={"c": 0.5})
    _, rel = symplectic_defect(A[0], omega_matrix(ad, traj.mu[0]), omega_matrix(ad, traj.mu[1]))
    assert rel > 1e-3


def test_open_bad_input(compile_model):
    _, integ, traj, U = _setup("spacecraft", "python", compile_model)

    def msg(field, **kw):
        with pytest.raises(ArgumentError) as e:
            integ.linearize(traj, **kw)
        assert "\n" not in str(e.value) and e.value.field == field, str(e.value)
        return str(e.value)

    assert "u is required" in msg("u")
    assert "shape" in msg("u", u=U[:, :2])
    assert "shape" in msg("u", u=U[:-1])
    assert "wrt" in msg("wrt", u=U, wrt="x")
    assert "unknown runtime parameter" in msg("params", u=U, params={"k": 1.0})
    assert "not this module's step" in msg("traj", u=U + 0.1)      # other inputs than the run's
    assert "not this module's step" in msg("traj", u=U, params={"c": 0.2})
    _, vehicle, _, _ = _setup("vehicle", "python", compile_model)
    with pytest.raises(ArgumentError) as e:
        vehicle.linearize(traj, u=U[:, :1])
    assert "damped_spacecraft" in str(e.value) and e.value.field == "traj"
    with pytest.raises(ArgumentError) as e:
        vehicle.linearize(_setup("vehicle", "python", compile_model)[2], u=[0.1],
                          wrt="params")
    assert "no runtime parameters" in str(e.value)


@pytest.mark.parametrize("name", list(CASES))
def test_open_casadi_step_reproduces_step(compile_model, name):
    """casadi_step (g, p, u, params, h, z, t) -> (F, g1, p1): solving F = 0 by CasADi's
    Newton and applying the update gives the module's step from the same record (Newton
    tolerances 1e-14: agreement to 1e-12)."""
    import casadi as ca
    _, integ, traj, U = _setup(name, "c", compile_model)
    f = integ.casadi_step()
    assert f.name_in() == ["g", "p", "u", "params", "h", "z", "t"]
    assert f.name_out() == ["F", "g1", "p1"]
    k = 2
    g, p, t = traj.g[k], traj.mu[k], traj.t[k]
    params = integ.open["defaults"]
    Z = ca.SX.sym("z", integ.nz)
    F = f(g, p, U[k], params, H, Z, t)[0]
    r = ca.Function("r", [Z], [F, ca.jacobian(F, Z)])
    z = np.zeros(integ.nz)
    for _ in range(12):             # Newton by CasADi's AD (converged after ~5)
        Fz, Jz = (np.array(a) for a in r(z))
        z = z - np.linalg.solve(Jz, Fz.ravel())
    F, g1, p1 = f(g, p, U[k], params, H, z, t)
    assert np.abs(np.array(F)).max() < 1e-13
    assert np.abs(np.array(g1) - traj.g[k + 1]).max() < 1e-12
    assert np.abs(np.array(p1).ravel() - traj.mu[k + 1]).max() < 1e-12


def test_open_linearize_matches_casadi_ad(compile_model):
    """B and P against CasADi's AD of casadi_step's residual and update (ambient g1),
    composed by the implicit function theorem here, to 1e-12 (round-off times cond(J))."""
    import casadi as ca
    model, integ, traj, U = _setup("spacecraft", "c", compile_model)
    A, B = integ.linearize(traj, u=U)
    P = integ.linearize(traj, u=U, wrt="params")
    f = integ.casadi_step()
    Z, Uu, Q = ca.SX.sym("z", integ.nz), ca.SX.sym("u", 3), ca.SX.sym("q", 1)
    for k in (0, STEPS - 1):
        F, g1, p1 = f(traj.g[k], traj.mu[k], Uu, Q, H, Z, traj.t[k])
        Y = ca.vertcat(ca.reshape(g1, -1, 1), p1)
        jac = ca.Function("j", [Z, Uu, Q], [F, ca.jacobian(F, Z), ca.jacobian(F, Uu),
                                            ca.jacobian(F, Q), ca.jacobian(Y, Z),
                                            ca.jacobian(Y, Uu), ca.jacobian(Y, Q), g1])
        z = np.zeros(integ.nz)
        for _ in range(12):
            Fz, Jz = (np.array(a) for a in jac(z, U[k], integ.open["defaults"])[:2])
            z = z - np.linalg.solve(Jz, Fz.ravel())
        _, J, Fu, Fq, Yz, Yu, Yq, g1v = (np.array(a) for a in
                                         jac(z, U[k], integ.open["defaults"]))
        for got, Fx, Yx in ((B[k], Fu, Yu), (P[k], Fq, Yq)):
            dY = Yx - Yz @ np.linalg.solve(J, Fx)
            ref = chart_jacobian(model.group, g1v, dY[:9], dY[9:])
            assert np.abs(ref - got).max() <= 1e-12 * np.abs(got).max(), k
