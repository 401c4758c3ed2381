"""Work-precision benchmark: hpgen's schemes against the integrators a user would
pick instead (SciPy DOP853 / RK45, CasADi cvodes and Gauss-Legendre collocation, classical
RK4 in NumPy and the same RK4 emitted as C), on a model's scene, in one process.

    hpgen bench examples/heavy_top.yaml --T 10 --out bench-heavy_top
    from hpgen.bench import run_bench; res = run_bench("examples/heavy_top.yaml", T=10)

Modules: problem (the scene as y' = f(y) on y = (g row-major, mu), reference, figures),
crk4 (+ rk4.c.j2: the C RK4), schemes (hpgen's points), peers (the others), measure (timing
rule, Point), report (CSV / Markdown / PNG, equal-error comparisons), core (run_bench),
cli (the ``hpgen bench`` subcommand). Importing this package is cheap: numpy, scipy and
casadi load when run_bench runs.
"""
from __future__ import annotations

__all__ = ["run_bench"]


def run_bench(model, **options):
    """See :func:`hpgen.bench.core.run_bench`."""
    from .core import run_bench as _run
    return _run(model, **options)
