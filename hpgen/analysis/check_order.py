"""The order study of ``hpgen check`` (the report's ``order``; hpgen.analysis.check's module
docstring): the errors at T of runs with h, h/2, h/4 against DOP853 on the continuous
equations (a constrained model: the differences of successive halvings), their observed
orders (log2 of successive error ratios) against the order the scheme is expected to show,
and the refinement of h until the two agree."""
from __future__ import annotations

import numpy as np

REFERENCE_RTOL = 1e-12
FLOOR = 1e-10
#: an observed order within this of the expected one agrees (the slope of three halvings
#: of a clean h^p error is p to about 0.05; 0.25 leaves room for the next term)
ORDER_TOL = 0.25
#: the step budget of one refinement run of the order study (T / h_finest steps)
REFINE_MAX_STEPS = 2 ** 17


def expected_order(left_invariant: bool, scheme_order: int, rkmk) -> tuple[int, str]:
    """(order, why) that a scheme shows on a model (docs/numerics.md sec. 7).

    scheme_order: the tableau's order with the exact RKMK constraint, min(order, 2) with
    ``truncated`` (q = 0), 4 for RKMK-RK4; rkmk: 'exact' | 'truncated', None for a scheme
    that is not one of hpgen's (RKMK-RK4). A left-invariant l (no g in l) turns every
    q = 0 step into the reduced Euler-Poincare step of eq. ``dlp``, which is order 2 whatever
    the tableau; the variational Euler tableaus (order 1) are order 2 there with either
    constraint (measured: free rigid body, euler-forward and euler-backward, exp and cay).
    When l depends on g (heavy top) they are order 1, which shows only at small h: 2.1 is
    observed on h = 0.1 .. 0.0125, 1.19 between h = 7.8e-4 and 3.9e-4 (see ``_refine``).
    """
    if rkmk is None:
        return scheme_order, "explicit RKMK-RK4"
    if left_invariant and rkmk == "truncated":
        return 2, "l left-invariant: a q = 0 step is the reduced step of eq. dlp"
    if left_invariant and scheme_order == 1:
        return 2, "l left-invariant: variational Euler is order 2"
    if rkmk == "truncated":
        return scheme_order, ("l depends on g: variational Euler is order 1" if scheme_order == 1
                              else "the truncated constraint (q = 0) caps the order at 2")
    return scheme_order, "the tableau's order, exact RKMK constraint"


def _slopes(errs):
    """log2 of successive error ratios (None where an error is 0)."""
    return [float(np.log2(a / b)) if a > 0 and b > 0 else None
            for a, b in zip(errs[:-1], errs[1:])]


def _agreeing(errs, expected):
    """The first k from which the slopes k and k + 1 agree with ``expected`` (within
    ORDER_TOL), the errors down to h / 2^(k+2) above FLOOR; None if there is none. Two
    slopes, not one: an error that changes sign between two h gives one accidental slope
    (heavy top, euler-backward: 0.97 then 0.10 near h = 2e-3)."""
    obs = _slopes(errs)
    for k in range(len(obs) - 1):
        pair = obs[k:k + 2]
        if (errs[k + 2] >= FLOOR and None not in pair
                and all(abs(o - expected) <= ORDER_TOL for o in pair)):
            return k
    return None


def _refine(errs, expected, error_at, h, n_o) -> dict:
    """Halve h beyond h/4 (appending to ``errs``) until the observed order agrees with the
    expected one, the finest error falls below FLOOR or a run would exceed REFINE_MAX_STEPS
    steps; ``error_at(k)`` is the error with step h / 2^k. Returns the report's ``refined``
    ({h, error, observed} over every level), ``asymptotic_h`` and ``status``."""
    errs = list(errs)
    k = _agreeing(errs, expected)
    while (k is None and errs[-1] >= FLOOR and n_o * 2 ** len(errs) <= REFINE_MAX_STEPS):
        errs.append(error_at(len(errs)))
        k = _agreeing(errs, expected)
    status = "asymptotic" if k is not None else ("floor" if errs[-1] < FLOOR else "not reached")
    return {"refined": {"h": [h / 2 ** i for i in range(len(errs))], "error": errs,
                        "observed": _slopes(errs)},
            "asymptotic_h": None if k is None else h / 2 ** k, "status": status}


def scheme_order(sch, model, scheme: str) -> tuple[int, str]:
    """(order, why) that the check's scheme ``sch`` is expected to show on ``model``:
    expected_order, a splitting scheme's composition order, or the order of the composition
    of a symmetric step when higher."""
    expected, why = expected_order(model.left_invariant, sch.order,
                                   sch.info.get("rkmk") if scheme == "hpgen" else None)
    if getattr(sch, "splitting", False):
        expected, why = sch.order, "the splitting scheme's composition order"
    comp = getattr(sch, "composition", None)
    if comp is not None and comp.order > expected:
        expected, why = comp.order, f"the composition {comp.name} of a symmetric step"
    return expected, why


def order_study(sch, eq, g0, mu0, h: float, n_o: int, u_of, U, *, constrained: bool,
                expected: int, why: str) -> dict:
    """The report's ``order`` of the scheme ``sch`` (its ``simulate``) from (g0, mu0) over
    T = n_o h; eq: the model's ContinuousEquations (the reference), u_of(k, N): the inputs
    of the run with h / 2^k and N steps, U: the input rows held over the steps of h (None
    without inputs)."""
    T = n_o * h

    def final(k):               # the state at T of the run with step h / 2^k
        N = n_o * 2 ** k
        g, mu = sch.simulate(g0, mu0, h / 2 ** k, N, every=N, u=u_of(k, N))
        return g[-1], mu[-1]

    if constrained:
        # no independent reference of the constrained equations: the differences of
        # successive halvings (self-convergence), |x(h / 2^k) - x(h / 2^(k+1))| ~ C h^p
        finals: dict = {}

        def error_at(k):
            for j in (k, k + 1):
                if j not in finals:
                    finals[j] = final(j)
            (ga, ma), (gb, mb) = finals[k], finals[k + 1]
            return float(max(np.abs(ga - gb).max(), np.abs(ma - mb).max()))
        reference = "self-convergence: |x(h) - x(h/2)| at T (no constrained reference)"
    else:
        gT, muT = (a[0] for a in eq.reference(g0, mu0, [T], rtol=REFERENCE_RTOL, u_rows=U,
                                              u_h=h))
        reference = f"DOP853 rtol=atol={REFERENCE_RTOL:g}"

        def error_at(k):            # error at T of the run with step h / 2^k
            g, mu = final(k)
            return float(max(np.abs(g - gT).max(), np.abs(mu - muT).max()))

    errs = [error_at(k) for k in range(3)]
    return {"expected": expected, "why": why, "horizon": T, "h": [h, h / 2, h / 4],
            "error": errs, "observed": _slopes(errs), "floor": bool(errs[-1] < FLOOR),
            "reference": reference, **_refine(errs, expected, error_at, h, n_o)}
