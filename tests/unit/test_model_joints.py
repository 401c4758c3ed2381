"""Mapping entries of ``constraints:`` (hpgen.model.joints): families of row blocks over
joints, the ball and pin shorthands, their expansion and their one-line refusals."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hpgen.model import load_model, load_model_text
from conftest import model_error

ROOT = Path(__file__).resolve().parents[2]

HEAD = """\
name: links
group: SE3^N
parameters: {N: 4, m: 1.0, J: [0.02, 0.02, 0.002], grav: 9.81,
             top: [0.0, 0.0, 0.25], bot: [0.0, 0.0, -0.25]}
lagrangian: sum(i, 0.5*m*norm2(v[i]) + 0.5*dot(w[i], J*w[i]) - m*grav*x[i][2])
constraints:
"""
WRITTEN = HEAD + "".join(
    f"  - x[{i}] + R[{i}] @ top - x[{i - 1}] - R[{i - 1}] @ bot\n" for i in range(1, 4))


def _rows(model):
    return [r for c in model.constraints for r in c.rows]


def _err(text) -> str:
    return model_error(text)


@pytest.mark.parametrize("entry", [
    '{for: i, in: [1, N], row: "x[i] + R[i] @ top - x[i-1] - R[i-1] @ bot"}',
    "{for: j, in: [1, N], ball: [j - 1, j], at: [bot, top]}",
    "{for: j, in: [0, N - 1], ball: [j, j + 1], at: [bot, top]}",
])
def test_a_family_expands_to_the_rows_written_out(entry):
    model = load_model_text(HEAD + f"  - {entry}\n")
    written = load_model_text(WRITTEN)
    assert len(_rows(model)) == 9
    assert [r.expand() for r in _rows(model)] == [r.expand() for r in _rows(written)]
    var = entry.split("for: ")[1][0]
    assert [c.label for c in model.constraints] == \
        [f"constraints[0] ({var} = {k})" for k in range(3)] if var == "j" and "0, N" in entry \
        else [f"constraints[0] ({var} = {k})" for k in range(1, 4)]


def test_pin_shorthand_and_world_point():
    pin = load_model_text(HEAD + "  - {pin: 0, at: top}\n")
    assert [r.expand() for r in _rows(pin)] == \
        [r.expand() for r in _rows(load_model_text(HEAD + "  - x[0] + R[0] @ top\n"))]
    moved = load_model_text(HEAD + "  - {pin: 2, at: top, to: bot}\n")
    assert [r.expand() for r in _rows(moved)] == [r.expand() for r in _rows(
        load_model_text(HEAD + "  - x[2] + R[2] @ top - bot\n"))]


def test_shorthands_on_a_product_and_a_single_group():
    product = """\
name: two
group: [SE3, SE3]
parameters: {top: [0.0, 0.0, 0.25], bot: [0.0, 0.0, -0.25]}
lagrangian: 0.5*dot(xi, xi)
constraints:
  - {pin: 0, at: top}
  - {ball: [0, 1], at: [bot, top]}
"""
    m = load_model_text(product)
    assert [c.text for c in m.constraints] == [
        "x_0 + R_0 @ (top)", "x_1 + R_1 @ (top) - x_0 - R_0 @ (bot)"]
    single = "name: one\ngroup: SE3\nparameters: {top: [0.0, 0.0, 0.25]}\n" \
             "lagrangian: 0.5*dot(xi, xi)\nconstraints: [{pin: 0, at: top}]\n"
    assert load_model_text(single).constraints[0].text == "x + R @ (top)"


@pytest.mark.parametrize("entry, expected", [
    ("{for: i, in: [1, N + 1], ball: [i - 1, i], at: [bot, top]}",
     "constraints[0]: (i = 4): body index 4 out of range for x"),
    ("{for: i, in: [1, N], ball: [i - 1, i]}", "constraints[0]: ball: needs at:"),
    ("{for: i, in: [1, N], ball: [i - 1, i], at: [bot, top], row: \"x[0]\"}",
     "constraints[0]: expected exactly one of row:"),
    ("{for: i, ball: [i - 1, i], at: [bot, top]}", "for: and in: go together"),
    ("{for: m, in: [1, N], ball: [m - 1, m], at: [bot, top]}",
     "constraints[0].for: expected a new name for the loop variable"),
    ("{for: i, in: [1, M], ball: [i - 1, i], at: [bot, top]}",
     "constraints[0].in: the bound 'M'"),
    ("{for: i, in: [1], ball: [i - 1, i], at: [bot, top]}",
     "constraints[0].in: expected [start, stop]"),
    ("{for: i, in: [1, N], ball: [i], at: [bot, top]}",
     "constraints[0].ball: expected the two bodies [A, B]"),
    ("{pin: 0, at: top, angle: bot}", "constraints[0]: unknown key 'angle'"),
    ("{pin: 0, at: [1.0, 2.0, 3.0]}", "constraints[0].at: expected a vector expression"),
    ("{for: i, in: [0, N], row: \"x[i] - v[i]\"}", "constraints[0]: (i = 0): "),
    ("{for: i, in: [0, 2], pin: i, at: top}", "constraints[1] (i = 1) row 0 is redundant"),
])
def test_bad_entries(entry, expected):
    first = "  - {pin: 1, at: top}\n" if "[0, 2], pin" in entry else ""
    text = HEAD + first + f"  - {entry}\n"
    assert expected in _err(text)


def test_product_needs_literal_bodies():
    text = """\
name: two
group: [SE3, SE3]
parameters: {top: [0.0, 0.0, 0.25]}
lagrangian: 0.5*dot(xi, xi)
constraints:
  - {for: i, in: [0, 2], pin: i, at: top}
"""
    assert "a body index of a product group is an integer literal" in _err(text)


def test_initial_state_violations_name_the_joint():
    text = (HEAD.replace("N: 4", "N: 2") + "  - {pin: 0, at: top}\n"
            "  - {for: i, in: [1, N], ball: [i - 1, i], at: [bot, top]}\n"
            "scene: {h: 0.001, steps: 1, initial: {g: [{position: [0, 0, -0.25]}, "
            "{position: [0, 0, -0.7]}], xi: [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]}}\n")
    assert "violates constraints[1] (i = 1) row 2: residual 5.000e-02" in _err(text)


@pytest.mark.parametrize("n", [2, 5])
def test_pendulum_chain_example_is_short_and_admissible(n):
    path = ROOT / "examples" / "pendulum_chain.yaml"
    assert len(path.read_text().splitlines()) <= 30
    from hpgen.model.overrides import apply_overrides
    model = load_model_text(apply_overrides(path.read_text(), {"N": n}), str(path))
    assert model.group.d == 6 * n and len(_rows(model)) == 3 * n
    assert load_model(path).group.d == 12


def test_hinge_and_fixed_add_alignment_rows():
    hinge = load_model_text(HEAD + "  - {for: i, in: [1, N], hinge: [i - 1, i], at: [bot, top], "
                                   "axis: y}\n")
    assert len(_rows(hinge)) == 3 * 5
    assert [c.label for c in hinge.constraints[:3]] == [
        "constraints[0] (i = 1)", "constraints[0] (i = 1) axis row 0",
        "constraints[0] (i = 1) axis row 1"]
    assert hinge.constraints[1].text == "(transpose(R[(i - 1)]) @ R[(i)])[0, 1]"
    assert hinge.constraints[2].text == "(transpose(R[(i - 1)]) @ R[(i)])[2, 1]"
    from scipy.spatial.transform import Rotation

    from hpgen.model.constraints import constraint_values
    g, joint = np.eye(16), np.zeros(3)    # admissible: links 1, 2, 3 turned about y
    for i in range(4):
        R = Rotation.from_rotvec([0.0, 0.3 * (i > 0), 0.0]).as_matrix()
        g[4 * i:4 * i + 3, 4 * i:4 * i + 3] = R
        g[4 * i:4 * i + 3, 4 * i + 3] = joint - R @ [0, 0, 0.25]
        joint = joint - 2 * R @ [0, 0, 0.25]
    phi, Phi, _ = constraint_values(hinge.constraints, hinge.g_symbols, hinge.group, g)
    assert np.abs(phi).max() < 1e-15
    turn, tilt = np.zeros(24), np.zeros(24)
    turn[7], tilt[6] = 1.0, 1.0           # link 1 about its y axis, about its x axis
    assert np.abs(Phi[3:5] @ turn).max() < 1e-15 < np.abs(Phi[0:3] @ turn).max()
    assert np.abs(Phi[3:5] @ tilt).max() > 0.5     # joint 1's axis rows (rows 0-2: its ball)
    fixed = load_model_text(HEAD + "  - {fixed: [0, 1], at: [bot, top]}\n")
    assert len(_rows(fixed)) == 6
    assert "axis: belongs to hinge:" in _err(HEAD + "  - {ball: [0, 1], at: [bot, top], axis: z}\n")
    assert "constraints[0].axis: expected the hinge's axis" in _err(
        HEAD + "  - {hinge: [0, 1], at: [bot, top], axis: w}\n")
    assert "constraints[0].hinge: expected the two bodies" in _err(
        HEAD + "  - {hinge: [0], at: [bot, top], axis: z}\n")
