"""The expected order of ``hpgen check`` depends on the model, and the report says where the
asymptotic regime starts (hpgen.analysis.check_order.expected_order / _refine).

Facts behind the expectations (docs/numerics.md, "Orders"): with a left-invariant l every
q = 0 step is the reduced step of eq. dlp (order 2) and variational Euler is order 2; with l
depending on g (heavy top) variational Euler is order 1, but its error is dominated by an
h^2 term down to h ~ 1e-3: slopes 2.06 1.98 on h = 0.1, 0.05, 0.025, then 1.19, 1.10 between
7.8e-4 and 2e-4 (measured). Before this test the report said "expected 1" for the free body.
"""
from __future__ import annotations

import math

import pytest

from conftest import EXAMPLES
from hpgen.analysis.check import run_check
from hpgen.analysis.check_order import (FLOOR, ORDER_TOL, REFINE_MAX_STEPS, _refine,
                                        expected_order)
from hpgen.analysis.check_report import format_report


@pytest.mark.parametrize("left_invariant,order,rkmk,expected", [
    (True, 1, "truncated", 2), (True, 1, "exact", 2), (True, 2, "truncated", 2),
    (True, 4, "exact", 4), (True, 6, "exact", 6),
    (False, 1, "truncated", 1), (False, 1, "exact", 1), (False, 2, "truncated", 2),
    (False, 4, "exact", 4), (False, 4, None, 4), (True, 4, None, 4)])
def test_expected_order_table(left_invariant, order, rkmk, expected):
    got, why = expected_order(left_invariant, order, rkmk)
    assert got == expected and why


def _levels(err_of_h, h, n):
    return [err_of_h(h / 2 ** k) for k in range(n)]


def test_refine_finds_where_two_term_error_turns_first_order():
    """e(h) = a h + b h^2: the slope log2(e(h) / e(h/2)) is 1 + log2((1 + r) / (1 + r/2)),
    r = b h / a, within ORDER_TOL of 1 exactly when r <= r_max (solved below): the reported
    h is the first level of the halving ladder with r <= r_max."""
    a, b, h, n_o = 0.2, 80.0, 0.1, 10
    err = lambda s: a * s + b * s * s          # noqa: E731
    out = _refine(_levels(err, h, 3), 1, lambda k: err(h / 2 ** k), h, n_o)
    assert out["status"] == "asymptotic"
    # the slope at r: 1 + log2((1 + r) / (1 + r / 2)) <= 1 + ORDER_TOL  <=>  r <= r_max
    q = 2 ** ORDER_TOL
    r_max = (q - 1) / (1 - q / 2)
    h_star = out["asymptotic_h"]
    assert b * h_star / a <= r_max < b * (2 * h_star) / a     # the first level that agrees
    slopes = out["refined"]["observed"]
    assert len(out["refined"]["error"]) == len(slopes) + 1 == len(out["refined"]["h"])


def test_refine_stops_at_budget_and_at_floor():
    h, n_o = 0.1, 10
    quad = lambda s: 1e3 * s * s           # noqa: E731  order 2 where 1 is expected
    out = _refine(_levels(quad, h, 3), 1, lambda k: quad(h / 2 ** k), h, n_o)
    assert out["status"] == "not reached" and out["asymptotic_h"] is None
    assert n_o * 2 ** (len(out["refined"]["h"]) - 1) <= REFINE_MAX_STEPS
    assert n_o * 2 ** len(out["refined"]["h"]) > REFINE_MAX_STEPS
    sixth = lambda s: 1e-4 * s ** 6            # noqa: E731  below FLOOR at once
    out = _refine(_levels(sixth, h, 3), 4, lambda k: sixth(h / 2 ** k), h, n_o)
    assert out["status"] == "floor" and len(out["refined"]["h"]) == 3
    assert out["refined"]["error"][-1] < FLOOR


def test_refine_ignores_one_accidental_slope():
    """An error changing sign between two h gives one slope near the order by accident."""
    h = 0.1
    errs = [0.8, 0.186, 0.0432, 0.00958, 0.00181, 2.11e-4, 1.08e-4, 1.006e-4]   # 0.97, 0.10
    out = _refine(errs, 1, lambda k: 1.0 * (h / 2 ** k), h, 10)
    assert out["asymptotic_h"] is not None and out["asymptotic_h"] < h / 2 ** 6


def test_check_heavy_top_variational_euler_says_where_order_1_starts(cache_dir):
    r = run_check(EXAMPLES / "heavy_top.yaml", tableau="euler-forward", tau="cay",
                  rkmk="truncated", h=0.1, steps=20, cache_dir=cache_dir, n_states=1)
    o = r["order"]
    assert o["expected"] == 1
    assert all(abs(v - 2) < 0.1 for v in o["observed"])     # pre-asymptotic at h = 0.1
    assert o["status"] == "asymptotic" and 1e-4 < o["asymptotic_h"] < 2e-3
    k = o["refined"]["h"].index(o["asymptotic_h"])
    assert all(abs(v - 1) <= ORDER_TOL for v in o["refined"]["observed"][k:k + 2])
    text = format_report(r)
    assert "expected 1" in text and f"from h = {o['asymptotic_h']:.3g}" in text


def test_check_free_body_variational_euler_expects_order_2(cache_dir):
    r = run_check(EXAMPLES / "free_rigid_body.yaml", tableau="euler-forward", tau="cay",
                  rkmk="truncated", h=0.1, steps=20, cache_dir=cache_dir, n_states=1)
    o = r["order"]
    assert o["expected"] == 2 and o["asymptotic_h"] == 0.1 and len(o["refined"]["h"]) == 3
    assert math.isclose(o["observed"][-1], 2, abs_tol=0.05)
    assert "expected 2" in format_report(r)
