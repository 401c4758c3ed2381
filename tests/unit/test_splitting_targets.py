"""benchmarks/splitting_targets.py: the free body's equal-error part runs (--quick, two
generated schemes) and reads every family's time off the fronts it measured. No timed
assertion: the ratios are the benchmark's output, not a test's."""
from __future__ import annotations

import importlib.util
import math

import pytest

from conftest import ROOT


@pytest.fixture(scope="module")
def targets():
    spec = importlib.util.spec_from_file_location(
        "splitting_targets", ROOT / "benchmarks" / "splitting_targets.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_free_body_equal_error_quick(targets, cache_dir, capsys):
    splits = ("split2", "split4-suzuki-fasso")
    out = targets.free_body_equal_error(True, splits, cache_dir)
    table = capsys.readouterr().out
    assert "Free rigid body, T = 10 (reference: exact" in table
    assert list(out) == [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
    rows = [line for line in table.splitlines() if line.startswith("| 1e-") or
            line.startswith("| 0.0001")]
    assert len(rows) == len(out)
    # the quick grid (h down to 10 * 2^-11) brackets 1e-4 .. 1e-6 for both kinds
    for e in (1e-4, 1e-5, 1e-6):
        tg, best, th, hand = out[e]
        assert best in {f"hpgen {s}" for s in splits}
        assert hand in targets.HAND
        assert math.isfinite(tg) and tg > 0 and math.isfinite(th) and th > 0


def test_main_runs_the_free_equal_part(targets, cache_dir, capsys):
    assert targets.main(["--quick", "--part", "free-equal", "--splits", "split2",
                         "--cache-dir", str(cache_dir)]) == 0
    assert "best hand splitting / gen" in capsys.readouterr().out
