"""Families of bodies (group G^N): the constructs of the model language and their refusals."""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from hpgen.api import CompileOptions, content_hash
from hpgen.errors import ModelError
from hpgen.model import load_model_text
from hpgen.model.families import BodyFamily, FamilyGroup, FamilySum
from hpgen.model.overrides import apply_overrides, parse_assignment


def model(lag: str, group="SE3^N", params="{N: 3, m: 1.0, c: [0.0, 0.0, -0.5]}", extra=""):
    return load_model_text(f"name: m\ngroup: {group}\nparameters: {params}\nlagrangian: {lag}\n"
                           + extra, filename="m.yaml")


def err(lag: str, group="SE3^N", params="{N: 3, m: 1.0, c: [0.0, 0.0, -0.5]}",
        extra="") -> str:
    with pytest.raises(ModelError) as info:
        model(lag, group, params, extra)
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith("m.yaml:")
    return msg


def xi(k):
    return sp.Symbol(f"xi_{k}", real=True)


def g(i, j):
    return sp.Symbol(f"g_{i}_{j}", real=True)


KIN = "0.5*norm2(xi[0])"


# ---- the group ----------------------------------------------------------------------------------
@pytest.mark.parametrize("spec, params, name, count", [
    ("SE3^N", "{N: 3}", "[SE3, SE3, SE3]", 3),
    ("SO3^2", "{}", "[SO3, SO3]", 2),
    ("R2 ^ K", "{K: 1}", "[R2]", 1),
    ("SE2^N", "{N: 2}", "[SE2, SE2]", 2),
])
def test_family_group(spec, params, name, count):
    m = model(KIN, group=f'"{spec}"', params=params)
    assert isinstance(m.group, FamilyGroup) and m.group.name == name
    assert m.family.count == count and m.family.body == name[1:4].rstrip(",]")
    assert m.group.d == count * m.group.parts[0].d


def test_body_names_equal_the_product_aliases():
    m = model("sum(i, dot(xi[i], xi[i]) + R[i][2, 2] + x[i][0] + g[i][3, 3]) + R_1[0, 0]"
              " + x_2[1] + dot(xi_0, xi_0)")
    ref = sum(sum(xi(6 * i + k)**2 for k in range(6)) + g(4 * i + 2, 4 * i + 2)
              + g(4 * i, 4 * i + 3) + g(4 * i + 3, 4 * i + 3) for i in range(3)) \
        + g(4, 4) + g(9, 11) \
        + sum(xi(k)**2 for k in range(6))
    assert sp.expand(m.lagrangian - ref) == 0


def test_angular_and_linear_velocities():
    se3 = model("sum(i, i*norm2(w[i]) + (i + 10)*norm2(v[i]))")
    ref = sum(i * xi(6 * i + k)**2 + (i + 10) * xi(6 * i + 3 + k)**2
              for i in range(3) for k in range(3))
    assert sp.expand(se3.lagrangian - ref) == 0
    se2 = model("sum(i, w[i]**2 + norm2(v[i]))", group="SE2^N")
    assert sp.expand(se2.lagrangian - sum(xi(k)**2 for k in range(9))) == 0
    so3 = model("sum(i, norm2(w[i]))", group="SO3^N")
    assert sp.expand(so3.lagrangian - sum(xi(k)**2 for k in range(9))) == 0
    rn = model("sum(i, norm2(v[i]) + x[i][1])", group="R2^N")
    assert sp.expand(rn.lagrangian - sum(xi(k)**2 for k in range(6))
                     - sum(g(3 * i + 1, 3 * i + 2) for i in range(3))) == 0


# ---- parameters ---------------------------------------------------------------------------------
def test_body_indexed_parameters_list_shared_and_rows():
    m = model("sum(i, m[i]*norm2(v[i]) + k[i]*w[i][0]**2 + dot(J[i], w[i]))",
              params="{N: 3, m: [1, 2, 3], k: 5, J: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}")
    ref = sum((i + 1) * xi(6 * i + 3 + k)**2 for i in range(3) for k in range(3)) \
        + sum(5 * xi(6 * i)**2 + xi(6 * i + i) for i in range(3))
    assert sp.expand(m.lagrangian - ref) == 0


def test_shared_vector_and_literal_body_index():
    m = model("sum(i, 0.5*norm2(xi[i])) - (R[0] @ c)[2] + m*x[N - 1][2]")
    assert sp.expand(m.lagrangian - sum(xi(k)**2 for k in range(18)) / 2
                     - 0.5 * g(2, 2) - g(10, 11)) == 0


# ---- sums ---------------------------------------------------------------------------------------
def test_sum_ranges_nested_and_empty():
    m = model("sum(i, norm2(xi[i])) + sum(i, 1, N, (i + 0.5)*x[i][2])"
              " + sum(i, sum(j, i + 1, N, x[i][0]*x[j][0]))")
    ref = sum(xi(k)**2 for k in range(18)) + 1.5 * g(6, 7) + 2.5 * g(10, 11) \
        + g(0, 3) * g(4, 7) + g(0, 3) * g(8, 11) + g(4, 7) * g(8, 11)
    assert sp.expand(m.lagrangian - ref) == 0
    one = model("sum(i, norm2(xi[i])) + sum(i, 1, N, x[i][2])", params="{N: 1}")
    assert sp.expand(one.lagrangian - sum(xi(k)**2 for k in range(6))) == 0


def test_sum_outside_a_family_with_a_range():
    m = model("sum(k, 0, 3, I[k]*xi[k]**2)", group="SO3", params="{I: [1, 2, 3]}")
    assert sp.expand(m.lagrangian - (xi(0)**2 + 2 * xi(1)**2 + 3 * xi(2)**2)) == 0


def test_vector_functions():
    m = model("norm2(cross(w[0], c)) + dot(transpose(R[1]) @ c, c) + (R[0] @ c)[2]",
              group="SE3^N")
    w = sp.Matrix([xi(0), xi(1), xi(2)])
    c = sp.Matrix([0, 0, -0.5])
    R1 = sp.Matrix(3, 3, lambda a, b: g(4 + a, 4 + b))
    ref = w.cross(c).dot(w.cross(c)) + (R1.T * c).dot(c) - 0.5 * g(2, 2)
    assert sp.expand(m.lagrangian - ref) == 0


def test_family_structure_is_kept():
    m = model("sum(i, 0.5*m*norm2(v[i])) - 2*x[0][2] - sum(j, 1, N, m*x[j][2]*x[j - 1][2])")
    fam = m.family
    assert isinstance(fam, BodyFamily) and (fam.body, fam.count, fam.count_name) == \
        ("SE3", 3, "N")
    assert fam.sums == (FamilySum("i", 0, 3, "0", "N", "0.5*m*norm2(v[i])", 1),
                        FamilySum("j", 1, 3, "1", "N", "m*x[j][2]*x[j - 1][2]", -1))
    assert fam.rest == "- 2*x[0][2]"
    assert model("xi[0]**2", group="SE3", params="{N: 3}").family is None


def test_scene_one_body_initial_state_and_family_records():
    scene = ("scene:\n  h: 0.01\n  steps: 3\n  initial: {g: {rotvec: [0.1, 0, 0]}, "
             "xi: [1, 2, 3, 4, 5, 6]}\n  record: [g, {tip: \"x[N - 1][2] + R[0][2, 2]\"}]\n")
    m = model("sum(i, norm2(xi[i]))", extra=scene)
    assert m.scene.xi0 == (1.0, 2.0, 3.0, 4.0, 5.0, 6.0) * 3
    G = np.array(m.scene.g0)
    assert np.allclose(G[4:7, 4:7], G[0:3, 0:3]) and abs(G[1, 1] - np.cos(0.1)) < 1e-15
    assert m.scene.expressions[0].expr == g(10, 11) + g(2, 2)


# ---- overrides ----------------------------------------------------------------------------------
CHAIN = ("# a comment\nname: m\ngroup: SE3^N\nparameters:\n  N: 2   # bodies\n  m: [1.0, 2.0]\n"
         "lagrangian: sum(i, m[i]*norm2(xi[i]))\n")


def test_override_changes_the_model_and_its_hash():
    text = apply_overrides(CHAIN, {"N": 3, "m": [1.0, 2.0, 0.5]})
    assert "# bodies" in text and "# a comment" in text
    m = load_model_text(text, "m.yaml")
    assert m.family.count == 3 and dict(m.parameters)["m"] == (1.0, 2.0, 0.5)
    opts = CompileOptions()
    assert content_hash(text, opts) != content_hash(CHAIN, opts)
    assert apply_overrides(CHAIN, {}) == CHAIN
    assert parse_assignment("N=8") == ("N", 8)
    assert parse_assignment(" J = [1, 2.5, 1e-3]") == ("J", [1, 2.5, 0.001])
    assert parse_assignment("k=1e4") == ("k", 1e4)


@pytest.mark.parametrize("overrides, expect", [
    ({"M": 3}, "cannot set 'M': it is not a parameter of the model"),
    ({"N": "x"}, "expected a finite number"),
    ({"N": float("nan")}, "expected a finite number"),
])
def test_override_refusals(overrides, expect):
    with pytest.raises(ModelError) as info:
        apply_overrides(CHAIN, overrides, file="c.yaml")
    assert expect in str(info.value) and str(info.value).startswith("c.yaml: parameters.")


@pytest.mark.parametrize("text, expect", [
    ("N", "expected NAME=VALUE"), ("=3", "expected NAME=VALUE"),
    ("N=[1, {a: 2}]", "expected a finite number"), ("N=import os", "expected a finite number"),
])
def test_set_option_refusals(text, expect):
    with pytest.raises(ModelError) as info:
        parse_assignment(text)
    assert expect in str(info.value) and "option set" in str(info.value)


def test_overridden_n_is_validated_like_the_file():
    with pytest.raises(ModelError) as info:
        load_model_text(apply_overrides(CHAIN, {"N": 0}), "c.yaml")
    assert "c.yaml:5: parameters.N:" in str(info.value) and "positive integer" in str(info.value)
    with pytest.raises(ModelError) as info:
        load_model_text(apply_overrides(CHAIN, {"N": 3}), "c.yaml")
    assert "has 2 entries but the family has N = 3 bodies" in str(info.value)


# ---- refusals -----------------------------------------------------------------------------------
@pytest.mark.parametrize("lag, group, params, expect", [
    ("sum(i, norm2(xi[i])) + x[3][0]", "SE3^N", None,
     "body index 3 out of range for x: the family has N = 3 bodies (0..2)"),
    ("sum(i, norm2(xi[i])) + sum(i, 1, N + 1, x[i][0])", "SE3^N", None,
     "body index 3 out of range"),
    ("sum(i, norm2(xi[i])) + x[i - 1][0]", "SE3^N", None, "not a sum variable or a parameter"),
    ("sum(i, 1, N, norm2(xi[i - 2]))", "SE3^N", None, "body index -1 out of range"),
    ("sum(i, m[i]*norm2(xi[i]))", "SE3^N", "{N: 3, m: [1.0, 2.0]}",
     "the body-indexed parameter m has 2 entries but the family has N = 3 bodies"),
    ("sum(i, m[i, 0]*norm2(xi[i]))", "SE3^N", None, "the parameter m is a scalar"),
    ("sum(i, J[i, 3]*norm2(xi[i]))", "SE3^N", "{N: 3, J: [[1, 2, 3], [1, 2, 3], [1, 2, 3]]}",
     "index [0, 3] out of range for the parameter J (shape 3 x 3)"),
    ("sum(m, norm2(xi[m]))", "SE3^N", None, "the sum variable 'm' shadows a name"),
    ("sum(x, norm2(xi[x]))", "SE3^N", None, "the sum variable 'x' shadows a name"),
    ("sum(N, norm2(xi[N]))", "SE3^N", None, "the sum variable 'N' shadows a name"),
    ("sum(i, sum(i, norm2(xi[i])))", "SE3^N", None, "the sum variable 'i' shadows a name"),
    ("sum(sin, norm2(xi[0]))", "SE3^N", None, "shadows a name"),
    ("sum(i, xi[i][0]**2)", "SO3", "{}", "sum(i, term) sums over the bodies of a family"),
    ("sum(i, 1, xi[i][0]**2)", "SE3^N", None, "sum takes (i, term)"),
    ("sum(2, xi[0][0]**2)", "SE3^N", None, "sum takes (i, term)"),
    ("sum(i, 0, 20000, xi[0][0]**2)", "SE3^N", None, "sum over 20000 terms (limit 10000)"),
    ("sum(i, 0, 10**9, xi[0][0]**2)", "SE3^N", None, "expected an integer: a literal"),
    ("sum(i, 0, 2.5, xi[0][0]**2)", "SE3^N", None, "expected an integer: a literal"),
    ("sum(i, 0, sin(1), xi[0][0]**2)", "SE3^N", None, "expected an integer: a literal"),
    ("sum(i, 0, N*N*N*N*N*N*N*N*N*N*N*N*N*N*N*N*N*N*N*N, xi[0][0]**2)", "SE3^N", None,
     "index expression too large"),
    ("norm2(xi)", "SE3^N", None, "xi is indexed by body in a family model: write xi[i]"),
    ("norm2(xi[0]) + R[0, 1, 1]", "SE3^N", None, "indices must be one or two"),
    ("norm2(xi[0]) + R[0, 1][0]", "SE3^N", None, "R takes one body index"),
    ("norm2(xi[0]) + xi[7][0]", "SE3^N", None, "body index 7 out of range for xi"),
    ("norm2(cross(xi[0], c))", "SE3^N", None, "cross: expected two vectors of length 3"),
    ("norm2(xi[0]) + transpose(c)[0]", "SE3^N", None, "transpose: expected a matrix"),
    ("norm2(xi[0]) + norm2(m)", "SE3^N", None, "norm2: expected a vector or a matrix"),
    ("norm2(xi[0]) + norm2(R[0] @ xi[0])", "SE3^N", None, "dot: shapes do not match"),
    ("norm2(xi[0]) + xi[0][m]", "SE3^N", None, "not an integer parameter"),
    ("norm2(w[0])", "SO3^N", "{N: 2, w: 1.0}", "the parameter 'w' has the name of a body"),
    ("norm2(v[0])", "SO3^N", None, "unknown name 'v'"),
    ("norm2(xi[0])", "SE3^N", "{N: 0}", "the parameter N of 'SE3^N' must be a positive integer"),
    ("norm2(xi[0])", "SE3^N", "{N: 2.0}", "must be a positive integer"),
    ("norm2(xi[0])", "SE3^N", "{N: -2}", "must be a positive integer"),
    ("norm2(xi[0])", "SE3^N", "{M: 2}", "the body count 'N' of 'SE3^N' is not a parameter"),
    ("norm2(xi[0])", "SE3^N", "{N: 5000}", "too many bodies: 5000 (limit 4096)"),
    ("norm2(xi[0])", "SE3^N", "{N: 257}", "group too large: matrix size 1028, dimension 1542 (limit 1024 each)"),
    ("norm2(xi[0])", "SE4^N", None, "unknown group 'SE4'"),
    ("norm2(xi[0])", "SE3^", None, "malformed family 'SE3^'"),
    ("norm2(xi[0])", "SE3^N^2", None, "malformed family"),
    ("norm2(xi[0])", "[SO3, SE3^N]", None, "it cannot be a factor of a list"),
])
def test_refusals(lag, group, params, expect):
    msg = err(lag, group=f'"{group}"' if not group.startswith("[") else group,
              params=params or "{N: 3, m: 1.0, c: [0.0, 0.0, -0.5]}")
    assert expect in msg, msg


def test_refusal_fields():
    assert err("norm2(xi[0])", params="{N: 0}").startswith("m.yaml:3: parameters.N:")
    assert err("norm2(xi[0])", group="SE4^N").startswith("m.yaml:2: group:")
    assert err("norm2(xi[0]) + x[5][0]").startswith("m.yaml:4: lagrangian:")
    assert "(column 16)" in err("norm2(xi[0]) + x[5][0]")


def test_override_block_values_and_aliases():
    text = ("name: m\ngroup: SO3^N\nparameters:\n  M: &n 2\n  L: *n\n  N: 2 # bodies\n"
            "  J:\n    - 1.0\n    - 2.0\n  K: 3\nlagrangian: sum(i, J[i]*norm2(w[i]))\n")
    out = apply_overrides(text, {"J": [5.0, 6.0, 7.0], "N": 3})
    m = load_model_text(out, "m.yaml")
    assert dict(m.parameters)["J"] == (5.0, 6.0, 7.0) and m.family.count == 3
    assert "N: 3 # bodies" in out and out.count("\n") == text.count("\n")   # lines kept
    with pytest.raises(ModelError) as info:
        apply_overrides(text, {"L": 4}, file="m.yaml")
    assert "m.yaml: parameters.L: cannot set 'L': its value is a YAML alias" in str(info.value)


def test_section_records_and_runtime_parameters_in_a_family():
    text = ("name: m\ngroup: SO3^N\nparameters: {N: 2, J: [1.0, 2.0, 3.0], k: [0.5, 0.25]}\n"
            "runtime_parameters: [J, k]\n"
            "lagrangian: sum(i, 0.5*dot(w[i], J*w[i]) + k[i]*R[i][2, 2])\n"
            "scene:\n  h: 0.1\n  steps: 2\n  initial: {xi: [1, 0, 0]}\n"
            "  section: mu[1][0] - mu[0][0]\n  record: [{a: \"dot(mu[0], xi[1])\"}]\n")
    m = load_model_text(text, "m.yaml")
    mu = [sp.Symbol(f"mu_{k}", real=True) for k in range(6)]
    assert m.scene.section.expr == mu[3] - mu[0]
    assert m.scene.expressions[0].expr == mu[0] * xi(3) + mu[1] * xi(4) + mu[2] * xi(5)
    k0, k1 = (sp.Symbol(f"param:k[{i}]", real=True) for i in range(2))
    assert sp.expand(m.lagrangian.diff(g(2, 2)) - k0) == 0 and m.lagrangian.diff(g(5, 5)) == k1
