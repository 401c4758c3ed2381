"""A family module's run step reads and writes only g's block nonzeros (hpgen_newton.c,
HPGEN_G_PACKED): the update's variant writes g_{k+1} as its structural nonzeros, and neither
the step nor its finiteness check touches the n^2 - N nb^2 structural zeros of the dense g
the run keeps. Checked on the 2-link pendulum chain (SE3^2, n = 8, J sparse by request: a
small family's J is dense by default, and so is its g) through the C run API:
a NaN planted in a structural zero of a run's g is neither read (the steps stay finite and
bitwise those of an unpoisoned run) nor overwritten (it is still there after the steps).
"""
from __future__ import annotations

import ctypes

import numpy as np
import pytest

import hpgen
from hpgen.api import read_model_text
from hpgen.model import load_model_text
from hpgen.model.overrides import apply_overrides
from hpgen.runtime.newton import NewtonOptions

from conftest import EXAMPLES

CHAIN = EXAMPLES / "pendulum_chain.yaml"
N = 2


@pytest.fixture(scope="module")
def chain(cache_dir):
    text = apply_overrides(read_model_text(str(CHAIN)), {"N": N}, file=str(CHAIN))
    scene = load_model_text(text, filename=str(CHAIN)).scene
    integ = hpgen.compile(CHAIN, parameters={"N": N}, jacobian="sparse", cache_dir=cache_dir)
    return integ, scene


def _start(integ, scene):
    """(backend, run, g0 flat) of a run at the scene's start (predictor-free first step)."""
    g0 = np.asarray(scene.g0, dtype=float)
    p0 = integ.legendre(g0, scene.xi0)
    be = integ.engine.backend
    z0 = integ.kernel("guess", np.asarray(scene.xi0, float), g0.ravel(order="F"), p0,
                      np.array([scene.h]))[0]
    return be, be.start(g0.ravel(order="F"), p0, z0), g0.ravel(order="F")


@pytest.mark.parametrize("simplified", [False, True])
def test_run_steps_leave_the_structural_zeros_of_g_alone(chain, simplified):
    integ, scene = chain
    n = integ.meta["n"]
    opts = NewtonOptions(simplified=simplified, tol=1e-14, maxit=50, predictor=True)
    be, ref, g0 = _start(integ, scene)
    be, run, _ = _start(integ, scene)
    off = 0 + 4 * n          # g[0, 4]: a zero between body 0's rows and body 1's columns
    assert g0[off] == 0.0
    ctypes.memmove(ctypes.addressof(run) + 8 * off, ctypes.byref(ctypes.c_double(np.nan)), 8)
    done_ref = be.advance(ref, scene.h, 25, 5, opts)
    done = be.advance(run, scene.h, 25, 5, opts)
    assert done[0] == done_ref[0] == 25 and done[3]["code"] == 0
    g, p, z, k = be.state(run)
    g_ref, p_ref, z_ref, _ = be.state(ref)
    assert k == 25 and np.isnan(g[off])            # never overwritten
    keep = np.isfinite(g)
    assert keep.sum() == n * n - 1
    # never read: the other entries and the momenta bitwise those of the clean run
    assert np.array_equal(g[keep], g_ref[keep]) and np.array_equal(p, p_ref)
    assert np.array_equal(z, z_ref)
    # and the step moved: g is not g0
    assert np.abs(g_ref - g0).max() > 1e-3 * scene.h


def test_run_init_takes_g0_on_the_block_pattern(chain):
    integ, scene = chain
    n = integ.meta["n"]
    g0 = np.asarray(scene.g0, dtype=float).ravel(order="F").copy()
    off = 4 + 0 * n          # g[4, 0]: a structural zero
    g0[off] = 0.25
    p0 = integ.legendre(np.asarray(scene.g0, float), scene.xi0)
    be = integ.engine.backend
    run = be.start(g0, p0, np.zeros(integ.meta["nz"]))
    g, _, _, _ = be.state(run)
    assert g[off] == 0.0
    g0[off] = 0.0
    assert np.array_equal(g, g0)
