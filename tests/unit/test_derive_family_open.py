"""An open family model (runtime parameters, the time t in the Lagrangian) derived once per
body and per joint (hpgen.derive.family) against the same model expanded on the product group
(derive(..., expand=True)): the kernels at random points, in the step vector hv = [h, t_k,
params] of hpgen.abi, and runs, to round-off; the compiled C and Python modules and a sweep
over the gravity."""
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

GRAVITY = (EXAMPLES / "pendulum_chain_gravity.yaml").read_text()
SCHEMES = [("stormer-verlet", "truncated"), ("gauss2", "exact")]


def chain(n: int, runtime: str = "[grav]", timed: bool = True):
    """The gravity chain with N = n, the given runtime parameters and (timed) a gravity that
    varies in time."""
    text = GRAVITY.replace("{N: 4,", "{N: %d," % n).replace(
        "runtime_parameters: [grav]", f"runtime_parameters: {runtime}")
    if timed:
        text = text.replace("- m*grav*(", "- m*grav*(1 + 0.1*sin(3*t))*(")
    return load_model_text(text)


@functools.lru_cache(maxsize=None)
def pair(n, tab, rk, runtime="[grav]", timed=True):
    m = chain(n, runtime, timed)
    return (derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


def close(a, b, what):
    assert np.abs(a - b).max() <= 1e-13 * (1.0 + np.abs(b).max()), what


def compare_step_kernels(fam, dense, P, z, g, p, hv):
    """F, J and update of the family module at z[P] against the expanded module's at z (P: the
    family's unknowns in the expanded order); returns both modules' step_partials."""
    Fd, Jd = evaluate(dense, "residual_jacobian", z, g, p, hv)
    Ff, Jf = evaluate(fam, "residual_jacobian", z[P], g, p, hv)
    close(Ff, Fd[P], "F")
    nz = fam.nz
    close(Jf.reshape(nz, nz, order="F"), Jd.reshape(nz, nz, order="F")[np.ix_(P, P)], "J")
    for a, b in zip(evaluate(fam, "update", z[P], g, p, hv),
                    evaluate(dense, "update", z, g, p, hv)):
        close(a, b, "update")
    return (evaluate(fam, "step_partials", z[P], g, p, hv),
            evaluate(dense, "step_partials", z, g, p, hv))


def test_runtime_parameters_and_time_are_derived_per_body():
    assert family_local(chain(3))
    assert family_local(chain(3, "[grav, m]"))
    assert chain(3).open_system and chain(3).time_dependent
    forced = GRAVITY.replace("integrator:", "forces: [%s]\nintegrator:" % ", ".join(
        ["0.0"] * 24))
    forced = forced.replace("0.0, 0.0, 0.0]\nintegrator", "0.0, 0.0, t]\nintegrator")
    assert not family_local(load_model_text(forced))      # forces: still expanded


@pytest.mark.parametrize("n", [2, 3])
@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_step_kernels_match_the_expansion(n, tab, rk):
    fam, dense = pair(n, tab, rk)
    assert fam.open_spec == dense.open_spec
    P = permutation(fam, dense, 6, n)
    g, p, rng = state(n, 11)
    z = 0.3 * rng.standard_normal(dense.nz)
    hv = np.array([0.01, 0.37, 7.5])
    Fd, Jd = evaluate(dense, "residual_jacobian", z, g, p, hv)
    Ff, Jf = evaluate(fam, "residual_jacobian", z[P], g, p, hv)
    close(Ff, Fd[P], "F")
    nz = fam.nz
    close(Jf.reshape(nz, nz, order="F"), Jd.reshape(nz, nz, order="F")[np.ix_(P, P)], "J")
    for name, args in (("update", (z, g, p, hv)), ("margin", (z, hv)),
                       ("chart_point", (z, g, hv, [0.5])), ("update_p", (z, g, p, hv))):
        ref = evaluate(dense, name, *args)
        got = evaluate(fam, name, z[P], *args[1:])
        for a, b in zip(got, ref):
            close(a, b, name)
    # step_partials: Fs, Yz, Ys and the open module's FH, YH (partials in hv)
    sd = evaluate(dense, "step_partials", z, g, p, hv)
    sf = evaluate(fam, "step_partials", z[P], g, p, hv)
    assert len(sd) == len(sf) == 5
    rows = lambda M, k: M.reshape(nz, k, order="F")[P].ravel(order="F")  # noqa: E731
    close(sf[0], rows(sd[0], 12 * n), "Fs")
    close(sf[1], sd[1].reshape(12 * n, nz, order="F")[:, P].ravel(order="F"), "Yz")
    close(sf[2], sd[2], "Ys")
    close(sf[3], rows(sd[3], 3), "FH")
    close(sf[4], sd[4], "YH")


@pytest.mark.parametrize("n", [2, 3])
def test_state_kernels_match_the_expansion(n):
    fam, dense = pair(n, "stormer-verlet", "truncated")
    g, p, rng = state(n, 5)
    xi = rng.standard_normal(6 * n)
    hv = np.array([0.01, 1.1, 4.0])
    for name, args in (("legendre", (g, xi, hv)), ("hessian", (g, xi, hv)),
                       ("energy", (g, xi, hv)), ("momentum", (g, p)),
                       ("observe", (g, p, hv)), ("record", (g, p, xi, hv)),
                       ("velocity_step", (g, p, xi, hv)), ("guess", (xi, g, p, hv))):
        ref, got = evaluate(dense, name, *args), evaluate(fam, name, *args)
        if name == "guess":
            ref = [ref[0][permutation(fam, dense, 6, n)]]
        for a, b in zip(got, ref):
            close(a, b, name)


@pytest.mark.parametrize("example", ["pendulum_chain_gravity", "damped_pendulum_chain"])
def test_kernels_do_not_grow_with_the_bodies(example):
    """With a runtime parameter, t, inputs and a per-body force the chain's kernels still
    call each body and joint function through one mapped call: the same instruction counts
    for N = 3 and 6 (the record with the forces' power and work included)."""
    sizes = {}
    text = (EXAMPLES / f"{example}.yaml").read_text()
    for n in (3, 6):
        m = load_model_text(text.replace("{N: 4,", "{N: %d," % n))
        s = derive(m, resolve_tableau("stormer-verlet"), "cay", "truncated")
        sizes[n] = {k.name: k.function.n_instructions() for k in s.kernels
                    if k.name in ("residual", "residual_jacobian", "update", "step_partials",
                                  "hessian", "observe", "record", "velocity_step")}
        names = [f.name() for f in s.kernel("residual").function.find_functions()]
        assert f"map{n}_body0_residual_w" in names
    assert sizes[3] == sizes[6]


def run(step, g, p, h, steps, params, t0=0.0, closed=False):
    """``steps`` steps with CasADi's evaluation of ``step``'s kernels (Newton, dense solve);
    the step vector [h, t_k, params], or [h] for a closed model."""
    nz, out = step.nz, []
    for k in range(steps):
        hv = np.array([h]) if closed else np.concatenate([[h, t0 + k * h], params])
        xi = evaluate(step, "velocity_step", g, p, np.zeros(len(p)), *([] if closed else [hv]))[0]
        z = evaluate(step, "guess", xi, g, p, hv)[0]
        for _ in range(30):
            F, J = evaluate(step, "residual_jacobian", z, g, p, hv)
            dz = np.linalg.solve(J.reshape(nz, nz, order="F"), F)
            z = z - dz
            if np.abs(dz).max() <= 1e-14 * (1 + np.abs(z).max()):
                break
        g, p = evaluate(step, "update", z, g, p, hv)
        out.append(np.concatenate([g, p]))
    return np.array(out)


@pytest.mark.parametrize("runtime,params", [("[grav]", [6.0]), ("[grav, m]", [6.0, 1.7])])
def test_runs_match_the_expansion(runtime, params):
    """30 steps of the N = 2 chain; with the mass a runtime parameter d2l/dxi2 depends on it
    and the node velocity is an unknown (the family's rows then come in another order than
    the expansion's, the states agree)."""
    fam, dense = pair(2, "stormer-verlet", "truncated", runtime)
    g0 = np.eye(8).ravel(order="F")
    hv = np.concatenate([[1e-3, 0.0], params])
    p0 = evaluate(dense, "legendre", g0, np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], 2), hv)[0]
    a = run(fam, g0, p0, 1e-3, 30, params)
    b = run(dense, g0, p0, 1e-3, 30, params)
    assert np.abs(a - b).max() <= 1e-12


@pytest.mark.slow
def test_compiled_modules_and_a_sweep_over_the_gravity(tmp_path):
    """The generated modules (C and Python) of the N = 2 gravity chain run 200 steps like
    CasADi's evaluation of the expanded derivation, to round-off, at a gravity given at run
    time; a sweep over three gravities gives each member's simulate."""
    import hpgen
    n, grav = 2, 5.0
    dense = derive(chain(n, timed=False), resolve_tableau("stormer-verlet"), "cay",
                   "truncated", expand=True)
    g0 = np.eye(4 * n)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    p0 = evaluate(dense, "legendre", g0.ravel(order="F"), xi0, [1e-3, 0.0, grav])[0]
    ref = run(dense, g0.ravel(order="F"), p0, 1e-3, 200, [grav])
    gref = np.array([r[:16 * n * n].reshape(4 * n, 4 * n, order="F").ravel() for r in ref])
    ref_rows = np.hstack([gref, ref[:, 16 * n * n:]])
    out, integ = {}, {}
    for backend in ("c", "python"):
        integ[backend] = hpgen.compile(EXAMPLES / "pendulum_chain_gravity.yaml",
                                       backend=backend, cache_dir=tmp_path,
                                       parameters={"N": n})
        traj = integ[backend].simulate(g0, 1e-3, 200, mu0=p0, params={"grav": grav})
        out[backend] = np.hstack([traj.g[1:].reshape(200, -1), traj.mu[1:]])
        assert np.abs(out[backend] - ref_rows).max() <= 1e-11, backend
    assert np.abs(out["c"] - out["python"]).max() <= 1e-13
    gravs = np.array([1.0, 5.0, 9.81])
    res = hpgen.sweep(integ["c"], xi0=np.tile(xi0, (3, 1)), h=1e-3, steps=200,
                      params={"grav": gravs}, progress=False, threads=1)
    for k, gv in enumerate(gravs):
        one = integ["c"].simulate(g0, 1e-3, 200, xi0=xi0, params={"grav": gv})
        assert np.array_equal(res["g"][k], one.g) and np.array_equal(res["mu"][k], one.mu)
    assert np.abs(res["g"][0, -1] - res["g"][2, -1]).max() > 1e-3   # the gravity matters


DAMPED = (EXAMPLES / "damped_pendulum_chain.yaml").read_text()


@functools.lru_cache(maxsize=None)
def damped_pair(n, tab, rk):
    """The damped chain with a time-dependent drive, derived per body and expanded."""
    text = DAMPED.replace("{N: 4,", "{N: %d," % n).replace(
        '"-c*w[i][2]", "0"', '"-c*w[i][2]*(i + 1)", "-0.1*v[i][0]*R[i][2, 2]*sin(t)"')
    m = load_model_text(text)
    assert family_local(m)
    return (derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


@pytest.mark.parametrize("n", [2, 3])
@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_per_body_forces_match_the_expansion(n, tab, rk):
    """Body i's force in body i's step: the kernels of the forced chain (damping c a runtime
    parameter, the input u, t) equal the expansion's, the record's power included."""
    fam, dense = damped_pair(n, tab, rk)
    P = permutation(fam, dense, 6, n)
    g, p, rng = state(n, 13)
    z = 0.3 * rng.standard_normal(dense.nz)
    hv = np.array([0.01, 0.37, 0.8, 0.3])            # h, t_k, u, c
    Fd, Jd = evaluate(dense, "residual_jacobian", z, g, p, hv)
    Ff, Jf = evaluate(fam, "residual_jacobian", z[P], g, p, hv)
    close(Ff, Fd[P], "F")
    nz = fam.nz
    close(Jf.reshape(nz, nz, order="F"), Jd.reshape(nz, nz, order="F")[np.ix_(P, P)], "J")
    for a, b in zip(evaluate(fam, "update", z[P], g, p, hv), evaluate(dense, "update", z, g, p, hv)):
        close(a, b, "update")
    sd = evaluate(dense, "step_partials", z, g, p, hv)
    sf = evaluate(fam, "step_partials", z[P], g, p, hv)
    close(sf[3], sd[3].reshape(nz, 4, order="F")[P].ravel(order="F"), "FH")
    close(sf[4], sd[4], "YH")
    xi = rng.standard_normal(6 * n)
    assert "power" in [name for name, _, _ in fam.record_layout]
    close(evaluate(fam, "record", g, p, xi, hv)[0], evaluate(dense, "record", g, p, xi, hv)[0],
          "record")


@pytest.mark.slow
def test_the_damped_chain_modules_match_the_expansion(tmp_path):
    """The damped chain's C and Python modules (N = 2) with a control torque u and the
    damping c at run time: 200 steps like CasADi's evaluation of the expansion."""
    import hpgen
    n, c, u = 2, 0.4, 0.25
    m = load_model_text(DAMPED.replace("{N: 4,", "{N: 2,"))
    dense = derive(m, resolve_tableau("stormer-verlet"), "cay", "truncated", expand=True)
    g0 = np.eye(4 * n)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    hv = [1e-3, 0.0, u, c]
    p0 = evaluate(dense, "legendre", g0.ravel(order="F"), xi0, hv)[0]
    raw = run(dense, g0.ravel(order="F"), p0, 1e-3, 200, [u, c])
    ng = (4 * n) ** 2
    ref = [np.concatenate([r[:ng].reshape(4 * n, 4 * n, order="F").ravel(), r[ng:]])
           for r in raw]
    out = {}
    for backend in ("c", "python"):
        integ = hpgen.compile(EXAMPLES / "damped_pendulum_chain.yaml", backend=backend,
                              cache_dir=tmp_path, parameters={"N": n})
        traj = integ.simulate(g0, 1e-3, 200, mu0=p0, u=[u], params={"c": c})
        out[backend] = np.hstack([traj.g[1:].reshape(200, -1), traj.mu[1:]])
        assert np.abs(out[backend] - np.array(ref)).max() <= 1e-11, backend
    assert np.abs(out["c"] - out["python"]).max() <= 1e-13


def _chart(g_ref, g, n):
    """(eta per body) with g = g_ref (I + eta^) to first order, SE3^n."""
    out = []
    for k in range(n):
        s = slice(4 * k, 4 * k + 4)
        M = np.linalg.solve(g_ref[s, s], g[s, s]) - np.eye(4)
        out += [M[2, 1], M[0, 2], M[1, 0], *M[0:3, 3]]
    return np.array(out)


@pytest.mark.slow
def test_linearize_of_the_damped_chain_module_against_differences(tmp_path):
    """linearize on the per-body module: A's dp columns, B = d/du and P = d/dc of one step
    against central differences of simulate (C backend, N = 2)."""
    import hpgen
    n, h, c, u = 2, 1e-2, 0.4, 0.25
    integ = hpgen.compile(EXAMPLES / "damped_pendulum_chain.yaml", backend="c",
                          cache_dir=tmp_path, parameters={"N": n})
    g0 = np.eye(4 * n)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    traj = integ.simulate(g0, h, 1, xi0=xi0, u=[u], params={"c": c})
    mu0 = traj.mu[0]
    A, B = integ.linearize(traj, u=[u], params={"c": c})
    P = integ.linearize(traj, u=[u], params={"c": c}, wrt="params")
    d, eps = 6 * n, 1e-6

    def out(mu=mu0, uu=u, cc=c):
        t = integ.simulate(g0, h, 1, mu0=mu, u=[uu], params={"c": cc})
        return np.concatenate([_chart(traj.g[1], t.g[1], n), t.mu[1] - traj.mu[1]])
    fd_u = (out(uu=u + eps) - out(uu=u - eps)) / (2 * eps)
    fd_c = (out(cc=c + eps) - out(cc=c - eps)) / (2 * eps)
    scale = 1.0 + np.abs(A[0]).max()
    assert np.abs(B[0][:, 0] - fd_u).max() <= 1e-6 * scale
    assert np.abs(P[0][:, 0] - fd_c).max() <= 1e-6 * scale
    assert np.abs(fd_u).max() > 1e-3 and np.abs(fd_c).max() > 1e-3
    for j in (0, 4, d - 1):
        e = np.zeros(d)
        e[j] = eps
        fd = (out(mu=mu0 + e) - out(mu=mu0 - e)) / (2 * eps)
        assert np.abs(A[0][:, d + j] - fd).max() <= 1e-6 * scale


@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_the_body_force_is_inlined_in_the_body_step(tab, rk):
    """The per-body force (of w, v, R, t, u, c) enters the body step's residual and update as
    its expression, not a call node (their Jacobians see through it), the record's force stays
    a call, and the Newton matrix assembled from the blocks equals casadi.jacobian of the
    mapped step of the damped chain (N = 3) at a random point."""
    import casadi as ca
    from hpgen.derive.family import _functions
    from hpgen.derive.family_jacobian import assembled_jacobian
    from hpgen.derive.family_map import mapped_step_parts
    n = 3
    m = load_model_text(DAMPED.replace("{N: 4,", "{N: %d," % n).replace(
        '"-c*w[i][2]", "0"', '"-c*w[i][2]*(i + 1)", "-0.1*v[i][0]*R[i][2, 2]*sin(t)"'))
    funcs = _functions(m, resolve_tableau(tab), "cay", rk)
    body, st = funcs[0], next(iter(funcs[3].values()))
    for f in (st["F"], st["U"]):
        assert ca.OP_CALL not in {f.instruction_id(k) for k in range(f.n_instructions())}
    assert st["force"].name() == "body_force"
    nj = sum(len(j.rows) for j in m.family.local.joints)
    G, P = ca.MX.sym("G", body.n * body.n, n), ca.MX.sym("P", body.d, n)
    hv, z = ca.MX.sym("h", 4), ca.MX.sym("z", st["nz"] * n + 2 * nj)
    eqs, parts = mapped_step_parts(m, funcs, G, P, hv, z, ca.MX.sym("xi", body.d * n))
    fa = ca.Function("a", [z, G, P, hv], [assembled_jacobian(m, funcs, parts)])
    fr = ca.Function("r", [z, G, P, hv], [ca.jacobian(eqs.residual, z)])
    g, p, rng = state(n, 17)
    Gv = g.reshape(4 * n, 4 * n, order="F")
    Gv = np.stack([Gv[4 * k:4 * k + 4, 4 * k:4 * k + 4].ravel(order="F") for k in range(n)], 1)
    args = [0.3 * rng.standard_normal(z.numel()), Gv, p.reshape(6, n, order="F"),
            [0.01, 0.37, 0.8, 0.3]]
    A, R = (np.array(ca.densify(f(*args))) for f in (fa, fr))
    close(A, R, "J")
