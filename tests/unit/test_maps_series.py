"""The exp chart's scalar functions (hpgen.groups.series: branch-free half-angle polynomials)
against 50-digit mpmath, in ulps, at the points where removable singularities and former
branch points bite: t = |w| in {0, 1e-8, 1e-4, 0.1, 1 -+ 1 ulp, 1, 3, pi - 1e-9, pi}.

- values: relative error <= 8 ulp (2^-52; measured <= 6.8, d_dexpinv_c at t = pi, whose two
  terms r D'/4 and c^2/2 cancel 2:1 there), except sin t / t for t >= 3,
  computed as (sin u / u) cos u with cos u = 1 - u^2 (1 - cos u)/u^2 accurate in absolute
  terms only (cos 1.5 = 0.07: 8 ulp relative at t = 3; sin t / t vanishes at pi): absolute
  error <= 2 ulp there;
- first and second s-derivatives by casadi AD (what the derive stage builds from them),
  relative <= 12 ulp (measured <= 8.6, the second derivative of dexpinv_c at pi); the
  explicit d_* functions equal the AD derivatives to a few ulp;
- exact limits at s = 0 (no NaN, nothing masked);
- beyond the accuracy domain (|w| > pi, where the exp chart's margin is negative) the
  documented degradation: exp(w^) within 1e-15 up to |w| = 4 and 1e-12 up to 2 pi - 0.3;
- the kernels' cost: the SO3/SE3 exp-chart maps contain no sqrt, trigonometric call or
  comparison (no branch) and their instruction counts stay small.
"""
from __future__ import annotations

import collections
import math

import casadi as ca
import mpmath as mp
import numpy as np
import pytest

from _mp_series import mp_series_function
from hpgen.groups import group_from_spec, series

ULP = 2.0**-52
T_POINTS = (1e-8, 1e-4, 0.1, np.nextafter(1.0, 0.0), 1.0, np.nextafter(1.0, 2.0), 3.0,
            math.pi - 1e-9, math.pi)


@pytest.fixture(scope="module")
def functions():
    """casadi Function s -> [f, f', f''] for every series function (AD derivatives)."""
    S = ca.SX.sym("s")
    out = {}
    for name in series.NAMES:
        f = series.evaluate(name, S)
        d1 = ca.jacobian(f, S)
        out[name] = ca.Function(name, [S], [f, d1, ca.jacobian(d1, S)])
    return out


@pytest.mark.parametrize("name", series.NAMES)
def test_values_and_ad_derivatives_in_ulps(functions, name):
    worst = [0.0, 0.0, 0.0]
    truth = mp_series_function(name)
    with mp.workdps(50):
        for t in T_POINTS:
            s = t * t
            got = [float(v) for v in functions[name](s)]
            sm = mp.mpf(s)
            refs = [truth(sm), mp.diff(truth, sm), mp.diff(truth, sm, 2)]
            for k, (g, r) in enumerate(zip(got, refs)):
                err = abs(mp.mpf(g) - r)
                if name == "sinc" and k == 0 and t >= 3:  # near its zero t = pi: absolute
                    assert err <= 2 * ULP, (name, t, float(err))
                    continue
                rel = float(err / abs(r)) / ULP
                worst[k] = max(worst[k], rel)
                assert rel <= (8 if k == 0 else 12), (name, t, k, g, float(r), rel)
    print(f"\n{name}: max relative error (ulp) value / d/ds / d2/ds2: "
          f"{worst[0]:.1f} / {worst[1]:.1f} / {worst[2]:.1f}", end="")


def test_limits_at_zero(functions):
    exact = {"sinc": 1.0, "cosc": 0.5, "sinc3": 1 / 6, "dexpinv_c": 1 / 12,
             "d_cosc": -1 / 24, "d_sinc3": -1 / 120, "d_dexpinv_c": 1 / 720}
    for s in (0.0, 1e-300):
        for name, ref in exact.items():
            val, d1, d2 = (float(v) for v in functions[name](s))
            if name.startswith("d_"):
                assert abs(val - ref) <= 2 * ULP * abs(ref), (name, s, val)
            else:
                assert val == ref, (name, s, val)  # exact: the removable singularity
            assert math.isfinite(d1) and math.isfinite(d2)


def test_explicit_derivatives_equal_ad(functions):
    """d_cosc, d_sinc3, d_dexpinv_c (used by SE3) are the derivatives of the coded values."""
    for t in T_POINTS + (0.0, 2.0):
        s = t * t
        for name in ("cosc", "sinc3", "dexpinv_c"):
            ad = float(functions[name](s)[1])
            explicit = float(functions["d_" + name](s)[0])
            assert abs(ad - explicit) <= 4 * ULP * abs(ad), (name, t, ad, explicit)


@pytest.mark.parametrize("t,bound", [(3.3, 1e-15), (4.0, 1e-15), (2 * math.pi - 0.3, 1e-12),
                                     (3 * math.pi, 1e-6), (100.0, None)])
def test_beyond_the_accuracy_domain(t, bound):
    """|w| > pi: exp(w^) degrades smoothly (documented in hpgen.groups.series), all maps and
    their derivatives stay finite."""
    G = group_from_spec("SO3")
    x = ca.SX.sym("x", 3)
    Ms = [G.tau("exp", x), G.dtau_inv("exp", x), G.dtau("exp", x)]
    fn = ca.Function("f", [x], Ms + [ca.jacobian(ca.vec(M), x) for M in Ms])
    u = np.array([0.36, 0.48, 0.8])
    out = [np.array(o, float) for o in fn(t * u)]
    assert all(np.isfinite(o).all() for o in out), t
    if bound is not None:
        W = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
        ref = np.eye(3) + math.sin(t) * W + (1 - math.cos(t)) * (W @ W)
        assert np.abs(out[0] - ref).max() <= bound, (t, np.abs(out[0] - ref).max())


def _op_counts(f):
    names = {v: k[3:] for k, v in vars(ca).items() if k.startswith("OP_") and isinstance(v, int)}
    return collections.Counter(names.get(f.instruction_id(k), "?")
                               for k in range(f.n_instructions()))


@pytest.mark.parametrize("spec,limit", [("SO3", 340), ("SE3", 800)])
def test_exp_maps_are_branch_free_and_small(spec, limit):
    """No sqrt, sin, cos, tan, comparison or if_else in the exp-chart maps and their first
    derivatives (what makes them cheap in C), and a bound on their size: tau, dtau_inv and
    dtau of one argument with the first derivatives of dtau_inv (measured: SO3 307,
    SE3 751 instructions; 348 and 799 with the former Taylor/closed-form branch, which
    also called sqrt, sin, cos and tan)."""
    G = group_from_spec(spec)
    x, y = ca.SX.sym("x", G.d), ca.SX.sym("y", G.d)
    Di = G.dtau_inv("exp", x)
    outs = ca.cse([ca.vec(G.tau("exp", x)), ca.vec(Di), ca.vec(G.dtau("exp", x)),
                   ca.jtimes(ca.vec(Di), x, y)])
    f = ca.Function("f", [x, y], outs)
    ops = _op_counts(f)
    banned = {k: ops[k] for k in ("SQRT", "SIN", "COS", "TAN", "LT", "LE", "IF_ELSE_ZERO")
              if ops[k]}
    assert not banned, banned
    print(f"\n{spec}: exp maps + d dexp^-1: {f.n_instructions()} instructions", end="")
    assert f.n_instructions() <= limit
