"""Runtime per-body parameter lists (``m[i]``, ``k[i]`` with ``m``, ``k`` in
runtime_parameters: body data, hpgen.model.bodyterms) derived once per body and per joint
against the same model expanded on the product group: the kernels at random points when the
data stay out of d2l/dxi2, 200-step runs when they enter it (the expansion's node velocity is
then an unknown, the family's explicit), to round-off; the compiled modules and a sweep over
one link's mass."""
from __future__ import annotations

import functools

import numpy as np
import pytest

from hpgen.derive import derive
from hpgen.derive.family import family_local
from hpgen.model import load_model_text
from hpgen.tableaus import resolve_tableau
from tests.conftest import EXAMPLES
from tests.unit.test_derive_family import evaluate, permutation, state
from tests.unit.test_derive_family_open import close, compare_step_kernels, run

GRAVITY = (EXAMPLES / "pendulum_chain_gravity.yaml").read_text()
SCHEMES = [("stormer-verlet", "truncated"), ("gauss2", "exact")]


def chain_text(n: int, runtime: str = "[grav, m, k]", force: bool = False) -> str:
    """The gravity chain with per-body lists m (mass, in d2l/dxi2; one shared number when
    it is not runtime) and k (a gravity factor, not in it); ``force``: a per-body damping
    with a per-body coefficient c[i]."""
    ms = [1.0 + 0.25 * i for i in range(n)] if " m" in runtime else 1.25
    ks = [1.0 - 0.1 * i for i in range(n)]
    text = GRAVITY.replace("{N: 4, m: 1.0,", "{N: %d, m: %s, k: %s, c: %s," % (
        n, ms, ks, [0.1 * (i + 1) for i in range(n)]))
    text = text.replace("runtime_parameters: [grav]", f"runtime_parameters: {runtime}")
    text = text.replace("0.5*m*norm2", "0.5*m[i]*norm2").replace(
        "- m*grav*(", "- k[i]*m[i]*grav*(1 + 0.1*sin(3*t))*(")
    if force:
        text = text.replace("constraints:", 'forces: {for: i, body: ["-c[i]*w[i][0]", '
                            '"-c[i]*w[i][1]", "-c[i]*w[i][2]", "0", "0", "0"]}\nconstraints:')
    return text


@functools.lru_cache(maxsize=None)
def pair(n, tab, rk, runtime="[grav, m, k]", force=False):
    m = load_model_text(chain_text(n, runtime, force))
    assert family_local(m)
    return (m, derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


def test_body_data_of_the_model():
    m = load_model_text(chain_text(3))
    names = [s.name for s, _ in m.family.local.data]
    assert names == ["body:k", "body:m"]
    assert [str(v) for v in m.family.local.data[1][1]] == ["param:m[0]", "param:m[1]",
                                                           "param:m[2]"]
    assert dict(m.runtime_parameters)["m"] == (3,)
    # a fixed per-body list stays expanded (its values are frozen into the expansion)
    assert not family_local(load_model_text(chain_text(3, "[grav, m]")))


@pytest.mark.parametrize("n", [2, 3])
@pytest.mark.parametrize("tab,rk", SCHEMES)
@pytest.mark.parametrize("force", [False, True])
def test_step_kernels_match_the_expansion(n, tab, rk, force):
    """k[i] (and c[i] of a per-body force) outside d2l/dxi2: the same unknowns as the
    expansion; F, J, update, step_partials (FH, YH in hv) and the state kernels agree."""
    _, fam, dense = pair(n, tab, rk, "[grav, k, c]" if force else "[grav, k]", force)
    nP = 1 + (2 * n if force else n)
    P = permutation(fam, dense, 6, n)
    g, p, rng = state(n, 17)
    z = 0.3 * rng.standard_normal(dense.nz)
    hv = np.concatenate([[0.01, 0.37], rng.uniform(0.5, 2.0, nP)])
    sf, sd = compare_step_kernels(fam, dense, P, z, g, p, hv)
    nz = fam.nz
    close(sf[3], sd[3].reshape(nz, 2 + nP, order="F")[P].ravel(order="F"), "FH")
    close(sf[4], sd[4], "YH")
    xi = rng.standard_normal(6 * n)
    for name, args in (("legendre", (g, xi, hv)), ("hessian", (g, xi, hv)),
                       ("energy", (g, xi, hv)), ("observe", (g, p, hv)),
                       ("record", (g, p, xi, hv)), ("velocity_step", (g, p, xi, hv))):
        for a, b in zip(evaluate(fam, name, *args), evaluate(dense, name, *args)):
            close(a, b, name)


@pytest.mark.parametrize("n", [2, 3])
def test_masses_in_the_hessian_match_the_expansion(n):
    """m[i] at run time enters d2l/dxi2: the family inverts it per body from the body's own
    masses (explicit node velocity), the expansion solves for the velocity; the state
    kernels agree, and 200 steps agree to round-off."""
    m, fam, dense = pair(n, "stormer-verlet", "truncated")
    assert "v1" in [lab for lab, _, _ in dense.unknowns]
    assert "v1" not in [lab for lab, _, _ in fam.unknowns]
    rng = np.random.default_rng(3)
    g, p, _ = state(n, 19)
    params = np.concatenate([[6.0], rng.uniform(0.5, 2.0, 2 * n)])
    hv = np.concatenate([[1e-3, 0.2], params])
    xi = rng.standard_normal(6 * n)
    for name, args in (("legendre", (g, xi, hv)), ("hessian", (g, xi, hv)),
                       ("energy", (g, xi, hv)), ("observe", (g, p, hv)),
                       ("velocity_step", (g, p, xi, hv))):
        for a, b in zip(evaluate(fam, name, *args), evaluate(dense, name, *args)):
            close(a, b, name)
    g0 = np.eye(4 * n).ravel(order="F")
    p0 = evaluate(dense, "legendre", g0, np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n), hv)[0]
    a = run(fam, g0, p0, 1e-3, 200, params, t0=0.2)
    b = run(dense, g0, p0, 1e-3, 200, params, t0=0.2)
    assert np.abs(a - b).max() <= 1e-12 * (1 + np.abs(b).max())


@pytest.mark.slow
def test_compiled_modules_and_a_sweep_over_one_link_mass(tmp_path):
    """The C and Python modules of the N = 2 chain with the masses and the gravity factors
    given at run time (params={"m": [...], "k": [...]}) run 200 steps like CasADi's
    evaluation of the expansion; a sweep over link 1's mass gives each member's simulate
    bitwise."""
    import hpgen
    n = 2
    path = tmp_path / "mass_chain.yaml"
    path.write_text(chain_text(n))
    m, _, dense = pair(n, "stormer-verlet", "truncated")
    masses, ks, grav = np.array([1.3, 0.7]), np.array([0.9, 1.1]), 8.0
    params = np.concatenate([[grav], masses, ks])
    g0 = np.eye(4 * n)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    p0 = evaluate(dense, "legendre", g0.ravel(order="F"), xi0,
                  np.concatenate([[1e-3, 0.0], params]))[0]
    raw = run(dense, g0.ravel(order="F"), p0, 1e-3, 200, params)
    ng = (4 * n) ** 2
    ref = np.array([np.concatenate([r[:ng].reshape(4 * n, 4 * n, order="F").ravel(), r[ng:]])
                    for r in raw])
    out, integ = {}, {}
    values = {"grav": grav, "m": masses, "k": ks}
    for backend in ("c", "python"):
        integ[backend] = hpgen.compile(path, backend=backend, cache_dir=tmp_path)
        traj = integ[backend].simulate(g0, 1e-3, 200, mu0=p0, params=values)
        out[backend] = np.hstack([traj.g[1:].reshape(200, -1), traj.mu[1:]])
        assert np.abs(out[backend] - ref).max() <= 1e-11, backend
    assert np.abs(out["c"] - out["python"]).max() <= 1e-13
    link1 = np.array([0.5, 1.0, 2.0])
    grid = np.tile(masses, (3, 1))
    grid[:, 1] = link1
    res = hpgen.sweep(integ["c"], xi0=np.tile(xi0, (3, 1)), h=1e-3, steps=200,
                      params={"grav": np.full(3, grav), "m": grid, "k": np.tile(ks, (3, 1))},
                      progress=False, threads=1)
    for b in range(3):
        one = integ["c"].simulate(g0, 1e-3, 200, xi0=xi0,
                                  params={"grav": grav, "m": grid[b], "k": ks})
        assert np.array_equal(res["g"][b], one.g) and np.array_equal(res["mu"][b], one.mu)
    assert np.abs(res["g"][0, -1] - res["g"][2, -1]).max() > 1e-3    # the mass matters
