"""Compositions of the compiled symmetric step (integrator.compose, hpgen.tableaus.composition):
the composed step is one step of the run engine, S(gamma_s h) o ... o S(gamma_1 h), each
substep a Newton solve of the same kernels.

Orders are measured on the double spherical pendulum (two ball-jointed links, constrained
Stormer-Verlet, nz = 24) against the independent reference (DOP853 in reduced coordinates,
rtol = atol = 1e-13): the error at t = 1 over halvings of h. Tolerances: the rate of the
finest pair within 0.2 of the order (the pairs before it are pre-asymptotic for the large
negative substeps of the order-6 compositions), the constraint residual and its hidden
(velocity) form at round-off at every node, as for the plain step.
"""
from __future__ import annotations

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain, reference
from hpgen.errors import ModelError
from test_constraints import CHAIN, MODEL, _initial, _reference_state, constraint_residuals

# the heavy top with a Poincare section (tests/integration/test_sections.py), composed from
# Stormer-Verlet cay/truncated (its step symmetric though l depends on g): nz <= UNROLL_MAX,
# so the two backends agree bitwise
HEAVY_TOP = """
name: heavy_top_section
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, chi: [0.0, 0.0, 1.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*(R[2,0]*chi[0] + R[2,1]*chi[1] + R[2,2]*chi[2])
scene:
  h: 0.05
  steps: 2000
  initial: {g: {rotvec: [0.3, 0.2, 0.0]}, xi: [0.2, 1.0, 3.0]}
  section: R[2,2] - 0.97
"""


@pytest.fixture(scope="module")
def reference_at_1():
    Rs, ws, _, _ = _initial()
    qpos, qvel = chain.to_joint(CHAIN, chain.from_rotations(CHAIN, np.array(Rs), np.array(ws)))
    return _reference_state(reference.solve(CHAIN, qpos, qvel, [1.0]).final)


def _errors(integ, hs, ref):
    _, _, g0, xi0 = _initial()
    gr, pr = ref
    errs = []
    for h in hs:
        steps = int(round(1.0 / h))
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=steps, every=1)
        errs.append(max(np.abs(tr.g[-1] - gr).max(), np.abs(tr.mu[-1] - pr).max()))
        phi, hidden = constraint_residuals(tr.g, tr.mu)
        assert phi < 1e-14 and hidden < 1e-13, (h, phi, hidden)
    return np.array(errs)


@pytest.mark.parametrize("name, hs, order", [
    ("yoshida4", (0.02, 0.01, 0.005), 4),
    ("suzuki4", (0.02, 0.01, 0.005), 4),
    ("kahan-li6", (0.0125, 0.00625, 0.003125), 6),
])
def test_composed_constrained_sv_has_the_composition_order(compile_model, reference_at_1, name,
                                                           hs, order):
    integ = compile_model(MODEL, compose=name)
    errs = _errors(integ, hs, reference_at_1)
    rates = np.log2(errs[:-1] / errs[1:])
    print(name, "errors", errs, "rates", rates)
    assert abs(rates[-1] - order) < 0.2 and rates[0] > order - 0.6
    assert errs[-1] > 1e-11     # still far above the reference's own error (1e-13)


def test_composition_compiles_once(compile_model):
    plain = compile_model(MODEL)
    composed = compile_model(MODEL, compose="suzuki4")
    assert composed.module_dir == plain.module_dir and composed.meta == plain.meta
    assert composed.composition.name == "suzuki4" and plain.composition is None


def test_composed_step_is_symmetric_and_is_the_substeps(compile_model):
    """step(h) then step(-h) is the identity to round-off (the base step is symmetric and
    the coefficients are); the composed run's first step equals the substeps one by one."""
    plain = compile_model(MODEL)
    integ = compile_model(MODEL, compose="yoshida4")
    _, _, g0, xi0 = _initial()
    p0 = np.asarray(integ.legendre(g0, xi0))
    g1, p1 = integ.step(g0, p0, 0.05)
    g2, p2 = integ.step(g1, p1, -0.05)
    assert max(np.abs(g2 - g0).max(), np.abs(p2 - p0).max()) < 1e-13
    g, p = g0, p0
    for w in integ.composition.gammas:
        g, p = plain.step(g, p, w * 0.05)
    tr = integ.simulate(g0=g0, xi0=xi0, h=0.05, steps=1)
    assert max(np.abs(tr.g[1] - g).max(), np.abs(tr.mu[1] - p).max()) < 1e-13


def test_composed_energy_bounded(compile_model):
    """Energy error of the order-4 composition over t = 40 (2000 and 4000 steps): the band
    shrinks like h^4 (rate within 0.5 of 4) and does not drift (the last quarter's band
    within 1.5 times the first's); the constraints hold at every node."""
    integ = compile_model(MODEL, compose="suzuki4")
    _, _, g0, xi0 = _initial()
    bands = []
    for h in (0.02, 0.01):
        tr = integ.simulate(g0=g0, xi0=xi0, h=h, steps=int(round(40 / h)), every=1)
        dE = np.abs(tr.energy() - tr.energy()[0])
        q = len(dE) // 4
        first, last = dE[:q].max(), dE[-q:].max()
        print(f"suzuki4 h = {h}: energy band first quarter {first:.2e}, last {last:.2e}")
        assert last < 1.5 * first
        bands.append(dE.max())
        phi, hidden = constraint_residuals(tr.g, tr.mu)
        assert phi < 1e-14 and hidden < 1e-13
    assert abs(np.log2(bands[0] / bands[1]) - 4.0) < 0.5


@pytest.fixture(scope="module")
def top(compile_model):
    return {b: compile_model(HEAVY_TOP, backend=b, tableau="stormer-verlet", tau="cay",
                            rkmk="truncated", compose="suzuki4")
            for b in ("c", "python")}


def _top_start():
    from scipy.spatial.transform import Rotation
    return Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix(), np.array([0.2, 1.0, 3.0])


def test_every_run_kind_composes_bitwise_on_both_backends(top):
    """simulate, every, stream (chunks continue the substeps' predictors), record, backward,
    batches and sections: the C loop and its Python mirror give the same bits (nz = 9)."""
    g0, xi0 = _top_start()
    out = {}
    for b, integ in top.items():
        sim = integ.simulate(g0, 0.05, 300, xi0=xi0, every=1)
        chunks = list(integ.stream(g0, 0.05, 300, xi0=xi0, every=3, chunk=17))
        rec = integ.record(g0, 0.05, 300, xi0=xi0, every=3)
        back = integ.simulate(g0, -0.05, 300, xi0=xi0, every=3)
        sec = integ.sections(g0, 0.05, 2000, xi0=xi0, chunk=7)
        out[b] = (sim, chunks, rec, back, sec)
        assert np.array_equal(np.concatenate([c.g for c in chunks])[-1], sim.g[-1])
        assert np.array_equal(sim.g[::3], integ.simulate(g0, 0.05, 300, xi0=xi0, every=3).g)
        assert len(sec.t) > 3
    c, py = out["c"], out["python"]
    assert np.array_equal(c[0].g, py[0].g) and np.array_equal(c[0].mu, py[0].mu)
    assert np.array_equal(c[3].g, py[3].g) and np.array_equal(c[3].mu, py[3].mu)
    assert np.array_equal(c[4].t, py[4].t) and np.array_equal(c[4].g, py[4].g)
    batch = top["c"].simulate_batch(g0, 0.05, 60, xi0=np.stack([xi0, 1.01 * xi0]), every=3)
    one = top["c"].simulate(g0, 0.05, 60, xi0=1.01 * xi0, every=3)
    assert np.array_equal(batch[1].g, one.g) and np.array_equal(batch[1].mu, one.mu)


def test_composed_sections_are_on_the_composed_orbit(top):
    """A crossing's t and mu are the linear interpolation between the composed steps that
    bracket it (as for the plain step); g is one plain step S(theta h) from the step's
    start: O(h^3) from the composed orbit, well inside the interpolation's O(h^2)."""
    g0, xi0 = _top_start()
    integ = top["c"]
    h = 0.05
    sim = integ.simulate(g0, h, 2000, xi0=xi0, every=1)
    sec = integ.sections(g0, h, 2000, xi0=xi0)
    s = sim.g[:, 2, 2] - 0.97
    ks = np.flatnonzero((s[:-1] < 0) & (s[1:] >= 0))
    assert len(ks) == len(sec.t) > 3
    theta = s[ks] / (s[ks] - s[ks + 1])
    assert np.allclose(sec.t, (ks + theta) * h, rtol=0, atol=1e-12)
    assert np.allclose(sec.mu, (1 - theta)[:, None] * sim.mu[ks] + theta[:, None] * sim.mu[ks + 1],
                       rtol=0, atol=1e-12)
    assert np.abs(sec.g[:, 2, 2] - 0.97).max() < 10 * h ** 2


def test_composed_linearize_is_the_product_of_the_substep_partials(top):
    """linearize of the composed step against central differences of the composed step, and
    symplectic (A^T Omega(p_1) A = Omega(p_0)); both backends agree."""
    from hpgen.analysis.symplectic import ad_matrices, omega_matrix
    from hpgen.groups.elements import rotation_from_rotvec
    from scipy.spatial.transform import Rotation
    g0, xi0 = _top_start()
    h, eps = 0.05, 1e-6
    A = {}
    for b, integ in top.items():
        tr = integ.simulate(g0, h, 4, xi0=xi0)
        A[b] = integ.linearize(tr)
    integ = top["c"]
    tr = integ.simulate(g0, h, 1, xi0=xi0)
    gk, pk = tr.g[0], tr.mu[0]
    g1, p1 = integ.step(gk, pk, h)
    fd = np.zeros((6, 6))
    for j in range(6):
        e = np.zeros(6)
        e[j] = eps
        out = []
        for sgn in (1, -1):
            ga = gk @ rotation_from_rotvec(sgn * e[:3])
            gb, pb = integ.step(ga, pk + sgn * e[3:], h)
            out.append(np.concatenate([Rotation.from_matrix(g1.T @ gb).as_rotvec(), pb]))
        fd[:, j] = (out[0] - out[1]) / (2 * eps)
    assert np.abs(fd - A["c"][0]).max() < 1e-7
    assert np.abs(A["c"] - A["python"]).max() < 1e-12
    from hpgen.model import load_model_text
    ad = ad_matrices(load_model_text(HEAVY_TOP, "top.yaml").group)
    om0, om1 = omega_matrix(ad, tr.mu[0]), omega_matrix(ad, tr.mu[1])
    assert np.abs(A["c"][0].T @ om1 @ A["c"][0] - om0).max() < 1e-12


def test_non_symmetric_or_unknown_bases_are_refused(compile_model):
    from hpgen.tableaus.composition import check_base
    for tab, rkmk, uses_g, what in (
            ("euler-backward", "truncated", False, "not symmetric"),
            ("split4-yoshida", "truncated", False, "already a composition"),
            ("gauss2", "exact", False, "use rkmk: truncated"),
            ("stormer-verlet", "exact", True, "use rkmk: truncated"),
            ("midpoint", "truncated", True, "use tableau: stormer-verlet")):
        with pytest.raises(ModelError) as info:
            check_base(tab, rkmk=rkmk, step_uses_g=uses_g)
        assert what in str(info.value) and "\n" not in str(info.value)
    for tab, uses_g in (("stormer-verlet", True), ("gauss2", False), ("midpoint", False)):
        check_base(tab, rkmk="truncated", step_uses_g=uses_g)
    with pytest.raises(ModelError, match="option compose: expected one of yoshida4"):
        compile_model(MODEL, compose="rk4")
    with pytest.raises(ModelError, match="integrator.compose: the tableau euler-forward is "
                                         "not symmetric"):
        compile_model(ROOT / "examples" / "heavy_top.yaml", tableau="euler-forward",
                      compose="yoshida4")


def test_cli_compose_and_list(tmp_path, cache_dir):
    from hpgen.cli import main
    out = tmp_path / "ht.npz"
    assert main(["run", str(ROOT / "examples" / "heavy_top.yaml"), "--compose", "yoshida4",
                 "--tableau", "stormer-verlet", "--rkmk", "truncated", "--steps", "40", "--out", str(out), "--cache-dir", str(cache_dir),
                 "--no-progress"]) == 0
    assert out.exists()
    assert main(["run", str(ROOT / "examples" / "heavy_top.yaml"), "--tableau", "euler-forward",
                 "--compose", "yoshida4", "--steps", "4", "--out", str(out),
                 "--cache-dir", str(cache_dir)]) == 2
    # the model's gauss2 / exp / exact: its step is not symmetric
    assert main(["run", str(ROOT / "examples" / "heavy_top.yaml"), "--compose", "yoshida4",
                 "--steps", "4", "--out", str(out), "--cache-dir", str(cache_dir)]) == 2


def test_composed_run_snapshot_continues_bitwise(top):
    """A composed run's checkpoint (the C run's bytes; the Python run's arrays) holds the
    fractions and every substep's predictor history: restored, it continues bitwise."""
    from hpgen.runtime.newton import NewtonOptions
    g0, xi0 = _top_start()
    for b, integ in top.items():
        be = integ.engine.backend
        p0 = np.asarray(integ.legendre(g0, xi0))
        z0 = integ.kernel("guess", xi0, g0.ravel(order="F"), p0, [0.05])[0]
        opts = NewtonOptions(simplified=True)
        gf = g0.ravel(order="F")
        whole = be.start(gf, p0, z0)
        _, g_all, p_all, _ = be.advance(whole, 0.05, 60, 5, opts)
        part = be.start(gf, p0, z0)
        be.advance(part, 0.05, 25, 5, opts)
        resumed = be.restore(be.snapshot(part))
        _, g_end, p_end, _ = be.advance(resumed, 0.05, 35, 5, opts)
        assert np.array_equal(g_end[-1], g_all[-1]) and np.array_equal(p_end[-1], p_all[-1]), b


@pytest.mark.slow
@pytest.mark.parametrize("name, order", [("suzuki4", 4), ("kahan-li6", 6)])
def test_composed_pendulum_chain_order(compile_model, name, order):
    """examples/pendulum_chain.yaml at N = 3 (the family model, the benchmark's start:
    hanging down, random joint rates) against the reference at T = 1, h = 0.01, 0.005,
    0.0025; the joints' position and velocity gaps at round-off at every node. Full Newton:
    the sparse default (simplified, J kept) stops at KEEP_J_FLOOR (docs/numerics.md sec. 8),
    which leaves the velocity form at ~1e-12 rather than round-off."""
    from hpgen.bench.multibody import hpgen_chain
    from hpgen.runtime.newton import NewtonOptions
    spec = chain.ChainSpec(3)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel))
    ref = reference.solve(spec, qpos, qvel, [1.0]).final
    integ = compile_model(hpgen_chain.MODEL, parameters={"N": 3}, compose=name)
    errs = []
    for h in (0.01, 0.005, 0.0025):
        tr = integ.simulate(g0, h, int(round(1 / h)), xi0=xi0, every=1,
                            newton=NewtonOptions(simplified=False))
        states = hpgen_chain.from_hpgen(spec, tr.g, tr.xi())
        errs.append(chain.trajectory_error(states[-1], ref))
        gaps = np.max([chain.constraint_residual(spec, s) for s in states], axis=0)
        assert gaps[0] < 1e-13 and gaps[1] < 1e-12, gaps
    rates = np.log2(np.array(errs[:-1]) / np.array(errs[1:]))
    print(name, "pendulum_chain N = 3 errors", errs, "rates", rates)
    assert abs(rates[-1] - order) < 0.2 and rates[0] > order - 0.5
