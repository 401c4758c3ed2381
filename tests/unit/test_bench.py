"""hpgen.bench (work-precision benchmark): files and columns, convergence of the measured
errors, the C RK4 against the NumPy RK4, the equal-error interpolation, bad input.

One small run is shared (free rigid body, T = 2, exact reference): Stormer-Verlet / Cayley /
truncated at h = 0.1, 0.05, 0.025, DOP853 at three tolerances, one point each of cvodes
(Adams) and collocation, RK4 in NumPy and C at two h. Timings are never asserted on.
"""
from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from conftest import EXAMPLES

FREE_BODY = EXAMPLES / "free_rigid_body.yaml"
HS = [0.1, 0.05, 0.025]
RTOLS = [1e-4, 1e-7, 1e-10]


@pytest.fixture(scope="module")
def bench(tmp_path_factory, cache_dir):
    from hpgen.bench import run_bench
    out = tmp_path_factory.mktemp("bench")
    res = run_bench(FREE_BODY, T=2.0, schemes=[("stormer-verlet", "cay", "truncated")], h=HS,
                    rtol=RTOLS, cvodes_tol=[1e-6], collocation_h=[0.1], rk4_h=[0.1, 0.05],
                    peers=["DOP853", "cvodes-adams", "collocation", "RK4-numpy", "RK4-C"],
                    min_time=0, min_repeats=1, samples=20, out=out, cache_dir=cache_dir,
                    log=lambda s: None)
    return res, out


def test_files_and_columns(bench):
    from hpgen.bench.report import CSV_COLUMNS, MD_COLUMNS
    res, out = bench
    assert {p.name for p in res.files} == {"work_precision.csv", "work_precision.md",
                                           "work_precision.png"}
    with open(out / "work_precision.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    assert tuple(rows[0]) == CSV_COLUMNS
    assert {"method", "parameter", "error", "energy_drift", "wall_time_s", "notes"} <= set(rows[0])
    assert len(rows) - 1 == len(res.points) == len(HS) + len(RTOLS) + 1 + 1 + 2 + 2
    md = (out / "work_precision.md").read_text()
    assert "| " + " | ".join(MD_COLUMNS) + " |" in md
    assert "equal error" in md
    assert (out / "work_precision.png").stat().st_size > 0
    for p in res.points:          # every method ran and has its figures
        assert p.ok and math.isfinite(p.error) and math.isfinite(p.energy_drift), p
        assert p.group_defect >= 0 and p.wall_s > 0 and p.repeats >= 1


def _rates(points):
    e = np.array([p.error for p in points])
    return np.log2(e[:-1] / e[1:])


def test_hpgen_error_decreases_at_the_tableau_order(bench):
    # Stormer-Verlet with the truncated constraint has order 2. It is a symmetric method,
    # so its error expansion has even powers only: the observed rate between h and h/2 is
    # 2 + O(h^2) (measured 1.981 and 1.995 here). +-0.15 is 7x the larger deviation and
    # still tells order 2 from 1 or 3. Errors (1e-2 .. 1e-3) are far above the exact
    # reference's own error (~1e-14), which cannot spoil the rate.
    res, _ = bench
    pts = sorted(res.family("hpgen stormer-verlet/cay/truncated"), key=lambda p: -p.param)
    assert [p.param for p in pts] == pytest.approx(HS)
    rates = _rates(pts)
    assert np.all(np.abs(rates - 2.0) < 0.15), rates


def test_dop853_error_decreases_with_rtol(bench):
    # Adaptive codes control local errors, so the global error is only roughly proportional
    # to rtol (error / rtol varies by about a decade); 3 decades of rtol must buy at least
    # one decade of error (measured: 3.1 and 2.4 decades).
    res, _ = bench
    pts = sorted(res.family("DOP853"), key=lambda p: -p.param)
    assert [p.param for p in pts] == pytest.approx(RTOLS)
    e = [p.error for p in pts]
    assert e[1] < e[0] / 10 and e[2] < e[1] / 10, e


def test_c_rk4_equals_numpy_rk4(bench):
    # Same f (the C vector field) and the same operations in the same order (the template's
    # loop mirrors rk4_numpy): equal to round-off. Measured bitwise equal; the bound allows
    # a compiler contracting a*b+c into an FMA, about one ulp per step and entry.
    res, _ = bench
    c, py = res.family("RK4-C"), res.family("RK4-numpy")
    assert [p.param for p in c] == [p.param for p in py]
    for a, b in zip(c, py):
        scale = np.abs(b.y_end).max()
        assert np.abs(a.y_end - b.y_end).max() <= a.steps * 4e-16 * scale
        assert a.samples[1].shape == b.samples[1].shape
        assert np.abs(a.samples[1] - b.samples[1]).max() <= a.steps * 4e-16 * scale
        assert a.error == pytest.approx(b.error, rel=1e-6)


def test_time_at_error_interpolates_on_the_pareto_front():
    from hpgen.bench.measure import Point
    from hpgen.bench.report import comparisons, time_at_error

    def pt(err, t, fam="peer", kind="peer"):
        p = Point(fam, fam, kind, "h", 1.0, error=err, wall_s=t, repeats=1)
        p.y_end = np.zeros(1)
        return p

    # time = error^-1/2 exactly (log-log straight line), plus a dominated point
    peer = [pt(1e-2, 10.0), pt(1e-6, 1000.0), pt(1e-4, 5000.0)]
    assert time_at_error(peer, 1e-4) == pytest.approx(100.0)
    assert time_at_error(peer, 1e-7) is None and time_at_error(peer, 1.0) is None
    rows = comparisons(peer + [pt(1e-4, 50.0, "hp", "hpgen"), pt(1.0, 1.0, "hp", "hpgen")])
    assert rows[0][1]["peer"] == pytest.approx(2.0) and rows[1][1]["peer"] is None


@pytest.mark.parametrize("argv, field", [
    (["--h", "0.1,-0.05"], "option h"),
    (["--h", "0.1,abc"], "option h"),
    (["--rtol", "1e-6,2"], "option rtol"),
    (["--peers", "DOP853,euler"], "option peers"),
    (["--T", "nan"], "option T"),
    (["--tau", "cay,foo"], "option tau"),
])
def test_cli_bad_grid_is_one_line_exit_2(argv, field, capsys, tmp_path):
    from hpgen.cli import main
    code = main(["bench", str(FREE_BODY), "--out", str(tmp_path / "b"), *argv])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1 and err.startswith("hpgen: error: ") and field in err, err
    assert "Traceback" not in err and not (tmp_path / "b").exists()


def test_cli_missing_file_and_model_without_scene(capsys, tmp_path, model_file):
    from conftest import FREE_BODY as NO_SCENE
    from hpgen.cli import main
    assert main(["bench", str(tmp_path / "nope.yaml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "nope.yaml" in err
    assert main(["bench", str(model_file(NO_SCENE)), "--out", str(tmp_path / "b")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "scene" in err
