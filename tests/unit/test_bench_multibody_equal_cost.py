"""The equal-cost comparison of benchmarks/chain_compose_bench.py: hpgen's streamed runner
(hpgen_chain.run: records of every k-th node, energy and gaps vectorized over them), the
peers' sampling on the same nodes, and the log-log comparisons of hpgen.bench.multibody.
equal_cost."""
from __future__ import annotations

import importlib.util
import json
import math

import numpy as np
import pytest

from conftest import ROOT
from hpgen.bench.multibody import chain, equal_cost, hpgen_chain
from hpgen.errors import ArgumentError


def _row(runner, h, cost, band, stable=True):
    return dict(runner=runner, h=h, cost=cost, band=band, stable=stable)


def test_band_and_cost_at_interpolate_log_log_without_extrapolating():
    rk4 = [_row("rk4", 1e-3, 0.1, 1e-10), _row("rk4", 1e-2, 0.01, 1e-6),
           _row("rk4", 1e-1, 0.001, 1.0, stable=False)]           # unstable: left out
    mid = math.sqrt(0.1 * 0.01)
    assert equal_cost.band_at(mid, rk4) == pytest.approx(1e-8, rel=1e-12)
    assert equal_cost.cost_at(1e-8, rk4) == pytest.approx(mid, rel=1e-12)
    assert equal_cost.band_at(0.005, rk4) is None and equal_cost.band_at(0.2, rk4) is None
    assert equal_cost.cost_at(1e-4, rk4) is None
    # cost_at follows the peer's frontier: a row dearer and less accurate than another
    # (here the 0.1 one against the 0.02 one) is dominated and left out (one-valued)
    odd = rk4[:2] + [_row("rk4", 5e-3, 0.02, 1e-11)]
    assert equal_cost.cost_at(1e-8, odd) == pytest.approx(0.01 * 2 ** 0.4, rel=1e-12)


def test_compare_reports_ratios_and_dominance():
    rk4 = [_row("rk4", 1e-3, 0.1, 1e-6), _row("rk4", 2e-3, 0.05, 1e-5),
           _row("rk4", 4e-3, 0.025, 1e-4)]
    win = _row("hpgen", 1e-2, 0.05, 1e-6)      # RK4's cost, ten times smaller band
    c = equal_cost.compare(win, rk4)
    assert c["band_ratio"] == pytest.approx(0.1, rel=1e-12)
    assert c["cost_ratio"] == pytest.approx(0.5, rel=1e-12)
    assert c["dominates"] == [1e-3, 2e-3] and c["dominated_by"] == []
    lose = _row("hpgen", 1e-3, 0.1, 1e-5)
    c = equal_cost.compare(lose, rk4)
    assert c["band_ratio"] == pytest.approx(10.0, rel=1e-12)
    assert c["cost_ratio"] == pytest.approx(2.0, rel=1e-12)
    assert c["dominated_by"] == [1e-3, 2e-3] and c["dominates"] == []
    s = equal_cost.summary([lose, win], rk4)
    assert s["wins"] and s["band_row"] == ("hpgen", 1e-2) and s["cost_ratio"] == pytest.approx(0.5)
    assert not equal_cost.summary([lose], rk4)["wins"]


def test_crossover_interpolates_in_log_n_and_log_ratio():
    # ratio 4 at N = 10, 1/4 at N = 40: through 1 at the geometric mean, N = 20
    assert equal_cost.crossover([10, 40], [4.0, 0.25]) == pytest.approx(20.0, rel=1e-12)
    assert equal_cost.crossover([10, 16, 32], [3.0, None, 0.5]) == pytest.approx(
        math.exp(math.log(10) + math.log(3) / math.log(6) * math.log(3.2)), rel=1e-12)
    assert equal_cost.crossover([10, 16], [0.5, 0.1]) == 10.0
    assert equal_cost.crossover([10, 16], [3.0, 1.5]) is None


def test_node_energy_and_gaps_are_the_chain_functions_over_nodes():
    spec = chain.ChainSpec(4)
    states = [chain.from_joint(spec, *chain.initial_joint_state(spec, seed=s, angle=0.7))
              for s in range(3)]
    for frames in ("pin", "centre"):
        pairs = [hpgen_chain.to_hpgen(spec, s, frames) for s in states]
        g, xi = np.stack([p[0] for p in pairs]), np.stack([p[1] for p in pairs])
        nodes = hpgen_chain.node_arrays(spec, g, xi, frames)
        E = hpgen_chain.node_energy(spec, *nodes)
        ref = [sum(chain.energy(spec, s)) for s in states]
        assert np.abs(E - ref).max() <= 1e-13 * np.abs(ref).max()
        gaps = hpgen_chain.node_gaps(spec, *nodes)
        assert np.array_equal(gaps, np.max([chain.constraint_residual(spec, s)
                                            for s in hpgen_chain.from_hpgen(spec, g, xi,
                                                                            frames)], axis=0))


def test_chunk_steps_bounds_the_records_memory():
    spec = chain.ChainSpec(64)
    record = 8 * (16 * 64 * 64 + 6 * 64)
    c = hpgen_chain.chunk_steps(spec, 100_000, 10)
    assert c % 10 == 0 and c // 10 * record <= hpgen_chain.RECORD_MEMORY
    assert (c // 10 + 1) * record > hpgen_chain.RECORD_MEMORY
    assert hpgen_chain.chunk_steps(spec, 100_000, 10, memory=1.0) == 10     # one record
    assert hpgen_chain.chunk_steps(chain.ChainSpec(2), 500, 10) == 500


@pytest.fixture(scope="module")
def chain2(compile_model):
    spec = chain.ChainSpec(2)
    integ = compile_model(hpgen_chain.CENTRE_MODEL, parameters={"N": 2})
    qpos, qvel = chain.named_joint_state(spec, "random")
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), "centre")
    return spec, integ, g0, xi0, qpos, qvel


def test_run_records_every_kth_node_of_simulate_in_any_chunking(chain2):
    """The streamed records are simulate(every=10)'s (the last one bitwise, the times to
    round-off), whatever the chunk size; the energy is the module's own (Trajectory.energy)
    to round-off; the clocks are separate."""
    spec, integ, g0, xi0, _, _ = chain2
    h, steps = 2e-3, 400
    tr = integ.simulate(g0, h, steps, xi0=xi0, every=10)
    record = 8 * (16 * 4 + 12)
    for memory in (hpgen_chain.RECORD_MEMORY, 3 * record):        # one chunk; 3 records each
        r = hpgen_chain.run(integ, spec, g0, xi0, h, steps, every=10, frames="centre",
                            memory=memory)
        assert np.abs(r.times - tr.t).max() < 1e-14 and len(r.energy) == steps // 10 + 1
        assert np.abs(r.energy - tr.energy()).max() <= 1e-13 * abs(tr.energy()[0])
        assert r.iterations == tr.newton_iterations and r.steps == steps
        assert r.cpu_seconds > 0 and r.observe_seconds > 0 and r.gaps.max() < 1e-12
        last = hpgen_chain.from_hpgen(spec, tr.g[-1:], tr.xi()[-1:], "centre")[0]
        assert np.array_equal(r.last.R, last.R) and np.array_equal(r.last.v, last.v)
    with pytest.raises(ArgumentError, match="every"):
        hpgen_chain.run(integ, spec, g0, xi0, h, steps, every=0)


def test_mujoco_samples_the_same_nodes_as_hpgen(chain2):
    """With the same dt, steps and every, MuJoCo's energy samples sit at hpgen's record
    times; its CPU and energy clocks are reported apart, and its band at dt = 2e-3 over
    0.8 s is far below hpgen SV's (RK4, order 4, against order 2)."""
    pytest.importorskip("mujoco")
    from hpgen.bench.multibody import mujoco_peer
    spec, integ, g0, xi0, qpos, qvel = chain2
    h, steps = 2e-3, 400
    run = mujoco_peer.run(spec, qpos, qvel, h, steps, "RK4", sample=10)
    r = hpgen_chain.run(integ, spec, g0, xi0, h, steps, every=10, frames="centre")
    assert np.allclose(run.times, r.times, rtol=0, atol=1e-12)
    assert abs(run.energy[0] - r.energy[0]) <= 1e-12 * abs(r.energy[0])
    assert run.cpu_seconds > 0 and run.observe_seconds > 0
    assert np.abs(run.energy - run.energy[0]).max() < 1e-3 * np.abs(r.energy - r.energy[0]).max()


def test_compose_bench_smoke_writes_rows_summary_and_figure(tmp_path, compile_model):
    compile_model(hpgen_chain.CENTRE_MODEL, parameters={"N": 2})   # warm the session cache
    spec = importlib.util.spec_from_file_location(
        "chain_compose_bench", ROOT / "benchmarks" / "chain_compose_bench.py")
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    bench.main(["--n", "2", "--t", "0.4", "--runs", "sv:2e-3", "--rk4-dt", "1e-3", "4e-3",
                "--pinocchio", "none", "--error-max-n", "0", "--out", str(tmp_path)])
    report = json.loads((tmp_path / "chain_compose.json").read_text())
    (n2,) = report["N"]
    assert n2["N"] == 2 and n2["T"] == 0.4 and report["every"] == 10
    hp = [r for r in n2["rows"] if r["runner"] == "hpgen SV"]
    assert len(hp) == 1 and hp[0]["steps"] == 200 and hp[0]["band"] > 0
    assert n2["stream_check"]["steps"] == 200
    assert (tmp_path / "chain_equal_cost.png").stat().st_size > 0
    if importlib.util.find_spec("mujoco") is not None:
        assert [r["h"] for r in n2["rows"] if r["runner"] == "MuJoCo RK4"] == [1e-3, 4e-3]
        assert "crossover_N" in report and n2["vs_rk4"] is not None
