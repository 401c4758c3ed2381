"""benchmarks/chain_bench.py's pieces that can be checked without a long run: the chain
example's state conversions (hpgen.bench.multibody.hpgen_chain) against the example's own
constraint rows and energy, and the compile budget that skips an N."""
from __future__ import annotations

import importlib.util

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.errors import HpgenError
from hpgen.model import load_model_text
from hpgen.model.constraints import constraint_values
from hpgen.model.overrides import apply_overrides


def _model(n):
    text = apply_overrides(hpgen_chain.MODEL.read_text(), {"N": n})
    return load_model_text(text, str(hpgen_chain.MODEL))


def test_conversions_put_a_chain_state_on_the_example_constraints_with_its_energy():
    spec = chain.ChainSpec(3)
    qpos, qvel = chain.initial_joint_state(spec, seed=2, angle=0.6, rate=1.5)
    state = chain.from_joint(spec, qpos, qvel)
    g, xi = hpgen_chain.to_hpgen(spec, state)
    model = _model(3)
    hpgen_chain.check_parameters(spec, model)
    phi, Phi, _ = constraint_values(model.constraints, model.g_symbols, model.group, g)
    assert np.abs(phi).max() < 1e-15 and np.abs(Phi @ xi).max() < 1e-14
    subs = {s: float(v) for row, grow in zip(model.g_symbols, g) for s, v in zip(row, grow)}
    subs.update({s: float(v) for s, v in zip(model.xi_symbols, xi)})
    energy = sum(chain.energy(spec, state))
    lag = float(model.lagrangian.xreplace(subs))
    kinetic = chain.energy(spec, state)[0]
    assert lag == pytest.approx(kinetic - (energy - kinetic), rel=1e-14, abs=1e-14)
    back = hpgen_chain.from_hpgen(spec, np.stack([g, g]), np.stack([xi, xi]))
    assert len(back) == 2
    for f in ("R", "x", "omega", "v"):
        assert np.abs(getattr(back[1], f) - getattr(state, f)).max() < 1e-15


def test_check_parameters_refuses_another_chain():
    with pytest.raises(HpgenError, match="parameters are not those"):
        hpgen_chain.check_parameters(chain.ChainSpec(2, mass=2.0), _model(2))


def test_a_compile_over_the_budget_is_stopped(tmp_path):
    spec = importlib.util.spec_from_file_location("chain_bench",
                                                  ROOT / "benchmarks" / "chain_bench.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    assert bench.cold_compile(2, tmp_path / "cache", budget=0.2) is None
    assert not list((tmp_path / "cache").glob("*/meta.json"))
