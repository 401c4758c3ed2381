"""Quaternions and rotation vectors of group elements (hpgen.groups.elements): the scalar-first
convention checked against the rotation vector, unit norm refused otherwise, the model file's
``initial.g: {quat: [w, x, y, z]}`` equal to ``Integrator.group.from_quat``, and the attitudes
of a run read back (``as_quat`` / ``as_rotvec``)."""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hpgen
from hpgen.errors import ArgumentError, ModelError
from hpgen.groups.elements import (quat_from_rotation, rotation_from_quat, rotation_from_rotvec,
                                   rotvec_from_rotation)
from hpgen.model import load_model_text
from hpgen.runtime.initial import GroupElements

REPO = Path(hpgen.__file__).resolve().parents[1]
EPS = np.finfo(float).eps


def _random_rotvecs(k, seed=0):
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(k, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = rng.uniform(0, math.pi, size=k)
    return axes * angles[:, None]


def test_quaternion_is_scalar_first_and_turns_like_the_rotation_vector():
    # a quarter turn about z: x -> y (right-handed), q = [cos(pi/4), 0, 0, sin(pi/4)]
    R = rotation_from_quat([math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)])
    np.testing.assert_allclose(R @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=4 * EPS)
    for w in _random_rotvecs(50):
        t = np.linalg.norm(w)
        q = np.concatenate([[math.cos(t / 2)], math.sin(t / 2) * w / t])
        np.testing.assert_allclose(rotation_from_quat(q), rotation_from_rotvec(w), atol=8 * EPS)
        np.testing.assert_allclose(rotation_from_quat(-q), rotation_from_rotvec(w), atol=8 * EPS)


def test_read_back_inverts_the_constructors():
    W = _random_rotvecs(200, seed=1)
    Rs = np.array([rotation_from_rotvec(w) for w in W])
    Q = quat_from_rotation(Rs)
    assert Q.shape == (200, 4) and np.all(Q[:, 0] >= 0)
    np.testing.assert_allclose(np.linalg.norm(Q, axis=1), 1.0, atol=4 * EPS)
    np.testing.assert_allclose(np.array([rotation_from_quat(q) for q in Q]), Rs, atol=16 * EPS)
    np.testing.assert_allclose(rotvec_from_rotation(Rs), W, atol=1e-13)
    # the identity, a tiny angle (no cancellation) and a half turn (w = 0: x > 0)
    np.testing.assert_array_equal(rotvec_from_rotation(np.eye(3)), [0.0, 0.0, 0.0])
    tiny = np.array([1e-9, -2e-9, 3e-9])
    np.testing.assert_allclose(rotvec_from_rotation(rotation_from_rotvec(tiny)), tiny,
                               rtol=1e-6)
    half = quat_from_rotation(rotation_from_rotvec([-math.pi, 0.0, 0.0]))   # q ~ -q: either
    np.testing.assert_allclose(np.abs(half), [0.0, 1.0, 0.0, 0.0], atol=4 * EPS)
    np.testing.assert_array_equal(quat_from_rotation(np.diag([1.0, -1.0, -1.0])),
                                  [0.0, 1.0, 0.0, 0.0])        # w = 0 exactly: x > 0


def test_from_quat_checks_the_norm_and_the_group():
    so3, se3, se2 = GroupElements("SO3"), GroupElements("SE3"), GroupElements("SE2")
    q = [0.5, 0.5, -0.5, 0.5]
    np.testing.assert_array_equal(se3.from_quat(q, position=[1, 2, 3])[:3, :3], so3.from_quat(q))
    np.testing.assert_array_equal(se3.from_quat(q, position=[1, 2, 3])[:3, 3], [1, 2, 3])
    for call, field, words in (
            (lambda: so3.from_quat([1.0, 0.0, 0.0, 1e-4]), "quat", "unit quaternion"),
            (lambda: so3.from_quat([2.0, 0.0, 0.0, 0.0]), "quat", "norm 2"),
            (lambda: so3.from_quat([1.0, 0.0, 0.0]), "quat", "4 real numbers"),
            (lambda: so3.from_quat([1.0, 0.0, 0.0, math.nan]), "quat", "finite"),
            (lambda: se2.from_quat([1.0, 0.0, 0.0, 0.0]), "quat", "angle"),
            (lambda: so3.as_quat(np.eye(4)), "g", "(..., 3, 3)"),
            (lambda: GroupElements("R3").as_quat(np.eye(4)), "factor", "no 3 x 3"),
            (lambda: GroupElements("[SO3, SO3]").as_quat(np.eye(6)), "factor", "factor=k")):
        with pytest.raises(ArgumentError) as info:
            call()
        msg = str(info.value)
        assert info.value.field == field and words in msg and "\n" not in msg
    # a product: the factor's block is read
    G = GroupElements("[SO3, SO3]").product(so3.from_rotvec([0.1, 0, 0]),
                                            so3.from_rotvec([0, 0.2, 0]))
    np.testing.assert_allclose(GroupElements("[SO3, SO3]").as_rotvec(G, factor=1),
                               [0, 0.2, 0], atol=1e-15)


def _scene_g(group, d, g_yaml):
    text = (f"name: m\ngroup: {group}\nlagrangian: 0.5*dot(xi, xi)\n"
            f"scene: {{h: 0.1, steps: 1, initial: {{g: {g_yaml}, xi: {[0.0] * d}}}}}\n")
    return np.array(load_model_text(text, "m.yaml").scene.g0)


def test_model_file_quat_equals_from_quat():
    q = [0.7071067811865476, 0.0, 0.7071067811865476, 0.0]
    np.testing.assert_array_equal(_scene_g("SO3", 3, f"{{quat: {q}}}"),
                                  GroupElements("SO3").from_quat(q))
    np.testing.assert_array_equal(_scene_g("SE3", 6, f"{{quat: {q}, position: [1, 2, 3]}}"),
                                  GroupElements("SE3").from_quat(q, [1, 2, 3]))
    for g_yaml, field, words in (
            ("{quat: [1, 0, 0, 0.001]}", "quat", "unit quaternion [w, x, y, z] (scalar first)"),
            ("{quat: [1, 0, 0]}", "quat", "list of 4 numbers"),
            ("{quat: [1, 0, 0, 0], rotvec: [0, 0, 0]}", "quat", "not both")):
        with pytest.raises(ModelError) as info:
            _scene_g("SO3", 3, g_yaml)
        assert f"scene.initial.g.{field}" in str(info.value) and words in str(info.value)
    with pytest.raises(ModelError, match="unknown key 'quat'"):
        _scene_g("SE2", 3, "{quat: [1, 0, 0, 0]}")


def test_trajectory_and_records_attitudes(compile_model):
    text = ("name: qbody\ngroup: SE3\nparameters: {I: [2.0, 1.0, 0.5]}\n"
            "lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2 + "
            "xi[3]**2 + xi[4]**2 + xi[5]**2)\n"
            "scene: {h: 0.05, steps: 20, initial: {xi: [0.3, 1.0, 2.0, 0, 0, 1]}, "
            "record: [g, energy]}\n")
    integ = compile_model(text, backend="python")
    g0 = integ.group.from_quat([0.5, 0.5, 0.5, 0.5], position=[0, 0, 1])
    tr = integ.simulate(g0, 0.05, 20, xi0=[0.3, 1.0, 2.0, 0, 0, 1])
    Q, W = tr.as_quat(), tr.as_rotvec()
    assert Q.shape == (21, 4) and W.shape == (21, 3)
    np.testing.assert_allclose(Q[0], [0.5, 0.5, 0.5, 0.5], atol=4 * EPS)
    np.testing.assert_allclose(np.array([rotation_from_quat(q) for q in Q]), tr.g[:, :3, :3],
                               atol=16 * EPS)
    np.testing.assert_allclose(np.array([rotation_from_rotvec(w) for w in W]), tr.g[:, :3, :3],
                               atol=1e-14)
    rec = integ.record(g0, 0.05, 20, xi0=[0.3, 1.0, 2.0, 0, 0, 1])
    np.testing.assert_array_equal(rec.as_quat(), quat_from_rotation(rec["g"][:, :3, :3]))
    no_g = type(rec)(t=rec.t, arrays={"energy": rec["energy"]}, h=rec.h, every=rec.every,
                     integrator=integ)
    with pytest.raises(ArgumentError, match="record g"):
        no_g.as_rotvec()


def test_runtime_and_elements_import_no_compile_stack():
    code = ("import sys, hpgen.runtime, hpgen.groups.elements, hpgen.runtime.initial; "
            "print([m for m in ('sympy', 'casadi', 'jinja2') if m in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"}, check=True)
    assert out.stdout.strip() == "[]"


def test_model_stage_does_not_import_the_runtime():
    for path in (REPO / "hpgen" / "model").glob("*.py"):
        for line in path.read_text().splitlines():
            assert not line.lstrip().startswith(("from ..runtime", "from hpgen.runtime",
                                                 "import hpgen.runtime")), (path.name, line)
