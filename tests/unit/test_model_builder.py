"""Models declared in Python (hpgen.model.builder): a mapping with the model file's keys and a
ModelBuilder with SymPy expressions compile into the module of the equivalent YAML file (the
same content hash, a cache hit, bitwise the same run), checked by the loader's rules with
one-line errors naming the field."""
from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import hpgen
from hpgen.api import CompileOptions, content_hash, model_source
from hpgen.errors import ModelError
from hpgen.model import load_model_text
from hpgen.model.builder import ModelBuilder, model_text

REPO = Path(hpgen.__file__).resolve().parents[1]

DAMPED_TOP = """\
name: top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, c: 0.1}
runtime_parameters: [c]
lagrangian: I[0]*xi[0]**2/2 + I[1]*xi[1]**2/2 + I[2]*xi[2]**2/2 - Mg*R[2, 2]
forces: ["-c*xi[0]", "-c*xi[1]", "-c*xi[2]"]
scene: {h: 0.05, steps: 40, initial: {g: {rotvec: [0.3, 0.2, 0.0]}, xi: [0.2, 1.0, 3.0]}}
"""
SCENE = {"h": 0.05, "steps": 40, "initial": {"g": {"rotvec": [0.3, 0.2, 0.0]},
                                             "xi": [0.2, 1.0, 3.0]}}


def damped_top() -> ModelBuilder:
    m = ModelBuilder("top", "SO3")
    inertia, Mg = m.parameter("I", [1.0, 5.0, 6.0]), m.parameter("Mg", 1.0)
    c = m.parameter("c", 0.1, runtime=True)
    xi, R = m.xi, m.R
    m.lagrangian = sum(inertia[i] * xi[i]**2 for i in range(3)) / 2 - Mg * R[2, 2]
    m.forces = [-c * xi[0], -c * xi[1], -c * xi[2]]
    m.scene = SCENE
    return m


def _hash(model) -> str:
    return content_hash(model_source(model)[1], CompileOptions())


def test_mapping_and_builder_have_the_yaml_files_hash(tmp_path):
    path = tmp_path / "top.yaml"
    path.write_text(DAMPED_TOP)
    mapping = {"name": "top", "group": "SO3",
               "parameters": {"I": np.array([1.0, 5.0, 6.0]), "Mg": np.float64(1.0), "c": 0.1},
               "runtime_parameters": ("c",),
               "lagrangian": "I[0]*xi[0]**2/2 + I[1]*xi[1]**2/2 + I[2]*xi[2]**2/2 - Mg*R[2, 2]",
               "forces": ["-c*xi[0]", "-c*xi[1]", "-c*xi[2]"], "scene": SCENE}
    assert _hash(mapping) == _hash(damped_top()) == _hash(path)
    # and a different model has a different hash
    other = damped_top()
    other.lagrangian = other.lagrangian + other.xi[0]
    assert _hash(other) != _hash(path)
    a = load_model_text(DAMPED_TOP)
    b = load_model_text(damped_top().to_yaml())
    assert sp.simplify(a.lagrangian - b.lagrangian) == 0 and a.forces == b.forces


@pytest.mark.parametrize("backend", ["python", "c"])
def test_builder_compiles_the_yaml_files_module(tmp_path, cache_dir, backend):
    path = tmp_path / "top.yaml"
    path.write_text(DAMPED_TOP)
    first = hpgen.build(path, backend=backend, cache_dir=cache_dir)
    again = hpgen.build(damped_top(), backend=backend, cache_dir=cache_dir)
    assert again.cached and again.module_dir == first.module_dir
    assert again.meta["hash"] == first.meta["hash"]
    sc = load_model_text(DAMPED_TOP).scene
    runs = [m.load().simulate(np.array(sc.g0), sc.h, sc.steps, xi0=sc.xi0, params={"c": 0.3})
            for m in (first, again)]
    np.testing.assert_array_equal(runs[0].g, runs[1].g)
    np.testing.assert_array_equal(runs[0].mu, runs[1].mu)
    assert np.all(np.diff(runs[0].energy()) < 0)          # damped: the energy decreases


def test_inputs_and_time():
    m = ModelBuilder("sat", "SE3")
    u = [m.input(f"u{i}") for i in range(2)]
    k = m.parameter("k", [[1.0, 0.0], [0.0, 2.0]])
    xi, x, t = m.xi, m.x, m.t
    m.lagrangian = sum(xi[i]**2 for i in range(6)) / 2 - sp.exp(-t) * x[2] + k[1, 1] * 0
    m.forces = [0, 0, 0, u[0] * sp.cos(t), u[1], sp.sqrt(2) * sp.pi * xi[5]]
    model = load_model_text(m.to_yaml(), "<mapping>")
    assert model.inputs == ("u0", "u1") and model.time_dependent and model.forced
    text = m.to_yaml()
    assert "forces: [0, 0, 0, u0*cos(t), u1, 'sqrt(2)*pi*xi[5]']" in text
    assert "x[2]*exp(-t)" in text


@pytest.mark.parametrize("mapping, field, words", [
    ({"name": "m", "group": "SO3", "lagrangian": "0.5*dot(xi, xi)", "colour": 1},
     "colour", "unknown key"),
    ({"name": "m", "group": "SO4", "lagrangian": "0.5*dot(xi, xi)"}, "group", "SO4"),
    ({"name": "m", "group": "SO3", "lagrangian": "__import__('os')"}, "lagrangian", "dunder"),
    ({"name": "m", "group": "SO3", "lagrangian": "0.5*dot(xi, xi)",
      "scene": {"h": float("nan"), "steps": 1, "initial": {"xi": [1, 2, 3]}}},
     "scene.h", "finite"),
    ({"name": "m", "group": "SO3", "lagrangian": "0.5*dot(xi, xi)", "parameters": {"a": "1"}},
     "parameters.a", "quoted strings are not numbers"),
    ({"name": "m", "group": "SO3", "lagrangian": "0.5*dot(xi, xi)", 3: 4}, None, "strings"),
    ({"name": "m", "group": "SO3", "lagrangian": sp.Symbol("a")}, "lagrangian", "SymPy"),
    ({"name": "m", "group": "SO3", "lagrangian": object()}, "lagrangian", "object"),
])
def test_mapping_errors_name_the_field(mapping, field, words, cache_dir):
    with pytest.raises(ModelError) as info:
        hpgen.build(mapping, backend="python", cache_dir=cache_dir)
    msg = str(info.value)
    assert msg.startswith("<mapping>: ") and words.lower() in msg.lower() and "\n" not in msg
    assert info.value.line is None and re.match(r"<mapping>:\d", msg) is None
    if field:
        assert info.value.field == field or info.value.field.startswith(field), msg


def test_builder_refuses_what_the_language_lacks(cache_dir):
    m = ModelBuilder("m", "SO3")
    for lag, words in ((sp.Abs(m.xi[0]), "Abs"), (sp.Symbol("y") * m.xi[0], "'y'"),
                       (sp.atan(m.xi[0]), "atan"), (sp.I * m.xi[0], "ImaginaryUnit"),
                       (m.xi, "expected a SymPy scalar"), (sp.oo * m.xi[0], "Infinity")):
        m.lagrangian = lag
        with pytest.raises(ModelError) as info:
            m.to_mapping()
        assert info.value.field == "lagrangian" and words in str(info.value), str(info.value)
    with pytest.raises(ModelError, match="group"):
        ModelBuilder("m", "SO4")
    m.parameter("c", 1.0)
    with pytest.raises(ModelError, match="declared twice"):
        m.parameter("c", 2.0)
    m.lagrangian = m.xi[0]**2 + m.t
    m.parameter("t", 1.0)            # the loader's rules: t is reserved
    with pytest.raises(ModelError, match="parameters.t: parameter name 't' is reserved"):
        hpgen.build(m, backend="python", cache_dir=cache_dir)
    assert ModelBuilder("m", "SO3").R.shape == (3, 3) and ModelBuilder("m", "SO3").x is None
    prod = ModelBuilder("m", ["SO3", "R3"])
    assert prod.xi.shape == (6, 1) and prod.g.shape == (7, 7) and prod.R is None


def test_floats_print_exactly():
    m = ModelBuilder("m", "R1")
    m.lagrangian = sp.Float(0.1) * m.xi[0]**2 + sp.Float(1 / 3) * m.xi[0]**4
    model = load_model_text(m.to_yaml())
    xi0 = model.xi_symbols[0]
    assert model.lagrangian.coeff(xi0**2) == sp.Float(0.1) and \
        float(model.lagrangian.coeff(xi0**4)) == 1 / 3


def test_compile_refuses_other_objects():
    with pytest.raises(ModelError, match="model: expected the path of a model file, a mapping"):
        hpgen.compile(3)
    with pytest.raises(ModelError, match="mapping with the model file's keys"):
        model_text([1, 2])


def test_api_page_example_runs(monkeypatch, tmp_path):
    page = (REPO / "docs" / "api.md").read_text()
    block = next(b for b in re.findall(r"```python\n(.*?)```", page, re.S) if "ModelBuilder(" in b)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    scope: dict = {}
    exec(compile(block, "docs/api.md", "exec"), scope)        # the page's own example
    integ = scope["integ"]
    assert integ.meta["module"].startswith("top_")
    tr = integ.simulate(np.eye(3), 0.05, 10, xi0=[0.2, 1.0, 3.0], params={"c": 0.2})
    assert np.all(np.isfinite(tr.mu))
    assert "runtime_parameters: [c]" in scope["m"].to_yaml()
