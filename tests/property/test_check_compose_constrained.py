"""``hpgen check`` on composed steps (--compose) and on constrained models
(hpgen.analysis.check, hpgen.analysis.constrained).

- Composed: Stormer-Verlet (cay, truncated) composed by suzuki4 on the heavy top is order 4
  (observed slope within ORDER_TOL of 4 against DOP853), symplectic (the product of the
  substeps' Jacobians, relative defect within the check's round-off bound) and its base step
  symmetric (S(-h) S(h) = id to round-off); with the exact RKMK constraint the base step is
  not symmetric and the check fails on it. A non-symmetric tableau or a splitting base, or
  the rkmk-rk4 scheme with a composition, is refused in one line (CLI exit 2).
- Constrained (four-bar linkage, pendulum chain N = 3): the constraint residuals max|phi| and
  max|Phi xi| at round-off (<= CONSTRAINT_TOL = 1e-12), order 2 by self-convergence,
  symplectic on the tangent space of the constraint manifold; off the manifold (all of
  T*G) the same Jacobian's defect is O(1e-6) or more: the restriction is what makes it pass.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from hpgen.errors import ModelError

EXAMPLES = ROOT / "examples"


def test_composed_check_is_order_four_symplectic_and_symmetric(cache_dir):
    from hpgen.analysis.check import ORDER_TOL, run_check
    r = run_check(EXAMPLES / "heavy_top.yaml", tableau="stormer-verlet", tau="cay",
                  rkmk="truncated", compose="suzuki4", h=0.05, steps=40, order_horizon=1.0,
                  cache_dir=cache_dir, n_states=2)
    assert r["integrator"]["compose"] == "suzuki4"
    assert r["order"]["expected"] == 4 and "suzuki4" in r["order"]["why"]
    assert abs(r["order"]["observed"][-1] - 4) <= ORDER_TOL
    assert r["checks"]["symplectic"] and r["checks"]["group"] and r["checks"]["symmetric"]
    assert r["passed"] and r["symplectic"]["relative"] < 1e-13
    assert r["symmetry"]["defect"] < 1e-14


def test_composed_check_fails_on_a_non_symmetric_base(cache_dir):
    """Stormer-Verlet with the exact RKMK constraint on the heavy top: S(-h) S(h) differs
    from the identity by O(h^4) (4e-6 at h = 0.05), so suzuki4 of it is order 3, not 4: the
    symmetry check fails (exit status 3 in the CLI) and the observed order shows it."""
    from hpgen.analysis.check import run_check
    r = run_check(EXAMPLES / "heavy_top.yaml", tableau="stormer-verlet", tau="cay",
                  rkmk="exact", compose="suzuki4", h=0.05, steps=10, order_horizon=1.0,
                  cache_dir=cache_dir, n_states=1)
    assert r["checks"]["symmetric"] is False and not r["passed"]
    assert r["symmetry"]["defect"] > 1e-7
    assert r["order"]["refined"]["observed"][-1] < 3.2


def test_composed_check_refusals(cache_dir, capsys):
    from hpgen.analysis.check import run_check
    from hpgen.cli import main
    with pytest.raises(ModelError, match="integrator.compose: the tableau euler-forward is "
                                         "not symmetric"):
        run_check(EXAMPLES / "heavy_top.yaml", tableau="euler-forward", compose="suzuki4",
                  steps=4, cache_dir=cache_dir)
    with pytest.raises(ModelError, match="rkmk-rk4 scheme .* unconstrained, uncomposed"):
        run_check(EXAMPLES / "heavy_top.yaml", scheme="rkmk-rk4", compose="suzuki4", steps=4)
    assert main(["check", str(EXAMPLES / "heavy_top.yaml"), "--tableau", "split4-yoshida",
                 "--compose", "suzuki4", "--steps", "4", "--cache-dir", str(cache_dir)]) == 2
    err = capsys.readouterr().err.strip()
    assert "already a composition" in err and "\n" not in err


@pytest.mark.parametrize("name, parameters, rows", [("four_bar", None, 8),
                                                    ("pendulum_chain", {"N": 3}, 9)])
def test_constrained_check(cache_dir, name, parameters, rows):
    from hpgen.analysis.check import ORDER_TOL, run_check
    from hpgen.analysis.constrained import CONSTRAINT_TOL
    r = run_check(EXAMPLES / f"{name}.yaml", steps=60, cache_dir=cache_dir, n_states=2,
                  parameters=parameters)
    k = r["constraints"]
    assert k["count"] == rows and max(k["position"], k["velocity"]) <= CONSTRAINT_TOL
    assert r["checks"]["constraints"] and r["checks"]["symplectic"] and r["passed"]
    assert r["checks"]["momentum"] is None
    assert r["symplectic"]["on_manifold"] and r["symplectic"]["relative"] < 1e-13
    assert r["order"]["reference"].startswith("self-convergence")
    assert abs(r["order"]["observed"][-1] - 2) <= ORDER_TOL


def test_the_manifold_restriction_is_what_passes(cache_dir):
    """The four-bar step's Jacobian: defect on the tangent space of the constraint manifold
    at round-off, on all of T*G O(1) (the projection onto the manifold)."""
    from hpgen.analysis.check import _Hpgen, _load
    from hpgen.analysis.constrained import ManifoldCheck, manifold_defect
    from hpgen.analysis.rkmk import ContinuousEquations
    from hpgen.analysis.symplectic import ad_matrices, omega_matrix, symplectic_defect
    path = EXAMPLES / "four_bar.yaml"
    model = _load(path)
    sc, eq = model.scene, ContinuousEquations(model)
    sch = _Hpgen(path, model, None, None, None, "c", cache_dir)
    g, mu = sch.simulate(np.array(sc.g0), None if sc.mu0 is None else np.array(sc.mu0),
                         sc.h, 30) if sc.mu0 is not None else sch.simulate(
        np.array(sc.g0), eq.legendre(np.array(sc.g0), np.array(sc.xi0)), sc.h, 30)
    man, ad = ManifoldCheck(model), ad_matrices(model.group)
    for k in (0, 29):
        T = man.tangent_basis(g[k], mu[k], eq.velocity(g[k], mu[k]))
        assert T.shape[1] == 2 * (model.group.d - man.m)
        Phi, g1, p1 = sch.map_jacobian(g[k], mu[k], sc.h)
        om0, om1 = omega_matrix(ad, mu[k]), omega_matrix(ad, p1)
        on = manifold_defect(Phi, T, om0, om1)[1]
        off = symplectic_defect(Phi, om0, om1)[1]
        assert on < 1e-13 and off > 1e-6, (on, off)


def test_cli_check_constrained_and_composed(cache_dir, capsys):
    from hpgen.cli import main
    assert main(["check", str(EXAMPLES / "pendulum_chain.yaml"), "--set", "N=3", "--steps",
                 "30", "--states", "1", "--cache-dir", str(cache_dir)]) == 0
    out = capsys.readouterr().out
    assert "constraint residual" in out and "constraint manifold" in out
    assert "[SE3, SE3, SE3]" in out
