"""Composed steps on a sparse module (the capsule chain, Suzuki's five substeps p, p, 1 - 4p,
p, p): the chord's rate stop holds the substeps near two iterates each, and the build option
-DHPGEN_COMPOSE_SHARE_J=1 (the C runtime's hpgen_run_cstep_then) shares the first substep's
J factors with the substeps of the same fraction: two J a composed step instead of five,
the same states to Newton's tolerance, the joints closed to round-off (a shared J takes no
stall stop: its slow modes would leave errors that the joints' velocity form shows)."""
from __future__ import annotations

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain

from conftest import EXAMPLES


def test_suzuki4_with_shared_j(cache_dir):
    n, h, steps = 4, 2e-3, 300
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), "centre")
    runs = {}
    for key, flags in (("default", None), ("shared", ["-DHPGEN_COMPOSE_SHARE_J=1"])):
        integ = hpgen.compile(EXAMPLES / "capsule_chain.yaml", parameters={"N": n},
                              compose="suzuki4", cache_dir=cache_dir, cflags=flags)
        runs[key] = integ.simulate(g0, h, steps, xi0=xi0, every=10)
        assert runs[key].error is None
    assert runs["default"].jacobians == 5 * steps
    assert runs["default"].newton_iterations <= 5 * 2.2 * steps
    assert runs["shared"].jacobians <= 2.2 * steps
    mu = runs["default"].mu
    assert np.abs(runs["shared"].mu - mu).max() <= steps * 1e-12 * (1.0 + np.abs(mu).max())
    for key, run in runs.items():
        gaps = [chain.constraint_residual(spec, s)
                for s in hpgen_chain.from_hpgen(spec, run.g, run.xi(), "centre")]
        assert max(x[0] for x in gaps) <= 1e-12, key
        assert max(x[1] for x in gaps) <= 1e-12, key
