"""The ``hpgen bench`` subcommand: argument parser and command (used by hpgen.cli).

Grid options are comma lists, parsed here and checked by run_bench: a bad value is a
ModelError (one line, exit status 2 from hpgen.cli). Progress goes to stderr, the tables
(Markdown) to stdout. Standard library only at import (hpgen.cli builds every parser).
"""
from __future__ import annotations

import sys


def add_parser(sub):
    """Add ``bench`` to hpgen's subparsers."""
    b = sub.add_parser("bench", help="work-precision benchmark against SciPy, CasADi, RK4",
                       description="work-precision benchmark of hpgen schemes against "
                       "SciPy, CasADi and RK4 (NumPy and C) on the model's scene")
    b.add_argument("model", help="model file with a scene")
    b.add_argument("--T", help="horizon (default scene steps * h)")
    b.add_argument("--tableau", help="comma list of tableaus (default grid: stormer-verlet/"
                   "cay/truncated, gauss2/exp/exact, gauss2/cay/exact, gauss3/cay/exact)")
    b.add_argument("--tau", help="comma list of chart maps (with --tableau/--rkmk: product)")
    b.add_argument("--rkmk", help="comma list of exact, truncated")
    b.add_argument("--h", help="comma list of hpgen steps (default scene h * 2^-k, k = -1..4)")
    b.add_argument("--rk4-h", help="comma list of RK4 steps (default: as --h)")
    b.add_argument("--collocation-h", help="comma list (default scene h * 2^-k, k = 0..2)")
    b.add_argument("--rtol", help="comma list for SciPy DOP853/RK45, atol = 1e-3 rtol "
                   "(default 1e-4,1e-6,...,1e-12)")
    b.add_argument("--cvodes-tol", help="comma list of cvodes reltol (default: as --rtol)")
    b.add_argument("--peers", help="comma list of DOP853, RK45, cvodes-bdf, cvodes-adams, "
                   "collocation, RK4-numpy, RK4-C, splitting-2, splitting-4, splitting-6, RATTLE "
                   "(default all; the last four on rigid bodies only)")
    b.add_argument("--reference", default="auto", help="auto (exact if known, else DOP853 "
                   "rtol = atol = 1e-13), exact, dop853, none")
    b.add_argument("--samples", default="200", help="samples for the energy drift (default 200)")
    b.add_argument("--min-time", default="0.2", help="timing: seconds of repeats (default 0.2)")
    b.add_argument("--out", help="output directory (default bench-<model name>/)")
    b.add_argument("--cache-dir", help="build cache directory (default $XDG_CACHE_HOME/hpgen, "
                   "else ~/.cache/hpgen)")
    b.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    b.add_argument("--u", nargs="+", metavar="U", help="the constant control inputs of a model "
                   "with inputs (m numbers; default: the scene's u)")
    return b


def add_recommend_parser(sub):
    """Add ``recommend`` (hpgen.bench.recommend) to hpgen's subparsers."""
    r = sub.add_parser("recommend", help="the scheme that reaches an error over T fastest",
                       description="rank hpgen's schemes that apply to the model by the "
                       "predicted time to reach --error over --T, from a short measured run")
    r.add_argument("model", help="model file with a scene")
    r.add_argument("--error", required=True, help="target error max(|g - g_ref|, "
                   "|mu - mu_ref|) at T")
    r.add_argument("--T", required=True, help="horizon")
    r.add_argument("--cache-dir", help="build cache directory")
    return r


def _number(text, field, convert=float):
    from ..errors import ModelError
    if text is None:
        return None
    try:
        return convert(text)
    except ValueError:
        raise ModelError(f"expected a number, got {text!r}", field=field) from None


def cmd_bench(args) -> int:
    from .core import parse_list, run_bench
    from .report import comparison_table, md_table
    from ..runtime.progress import bar
    # the stages run_bench reports (compiles, peers), counted by a bar; lines above it
    with bar(None, "bench", "stage", False if args.no_progress else None) as stages:
        def log(line):
            stages.write(line, file=sys.stderr)
            stages.update()
        res = run_bench(
            args.model, T=_number(args.T, "option T"),
            tableau=parse_list(args.tableau, "option tableau", str),
            tau=parse_list(args.tau, "option tau", str),
            rkmk=parse_list(args.rkmk, "option rkmk", str),
            h=parse_list(args.h, "option h"), rk4_h=parse_list(args.rk4_h, "option rk4_h"),
            collocation_h=parse_list(args.collocation_h, "option collocation_h"),
            rtol=parse_list(args.rtol, "option rtol"),
            cvodes_tol=parse_list(args.cvodes_tol, "option cvodes_tol"),
            peers=parse_list(args.peers, "option peers", str), reference=args.reference,
            samples=_number(args.samples, "option samples", int),
            min_time=_number(args.min_time, "option min_time"), out=args.out,
            cache_dir=args.cache_dir, log=log,
            u=None if args.u is None else [_number(x, "option u") for x in args.u])
    print(f"# {res.model_name}, T = {res.T:g}; reference: {res.reference}\n")
    print(md_table(res.points))
    print("\nhpgen against each peer at equal error (peer time / hpgen time, log-log "
          "interpolation on the peer's Pareto front):\n")
    print(comparison_table(res.points))
    for note in res.notes:
        print(f"note: {note}")
    print("\n" + ", ".join(str(f) for f in res.files), file=sys.stdout)
    return 0
