"""The body step's stage-force input holds only the force components that some joint force
can make nonzero (hpgen.derive.family_joint_forces.force_components): the damper's couples
leave the linear force out; a joint force with a linear component brings it in. Kernels
against the expansion (F, J, update, step_partials) in both cases."""
from __future__ import annotations

import functools

import numpy as np
import pytest

from hpgen.derive import derive
from hpgen.derive.family import _functions
from hpgen.derive.family_joint_forces import force_components
from hpgen.model import load_model_text
from hpgen.tableaus import resolve_tableau
from tests.unit.test_derive_family import permutation, state
from tests.unit.test_derive_family_joint_forces import SCHEMES, chain_text
from tests.unit.test_derive_family_open import close, compare_step_kernels

# body i's linear force along its frame's y: a damper on the joint's sliding (component 4)
LINEAR = ('"-c*(w[i][2] - (transpose(R[i]) @ R[i - 1] @ w[i - 1])[2])", "0", "0", "0"]',
          '"-c*(w[i][2] - (transpose(R[i]) @ R[i - 1] @ w[i - 1])[2])", "0", '
          '"-0.5*c*(v[i][1] - v[i - 1][1])", "0"]')


def linear_text(n: int) -> str:
    text = chain_text(n)
    assert LINEAR[0] in text
    return text.replace(LINEAR[0], LINEAR[1])


@functools.lru_cache(maxsize=None)
def linear_pair(n, tab, rk):
    m = load_model_text(linear_text(n))
    return (derive(m, resolve_tableau(tab), "cay", rk),
            derive(m, resolve_tableau(tab), "cay", rk, expand=True))


@pytest.mark.parametrize("tab,rk", SCHEMES)
@pytest.mark.parametrize("text,comps", [(chain_text, (0, 1, 2)),
                                        (linear_text, (0, 1, 2, 4))])
def test_the_stage_forces_carry_the_nonzero_components(text, comps, tab, rk):
    m = load_model_text(text(3))
    assert force_components(m) == comps
    tableau = resolve_tableau(tab)
    st, = _functions(m, tableau, "cay", rk)[3].values()
    assert st["F"].size1_in(5) == tableau.stages * len(comps)       # the body step's fext
    fn, _ = st["JS"][0]
    assert [fn.size1_out(k) for k in range(2)] == [tableau.stages * len(comps)] * 2


@pytest.mark.parametrize("tab,rk", SCHEMES)
def test_a_linear_joint_force_matches_the_expansion(tab, rk):
    n = 3
    fam, dense = linear_pair(n, tab, rk)
    P = permutation(fam, dense, 6, n)
    g, p, rng = state(n, 29)
    z = 0.3 * rng.standard_normal(dense.nz)
    hv = np.array([0.01, 0.37, 0.3])
    sf, sd = compare_step_kernels(fam, dense, P, z, g, p, hv)
    nz = fam.nz
    close(sf[0], sd[0].reshape(nz, 12 * n, order="F")[P].ravel(order="F"), "Fs")
    close(sf[3], sd[3].reshape(nz, len(hv), order="F")[P].ravel(order="F"), "FH")
