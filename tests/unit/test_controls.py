"""Control inputs u as data (hpgen.model.controls): the scene's u, --u tokens and tables,
their rows per step (u_k = u(t_k) held over step k), and their one-line errors."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from hpgen.errors import ModelError
from hpgen.model import load_model
from hpgen.model.controls import parse_cli_controls, read_table

QUAD = Path(__file__).resolve().parents[1] / "controls" / "quadrotor.yaml"
NAMES = ("T1", "T2", "T3", "T4")


@pytest.fixture(scope="module")
def quad():
    return load_model(QUAD)


def _cli(quad, *tokens, interpolation=None):
    return parse_cli_controls(tokens, quad.inputs, dict(quad.parameters), quad.group,
                              interpolation)


def test_scene_expressions_are_sampled_at_each_steps_start(quad):
    spec = quad.scene.u
    assert spec.kind == "expressions" and quad.inputs == NAMES
    h, t0 = 0.01, 0.5
    U = spec.rows(h, 7, t0=t0)
    t = t0 + np.arange(7) * h
    assert U.shape == (7, 4)
    assert np.array_equal(U[:, 1], np.full(7, 2.4525))
    assert np.allclose(U[:, 0], 2.4525 + 0.2 * np.sin(3 * t), rtol=0, atol=1e-15)
    assert np.allclose(U[:, 2], 2.4525 + 0.1 * np.cos(2 * t), rtol=0, atol=1e-15)
    assert spec.rows(h, 0).shape == (4,)                  # a run of 0 steps: the start's row


def test_constant_and_parameters(quad):
    c = _cli(quad, "1", "2", "3.5", "4")
    assert c.kind == "constant" and np.array_equal(c.rows(0.1, 5), [1, 2, 3.5, 4])
    e = _cli(quad, "m*grav/4", "0", "2*t", "L")              # fixed parameters are numbers
    assert np.allclose(e.rows(0.5, 3), [[9.81 / 4, 0, 0, 0.2], [9.81 / 4, 0, 1, 0.2],
                                        [9.81 / 4, 0, 2, 0.2]], rtol=0, atol=1e-15)


def test_tables_per_step_and_timed(quad, tmp_path):
    U = np.arange(40.0).reshape(10, 4)
    t = np.array([0.0, 0.1, 0.2, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0])
    np.savez(tmp_path / "step.npz", u=U)
    np.savez(tmp_path / "timed.npz", u=U, t=t)
    np.savetxt(tmp_path / "step.csv", U, delimiter=",")
    (tmp_path / "named.csv").write_text(
        "T3,t,T1,T4,T2\n" + "".join(f"{r[2]},{tt},{r[0]},{r[3]},{r[1]}\n"
                                    for r, tt in zip(U, t)))
    for f in ("step.npz", "step.csv"):
        s = _cli(quad, str(tmp_path / f))
        assert np.array_equal(s.rows(0.3, 6), U[:6])       # rows past the run: unused
        with pytest.raises(ModelError, match="has 10 rows, and the run needs one per step"):
            s.rows(0.3, 11)
    for f in ("timed.npz", "named.csv"):
        hold = _cli(quad, str(tmp_path / f))
        # t_k = 0, 0.1, 0.2, 0.3 (between rows 2 and 3: hold row 2), 0.4, ... (round-off
        # at the table's times does not move a step to the previous row)
        assert np.array_equal(hold.rows(0.1, 6), U[[0, 1, 2, 2, 3, 4]])
        lin = _cli(quad, str(tmp_path / f), interpolation="linear")
        assert np.allclose(lin.rows(0.1, 6)[3], 0.5 * (U[2] + U[3]), rtol=0, atol=1e-12)
        assert np.array_equal(hold.rows(0.5, 4)[-1], U[-1])  # after the last time: held
        with pytest.raises(ModelError, match="ends at t = 1, before the time 1.2"):
            lin.rows(0.3, 5)
        with pytest.raises(ModelError, match="starts at t = 0, after the time -0.1"):
            hold.rows(0.1, 3, t0=-0.1)


@pytest.mark.parametrize("text, parts", [
    ("T1,T2,T3\n1,2,3\n", ["row 0", "expected the columns T1, T2, T3, T4"]),
    ("1,2,3,4\n1,2,x,4\n", ["row 1", "expected a number, got 'x'"]),
    ("1,2,3,4\n1,2,3\n", ["row 1", "expected 4 columns, got 3"]),
    ("1,2,3\n", ["row 0", "expected 4 columns", "or 5 (t first)"]),
    ("1,2,3,4\n1,2,nan,4\n", ["row 1", "input T3 is not finite"]),
    ("0,1,2,3,4\n0,1,2,3,4\n", ["row 1", "times must increase strictly"]),
    ("", ["no rows"]),
])
def test_bad_csv_tables(tmp_path, text, parts):
    path = tmp_path / "u.csv"
    path.write_text(text)
    with pytest.raises(ModelError) as e:
        read_table(path, NAMES)
    assert "\n" not in str(e.value) and str(path) in str(e.value)
    for p in parts:
        assert p in str(e.value)


@pytest.mark.parametrize("arrays, parts", [
    (dict(v=np.ones((3, 4))), ["expected an array named u", "found v"]),
    (dict(u=np.ones((3, 3))), ["u", "expected shape (rows, 4)"]),
    (dict(u=np.array([["a"] * 4])), ["u", "expected real numbers"]),
    (dict(u=np.ones((3, 4)), t=np.ones(2)), ["t", "one time per row"]),
])
def test_bad_npz_tables(tmp_path, arrays, parts):
    path = tmp_path / "u.npz"
    np.savez(path, **arrays)
    with pytest.raises(ModelError) as e:
        read_table(path, NAMES)
    for p in parts:
        assert p in str(e.value)


@pytest.mark.parametrize("tokens, parts", [
    (("1", "2", "3"), ["option u", "expected 4 entries", "T1, T2, T3, T4"]),
    (("1", "2", "3", "inf"), ["option u[3]", "input T4 is not finite"]),
    (("1", "2", "3", "xi[0]"), ["option u[3]", "unknown name 'xi'"]),
    (("1", "2", "3", "__import__('os')"), ["option u[3]", "not allowed"]),
    (("1", "2", "3", "log(t - 1)"), ["option u[3]", "u(T4) = log(t - 1) is not finite at "
                                     "step 0"]),
    (("nope.csv",), ["option u.table", "nope.csv: no such file"]),
])
def test_bad_cli_tokens(quad, tokens, parts):
    with pytest.raises(ModelError) as e:
        _cli(quad, *tokens).rows(0.1, 3)
    assert "\n" not in str(e.value)
    for p in parts:
        assert p in str(e.value)


def test_u_is_not_in_the_module_hash(tmp_path):
    """u is a run-time value: another u does not recompile (the fingerprint drops it)."""
    from hpgen.model.fingerprint import normalized_model
    text = QUAD.read_text()
    other = text.replace('u: ["2.4525 + 0.2*sin(3*t)"', 'u: ["1.0"')
    assert other != text
    assert normalized_model(text) == normalized_model(other)


def test_scene_table_is_relative_to_the_model_file(tmp_path, monkeypatch):
    (tmp_path / "m").mkdir()
    U = np.arange(8.0).reshape(2, 4)
    np.savetxt(tmp_path / "m" / "thrust.csv", np.c_[[0.0, 1.0], U], delimiter=",",
               header="t,T1,T2,T3,T4", comments="")
    text = QUAD.read_text().replace(
        'u: ["2.4525 + 0.2*sin(3*t)", 2.4525, "2.4525 + 0.1*cos(2*t)", 2.4525]',
        "u: {table: thrust.csv, interpolation: linear}")
    (tmp_path / "m" / "quad.yaml").write_text(text)
    monkeypatch.chdir(tmp_path)
    spec = load_model(Path("m") / "quad.yaml").scene.u
    assert spec.kind == "table" and spec.interpolation == "linear"
    assert np.allclose(spec.rows(0.25, 3), [U[0], 0.75 * U[0] + 0.25 * U[1], 0.5 * (U[0] + U[1])],
                       rtol=0, atol=1e-15)
