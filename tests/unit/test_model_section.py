"""The scene's Poincare section ``scene.section``: s(g, mu) parsed like the Lagrangian."""
from __future__ import annotations

import pytest
import sympy as sp

from hpgen.errors import ModelError
from hpgen.groups import group_from_spec
from hpgen.model import SectionSpec, load_model_text
from hpgen.model import expr as expr_mod

LAGRANGIANS = {
    "SO3": "0.5*(xi[0]**2 + 2*xi[1]**2 + 3*xi[2]**2)",
    "SE3": "0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2 + xi[3]**2 + xi[4]**2 + xi[5]**2)",
    "[SO3, R3]": "0.5*dot(xi, xi)",
    "SE2": "0.5*dot(xi, xi)",
}
DIMS = {"SO3": 3, "SE3": 6, "[SO3, R3]": 6, "SE2": 3}
PARAMS = "parameters: {I: [1.0, 2.0, 3.0], k: 2}\n"
SECTION_LINE = 10                      # the line of "section:" in the file below


def text(section: str, group="SO3", params=PARAMS) -> str:
    d = DIMS[group]
    return (f"name: m\ngroup: {group}\n{params}lagrangian: {LAGRANGIANS[group]}\n"
            f"scene:\n  h: 0.1\n  steps: 10\n  initial: {{xi: {[0.1] * d}}}\n"
            f"  record: [g, mu]\n  section: {section}\n")


def model(section: str, group="SO3", params=PARAMS):
    return load_model_text(text(section, group, params), filename="m.yaml")


def err(section: str, group="SO3", params=PARAMS) -> ModelError:
    with pytest.raises(ModelError) as info:
        model(section, group, params)
    e = info.value
    msg = str(e)
    assert "\n" not in msg and "\r" not in msg
    assert e.field == "scene.section", msg
    assert msg.startswith(f"m.yaml:{SECTION_LINE}: scene.section: "), msg
    return e


def mu(k):
    return sp.Symbol(f"mu_{k}", real=True)


# ---- accepted ------------------------------------------------------------------------------
def test_no_section_is_none():
    m = load_model_text(text("mu[0]").replace("  section: mu[0]\n", ""), filename="m.yaml")
    assert m.scene.section is None


def test_mu_component_on_se3():
    m = model("mu[5]", group="SE3")
    s = m.scene.section
    assert isinstance(s, SectionSpec)
    assert s.text == "mu[5]"
    assert s.expr == mu(5)
    assert s.mu_symbols == tuple(mu(k) for k in range(6))
    assert len(s.g_symbols) == 4 and all(len(row) == 4 for row in s.g_symbols)


def test_rotation_translation_and_mu_on_se3():
    m = model("R[2,0]*mu[0] + x[1] - 0.5", group="SE3")
    s = m.scene.section
    g = s.g_symbols
    assert sp.expand(s.expr - (g[2][0] * mu(0) + g[1][3] - sp.Float(0.5))) == 0
    # the section's g symbols are the Lagrangian's (same names and assumptions: equal in sympy)
    assert s.g_symbols == m.g_symbols
    assert {sym for row in s.g_symbols for sym in row} == \
        {sym for row in m.g_symbols for sym in row}


def test_parameters_functions_and_pi_on_so3():
    s = model("k*sin(R[2, 2]) + dot(I, mu) - pi").scene.section
    g = s.g_symbols
    want = 2 * sp.sin(g[2][2]) + 1.0 * mu(0) + 2.0 * mu(1) + 3.0 * mu(2) - sp.pi
    assert sp.expand(s.expr - want) == 0


def test_g_only_section():
    s = model("g[0, 0] - 0.9").scene.section
    assert s.expr.free_symbols == {s.g_symbols[0][0]}


def test_product_group_slices():
    s = model("mu_1[2] + R_0[0, 0]*mu_0[1] - x_1[0]", group="[SO3, R3]").scene.section
    g = s.g_symbols
    want = mu(5) + g[0][0] * mu(1) - g[3][6]
    assert sp.expand(s.expr - want) == 0
    assert len(s.mu_symbols) == 6 and len(g) == 7


def test_literal_block_and_quoted():
    s = model("'mu[1] - 0.25'").scene.section
    assert s.text == "mu[1] - 0.25"
    m = load_model_text(text("|\n    (mu[0]\n     + R[0, 1])"), filename="m.yaml")
    assert sp.expand(m.scene.section.expr - (mu(0) + m.g_symbols[0][1])) == 0


def test_parse_section_direct():
    e, mus, gs = expr_mod.parse_section("mu[0]*g[0, 1]", group_from_spec("SO2"), {})
    assert e == mu(0) * sp.Symbol("g_0_1", real=True)
    assert mus == (mu(0),)
    assert gs == tuple(tuple(sp.Symbol(f"g_{i}_{j}", real=True) for j in range(2))
                       for i in range(2))


def test_parse_section_direct_error_has_field():
    with pytest.raises(ModelError) as info:
        expr_mod.parse_section("xi[0]", group_from_spec("SO3"), {})
    assert info.value.field == "scene.section"
    assert "not xi" in str(info.value)


def test_lagrangian_unchanged_by_section():
    a = model("mu[0]")
    b = load_model_text(text("mu[0]").replace("  section: mu[0]\n", ""), filename="m.yaml")
    assert a.lagrangian == b.lagrangian and a.xi_symbols == b.xi_symbols
    assert a.g_symbols == b.g_symbols


# ---- refused -------------------------------------------------------------------------------
def test_xi_is_refused():
    e = err("xi[0] - 0.1")
    assert "the section may use mu" in e.message and "not xi" in e.message
    e = err("mu[0] + xi_0[1]", group="[SO3, R3]")
    assert "not xi" in e.message
    assert "not xi" in err("xi_0").message


def test_unknown_name():
    e = err("mu[0] + foo")
    assert "unknown name 'foo'" in e.message
    assert "mu" in e.message and "I" in e.message and "pi" in e.message


def test_constant_is_refused():
    for sec in ("1.5", "0", "'2*pi'", "mu[0] - mu[0]", "k - 1"):
        e = err(sec)
        assert "constant" in e.message and "never cross" in e.message, (sec, e.message)


def test_constant_entry_of_g_is_refused():
    # g[3, 3] is 1 on SE3: a section in it alone never crosses
    e = err("g[3, 3] - 0.5", group="SE3")
    assert "constant on the group" in e.message


def test_not_scalar():
    assert "must be a scalar" in err("mu").message
    assert "3 x 3 matrix" in err("R").message


def test_syntax_error():
    e = err("mu[0] +")
    assert "syntax error" in e.message and "allowed:" in e.message


@pytest.mark.parametrize("sec, want", [
    ("mu.__class__", "attribute access is not allowed"),
    ("__import__", "dunder names are forbidden"),
    ("'open(\"/tmp/hpgen_pwned_section\")'", "function 'open' is not allowed"),
    ("'(lambda: 1)()'", "not allowed"),
    ("'[m for m in mu][0]'", "not allowed"),
    ("'mu[0] % 2'", "operator % is not allowed"),
    ("'mu[-1]'", "non-negative integer literals"),
])
def test_hostile_and_disallowed(sec, want):
    assert want in err(sec).message


def test_index_out_of_range_and_undefined_blocks():
    assert "out of range" in err("mu[3]").message
    assert "x is not defined" in err("x[0] + mu[0]").message
    assert "R is not defined for a product group" in err("R[0, 0]", group="[SO3, R3]").message


def test_not_a_string():
    for sec in ("true", "[1, 2]", "'   '"):
        assert "expected an expression" in err(sec).message


def test_parameter_named_mu_clashes():
    e = err("mu[0]", params="parameters: {mu: 1.0}\n")
    assert "'mu'" in e.message and "rename" in e.message
    # without a section such a parameter stays allowed
    load_model_text(text("x").replace("  section: x\n", "").replace(PARAMS, "parameters: "
                                                                           "{mu: 1.0}\n"),
                    filename="m.yaml")


def test_error_line_inside_literal_block():
    with pytest.raises(ModelError) as info:
        load_model_text(text("|\n    (mu[0]\n     + foo)"), filename="m.yaml")
    assert str(info.value).startswith(f"m.yaml:{SECTION_LINE + 2}: scene.section: ")
