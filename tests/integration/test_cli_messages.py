"""What ``hpgen`` says to a newcomer (issue 17): the conservation figures of ``hpgen run`` are
only those of the spatial momenta the model's symmetry conserves (decided from the model by
hpgen.analysis.symmetry, not from the run's numbers); the scheme actually used is printed by
``compile`` and ``run``; ``hpgen --help`` lists every subcommand on one line each;
``hpgen compile`` without -o writes nothing into the working directory."""
from __future__ import annotations

import os
import re
import subprocess
import sys

import numpy as np
import pytest

from conftest import EXAMPLES, FREE_BODY, ROOT
from hpgen.analysis.symmetry import conserved_directions, describe
from hpgen.model import load_model, load_model_text

REQUIRED_COMMANDS = ("compile", "run", "list", "check", "bench")


def hpgen(*args, cwd=None, env=None):
    env = {**os.environ, "PYTHONPATH": str(ROOT), **(env or {})}
    return subprocess.run([sys.executable, "-m", "hpgen", *map(str, args)], capture_output=True,
                          text=True, timeout=600, cwd=cwd, env=env)


# ---- which momenta are conserved ----------------------------------------------------------

@pytest.mark.parametrize("example, expected", [
    ("heavy_top", [[0, 0, 1]]),                       # only the vertical e3
    ("free_rigid_body", np.eye(3)),                   # l left-invariant: all
    ("underwater_vehicle", np.eye(6)),
    ("double_body_chain", [[0, 0, 1, 0, 0, 1]]),      # the chain turned as a whole about e3
])
def test_conserved_directions_of_the_examples(example, expected):
    V = conserved_directions(load_model(EXAMPLES / f"{example}.yaml"))
    assert np.array_equal(V, np.array(expected, dtype=float)), V


def _sums(d, blocks):
    """Rows e_k + e_(6 + k) + ... (one per k in blocks): a component summed over the bodies."""
    return [[1.0 if i % 6 == k else 0.0 for i in range(d)] for k in blocks]


@pytest.mark.parametrize("example, expected", [
    # pinned at the origin: only the vertical angular momentum of the whole chain, not a link's
    ("pendulum_chain", _sums(12, [2])),
    ("four_bar", np.zeros((0, 9))),                    # two pins to the ground: nothing
    ("spacecraft_panels", _sums(18, range(6))),        # free tree: the total momentum
])
def test_constraints_restrict_the_conserved_directions(example, expected):
    model = load_model(EXAMPLES / f"{example}.yaml")
    V = conserved_directions(model, g0=model.scene.g0)
    assert np.array_equal(V, np.array(expected, dtype=float).reshape(-1, V.shape[1])), V


SO3_HEAD = "name: m\ngroup: SO3\nparameters: {k: 2.0}\n"
R2_HEAD = "name: m\ngroup: R2\nparameters: {k: 2.0}\n"


@pytest.mark.parametrize("text, expected", [
    # g appears in l, yet l is invariant on the group: |row 2 of R| = 1 (decided on the group)
    (SO3_HEAD + "lagrangian: 0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2) - k*(R[2,0]**2 + R[2,1]**2"
     " + R[2,2]**2)\n", np.eye(3)),
    # a potential in x[0] only: translation along e1 (coordinate 1) is a symmetry
    (R2_HEAD + "lagrangian: 0.5*(xi[0]**2 + xi[1]**2) - 0.5*k*x[0]**2\n", [[0, 1]]),
    (R2_HEAD + "lagrangian: 0.5*(xi[0]**2 + xi[1]**2) - 0.5*k*(x[0]**2 + x[1]**2)\n",
     np.zeros((0, 2))),
    # a potential in x[0] - x[1]: the combination e0 + e1
    (R2_HEAD + "lagrangian: 0.5*(xi[0]**2 + xi[1]**2) - 0.5*k*(x[0] - x[1])**2\n", [[1, 1]]),
])
def test_conserved_directions_are_decided_from_the_lagrangian(text, expected):
    V = conserved_directions(load_model_text(text))
    assert np.array_equal(V, np.array(expected, dtype=float).reshape(-1, V.shape[1])), V
    assert describe(np.array([[1.0, 1.0]])) == ["J[0] + J[1]"]


def _momentum_line(stdout):
    line, = [ln for ln in stdout.splitlines() if "spatial momentum" in ln]
    return line, re.findall(r"\d\.\d\de[+-]\d\d", line)


def test_run_reports_only_the_conserved_momentum(tmp_path):
    out = hpgen("run", EXAMPLES / "heavy_top.yaml", "--out", tmp_path / "top.npz", "--steps",
                "400", "--cache-dir", tmp_path / "cache")
    assert out.returncode == 0, out.stderr
    line, figures = _momentum_line(out.stdout)
    assert "J[2]" in line and "J[0]" not in line and "J[1]" not in line
    m = np.load(tmp_path / "top.npz")["momentum"]
    assert figures == [f"{np.abs(m[:, 2] - m[0, 2]).max():.2e}"]     # the one figure is J[2]'s
    body = hpgen("run", EXAMPLES / "free_rigid_body.yaml", "--out", tmp_path / "body.npz",
                 "--steps", "100", "--cache-dir", tmp_path / "cache")
    assert body.returncode == 0, body.stderr
    line, figures = _momentum_line(body.stdout)
    assert "conserved" in line and len(figures) == 3


# ---- scheme, help, where compile writes ----------------------------------------------------

def test_help_lists_every_subcommand_on_one_line():
    from hpgen.cli import _parser
    sub = next(a for a in _parser()._actions if a.dest == "command")
    assert set(REQUIRED_COMMANDS) <= set(sub.choices)
    out = hpgen("--help", env={"COLUMNS": "80"})
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    for name in sub.choices:
        i = next(i for i, ln in enumerate(lines) if re.match(rf"^    {name}\s+\S", ln))
        # the next line is another subcommand or the end of the list, not a wrapped line
        assert not re.match(r"^\s{6,}\S", lines[i + 1]), (name, lines[i:i + 2])
    description = next(ln for ln in lines if ln.startswith("hpgen:"))
    assert all(name in description for name in ("compile", "run", "check", "benchmark"))


def test_compile_without_o_writes_into_the_cache_only_and_prints_the_scheme(tmp_path):
    model = tmp_path / "body.yaml"
    model.write_text(FREE_BODY)                      # no integrator: section
    work = tmp_path / "work"
    work.mkdir()
    out = hpgen("compile", model, "--cache-dir", tmp_path / "cache", cwd=work)
    assert out.returncode == 0, out.stderr
    assert list(work.iterdir()) == [], "compile wrote into the working directory"
    first, scheme = out.stdout.splitlines()
    module = first.split()[0]
    assert module.startswith(str(tmp_path / "cache")) and os.path.isdir(module)
    assert "build cache" in first and "-o" in first
    assert scheme == ("scheme: tableau stormer-verlet, tau cay, rkmk exact (tableau, tau, "
                      "rkmk: hpgen's default)"), scheme
    run = hpgen("run", EXAMPLES / "heavy_top.yaml", "--out", tmp_path / "t.npz", "--steps", "10",
                "--cache-dir", tmp_path / "cache", "--tau", "cay")
    assert run.returncode == 0, run.stderr
    assert run.stdout.splitlines()[0] == ("scheme: tableau gauss2, tau cay, rkmk exact (--tau "
                                          "given; tableau, rkmk from the model's integrator:)")


def test_run_refuses_chunk_0_and_writes_nothing(tmp_path):
    out = hpgen("run", EXAMPLES / "free_rigid_body.yaml", "--out", tmp_path / "r.npz", "--chunk",
                "0", "--cache-dir", tmp_path / "cache")
    assert out.returncode == 2 and out.stderr.strip() == \
        "hpgen: error: chunk: expected an integer >= 1, got 0"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cache"]
