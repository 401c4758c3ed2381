"""Observables of records in one call (kernel observe, C hpgen_observe): the Legendre inverse
xi, energy, spatial momentum and group defect agree with the record-by-record path (Newton
on legendre(g, xi) = mu, then the energy/momentum/defect kernels) to round-off; a Lagrangian
that is not quadratic in xi is refined by that Newton path."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES

QUARTIC = """
name: quartic_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) + 0.05*xi[0]**4 - R[2,2]
"""


def _one_by_one(integ, tr):
    xi = np.array([integ.velocity(g, m) for g, m in zip(tr.g, tr.mu)])
    E = np.array([integ.energy(g, m) for g, m in zip(tr.g, tr.mu)])
    m = np.array([integ.momentum(g, p) for g, p in zip(tr.g, tr.mu)])
    e = np.array([integ.defect(g) for g in tr.g])
    return xi, E, m, e


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("model", ["heavy_top", "quartic"])
def test_observe_matches_the_record_by_record_path(compile_model, backend, model):
    from scipy.spatial.transform import Rotation
    src = EXAMPLES / "heavy_top.yaml" if model == "heavy_top" else QUARTIC
    integ = compile_model(src, tableau="stormer-verlet", tau="cay", rkmk="truncated",
                          backend=backend)
    assert integ.meta["legendre_quadratic"] is (model == "heavy_top")
    g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
    tr = integ.simulate(g0=g0, xi0=[0.2, 1.0, 3.0], h=0.05, steps=300, every=3)
    xi, E, m, e = _one_by_one(integ, tr)
    scale = np.abs(tr.mu).max()
    # round-off of the two ways of solving the Legendre equations (|mu| ~ 20)
    assert np.abs(tr.xi() - xi).max() <= 8e-16 * scale
    assert np.abs(tr.energy() - E).max() <= 8e-16 * scale ** 2
    np.testing.assert_array_equal(tr.momentum(), m)
    np.testing.assert_array_equal(tr.defect(), e)
    # cached, but callers get their own arrays
    a = tr.energy()
    a[:] = 0.0
    assert np.abs(tr.energy() - E).max() <= 8e-16 * scale ** 2
