"""hpgen check on forced and open models (issue 16): the energy-work balance and the forced
momentum balance instead of conservation, observed orders 4 against DOP853 on the
continuous forced equations (SO3 and SE3), and with zero forces the closed model's figures,
symplecticity defect included."""
from __future__ import annotations

import subprocess
import sys

import pytest

from conftest import EXAMPLES
from hpgen.analysis.check import run_check
from hpgen.analysis.check_report import format_report


@pytest.mark.parametrize("name", ["damped_top", "underwater_vehicle_drag", "spacecraft_slew"])
def test_forced_check_reports_balances_and_order(name, cache_dir):
    """Observed order 4 (Gauss 2 exact; measured 4.00 4.00 on the three scenes at the scene's
    h), E - W within 1e-5 of E_0 over 200 steps (measured 1.5e-6, 1.1e-6 at most, 2.9e-10),
    no symplecticity figure (n/a), the momentum balance of a left-invariant l (the slew:
    measured 3.7e-9) below 1e-7, and the report's rows say so."""
    r = run_check(EXAMPLES / f"{name}.yaml", steps=200, cache_dir=cache_dir)
    o = r["order"]
    assert r["passed"] and r["energy"]["balance"]
    assert o["expected"] == 4 and all(abs(v - 4) <= 0.25 for v in o["observed"])
    assert r["energy"]["max_error"] < 1e-5
    assert r["symplectic"]["defect"] is None and r["checks"]["symplectic"] is None
    text = format_report(r)
    assert "energy-work max |E - W - E0|" in text and "symplecticity defect" in text
    if name == "spacecraft_slew":
        assert r["momentum"]["balance"] and max(r["momentum"]["max_change"]) < 1e-7
        assert "momentum - impulse" in text


def test_zero_forces_check_equals_the_closed_model(tmp_path, cache_dir):
    """The heavy top with runtime parameters and forces that are identically zero: the
    closed heavy top's errors, energy and symplecticity figures (the same step: the forces
    vanish and the step vector only carries Mg)."""
    text = (EXAMPLES / "heavy_top.yaml").read_text()
    path = tmp_path / "open_top.yaml"
    path.write_text(text.replace("integrator:", "runtime_parameters: [Mg]\nforces: [\"0\", "
                                 "\"0\", \"0\"]\nintegrator:"))
    opened = run_check(path, steps=100, cache_dir=cache_dir)
    closed = run_check(EXAMPLES / "heavy_top.yaml", steps=100, cache_dir=cache_dir)
    assert not opened["energy"]["balance"] and opened["checks"]["symplectic"]
    assert opened["order"]["error"] == pytest.approx(closed["order"]["error"], rel=1e-9)
    assert opened["energy"]["max_error"] == pytest.approx(closed["energy"]["max_error"],
                                                          rel=1e-6)
    assert opened["symplectic"]["relative"] < 1e-14


def test_cli_check_on_a_forced_model(cache_dir):
    res = subprocess.run([sys.executable, "-m", "hpgen", "check",
                          str(EXAMPLES / "damped_top.yaml"), "--steps", "100", "--cache-dir",
                          str(cache_dir)], capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr
    assert "energy-work max |E - W - E0|" in res.stdout and "energy max |E - E0|" not in \
        res.stdout
