"""``scene.initial.project: true`` (hpgen.model.projection) and the refusals around the
constrained initial state and step: the projected state lies on the constraints and their
velocity form to round-off, the velocity correction is H-orthogonal to the admissible
velocities (H = d2l/dxi2, the kinetic metric), the scene says how far it moved, a run from it
keeps the constraints, and a Newton failure in a constrained step is a ConvergenceError
holding the partial run."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from scipy.linalg import null_space

from conftest import ROOT
from hpgen.errors import ConvergenceError, ModelError
from hpgen.model import load_model_text
from hpgen.model.constraints import constraint_values

DOUBLE = (ROOT / "tests" / "models" / "double_spherical_pendulum.yaml").read_text()
J = np.array([0.020833333333333332, 0.020833333333333332, 0.002])
H = np.diag(np.concatenate([J, np.ones(3), J, np.ones(3)]))      # m = 1

# both links tilted, link 1 0.03 off its joint, velocities that open both joints
OFF = """    g: [{rotvec: [0.3, -0.2, 0.1], position: [0.02, 0.0, -0.25]},
        {rotvec: [-0.1, 0.4, 0.0], position: [0.1, -0.05, -0.72]}]
    xi: [1.0, 0.5, 2.0, 0.3, 0.25, 0.1, -0.5, 1.5, -1.0, -0.625, 0.375, 0.2]
    project: true"""
ON = """    g: [{rotvec: [0, 0, 0], position: [0, 0, -0.25]}, {rotvec: [0, 0, 0], position: [0, 0, -0.75]}]
    xi: [1.0, 0.5, 2.0, -0.125, 0.25, 0.0, -0.5, 1.5, -1.0, -0.625, 0.375, 0.0]"""


def _scene(initial: str) -> str:
    assert ON in DOUBLE
    return DOUBLE.replace(ON, initial)


def test_projected_state_is_admissible_and_h_orthogonal():
    m = load_model_text(_scene(OFF), "m.yaml")
    sc = m.scene
    note = sc.projection
    g, xi = np.array(sc.g0), np.array(sc.xi0)
    phi, Phi, _ = constraint_values(m.constraints, m.g_symbols, m.group, g)
    print(note.note)
    assert np.abs(phi).max() < 1e-15
    assert np.abs(Phi @ xi).max() < 1e-14 * (1 + np.abs(xi).max())
    assert note.residual_after == np.abs(phi).max() or note.residual_after < 1e-15
    # what the file says, and how far it moved
    xi_file = np.array([1.0, 0.5, 2.0, 0.3, 0.25, 0.1, -0.5, 1.5, -1.0, -0.625, 0.375, 0.2])
    assert note.moved_xi == pytest.approx(np.abs(xi - xi_file).max(), rel=0, abs=0)
    assert 1e-3 < note.moved_g < 1.0 and note.moved_xi > 1e-2
    assert note.residual_before > 0.02
    # the velocity correction is H-orthogonal to the admissible velocities (null space of Phi)
    N = null_space(Phi)
    assert N.shape[1] == 6
    assert np.abs(N.T @ H @ (xi - xi_file)).max() < 1e-14
    # g stays on the group: the SE3 factors' bottom rows exact, rotations orthonormal
    for k in (0, 4):
        R = g[k:k + 3, k:k + 3]
        assert np.abs(R.T @ R - np.eye(3)).max() < 1e-15
        assert list(g[k + 3, k:k + 4]) == [0.0, 0.0, 0.0, 1.0]
    assert "moved by" in note.note and "\n" not in note.note


def test_admissible_state_barely_moves_and_without_project_is_kept():
    m = load_model_text(_scene(ON + "\n    project: true"), "m.yaml")
    plain = load_model_text(DOUBLE, "m.yaml")
    assert plain.scene.projection is None and not plain.scene.project
    assert m.scene.projection.moved_g < 1e-15 and m.scene.projection.moved_xi < 1e-15
    assert np.abs(np.array(m.scene.g0) - np.array(plain.scene.g0)).max() < 1e-15


def test_without_project_the_violation_is_refused_with_its_residual():
    text = _scene(OFF.replace("    project: true", ""))
    with pytest.raises(ModelError) as e:
        load_model_text(text, "m.yaml")
    msg = str(e.value)
    assert msg.startswith("m.yaml:") and "scene.initial.g: the initial g violates " \
        "constraints[0] row" in msg and "residual" in msg and "initial.project: true" in msg


@pytest.mark.parametrize("value,expected", [
    ("always", "scene.initial.project: expected true or false, got the string 'always'"),
    ("1", "scene.initial.project: expected true or false, got int 1"),
])
def test_project_must_be_a_boolean(value, expected):
    with pytest.raises(ModelError) as e:
        load_model_text(_scene(OFF.replace("project: true", f"project: {value}")), "m.yaml")
    assert expected in str(e.value)


def test_run_from_a_projected_scene_keeps_the_constraints(compile_model):
    m = load_model_text(_scene(OFF), "m.yaml")
    integ = compile_model(ROOT / "tests" / "models" / "double_spherical_pendulum.yaml")
    tr = integ.simulate(g0=np.array(m.scene.g0), xi0=np.array(m.scene.xi0), h=0.005,
                        steps=400, every=40)
    for g, mu in zip(tr.g, tr.mu):
        phi, Phi, _ = constraint_values(m.constraints, m.g_symbols, m.group, g)
        assert np.abs(phi).max() < 1e-14
        assert np.abs(Phi @ np.linalg.solve(H, mu)).max() < 1e-13


def test_cli_run_prints_the_projection(tmp_path, cache_dir):
    path = tmp_path / "projected.yaml"
    path.write_text(_scene(OFF).replace("steps: 5000", "steps: 20"))
    out = subprocess.run([sys.executable, "-m", "hpgen", "run", str(path), "--no-plot",
                          "--backend", "python",
                          "--out", str(tmp_path / "p.npz"), "--cache-dir", str(cache_dir)],
                         capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert out.returncode == 0, out.stderr
    line = [x for x in out.stdout.splitlines() if "projected onto the constraints" in x]
    assert len(line) == 1 and "g moved by" in line[0]


def test_newton_failure_in_a_constrained_step_keeps_the_partial_run(compile_model):
    """A constrained step whose Newton iteration cannot converge (maxit = 1 at a step that
    needs several) is a ConvergenceError naming the step, holding the nodes so far."""
    from hpgen.runtime import NewtonOptions
    m = load_model_text(DOUBLE, "m.yaml")
    integ = compile_model(ROOT / "tests" / "models" / "double_spherical_pendulum.yaml")
    g0, xi0 = np.array(m.scene.g0), np.array(m.scene.xi0)
    full = integ.simulate(g0=g0, xi0=xi0, h=0.05, steps=30, every=1)
    assert full.newton_iterations > 30          # more than one iteration per step
    with pytest.raises(ConvergenceError) as e:
        integ.simulate(g0=g0, xi0=xi0, h=0.05, steps=30, every=1,
                       newton=NewtonOptions(maxit=1))
    part = e.value.partial
    assert "Newton did not converge" in str(e.value) and "\n" not in str(e.value)
    assert part is not None and part.partial and 1 <= len(part.g) <= 30
    assert np.array_equal(part.g[0], g0)
