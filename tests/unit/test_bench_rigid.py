"""hpgen.bench.rigid (issue 14): the structure-preserving C peers (DLM splitting of order 2,
4, 6 and RATTLE / Moser-Veselov) against their own orders, the exact free-body solution, the
hand-written NumPy Moser-Veselov, and their conserved quantities; on the bench's tables.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import EXAMPLES

FREE_BODY = EXAMPLES / "free_rigid_body.yaml"
HEAVY_TOP = EXAMPLES / "heavy_top.yaml"


@pytest.fixture(scope="module")
def free(cache_dir):
    from hpgen.bench.problem import Problem
    from hpgen.bench.rigid import RigidPeers, rigid_parameters
    pb = Problem(FREE_BODY, T=2.0)
    return pb, RigidPeers(*rigid_parameters(pb.eq), cache_dir)


@pytest.fixture(scope="module")
def top(cache_dir):
    from hpgen.bench.crk4 import CRK4
    from hpgen.bench.problem import Problem
    from hpgen.bench.rigid import RigidPeers, rigid_parameters
    pb = Problem(HEAVY_TOP, T=2.0)
    return pb, RigidPeers(*rigid_parameters(pb.eq), cache_dir), CRK4(pb, cache_dir)


def test_parameters_read_off_the_lagrangian():
    from hpgen.bench.problem import Problem
    from hpgen.bench.rigid import rigid_parameters
    I, m = rigid_parameters(Problem(HEAVY_TOP).eq)
    assert I.tolist() == [1.0, 5.0, 6.0] and m.tolist() == [0.0, 0.0, 1.0]   # m = Mg chi
    I, m = rigid_parameters(Problem(FREE_BODY).eq)
    assert I.tolist() == pytest.approx([2.0, 1.0, 2.0 / 3.0], abs=0) and m.tolist() == [0] * 3
    # gyroscopic (turntable) and SE3 (underwater vehicle): not this kind of body
    assert rigid_parameters(Problem(EXAMPLES / "turntable.yaml").eq) is None
    assert rigid_parameters(Problem(EXAMPLES / "underwater_vehicle.yaml").eq) is None


def _errors(rigid, fam, pb, y_ref, hs):
    out = []
    for h in hs:
        steps = int(round(pb.T / h))
        _, y, done, _ = rigid.run(fam, pb.y0, pb.T / steps, steps)
        assert done == steps
        out.append(np.abs(y - y_ref).max())
    return np.array(out)


# Step ladders where the error is far above round-off / the reference's error (order 6: a
# coarser ladder, its error reaches 5e-14 at h = 0.025 on the free body).
LADDERS = {"splitting-2": [0.1, 0.05, 0.025], "splitting-4": [0.1, 0.05, 0.025],
           "splitting-6": [0.2, 0.1, 0.05], "RATTLE": [0.1, 0.05, 0.025]}


@pytest.mark.parametrize("fam", list(LADDERS))
def test_order_against_the_exact_free_body(free, fam):
    # All four are symmetric: error = C h^p + O(h^{p+2}), so the rate between h and h/2 is
    # p + O(h^2); measured (p = 2, 4, 6, 2): 2.000 / 3.99 / 6.0-6.2 / 2.01. +-0.3 is well
    # outside those and still tells p from p +- 1 (a composition with wrong coefficients
    # drops to order 2 or 3).
    from hpgen.bench.rigid import ORDERS
    pb, rigid = free
    y_ref, _ = pb.reference("exact", None)
    e = _errors(rigid, fam, pb, y_ref, LADDERS[fam])
    rates = np.log2(e[:-1] / e[1:])
    assert np.all(np.abs(rates - ORDERS[fam]) < 0.3), (e, rates)
    assert e[-1] < 1e-3


@pytest.mark.parametrize("fam", list(LADDERS))
def test_order_on_the_heavy_top(top, fam):
    # Against DOP853 at rtol = atol = 1e-13 (its error ~1e-12, below every error here:
    # smallest 2.6e-4 (order 4), 1e-10 (order 6 at h = 0.025: h ladder 0.1 .. 0.025)).
    # Measured rates: 2.11, 2.03 / 3.99, 4.00 / 6.09, 6.02 / 1.97, 1.99: the first rate of
    # the order-2 methods carries the O(h^2) correction, hence +-0.3 as above.
    from hpgen.bench.rigid import ORDERS
    pb, rigid, crk4 = top
    y_ref, _ = pb.reference("dop853", crk4.rhs)
    hs = [0.1, 0.05, 0.025]
    e = _errors(rigid, fam, pb, y_ref, hs)
    rates = np.log2(e[:-1] / e[1:])
    assert np.all(np.abs(rates - ORDERS[fam]) < 0.3), (e, rates)


def test_rattle_is_moser_veselov(free):
    # On the free body (no kicks) RATTLE is the Moser-Veselov map; the NumPy one solves the
    # same equation to round-off by another route (Newton in the exp chart), so the two
    # trajectories agree to round-off: 50 steps, |p| ~ 1, bound 50 steps x 1e-14.
    from handwritten.moser_veselov import MoserVeselov
    pb, rigid = free
    h, steps = 0.1, 50
    rec, _, done, its = rigid.run("RATTLE", pb.y0, h, steps, every=1)
    Rs, ps = MoserVeselov([2.0, 1.0, 2.0 / 3.0], h).simulate(pb.g0, pb.mu0, steps)
    assert done == steps and 1 <= its / steps <= 10
    assert np.abs(rec[:, :9].reshape(-1, 3, 3) - Rs).max() < 5e-13
    assert np.abs(rec[:, 9:] - ps).max() < 5e-13


@pytest.mark.parametrize("fam", ["splitting-2", "splitting-6", "RATTLE"])
def test_free_body_conservation(free, fam):
    # Every sub-step is an exact rotation: |Pi| (Casimir) and the spatial momentum R Pi are
    # kept and R stays orthogonal, to round-off: at most ~2e-16 per sub-step, grown linearly
    # (worst case): 20000 steps x 9 sub-steps x 2e-16 ~ 4e-11.
    pb, rigid = free
    steps = 20_000
    rec, _, done, _ = rigid.run(fam, pb.y0, 0.1, steps, every=1000)
    R, Pi = rec[:, :9].reshape(-1, 3, 3), rec[:, 9:]
    assert done == steps
    casimir = np.linalg.norm(Pi, axis=1)
    assert np.abs(casimir - casimir[0]).max() < 4e-11
    spatial = np.einsum("kij,kj->ki", R, Pi)
    assert np.abs(spatial - spatial[0]).max() < 4e-11
    assert np.abs(np.einsum("kji,kjl->kil", R, R) - np.eye(3)).max() < 4e-11
    # and the energy oscillates without drift (symplectic): the second half's maximum
    # deviation is no larger than the first half's plus a tenth of it
    dE = np.abs(pb.energy(rec) - pb.E0)
    half = len(dE) // 2
    assert dE[half:].max() <= 1.1 * dE[:half + 1].max() + 1e-14


def test_heavy_top_vertical_momentum_and_bounded_energy(top):
    # e3.(R Pi) is kept by the rotations and by the kicks (Gamma.(Gamma x m) = 0): round-off;
    # the energy of the order-2 splitting stays bounded over 10^5 steps (h = 0.05): no
    # drift, unlike RK4 whose energy error grows linearly.
    pb, rigid, _ = top
    steps = 100_000
    rec, _, done, _ = rigid.run("splitting-2", pb.y0, 0.05, steps, every=500)
    assert done == steps
    R, Pi = rec[:, :9].reshape(-1, 3, 3), rec[:, 9:]
    vert = np.einsum("ki,ki->k", R[:, 2, :], Pi)
    assert np.abs(vert - vert[0]).max() < 1e-10
    dE = np.abs(pb.energy(rec) - pb.E0)
    half = len(dE) // 2
    assert dE[half:].max() <= 1.1 * dE[:half + 1].max()
    assert dE.max() < 1e-2


def test_bench_tables_and_plot(tmp_path, cache_dir):
    from hpgen.bench import run_bench
    res = run_bench(FREE_BODY, T=2.0, schemes=[("stormer-verlet", "cay", "truncated")],
                    h=[0.1, 0.05], rk4_h=[0.1, 0.05],
                    peers=["RK4-C", "splitting-2", "splitting-4", "splitting-6", "RATTLE"],
                    min_time=0, min_repeats=1, samples=10, out=tmp_path, cache_dir=cache_dir,
                    log=lambda s: None)
    fams = {p.family for p in res.points}
    assert {"splitting-2", "splitting-4", "splitting-6", "RATTLE"} <= fams
    for p in res.points:
        assert p.ok and math.isfinite(p.error) and p.wall_s > 0, p
    md = (tmp_path / "work_precision.md").read_text()
    assert "DLM splitting, Kahan-Li order 6 (C)" in md and "RATTLE / hpgen" in md
    assert "hand-written rigid.c" in md
    csv = (tmp_path / "work_precision.csv").read_text()
    assert csv.count("splitting-4") == 2 and (tmp_path / "work_precision.png").exists()


def test_rigid_c_ships_as_package_data():
    import tomllib
    from pathlib import Path

    from conftest import ROOT
    data = tomllib.loads((ROOT / "pyproject.toml").read_text())
    shipped = data["tool"]["setuptools"]["package-data"]["hpgen.bench"]
    assert any(Path("rigid.c").match(pat) for pat in shipped)
    assert (ROOT / "hpgen" / "bench" / "rigid.c").is_file()
