"""Regenerate ``hpgen/groups/series_data.py``: exact Taylor coefficients of the series functions.

    python -m hpgen.tools.gen_series            # rewrite the data file
    python -m hpgen.tools.gen_series --check    # exit 1 if the committed file is stale

Each base function f(u) of ``hpgen.groups.series`` is even in u; sympy expands it to
f(u) = sum_k a_k x^k, x = u^2 (series evaluates them at the half angle u = t/2, x = s/4),
and the a_k are written as exact (numerator, denominator) pairs, so the output is
deterministic and independent of the float formatting. The test suite regenerates the
text in memory and compares it with the committed file (tests/unit/test_groups.py), so the
data cannot go stale. sympy is only needed here, never when hpgen compiles a model.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

#: base name -> (sympy expression builder in u, number of coefficients a_0 .. a_{K-1})
#: K is more than the polynomials use (see series.TERMS), so derivatives (k + 1) a_{k + 1}
#: and the accuracy analysis of the truncation have room.
BASES = {
    "cosc": (lambda sp, t: (1 - sp.cos(t)) / t**2, 16),
    "sinc3": (lambda sp, t: (t - sp.sin(t)) / t**3, 16),
}

DATA_PATH = Path(__file__).resolve().parents[1] / "groups" / "series_data.py"

_HEADER = '''"""Exact Taylor coefficients of the series functions (generated, do not edit).

Written by ``python -m hpgen.tools.gen_series`` (sympy). COEFFICIENTS[base][k] = (p, q) means
a_k = p / q in f(u) = sum_k a_k x^k, x = u^2, for the base functions

    cosc = (1 - cos u) / u^2,  sinc3 = (u - sin u) / u^3

(hpgen.groups.series evaluates them at the half angle u = t/2 of the chart argument).
"""

COEFFICIENTS = {
'''


def base_coefficients(name: str) -> tuple[tuple[int, int], ...]:
    """(p, q) with a_k = p/q exactly, k < K, from sympy's series of the even function f(t)."""
    import sympy as sp

    build, kmax = BASES[name]
    t = sp.Symbol("t", positive=True)
    ser = sp.series(build(sp, t), t, 0, 2 * kmax).removeO()
    poly = sp.Poly(sp.expand(ser), t)
    out = []
    for k in range(2 * kmax):
        c = sp.Rational(poly.coeff_monomial(t**k))
        if k % 2:
            if c != 0:
                raise RuntimeError(f"series base {name!r} is not an even function of t")
            continue
        out.append((int(c.p), int(c.q)))
    return tuple(out)


#: allowed truncation tail at t = series.T_MAX, absolute, after multiplying by the largest
#: matrix factor the base reaches (series.WEIGHTS)
TAIL_TOL = 2.0**-54


def required_terms(name: str, t_max: float | None = None, tol: float = TAIL_TOL) -> int:
    """Fewest terms N of the base polynomial series.TERMS[name] with, at the half angle of
    t = t_max (default series.T_MAX), x = t^2/4 and w = series.WEIGHTS[name](t):

        w * sum_{k >= N} |a_k| x^k <= tol               (value, in the matrices)
        w * sum_{k >= N} k |a_k| x^k <= tol             (x d/dx: first derivatives; along a
                                                         unit direction d/dt = (t/2) d/dx,
                                                         and t/2 <= x for t >= 2)

    (exact rational arithmetic on series_data; for t < t_max the tails only shrink)."""
    from fractions import Fraction

    from hpgen.groups import series

    t = series.T_MAX if t_max is None else t_max
    a = series.exact_coefficients(name)
    x = Fraction(t * t / 4)
    w = series.WEIGHTS[name](t)

    def ok(n):
        tail = sum(abs(c) * x**k for k, c in enumerate(a) if k >= n)
        dtail = sum(k * abs(c) * x**k for k, c in enumerate(a) if k >= n)
        return float(tail) * w <= tol and float(dtail) * w <= tol

    n = len(a)
    if not ok(n - 1):
        raise RuntimeError(f"{name}: series_data is too short for t_max = {t}")
    while n > 1 and ok(n - 1):
        n -= 1
    return n


def render() -> str:
    """The full text of series_data.py (deterministic)."""
    lines = [_HEADER]
    for name in BASES:
        lines.append(f"    {name!r}: (\n")
        for p, q in base_coefficients(name):
            lines.append(f"        ({p}, {q}),\n")
        lines.append("    ),\n")
    lines.append("}\n")
    return "".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m hpgen.tools.gen_series", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="only compare with the committed file")
    ap.add_argument("-o", "--out", type=Path, default=DATA_PATH)
    args = ap.parse_args(argv)
    text = render()
    if args.check:
        current = args.out.read_text() if args.out.exists() else ""
        if current != text:
            print(f"{args.out} is stale; run python -m hpgen.tools.gen_series", file=sys.stderr)
            return 1
        return 0
    args.out.write_text(text)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
