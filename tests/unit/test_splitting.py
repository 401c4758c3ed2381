"""The explicit splitting schemes (hpgen.splitting): catalog, structure recognition and its
refusals, and the guarantees of a generated step.

- Catalog: every symmetric composition of the basic step is symmetric and consistent (sum = 1
  to 4 ulp) and, from order 4, satisfies sum gamma^3 = 0 to round-off (the phi/phi*
  compositions: tests/unit/test_splitting_compositions.py); ``hpgen list`` shows every scheme.
- split2 is the hand-written Dullweber-Leimkuhler-McLachlan splitting of hpgen.bench.rigid
  (same sub-flows, same order): the heavy top's states agree to round-off over 1000 steps.
- Measured orders against the exact free rigid body (Jacobi elliptic functions), T = 10:
  the slope between two step sizes in the asymptotic range is the catalog order within 0.1
  (measured 2.02, 3.93-3.97, 5.98-5.99, 7.94-8.06).
- C and Python backends give bitwise equal states (SO3, SE3, SO3 x SO3).
- Invariants: a symmetric potential's momentum (heavy top e3.(R p), the two-body chain's
  total vertical momentum, every component for the underwater vehicle) changes by round-off
  only, 1e-12 relative over 2000 steps; the group defect stays at round-off (1e-13).
- Symplectic: the step's Jacobian (implicit differentiation of the generated kernels, as
  ``hpgen check``) keeps the canonical form to 1e-12 relative; ``linearize`` agrees with
  central differences of ``step`` (1e-7 relative, as tests/unit/test_linearize.py).
- Run kinds: record rows, sections (the crossing on the group, between the two step states),
  simulate_batch (lane-wise and body by body) bitwise equal to simulate; the step is explicit
  (no Newton iteration, no Jacobian) and its lanes take any number of unknowns.
- Models without the structure are refused with one line naming what breaks it.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.analysis.exact import free_rigid_body_attitude
from hpgen.analysis.symplectic import GeneratedMap, ad_matrices, omega_matrix, \
    symplectic_defect
from hpgen.errors import ArgumentError, ModelError
from hpgen.runtime.engine import RunArgs
from hpgen.splitting import SPLITTING_NAMES, get_splitting

HEAVY_TOP, FREE_BODY = EXAMPLES / "heavy_top.yaml", EXAMPLES / "free_rigid_body.yaml"
UNDERWATER, TWO_BODIES = EXAMPLES / "underwater_vehicle.yaml", EXAMPLES / "double_body_chain.yaml"
XI0 = np.array([0.2, 1.0, 3.0])


def _g0():
    from hpgen.groups.elements import rotation_from_rotvec
    return rotation_from_rotvec([0.3, 0.2, 0.0])


def _start(path):
    from hpgen.model import load_model
    sc = load_model(path).scene
    return np.array(sc.g0, dtype=float), sc.xi0, sc.mu0


# ---- catalog ------------------------------------------------------------------------------
@pytest.mark.parametrize("name", [n for n in SPLITTING_NAMES if get_splitting(n).gammas])
def test_catalog_entries_are_symmetric_consistent_compositions(name):
    s = get_splitting(name)
    g = s.gammas
    assert g == g[::-1] and s.stages == len(g)
    assert abs(math.fsum(g) - 1.0) <= 4 * 2.0 ** -52 * max(map(abs, g)) * len(g)
    if s.order >= 4:
        assert abs(math.fsum(x ** 3 for x in g)) <= 1e-14
    assert s.order in (2, 4, 6, 8)


def test_list_shows_the_splittings(capsys):
    from hpgen.cli import main
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    for name in SPLITTING_NAMES:
        assert name in out


def test_unknown_scheme_is_one_line():
    with pytest.raises(ModelError) as e:
        get_splitting("split5")
    assert "split2" in str(e.value) and "\n" not in str(e.value)


# ---- the step ------------------------------------------------------------------------------
def test_split2_is_the_hand_written_dlm_splitting(compile_model):
    from hpgen.bench.rigid import RigidPeers
    integ = compile_model(HEAVY_TOP, tableau="split2")
    inertia = np.array([1.0, 5.0, 6.0])
    tr = integ.simulate(_g0(), 0.01, 1000, xi0=XI0, every=1000)
    peer = RigidPeers(inertia, np.array([0.0, 0.0, 1.0]))
    _, y, done, _ = peer.run("splitting-2", np.concatenate([_g0().ravel(), inertia * XI0]),
                             0.01, 1000)
    assert done == 1000 and tr.newton_iterations == 0 == tr.jacobians   # explicit: no Newton
    assert np.abs(tr.g[-1].ravel() - y[:9]).max() <= 1e-12
    assert np.abs(tr.mu[-1] - y[9:]).max() <= 1e-12 * np.abs(y[9:]).max()


@pytest.mark.parametrize("name,hs", [("split2", (0.25, 0.125)), ("split4-yoshida", (0.25, 0.125)),
                                     ("split4-suzuki", (0.25, 0.125)),
                                     ("split6-kahan-li", (0.25, 0.125)),
                                     ("split6-yoshida", (0.25, 0.125)),
                                     ("split8-kahan-li", (0.25, 0.125)),
                                     ("split8-mclachlan", (0.25, 0.125))])
def test_measured_order_against_the_exact_free_body(compile_model, name, hs):
    integ = compile_model(FREE_BODY, tableau=name)
    inertia = np.array([2.0, 1.0, 0.6666666666666666])
    pi0 = np.array([math.cos(1.1), 0.0, math.sin(1.1)])
    T = 10.0
    RT, piT = (a[-1] for a in free_rigid_body_attitude(inertia, pi0, np.eye(3), [0.0, T]))
    errs = []
    for h in hs:
        N = round(T / h)
        tr = integ.simulate(np.eye(3), h, N, mu0=pi0, every=N)
        errs.append(max(np.abs(tr.g[-1] - RT).max(), np.abs(tr.mu[-1] - piT).max()))
    slope = math.log2(errs[0] / errs[1])
    assert abs(slope - get_splitting(name).order) <= 0.1, (name, errs, slope)


@pytest.mark.parametrize("path,name", [(HEAVY_TOP, "split6-kahan-li"),
                                       (UNDERWATER, "split4-suzuki"),
                                       (TWO_BODIES, "split2")])
def test_backends_bitwise_equal(compile_model, path, name):
    g0, xi0, mu0 = _start(path)
    runs = [compile_model(path, tableau=name, backend=b).simulate(g0, 0.02, 200, xi0=xi0,
                                                                  mu0=mu0, every=10)
            for b in ("c", "python")]
    assert np.array_equal(runs[0].g, runs[1].g) and np.array_equal(runs[0].mu, runs[1].mu)


def _vertical(g, mu, blocks):
    return sum((g[r:r + 3, r:r + 3] @ mu[o:o + 3])[2] for r, o in blocks)


@pytest.mark.parametrize("path,name,h", [(HEAVY_TOP, "split4-yoshida", 0.05),
                                         (TWO_BODIES, "split2", 0.002),
                                         (UNDERWATER, "split6-kahan-li", 0.05)])
def test_symmetric_momentum_and_group_kept(compile_model, path, name, h):
    integ = compile_model(path, tableau=name)
    g0, xi0, mu0 = _start(path)
    tr = integ.simulate(g0, h, 2000, xi0=xi0, mu0=mu0, every=20)
    if path == UNDERWATER:             # left-invariant: the whole spatial momentum
        m = np.array([integ.momentum(g, p) for g, p in zip(tr.g, tr.mu)])
        # round-off grows with the lever arm x of x x R P
        reach = np.abs(tr.g[:, :3, 3]).max() * np.abs(tr.mu).max()
        change, scale = np.abs(m - m[0]).max(), max(np.abs(m).max(), reach)
    else:                              # rotations about the vertical: e3 . sum_i R_i p_i
        blocks = [(0, 0)] if path == HEAVY_TOP else [(0, 0), (3, 3)]
        v = np.array([_vertical(g, p, blocks) for g, p in zip(tr.g, tr.mu)])
        change, scale = np.abs(v - v[0]).max(), np.abs(tr.mu).max()
    assert change <= 1e-12 * max(1.0, scale), change
    assert max(integ.defect(g) for g in tr.g) <= 1e-13


@pytest.mark.parametrize("path,name", [(HEAVY_TOP, "split6-kahan-li"),
                                       (UNDERWATER, "split2"), (TWO_BODIES, "split4-yoshida"),
                                       (HEAVY_TOP, "split4-blanes-moan-fasso")])
def test_step_is_symplectic_and_linearize_matches_differences(compile_model, path, name):
    from hpgen import build
    from hpgen.model import load_model
    model = load_model(path)
    compiled = build(path, tableau=name, backend="c")
    integ = compiled.load()
    g0, xi0, mu0 = _start(path)
    h = 0.05 if path != TWO_BODIES else 0.01
    traj = integ.simulate(g0, h, 4, xi0=xi0, mu0=mu0)
    A = integ.linearize(traj)
    gm = GeneratedMap(integ, compiled.derivation.step, model.group)
    ad = ad_matrices(model.group)
    for k in range(len(A)):
        Phi, _, _ = gm.map_jacobian(traj.g[k], traj.mu[k], h)
        assert np.abs(Phi - A[k]).max() <= 1e-12 * np.abs(A[k]).max()
        _, rel = symplectic_defect(A[k], omega_matrix(ad, traj.mu[k]),
                                   omega_matrix(ad, traj.mu[k + 1]))
        assert rel <= 1e-12, (k, rel)
    # central differences of step in the directions p -> p + eps e_i
    eps, g, p = 1e-5, traj.g[0], traj.mu[0]
    d = len(p)
    for i in range(d):
        e = np.zeros(d)
        e[i] = eps
        (_, pa), (_, pb) = integ.step(g, p + e, h), integ.step(g, p - e, h)
        fd = (pa - pb) / (2 * eps)
        assert np.abs(fd - A[0][d:, d + i]).max() <= 1e-7 * np.abs(A[0]).max()


SECTION_TOP = """
name: top_with_section
group: SO3
parameters: {I: [1.0, 5.0, 6.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - R[2,2]
integrator: {tableau: split4-yoshida}
scene:
  h: 0.02
  steps: 500
  initial: {g: {rotvec: [0.3, 0.2, 0.0]}, xi: [0.2, 1.0, 3.0]}
  record: [g, mu, energy]
  section: mu[0]
"""


def test_records_sections_and_batches(compile_model):
    integ = compile_model(SECTION_TOP)
    g0 = _g0()
    tr = integ.simulate(g0, 0.02, 500, xi0=XI0)
    rec = integ.record(g0, 0.02, 500, xi0=XI0, every=50)
    names = integ.record_names
    assert rec is not None and names
    sec = integ.sections(g0, 0.02, 500, xi0=XI0)
    assert len(sec.t) >= 1
    for t, g, k in zip(sec.t, sec.g, sec.step):
        assert k * 0.02 <= t <= (k + 1) * 0.02
        assert integ.defect(g) <= 1e-13
        # the crossing lies on the scheme's own step from state k: between g_k and g_{k+1}
        assert np.abs(g - tr.g[k]).max() <= np.abs(tr.g[k + 1] - tr.g[k]).max() + 1e-15
    xs = np.array([XI0, 1.1 * XI0, 0.9 * XI0])
    for lanes in (True, False):
        batch = integ.simulate_batch(g0, 0.02, 300, xi0=xs, every=30, threads=2, lanes=lanes)
        for b, x in enumerate(xs):
            one = integ.simulate(g0, 0.02, 300, xi0=x, every=30)
            assert np.array_equal(batch[b].g, one.g) and np.array_equal(batch[b].mu, one.mu)


@pytest.mark.parametrize("path,name,h", [(HEAVY_TOP, "split4-yoshida", 0.05),
                                         (TWO_BODIES, "split2", 0.002)])
def test_explicit_step_lanes_bitwise(compile_model, path, name, h):
    """The explicit step: no Newton (0 iterations, 0 Jacobians), and its lane-wise ensembles
    (11 bodies: a group of 8 lanes and 3 stepped alone; the two-body chain has nz = 6, more
    than the Newton lanes allow) bitwise equal to simulate, C and Python."""
    integ = compile_model(path, tableau=name)
    assert integ.engine.backend.lanes > 0
    g0, xi0, mu0 = _start(path)
    mu = integ.legendre(g0, xi0) if mu0 is None else np.asarray(mu0, dtype=float)
    mus = np.array([mu * (1.0 + 0.01 * k) for k in range(11)])
    py = compile_model(path, tableau=name, backend="python")
    for threads in (1, 2):
        batch = integ.simulate_batch(g0, h, 60, mu0=mus, every=7, threads=threads)
        for b in (0, 5, 10):
            one = integ.simulate(g0, h, 60, mu0=mus[b], every=7)
            assert one.newton_iterations == 0 == one.jacobians
            assert np.array_equal(batch[b].g, one.g) and np.array_equal(batch[b].mu, one.mu)
    other = py.simulate(g0, h, 60, mu0=mus[10], every=7)
    assert np.array_equal(other.g, batch[10].g) and np.array_equal(other.mu, batch[10].mu)


def test_explicit_batch_start_checks_like_simulate(compile_model):
    """An explicit module's ensemble start (one shared g0, mu0 rows: checked at once) gives
    each member simulate's start and the one-line errors of a member checked alone."""
    integ = compile_model(HEAVY_TOP, tableau="split2")
    g0, mus = _g0(), np.array([[0.2, 5.0, 18.0], [0.3, 4.0, 17.0]])
    batch = integ.simulate_batch(g0, 0.05, 20, mu0=mus, every=5, threads=1)
    each = integ.simulate_batch(np.array([g0, g0]), 0.05, 20, mu0=mus, every=5, threads=1)
    for b in range(2):
        one = integ.simulate(g0, 0.05, 20, mu0=mus[b], every=5)
        for got in (batch[b], each[b]):     # the starts as arrays, and member by member
            assert np.array_equal(got.g, one.g) and np.array_equal(got.mu, one.mu)
            assert np.array_equal(got.t, one.t) and got.error is None
            assert not (got.g.flags.writeable or got.mu.flags.writeable
                        or got.t.flags.writeable)
    starts = integ.engine.prepare_batch(RunArgs(g0, 0.05, 20, mu0=mus, every=5)).members
    listed = integ.engine.member_starts(RunArgs(g0, 0.05, 20, mu0=mus), 0.05, 20, 5,
                                        integ.engine.options(None))
    assert len(starts) == len(listed) == 2
    for s, t in zip([*starts[:1], starts[1]], listed):
        assert np.array_equal(s.mu0, t.mu0) and np.array_equal(s.z0, t.z0)
        assert np.array_equal(s.g0, t.g0) and (s.h, s.steps, s.every) == (t.h, t.steps, 5)
    bad = mus.copy()
    bad[1, 2] = np.nan
    with pytest.raises(ArgumentError) as e:
        integ.simulate_batch(g0, 0.05, 20, mu0=bad, threads=1)
    assert e.value.field == "mu0" and "non-finite" in str(e.value)
    with pytest.raises(ArgumentError) as e:
        integ.simulate_batch(1.01 * g0, 0.05, 20, mu0=mus, threads=1)
    assert "not on the group" in str(e.value)


# ---- refusals ------------------------------------------------------------------------------
@pytest.mark.parametrize("example,words", [("damped_top", "forces"),
                                           ("turntable", "linear in xi"),
                                           ("four_bar", "constraints"),
                                           ("pendulum_chain", "body class 0 (sums 0): d2l/dxi2"),
                                           ("damped_pendulum_chain", "forces free of the velocity"),
                                           ("capsule_chain:split4-suzuki",
                                            "only at the step's ends; use split2 with "
                                            "integrator.compose")])
def test_refused_with_one_line(compile_model, example, words):
    """The last three: constrained family models (hpgen.derive.family_split), whose bodies
    need the structure one by one, forces that are kicks and a one-stage scheme."""
    example, _, tab = example.partition(":")
    with pytest.raises(ModelError) as e:
        compile_model(EXAMPLES / f"{example}.yaml", tableau=tab or "split2", backend="python")
    msg = str(e.value)
    assert words in msg and "integrator.tableau" in msg and "\n" not in msg


@pytest.mark.parametrize("lagrangian,words", [
    ("0.5*(1 + R[0,0]**2)*xi[0]**2 + 0.5*xi[1]**2 + 0.5*xi[2]**2", "not constant"),
    ("0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2) + 0.1*xi[0]*xi[3] + 0.5*(xi[3]**2 + xi[4]**2 "
     "+ xi[5]**2)", "couples rotation and translation"),
    ("0.5*(xi[0]**2 + xi[1]**2 + xi[2]**2) + 0.5*(xi[3]**2 + xi[4]**2) - 0.5*xi[5]**2",
     "positive definite")])
def test_structure_refusals(compile_model, lagrangian, words):
    group = "SO3" if "xi[3]" not in lagrangian else "SE3"
    text = (f"name: m\ngroup: {group}\nlagrangian: {lagrangian}\n"
            "integrator: {tableau: split2}\n")
    with pytest.raises(ModelError) as e:
        compile_model(text, backend="python")
    assert words in str(e.value) and "\n" not in str(e.value)


def test_non_diagonal_inertia_uses_principal_axes(compile_model):
    """An SPD inertia with products of inertia: the same motion as the diagonal body in its
    principal frame (R -> R Q, p -> Q^T p), to round-off."""
    rng = np.random.default_rng(3)
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    Q *= np.sign(np.linalg.det(Q))
    D = np.array([1.0, 2.0, 3.5])
    M = Q @ np.diag(D) @ Q.T
    terms = " + ".join(f"{float(0.5 * M[i, j])!r}*xi[{i}]*xi[{j}]"
                       for i in range(3) for j in range(3))
    text = f"name: skewbody\ngroup: SO3\nlagrangian: {terms}\n"
    full = compile_model(text, tableau="split4-yoshida")
    evals, V = np.linalg.eigh(M)      # the principal frame recognise() uses (det V = +1)
    if np.linalg.det(V) < 0:
        V[:, 0] = -V[:, 0]
    diag = compile_model("name: diagbody\ngroup: SO3\nlagrangian: 0.5*("
                         + " + ".join(f"{float(e)!r}*xi[{i}]**2" for i, e in enumerate(evals))
                         + ")\n", tableau="split4-yoshida")
    p0 = np.array([0.3, -1.0, 0.7])
    a = full.simulate(np.eye(3), 0.05, 200, mu0=p0, every=200)
    b = diag.simulate(V, 0.05, 200, mu0=V.T @ p0, every=200)
    assert np.abs(a.g[-1] @ V - b.g[-1]).max() <= 1e-12
    assert np.abs(V.T @ a.mu[-1] - b.mu[-1]).max() <= 1e-12
    # invariants: |p| and the spatial momentum R p
    assert abs(np.linalg.norm(a.mu[-1]) - np.linalg.norm(p0)) <= 1e-13
    assert np.abs(a.g[-1] @ a.mu[-1] - p0).max() <= 1e-13


def test_symmetric_body_free_flow_is_exact(compile_model):
    """Two equal moments: the kinetic sub-flow is the exact free flow (two commuting
    rotations), so a free symmetric body is integrated exactly at any h (round-off)."""
    from scipy.spatial.transform import Rotation
    integ = compile_model("name: symbody\ngroup: SO3\nlagrangian: 0.5*(2.0*xi[0]**2 + "
                          "0.5*xi[1]**2 + 2.0*xi[2]**2)\n", tableau="split2")
    p0, h, N = np.array([0.3, 4.0, -0.7]), 0.5, 40
    tr = integ.simulate(np.eye(3), h, N, mu0=p0, every=N)
    t, Da, Dc = N * h, 2.0, 0.5
    phi = t * p0[1] * (1 / Dc - 1 / Da)
    Q2 = Rotation.from_rotvec([0.0, phi, 0.0]).as_matrix()
    R = Rotation.from_rotvec(t * p0 / Da).as_matrix() @ Q2
    assert np.abs(tr.g[-1] - R).max() <= 1e-12
    assert np.abs(tr.mu[-1] - Q2.T @ p0).max() <= 1e-12 * np.abs(p0).max()


def test_bench_default_grid_adds_splittings_where_they_apply():
    from hpgen.bench.core import _scheme_grid
    from hpgen.bench.schemes import DEFAULT_SPLITTINGS
    from hpgen.model import load_model
    top = [s[0] for s in _scheme_grid(load_model(HEAVY_TOP), None, None, None, None)]
    damped = [s[0] for s in _scheme_grid(load_model(EXAMPLES / "damped_top.yaml"), None, None,
                                         None, None)]
    assert set(DEFAULT_SPLITTINGS) <= set(top)
    assert not set(DEFAULT_SPLITTINGS) & set(damped)


def test_recommend_predicts_a_step_that_reaches_the_error(cache_dir):
    """The recommended scheme run at its predicted h over T reaches the requested error
    within a factor 10 (the free body's error grows about linearly in t)."""
    from hpgen import compile as hcompile
    from hpgen.bench.recommend import recommend, report
    T, target = 20.0, 1e-6
    cands, notes = recommend(FREE_BODY, target, T, cache_dir=cache_dir,
                             candidates=[("split2", None, None), ("split4-suzuki", None, None),
                                         ("stormer-verlet", None, None)])
    assert [c.seconds is not None for c in cands] == [True, True, True]
    assert cands[0].seconds <= cands[1].seconds <= cands[2].seconds
    text = report(cands, notes, target, T)
    assert f"recommendation: {cands[0].label} with h = " in text
    best = cands[0]
    integ = hcompile(FREE_BODY, tableau=best.label.split("/")[0], cache_dir=cache_dir)
    inertia = np.array([2.0, 1.0, 0.6666666666666666])
    pi0 = np.array([0.4535961214255773, 0.0, 0.8912073600614354])
    RT, piT = (a[-1] for a in free_rigid_body_attitude(inertia, pi0, np.eye(3), [0.0, T]))
    tr = integ.simulate(np.eye(3), T / best.steps, best.steps, mu0=pi0, every=best.steps)
    err = max(np.abs(tr.g[-1] - RT).max(), np.abs(tr.mu[-1] - piT).max())
    assert target / 10 <= err <= 10 * target, (best.label, best.h_star, err)


def test_runtime_parameter_in_the_potential_sweeps(compile_model):
    """V may depend on runtime parameters: the default equals the closed model bitwise, a
    parameter sweep (simulate_batch) equals the single runs, C equals Python."""
    text = ("name: top_rp\ngroup: SO3\nparameters: {I: [1.0, 5.0, 6.0], Mg: 1.0}\n"
            "runtime_parameters: [Mg]\nlagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + "
            "I[2]*xi[2]**2) - Mg*R[2,2]\n")
    runs = {}
    for b in ("c", "python"):
        integ = compile_model(text, tableau="split4-yoshida", backend=b)
        runs[b] = [integ.simulate(_g0(), 0.02, 100, xi0=XI0, every=100, params={"Mg": m})
                   for m in (1.0, 2.0)]
    closed = compile_model(HEAVY_TOP, tableau="split4-yoshida").simulate(_g0(), 0.02, 100,
                                                                         xi0=XI0, every=100)
    assert np.array_equal(runs["c"][0].g, closed.g) and np.array_equal(runs["c"][0].mu, closed.mu)
    assert not np.array_equal(runs["c"][1].g, closed.g)
    for a, b in zip(runs["c"], runs["python"]):
        assert np.array_equal(a.g, b.g) and np.array_equal(a.mu, b.mu)
    integ = compile_model(text, tableau="split4-yoshida")
    batch = integ.simulate_batch(_g0(), 0.02, 100, xi0=np.array([XI0, XI0]), every=100,
                                 params={"Mg": np.array([1.0, 2.0])}, threads=2)
    for got, one in zip(batch, runs["c"]):
        assert np.array_equal(got.g, one.g) and np.array_equal(got.mu, one.mu)
