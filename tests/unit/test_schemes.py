"""The registry of scheme options (hpgen.schemes) drives every place that names the options:
group support of the charts, the chart-map table, validation messages, the CLI and the
runtime (which reads it without the compile-time stack)."""
from __future__ import annotations

import subprocess
import sys

import casadi as ca
import pytest

from hpgen import schemes
from hpgen.api import CompileOptions
from hpgen.errors import ModelError
from hpgen.groups import GROUP_NAMES, group_from_spec
from hpgen.groups.maps import GROUP_CHARTS
from hpgen.model import load_model_text

FAMILY_EXAMPLE = {"R<n>": "R3", "SO2": "SO2", "SO3": "SO3", "SE2": "SE2", "SE3": "SE3"}


def test_every_group_family_is_tabulated_and_named_in_the_registry():
    assert tuple(FAMILY_EXAMPLE) == GROUP_NAMES
    assert tuple(GROUP_CHARTS) == GROUP_NAMES
    for chart in schemes.TAU.entries:
        assert chart.groups is None or set(chart.groups) <= set(GROUP_NAMES), chart


@pytest.mark.parametrize("family", GROUP_NAMES)
def test_group_supports_exactly_the_registered_charts(family):
    G = group_from_spec(FAMILY_EXAMPLE[family])
    assert G.tau_kinds == schemes.charts_on(family)
    x = ca.SX.sym("x", G.d)
    for chart in schemes.TAU.entries:
        calls = (G.tau, G.dtau_inv, G.dtau, G.tau_margin)
        if chart.on(family):
            shapes = [f(chart.name, x).shape for f in calls]
            assert shapes == [(G.n, G.n), (G.d, G.d), (G.d, G.d), (1, 1)], (chart.name, shapes)
        else:
            for f in calls:
                with pytest.raises(ModelError, match=f"tau = {chart.name} is not available on"):
                    f(chart.name, x)


def test_product_group_supports_the_charts_all_factors_support():
    assert group_from_spec(["SO3", "R3"]).tau_kinds == tuple(
        c.name for c in schemes.TAU.entries if c.on("SO3") and c.on("R<n>"))


def test_scheme_order_caps_truncated_at_two():
    assert [schemes.scheme_order(p, "exact") for p in (1, 2, 4, 6)] == [1, 2, 4, 6]
    assert [schemes.scheme_order(p, "truncated") for p in (1, 2, 4, 6)] == [1, 2, 2, 2]
    with pytest.raises(ModelError, match="expected one of exact, truncated, got 'rk4'"):
        schemes.scheme_order(4, "rk4")


@pytest.mark.parametrize("option,attr", [(schemes.TAU, "tau"), (schemes.RKMK, "rkmk"),
                                         (schemes.BACKEND, "backend")])
def test_api_validation_names_field_and_registered_values(option, attr):
    for name in option.names:
        CompileOptions(**{attr: name}).validate()
    with pytest.raises(ModelError) as err:
        CompileOptions(**{attr: "nope"}).validate()
    assert err.value.field == f"option {attr}"
    assert str(err.value) == (f"option {attr}: expected one of {', '.join(option.names)}, "
                              "got 'nope'")


@pytest.mark.parametrize("option", [schemes.TAU, schemes.RKMK], ids=lambda o: o.name)
def test_model_file_integrator_section_validated_by_registry(option):
    base = "name: m\ngroup: SO3\nlagrangian: 0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2)\n"
    for name in option.names:
        m = load_model_text(base + f"integrator: {{{option.name}: {name}}}\n", "m.yaml")
        assert getattr(m.integrator, option.name) == name
    with pytest.raises(ModelError) as err:
        load_model_text(base + f"integrator: {{{option.name}: 3}}\n", "m.yaml")
    assert str(err.value) == (f"m.yaml:4: integrator.{option.name}: expected one of "
                              f"{', '.join(option.names)}, got int 3")


def test_cli_choices_and_list_come_from_the_registry():
    from hpgen.cli import _parser
    compile_parser = _parser()._subparsers._group_actions[0].choices["compile"]
    choices = {a.dest: tuple(a.choices) for a in compile_parser._actions if a.choices}
    assert choices == {"tau": schemes.TAU.names, "rkmk": schemes.RKMK.names,
                       "backend": schemes.BACKEND.names,
                       "compose": tuple(c.name for c in schemes.compositions())}


def test_registry_and_runtime_loader_import_no_compile_time_stack():
    code = ("import sys\n"
            "for m in ('casadi', 'sympy', 'jinja2', 'mpmath'):\n"
            "    sys.modules[m] = None\n"
            "import hpgen.schemes, hpgen.runtime.loader\n"
            "assert hpgen.runtime.loader.BACKENDS == hpgen.schemes.BACKENDS\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
