"""The MuJoCo and Pinocchio peers of the chain (the optional extra hpgen[peers], which
`make install` and CI install): the models against the state convention and energy of
hpgen.bench.multibody.chain, and their RK4 runs against the DOP853 reference at two time
steps (the tolerance is the fourth-order error estimate from the larger step)."""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.bench.multibody import chain, mujoco_peer, pinocchio_peer, reference
from hpgen.errors import ArgumentError

mujoco = pytest.importorskip("mujoco", reason="needs the optional extra hpgen[peers]")
pinocchio = pytest.importorskip("pinocchio", reason="needs the optional extra hpgen[peers]")

T = 1.0


@pytest.fixture(scope="module")
def four_links():
    # a bent start (joints turned by about 0.3 rad), so that RK4's error at dt = 1e-4 (about
    # 1e-13) stands well above the reference's (about 1e-14)
    spec = chain.ChainSpec(4)
    qpos, qvel = chain.initial_joint_state(spec, angle=0.3)
    return spec, qpos, qvel, reference.solve(spec, qpos, qvel, [T]).final


def test_mujoco_model_matches_the_state_convention_and_energy():
    spec = chain.ChainSpec(4)
    qpos, qvel = chain.initial_joint_state(spec, seed=5, angle=0.7, rate=2.0)
    m = mujoco_peer.model(spec, 1e-3)
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = qpos, qvel
    mujoco.mj_forward(m, d)
    s = chain.from_joint(spec, qpos, qvel)
    assert np.abs(d.xmat[1:].reshape(-1, 3, 3) - s.R).max() < 1e-14
    assert np.abs(d.xipos[1:] - s.x).max() < 1e-14
    vel = np.zeros(6)
    for i in range(spec.n):
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_BODY, i + 1, vel, 1)   # local
        assert np.abs(vel[:3] - s.omega[i]).max() < 1e-13
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_BODY, i + 1, vel, 0)   # world
        assert np.abs(vel[3:] - s.v[i]).max() < 1e-13
    kinetic, potential = chain.energy(spec, s)
    assert d.energy == pytest.approx([potential, kinetic], rel=1e-14)
    assert np.abs(m.body_inertia[1:] - spec.inertia).max() == 0.0


def test_mujoco_capsule_inertia_from_its_geometry_is_ours():
    spec = chain.ChainSpec(1)
    volume = np.pi * spec.radius ** 2 * spec.length + 4 / 3 * np.pi * spec.radius ** 3
    xml = mujoco_peer.mjcf(spec, 1e-3)
    xml = xml[:xml.index("<inertial")] + xml[xml.index("<geom"):]
    xml = xml.replace('contype="0"', f'density="{spec.mass / volume!r}" contype="0"')
    m = mujoco.MjModel.from_xml_string(xml)
    assert m.body_mass[1] == pytest.approx(spec.mass, rel=1e-14)
    assert m.body_inertia[1] == pytest.approx(spec.inertia, rel=1e-12)


def test_mujoco_rk4_is_order_4_against_the_reference(four_links):
    spec, qpos, qvel, ref = four_links
    errors = []
    for dt in (4e-4, 2e-4, 1e-4):
        run = mujoco_peer.run(spec, qpos, qvel, dt, round(T / dt), sample=100)
        errors.append(chain.trajectory_error(chain.from_joint(spec, run.qpos, run.qvel), ref))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert (3.6 < orders).all() and (orders < 4.4).all(), errors
    # at dt = 1e-4 MuJoCo and the reference agree to RK4's predicted error there
    assert errors[2] < 1.5 * errors[1] / 16


def test_mujoco_run_records_energy_and_chunks_do_not_matter():
    spec = chain.ChainSpec(2)
    qpos, qvel = chain.initial_joint_state(spec)
    one = mujoco_peer.run(spec, qpos, qvel, 1e-3, 95, sample=10, chunk=1000)
    many = mujoco_peer.run(spec, qpos, qvel, 1e-3, 95, sample=10, chunk=20)
    assert np.array_equal(one.qpos, many.qpos) and np.array_equal(one.qvel, many.qvel)
    assert np.array_equal(one.energy, many.energy) and one.stable
    assert list(one.times) == pytest.approx([0.0, *np.arange(0.01, 0.095, 0.01), 0.095])
    final = chain.from_joint(spec, one.qpos, one.qvel)
    assert one.energy[-1] == pytest.approx(sum(chain.energy(spec, final)), rel=1e-13)
    assert one.energy[0] == pytest.approx(sum(chain.energy(spec, chain.from_joint(
        spec, qpos, qvel))), rel=1e-14)
    band = np.abs(one.energy - one.energy[0]).max() / abs(one.energy[0])
    assert 0 < band < 1e-8                   # RK4, 95 steps of 1e-3 on two links
    euler = mujoco_peer.run(spec, qpos, qvel, 1e-3, 95, integrator="Euler")
    assert np.abs(euler.energy - euler.energy[0]).max() > 10 * band * abs(one.energy[0])


def test_blow_ups_are_flagged():
    spec = chain.ChainSpec(4)
    qpos, qvel = chain.initial_joint_state(spec, rate=30.0)
    assert mujoco_peer.run(spec, qpos, qvel, 1e-4, 20, sample=10).stable
    assert not mujoco_peer.run(spec, qpos, qvel, 2e-2, 200, integrator="Euler").stable
    assert pinocchio_peer.run(spec, qpos, qvel, 1e-4, 20).stable
    blown = pinocchio_peer.run(spec, qpos, qvel, 5e-2, 200)
    assert not blown.stable and blown.steps < 200


def test_mujoco_bad_integrator():
    with pytest.raises(ArgumentError, match="^integrator: expected one of RK4, Euler"):
        mujoco_peer.mjcf(chain.ChainSpec(2), 1e-3, "rk45")


def test_pinocchio_model_matches_the_state_convention_and_energy():
    spec = chain.ChainSpec(4)
    qpos, qvel = chain.initial_joint_state(spec, seed=6, angle=0.7, rate=2.0)
    m = pinocchio_peer.model(spec)
    d = m.createData()
    q = pinocchio_peer.to_pinocchio(qpos)
    assert np.array_equal(pinocchio_peer.from_pinocchio(q), qpos)
    pinocchio.forwardKinematics(m, d, q, qvel)
    s = chain.from_joint(spec, qpos, qvel)
    for i in range(spec.n):
        assert np.abs(d.oMi[i + 1].rotation - s.R[i]).max() < 1e-14
        assert np.abs(d.v[i + 1].angular - s.omega[i]).max() < 1e-13
    energy = pinocchio.computeMechanicalEnergy(m, d, q, qvel)
    assert energy == pytest.approx(sum(chain.energy(spec, s)), rel=1e-14)


def test_pinocchio_dexpinv_inverts_the_integrate_jacobian():
    m = pinocchio_peer.model(chain.ChainSpec(1))
    phi, w = np.array([0.3, -0.2, 0.5]), np.array([1.0, 2.0, 3.0])
    jac = pinocchio.dIntegrate(m, pinocchio.neutral(m), phi, pinocchio.ARG1)
    assert np.abs(jac @ pinocchio_peer.dexpinv(phi[None], w[None])[0] - w).max() < 1e-14
    # the series branch (|phi| < 1e-3) against the closed form (whose cancellation error,
    # about 1e-16 / |phi|^2 in c, is multiplied by |phi|^2 here)
    small = 0.9e-3 * np.array([[0.6, 0.0, 0.8]])
    t = np.linalg.norm(small)
    c = 1 / t ** 2 - (1 + np.cos(t)) / (2 * t * np.sin(t))
    pw = np.cross(small[0], w)
    closed = w + 0.5 * pw + c * np.cross(small[0], pw)
    assert np.abs(pinocchio_peer.dexpinv(small, w[None])[0] - closed).max() < 1e-15 * 10


def reference_joint_accelerations(spec, qpos, qvel):
    """qacc of the reference: qvel_i = omega_i - P_i^T omega_(i-1), P_i = R(q_i), so
    qacc_i = omega_i' - P_i^T omega_(i-1)' + qvel_i x (P_i^T omega_(i-1))."""
    s = chain.from_joint(spec, qpos, qvel)
    _, wd, _ = reference.ChainDynamics(spec).accelerations(s.R, s.omega)
    rel = chain.quat_to_matrix(qpos.reshape(-1, 4))
    rel_w = qvel.reshape(-1, 3)
    out = wd.copy()
    for i in range(1, spec.n):
        out[i] += -rel[i].T @ wd[i - 1] + np.cross(rel_w[i], rel[i].T @ s.omega[i - 1])
    return out.reshape(-1)


@pytest.mark.parametrize("n, dynamics", [(8, "aba"), (8, "crba"), (64, "crba")])
def test_pinocchio_accelerations_match_the_reference(n, dynamics):
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec, seed=10, angle=0.05)
    m = pinocchio_peer.model(spec)
    f = pinocchio_peer.accelerations(m, m.createData(), dynamics)
    got = f(pinocchio_peer.to_pinocchio(qpos), qvel)
    want = reference_joint_accelerations(spec, qpos, qvel)
    # the joint-space mass matrix of the 64-link chain has a condition number near 1e9
    assert np.abs(got - want).max() < (1e-12 if n == 8 else 1e-7) * np.abs(want).max()


def test_mujoco_accelerations_match_the_reference():
    spec = chain.ChainSpec(64)
    qpos, qvel = chain.initial_joint_state(spec, seed=10, angle=0.05)
    m = mujoco_peer.model(spec, 1e-3)
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = qpos, qvel
    mujoco.mj_forward(m, d)
    want = reference_joint_accelerations(spec, qpos, qvel)
    assert np.abs(d.qacc - want).max() < 1e-7 * np.abs(want).max()


@pytest.mark.parametrize("dynamics", ["aba", "crba"])
def test_pinocchio_rkmk4_is_order_4_against_the_reference(dynamics):
    spec = chain.ChainSpec(2)
    qpos, qvel = chain.initial_joint_state(spec)
    horizon = 0.5
    ref = reference.solve(spec, qpos, qvel, [horizon]).final
    errors = []
    for dt in (1e-3, 5e-4):
        run = pinocchio_peer.run(spec, qpos, qvel, dt, round(horizon / dt), sample=50,
                                 dynamics=dynamics)
        errors.append(chain.trajectory_error(chain.from_joint(spec, run.qpos, run.qvel), ref))
        assert run.energy[0] == pytest.approx(sum(chain.energy(
            spec, chain.from_joint(spec, qpos, qvel))), rel=1e-14)
    order = np.log2(errors[0] / errors[1])
    assert 3.5 < order < 4.5, errors
    assert errors[1] < 1.5 * errors[0] / 16
