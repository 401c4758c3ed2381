"""The ball-jointed chain of hpgen.bench.multibody without the peers: capsule inertia, the
state convention and its conversions, and the DOP853 reference (conservation laws, the
joints, the small-oscillation period)."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from hpgen.bench.multibody import chain, reference, require
from hpgen.errors import ArgumentError, HpgenError


def test_capsule_inertia_limits():
    m, L, r = 1.0, 0.5, 0.05
    # no caps: a thin rod about its middle (m L^2 / 12), no axial moment
    rod = chain.capsule_inertia(m, L, 1e-10)
    assert rod[0] == pytest.approx(m * L * L / 12, rel=1e-8) and rod[2] < 1e-13
    # no cylinder: a solid sphere (2/5 m r^2 about every axis)
    assert chain.capsule_inertia(m, 1e-12, r) == pytest.approx([0.4 * m * r * r] * 3, rel=1e-9)
    # the benchmark's link: (83/320 + ...) as derived, a thin-rod value plus a small correction
    J = chain.ChainSpec(4).inertia
    assert J[0] == J[1] and m * L * L / 12 < J[0] < m * (L + 2 * r) ** 2 / 12


def test_quaternion_round_trip():
    rng = np.random.default_rng(3)
    q = rng.standard_normal((50, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    q *= np.sign(q[:, :1])
    R = chain.quat_to_matrix(q)
    assert np.abs(np.swapaxes(R, 1, 2) @ R - np.eye(3)).max() < 1e-15 * 10
    assert np.abs(np.linalg.det(R) - 1).max() < 1e-14
    assert np.abs(chain.matrix_to_quat(R) - q).max() < 1e-15 * 10
    # a quarter turn about z maps x to y
    Rz = chain.quat_to_matrix(np.array([np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4)]))
    assert Rz @ np.array([1.0, 0, 0]) == pytest.approx([0, 1, 0], abs=1e-15)


@pytest.mark.parametrize("n", [1, 2, 5])
def test_joint_coordinates_round_trip_and_joints(n):
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec, seed=n, angle=0.8, rate=2.0)
    state = chain.from_joint(spec, qpos, qvel)
    pos_res, vel_res = chain.constraint_residual(spec, state)
    assert pos_res < 1e-14 and vel_res < 1e-13
    back_q, back_v = chain.to_joint(spec, state)
    assert np.abs(back_q - qpos).max() < 1e-14 and np.abs(back_v - qvel).max() < 1e-13


def test_at_rest_the_chain_hangs_straight_down():
    spec = chain.ChainSpec(3)
    qpos = np.tile([1.0, 0, 0, 0], 3)
    state = chain.from_joint(spec, qpos, np.zeros(9))
    assert state.x[:, 2] == pytest.approx([-0.25, -0.75, -1.25])
    kinetic, potential = chain.energy(spec, state)
    assert kinetic == 0.0 and potential == pytest.approx(chain.rest_potential(spec))


def test_linear_velocities_are_the_derivative_of_the_positions():
    spec = chain.ChainSpec(4)
    qpos, qvel = chain.initial_joint_state(spec, seed=1)
    state = chain.from_joint(spec, qpos, qvel)
    eps = 1e-6

    def x_at(t):       # rotate every link by its own body angular velocity for time t
        theta = np.linalg.norm(state.omega, axis=1, keepdims=True) * t
        axis = state.omega / np.linalg.norm(state.omega, axis=1, keepdims=True)
        q = np.concatenate([np.cos(theta / 2), np.sin(theta / 2) * axis], axis=1)
        return chain.positions(spec, state.R @ chain.quat_to_matrix(q))

    fd = (x_at(eps) - x_at(-eps)) / (2 * eps)
    assert np.abs(fd - state.v).max() < 1e-8


def momentum_about_pin(spec, s):
    return (np.cross(s.x, spec.mass * s.v).sum(axis=0)
            + np.einsum("nij,nj->i", s.R, spec.inertia * s.omega))


def test_reference_keeps_energy_vertical_momentum_and_joints():
    spec = chain.ChainSpec(3)
    qpos, qvel = chain.initial_joint_state(spec, seed=2, angle=0.6, rate=2.0)
    sol = reference.solve(spec, qpos, qvel, [0.25, 0.5])
    s0 = chain.from_joint(spec, qpos, qvel)
    e0, l0 = sum(chain.energy(spec, s0)), momentum_about_pin(spec, s0)
    scale = abs(e0 - chain.rest_potential(spec))
    for s in sol.states:
        assert abs(sum(chain.energy(spec, s)) - e0) < 1e-12 * scale
        assert abs(momentum_about_pin(spec, s)[2] - l0[2]) < 1e-12
        assert chain.constraint_residual(spec, s)[0] < 1e-14
    assert sol.quat_drift < 1e-13
    assert np.abs(sol.final.x - s0.x).max() > 0.01            # it moved


def test_reference_small_oscillation_period_of_one_link():
    # a compound pendulum: theta'' = -m g d / (I + m d^2) theta, d = L / 2
    spec = chain.ChainSpec(1)
    theta0 = 1e-5
    qpos = np.array([np.cos(theta0 / 2), np.sin(theta0 / 2), 0.0, 0.0])
    d = spec.length / 2
    freq = np.sqrt(spec.mass * spec.g * d / (spec.inertia[0] + spec.mass * d * d))
    times = np.array([0.2, 0.5])
    sol = reference.solve(spec, qpos, np.zeros(3), times)
    for t, s in zip(times, sol.states):
        angle = np.arctan2(s.R[0, 2, 1], s.R[0, 2, 2])           # rotation about x
        assert angle == pytest.approx(theta0 * np.cos(freq * t), rel=1e-7)


def test_reference_accelerations_balance_forces():
    spec = chain.ChainSpec(4)
    qpos, qvel = chain.initial_joint_state(spec, seed=4)
    s = chain.from_joint(spec, qpos, qvel)
    xdd, wd, F = reference.ChainDynamics(spec).accelerations(s.R, s.omega)
    Fnext = np.concatenate([F[1:], np.zeros((1, 3))])
    gravity = np.array([0, 0, -spec.mass * spec.g])
    assert np.abs(spec.mass * xdd - (F - Fnext + gravity)).max() < 1e-12
    J, w = spec.inertia, s.omega
    torque = np.cross(spec.a, np.einsum("nji,nj->ni", s.R, F + Fnext))
    assert np.abs(J * wd + np.cross(w, J * w) - torque).max() < 1e-12
    # the whole chain: the pin force and gravity give the total momentum's rate
    assert np.abs(spec.mass * xdd.sum(axis=0) - (F[0] + spec.n * gravity)).max() < 1e-12


def test_bad_arguments_are_one_line_errors():
    with pytest.raises(ArgumentError, match="^n: expected a positive integer"):
        chain.ChainSpec(0)
    with pytest.raises(ArgumentError, match="radius"):
        chain.ChainSpec(2, radius=-1.0)
    spec = chain.ChainSpec(2)
    with pytest.raises(ArgumentError, match=r"qpos of shape \(8,\)"):
        chain.from_joint(spec, np.zeros(4), np.zeros(6))
    with pytest.raises(HpgenError, match=r"pip install 'hpgen\[peers\]'") as err:
        require("hpgen_no_such_peer_module")
    assert "\n" not in str(err.value)


def test_core_import_loads_no_peer():
    code = ("import sys, hpgen.bench.multibody.chain, hpgen.bench.multibody.reference, "
            "hpgen.bench.multibody.mujoco_peer, hpgen.bench.multibody.pinocchio_peer; "
            "print(sorted(m for m in ('mujoco', 'pinocchio', 'scipy') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"


def test_load_that_cancels_gravity():
    """A load of m g e3 on every centre (world) and no torque gives the chain without
    gravity: the same states to the integrator's tolerance (both runs DOP853 at 1e-13)."""
    spec, free = chain.ChainSpec(3), chain.ChainSpec(3, g=0.0)
    qpos, qvel = chain.initial_joint_state(spec, seed=4, angle=0.5, rate=1.5)

    def lift(t, R):
        return np.tile([0.0, 0.0, spec.mass * spec.g], (3, 1)), np.zeros((3, 3))
    a = reference.solve(spec, qpos, qvel, [0.5], load=lift).final
    b = reference.solve(free, qpos, qvel, [0.5]).final
    assert chain.trajectory_error(a, b) <= 1e-11
    # and a load changes the motion: a torque about the links' first axis
    c = reference.solve(free, qpos, qvel, [0.5], load=lambda t, R: (
        np.zeros((3, 3)), np.tile([0.3, 0.0, 0.0], (3, 1)))).final
    assert chain.trajectory_error(c, b) > 1e-3
