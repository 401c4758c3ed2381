"""Integrator.linearize (hpgen.runtime.linearize) and Integrator.casadi_step (issue 12).

- A[k] = d(eta_{k+1}, dp_{k+1}) / d(eta_k, dp_k) agrees with central differences of ``step``
  on the module's chart (g tau(eps e_i), p + eps e_i; outputs projected at g_{k+1}) to 1e-7
  relative, C and Python backends, on SO3 (heavy top), SE3 (underwater vehicle) and
  SO3 x SO3 (double body chain). Difference error: truncation eps^2 |d^3 step| ~ 1e-10 and
  round-off ~ (Newton tolerance 1e-14 + ulp) / eps ~ 1e-9 at eps = 1e-5.
- A agrees with CasADi's own AD of the residual and update (ambient coordinates, built here),
  composed by the implicit function theorem written out here, to 1e-12 (round-off times
  cond(J) ~ 10-100).
- The schemes are conservative (variational): A^T Omega(p_{k+1}) A = Omega(p_k), with the
  canonical form ``hpgen check`` uses, relative defect <= 1e-12 (hpgen check's round-off
  model: |A|^2 |Omega| ulp times the Newton/solve amplification).
- Bad input: another module's trajectory, wrong shapes, every != 1, records that are not
  this module's steps: one-line ArgumentError (field traj).
- casadi_step reproduces ``step``; a closed module takes no u, params, wrt. (linearize on the runtime path alone:
  tests/unit/test_runtime.py::test_generated_package_runs_without_compile_time_stack.)
"""
from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.analysis.rkmk import chart_jacobian
from hpgen.analysis.symplectic import StepSensitivity, ad_matrices, omega_matrix, \
    symplectic_defect
from hpgen.derive import derive
from hpgen.errors import ArgumentError
from hpgen.model import load_model
from hpgen.runtime.trajectory import Trajectory
from hpgen.tableaus import get_tableau

CASES = {  # example: steps simulated
    "heavy_top": 6,            # SO3, gauss2 exp exact
    "underwater_vehicle": 6,   # SE3, gauss2 cay exact
    "double_body_chain": 6,    # SO3 x SO3, stormer-verlet cay truncated
}
_SETUP = {}


def _setup(name, backend, compile_model):
    """(model, integ, traj) of an example from its scene's initial state and h."""
    key = (name, backend)
    if key not in _SETUP:
        path = EXAMPLES / f"{name}.yaml"
        model = load_model(path)
        integ = compile_model(path, backend=backend)
        sc = model.scene
        traj = integ.simulate(np.array(sc.g0), sc.h, CASES[name], xi0=sc.xi0, mu0=sc.mu0)
        _SETUP[key] = model, integ, traj
    return _SETUP[key]


def _tau(group, kind):
    x = ca.SX.sym("x", group.d)
    f = ca.Function("tau", [x], [group.tau(kind, x)])
    return lambda v: np.array(f(v))


def _fd(integ, model, g, p, h, eps=1e-5):
    """Central differences of step on the module's chart, outputs at the nominal g1."""
    group, d = model.group, model.group.d
    tau = _tau(group, integ.meta["options"]["tau"])
    g1, _ = integ.step(g, p, h)
    dG, dP = [], []
    for i in range(2 * d):
        e = np.zeros(2 * d)
        e[i] = eps
        (ga, pa), (gb, pb) = [integ.step(g @ tau(s * e[:d]), p + s * e[d:], h)
                              for s in (1.0, -1.0)]
        dG.append((ga - gb).ravel(order="F") / (2 * eps))
        dP.append((pa - pb) / (2 * eps))
    return chart_jacobian(group, g1, np.array(dG).T, np.array(dP).T)


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("name", list(CASES))
def test_linearize_matches_central_differences(compile_model, name, backend):
    model, integ, traj = _setup(name, backend, compile_model)
    A = integ.linearize(traj)
    assert A.shape == (len(traj) - 1, 2 * model.group.d, 2 * model.group.d)
    for k in (0, len(A) - 1):
        FD = _fd(integ, model, traj.g[k], traj.mu[k], traj.h)
        err = np.abs(FD - A[k]).max() / np.abs(A[k]).max()
        assert err < 1e-7, (name, backend, k, err)


@pytest.mark.parametrize("name", list(CASES))
def test_backends_agree(compile_model, name):
    _, ic, traj = _setup(name, "c", compile_model)
    _, ip, _ = _setup(name, "python", compile_model)
    Ac, Ap = ic.linearize(traj), ip.linearize(traj)
    assert np.abs(Ac - Ap).max() <= 1e-13 * np.abs(Ac).max()


@pytest.mark.parametrize("name", list(CASES))
def test_linearize_matches_casadi_ad_and_is_symplectic(compile_model, name):
    model, integ, traj = _setup(name, "c", compile_model)
    opts = integ.meta["options"]
    step = derive(model, get_tableau(opts["tableau"]), opts["tau"], opts["rkmk"])
    sens = StepSensitivity(step, model.group)
    ad = ad_matrices(model.group)
    A = integ.linearize(traj)
    nn, hv = model.group.n ** 2, np.array([traj.h])
    for k in range(len(A)):
        g, p = traj.g[k], traj.mu[k]
        gf = g.ravel(order="F")
        z = integ.kernel("guess", integ.velocity(g, p), gf, p, hv)[0]
        for _ in range(30):          # Newton by CasADi's own J and the module's residual
            F = integ.kernel("residual", z, gf, p, hv)[0]
            dz = np.linalg.solve(sens.partials(z, g, p, traj.h)[3], F)
            z = z - dz
            if np.abs(dz).max() <= 1e-15 * (1 + np.abs(z).max()):
                break
        dF_ds, dU_dz, dU_ds, J, g1, _ = sens.partials(z, g, p, traj.h)
        dU = dU_ds - dU_dz @ np.linalg.solve(J, dF_ds)     # implicit function theorem
        ref = chart_jacobian(model.group, g1, dU[:nn], dU[nn:])
        assert np.abs(ref - A[k]).max() <= 1e-12 * np.abs(A[k]).max(), (name, k)
        _, rel = symplectic_defect(A[k], omega_matrix(ad, p), omega_matrix(ad, traj.mu[k + 1]))
        assert rel <= 1e-12, (name, k, rel)


def test_bad_trajectories(compile_model):
    _, integ, traj = _setup("heavy_top", "c", compile_model)
    _, other, other_traj = _setup("underwater_vehicle", "c", compile_model)

    def msg(bad):
        with pytest.raises(ArgumentError) as e:
            integ.linearize(bad)
        text = str(e.value)
        assert "\n" not in text and e.value.field == "traj"
        return text

    assert "underwater_vehicle" in msg(other_traj)
    assert "Trajectory" in msg(np.zeros((3, 3)))
    short = Trajectory(t=traj.t[:1], g=traj.g[:1], mu=traj.mu[:1], h=traj.h, every=1)
    assert "K >= 1" in msg(short)
    wrong = Trajectory(t=traj.t, g=traj.g[:, :2, :2], mu=traj.mu, h=traj.h, every=1)
    assert "shape" in msg(wrong)
    assert "every=2" in msg(Trajectory(t=traj.t, g=traj.g, mu=traj.mu, h=traj.h, every=2))
    # records of this module, but not at this h: not its steps
    other_h = Trajectory(t=traj.t, g=traj.g, mu=traj.mu, h=traj.h * 1.01, every=1)
    assert "record 1 is not this module's step" in msg(other_h)


def test_casadi_step_reproduces_step(compile_model):
    model, integ, traj = _setup("underwater_vehicle", "c", compile_model)
    f = integ.casadi_step()
    assert f.name_in() == ["g", "p", "h", "z"] and f.name_out() == ["F", "g1", "p1"]
    g, p, h = traj.g[2], traj.mu[2], traj.h
    Z = ca.SX.sym("z", integ.nz)
    solve = ca.rootfinder("solve", "newton", ca.Function("r", [Z], [f(g, p, h, Z)[0]]),
                          {"abstol": 1e-14})
    gf = g.ravel(order="F")
    z = solve(integ.kernel("guess", integ.velocity(g, p), gf, p, np.array([h]))[0])
    F, g1, p1 = f(g, p, h, z)
    assert np.abs(np.array(F)).max() < 1e-13
    assert np.abs(np.array(g1) - traj.g[3]).max() < 1e-12
    assert np.abs(np.array(p1).ravel() - traj.mu[3]).max() < 1e-12


def test_closed_linearize_takes_no_inputs(compile_model):
    _, integ, traj = _setup("heavy_top", "python", compile_model)
    for kw in ({"u": [1.0]}, {"params": {"Mg": 1.0}}, {"wrt": "params"}):
        with pytest.raises(ArgumentError) as e:
            integ.linearize(traj, **kw)
        assert "\n" not in str(e.value) and "takes no" in str(e.value)
