"""Arguments of the Python API (issue 17): ArgumentError (a ValueError, not a ModelError) for
bad arguments, run sizes that cannot be held, complex inputs, scalar xi0/mu0 on
1-dimensional algebras, and the initial-state constructors ``Integrator.group`` (the same
elements as a model file's ``initial.g`` forms)."""
from __future__ import annotations

import math
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import hpgen
from hpgen.errors import ArgumentError, ModelError
from hpgen.model import load_model_text
from hpgen.runtime.args import STEPS_MAX
from hpgen.runtime.initial import GroupElements

from _toy_step import integrator

G0 = np.eye(3)
XI0 = np.array([0.3, 1.0, -0.4])
REPO = Path(hpgen.__file__).resolve().parents[1]


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("steps", [2**63, 10**20, STEPS_MAX + 1])
def test_steps_beyond_a_run_counter_are_refused(backend, steps):
    it = integrator(backend)
    for run in (lambda: it.simulate(G0, 0.1, steps, xi0=XI0),
                lambda: next(it.stream(G0, 0.1, steps, xi0=XI0)),
                lambda: it.record(G0, 0.1, steps, xi0=XI0)):
        with pytest.raises(ArgumentError) as info:
            run()
        msg = str(info.value)
        assert info.value.field == "steps" and "\n" not in msg and "stream" in msg


@pytest.mark.parametrize("backend", ["c", "python"])
def test_records_that_cannot_be_held_are_refused_before_allocation(backend):
    it = integrator(backend)
    with pytest.raises(ArgumentError) as info:
        it.simulate(G0, 0.1, 10**12, xi0=XI0)
    msg = str(info.value)
    assert info.value.field == "steps" and "memory" in msg and "stream" in msg
    with pytest.raises(ArgumentError, match="record"):
        it.record(G0, 0.1, 10**12, xi0=XI0)
    # stream holds one chunk: it takes the count (only its first chunk of 3 steps is run)
    assert len(next(it.stream(G0, 0.1, 10**12, xi0=XI0, chunk=3))) == 4


def test_cli_steps_too_large_is_exit_2(tmp_path):
    res = subprocess.run([sys.executable, "-m", "hpgen", "run", str(REPO / "examples" /
                          "free_rigid_body.yaml"), "--steps", "99999999999999999999",
                          "--backend", "python", "--out", str(tmp_path / "o.npz"),
                          "--cache-dir", str(tmp_path / "cache")],
                         capture_output=True, text=True, cwd=tmp_path,
                         env={"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"})
    assert res.returncode == 2, res.stderr
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and "steps" in lines[0] and "Traceback" not in res.stderr
    assert list(tmp_path.glob("*.npz")) == [] and not list(tmp_path.glob(".o.npz*"))


@pytest.mark.parametrize("kw, field", [
    ({"g0": np.eye(3) * (1 + 0j)}, "g0"), ({"g0": np.eye(3) + 1e-3j * np.ones((3, 3))}, "g0"),
    ({"xi0": XI0 + 0j}, "xi0"), ({"xi0": None, "mu0": [1j, 0, 0]}, "mu0"),
    ({"h": 0.1 + 0j}, "h"), ({"h": 0.0}, "h")])
def test_complex_inputs_are_refused_not_truncated(kw, field):
    args = {"g0": G0, "h": 0.1, "steps": 3, "xi0": XI0, **kw}
    with warnings.catch_warnings():
        warnings.simplefilter("error")          # no ComplexWarning either
        with pytest.raises(ArgumentError) as info:
            integrator("python").simulate(**args)
    assert info.value.field == field and isinstance(info.value, ValueError)
    assert not isinstance(info.value, ModelError)


def test_argument_error_is_a_value_error_with_one_line():
    e = ArgumentError("expected a\nthing", field="h")
    assert isinstance(e, ValueError) and isinstance(e, hpgen.HpgenError)
    assert str(e) == "h: expected a thing" and hpgen.ArgumentError is ArgumentError


def test_batch_arguments_are_argument_errors():
    with pytest.raises(ArgumentError, match="C backend"):
        integrator("python").simulate_batch(G0, 0.1, 3, xi0=[XI0])
    with pytest.raises(ArgumentError) as info:
        integrator("c").simulate_batch(np.zeros((2, 2)), 0.1, 3, xi0=[XI0])
    assert info.value.field == "g0"


R1_MODEL = """
name: slider
group: R1
parameters: {m: 2.0, k: 0.5}
lagrangian: 0.5*m*xi[0]**2 - 0.5*k*x[0]**2
scene:
  h: 0.1
  steps: 10
  initial: {g: {position: [0.3]}, xi: [0.7]}
"""


@pytest.mark.parametrize("backend", ["c", "python"])
def test_scalar_initial_state_on_a_1d_algebra(compile_model, backend):
    integ = compile_model(R1_MODEL, backend=backend)
    g0 = integ.group.from_position([0.3])
    model = load_model_text(R1_MODEL)
    np.testing.assert_array_equal(g0, np.array(model.scene.g0))
    a = integ.simulate(g0, 0.1, 10, xi0=0.7)
    b = integ.simulate(g0, 0.1, 10, xi0=[0.7])
    np.testing.assert_array_equal(a.mu, b.mu)
    np.testing.assert_array_equal(integ.simulate(g0, 0.1, 10, mu0=1.4).mu,
                                  integ.simulate(g0, 0.1, 10, mu0=np.array([1.4])).mu)
    with pytest.raises(ArgumentError):
        integrator("python").simulate(G0, 0.1, 3, xi0=0.7)       # d = 3: a scalar is wrong


def _scene_g(group, g_yaml, d):
    text = (f"name: m\ngroup: {group}\nlagrangian: " + " + ".join(
        f"xi[{i}]**2" for i in range(d)) + f"\nscene:\n  h: 0.1\n  steps: 1\n  initial: "
        f"{{g: {g_yaml}, xi: {[0.0] * d}}}\n")
    return np.array(load_model_text(text).scene.g0)


W = [0.3, -1.2, 2.9]


@pytest.mark.parametrize("group, d, g_yaml, build", [
    ("SO3", 3, f"{{rotvec: {W}}}", lambda G: G.from_rotvec(W)),
    ("SO3", 3, "{rotvec: [0, 0, 0]}", lambda G: G.from_rotvec([0, 0, 0])),
    ("SE3", 6, f"{{rotvec: {W}, position: [1, 2, 3]}}",
     lambda G: G.from_rotvec(W, position=[1, 2, 3])),
    ("SE3", 6, "{position: [1, 2, 3]}", lambda G: G.from_position([1, 2, 3])),
    ("SO2", 1, "{angle: 0.7}", lambda G: G.from_angle_position(0.7)),
    ("SE2", 3, "{angle: -2.5, position: [0.5, 4]}",
     lambda G: G.from_angle_position(-2.5, [0.5, 4])),
    ("R3", 3, "{position: [1, -2, 0.25]}", lambda G: G.from_position([1, -2, 0.25])),
    ("[SO3, R2]", 5, f"[{{rotvec: {W}}}, {{position: [7, 8]}}]",
     lambda G: G.product(GroupElements("SO3").from_rotvec(W),
                         GroupElements("R2").from_position([7, 8]))),
])
def test_group_constructors_equal_the_model_file(group, d, g_yaml, build):
    """Bitwise the model loader's initial.g (one piece of code: hpgen.runtime.initial)."""
    np.testing.assert_array_equal(build(GroupElements(group)), _scene_g(group, g_yaml, d))


def test_group_constructor_errors():
    so3, se2 = GroupElements("SO3"), GroupElements("SE2")
    for call, field in ((lambda: so3.from_angle_position(1.0), "angle"),
                        (lambda: se2.from_rotvec(W), "rotvec"),
                        (lambda: so3.from_rotvec([1, 2]), "rotvec"),
                        (lambda: so3.from_rotvec([1j, 0, 0]), "rotvec"),
                        (lambda: so3.from_rotvec(W, position=[1, 2, 3]), "position"),
                        (lambda: se2.from_angle_position(math.inf), "angle"),
                        (lambda: GroupElements("[SO3, R2]").from_rotvec(W), "from_rotvec")):
        with pytest.raises(ArgumentError) as info:
            call()
        assert info.value.field == field and "\n" not in str(info.value)


def test_integrator_group_from_meta(compile_model):
    integ = compile_model(REPO / "examples" / "free_rigid_body.yaml", backend="python")
    assert integ.group.name == "SO3" and integ.group.n == integ.n
    g0 = integ.group.from_rotvec([0.3, 0.2, 0.1])
    assert integ.defect(g0) <= 1e-15
    tr = integ.simulate(g0, 0.1, 3, xi0=[1.0, 0.0, 0.5])
    np.testing.assert_array_equal(tr.g[0], g0)


def test_runtime_initial_needs_numpy_only():
    code = ("import sys, hpgen.runtime.initial, hpgen.runtime; "
            "bad = [m for m in ('sympy', 'casadi', 'jinja2', 'yaml') if m in sys.modules]; "
            "print(bad)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"}, check=True)
    assert out.stdout.strip() == "[]"
