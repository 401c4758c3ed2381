"""benchmarks/chain_bench.py's pieces that can be checked without a long run: the chain
example's state conversions (hpgen.bench.multibody.hpgen_chain) against the example's own
constraint rows and energy, and the compile budget that skips an N."""
from __future__ import annotations

import importlib.util

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.errors import ArgumentError, HpgenError
from hpgen.model import load_model_text
from hpgen.model.constraints import constraint_values
from hpgen.model.overrides import apply_overrides


def _model(n, frames="pin"):
    path = hpgen_chain.MODELS[frames]
    text = apply_overrides(path.read_text(), {"N": n})
    return load_model_text(text, str(path))


@pytest.mark.parametrize("frames", ["pin", "centre"])
def test_conversions_put_a_chain_state_on_the_example_constraints_with_its_energy(frames):
    """Both model files (frames at the pin, at the centres): the converted state satisfies
    the file's joint rows and their velocity form, its Lagrangian is the chain's kinetic minus
    potential energy (potential zero at the pin), and the conversion inverts."""
    spec = chain.ChainSpec(3)
    qpos, qvel = chain.initial_joint_state(spec, seed=2, angle=0.6, rate=1.5)
    state = chain.from_joint(spec, qpos, qvel)
    g, xi = hpgen_chain.to_hpgen(spec, state, frames)
    model = _model(3, frames)
    hpgen_chain.check_parameters(spec, model, frames)
    phi, Phi, _ = constraint_values(model.constraints, model.g_symbols, model.group, g)
    assert np.abs(phi).max() < 1e-15 and np.abs(Phi @ xi).max() < 1e-14
    subs = {s: float(v) for row, grow in zip(model.g_symbols, g) for s, v in zip(row, grow)}
    subs.update({s: float(v) for s, v in zip(model.xi_symbols, xi)})
    energy = sum(chain.energy(spec, state))
    lag = float(model.lagrangian.xreplace(subs))
    kinetic = chain.energy(spec, state)[0]
    assert lag == pytest.approx(kinetic - (energy - kinetic), rel=1e-14, abs=1e-14)
    back = hpgen_chain.from_hpgen(spec, np.stack([g, g]), np.stack([xi, xi]), frames)
    assert len(back) == 2
    for f in ("R", "x", "omega", "v"):
        assert np.abs(getattr(back[1], f) - getattr(state, f)).max() < 1e-15


@pytest.mark.parametrize("frames", ["pin", "centre"])
def test_check_parameters_refuses_another_chain(frames):
    with pytest.raises(HpgenError, match="parameters are not those"):
        hpgen_chain.check_parameters(chain.ChainSpec(2, mass=2.0), _model(2, frames), frames)
    with pytest.raises(HpgenError, match="parameters are not those"):
        hpgen_chain.check_parameters(chain.ChainSpec(2, length=0.4), _model(2, frames), frames)


def test_an_unknown_frames_name_is_refused():
    spec = chain.ChainSpec(2)
    with pytest.raises(ArgumentError, match="frames"):
        hpgen_chain.to_hpgen(spec, chain.from_joint(spec, *chain.initial_joint_state(spec)),
                             "tip")


def test_named_starts():
    """The benchmark's start names: random (seed 0), randomS, tiltD (at rest, the straight
    chain rotated about x through the pin); anything else refused naming the field."""
    spec = chain.ChainSpec(3)
    q0, v0 = chain.named_joint_state(spec, "random")
    q1, v1 = chain.initial_joint_state(spec)
    assert np.array_equal(q0, q1) and np.array_equal(v0, v1)
    assert not np.array_equal(chain.named_joint_state(spec, "random3")[1], v1)
    qpos, qvel = chain.named_joint_state(spec, "tilt60")
    s = chain.from_joint(spec, qpos, qvel)
    assert np.all(qvel == 0) and max(chain.constraint_residual(spec, s)) < 1e-15
    # the bottom's height: -N length cos(60 degrees)
    bottom = s.x[-1] - s.R[-1] @ spec.a
    assert bottom[2] == pytest.approx(-3 * 0.5 * 0.5, rel=1e-14)
    for bad in ("tilted", "random-x", "sideways"):
        with pytest.raises(ArgumentError, match="start"):
            chain.named_joint_state(spec, bad)


def test_a_compile_over_the_budget_is_stopped(tmp_path):
    spec = importlib.util.spec_from_file_location("chain_bench",
                                                  ROOT / "benchmarks" / "chain_bench.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    assert bench.cold_compile(2, tmp_path / "cache", budget=0.2) is None
    assert not list((tmp_path / "cache").glob("*/meta.json"))


def _load(name):
    spec = importlib.util.spec_from_file_location(name, ROOT / "benchmarks" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_compose_bench_parses_runs_and_options():
    bench = _load("chain_compose_bench")
    assert bench.parse_run("kahan-li6:2e-2,1e-2") == ("kahan-li6", [2e-2, 1e-2], None)
    assert bench.parse_run("sv@simplified:2e-3") == ("sv", [2e-3], "simplified")
    assert bench.newton_options("simplified").simplified is True
    assert bench.newton_options("default") is None
    assert bench.compile_options("gauss2") == dict(tableau="gauss2", tau="cay", rkmk="exact")
    assert bench.compile_options("suzuki4") == dict(compose="suzuki4")
    assert bench.parse_run("split2+suzuki4@simplified:5e-3") == ("split2+suzuki4", [5e-3],
                                                                  "simplified")
    assert bench.compile_options("split2") == dict(tableau="split2")
    assert bench.compile_options("split2-fasso+kahan-li6") == dict(tableau="split2-fasso",
                                                                   compose="kahan-li6")
    for bad in ("rk4:1e-3", "sv:", "sv:-1e-3", "suzuki4:x", "sv@chord:1e-3", "split4:1e-3",
                "split2+rk4:1e-3"):
        with pytest.raises(SystemExit, match="--runs"):
            bench.parse_run(bad)
    assert [bench.default_t(n) for n in (10, 16, 32, 64)] == [100.0, 100.0, 20.0, 5.0]
    for n in (10, 16, 32):          # every default run is a valid --runs entry
        assert [bench.parse_run(text)[0] for text in bench.default_runs(n)][0] == "sv"
