"""Joint potentials (hpgen.model.bodyterms.JointPotential: a Lagrangian sum over a few
neighbouring bodies' configurations, no velocity; examples/rod.yaml's bending and twisting
energy) derived once per joint as conservative joint forces (hpgen.derive.family_potentials)
against the same model expanded on the product group: the state kernels, 200 steps of
CasADi's evaluation, the compiled modules' runs and energy records."""
from __future__ import annotations

import functools

import numpy as np
import pytest

from hpgen.derive import derive
from hpgen.derive.family import family_local
from hpgen.model import load_model_text
from hpgen.tableaus import resolve_tableau
from tests.conftest import EXAMPLES
from tests.unit.test_derive_family import evaluate
from tests.unit.test_derive_family_open import run as run_kernels

ROD = (EXAMPLES / "rod.yaml").read_text()
H = 5e-4


def rod_text(n: int) -> str:
    return ROD.replace("{N: 2,", "{N: %d," % n)


@functools.lru_cache(maxsize=None)
def pair(n, tab, rk):
    m = load_model_text(rod_text(n))
    assert family_local(m) and m.family.local.potentials
    return (derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


def bent(n: int):
    """(vec g, xi): the segments end to end, each turned 0.15 rad about y and 0.1 rad about z
    from its predecessor (bending and twisting energy), spinning at different rates."""
    from scipy.spatial.transform import Rotation
    c = np.array([0.0, 0.0, -0.05])
    Rs = [Rotation.from_rotvec([0.6, 0.15 * i, 0.1 * i]).as_matrix() for i in range(n)]
    g, x = np.zeros((4 * n, 4 * n)), Rs[0] @ c
    for i in range(n):
        if i:
            x = x + Rs[i - 1] @ c + Rs[i] @ c
        g[4 * i:4 * i + 3, 4 * i:4 * i + 3], g[4 * i:4 * i + 3, 4 * i + 3] = Rs[i], x
        g[4 * i + 3, 4 * i + 3] = 1.0
    xi = np.concatenate([[0.5 * i, -0.3, 4.0 - i, 0.0, 0.0, 0.0] for i in range(n)])
    return g.ravel(order="F"), xi


def run(step, g, p, steps):
    """``steps`` steps of the closed rod with CasADi's evaluation of ``step``'s kernels."""
    return run_kernels(step, g, p, H, steps, [], closed=True)


def test_the_rods_energy_is_a_joint_potential():
    m = load_model_text(rod_text(3))
    local = m.family.local
    assert len(local.bodies) == 1 and local.slots == 2
    pot, = local.potentials
    assert pot.instances == ((1, (0, 1)), (2, (1, 2)))
    assert not any(str(s).startswith("xi_") for s in pot.expr.free_symbols)


def test_a_term_with_velocity_coupling_two_bodies_stays_expanded():
    text = ROD.replace("- sum(i, 1, N, 0.5/ds*(", "- sum(i, 1, N, dot(w[i - 1], w[i]) + 0.5/ds*(")
    m = load_model_text(text)
    assert m.family.local is None and not family_local(m)


@pytest.mark.parametrize("n,tab,rk", [(2, "stormer-verlet", "truncated"),
                                      (3, "stormer-verlet", "truncated"),
                                      (3, "gauss2", "exact")])
def test_runs_match_the_expansion(n, tab, rk):
    """200 steps from a bent, spinning rod: the states agree to round-off (measured 2.6e-15
    on entries of size <= 1), and so do the energy, the Legendre map and the momentum."""
    fam, dense = pair(n, tab, rk)
    g0, xi0 = bent(n)
    for name, args in (("legendre", (g0, xi0)), ("energy", (g0, xi0)),
                       ("momentum", (g0, np.ones(6 * n)))):
        a, b = evaluate(fam, name, *args)[0], evaluate(dense, name, *args)[0]
        assert np.abs(a - b).max() <= 1e-14 * max(1.0, np.abs(b).max()), name
    p0 = evaluate(dense, "legendre", g0, xi0)[0]
    a, b = run(fam, g0, p0, 200), run(dense, g0, p0, 200)
    assert np.abs(a - b).max() <= 1e-13
    ng = 16 * n * n
    Ea = [evaluate(fam, "energy", r[:ng], evaluate(fam, "velocity_step", r[:ng], r[ng:],
                                                   np.zeros(6 * n))[0])[0] for r in a[::50]]
    Eb = [evaluate(dense, "energy", r[:ng], evaluate(dense, "velocity_step", r[:ng], r[ng:],
                                                     np.zeros(6 * n))[0])[0] for r in b[::50]]
    assert np.abs(np.ravel(Ea) - np.ravel(Eb)).max() <= 1e-14


def test_the_kernels_do_not_grow_with_the_number_of_segments():
    """The potential is mapped over the joints: the step kernels' MX graphs have as many
    operations at N = 3 as at N = 9 (step_partials, CasADi's Jacobian of the mapped step,
    aside)."""
    from hpgen.derive.family_kernels import mx_step_kernels
    counts = []
    for n in (3, 9):
        kernels = mx_step_kernels(load_model_text(rod_text(n)),
                                  resolve_tableau("stormer-verlet"), "cay", "truncated")
        counts.append({name: f.n_instructions() for name, (f, _, _) in kernels.items()
                       if name != "step_partials"})
    assert "energy" in counts[0] and counts[0] == counts[1]


@pytest.mark.slow
def test_the_modules_match_the_expansion(tmp_path):
    """The C and Python modules (N = 3) run 200 steps like CasADi's evaluation of the
    expansion (measured 3.7e-15), and record its energy."""
    import hpgen
    n = 3
    _, dense = pair(n, "stormer-verlet", "truncated")
    g0, xi0 = bent(n)
    p0 = evaluate(dense, "legendre", g0, xi0)[0]
    raw = run(dense, g0, p0, 200)
    ng = 16 * n * n
    ref = np.array([np.concatenate([r[:ng].reshape(4 * n, 4 * n, order="F").ravel(), r[ng:]])
                    for r in raw])
    energy = [evaluate(dense, "energy", r[:ng], evaluate(dense, "velocity_step", r[:ng],
                                                         r[ng:], np.zeros(6 * n))[0])[0]
              for r in raw[49::50]]
    out = {}
    G0 = g0.reshape(4 * n, 4 * n, order="F")
    for backend in ("c", "python"):
        integ = hpgen.compile(EXAMPLES / "rod.yaml", backend=backend, cache_dir=tmp_path,
                              parameters={"N": n})
        traj = integ.simulate(G0, H, 200, mu0=p0)
        out[backend] = np.hstack([traj.g[1:].reshape(200, -1), traj.mu[1:]])
        assert np.abs(out[backend] - ref).max() <= 1e-13, backend
        rec = integ.record(G0, H, 200, mu0=p0, every=50)
        assert np.abs(rec["energy"][1:] - np.ravel(energy)).max() <= 1e-14, backend
    assert np.abs(out["c"] - out["python"]).max() <= 1e-13


def test_a_runtime_parameter_in_the_potential():
    """EI a runtime parameter (an open model: the potential's force and energy take it from
    the step vector): 100 steps and the energy at EI = 0.08 agree with the expansion."""
    from tests.unit.test_derive_family_open import run as run_open
    n = 3
    m = load_model_text(rod_text(n).replace("integrator:", "runtime_parameters: [EI]\n"
                                                           "integrator:"))
    assert family_local(m) and m.open_system and m.family.local.potentials
    tab = resolve_tableau("stormer-verlet")
    fam, dense = (derive(m, tab, "cay", "truncated", expand=e) for e in (False, True))
    g0, xi0 = bent(n)
    hv = np.array([H, 0.0, 0.08])
    ea, eb = (evaluate(s, "energy", g0, xi0, hv)[0] for s in (fam, dense))
    assert np.abs(ea - eb).max() <= 1e-15
    p0 = evaluate(dense, "legendre", g0, xi0, hv)[0]
    a, b = run_open(fam, g0, p0, H, 100, [0.08]), run_open(dense, g0, p0, H, 100, [0.08])
    assert np.abs(a - b).max() <= 1e-13
