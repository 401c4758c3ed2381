"""Model files: YAML with lines, the schema, parameters, integrator and scene validation."""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from hpgen.errors import ModelError
from hpgen.model import load_model, load_model_text

HEAVY_TOP = """\
name: heavy_top                 # a comment
group: SO3
parameters:
  I: [1.0, 5.0, 6.0]
  Mg: 1.0
  chi: [0.0, 0.0, 1.0]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - \
  Mg*(R[2,0]*chi[0] + R[2,1]*chi[1] + R[2,2]*chi[2])
integrator:
  tableau: stormer-verlet
  tau: cay
  rkmk: exact
scene:
  h: 0.05
  steps: 2000
  initial: {g: identity, xi: [0.2, 1.0, 3.0]}
  record: [g, mu, energy, momentum]
  every: 10
"""

FREE_RB = "name: rb\ngroup: SO3\nlagrangian: 0.5*(2*xi[0]**2 + xi[1]**2 + (2/3)*xi[2]**2)\n"


def err(text, filename="m.yaml") -> str:
    with pytest.raises(ModelError) as info:
        load_model_text(text, filename=filename)
    return str(info.value)


def with_scene(scene: str, group="SO3", lag="0.5*dot(xi, xi)") -> str:
    return f"name: m\ngroup: {group}\nlagrangian: {lag}\nscene:\n{scene}"


# ---- valid files --------------------------------------------------------------------------------
def test_heavy_top_loads(tmp_path):
    p = tmp_path / "heavy_top.yaml"
    p.write_text(HEAVY_TOP)
    m = load_model(p)
    assert m.name == "heavy_top" and m.path == str(p) and m.source == HEAVY_TOP
    assert (m.group.n, m.group.d) == (3, 3) and m.group_spec == "SO3"
    xi = [sp.Symbol(f"xi_{k}", real=True) for k in range(3)]
    g = [[sp.Symbol(f"g_{i}_{j}", real=True) for j in range(3)] for i in range(3)]
    assert m.xi_symbols == tuple(xi)
    assert m.g_symbols == tuple(tuple(r) for r in g)
    assert sp.simplify(m.lagrangian - (sp.Rational(1, 2) * xi[0]**2 + sp.Rational(5, 2) * xi[1]**2
                                       + 3 * xi[2]**2 - g[2][2])) == 0
    assert not m.left_invariant
    assert dict(m.parameters) == {"I": (1.0, 5.0, 6.0), "Mg": 1.0, "chi": (0.0, 0.0, 1.0)}
    assert m.lagrangian.free_symbols == {xi[0], xi[1], xi[2], g[2][2]}  # parameters substituted
    assert m.integrator.tau == "cay" and m.integrator.rkmk == "exact"
    assert m.integrator.tableau == "stormer-verlet"
    s = m.scene
    assert s.h == 0.05 and s.steps == 2000 and s.every == 10
    assert s.g0 == ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    assert s.xi0 == (0.2, 1.0, 3.0) and s.mu0 is None
    assert s.record == ("g", "mu", "energy", "momentum")


def test_free_rigid_body_is_left_invariant_and_exact():
    m = load_model_text(FREE_RB)
    assert m.left_invariant and m.scene is None
    x = m.xi_symbols
    assert sp.expand(m.lagrangian - (x[0]**2 + x[1]**2 / 2 + x[2]**2 / 3)) == 0


def test_se3_aliases_x_and_R():
    m = load_model_text("name: body\ngroup: SE3\nparameters: {m: 2, c: [0, 0, 1]}\n"
                        "lagrangian: 0.5*m*dot(xi, xi) - m*dot(c, x) + R[0, 1]\n")
    assert (m.group.n, m.group.d) == (4, 6)
    g = m.g_symbols
    free = m.lagrangian.free_symbols - set(m.xi_symbols)
    assert free == {g[2][3], g[0][1]}      # x = g[0:3, 3], R = g[0:3, 0:3]


def test_product_group_names():
    m = load_model_text("name: two\ngroup: [SO3, R2]\n"
                        "lagrangian: dot(xi_0, xi_0) + xi_1[1]**2 + R_0[1, 1] + x_1[0] + g[4, 5]\n")
    assert (m.group.n, m.group.d) == (6, 5) and m.group_spec == ["SO3", "R2"]
    g, xi = m.g_symbols, m.xi_symbols
    assert m.lagrangian.free_symbols == {xi[0], xi[1], xi[2], xi[4], g[1][1], g[3][5], g[4][5]}
    assert "R is not defined for a product group" in err(
        "name: two\ngroup: [SO3, R2]\nlagrangian: xi[0]**2 + R[0, 0]\n")


def test_scientific_notation_and_ints():
    m = load_model_text("name: m\ngroup: SO2\nparameters: {a: 1e-3, b: 3}\n"
                        "lagrangian: a*xi[0]**2 + b*xi[0]\n")
    assert dict(m.parameters) == {"a": 1e-3, "b": 3.0}


def test_duration_and_product_initial_list():
    m = load_model_text(with_scene(
        "  h: 0.1\n  duration: 2.0\n  initial:\n"
        "    g: [{rotvec: [0, 0, 1.5]}, {position: [1, 2]}]\n"
        "    mu: [1, 2, 3, 4, 5]\n", group="[SO3, R2]", lag="dot(xi, xi)"))
    s = m.scene
    assert s.steps == 20 and s.mu0 == (1.0, 2.0, 3.0, 4.0, 5.0) and s.xi0 is None
    G = np.array(s.g0)
    assert np.allclose(G[:3, :3], [[np.cos(1.5), -np.sin(1.5), 0], [np.sin(1.5), np.cos(1.5), 0],
                                   [0, 0, 1]])
    assert G[3:, 3:].tolist() == [[1, 0, 1], [0, 1, 2], [0, 0, 1]]


def test_se2_angle_position():
    m = load_model_text(with_scene("  h: 0.1\n  steps: 3\n  initial: {g: {angle: 0.5, position: "
                                   "[1, 2]}, xi: [0, 0, 1]}\n", group="SE2"))
    assert np.allclose(m.scene.g0, [[np.cos(.5), -np.sin(.5), 1], [np.sin(.5), np.cos(.5), 2],
                                    [0, 0, 1]])


# ---- malformed files ----------------------------------------------------------------------------
def test_malformed_yaml():
    msg = err("name: a\ngroup: [SO3\nlagrangian: xi[0]\n")
    assert msg.startswith("m.yaml:") and "malformed YAML" in msg and "\n" not in msg


def test_empty_and_non_mapping():
    assert "empty" in err("")
    assert "m.yaml:1:" in err("- a\n- b\n") and "mapping" in err("- a\n")


def test_unknown_top_level_key():
    msg = err(FREE_RB + "lagrangien: 1\n")
    assert msg.startswith("m.yaml:4: lagrangien:") and "allowed keys" in msg and "scene" in msg


def test_unknown_scene_key_lists_allowed():
    msg = err(with_scene("  h: 0.1\n  stepz: 3\n"))
    assert "m.yaml:6: scene.stepz: unknown key" in msg and "duration" in msg


def test_duplicate_key():
    msg = err("name: a\nname: b\ngroup: SO3\nlagrangian: xi[0]**2\n")
    assert msg.startswith("m.yaml:2: name: duplicate key") and "line 1" in msg


def test_missing_lagrangian():
    msg = err("name: a\ngroup: SO3\n")
    assert "lagrangian" in msg and "missing" in msg and msg.startswith("m.yaml")


def test_python_tag_rejected():
    msg = err("name: a\ngroup: !!python/object/apply:os.system ['touch /tmp/x']\n"
              "lagrangian: xi[0]\n")
    assert "m.yaml:2" in msg and "tag" in msg


def test_schema_version():
    assert load_model_text("schema: 1\n" + FREE_RB).name == "rb"
    assert "schema: unsupported schema 2" in err("schema: 2\n" + FREE_RB)


def test_unknown_group():
    msg = err("name: a\ngroup: SO4\nlagrangian: xi[0]**2\n")
    assert msg.startswith("m.yaml:2: group:") and "SO4" in msg and "SE3" in msg


@pytest.mark.parametrize("bad", ["R0", "Rx"])
def test_malformed_rn(bad):
    msg = err(f"name: a\ngroup: {bad}\nlagrangian: xi[0]**2\n")
    assert msg.startswith("m.yaml:2: group:") and "R<n>" in msg


def test_group_too_large():
    assert "too large" in err("name: a\ngroup: R500\nlagrangian: xi[0]**2\n")


@pytest.mark.parametrize("name", ["int", "while", "main"])
def test_c_keyword_model_name(name):
    msg = err(f"name: {name}\ngroup: SO3\nlagrangian: xi[0]**2\n")
    assert msg.startswith("m.yaml:1: name:") and "C keyword" in msg


@pytest.mark.parametrize("name", ["9abc", "a-b", "_x", "'a b'"])
def test_non_identifier_model_name(name):
    msg = err(f"name: {name}\ngroup: SO3\nlagrangian: xi[0]**2\n")
    assert msg.startswith("m.yaml:1: name:") and ("identifier" in msg or "'_'" in msg)


@pytest.mark.parametrize("pname,expect", [("int", "C keyword"), ("xi", "reserved"),
                                          ("pi", "reserved"), ("R_0", "reserved"),
                                          ("lambda", "Python keyword"), ("__x", "'_'"),
                                          ("a.b", "identifier")])
def test_bad_parameter_names(pname, expect):
    msg = err(f"name: m\ngroup: SO3\nparameters:\n  {pname}: 1\nlagrangian: xi[0]**2\n")
    assert msg.startswith(f"m.yaml:4: parameters.{pname}:") and expect in msg


@pytest.mark.parametrize("value,expect", [
    ("'1.0'", "quoted strings are not numbers"), ("abc", "expected a number"),
    (".inf", "finite"), (".nan", "finite"), ("true", "boolean"), ("[]", "non-empty"),
    ("[[1, 2], [3]]", "equal length"), ("[[[1]]]", "expected"), ("{a: 1}", "expected a number"),
    ("[1, x]", "expected a number")])
def test_non_numeric_parameter(value, expect):
    msg = err(f"name: m\ngroup: SO3\nparameters:\n  k: {value}\nlagrangian: xi[0]**2\n")
    assert msg.startswith("m.yaml:4: parameters.k") and expect in msg


def test_integrator_choices():
    msg = err(FREE_RB + "integrator:\n  tau: expo\n")
    assert msg.startswith("m.yaml:5: integrator.tau:") and "exp, cay, skew" in msg
    msg = err(FREE_RB + "integrator:\n  rkmk: sloppy\n")
    assert "integrator.rkmk" in msg and "exact, truncated" in msg
    msg = err(FREE_RB + "integrator:\n  order: 2\n")
    assert "integrator.order: unknown key" in msg and "tableau" in msg
    m = load_model_text(FREE_RB + "integrator:\n  tau: skew\n")
    assert m.integrator.tau == "skew" and m.integrator.tableau == "stormer-verlet"


def test_integrator_tableau():
    pytest.importorskip("hpgen.tableaus", exc_type=ImportError)
    msg = err(FREE_RB + "integrator:\n  tableau: no-such-method\n")
    assert msg.startswith("m.yaml:5: integrator.tableau:")
    msg = err(FREE_RB + "integrator:\n  tableau: {A: [[0.5]], b: [x]}\n")
    assert "integrator.tableau.b[0]" in msg and "number" in msg
    m = load_model_text(FREE_RB + "integrator:\n  tableau: {A: [[0.5]], b: [1.0]}\n")
    assert not isinstance(m.integrator.tableau, str)


def test_file_errors(tmp_path):
    msg = str(pytest.raises(ModelError, load_model, tmp_path / "missing.yaml").value)
    assert "missing.yaml" in msg and "cannot read" in msg
    big = tmp_path / "big.yaml"
    big.write_text("#" * (3 * 1024 * 1024))
    assert "too large" in str(pytest.raises(ModelError, load_model, big).value)
    bad = tmp_path / "bad.yaml"
    bad.write_bytes(b"name: \xff\n")
    assert "UTF-8" in str(pytest.raises(ModelError, load_model, bad).value)


def test_alias_bomb_and_recursion():
    bomb = "a: &a [1,1,1,1,1,1,1,1,1,1]\n" + "".join(
        f"{c}: &{c} [*{p},*{p},*{p},*{p},*{p},*{p},*{p},*{p},*{p},*{p}]\n"
        for p, c in zip("abcdefg", "bcdefgh"))
    assert "too large" in err(bomb)
    assert "nesting" in err("a: " + "[" * 2000 + "]" * 2000 + "\n")


# ---- scene --------------------------------------------------------------------------------------
@pytest.mark.parametrize("h,expect", [("0", "h != 0"), (".nan", "finite"),
                                      (".inf", "finite"), ("'0.1'", "quoted")])
def test_bad_h(h, expect):
    msg = err(with_scene(f"  h: {h}\n  steps: 3\n  initial: {{xi: [1, 2, 3]}}\n"))
    assert msg.startswith("m.yaml:5: scene.h:") and expect in msg


@pytest.mark.parametrize("steps,expect", [("-1", "integer"), ("2.5", "integer"),
                                          ("true", "integer"), ("1e12", "integer")])
def test_bad_steps(steps, expect):
    msg = err(with_scene(f"  h: 0.1\n  steps: {steps}\n  initial: {{xi: [1, 2, 3]}}\n"))
    assert msg.startswith("m.yaml:6: scene.steps:") and expect in msg


def test_negative_h_is_a_backward_scene(tmp_path):
    """h < 0 runs backwards in time, as the API and ``--h`` do; duration counts |h| steps."""
    sc = load_model_text(with_scene("  h: -0.25\n  duration: 1.5\n  initial: {xi: [1, 2, 3]}\n"),
                         "m.yaml").scene
    assert sc.h == -0.25 and sc.steps == 6
    import subprocess
    import sys
    from pathlib import Path
    model = tmp_path / "back.yaml"
    model.write_text(with_scene("  h: -0.25\n  steps: 4\n  initial: {xi: [0.1, 0.2, 0.3]}\n"))
    res = subprocess.run([sys.executable, "-m", "hpgen", "run", str(model), "--backend",
                          "python", "--out", str(tmp_path / "o.npz"), "--cache-dir",
                          str(tmp_path / "cache")], capture_output=True, text=True,
                         cwd=Path(__file__).resolve().parents[2])
    assert res.returncode == 0, res.stderr
    np.testing.assert_array_equal(np.load(tmp_path / "o.npz")["t"], [0, -0.25, -0.5, -0.75, -1])


def test_steps_and_duration_rules():
    assert "not both" in err(with_scene("  h: 0.1\n  steps: 3\n  duration: 1\n"))
    msg = err(with_scene("  h: 0.3\n  duration: 1\n  initial: {xi: [1, 2, 3]}\n"))
    assert "scene.duration" in msg and "not an integer number of steps" in msg
    assert "missing steps" in err(with_scene("  h: 0.1\n  initial: {xi: [1, 2, 3]}\n"))


def test_initial_g_off_group():
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial:\n    g: [[1, 0, 0], [0, 1, 0], "
                         "[0, 0, 1.001]]\n    xi: [1, 2, 3]\n"))
    assert msg.startswith("m.yaml:8: scene.initial.g:") and "not on SO3" in msg
    assert "1e-10" in msg and "0.002" in msg
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial:\n    g: [[1, 0], [0, 1]]\n"
                         "    xi: [1, 2, 3]\n"))
    assert "scene.initial.g" in msg and "3 x 3" in msg
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial:\n    g: [[1, 0, 5], [0, 1, 0], "
                         "[0, 1, 1]]\n    xi: [1, 2, 3]\n", group="SE2"))
    assert "bottom row" in msg
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial:\n    g: {angle: 1}\n"
                         "    xi: [1, 2, 3]\n"))
    assert "scene.initial.g.angle: unknown key" in msg and "rotvec" in msg


def test_initial_velocity_rules():
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial: {xi: [1, 2]}\n"))
    assert msg.startswith("m.yaml:7: scene.initial.xi:") and "3 numbers" in msg
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial:\n    mu: [1, .nan, 3]\n"))
    assert msg.startswith("m.yaml:8: scene.initial.mu[1]:") and "finite" in msg
    assert "exactly one of xi or mu" in err(
        with_scene("  h: 0.1\n  steps: 1\n  initial: {xi: [1, 2, 3], mu: [1, 2, 3]}\n"))


def test_record_and_every():
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial: {xi: [1, 2, 3]}\n  record: [g, phi]\n"))
    assert "scene.record[1]" in msg and "energy" in msg
    msg = err(with_scene("  h: 0.1\n  steps: 1\n  initial: {xi: [1, 2, 3]}\n  every: 0\n"))
    assert "scene.every" in msg and ">= 1" in msg
