"""The constrained splitting step (``tableau: split2``, hpgen.derive.family_split) on open
models: examples/capsule_chain.yaml (N = 3) with the gravity a runtime parameter, a
time-dependent potential, a per-body force of (t, g, u) and a control input.

- runtime parameters: the module run at grav = 9.81 and 3.0 gives the model compiled with
  that constant to round-off (both backends), and a sweep over grav equals the runs one at a
  time bitwise;
- forces and t: order 2 (2.0 +- 0.1) of the error at T = 0.5 against DOP853 at 1e-13 on
  the reduced coordinates with the same loads (hpgen.bench.multibody.reference, ``load``),
  joints at round-off at every node, and order 4 (4.0 +- 0.2) of the suzuki4 composition
  (a symmetric step: the kicks at t_k and t_k + h); with V free of t the energy-work
  balance E - W - E0 falls as h^2;
- the Newton matrix assembled from blocks (the hidden rows folded through the velocity, e1
  passed through: no dV; the body force inlined in the kicks) equals casadi.jacobian of the
  open step, and
  linearize's input derivative B equals a central difference;
- a velocity-dependent force and forces between bodies are refused in one line.
"""
from __future__ import annotations

import casadi as ca
import numpy as np
import pytest

import hpgen
from conftest import ROOT
from hpgen.bench.multibody import chain as ch, hpgen_chain
from hpgen.bench.multibody.reference import solve
from hpgen.errors import ModelError

MODEL = ROOT / "examples" / "capsule_chain.yaml"
TEXT = MODEL.read_text()
SPEC = ch.ChainSpec(3)
RUNTIME = TEXT.replace("integrator:", "runtime_parameters: [grav]\nintegrator:")
# V_i gains -B sin(2t) x[i][0] (a world force B sin(2t) e1 on every centre); the body force
# is a torque A cos(om t) + u about the link's first axis and 0.2 R[i][2, 0] about its second
FORCED = TEXT.replace("grav: 9.81,", "grav: 9.81, A: 0.4, om: 3.0, B: 0.3,").replace(
    "(i + 0.5)*b[2]))", "(i + 0.5)*b[2]) + B*sin(2*t)*x[i][0])").replace(
    "integrator:", 'runtime_parameters: [grav]\ninputs: [u]\nforces: {for: i, body: '
    '["A*cos(om*t) + u", "0.2*R[i][2, 0]", "0", "0", "0", "0"]}\nintegrator:')
GRAV, U = 5.0, 0.15
# the same loads with V free of t: E - W (the forces' work, docs/numerics.md sec. 13) is the
# conserved balance of the flow
WORKED = FORCED.replace(" + B*sin(2*t)*x[i][0])", ")").replace(
    "record: [g, energy, momentum]", "record: [g, energy, momentum, power, work]")


def _load(t, R):
    """The forced model's loads for the reference: (world force, body torque) per link."""
    force, torque = np.zeros((3, 3)), np.zeros((3, 3))
    force[:, 0] = 0.3 * np.sin(2 * t)
    torque[:, 0] = 0.4 * np.cos(3.0 * t) + U
    torque[:, 1] = 0.2 * R[:, 2, 0]
    return force, torque


def _start(spec=SPEC):
    qpos, qvel = ch.initial_joint_state(spec, seed=4, angle=0.5, rate=1.5)
    return qpos, qvel, hpgen_chain.to_hpgen(spec, ch.from_joint(spec, qpos, qvel), "centre")


@pytest.mark.parametrize("backend", ["c", "python"])
def test_runtime_parameter_equals_the_constant(compile_model, backend):
    integ = compile_model(RUNTIME, parameters={"N": 3}, tableau="split2", backend=backend)
    assert integ.meta["unknowns"] == [["lambda", 0, 9], ["nu", 9, 18]]
    g0, xi0 = _start()[2]
    for grav in (9.81, 3.0):
        fixed = compile_model(MODEL, parameters={"N": 3, "grav": grav}, tableau="split2",
                              backend=backend)
        a = integ.simulate(g0=g0, xi0=xi0, h=1e-2, steps=300, every=10, params={"grav": grav})
        b = fixed.simulate(g0=g0, xi0=xi0, h=1e-2, steps=300, every=10)
        assert np.abs(a.g - b.g).max() <= 1e-13 and np.abs(a.mu - b.mu).max() <= 1e-12


def test_sweep_over_the_gravity(compile_model):
    integ = compile_model(RUNTIME, parameters={"N": 3}, tableau="split2")
    g0, xi0 = _start()[2]
    grav = np.array([9.81, 3.0, 1.0])
    res = hpgen.sweep(integ, g0=g0, xi0=np.array([xi0] * 3), h=1e-2, steps=100, every=10,
                      params={"grav": grav}, threads=2, progress=False)
    for i, gv in enumerate(grav):
        one = integ.simulate(g0=g0, xi0=xi0, h=1e-2, steps=100, every=10, params={"grav": gv})
        assert np.array_equal(res["g"][i], one.g) and np.array_equal(res["mu"][i], one.mu)
    assert not np.array_equal(res["g"][0], res["g"][1])


def _errors(integ, hs, T=0.5):
    qpos, qvel, (g0, xi0) = _start()
    ref = solve(ch.ChainSpec(3, g=GRAV), qpos, qvel, [T], load=_load).final
    errs = []
    for h in hs:
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=round(T / h), every=1, u=[U],
                            params={"grav": GRAV})
        states = hpgen_chain.from_hpgen(SPEC, tr.g, tr.xi(), "centre")
        pos, vel = np.max([ch.constraint_residual(SPEC, s) for s in states], axis=0)
        assert pos < 1e-13 and vel < 1e-13, (h, pos, vel)
        errs.append(ch.trajectory_error(states[-1], ref))
    return errs, np.log2(np.array(errs[:-1]) / np.array(errs[1:]))


@pytest.mark.parametrize("backend", ["c", "python"])
def test_forced_order_two(compile_model, backend):
    integ = compile_model(FORCED, parameters={"N": 3}, tableau="split2", backend=backend)
    errs, orders = _errors(integ, (4e-3, 2e-3, 1e-3))
    print("forced split2 errors", errs, "orders", orders)
    assert np.all(np.abs(orders - 2.0) <= 0.1), (errs, orders)


def test_forced_order_four_composed(compile_model):
    integ = compile_model(FORCED, parameters={"N": 3}, tableau="split2", compose="suzuki4")
    errs, orders = _errors(integ, (2e-2, 1e-2, 5e-3))
    print("forced split2 + suzuki4 errors", errs, "orders", orders)
    assert np.all(np.abs(orders - 4.0) <= 0.2), (errs, orders)


def test_energy_work_balance_order_two(compile_model):
    """max |E - W - E0| over T = 1 falls as h^2 (2.0 +- 0.1 per halving)."""
    integ = compile_model(WORKED, parameters={"N": 3}, tableau="split2")
    g0, xi0 = _start()[2]
    bal = []
    for h in (4e-3, 2e-3, 1e-3):
        r = integ.record(g0, h, round(1 / h), xi0=xi0, every=1, u=[U], params={"grav": GRAV})
        bal.append(np.abs(r["energy"] - r["work"] - r["energy"][0]).max())
    rates = np.log2(np.array(bal[:-1]) / np.array(bal[1:]))
    print("E - W balance", bal, "rates", rates)
    assert np.all(np.abs(rates - 2.0) <= 0.1), (bal, rates)


def test_linearize_input_derivative(compile_model):
    """B = d(eta, dp)_{k+1} / d u_k of the forced split2 step against a central difference
    in u (step 1e-6: round-off about 1e-16 |p| / 1e-6 ~ 1e-9, truncation 1e-12)."""
    integ = compile_model(FORCED, parameters={"N": 3}, tableau="split2")
    g0, xi0 = _start()[2]
    P, h, eps = {"grav": GRAV}, 1e-3, 1e-6
    tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=3, every=1, u=[U], params=P)
    A, B = integ.linearize(tr, u=[U], params=P)
    d = A.shape[1] // 2
    ends = [integ.simulate(g0=g0, xi0=xi0, h=h, steps=1, every=1, u=[U + s], params=P).mu[1]
            for s in (eps, -eps)]
    fd = (ends[0] - ends[1]) / (2 * eps)
    assert np.abs(fd).max() > 1e-4 and np.abs(fd - B[0][d:, 0]).max() <= 1e-8


def test_open_split_jacobian_equals_casadi_jacobian():
    from hpgen.derive.family import _functions
    from hpgen.derive.family_jacobian import assembled_jacobian
    from hpgen.derive.family_map import mapped_step_parts
    from hpgen.model import load_model_text
    from hpgen.tableaus import resolve_tableau
    model = load_model_text(FORCED.replace("{N: 2,", "{N: 4,"))
    funcs = _functions(model, resolve_tableau("split2"), "cay", "truncated")
    body, n = funcs[0], 4
    m = sum(len(j.rows) for j in model.family.local.joints)
    G, P = ca.MX.sym("G", body.n * body.n, n), ca.MX.sym("P", body.d, n)
    hv, z = ca.MX.sym("h", 2 + 1 + 1), ca.MX.sym("z", 2 * m)
    eqs, parts = mapped_step_parts(model, funcs, G, P, hv, z, ca.MX.sym("xi", body.d * n))
    fa = ca.Function("a", [z, G, P, hv], [assembled_jacobian(model, funcs, parts)])
    fr = ca.Function("r", [z, G, P, hv], [ca.jacobian(eqs.residual, z)])
    rng = np.random.default_rng(5)
    qpos, qvel, (g0, xi0) = _start(ch.ChainSpec(n))
    Gv = np.stack([g0[4 * k:4 * k + 4, 4 * k:4 * k + 4].ravel(order="F") for k in range(n)], 1)
    args = [0.1 * rng.standard_normal(2 * m), Gv, rng.standard_normal((6, n)),
            [0.01, 0.3, 0.15, 5.0]]
    A, R = (np.array(ca.densify(f(*args))) for f in (fa, fr))
    assert np.abs(A - R).max() <= 1e-13 * (1.0 + np.abs(R).max())
    # the hidden rows fold Phi V_P into the joints' blocks (e1 passed through): no dV
    called = {fa.instruction_MX(k).which_function().name() for k in range(fa.n_instructions())
              if fa.instruction_id(k) == ca.OP_CALL}
    assert not any("velocity_blocks" in c or "vel_d" in c for c in called), called
    # the kicks' body force is inlined in the body update (its Jacobian blocks see through it)
    ur = next(iter(funcs[3].values()))["UR"]
    assert ca.OP_CALL not in {ur.instruction_id(k) for k in range(ur.n_instructions())}


@pytest.mark.parametrize("example,words", [
    ("damped_pendulum_chain", "forces.body[0] (-c*w[i][0] + u) depends on it"),
    ("joint_damped_chain", "not forces between bodies (forces.joint)")])
def test_refusals(compile_model, example, words):
    with pytest.raises(ModelError) as e:
        compile_model(ROOT / "examples" / f"{example}.yaml", tableau="split2",
                      backend="python")
    msg = str(e.value)
    assert words in msg and "integrator.tableau" in msg and "\n" not in msg
