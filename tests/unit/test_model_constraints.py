"""The ``constraints:`` key (hpgen.model.constraints, hpgen.model.expr.parse_constraint) and the
constrained step's derivation (hpgen.derive.constraints)."""
from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from hpgen.model import load_model_text
from hpgen.model.fingerprint import normalized_model
from conftest import model_error

PEND = """\
name: pend
group: SE3
parameters: {m: 1.0, J: [0.02, 0.02, 0.002], grav: 9.81, top: [0.0, 0.0, 0.25]}
lagrangian: 0.5*(J[0]*xi[0]**2 + J[1]*xi[1]**2 + J[2]*xi[2]**2) + 0.5*m*(xi[3]**2 + xi[4]**2 + xi[5]**2) - m*grav*x[2]
constraints:
  - x + dot(R, top)
"""

PLANAR = """\
name: planar
group: [SE2, SE2]
parameters: {a: [2, 0], k: 0.5}
lagrangian: 0.5*(xi_0[0]**2 + xi_0[1]**2 + xi_0[2]**2 + xi_1[0]**2 + xi_1[1]**2 + xi_1[2]**2) - k*x_1[1]
constraints:
  - x_0[0]**2 + x_0[1]**2 - 1
  - x_1 - x_0 - dot(R_0, a)
"""


def _err(text) -> str:
    return model_error(text)


def _g(i, j):
    return sp.Symbol(f"g_{i}_{j}", real=True)


def test_vector_constraint_rows():
    m = load_model_text(PEND, "m.yaml")
    (c,) = m.constraints
    assert c.text == "x + dot(R, top)"
    assert len(c.rows) == 3
    for r in range(3):     # x_r + R[r, 2] * 0.25, the g symbols equal to the Lagrangian's
        assert sp.simplify(c.rows[r] - (_g(r, 3) + sp.Rational(1, 4) * _g(r, 2))) == 0
        assert c.rows[r].free_symbols <= {s for row in m.g_symbols for s in row}


def test_scalar_and_product_rows_in_file_order():
    m = load_model_text(PLANAR, "m.yaml")
    assert [len(c.rows) for c in m.constraints] == [1, 2]
    assert sp.expand(m.constraints[0].rows[0] - (_g(0, 2) ** 2 + _g(1, 2) ** 2 - 1)) == 0
    # x_1 - x_0 - R_0 (L, 0): rows g_3_5 - g_0_2 - 2 g_0_0 and g_4_5 - g_1_2 - 2 g_1_0
    assert sp.expand(m.constraints[1].rows[0] - (_g(3, 5) - _g(0, 2) - 2 * _g(0, 0))) == 0
    assert sp.expand(m.constraints[1].rows[1] - (_g(4, 5) - _g(1, 2) - 2 * _g(1, 0))) == 0


def test_unconstrained_model_has_none():
    assert load_model_text(PEND.split("constraints:")[0], "m.yaml").constraints == ()


@pytest.mark.parametrize("entry,expected", [
    ("R", "constraints[0]: a constraint must be a scalar or a vector, got shape (3, 3)"),
    ("x[0] + xi[0]", "constraints[0]: a constraint may use g (R, x, ...) and fixed parameters"),
    ("x[0] - t", "constraints[0]"),
    ("x[0] - grav", "constraints[0]: the runtime parameter 'grav' may not appear"),
    ("x[0] + nope", "constraints[0]"),
    ("2.0", "constraints[0]: expected an expression in g"),
])
def test_bad_entries(entry, expected):
    text = PEND.replace("  - x + dot(R, top)", f"  - {entry}")
    if "grav" in entry:
        text = text.replace("constraints:", "runtime_parameters: [grav]\nconstraints:")
    msg = _err(text)
    assert expected in msg and msg.startswith("m.yaml:")


def test_not_a_list_and_too_many_rows():
    assert "constraints: expected a non-empty list" in _err(
        PEND.replace("  - x + dot(R, top)", "  x + dot(R, top)"))
    six = PEND.replace("  - x + dot(R, top)", "  - x + dot(R, top)\n  - x + dot(R, top) + x")
    assert "6 constraint rows leave no freedom on SE3 (d = 6)" in _err(six)


def test_constraints_enter_the_content_hash():
    a = normalized_model(PEND)[0]
    assert a["constraints"][0].split() == "x + dot ( R , top )".split()
    assert normalized_model(PEND.replace("x + dot(R, top)", "x+dot(R,top)  # pin"))[0] == a
    assert normalized_model(PEND.replace("x + dot(R, top)", "x - dot(R, top)"))[0] != a


def test_body_jacobian_is_the_left_trivialized_derivative():
    """Phi(g) eta = d/de phi(g exp(e eta)) at 0, against a central difference on SE3."""
    import casadi as ca
    from scipy.linalg import expm
    from hpgen.derive.constraints import body_jacobian, constraint_function
    m = load_model_text(PEND, "m.yaml")
    group = m.group
    phi = constraint_function(m)
    rng = np.random.default_rng(1)
    g = expm(np.array(ca.evalf(group.hat(ca.SX(rng.normal(size=6)))), dtype=float))
    G = ca.SX.sym("G", 4, 4)
    Phi = ca.Function("Phi", [G], [body_jacobian(group, phi, G)])(g).full()
    e = 1e-6
    for a in range(6):
        E = np.array(ca.evalf(group.hat(ca.SX(np.eye(6)[:, a]))), dtype=float)
        fd = (phi(g @ expm(e * E)).full() - phi(g @ expm(-e * E)).full()).ravel() / (2 * e)
        assert np.abs(Phi[:, a] - fd).max() < 1e-8


def test_derived_step_unknowns():
    from hpgen.derive import derive
    from hpgen.tableaus import get_tableau
    m = load_model_text(PEND, "m.yaml")
    step = derive(m, get_tableau("stormer-verlet"), "cay", "truncated")
    # l quadratic in xi with a constant Hessian: the node velocity is explicit (no v1 block)
    assert step.unknowns == (("Xi", 0, 6), ("lambda", 6, 9), ("nu", 9, 12))
    assert step.nz == 12 and not step.reduced
    quartic = load_model_text(PEND.replace("xi[3]**2 +", "xi[3]**2 + 0.1*xi[3]**4 +"), "m.yaml")
    step = derive(quartic, get_tableau("stormer-verlet"), "cay", "truncated")
    assert step.unknowns[-1] == ("v1", 12, 18) and step.nz == 18


def test_check_runs_on_a_constrained_model(tmp_path):
    """hpgen check on a constrained model checks on the constraint manifold (the property
    tests in tests/property/test_check_compose_constrained.py measure it on the shipped
    scenes): the pin holds at round-off and the report says so."""
    from hpgen.analysis.check import run_check
    path = tmp_path / "pend.yaml"
    path.write_text(PEND + "scene: {h: 0.01, steps: 10, initial: {g: {rotvec: [0, 0, 0], "
                    "position: [0, 0, -0.25]}, xi: [1.0, 0, 0, 0, 0.25, 0]}}\n")
    r = run_check(path, cache_dir=tmp_path, steps=20, n_states=2)
    assert r["checks"]["constraints"], r["constraints"]


def test_reactions_of_a_hanging_pendulum(tmp_path):
    """At rest, hanging straight down: each node's two impulses carry the weight, so
    lambda_k + nu_k = -(pin force on the link) = (0, 0, -m grav) (docs/numerics.md sec. 14)."""
    import hpgen
    from hpgen.analysis.reactions import reactions
    path = tmp_path / "pend.yaml"
    path.write_text(PEND)
    integ = hpgen.compile(path, cache_dir=tmp_path / "cache", backend="python")
    g0 = np.eye(4)
    g0[2, 3] = -0.25
    tr = integ.simulate(g0=g0, mu0=np.zeros(6), h=0.01, steps=3)
    assert np.abs(tr.mu).max() < 1e-14 and np.abs(tr.g - g0).max() < 1e-15
    lam, nu = reactions(integ, tr.g, tr.mu, 0.01)
    assert lam.shape == nu.shape == (4, 3)
    np.testing.assert_allclose(lam[1:] + nu[:-1], [[0.0, 0.0, -9.81]] * 3, atol=1e-12)


def _reference_values(model, g0):
    """phi(g0) and Phi(g0) by sympy: Phi[r, a] = sum_ij dphi_r/dg_ij (g0 hat(e_a))_ij."""
    import casadi as ca
    d = model.group.d
    subs = {s: float(g0[i, j]) for i, row in enumerate(model.g_symbols)
            for j, s in enumerate(row)}
    rows = [r for c in model.constraints for r in c.rows]
    phi = np.array([float(r.xreplace(subs)) for r in rows])
    Phi = np.zeros((len(rows), d))
    for a in range(d):
        E = np.array(ca.evalf(model.group.hat(ca.SX(np.eye(d)[:, a]))), dtype=float)
        D = g0 @ E
        for k, r in enumerate(rows):
            Phi[k, a] = sum(float(sp.diff(r, s).xreplace(subs)) * D[i, j]
                            for i, row in enumerate(model.g_symbols)
                            for j, s in enumerate(row) if s in r.free_symbols)
    return phi, Phi


@pytest.mark.parametrize("text", [PLANAR, "chain"])
def test_constraint_values_match_sympy_derivatives(text):
    """The CasADi row function (values and the body-frame Jacobian at a generic g) agrees
    with sympy's derivatives of the rows to round-off, on a product and a family."""
    from pathlib import Path

    from hpgen.model.constraints import _generic_point, constraint_values
    from hpgen.model.overrides import apply_overrides
    if text == "chain":
        path = Path(__file__).resolve().parents[2] / "examples" / "pendulum_chain.yaml"
        text = apply_overrides(path.read_text(), {"N": 3})
    model = load_model_text(text)
    g0 = _generic_point(model.group)
    phi, Phi, labels = constraint_values(model.constraints, model.g_symbols, model.group, g0)
    ref_phi, ref_Phi = _reference_values(model, g0)
    assert len(labels) == len(ref_phi) and Phi.shape == ref_Phi.shape
    assert np.abs(phi).min() > 1e-3                   # a generic point violates every row
    assert np.abs(phi - ref_phi).max() <= 1e-14 * (1 + np.abs(ref_phi).max())
    assert np.abs(Phi - ref_Phi).max() <= 1e-14 * (1 + np.abs(ref_Phi).max())


@pytest.mark.parametrize("kind", ["chain", "scattered", "singular"])
def test_singular_values_by_blocks_match_svd(kind):
    """The blockwise / banded singular values of a symmetric matrix above the dense size
    equal numpy's SVD to round-off (a chain of overlapping blocks, a scattered pattern,
    and a chain with an exactly zero row: a zero singular value)."""
    from hpgen.model.constraints import DENSE_EIGEN_SIZE, LEGENDRE_TOL, _singular_values
    rng = np.random.default_rng(7)
    n = DENSE_EIGEN_SIZE + 57
    a = np.zeros((n, n))
    if kind == "scattered":
        a = rng.standard_normal((n, n)) * (rng.random((n, n)) < 0.01)
    else:
        for i in range(0, n - 6, 4):
            a[i:i + 6, i:i + 6] += rng.standard_normal((6, 6))
    a = a + a.T + np.diag(rng.uniform(5.0, 6.0, n) * rng.choice([-1, 1], n))
    if kind == "singular":
        a[n // 2, :] = a[:, n // 2] = 0.0
    ref = np.linalg.svd(a, compute_uv=False)
    s = _singular_values(a)
    assert s.shape == ref.shape
    assert np.abs(s - ref).max() <= 1e-12 * ref[0]
    assert (s[-1] <= LEGENDRE_TOL * s[0]) == (kind == "singular")
