"""Structure checks (hpgen.analysis.check / symplectic): every generated scheme tried is
symplectic to round-off, the explicit RKMK-RK4 is not (so the check can fail), and the
``hpgen check`` report / JSON / exit status.

Bound: relative defect max|Phi'^T Omega(p1) Phi' - Omega(p0)| / (|Phi'|_2^2 |Omega(p1)|_2)
<= SYMPLECTIC_RTOL = 1e-12. Phi' carries the round-off of an LU solve with dF/dz, relative
size a few eps cond(dF/dz), and the defect is quadratic in Phi': measured 1.4e-16 to 8.2e-16
here (cond(dF/dz) up to 2740), so the bound has a margin above 10^3. RKMK-RK4 at the same h has an
O(h^5) defect, measured 9e-8 (free body), 1.8e-7 (SE3) and 1.6e-6 (heavy top) relative at
h = 0.1, at least 1e4 times the bound.
"""
from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from conftest import EXAMPLES, FREE_BODY, HEAVY_TOP, ROOT, SE3_BODY
from hpgen.analysis.check import SYMPLECTIC_RTOL, run_check
from hpgen.analysis.rkmk import RKMK4
from hpgen.analysis.symplectic import GeneratedMap, ad_matrices, defect_along
from hpgen.derive import derive
from hpgen.model import load_model
from hpgen.tableaus import get_tableau

from reference import rotvec

H = 0.1
SCHEMES = [("stormer-verlet", "cay", "truncated"), ("gauss2", "exp", "exact"),
           ("midpoint", "cay", "exact"), ("euler-forward", "exp", "truncated")]
SE3_G0 = np.eye(4)
SE3_G0[:3, :3], SE3_G0[:3, 3] = rotvec([0.1, -0.2, 0.3]), [0.2, 0.0, -0.1]
PROBLEMS = {
    "free-body": (FREE_BODY, np.eye(3), np.array([0.4535961214255773, 0.0, 0.8912073600614354])),
    "heavy-top": (HEAVY_TOP, rotvec([0.3, 0.2, 0.0]), np.array([0.2, 5.0, 18.0])),
    "se3-body": (SE3_BODY, SE3_G0, np.array([0.6, 0.5, 0.27, 0.5, 0.3, -0.9])),
}
CASES = [(prob, *s) for prob in ("free-body", "heavy-top") for s in SCHEMES] + [
    ("se3-body", "midpoint", "cay", "exact"), ("se3-body", "euler-forward", "exp", "truncated")]
_RK = {}


def _states(run, g0, mu0, k=3, every=4):
    g, mu = run(g0, mu0, H, k * every)
    return [(g[i], mu[i]) for i in range(0, k * every + 1, every)]


def _rkmk_defect(model_file, prob):
    """RKMK-RK4 relative defects at states of its own run from the same initial state."""
    if prob not in _RK:
        text, g0, mu0 = PROBLEMS[prob]
        model = load_model(model_file(text))
        rk = RKMK4(model)
        states = _states(lambda *a: rk.simulate(*a), g0, mu0)
        _RK[prob] = [s["relative"] for s in defect_along(rk.map_jacobian,
                                                          ad_matrices(model.group), states, H)]
    return _RK[prob]


@pytest.mark.parametrize("prob,tableau,tau,rkmk", CASES,
                         ids=[f"{c[0]}-{c[1]}-{c[2]}-{c[3]}" for c in CASES])
def test_generated_schemes_are_symplectic_and_rkmk_is_not(compile_model, model_file, prob,
                                                          tableau, tau, rkmk):
    text, g0, mu0 = PROBLEMS[prob]
    model = load_model(model_file(text))
    integ = compile_model(text, tableau=tableau, tau=tau, rkmk=rkmk, backend="c")
    gm = GeneratedMap(integ, derive(model, get_tableau(tableau), tau, rkmk), model.group)

    def run(g, mu, h, steps):
        tr = integ.simulate(g0=g, mu0=mu, h=h, steps=steps)
        return tr.g, tr.mu

    states = _states(run, g0, mu0)
    recs = defect_along(gm.map_jacobian, ad_matrices(model.group), states, H)
    rel = max(r["relative"] for r in recs)
    assert gm.last["kernel_mismatch"] < 1e-12        # generated dF/dz = CasADi's
    rk = min(_rkmk_defect(model_file, prob))
    print(f"{prob} {tableau}/{tau}/{rkmk}: relative defect {rel:.2e} "
          f"(abs {max(r['absolute'] for r in recs):.2e}, cond J {gm.last['cond_J']:.0f}); "
          f"RKMK-RK4 {rk:.2e}")
    assert rel <= SYMPLECTIC_RTOL
    assert rk >= 1e4 * max(rel, SYMPLECTIC_RTOL)


DOC_KEYS = {"hpgen_version", "model", "file", "group", "scheme", "integrator", "h", "steps",
            "duration", "order", "energy", "momentum", "group_defect", "symplectic", "checks",
            "passed", "seconds", "inputs", "constraints", "symmetry"}


def test_cli_check_free_rigid_body_exits_0_and_writes_json(tmp_path, cache_dir):
    out = subprocess.run([sys.executable, "-m", "hpgen", "check",
                          str(EXAMPLES / "free_rigid_body.yaml"), "--json",
                          str(tmp_path / "c.json"), "--cache-dir", str(cache_dir)],
                         capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "symplecticity defect" in out.stdout and "PASS" in out.stdout
    r = json.loads((tmp_path / "c.json").read_text())
    assert set(r) == DOC_KEYS
    assert set(r["order"]) >= {"expected", "horizon", "h", "error", "observed", "floor"}
    assert set(r["energy"]) >= {"initial", "max_error", "relative_max_error", "drift_slope"}
    assert set(r["momentum"]) >= {"initial", "max_change", "left_invariant"}
    assert set(r["symplectic"]) >= {"defect", "relative", "tolerance", "states", "form"}
    assert set(r["checks"]) == {"symplectic", "group", "momentum", "symmetric", "constraints"}
    assert r["checks"]["symmetric"] is None and r["checks"]["constraints"] is None
    assert r["passed"] and all(v for k, v in r["checks"].items()
                               if k not in ("symmetric", "constraints"))
    assert r["integrator"]["tableau"] == "stormer-verlet" and r["steps"] == 1000
    assert len(r["order"]["error"]) == 3 and abs(r["order"]["observed"][-1] - 2) < 0.1
    assert r["symplectic"]["relative"] <= SYMPLECTIC_RTOL and r["group_defect"]["max"] < 1e-12
    assert max(r["momentum"]["max_change"]) < 1e-12


def test_check_fails_for_rkmk_rk4(tmp_path, cache_dir):
    from hpgen.cli import main
    path = EXAMPLES / "free_rigid_body.yaml"
    code = main(["check", str(path), "--scheme", "rkmk-rk4", "--steps", "40",
                 "--json", str(tmp_path / "rk.json")])
    r = json.loads((tmp_path / "rk.json").read_text())
    assert code == 3 and not r["passed"] and r["checks"]["symplectic"] is False
    assert r["symplectic"]["relative"] > 1e4 * SYMPLECTIC_RTOL
    assert abs(r["order"]["observed"][-1] - 4) < 0.1 and r["group_defect"]["max"] < 1e-12


def test_check_report_for_heavy_top_api(cache_dir):
    r = run_check(EXAMPLES / "heavy_top.yaml", tableau="midpoint", tau="cay", rkmk="exact",
                  steps=100, cache_dir=cache_dir, n_states=2)
    assert r["passed"] and r["checks"]["momentum"] is None      # l depends on g
    assert len(r["symplectic"]["states"]) == 2
    # the vertical spatial momentum e3.(R p) is conserved by the variational scheme
    assert r["momentum"]["max_change"][2] < 1e-12 * np.abs(r["momentum"]["initial"]).max()
    assert abs(r["order"]["observed"][-1] - 2) < 0.1
