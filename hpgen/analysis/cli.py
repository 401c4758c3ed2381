"""The ``hpgen check`` subcommand: argument parser and command (used by hpgen.cli).

The table of hpgen.analysis.check_report on stdout; exit status 0 when every structure check
that applies passes, 3 when one fails (ModelError / ArgumentError: one line, exit 2 from
hpgen.cli). Standard library only at import (hpgen.cli builds every parser).
"""
from __future__ import annotations


def add_parser(sub, add_options, add_compose, add_set, add_u_options):
    """The ``check`` subparser of ``sub``, with hpgen.cli's shared option groups."""
    k = sub.add_parser("check", help="order, energy, momentum, group, symplecticity checks",
                       description="observed order, energy, momentum map, group and "
                       "symplecticity defects of an integrator on the model's scene",
                       epilog="exit status 3 when a structure check fails")
    add_options(k)
    add_compose(k)
    add_set(k)
    k.add_argument("--scheme", choices=("hpgen", "rkmk-rk4"), default="hpgen",
                   help="the compiled scheme (default) or the non-variational RKMK-RK4")
    k.add_argument("--h", type=float, help="override scene.h")
    k.add_argument("--steps", type=int, help="override scene.steps")
    k.add_argument("--order-horizon", type=float,
                   help="time span of the order runs (default min(1, steps h))")
    k.add_argument("--states", type=int, default=4,
                   help="states along the run where the symplecticity defect is computed")
    k.add_argument("--json", help="also write the figures to this JSON file")
    add_u_options(k)
    return k


def cmd_check(args, load_model, overrides) -> int:
    """``hpgen check``: print the table (hpgen.analysis.check); exit 3 if a check fails.
    load_model(file, overrides) and overrides: hpgen.cli's model loading and --set pairs."""
    from ..model.controls import controls_for
    from .check import run_check
    from .check_report import format_report, write_json
    model = load_model(args.model, overrides)
    controls = controls_for(model, args.u, args.u_interpolation, args.model) \
        if model.inputs or args.u else None
    report = run_check(args.model, scheme=args.scheme, tableau=args.tableau, tau=args.tau,
                       rkmk=args.rkmk, h=args.h, steps=args.steps, backend=args.backend,
                       cache_dir=args.cache_dir, order_horizon=args.order_horizon,
                       n_states=args.states, controls=controls, compose=args.compose,
                       parameters=overrides)
    print(format_report(report))
    if args.json:
        print(f"  figures -> {write_json(report, args.json)}")
    return 0 if report["passed"] else 3
