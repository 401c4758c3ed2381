"""``hpgen run`` failing mid-way, once per error type (issue 15 item 6): ConvergenceError (a
non-finite step), DomainError (the chart map leaves its domain), RecordError (a record
expression becomes non-finite). Each: exit status 1, one line on stderr naming the step and
where the samples before the failure were saved, no traceback; the saved file is flagged
partial=True and holds bitwise the samples the API's partial Records hold; the chunk folder
of the run is removed (nothing to resume: the failure is deterministic). A failed run prints
the counters' line a completed run prints (the guard's re-solved steps) before its error."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import hpgen
from hpgen.model import load_model

SCENES = {
    # Stormer-Verlet past its stability limit (omega h = 10): the state overflows
    "ConvergenceError": ("""
name: spring
group: R2
parameters: {k: 10000.0}
lagrangian: 0.5*(xi[0]**2 + xi[1]**2) - 0.5*k*(x[0]**2 + x[1]**2)
integrator: {tableau: stormer-verlet, tau: cay, rkmk: truncated}
scene:
  h: 0.1
  steps: 1000
  initial: {g: {position: [1.0, 0.0]}, xi: [0.0, 50.0]}
  record: [g, mu]
""", "non-finite value"),
    # a pendulum falling from near the top speeds up until the step's root lies past exp's
    # domain |h omega| < pi (Newton converges there: a DomainError; past skew's fold instead,
    # Newton diverges: a ConvergenceError, issue 17)
    "DomainError": ("""
name: pendulum
group: SO3
parameters: {Mg: 300.0}
lagrangian: 0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2) - Mg*R[2,2]
integrator: {tableau: gauss2, tau: exp, rkmk: exact}
scene:
  h: 0.1
  steps: 400
  initial: {g: {rotvec: [0.1, 0.0, 0.0]}, xi: [0.0, 0.0, 0.0]}
  record: [g, mu, energy]
""", "domain"),
    # the same pendulum, slower: sqrt(R[2,2]) is NaN once it has fallen past the horizontal
    "RecordError": ("""
name: pendulum
group: SO3
parameters: {Mg: 1.0}
lagrangian: 0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2) - Mg*R[2,2]
integrator: {tableau: stormer-verlet, tau: cay, rkmk: truncated}
scene:
  h: 0.05
  steps: 400
  initial: {g: {rotvec: [0.1, 0.0, 0.0]}, xi: [0.0, 0.0, 0.0]}
  record: [energy, {root: "sqrt(R[2,2])"}]
""", "not finite"),
}
CHUNK = 4


@pytest.mark.parametrize("error", list(SCENES))
def test_run_failing_mid_way_saves_partial_and_exits_1(tmp_path, error):
    text, words = SCENES[error]
    model = tmp_path / "model.yaml"
    model.write_text(text)
    cache, out = tmp_path / "cache", tmp_path / "run.npz"
    sc = load_model(model).scene
    with pytest.raises(hpgen.ConvergenceError) as info:
        hpgen.compile(model, cache_dir=cache).record(sc.g0, sc.h, sc.steps, xi0=sc.xi0,
                                                      every=sc.every)
    e = info.value
    assert type(e).__name__ == error and e.step > 2 * CHUNK, (type(e), e.step)   # mid-way
    proc = subprocess.run([sys.executable, "-m", "hpgen", "run", str(model), "--out", str(out),
                           "--cache-dir", str(cache), "--chunk", str(CHUNK)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 1, proc.stderr[-3000:]
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in proc.stderr, proc.stderr[-3000:]
    n = len(e.partial)
    assert lines[0].startswith(f"hpgen: error: step {e.step} ") and words in lines[0]
    assert lines[0].endswith(f"the {n} samples before the failure were saved to {out} with "
                             "partial=True"), lines[0]
    data = np.load(out)
    assert bool(data["partial"]) and str(data["error"]) == str(e)
    for name in ("t", *e.partial.names):
        ref = e.partial.t if name == "t" else e.partial[name]
        assert np.array_equal(data[name], ref, equal_nan=True), name
    assert not (tmp_path / "run.npz.partial").exists()
    assert [p.name for p in tmp_path.iterdir()] == ["model.yaml", "cache", "run.npz"] or \
        sorted(p.name for p in tmp_path.iterdir()) == ["cache", "model.yaml", "run.npz"]


# the three-root particle of tests/unit/test_run_guard.py, pushed away from x = 0: its
# velocity crosses the fold of xi - xi^3, where the guard re-solves a step, and a later step
# has no root near the predictor (Newton does not converge)
GUARDED_THEN_FAILING = """
name: particle
group: R1
parameters: {b: 1.0}
lagrangian: 0.5*xi[0]**2 - 0.25*b*xi[0]**4 + 0.5*x[0]**2
scene:
  h: 0.1
  steps: 100
  initial: {g: {position: [0.65]}, xi: [0.0]}
"""


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("section", [False, True])
def test_a_failed_run_prints_its_counters_line_then_the_error(tmp_path, cache_dir, capsys,
                                                              backend, section):
    """The guard's line of the steps done before the failure (stdout), as a run that
    completes prints it, then the error's line (stderr, exit 1); the saved file holds the
    counters of the API's partial result, Newton iterations of the failed step included."""
    from hpgen.cli import main
    model = tmp_path / "model.yaml"
    model.write_text(GUARDED_THEN_FAILING + ('  section: "mu[0]"\n' if section else ""))
    sc = load_model(model).scene
    integ = hpgen.compile(model, backend=backend, cache_dir=cache_dir)
    with pytest.raises(hpgen.ConvergenceError) as info:
        (integ.sections if section else integ.record)(sc.g0, sc.h, sc.steps, xi0=sc.xi0)
    part = info.value.partial
    assert part.guarded == 1 and part.newton_iterations > 0
    out = tmp_path / "run.npz"
    capsys.readouterr()
    assert main(["run", str(model), "--out", str(out), "--cache-dir", str(cache_dir),
                 "--backend", backend, "--chunk", "10", "--no-plot", "--no-progress"]) == 1
    std = capsys.readouterr()
    assert std.out.splitlines()[-1] == ("  1 step re-solved by the wrong-root guard (its root "
                                        "jumped away from the predictor's offsets)")
    line, = std.err.strip().splitlines()
    assert line.startswith(f"hpgen: error: step {info.value.step} ") and "Newton" in line
    with np.load(out) as f:
        assert bool(f["partial"]) and int(f["guarded"]) == 1
        assert int(f["newton_iterations"]) == part.newton_iterations
