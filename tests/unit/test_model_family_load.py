"""A family whose Lagrangian sums are local is loaded without expanding its Lagrangian
(hpgen.model.family_load): Model.lagrangian is built on first use and equals the full
parse's; the constraint Legendre check reads the body terms and gives the full Lagrangian's
d2l/dxi2; texts the fast path does not accept are parsed in full."""
from __future__ import annotations

import numpy as np
import pytest

from hpgen.errors import ModelError
from hpgen.model import load_model_text
from hpgen.model.constraints import _generic_point, _legendre_map
from hpgen.model.expr import parse_lagrangian
from hpgen.model.family_load import BodyLagrangian
from tests.conftest import EXAMPLES

CHAIN = (EXAMPLES / "pendulum_chain.yaml").read_text()
MASSES = CHAIN.replace("{N: 2, m: 1.0,", "{N: 3, m: [1.0, 1.5, 0.5],").replace(
    "lagrangian:", "runtime_parameters: [m]\nlagrangian:").replace("m*", "m[i]*")


@pytest.mark.parametrize("text", [CHAIN.replace("{N: 2,", "{N: 5,"), MASSES])
def test_the_lagrangian_is_built_on_first_use_and_equals_the_full_parse(text):
    m = load_model_text(text)
    assert m.lagrangian_expr is None and m.family.local is not None
    assert not m.left_invariant and not m.time_dependent       # from the body terms
    params = {**{k: (list(v) if isinstance(v, tuple) else v) for k, v in m.parameters}}
    params["N"] = m.family.count
    for name, shape in m.runtime_parameters:
        syms = [s for s in m.runtime_symbols if str(s).startswith(f"param:{name}")]
        params[name] = np.array(syms, dtype=object).reshape(shape) if shape else syms[0]
    from hpgen.model.symbols import TIME_SYMBOL
    full, _, _ = parse_lagrangian(m.lagrangian_text, m.group, params,
                                  extra={"t": TIME_SYMBOL})
    assert (m.lagrangian - full).expand() == 0
    assert m.lagrangian_expr is not None


def test_the_legendre_map_of_the_body_terms_is_the_full_one():
    m = load_model_text(MASSES)
    body_lag = BodyLagrangian(m.family.local.bodies, dict(m.family.local.data))
    g = _generic_point(m.group)
    runtime = dict(zip(m.runtime_symbols, m.runtime_defaults))
    Hb = _legendre_map((body_lag, m.xi_symbols, runtime), m.g_symbols, m.group, g)
    Hf = _legendre_map((m.lagrangian, m.xi_symbols, runtime), m.g_symbols, m.group, g)
    assert np.abs(Hb - Hf).max() <= 1e-14 * np.abs(Hf).max()
    assert np.abs(Hf[6:12, 6:12]).max() > 1.2        # body 1's mass 1.5 is in it


@pytest.mark.parametrize("lag,message", [
    ("sum(i, 0, N + 1, 0.5*norm2(xi[i]))", "body index 3 out of range"),
    ("sum(m, 0.5*norm2(xi[m]))", "the sum variable 'm' shadows a name"),
    ("sum(i, 0.5*norm2(xi[i])) + 0.5*u", "may not appear in the Lagrangian"),
])
def test_texts_the_fast_path_declines_keep_their_refusals(lag, message):
    text = f"""name: bad
group: SO3^N
parameters: {{N: 3, m: 1.0}}
inputs: [u]
lagrangian: {lag}
forces: {{for: i, body: ["u", "0", "0"]}}
"""
    with pytest.raises(ModelError, match=message):
        load_model_text(text)


def test_a_joint_potential_stays_unexpanded_and_the_projection_is_the_full_ls():
    """The rod's bending/twisting sum (a joint potential) no longer makes the loader expand
    l; its initial.project (metric from the body terms) is bitwise the full l's."""
    from hpgen.model.projection import project
    from hpgen.model.symbols import TIME_SYMBOL
    rod = (EXAMPLES / "rod.yaml").read_text().replace("{N: 2,", "{N: 3,")
    m = load_model_text(rod)
    assert m.lagrangian_expr is None and len(m.family.local.potentials) == 1
    head, rest = rod.split("constraints:\n")
    raw = load_model_text(head + rest[rest.index("integrator:"):].replace(
        "    project: true\n", ""))                   # the initial state as written
    g, xi, note = project(m.constraints, m.g_symbols, m.group, m.lagrangian, m.xi_symbols,
                          {TIME_SYMBOL: 0}, raw.scene.g0, raw.scene.xi0)
    assert note.iterations > 0 and note == m.scene.projection
    assert np.array_equal(g, np.array(m.scene.g0)) and np.array_equal(xi, m.scene.xi0)
