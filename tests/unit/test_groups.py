"""Chart maps tau, dtau^{-1}, dtau of every catalog group, checked numerically.

References are independent of the closed forms: scipy expm/logm, finite differences and casadi
AD of tau (right-trivialized: dtau_x(y) = vee(D tau(x)[y] tau(x)^{-1}), Definition def:dtau),
the Bernoulli series of eq:dexp, and 50-digit mpmath for the series functions
(more in tests/unit/test_maps_series.py).
"""
from __future__ import annotations

import functools
import math
import subprocess
import sys

import casadi as ca
import mpmath as mp
import numpy as np
import pytest
import scipy.linalg as sla

from hpgen.errors import ModelError
from _mp_series import mp_series_function
from hpgen.groups import group_from_spec, maps, series

GROUPS = ("R2", "SO2", "SO3", "SE2", "SE3", ("SO3", "R3"))
CASES = [(g, k) for g in GROUPS for k in group_from_spec(list(g) if isinstance(g, tuple) else g)
         .tau_kinds]
NORMS = (0.0, 1e-9, 0.3, 2.5)


def _group(spec):
    return group_from_spec(list(spec) if isinstance(spec, tuple) else spec)


@functools.lru_cache(maxsize=None)
def _funcs(spec, kind):
    """Numeric casadi Functions of one (group, kind): maps, derivatives, hat and vee."""
    G = _group(spec)
    x = ca.SX.sym("x", G.d)
    T, Di, D = G.tau(kind, x), G.dtau_inv(kind, x), G.dtau(kind, x)
    maps = ca.Function("maps", [x], [T, Di, D, G.tau_margin(kind, x), G.group_defect(T)])
    jT = ca.jacobian(ca.vec(T), x)
    outs = [ca.vec(T), ca.vec(Di), ca.vec(D)]
    j1 = [ca.jacobian(o, x) for o in outs]
    j2 = [ca.jacobian(ca.vec(j), x) for j in j1]
    derivs = ca.Function("derivs", [x], outs + j1 + j2)
    M = ca.SX.sym("M", G.n, G.n)
    return {"G": G, "maps": maps, "jtau": ca.Function("jtau", [x], [jT]), "derivs": derivs,
            "hat": ca.Function("hat", [x], [G.hat(x)]), "vee": ca.Function("vee", [M], [G.vee(M)]),
            "ad": ca.Function("ad", [x], [G.ad(x)])}


def _ev(f, *args):
    out = f(*args)
    out = out if isinstance(out, (list, tuple)) else [out]
    return [np.array(o, dtype=float) for o in out]


def _points(spec, kind, seed=0):
    """x = 0, then |x| ~ 1e-9, 0.3, 2.5 (skew: 0.9) along seeded random directions."""
    G = _group(spec)
    rng = np.random.default_rng(seed + 7 * len(str(spec)) + len(kind))
    pts = [np.zeros(G.d)]
    for r in NORMS[1:]:
        r = min(r, 0.9) if kind == "skew" else r
        for _ in range(2):
            u = rng.normal(size=G.d)
            if kind == "skew":  # the chart constraint is per SO factor
                pts.append(r * u / np.linalg.norm(u) / math.sqrt(max(1, len(G.factors))))
            else:
                pts.append(r * u / np.linalg.norm(u))
    return pts


#: documented chart domains (hpgen.groups.maps): |omega|^2 < limit on every rotation factor
_MARGIN_LIMIT = {"exp": math.pi**2, "cay": 4.0, "skew": 0.5}


def _inside_chart(spec, kind, x):
    for L in _group(spec).factors:
        if L.name in ("SO2", "SO3", "SE2", "SE3"):
            w = x[L.off:L.off + (3 if L.name in ("SO3", "SE3") else 1)]
            if np.dot(w, w) >= _MARGIN_LIMIT[kind]:
                return False
    return True


def _dtau_reference(F, x, h=2e-4):
    """Right-trivialized tangent by a 4th-order central difference of tau.

    Error ~ h^4 |tau^(5)| + eps |tau| / h: below 1e-11 here (skew at |x| = 0.9 is the worst).
    """
    G = F["G"]
    T = _ev(F["maps"], x)[0]
    Tinv = np.linalg.inv(T)
    cols = []
    for k in range(G.d):
        e = np.zeros(G.d)
        e[k] = h
        tp = [_ev(F["maps"], x + m * e)[0] for m in (-2, -1, 1, 2)]
        dT = (tp[0] - 8 * tp[1] + 8 * tp[2] - tp[3]) / (12 * h)
        cols.append(_ev(F["vee"], dT @ Tinv)[0].ravel())
    return np.column_stack(cols)


def _dtau_ad(F, x):
    G = F["G"]
    T = _ev(F["maps"], x)[0]
    J = _ev(F["jtau"], x)[0]
    Tinv = np.linalg.inv(T)
    return np.column_stack([_ev(F["vee"], J[:, k].reshape(G.n, G.n, order="F") @ Tinv)[0].ravel()
                            for k in range(G.d)])


@pytest.mark.parametrize("spec,kind", CASES)
def test_tau_on_group_inverse_and_exp(spec, kind):
    F = _funcs(spec, kind)
    for x in _points(spec, kind):
        T, _, _, margin, defect = _ev(F["maps"], x)
        assert defect.item() < 1e-14, (x, defect)
        assert (margin.item() > 0) == _inside_chart(spec, kind, x), (x, margin)
        Tm = _ev(F["maps"], -x)[0]
        assert np.max(np.abs(T @ Tm - np.eye(T.shape[0]))) < 1e-14
        if kind == "exp":
            ref = sla.expm(_ev(F["hat"], x)[0])
            assert np.max(np.abs(T - ref)) < 1e-14, (x, np.max(np.abs(T - ref)))


PRODUCTS = [("dtau_inv", False), ("dtau_inv", True), ("dtau", False), ("dtau", True)]


def _product_gap(spec, kind, which, transposed, closed):
    """Over the test points and seeded m: (max |f(x, m) - M m|, its bound 8 eps |m| (1 + |x|)^2,
    whether f(x, m) == M m bitwise), f the closed form ``closed(x, m)``, M = dtau_inv(x) or
    dtau(x) (``which``), transposed or not."""
    G = _group(spec)
    x, m = ca.SX.sym("x", G.d), ca.SX.sym("m", G.d)
    M = G.dtau_inv(kind, x) if which == "dtau_inv" else G.dtau(kind, x)
    f = ca.Function("f", [x, m], [closed(x, m), ca.mtimes(M.T if transposed else M, m)])
    rng = np.random.default_rng(3)
    worst, exact = (0.0, 1.0), True
    for x0 in _points(spec, kind):
        m0 = rng.standard_normal(G.d) * 10.0
        a, b = _ev(f, x0, m0)
        exact = exact and np.array_equal(a, b)
        gap = np.max(np.abs(a - b))
        bound = 8 * np.finfo(float).eps * np.max(np.abs(m0)) * (1.0 + np.max(np.abs(x0))) ** 2
        worst = max(worst, (gap, bound), key=lambda t: t[0] / t[1])
    return worst[0], worst[1], exact


@pytest.mark.parametrize("spec,kind", CASES)
def test_chart_products_are_the_matrices_times_m(spec, kind):
    """chart_product (dtau^{-1}_x m, its transpose, dtau_x m, its transpose: what the
    derivation applies to velocities and momenta) against the matrices of dtau_inv / dtau
    times m: exactly the product where no closed form is tabulated, else to a few ulps of
    |m| (1 + |x|)^2 (SO3's Cayley chart: m -+ (x x m)/2 + (x.m) x/4 and
    (4/(4 + |x|^2)) (m +- (x x m)/2), the same terms summed in another order)."""
    G = _group(spec)
    closed = (getattr(G, "family", None), kind) in maps.CHART_PRODUCTS
    for which, tr in PRODUCTS:
        gap, bound, exact = _product_gap(
            spec, kind, which, tr, lambda x, m: G.chart_product(kind, which, x, m, tr))
        if closed:
            assert gap <= bound, (which, tr, gap, bound)
        else:
            assert exact, (spec, kind, which, tr)
    gap, bound, exact = _product_gap(spec, kind, "dtau_inv", True,
                                     lambda x, m: G.dtau_inv_T_times(kind, x, m))
    assert gap <= bound and (closed or exact)


@pytest.mark.parametrize("which,transposed", PRODUCTS)
def test_chart_product_check_catches_a_sign_error(which, transposed):
    """The check above fails SO3's Cayley closed form with the sign of its cross-product term
    flipped (f(-x, m): an O(|x| |m|) gap, far above the bound)."""
    f = maps.CHART_PRODUCTS[("SO3", "cay")][(which, transposed)]
    gap, bound, _ = _product_gap("SO3", "cay", which, transposed, lambda x, m: f(-x, m))
    assert gap > 1e6 * bound


@pytest.mark.parametrize("spec,kind", CASES)
def test_dtau_inv_against_derivative_of_tau(spec, kind):
    F = _funcs(spec, kind)
    for x in _points(spec, kind):
        _, Di, D, _, _ = _ev(F["maps"], x)
        I = np.eye(D.shape[0])
        assert np.max(np.abs(D @ Di - I)) < 1e-13
        fd = _dtau_reference(F, x)
        assert np.max(np.abs(D - fd)) < 1e-9, (x, np.max(np.abs(D - fd)))
        assert np.max(np.abs(Di @ fd - I)) < 1e-9
        ad = _dtau_ad(F, x)  # AD of the tau formula: exact up to round-off
        assert np.max(np.abs(D - ad)) < 1e-13 * max(1.0, np.max(np.abs(ad)))
        assert np.max(np.abs(Di @ ad - I)) < 1e-13


def _ad_series(adx, coeff, q=40):
    """sum_{j <= q} coeff(j) ad_x^j."""
    out, P = np.zeros_like(adx), np.eye(adx.shape[0])
    for j in range(q + 1):
        out, P = out + coeff(j) * P, P @ adx
    return out


@pytest.mark.parametrize("spec", GROUPS)
def test_dexp_against_bernoulli_series(spec):
    """eq:dexp: dexp^{-1}_x = sum_j B_j/j! ad_x^j (B_1 = -1/2), dexp_x = sum_j ad_x^j/(j+1)!."""
    F = _funcs(spec, "exp")
    for x in _points(spec, "exp")[:5]:  # |x| <= 0.3: 40 terms are exact to round-off
        adx = _ev(F["ad"], x)[0]
        _, Di, D, _, _ = _ev(F["maps"], x)
        ref_inv = _ad_series(adx, lambda j: float(mp.bernoulli(j)) / math.factorial(j))
        ref = _ad_series(adx, lambda j: 1.0 / math.factorial(j + 1))
        assert np.max(np.abs(Di - ref_inv)) < 1e-14
        assert np.max(np.abs(D - ref)) < 1e-14


def _inv_chart(kind, g, vee):
    if kind == "cay":  # cay(X) = g  <=>  X = 2 (g - I)(g + I)^{-1}
        I = np.eye(g.shape[0])
        return vee(2 * (g - I) @ np.linalg.inv(g + I))
    return vee(np.real(sla.logm(g)))


@pytest.mark.parametrize("spec", ["SO3", "SE3"])
@pytest.mark.parametrize("kind", ["cay", "exp"])
def test_first_order_expansion_of_inverse_chart(spec, kind):
    """tau^{-1}(exp(-eta) tau(a) exp(eps)) = a + dtau^{-1}_a(-eta) + dtau^{-1}_{-a}(eps) + O(2)."""
    F = _funcs(spec, kind)
    rng = np.random.default_rng(3)
    vee = lambda M: _ev(F["vee"], M)[0].ravel()  # noqa: E731
    hat = lambda v: _ev(F["hat"], v)[0]  # noqa: E731
    for a in _points(spec, kind)[1:]:
        eta0, eps0 = rng.normal(size=len(a)), rng.normal(size=len(a))
        eta0, eps0 = eta0 / np.linalg.norm(eta0), eps0 / np.linalg.norm(eps0)
        residuals = []
        for delta in (1e-4, 1e-5):
            eta, eps = delta * eta0, delta * eps0
            g = sla.expm(-hat(eta)) @ _ev(F["maps"], a)[0] @ sla.expm(hat(eps))
            pred = a + _ev(F["maps"], a)[1] @ (-eta) + _ev(F["maps"], -a)[1] @ eps
            residuals.append(np.linalg.norm(_inv_chart(kind, g, vee) - pred))
        # O(delta^2): |residual| ~ delta^2 and dividing delta by 10 divides it by ~100
        assert residuals[0] < 20 * 1e-4**2, residuals
        assert residuals[0] / 200 < residuals[1] < residuals[0] / 50, residuals


#: rotation sizes |w| for the NaN check: the former series branch point 1 (where the hard
#: cases put chart arguments) on both sides, the exp chart's domain bound pi (the series'
#: accuracy bound) and far outside it (the polynomials stay finite)
_SPECIAL_NORMS = (1e-300, np.nextafter(1.0, 0.0), 1.0, math.pi, 10.0, 1e3)


def _threshold_points(spec, kind):
    """x = 0 and x whose rotation part has |w| exactly each of _SPECIAL_NORMS."""
    G = _group(spec)
    pts = [np.zeros(G.d)]
    if kind == "skew":
        return pts + [0.5 * np.ones(G.d) / math.sqrt(G.d)]
    for r in _SPECIAL_NORMS:
        x = np.linspace(0.1, 0.6, G.d)  # translation parts stay generic
        for L in G.factors:
            if L.name in ("SO2", "SO3", "SE2", "SE3"):
                x[L.off:L.off + (3 if L.name in ("SO3", "SE3") else 1)] = 0.0
                x[L.off] = r
        pts.append(x)
    return pts


@pytest.mark.parametrize("spec,kind", CASES)
def test_no_nan_in_maps_and_two_derivatives(spec, kind):
    F = _funcs(spec, kind)
    for x in _threshold_points(spec, kind):
        for out in _ev(F["derivs"], x):
            assert np.all(np.isfinite(out)), (spec, kind, x)


#: size of the matrix factor each series function multiplies in the maps, |v| = 1
_FACTOR = {
    "sinc": lambda t: max(1.0, t),      # W in exp; v in the se3 translation
    "cosc": lambda t: max(1.0, t * t),  # W^2 in exp, W in dexp, V in se3 dexp, w x v
    "sinc3": lambda t: 2 * t * t,       # W^2, WV + VW
    "dexpinv_c": lambda t: 2 * t * t,   # W^2, WV + VW
    "d_cosc": lambda t: 2 * t * t,      # 2 (w.v) W
    "d_sinc3": lambda t: 2 * t**3,      # 2 (w.v) W^2
    "d_dexpinv_c": lambda t: 2 * t**3,  # 2 (w.v) W^2
}


def test_series_functions_against_mpmath():
    """Each function against mpmath on the accuracy domain |w| <= pi (series.T_MAX).

    The maps need absolute accuracy of the matrices, so the error of f is weighted by the size
    of the factor it multiplies there (_FACTOR, |v| = 1); for s <= 0.2 each function is also
    accurate relative to itself. At s = 0 the value functions are their exact limits."""
    S = ca.SX.sym("s")
    fn = ca.Function("f", [S], [series.evaluate(name, S) for name in series.NAMES])
    for s in [1e-20, 1e-9, 0.01, 0.2, np.nextafter(1.0, 0), 1.0, np.nextafter(1.0, 2), 2.25,
              4.0, 9.0, np.nextafter(math.pi**2, 0), math.pi**2]:
        vals = [float(v) for v in fn(s)]
        for name, val in zip(series.NAMES, vals):
            with mp.workdps(120):  # enough digits for the cancellation at s = 1e-20
                ref = float(mp_series_function(name)(mp.mpf(s)))
            w = _FACTOR[name](math.sqrt(s))
            assert abs(val - ref) * w <= 8e-16, (name, s, val, ref)
            if s <= 0.2:
                assert abs(val - ref) <= 1.5e-15 * abs(ref), (name, s, val, ref)
    limits = [1.0, 0.5, 1 / 6, 1 / 12]
    for s in (0.0, 1e-300):
        assert [float(v) for v in fn(s)][:4] == limits


def test_series_data_is_up_to_date():
    """series_data.py is what hpgen.tools.gen_series (sympy) generates today."""
    from hpgen.tools import gen_series

    assert gen_series.DATA_PATH.read_text() == gen_series.render()


def test_series_terms_are_the_fewest_meeting_the_matrix_tolerance():
    from hpgen.tools.gen_series import required_terms

    for name, terms in series.TERMS.items():
        assert terms == required_terms(name), (name, terms, required_terms(name))
    assert series.T_MAX == math.pi  # the exp chart's domain (maps._exp_margin)


def test_series_import_does_not_need_sympy():
    code = ("import sys, hpgen.groups.series, hpgen.groups.maps; "
            "sys.exit(1 if 'sympy' in sys.modules else 0)")
    assert subprocess.run([sys.executable, "-c", code]).returncode == 0


def _mp_hat3(w):
    return mp.matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def _mp_exp_maps(spec, x):
    """(exp(x^), dexp^{-1}_x, dexp_x) in mpmath, independent of the closed forms: mp.expm,
    dexp_x = sum_j ad_x^j / (j+1)! and its inverse."""
    if spec == "SO3":
        X = ad = _mp_hat3(x)
    else:
        W, V = _mp_hat3(x[:3]), _mp_hat3(x[3:])
        X, ad = mp.zeros(4, 4), mp.zeros(6, 6)
        for i in range(3):
            X[i, 3] = x[3 + i]
            for j in range(3):
                X[i, j] = ad[i, j] = ad[3 + i, 3 + j] = W[i, j]
                ad[3 + i, j] = V[i, j]
    D, P, j = mp.zeros(ad.rows, ad.rows), mp.eye(ad.rows), 0
    while mp.mnorm(P, 1) > mp.mpf(10)**-90 * mp.factorial(j + 1):
        D, P, j = D + P / mp.factorial(j + 1), P * ad, j + 1
    return mp.expm(X), D**-1, D


@pytest.mark.parametrize("spec", ["SO3", "SE3"])
def test_exp_chart_matrices_and_derivatives_against_mpmath(spec):
    """Matrix-level accuracy of exp, dexp^{-1} and dexp and of their first directional
    derivatives (casadi AD, as the derive stage uses them) for |w| in [0, pi] (the series'
    accuracy domain, series.T_MAX), |v| = 1, also around |w| = 1 where the hard cases put
    chart arguments: max abs error <= 1e-15 max(1, max abs entry)."""
    F = _funcs(spec, "exp")
    G = F["G"]
    x, y = ca.SX.sym("x", G.d), ca.SX.sym("y", G.d)
    Ms = [G.tau("exp", x), G.dtau_inv("exp", x), G.dtau("exp", x)]
    fn = ca.Function("f", [x, y], Ms + [ca.jtimes(ca.vec(M), x, y) for M in Ms])
    rng = np.random.default_rng(11)
    h = mp.mpf(10)**-20
    with mp.workdps(50):
        for r in (0.0, 1e-3, 0.3, np.nextafter(1.0, 0), 1.0, np.nextafter(1.0, 9), 1.01, 1.5,
                  3.0, series.T_MAX):
            for _ in range(2):
                w = rng.normal(size=3)
                w *= r / np.linalg.norm(w)
                xv = w if spec == "SO3" else np.concatenate([w, rng.normal(size=3) / math.sqrt(3)])
                yv = rng.normal(size=G.d)
                yv /= np.linalg.norm(yv)
                out = [np.array(o, float) for o in fn(xv, yv)]
                plus = _mp_exp_maps(spec, [mp.mpf(a) + h * mp.mpf(b) for a, b in zip(xv, yv)])
                minus = _mp_exp_maps(spec, [mp.mpf(a) - h * mp.mpf(b) for a, b in zip(xv, yv)])
                for k in range(3):
                    val = (plus[k] + minus[k]) / 2            # + O(h^2) = 1e-40
                    der = (plus[k] - minus[k]) / (2 * h)      # + O(h^2)
                    n = val.rows
                    for num, ref in ((out[k], [[val[i, j] for j in range(n)] for i in range(n)]),
                                     (out[3 + k].reshape(n, n, order="F"),
                                      [[der[i, j] for j in range(n)] for i in range(n)])):
                        ref = np.array(ref, dtype=object)
                        err = max(abs(mp.mpf(float(num[i, j])) - ref[i, j])
                                  for i in range(n) for j in range(n))
                        scale = max(1.0, float(max(abs(e) for e in ref.ravel())))
                        assert err <= 1e-15 * scale, (spec, k, r, float(err))


def test_series_functions_finite_with_two_derivatives():
    """Every function and its first two s-derivatives are finite at s = 0, inside and far
    outside the accuracy domain (no branch: nothing can be NaN * 0)."""
    S = ca.SX.sym("s")
    for name in series.NAMES:
        f = series.evaluate(name, S)
        d1 = ca.jacobian(f, S)
        fn = ca.Function("b", [S], [f, d1, ca.jacobian(d1, S)])
        for s in (0.0, 1e-300, np.nextafter(1.0, 0), 1.0, math.pi**2, 100.0, 1e6):
            assert all(np.isfinite(float(v)) for v in fn(s)), (name, s)


def test_unsupported_kind_raises_model_error():
    x6 = ca.SX.sym("x", 6)
    for spec, d in (("SE2", 3), ("SE3", 6), ("R2", 2), (("SO3", "R3"), 6)):
        G = _group(spec)
        with pytest.raises(ModelError) as err:
            G.tau("skew", ca.SX.sym("x", d))
        assert err.value.field == "integrator.tau"
        assert "skew is not available" in str(err.value) and "use one of" in str(err.value)
    with pytest.raises(ModelError, match="exp, cay, skew"):
        _group("SO3").dtau_inv("rk4", x6[0:3])


def test_margins_sign():
    cases = [("SO3", "exp", [3.0, 0, 0], True), ("SO3", "exp", [3.2, 0, 0], False),
             ("SE3", "exp", [0, 0, 3.2, 9, 9, 9], False), ("SE2", "exp", [3.1, 5, 5], True),
             ("SO2", "exp", [3.2], False), ("SO3", "skew", [0.7, 0, 0], True),
             ("SO3", "skew", [0.72, 0, 0], False), ("SO3", "skew", [0.6, 0.6, 0.6], False),
             ("SO2", "skew", [1.01], False), ("SO3", "cay", [1.99, 0, 0], True),
             ("SO3", "cay", [2.01, 0, 0], False), ("SO3", "cay", [100, 0, 0], False),
             ("SE3", "cay", [0, 0, 1.9, 50, 50, 50], True),
             ("SE3", "cay", [0, 0, 50, 1, 1, 1], False)]
    for spec, kind, x, inside in cases:
        m = _ev(_funcs(spec, kind)["maps"], np.array(x, float))[3].item()
        assert (m > 0) == inside, (spec, kind, x, m)
