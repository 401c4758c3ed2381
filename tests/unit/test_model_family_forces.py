"""The per-body form of ``forces:`` in a family model (hpgen.model.family_forces): written once
for body i, expanded to the same Model.forces as the N*d list written out by hand; refusals in
one line naming the field."""
from __future__ import annotations

import pytest

from hpgen.derive.family import family_local
from hpgen.errors import ModelError
from hpgen.model import load_model_text

BASE = """
name: damped
group: SO3^N
parameters: {N: 3, J: [1.0, 1.0, 0.5], mgl: 2.0, c: 0.1}
runtime_parameters: [c]
inputs: [u]
lagrangian: sum(i, 0.5*dot(w[i], J*w[i]) + mgl*R[i][2, 2])
forces: %s
"""
PER_BODY = '{for: i, body: ["-c*w[i][0] + u*sin(t)", "-c*w[i][1]*(i + 1)", "R[i][2, 0]"]}'


def model(forces: str, base: str = BASE):
    return load_model_text(base % forces)


def test_the_per_body_form_expands_to_the_written_out_list():
    per_body = model(PER_BODY)
    entries = []
    for k in range(3):
        entries += [f'"-c*w[{k}][0] + u*sin(t)"', f'"-c*w[{k}][1]*({k} + 1)"', f'"R[{k}][2, 0]"']
    listed = model("[" + ", ".join(entries) + "]")
    assert len(per_body.forces) == 9
    assert [f.expand() for f in per_body.forces] == [f.expand() for f in listed.forces]
    assert family_local(per_body) and not family_local(listed)
    assert per_body.family.local.force is not None and per_body.forced


@pytest.mark.parametrize("forces,field,words", [
    ('{for: i, body: ["0", "0"]}', "forces.body", "expected a list of 3"),
    ('{for: i, each: ["0", "0", "0"]}', "forces", "keys for"),
    ('{for: c, body: ["0", "0", "0"]}', "forces.for", "shadows"),
    ('{for: w, body: ["0", "0", "0"]}', "forces.for", "shadows"),
    ('{for: i, body: ["w[0][0]", "0", "0"]}', "forces.body[0]", "only body i's names"),
    ('{for: i, body: ["0", "R[i - 1][0, 0]", "0"]}', "forces.body[1]", "only body i's"),
    ('{for: i, body: ["0", "0", "w[i]"]}', "forces.body[2]", "scalar"),
    ('{for: i, body: ["0", "0", "foo"]}', "forces.body[2]", "foo"),
])
def test_refusals_name_the_field(forces, field, words):
    with pytest.raises(ModelError) as e:
        model(forces)
    msg = str(e.value)
    assert f"{field}:" in msg and words in msg and "\n" not in msg


def test_the_per_body_form_needs_a_family():
    text = BASE.replace("group: SO3^N", "group: SO3").replace(
        "sum(i, 0.5*dot(w[i], J*w[i]) + mgl*R[i][2, 2])", "0.5*dot(xi, J*xi)")
    with pytest.raises(ModelError, match="needs a family group"):
        model('{for: i, body: ["0", "0", "0"]}', text)
