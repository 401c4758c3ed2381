"""The run engine (hpgen.runtime.engine) through its declared interface.

- The runtime imports nothing of the compile side: no module of hpgen/runtime imports
  hpgen.api, hpgen.derive or hpgen.codegen, and ``import hpgen.runtime`` loads none of them
  (nor sympy, casadi, jinja2).
- An output written outside the runtime (here: only the last state of a run) runs on the one
  start -> advance -> restart loop: in chunks of any size it gives bitwise simulate's last
  record, on both backends.
- A run whose first call fails at step 0 is restarted from the first step solved by
  continuation; the RunHandle then holds the restarted run (its steps and snapshot are the
  run's, which chunked output commits).
"""
from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from hpgen.runtime.engine import Part, RunArgs, RunStart

ROOT = Path(__file__).resolve().parents[2]
FREE = ROOT / "examples" / "free_rigid_body.yaml"
COMPILE_SIDE = ("api", "derive", "codegen")


def _compile_side(node) -> set:
    """The compile-side packages an import statement of hpgen/runtime names."""
    if isinstance(node, ast.ImportFrom):
        if node.level == 2:          # from .. import x / from ..x import y
            names = [node.module or ""] + [a.name for a in node.names]
        elif node.level == 0 and (node.module or "").startswith("hpgen."):
            names = [node.module.split(".")[1]]
        else:
            return set()
    elif isinstance(node, ast.Import):
        names = [a.name.split(".")[1] for a in node.names if a.name.startswith("hpgen.")]
    else:
        return set()
    return {n.split(".")[0] for n in names} & set(COMPILE_SIDE)


def test_runtime_imports_nothing_of_the_compile_side():
    """Module level: none of api, derive, codegen; inside a function (casadi_step's lazy
    import of hpgen.derive.export): never hpgen.api."""
    for path in sorted((ROOT / "hpgen" / "runtime").glob("*.py")):
        tree = ast.parse(path.read_text())
        for node in tree.body:
            assert not _compile_side(node), f"{path.name}:{node.lineno}"
        for node in ast.walk(tree):
            assert "api" not in _compile_side(node), f"{path.name}:{node.lineno}"
    code = ("import sys, hpgen.runtime; "
            "bad = [m for m in ('sympy', 'casadi', 'jinja2', 'hpgen.api', 'hpgen.derive', "
            "'hpgen.codegen') if m in sys.modules]; print(bad); sys.exit(1 if bad else 0)")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                         text=True)
    assert out.returncode == 0, out.stdout + out.stderr


class LastState:
    """An output kept outside the runtime: only the state after the run's last step."""

    def __init__(self, engine, s: RunStart, chunk: int):
        self.engine, self.s, self.chunk = engine, s, chunk

    def span(self, k, first):
        return None if k >= self.s.steps else (min(self.chunk, self.s.steps - k),)

    def advance(self, run, span) -> Part:
        done, g, p, st = self.engine.backend.advance(run, self.s.h, span[0], 1, self.s.opts)
        return Part(done, (g[-1:], p[-1:]), st)


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("chunk", [1, 7, 50])
def test_an_output_of_ones_own_runs_on_the_one_loop(compile_model, backend, chunk):
    integ = compile_model(FREE, backend=backend)
    g0, mu0, h, steps = np.eye(3), np.array([0.3, -1.1, 0.7]), 0.05, 50
    engine = integ.engine
    s = engine.prepare(RunArgs(g0, h, steps, mu0=mu0))
    out = LastState(engine, s, chunk)
    parts = list(engine.parts(out, s))
    assert [k for k, _, _ in parts] == list(range(0, steps, chunk))
    assert [first for _, first, _ in parts] == [True] + [False] * (len(parts) - 1)
    g, p = parts[-1][2].data
    tr = integ.simulate(g0, h, steps, mu0=mu0)
    assert g[-1].tobytes() == tr.g[-1].T.ravel().tobytes()
    assert p[-1].tobytes() == tr.mu[-1].tobytes()


@pytest.mark.parametrize("backend", ["c", "python"])
def test_a_failed_first_call_restarts_and_the_handle_follows(compile_model, backend):
    integ = compile_model(FREE, backend=backend)
    engine = integ.engine
    g0, mu0, h, steps = np.eye(3), np.array([0.3, -1.1, 0.7]), 0.05, 12
    good = engine.prepare(RunArgs(g0, h, steps, mu0=mu0))
    bad = RunStart(good.h, good.steps, good.every, good.opts, good.g0, good.mu0, good.xi0,
                   np.full(integ.nz, 1e200), good.inputs)
    handle = engine.new_run(bad)
    first_run = handle.run
    out = LastState(engine, bad, steps)
    (k, first, part), = list(engine.parts(out, bad, handle))
    assert part.status["code"] == 0 and part.done == steps
    assert handle.run is not first_run and handle.steps_done() == steps
    tr = integ.simulate(g0, h, steps, mu0=mu0)
    np.testing.assert_allclose(part.data[1][-1], tr.mu[-1], rtol=0, atol=1e-12)
    # the snapshot is the restarted run's: restored, it continues from step `steps`
    again = engine.restore(handle.snapshot(), None)
    assert again.steps_done() == steps
