"""``hpgen check`` on composed steps (--compose) and on constrained models
(hpgen.analysis.check, hpgen.analysis.constrained).

- Composed: Stormer-Verlet (cay, truncated) composed by suzuki4 on the heavy top is order 4
  (observed slope within ORDER_TOL of 4 against DOP853), symplectic (the product of the
  substeps' Jacobians, relative defect within the check's round-off bound) and its base step
  symmetric (S(-h) S(h) = id to round-off). With the exact RKMK constraint the base step is
  not symmetric (measured here on the plain step), so a composition of it is refused, as are
  a non-symmetric tableau, a splitting base and the rkmk-rk4 scheme with a composition: in
  one line (CLI exit 2).
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
    from hpgen.analysis.check import run_check
    from hpgen.analysis.check_order import ORDER_TOL
    r = run_check(EXAMPLES / "heavy_top.yaml", tableau="stormer-verlet", tau="cay",
                  rkmk="truncated", compose="suzuki4", h=0.05, steps=40, order_horizon=1.0,
                  cache_dir=cache_dir, n_states=2)
    assert r["integrator"]["compose"] == "suzuki4"
    assert r["order"]["expected"] == 4 and "suzuki4" in r["order"]["why"]
    assert abs(r["order"]["observed"][-1] - 4) <= ORDER_TOL
    assert r["checks"]["symplectic"] and r["checks"]["group"] and r["checks"]["symmetric"]
    assert r["passed"] and r["symplectic"]["relative"] < 1e-13
    assert r["symmetry"]["defect"] < 1e-14


def _symmetry_defect(integ, h):
    """max |S(-h) S(h) x - x| of the plain step from one heavy-top state."""
    from scipy.spatial.transform import Rotation
    g = Rotation.from_rotvec([0.3, 0.2, 0.1]).as_matrix()
    p = np.asarray(integ.legendre(g, np.array([0.2, 1.0, 3.0])))
    g1, p1 = integ.step(g, p, h)
    g2, p2 = integ.step(g1, p1, -h)
    return max(np.abs(g2 - g).max(), np.abs(p2 - p).max())


def test_exact_rkmk_base_is_not_symmetric_and_is_refused(compile_model, cache_dir):
    """The plain step S(h) at h = 0.05: Stormer-Verlet cay/exact on the heavy top misses
    S(-h) S(h) = id by O(h^4) (4e-4 at h = 0.05, 2.6e-5 at 0.025), Gauss 2 exp/exact on the
    free body (l left-invariant) by O(h^6) (2e-10); cay/truncated Stormer-Verlet on the
    heavy top is symmetric to round-off. So compose refuses rkmk: exact, in one line."""
    from hpgen.analysis.check import run_check
    from hpgen.cli import main
    top = EXAMPLES / "heavy_top.yaml"
    exact = compile_model(top, tableau="stormer-verlet", tau="cay", rkmk="exact",
                          backend="python")
    truncated = compile_model(top, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                              backend="python")
    free = compile_model(EXAMPLES / "free_rigid_body.yaml", tableau="gauss2", tau="exp",
                         rkmk="exact", backend="python")
    d1, d2 = _symmetry_defect(exact, 0.05), _symmetry_defect(exact, 0.025)
    assert d1 > 1e-6 and abs(np.log2(d1 / d2) - 4) < 0.5, (d1, d2)
    assert _symmetry_defect(free, 0.05) > 1e-11
    assert _symmetry_defect(truncated, 0.05) < 1e-14
    with pytest.raises(ModelError, match="integrator.compose: rkmk exact does not keep the "
                                         "step of stormer-verlet symmetric"):
        run_check(top, tableau="stormer-verlet", tau="cay", rkmk="exact", compose="suzuki4",
                  h=0.05, steps=10, cache_dir=cache_dir, n_states=1)
    with pytest.raises(ModelError, match="use rkmk: truncated"):
        compile_model(EXAMPLES / "free_rigid_body.yaml", tableau="gauss2", rkmk="exact",
                      compose="suzuki4")
    assert main(["run", str(top), "--compose", "suzuki4", "--steps", "4", "--out",
                 str(cache_dir / "x.npz"), "--cache-dir", str(cache_dir)]) == 2


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
    from hpgen.analysis.check import run_check
    from hpgen.analysis.check_order import ORDER_TOL
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
