"""Model files with forces, control inputs, runtime parameters and the time t (issue 16, the
schema's optional keys ``runtime_parameters``, ``inputs``, ``forces``)."""
from __future__ import annotations

import pytest
import sympy as sp

from hpgen.model import load_model_text
from hpgen.model.symbols import TIME_SYMBOL, input_symbol, runtime_symbol
from conftest import model_error

TOP = """\
name: controlled_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, c: 0.05, chi: [0.0, 0.0, 1.0]}
runtime_parameters: [Mg, c, chi]
inputs: [u0, u1, u2]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*(R[2, 0]*chi[0] + R[2, 1]*chi[1] + R[2, 2]*chi[2])*cos(t)
forces: ["-c*xi[0] + u0", "-c*xi[1] + u1", "-c*xi[2] + u2*sin(t)"]
"""


def _err(text) -> str:
    return model_error(text)


def test_forced_model_fields():
    m = load_model_text(TOP, "m.yaml")
    assert m.runtime_parameters == (("Mg", ()), ("c", ()), ("chi", (3,)))
    assert m.runtime_symbols == (runtime_symbol("Mg"), runtime_symbol("c"),
                                 *(runtime_symbol("chi", (k,)) for k in range(3)))
    assert m.runtime_defaults == (1.0, 0.05, 0.0, 0.0, 1.0)
    assert m.inputs == ("u0", "u1", "u2")
    assert m.input_symbols == tuple(input_symbol(u) for u in m.inputs)
    assert m.forced and m.time_dependent and m.open_system
    assert len(m.forces) == 3 and m.forces_text[0] == "-c*xi[0] + u0"
    xi0, c, u0 = m.xi_symbols[0], runtime_symbol("c"), input_symbol("u0")
    assert sp.simplify(m.forces[0] - (-c * xi0 + u0)) == 0
    # runtime parameters stay symbols in the Lagrangian, fixed ones are substituted
    free = m.lagrangian.free_symbols
    assert runtime_symbol("Mg") in free and TIME_SYMBOL in free
    assert not any(str(s) == "I" or str(s).startswith("param:I") for s in free)


def test_old_files_are_closed_and_zero_forces_stay_closed():
    plain = TOP.split("runtime_parameters")[0] + \
        "lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2, 2]\n"
    m = load_model_text(plain)
    assert (m.runtime_parameters, m.inputs, m.forces) == ((), (), ())
    assert not (m.forced or m.time_dependent or m.open_system)
    z = load_model_text(plain + "forces: [0, 0.0, '0*xi[0]']\n")
    assert len(z.forces) == 3 and not z.forced and not z.open_system


def test_constant_and_closed_loop_forces_parse():
    m = load_model_text(TOP.replace('forces: ["-c*xi[0] + u0"', 'forces: [1.5'))
    assert m.forces[0] == 1.5
    m = load_model_text(TOP.replace('"-c*xi[1] + u1"', '"-(R[0, 2] - R[2, 0])"'))
    assert m.forces[1].free_symbols <= {s for row in m.g_symbols for s in row}


@pytest.mark.parametrize("change, expected", [
    (('forces: ["-c*xi[0] + u0", ', 'forces: ['), ["forces:", "expected 3 expressions", "got 2"]),
    (('["-c*xi[0] + u0", "-c*xi[1] + u1", "-c*xi[2] + u2*sin(t)"]', '"-c*xi[0]"'),
     ["forces", "expected a list"]),
    (("u2*sin(t)", "v2"), ["forces[2]", "unknown name 'v2'"]),
    (("*cos(t)", "*u0"), ["lagrangian", "the input 'u0' may not appear in the Lagrangian"]),
    (("[Mg, c, chi]", "[Mg, k]"), ["runtime_parameters[1]", "unknown runtime parameter 'k'"]),
    (("[Mg, c, chi]", "[Mg, Mg]"), ["runtime_parameters[1]", "'Mg' is listed twice"]),
    (("[Mg, c, chi]", "Mg"), ["runtime_parameters", "expected a list"]),
    (("[u0, u1, u2]", "[u0, u0, u2]"), ["inputs[1]", "'u0' is listed twice"]),
    (("[u0, u1, u2]", "[c, u1, u2]"), ["inputs[0]", "also a parameter"]),
    (("[u0, u1, u2]", "[t, u1, u2]"), ["inputs[0]", "reserved"]),
    (("[u0, u1, u2]", "[1u, u1, u2]"), ["inputs[0]", "not an identifier"]),
    (("u2*sin(t)", "__import__('os')"), ["forces[2]", "not allowed"]),
    (("u2*sin(t)", "xi"), ["forces[2]", "must be a scalar"]),
    (("u2*sin(t)", "1/0"), ["forces[2]", "not finite"]),
    (("c: 0.05", "t: 0.05"), ["parameters.t", "reserved"]),
])
def test_bad_forced_models(change, expected):
    msg = _err(TOP.replace(*change))
    assert msg.startswith("m.yaml:")
    for part in expected:
        assert part in msg, msg


def test_scene_may_not_use_runtime_parameters():
    scene = ("scene:\n  h: 0.05\n  steps: 10\n  initial: {g: identity, xi: [0.1, 0.2, 0.3]}\n"
             "  section: c*mu[0] - 0.1\n")
    msg = _err(TOP + scene)
    assert "scene.section" in msg and "runtime parameter 'c'" in msg
    msg = _err(TOP + scene.replace("section: c*mu[0] - 0.1", "record: [{w: \"chi[2]*xi[0]\"}]"))
    assert "scene.record" in msg and "runtime parameter 'chi'" in msg
