"""User expressions in ``scene.record``: ``{label: "expression"}`` entries parsed like the
Lagrangian (hpgen.model.expr.parse_record) into RecordExpr, next to the built-in names."""
from __future__ import annotations

import os

import pytest
import sympy as sp

from hpgen.errors import ModelError
from hpgen.groups import group_from_spec
from hpgen.model import load_model_text
from hpgen.model import expr as expr_mod
from hpgen.model.types import RecordExpr

HEAVY_TOP = ("name: top\ngroup: SO3\nparameters: {{I: [2.0, 1.0, 4.0], m: 2, l: 0.5}}\n"
             "lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)"
             " - m*9.81*l*R[2, 2]\n"
             "scene:\n  h: 0.1\n  steps: 10\n  initial: {{xi: [0.1, 0.2, 0.3]}}\n"
             "  section: mu[0]\n"
             "  record: {record}\n")
SE3 = ("name: body\ngroup: SE3\nparameters: {{M: [1.0, 1.0, 1.0, 2.0, 2.0, 2.0]}}\n"
       "lagrangian: 0.5*dot(M, xi*xi) - 9.81*x[2]\n"
       "scene:\n  h: 0.1\n  steps: 10\n  initial: {{xi: [0.1, 0.2, 0.3, 0, 0, 0]}}\n"
       "  record: {record}\n")
PRODUCT = ("name: pair\ngroup: [SO3, R3]\nlagrangian: 0.5*dot(xi, xi) - x_1[2]\n"
           "scene:\n  h: 0.1\n  steps: 10\n  initial: {{xi: [0.1, 0.2, 0.3, 0, 0, 0]}}\n"
           "  record: {record}\n")


def xi(k):
    return sp.Symbol(f"xi_{k}", real=True)


def mu(k):
    return sp.Symbol(f"mu_{k}", real=True)


def load(record: str, template=HEAVY_TOP):
    return load_model_text(template.format(record=record), filename="m.yaml")


def err(record: str, field: str, template=HEAVY_TOP) -> ModelError:
    with pytest.raises(ModelError) as info:
        load(record, template)
    e = info.value
    msg = str(e)
    assert "\n" not in msg and "\r" not in msg
    assert e.field == field, msg
    line = template.splitlines().index("  record: {record}") + 1     # the line of "record:"
    assert e.file == "m.yaml" and e.line == line, msg
    assert msg.startswith(f"m.yaml:{line}: {field}: "), msg
    return e


# ---- accepted ------------------------------------------------------------------------------
def test_heavy_top_expressions():
    m = load('[g, energy, {height: "R[2,2]"}, {spin: "xi[2] - mu[0]/I[0]"}]')
    sc = m.scene
    assert sc.record == ("g", "energy", "height", "spin")
    assert [type(e) for e in sc.expressions] == [RecordExpr, RecordExpr]
    height, spin = sc.expressions
    assert (height.label, height.text) == ("height", "R[2,2]")
    assert height.expr == m.g_symbols[2][2] == sp.Symbol("g_2_2", real=True)
    assert (spin.label, spin.text) == ("spin", "xi[2] - mu[0]/I[0]")
    assert sp.expand(spin.expr - (xi(2) - sp.Float(0.5) * mu(0))) == 0
    for e in sc.expressions:
        # the same symbols as the Lagrangian's (xi, g) and the section's (mu)
        assert e.xi_symbols == m.xi_symbols == tuple(xi(k) for k in range(3))
        assert e.mu_symbols == sc.section.mu_symbols == tuple(mu(k) for k in range(3))
        assert e.g_symbols == m.g_symbols
    assert spin.expr.free_symbols == {xi(2), mu(0)}
    assert spin.expr.free_symbols <= set(m.xi_symbols) | set(spin.mu_symbols)


def test_parameters_functions_and_dot():
    m = load('[{e: "0.5*dot(I, xi*xi) + m*l*cos(pi)*R[2, 2]"}, {p: "sqrt(dot(mu, mu))"}]')
    e, p = m.scene.expressions
    g = m.g_symbols
    want = (sp.Float(1.0) * xi(0) ** 2 + sp.Float(0.5) * xi(1) ** 2 + sp.Float(2.0) * xi(2) ** 2
            - sp.Float(1.0) * g[2][2])
    assert sp.expand(e.expr - want) == 0
    assert sp.expand(p.expr - sp.sqrt(mu(0) ** 2 + mu(1) ** 2 + mu(2) ** 2)) == 0


def test_se3_expressions():
    m = load('[{z: "x[2]"}, g, {power: "dot(mu, xi)"}, {tilt: "R[2, 2]*mu[3]"}]', SE3)
    sc = m.scene
    assert sc.record == ("z", "g", "power", "tilt")
    z, power, tilt = sc.expressions
    g = m.g_symbols
    assert len(g) == 4 and z.expr == g[2][3] == sp.Symbol("g_2_3", real=True)
    assert sp.expand(power.expr - sum(mu(k) * xi(k) for k in range(6))) == 0
    assert sp.expand(tilt.expr - g[2][2] * mu(3)) == 0
    assert z.xi_symbols == m.xi_symbols and len(z.mu_symbols) == 6 and z.g_symbols == g


def test_product_group_slices():
    m = load('[{h: "x_1[2]"}, {w: "xi_0[1] + mu_1[0]*R_0[0, 0]"}]', PRODUCT)
    h, w = m.scene.expressions
    g = m.g_symbols
    assert len(g) == 7 and h.expr == g[5][6] == sp.Symbol("g_5_6", real=True)
    assert sp.expand(w.expr - (xi(1) + mu(3) * g[0][0])) == 0
    assert w.xi_symbols == m.xi_symbols and w.mu_symbols == tuple(mu(k) for k in range(6))


def test_order_is_kept_and_default():
    m = load('[{a: "xi[0]"}, momentum, {b: "mu[1]"}, g, {c: "R[0, 1]"}, defect]')
    assert m.scene.record == ("a", "momentum", "b", "g", "c", "defect")
    assert [e.label for e in m.scene.expressions] == ["a", "b", "c"]
    plain = load("[g, mu]")
    assert plain.scene.record == ("g", "mu") and plain.scene.expressions == ()
    default = load_model_text(HEAVY_TOP.format(record="[g]").replace("  record: [g]\n", ""),
                              filename="m.yaml")
    assert default.scene.record == ("g", "mu") and default.scene.expressions == ()


def test_block_style_entry_and_label_forms():
    m = load('\n    - g\n    - Height_2: |\n        (R[2, 2]\n         + xi[0])\n'
             '    - {' + "z" * 64 + ': "mu[2]"}')
    assert m.scene.record == ("g", "Height_2", "z" * 64)
    assert sp.expand(m.scene.expressions[0].expr - (m.g_symbols[2][2] + xi(0))) == 0


def test_parse_record_direct():
    e, xs, ms, gs = expr_mod.parse_record("mu[0]*g[0, 1] + xi[0]", group_from_spec("SO2"), {},
                                          "scene.record[0].q")
    assert e == mu(0) * sp.Symbol("g_0_1", real=True) + xi(0)
    assert xs == (xi(0),) and ms == (mu(0),)
    assert gs == tuple(tuple(sp.Symbol(f"g_{i}_{j}", real=True) for j in range(2))
                       for i in range(2))
    with pytest.raises(ModelError) as info:
        expr_mod.parse_record("xi", group_from_spec("SO3"), {}, "scene.record[3].v")
    assert info.value.field == "scene.record[3].v" and "scalar" in info.value.message


# ---- refused -------------------------------------------------------------------------------
@pytest.mark.parametrize("label, expect", [
    ("1a", "not a valid name"), ("a-b", "not a valid name"), ("_a", "not a valid name"),
    ("a" * 65, "not a valid name"), ("t", "reserved"), ("lambda", "Python keyword"),
    ("None", "Python keyword"),
])
def test_bad_label(label, expect):
    e = err('[g, {"%s": "xi[0]"}]' % label, f"scene.record[1].{label}")
    assert expect in e.message


@pytest.mark.parametrize("name", ["g", "mu", "xi", "energy", "momentum", "defect"])
def test_label_equal_to_builtin_name(name):
    e = err('[{%s: "xi[0]"}]' % name, f"scene.record[0].{name}")
    assert "built-in record name" in e.message


def test_duplicates():
    assert "listed twice" in err('[{a: "xi[0]"}, g, {a: "xi[1]"}]', "scene.record[2].a").message
    assert "listed twice" in err("[g, energy, g]", "scene.record[2]").message


def test_not_scalar():
    e = err('[{w: "xi"}]', "scene.record[0].w")
    assert "must be a scalar" in e.message and "vector of length 3" in e.message
    e = err('[{rot: "R"}]', "scene.record[0].rot")
    assert "3 x 3 matrix" in e.message


@pytest.mark.parametrize("text", ['"I[0] - 2*m"', '"pi"', '"0*xi[0]"'])
def test_constant(text):
    e = err("[{c: %s}]" % text, "scene.record[0].c")
    assert "constant" in e.message and "expected" in e.message


def test_constant_on_se3_bottom_row():
    e = err('[{c: "g[3, 3]"}]', "scene.record[0].c", SE3)
    assert "constant" in e.message


@pytest.mark.parametrize("value", ["3", "2.5"])
def test_number_instead_of_string(value):
    e = err("[{c: %s}]" % value, "scene.record[0].c")
    assert "constant" in e.message and "string" in e.message


@pytest.mark.parametrize("value", ["''", "[1, 2]", "null", "{a: b}"])
def test_not_an_expression_string(value):
    e = err("[{c: %s}]" % value, "scene.record[0].c")
    assert "expected an expression" in e.message


def test_mapping_with_two_keys_or_none():
    e = err('[g, {a: "xi[0]", b: "xi[1]"}]', "scene.record[1]")
    assert "exactly one key" in e.message and "2 keys" in e.message
    assert "0 keys" in err("[{}]", "scene.record[0]").message


def test_unknown_entries():
    assert "expected one of" in err("[g, position]", "scene.record[1]").message
    assert "expected one of" in err("[g, 3]", "scene.record[1]").message
    assert "non-empty list" in err("[]", "scene.record").message


def test_unknown_name_in_expression():
    e = err('[{a: "xi[0] + omega"}]', "scene.record[0].a")
    assert "unknown name 'omega'" in e.message and "column" in e.message


def test_index_out_of_range():
    e = err('[{a: "mu[3]"}]', "scene.record[0].a")
    assert "out of range" in e.message


def test_parameter_named_mu_is_refused():
    tpl = HEAVY_TOP.replace("l: 0.5}", "l: 0.5, mu_1: 3}").replace("section: mu[0]", "every: 1")
    e = err('[{a: "xi[0]"}]', "scene.record[0].a", tpl)
    assert "mu_1" in e.message and "rename" in e.message


@pytest.mark.parametrize("payload", ["__import__('os').system('touch {p}')", "open('{p}', 'w')",
                                     "().__class__.__bases__[0].__subclasses__()",
                                     "eval('open(\\'{p}\\', \\'w\\')')",
                                     "xi.__class__", "[open('{p}', 'w') for t in xi][0]"])
def test_payload_is_inert(tmp_path, payload):
    target = tmp_path / "pwned"
    record = "\n    - a: |\n        " + payload.format(p=target)
    with pytest.raises(ModelError) as info:
        load(record)
    e = info.value
    assert e.field == "scene.record[0].a", str(e)
    assert "not allowed" in e.message, e.message
    assert not target.exists()
    assert not os.path.exists("/tmp/pwned")


def test_import_payload_message():
    e = err('[{a: "__import__(\'os\')"}]', "scene.record[0].a")
    assert "dunder names are forbidden" in e.message
