"""Failure at run time: reported with step, time, residual and iterations, never hidden;
the samples computed before the failure are kept and flagged partial."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

import hpgen
from conftest import FREE_BODY
from hpgen.runtime import NewtonOptions

SKEW_SCENE = FREE_BODY + """
integrator: {tableau: midpoint, tau: skew, rkmk: truncated}
scene:
  h: 0.2
  steps: 50
  initial: {g: identity, mu: [2.0, 0.5, 0.5]}
  record: [g, mu, energy]
"""


@pytest.mark.parametrize("backend", ["c", "python"])
def test_skew_outside_its_domain_is_a_domain_error(compile_model, backend):
    """The skew projector needs |h xi| < 1; here |xi| ~ 1.1 so h = 0.2 is fine and h = 1.2
    is not: the step must fail as a DomainError naming step 0 (no garbage, no NaN state)."""
    integ = compile_model(SKEW_SCENE, backend=backend)
    ok = integ.simulate(g0=np.eye(3), mu0=[2.0, 0.5, 0.5], h=0.2, steps=20)
    assert np.isfinite(ok.mu).all()
    with pytest.raises(hpgen.DomainError) as err:
        integ.simulate(g0=np.eye(3), mu0=[2.0, 0.5, 0.5], h=1.2, steps=20)
    e = err.value
    assert e.step == 0 and "domain" in str(e) and "smaller h" in str(e)
    assert e.partial is not None and e.partial.partial and len(e.partial) == 1


@pytest.mark.parametrize("backend", ["c", "python"])
def test_newton_failure_reports_and_keeps_partial_trajectory(compile_model, backend):
    integ = compile_model(FREE_BODY, tableau="gauss2", tau="cay", rkmk="exact", backend=backend)
    with pytest.raises(hpgen.ConvergenceError) as err:
        integ.simulate(g0=np.eye(3), mu0=[0.4, 0.1, 0.8], h=0.1, steps=10,
                       newton=NewtonOptions(maxit=1))
    e = err.value
    assert (e.step, e.iterations) == (0, 1) and e.residual > 0
    assert "did not converge" in str(e) and e.partial.partial


def test_cli_run_saves_partial_samples_and_exits_1(tmp_path, model_file):
    path = model_file(SKEW_SCENE.replace("h: 0.2", "h: 1.2"))
    out = subprocess.run([sys.executable, "-m", "hpgen", "run", str(path), "--out",
                          str(tmp_path / "run.npz"), "--cache-dir", str(tmp_path / "c")],
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 1
    assert out.stderr.startswith("hpgen: error: step 0") and "Traceback" not in out.stderr
    data = np.load(tmp_path / "run.npz")
    assert bool(data["partial"]) and data["g"].shape == (1, 3, 3) and "domain" in str(data["error"])
