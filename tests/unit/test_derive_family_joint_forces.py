"""Forces between bodies written once per joint (``forces: {for: i, joint: {...}}``,
hpgen.model.joint_forces; examples/joint_damped_chain.yaml: a damper in every ball joint)
derived per body and per joint (hpgen.derive.family_joint_forces) against the same model
expanded on the product group: the kernels at random points, the compiled modules' runs; and
the scene's physics: the energy decays, the momentum about the vertical is kept."""
from __future__ import annotations

import functools

import numpy as np
import pytest

from hpgen.derive import derive
from hpgen.derive.family import family_local
from hpgen.errors import ModelError
from hpgen.model import load_model_text
from hpgen.tableaus import resolve_tableau
from tests.conftest import EXAMPLES
from tests.unit.test_derive_family import evaluate, permutation, state
from tests.unit.test_derive_family_open import close, compare_step_kernels, run

JOINTS = (EXAMPLES / "joint_damped_chain.yaml").read_text()
SCHEMES = [("stormer-verlet", "truncated"), ("gauss2", "exact")]


def chain_text(n: int, driven: bool = False) -> str:
    """The joint-damped chain with N = n; ``driven``: a body force with an input and t
    besides the joint force, and a joint spring that depends on i."""
    text = JOINTS.replace("{N: 3,", "{N: %d," % n)
    if driven:
        text = text.replace("runtime_parameters: [c]", "runtime_parameters: [c]\ninputs: [u]")
        text = text.replace("  for: i\n", '  for: i\n  body: ["u*sin(t)", "0", "-0.1*w[i][2]", '
                            '"0", "0", "0"]\n')
        text = text.replace('"-c*(w[i][0] - (transpose(R[i]) @ R[i - 1] @ w[i - 1])[0])"',
                            '"-c*(w[i][0] - (transpose(R[i]) @ R[i - 1] @ w[i - 1])[0])'
                            ' - 0.3*i*(transpose(R[i - 1]) @ R[i])[2, 1]"')
    return text


@functools.lru_cache(maxsize=None)
def pair(n, tab, rk, driven=False):
    m = load_model_text(chain_text(n, driven))
    assert family_local(m) and m.family.local.force.joints
    return (derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


def test_the_joint_force_is_expanded_onto_both_bodies():
    m = load_model_text(chain_text(3))
    jf, = m.family.local.force.joints
    assert jf.instances == ((1, (0, 1)), (2, (1, 2)))
    # body 1 carries joint 1's torque and joint 2's reaction; its linear force is zero
    assert all(m.forces[6 + k] != 0 for k in range(3)) and m.forces[9:12] == (0, 0, 0)


@pytest.mark.parametrize("n", [2, 3, pytest.param(8, marks=pytest.mark.slow)])
@pytest.mark.parametrize("tab,rk", SCHEMES)
@pytest.mark.parametrize("driven", [False, True])
def test_step_kernels_match_the_expansion(n, tab, rk, driven):
    fam, dense = pair(n, tab, rk, driven)
    P = permutation(fam, dense, 6, n)
    g, p, rng = state(n, 23)
    z = 0.3 * rng.standard_normal(dense.nz)
    hv = np.array([0.01, 0.37, 0.8, 0.3] if driven else [0.01, 0.37, 0.3])
    sf, sd = compare_step_kernels(fam, dense, P, z, g, p, hv)
    nz = fam.nz
    close(sf[0], sd[0].reshape(nz, 12 * n, order="F")[P].ravel(order="F"), "Fs")
    close(sf[3], sd[3].reshape(nz, len(hv), order="F")[P].ravel(order="F"), "FH")
    close(sf[4], sd[4], "YH")
    xi = rng.standard_normal(6 * n)
    assert "power" in [name for name, _, _ in fam.record_layout]
    close(evaluate(fam, "record", g, p, xi, hv)[0], evaluate(dense, "record", g, p, xi, hv)[0],
          "record")


FREE = """
name: free_joint_forces
group: SO3^N
parameters: {N: 3, c: 0.1, I: [1.0, 2.0, 3.0]}
runtime_parameters: [c]
lagrangian: sum(i, 0.5*dot(w[i], I*w[i]))
forces:
  for: i
  joint: {in: [1, N], bodies: [i - 1, i], force: [["0", "0", "c*(w[i][2] - w[i - 1][2])"],
                                                  ["0", "0", "-c*(w[i][2] - w[i - 1][2])"]]}
"""


@pytest.mark.parametrize("n", [1, 3])
def test_a_family_without_constraints(n):
    """Joint forces between free bodies (no constraints: the per-body composition) and the
    free family alone: the kernels equal the expansion's."""
    text = FREE.replace("{N: 3,", "{N: %d," % n)
    for t in (text, text.split("forces:")[0]):
        m = load_model_text(t)
        assert family_local(m)
        tab = resolve_tableau("stormer-verlet")
        fam, dense = (derive(m, tab, "cay", "truncated", expand=e) for e in (False, True))
        rng = np.random.default_rng(5)
        g = np.eye(3 * n).ravel(order="F")
        p, z = rng.standard_normal(3 * n), 0.3 * rng.standard_normal(dense.nz)
        hv = np.array([0.01, 0.37, 0.3])
        compare_step_kernels(fam, dense, np.arange(dense.nz), z, g, p, hv)


@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_the_kernels_do_not_grow_with_the_number_of_bodies(tab, rk):
    """The joint forces are mapped over the joints (hpgen.derive.family_joint_forces): the
    step kernels' MX graphs have as many operations at N = 3 as at N = 9 (the composition
    had one call per body, joint and stage); step_partials, CasADi's Jacobian of the mapped
    step, aside."""
    from hpgen.derive.family_kernels import mx_step_kernels
    counts = []
    for n in (3, 9):
        kernels = mx_step_kernels(load_model_text(chain_text(n, True)), resolve_tableau(tab),
                                  "cay", rk)
        counts.append({name: f.n_instructions() for name, (f, _, _) in kernels.items()
                       if name != "step_partials"})
    assert "record" in counts[0] and counts[0] == counts[1]


@pytest.mark.parametrize("text,message", [
    ('    bodies: [i - 1, i]', "forces.joint.bodies"),
    ('    bodies: [i - 1, i, i + 1]', "expected 3 lists of 6 expressions"),
])
def test_refusals_name_the_field(text, message):
    bad = JOINTS.replace("    bodies: [i - 1, i]", text).replace("in: [1, N]\n    bodies",
                                                                   "in: [0, N]\n    bodies")
    with pytest.raises(ModelError, match=message):
        load_model_text(bad)


def test_a_joint_force_may_use_only_its_bodies():
    bad = JOINTS.replace('"-c*(w[i][0] - ', '"-c*(w[i + 1][0] - ')
    with pytest.raises(ModelError, match=r"forces.joint.force\[1\]\[0\]: a joint force may "
                                         "use only the names of the bodies listed"):
        load_model_text(bad)


@pytest.mark.slow
@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_the_modules_match_the_expansion(tab, rk, tmp_path):
    """The C and Python modules (N = 2; the joint forces mapped over the joints) run 200 steps
    like CasADi's evaluation of the expansion."""
    import hpgen
    n, c = 2, 0.4
    _, dense = pair(n, tab, rk)
    g0 = np.eye(4 * n)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    p0 = evaluate(dense, "legendre", g0.ravel(order="F"), xi0, [1e-3, 0.0, c])[0]
    raw = run(dense, g0.ravel(order="F"), p0, 1e-3, 200, [c])
    ng = (4 * n) ** 2
    ref = np.array([np.concatenate([r[:ng].reshape(4 * n, 4 * n, order="F").ravel(), r[ng:]])
                    for r in raw])
    out = {}
    for backend in ("c", "python"):
        integ = hpgen.compile(EXAMPLES / "joint_damped_chain.yaml", backend=backend,
                              cache_dir=tmp_path, parameters={"N": n}, tableau=tab, rkmk=rk)
        traj = integ.simulate(g0, 1e-3, 200, mu0=p0, params={"c": c})
        out[backend] = np.hstack([traj.g[1:].reshape(200, -1), traj.mu[1:]])
        assert np.abs(out[backend] - ref).max() <= 1e-11, backend
    assert np.abs(out["c"] - out["python"]).max() <= 1e-13


@pytest.mark.slow
def test_the_scene_physics(tmp_path):
    """The N = 3 scene (C): the energy recorded every 50 steps decays monotonically and
    falls by far more than the undamped chain's energy band, energy - work is kept to order
    2 in h, and the angular momentum about the vertical through the pin to round-off."""
    import hpgen

    n = 3
    integ = hpgen.compile(EXAMPLES / "joint_damped_chain.yaml", backend="c", cache_dir=tmp_path)
    xi0 = np.tile([3.0, 1.0, 0.5, 0.0, 0.0, 0.0], n)
    free = integ.record(np.eye(4 * n), 1e-3, 5000, xi0=xi0, params={"c": 0.0}, every=50)
    band = np.ptp(free["energy"])
    assert band < 1e-3 * np.abs(free["energy"]).max()
    r = integ.record(np.eye(4 * n), 1e-3, 5000, xi0=xi0, params={"c": 0.2}, every=50)
    E = r["energy"]
    assert np.all(np.diff(E) < 0) and E[0] - E[-1] > 100 * band
    Lz = r["momentum"][:, 2::6].sum(axis=1)
    assert abs(Lz[0]) > 1e-3 and np.ptp(Lz) <= 1e-12
    # energy - work is kept to the scheme's order 2 (measured ratio 4.00 for h 2e-3 -> 1e-3)
    coarse = integ.record(np.eye(4 * n), 2e-3, 2500, xi0=xi0, params={"c": 0.2}, every=25)
    ratio = np.ptp(coarse["energy"] - coarse["work"]) / np.ptp(E - r["work"])
    assert 0.75 * 4 <= ratio <= 1.25 * 4
