"""A sparse Newton pass that wanders fails, and the next route takes the step
(hpgen.runtime.newton_sparse.wanders, the C runtime's hpgen_wanders): a correction larger
than the pass's first one, above the noise, has left the start's Newton basin, and the root
such iterates end at need not be the step's (the capsule chain's Gauss 2 step at h = 1e-2
took a root with the energy 120 higher and failed 400 steps later). The routes: the chord
from the start, J at every iterate from the same start, the run's plain warm start."""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from hpgen.abi import NO_CONVERGENCE, OK, STALL_MAX
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime import newton_sparse
from hpgen.runtime.newton import Kernels
from hpgen.runtime.newton_sparse import solve_pass, solve_sparse, wanders

from conftest import EXAMPLES

NZ = 6


def two_roots(first_scale: float):
    """(Kernels of F_i(z) = (z_i - 1)(z_i + 3), roots 1 and -3 per entry, whose first J is
    first_scale times the true one (a poor start's J), the J evaluations)."""
    calls = []

    def residual(z, g, p, hv):
        z = np.asarray(z)
        return [((z - 1.0) * (z + 3.0)).tolist()]

    def residual_jacobian(z, g, p, hv):
        calls.append(1)
        d = 2.0 * np.asarray(z) + 2.0
        if len(calls) == 1:
            d = d * first_scale
        return residual(z, g, p, hv)[0], np.diag(d).ravel(order="F").tolist()
    kern = Kernels(NZ, residual, None, residual_jacobian,
                   pattern=(list(range(NZ + 1)), list(range(NZ))))
    return kern, calls


def test_the_rule():
    assert wanders(2.0, 1.0, 3.0)
    assert not wanders(0.5, 1.0, 3.0)                       # contracting
    noise = STALL_MAX * 4.0
    assert not wanders(0.5 * noise, 0.1 * noise, 3.0)       # growing, but at the noise
    assert wanders(2.0 * noise, 0.1 * noise, 3.0)


def test_a_wandering_chord_fails_and_j_at_every_iterate_takes_the_step(monkeypatch):
    """From z = 1.5 with a first J a fifth of the true one: the chord's first correction
    overshoots to -0.75, its second (2.6 against 2.25) grows: the pass fails there; the pass
    with J at every iterate from the same start converges to the root near the start, 1.
    Without the rule the chord also gets to 1, by 16 iterates and three J."""
    kern, calls = two_roots(0.2)
    z0 = [1.5] * NZ
    code, _, it, _, jacs = solve_pass(kern, z0, [], [], [1e-3], 1e-14, 30, True)
    assert code == NO_CONVERGENCE and it == 2 and jacs == 1
    calls.clear()
    code, z, it, _, jacs = solve_sparse(kern, z0, [], [], [1e-3], 1e-14, 30)
    assert code == OK and np.abs(np.asarray(z) - 1.0).max() <= 1e-14
    assert jacs == len(calls) and it == 2 + (jacs - 1)      # both passes counted
    monkeypatch.setattr(newton_sparse, "wanders", lambda *a: False)
    calls.clear()
    code, z, it, _, _ = solve_pass(kern, z0, [], [], [1e-3], 1e-14, 30, True)
    assert code == OK and it > 10


@pytest.mark.slow
def test_gauss2_on_the_chain_at_1e_2_keeps_its_energy(cache_dir):
    """The capsule chain, N = 10, random joint velocities, Gauss 2 (cay, exact) at h = 1e-2
    over T = 50: no ConvergenceError (the chord took a spurious root at t = 43.95 and failed
    at t = 45.79 without the rule) and the energy, every tenth step, within 1e-2 of |E0|
    (5e-4 measured; the spurious root's jump was 0.57 |E0|)."""
    n, h, steps = 10, 1e-2, 5000
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), "centre")
    integ = hpgen.compile(EXAMPLES / "capsule_chain.yaml", parameters={"N": n},
                          tableau="gauss2", tau="cay", rkmk="exact", cache_dir=cache_dir)
    run = integ.simulate(g0, h, steps, xi0=xi0, every=10)
    E = run.energy()
    assert np.abs(E - E[0]).max() <= 1e-2 * abs(E[0])
