"""Property: any text through load_model_text returns a Model or raises ModelError, nothing else."""
from __future__ import annotations

import json

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from hpgen.errors import ModelError
from hpgen.model import load_model_text
from hpgen.model.types import Model

SETTINGS = settings(max_examples=200, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

_ATOMS = ["xi", "g", "R", "x", "xi[0]", "xi[2]", "xi[7]", "g[0, 1]", "R[2, 2]", "I", "I[1]", "k",
          "pi", "0", "1", "2", "0.5", "1e308", "1e-300", "-1", "sin", "dot(xi, xi)", "dot(R, xi)",
          "dot(I, xi)", "sqrt(-1)", "log(0)", "exp(1000)", "__import__", "open('f')", "xi.real",
          "lambda: 0", "[1, 2]", "(1, 2)", "'s'", "None", "True", "foo", "xi[-1]", "xi[0:1]",
          "M", "M[1, 1]", "dot(M, M)", "tan(pi/2)"]
_OPS = [" + ", " - ", "*", "/", "**", " % ", " @ ", ", ", " if ", " < ", "(", ")", "[", "]", " "]

expr_text = st.one_of(
    st.text(max_size=60),
    st.text(alphabet="xigRpdotsncqre[](),.+-*/%0123456789_ '\"\n:", max_size=80),
    st.lists(st.one_of(st.sampled_from(_ATOMS), st.sampled_from(_OPS)), max_size=25)
      .map("".join),
)

PREFIX = ("name: m\ngroup: {group}\nparameters:\n  I: [1.0, 2.0, 3.0]\n  M: [[1, 2], [3, 4]]\n"
          "  k: 2\nlagrangian: ")


def _check(text):
    try:
        result = load_model_text(text, filename="fuzz.yaml")
    except ModelError as e:
        msg = str(e)
        assert msg.startswith("fuzz.yaml") and "\n" not in msg
        return
    assert isinstance(result, Model)


@SETTINGS
@given(lag=expr_text, group=st.sampled_from(["SO3", "SE3", "SO2", "R2", "[SO3, R2]", "SE2"]))
def test_random_lagrangian_text(lag, group):
    _check(PREFIX.format(group=group) + json.dumps(lag) + "\n")


_YAML_BITS = ["name: m\n", "group: SO3\n", "group: [SO3, SE2]\n", "lagrangian: xi[0]**2\n",
              "lagrangian: |\n  dot(xi, xi)\n", "parameters: {a: 1e-3, b: [1, 2]}\n",
              "integrator: {tau: cay, tableau: midpoint}\n", "integrator: {tableau: {A: [[0.5]], "
              "b: [1]}}\n", "scene:\n  h: 0.1\n  steps: 3\n  initial: {xi: [1, 2, 3]}\n",
              "scene: {h: .nan, duration: 1}\n", "&a [*a]\n", "x: !!python/object:os.system 1\n",
              "- 1\n", "? [a]\n: 1\n", "name: m\nname: n\n", "a: b: c\n", "\t", "{", "[", "'",
              "schema: 1\n", "schema: 2\n", "scene:\n  initial:\n    g: {rotvec: [1, 2, 3]}\n",
              "<<: {x: 1}\n", "%YAML 1.1\n---\n", "---\n...\n---\n"]

yaml_text = st.one_of(
    st.text(max_size=120),
    st.lists(st.sampled_from(_YAML_BITS), max_size=8).map("".join),
    st.lists(st.one_of(st.sampled_from(_YAML_BITS), st.text(max_size=6)), max_size=8)
      .map("".join),
)


@SETTINGS
@given(text=yaml_text)
def test_random_yaml_text(text):
    _check(text)
