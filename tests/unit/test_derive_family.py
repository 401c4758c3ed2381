"""A family model derived once per body and per joint (hpgen.derive.family, call nodes)
against the same model expanded on the product group (derive(..., expand=True)): residual,
Jacobian, update and the other kernels at random points, and 200-step runs, to round-off.

The two steps order their unknowns differently (the family body by body, the expansion block
by block over all bodies); ``permutation`` maps one onto the other from the block labels."""
from __future__ import annotations

import functools

import casadi as ca
import numpy as np
import pytest

from hpgen.derive import derive
from hpgen.model import load_model_text
from hpgen.tableaus import resolve_tableau
from tests.conftest import EXAMPLES

CHAIN = (EXAMPLES / "pendulum_chain.yaml").read_text()
SCHEMES = [("stormer-verlet", "truncated"), ("stormer-verlet", "exact"),
           ("gauss2", "truncated"), ("gauss2", "exact")]


def chain(n: int):
    return load_model_text(CHAIN.replace("{N: 2,", "{N: %d," % n))


def permutation(fam, dense, db: int, count: int) -> np.ndarray:
    """P with z_family = z_dense[P] (rows likewise)."""
    where = {lab: (a, b) for lab, a, b in dense.unknowns}
    P = np.zeros(fam.nz, dtype=int)
    for lab, a, b in fam.unknowns:
        if "[" in lab:                        # body k's share of the expanded block
            name, k = lab[:-1].split("[")
            start = where[name][0] + int(k) * (b - a)
            assert where[name][1] - where[name][0] == count * (b - a)
        else:
            start = where[lab][0]
            assert where[lab][1] - where[lab][0] == b - a
        P[a:b] = np.arange(start, start + b - a)
    assert sorted(P) == list(range(dense.nz))
    return P


def state(n: int, seed: int):
    """A generic admissible-ish point (g on the group, p, z small) of SE3^n."""
    rng = np.random.default_rng(seed)
    g = np.eye(4 * n)
    for k in range(n):
        w = rng.uniform(-0.5, 0.5, 3)
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        g[4 * k:4 * k + 3, 4 * k:4 * k + 3] = np.linalg.solve(np.eye(3) - W / 2, np.eye(3) + W / 2)
        g[4 * k:4 * k + 3, 4 * k + 3] = rng.uniform(-0.3, 0.3, 3)
    return g.ravel(order="F"), rng.standard_normal(6 * n), rng


def evaluate(step, name, *args):
    f = step.kernel(name).function
    return [np.array(o, dtype=float).ravel(order="F")
            for o in f.call([ca.DM(np.asarray(a, dtype=float)) for a in args])]


@functools.lru_cache(maxsize=None)
def pair(n, tab, rk):
    m = chain(n)
    return (derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


@pytest.fixture(scope="module")
def steps():
    class Lazy:
        def __getitem__(self, key):
            return pair(*key)
    return Lazy()


@pytest.mark.parametrize("n", [2, 3, pytest.param(8, marks=pytest.mark.slow)])
@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_residual_jacobian_update_match_the_expansion(steps, n, tab, rk):
    fam, dense = steps[n, tab, rk]
    assert fam.nz == dense.nz
    P = permutation(fam, dense, 6, n)
    g, p, rng = state(n, 7)
    zd = 0.3 * rng.standard_normal(dense.nz)
    h = np.array([0.01])
    Fd, Jd = evaluate(dense, "residual_jacobian", zd, g, p, h)
    Ff, Jf = evaluate(fam, "residual_jacobian", zd[P], g, p, h)
    scale = 1.0 + np.abs(Fd).max()
    assert np.abs(Ff - Fd[P]).max() <= 1e-13 * scale
    Jd = Jd.reshape(dense.nz, dense.nz, order="F")[np.ix_(P, P)]
    Jf = Jf.reshape(fam.nz, fam.nz, order="F")
    assert np.abs(Jf - Jd).max() <= 1e-13 * (1.0 + np.abs(Jd).max())
    # the family's Jacobian keeps the bodies' structure: body 0's rows do not see body 1's z
    b0 = [b for lab, a, b in fam.unknowns if lab.endswith("[0]")][-1]
    b1 = [b for lab, a, b in fam.unknowns if lab.endswith("[1]")][-1]
    assert fam.kernel("jacobian").function.sparsity_out(0).nnz() < fam.nz ** 2
    assert not np.any(Jf[:b0, b0:b1])
    for name in ("update", "margin", "chart_point"):
        extra = {"update": (zd, g, p, h), "margin": (zd, h), "chart_point": (zd, g, h, [0.5])}
        args = list(extra[name])
        ref = evaluate(dense, name, *args)
        args[0] = zd[P]
        got = evaluate(fam, name, *args)
        for a, b in zip(got, ref):
            assert np.abs(a - b).max() <= 1e-13 * (1.0 + np.abs(b).max()), name


@pytest.mark.parametrize("n", [2, 3])
def test_state_kernels_match_the_expansion(steps, n):
    fam, dense = steps[n, "stormer-verlet", "truncated"]
    g, p, rng = state(n, 3)
    xi = rng.standard_normal(6 * n)
    for name, args in (("legendre", (g, xi)), ("hessian", (g, xi)), ("energy", (g, xi)),
                       ("momentum", (g, p)), ("observe", (g, p)), ("record", (g, p, xi)),
                       ("velocity_step", (g, p, xi)), ("guess", (xi, g, p, [0.01]))):
        ref, got = evaluate(dense, name, *args), evaluate(fam, name, *args)
        if name == "guess":
            ref = [ref[0][permutation(fam, dense, 6, n)]]
        for a, b in zip(got, ref):
            assert np.abs(a - b).max() <= 1e-13 * (1.0 + np.abs(b).max()), name


def test_step_kernels_do_not_grow_with_the_bodies():
    """The chain's step and state kernels call each body and joint function through one
    mapped call: their instruction lists are the same for N = 3 and N = 6, and the residual
    holds no unrolled copy of a body's equations."""
    sizes = {}
    for n in (3, 6):
        s = derive(chain(n), resolve_tableau("stormer-verlet"), "cay", "truncated")
        sizes[n] = {k.name: k.function.n_instructions() for k in s.kernels
                    if k.name in ("residual", "residual_jacobian", "update", "step_partials",
                                  "hessian", "observe", "record")}
        names = [f.name() for f in s.kernel("residual").function.find_functions()]
        assert f"map{n}_body0_residual_w" in names
    assert sizes[3] == sizes[6]
    assert sizes[3]["residual"] < 200


def test_step_partials_are_assembled_blockwise():
    """The chain's step_partials is assembled from per-body and per-joint blocks like J
    (hpgen.derive.family_partials): its SX form (what the Python printer walks,
    hpgen.codegen.pycallees.as_sx) calls the body step's and the joints' block functions, and
    grows per body by less than twice J's SX form (casadi.jacobian of the perturbed mapped
    step unrolled ~8 times J's growth: the MX chain rule's products per seed colour)."""
    from hpgen.codegen.pycallees import as_sx, callee_functions
    sizes = {}
    for n in (3, 6):
        s = derive(chain(n), resolve_tableau("stormer-verlet"), "cay", "truncated")
        kernel = s.kernel("step_partials")
        called = {name for name, _ in callee_functions([kernel])}
        assert {"_call_body0_residual_blocks_s", "_call_body0_update_blocks_s",
                "_call_joint0_old_kick_blocks", "_call_body_chart_jac"} <= called
        sizes[n] = [as_sx(s.kernel(k)).function.n_instructions()
                    for k in ("step_partials", "jacobian")]
    per_body = [(sizes[6][k] - sizes[3][k]) / 3 for k in range(2)]
    assert per_body[0] < 2 * per_body[1]


def test_callees_of_one_name_are_one_function():
    """The Python printer keys the callees by name (hpgen.codegen.pycallees): over all the
    chain's kernels (J's and step_partials' block products read differently shaped
    intermediates) every name is one function."""
    from hpgen.codegen.pycallees import _callees, as_sx
    s = derive(chain(3), resolve_tableau("stormer-verlet"), "cay", "truncated")
    seen: dict = {}
    stack = [as_sx(k).function for k in s.kernels]
    while stack:
        for fn in _callees(stack.pop()).values():
            sx = fn.expand() if fn.is_a("MXFunction") else fn
            text = sx.serialize()
            if text not in seen.setdefault(fn.name(), set()):
                seen[fn.name()].add(text)
                stack.append(sx)
    assert all(len(v) == 1 for v in seen.values()), [k for k, v in seen.items() if len(v) > 1]


def run(step, P, g, p, h, steps):
    """``steps`` steps with CasADi's evaluation of ``step``'s kernels (Newton, dense solve)."""
    nz = step.nz
    out = []
    for _ in range(steps):
        xi = evaluate(step, "velocity_step", g, p, np.zeros(len(p)))[0]
        z = evaluate(step, "guess", xi, g, p, [h])[0]
        for _ in range(30):
            F, J = evaluate(step, "residual_jacobian", z, g, p, [h])
            dz = np.linalg.solve(J.reshape(nz, nz, order="F"), F)
            z = z - dz
            if np.abs(dz).max() <= 1e-14 * (1 + np.abs(z).max()):
                break
        g, p = evaluate(step, "update", z, g, p, [h])
        out.append(np.concatenate([g, p]))
    return np.array(out)


@pytest.mark.slow
@pytest.mark.parametrize("n", [2, 3])
def test_200_steps_match_the_expansion(steps, n):
    fam, dense = steps[n, "stormer-verlet", "truncated"]
    m = chain(n)
    g0 = np.array(m.scene.g0, dtype=float).ravel(order="F")
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    p0 = evaluate(dense, "legendre", g0, xi0)[0]
    a = run(fam, None, g0, p0, 1e-3, 200)
    b = run(dense, None, g0, p0, 1e-3, 200)
    assert np.abs(a - b).max() <= 1e-11


@pytest.mark.slow
def test_compiled_c_and_python_modules_match_the_expansion(tmp_path):
    """The generated modules (C and Python backends) of the N = 2 chain run 200 steps like
    CasADi's evaluation of the expanded derivation, to round-off."""
    import hpgen
    n = 2
    _, dense = pair(n, "stormer-verlet", "truncated")
    g0 = np.eye(4 * n)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    p0 = evaluate(dense, "legendre", g0.ravel(order="F"), xi0)[0]
    ref = run(dense, None, g0.ravel(order="F"), p0, 1e-3, 200)
    out = {}
    for backend in ("c", "python"):
        integ = hpgen.compile(EXAMPLES / "pendulum_chain.yaml", backend=backend,
                              cache_dir=tmp_path, parameters={"N": n})
        traj = integ.simulate(g0, 1e-3, 200, mu0=p0)
        out[backend] = np.hstack([traj.g[1:].reshape(200, -1), traj.mu[1:]])
    gref = np.array([r[:16 * n * n].reshape(4 * n, 4 * n, order="F").ravel() for r in ref])
    ref_rows = np.hstack([gref, ref[:, 16 * n * n:]])
    for backend, rows in out.items():
        assert np.abs(rows - ref_rows).max() <= 1e-11, backend
    assert np.abs(out["c"] - out["python"]).max() <= 1e-13


def test_local_terms_of_the_chain_and_a_coupled_family():
    """The chain's sum and joints are local (one body; two bodies per ball joint, the pin one);
    a family whose sum couples neighbours (a spring between R[i-1] and R[i]) is not, and is
    derived expanded."""
    local = chain(3).family.local
    assert local is not None and len(local.bodies) == 1
    assert [j.bodies for j in local.joints] == [(0,), (1, 0), (2, 1)]
    from tests.unit.test_families_step import family_text
    text = family_text(3)
    coupled = load_model_text(text)
    assert coupled.family is not None and coupled.family.local is None
    assert all("[" not in lab for lab, _, _ in derive(
        coupled, resolve_tableau("stormer-verlet"), "cay", "truncated").unknowns)


def test_family_group_sizes_beyond_the_dense_limit_load():
    """SE3^64 (n = 256, d = 384) loads; the product-group limit (64) still holds otherwise."""
    m = chain(64)
    assert (m.group.n, m.group.d) == (256, 384) and m.family.local is not None


@pytest.mark.parametrize("extra, quadratic",
                         [("", True), (" + 0.01*norm2(w[i])*norm2(w[i])", False)])
def test_family_legendre_quadratic_as_expanded(extra, quadratic):
    """A family's legendre_quadratic (the record's velocity in one exact step) is the
    expansion's: read from the bodies' Hessians, where the product's (call nodes) cannot say."""
    term = "0.5*dot(w[i], J*w[i])"
    assert CHAIN.count(term) == 1
    model = load_model_text(CHAIN.replace("{N: 2,", "{N: 3,").replace(term, term + extra))
    sv = resolve_tableau("stormer-verlet")
    fam = derive(model, sv, "cay", "truncated")
    dense = derive(model, sv, "cay", "truncated", expand=True)
    assert fam.legendre_quadratic is dense.legendre_quadratic is quadratic
