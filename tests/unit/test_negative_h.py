"""h < 0 runs backwards in time everywhere: the API, a scene's h, hpgen.sweep and the sweep
grid file (h = 0 is refused in one line by each)."""
from __future__ import annotations

import numpy as np
import pytest

import hpgen
from conftest import EXAMPLES
from hpgen.ensemble.grid import read_grid
from hpgen.errors import ArgumentError, ModelError

W0 = np.array([[0.2, 1.0, 3.0], [0.3, 0.9, 2.5]])


@pytest.fixture(scope="module")
def body(compile_model):
    return compile_model(EXAMPLES / "free_rigid_body.yaml", tableau="gauss2")


def test_sweep_runs_backwards_as_simulate_batch(body):
    res = hpgen.sweep(body, xi0=W0, h=-0.1, steps=20, every=5, progress=False)
    ref = body.simulate_batch(np.eye(3), -0.1, 20, xi0=W0, every=5)
    for i, r in enumerate(ref):
        np.testing.assert_array_equal(res["g"][i], r.g)
        np.testing.assert_array_equal(res.t[i], r.t)
    np.testing.assert_allclose(res.t[0], [0.0, -0.5, -1.0, -1.5, -2.0])
    # and back: the forward run from the backward run's end returns to the start
    fwd = body.simulate(res["g"][0][-1], 0.1, 20, mu0=res["mu"][0][-1])
    np.testing.assert_allclose(fwd.g[-1], np.eye(3), atol=1e-12)
    with pytest.raises((ArgumentError, ModelError), match="non-zero"):
        hpgen.sweep(body, xi0=W0, h=0.0, steps=2, progress=False)


def test_grid_file_takes_negative_h(tmp_path):
    grid = tmp_path / "grid.yaml"
    grid.write_text("xi0: [[1, 2, 3], [1, 2, 4]]\nh: [-0.1, 0.1]\n")
    assert read_grid(grid, 3, 3)["h"] == [-0.1, 0.1]
    grid.write_text("xi0: [[1, 2, 3]]\nh: 0\n")
    with pytest.raises(ModelError, match=r"grid.yaml:2: h: expected a step h != 0"):
        read_grid(grid, 3, 3)
