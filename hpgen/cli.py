"""Command line: ``hpgen compile``, ``hpgen run``, ``hpgen list``, ``hpgen sweep``.

Exit status: 0 success, 2 bad input (ModelError; usage errors), 1 any other hpgen failure
(BuildError, ConvergenceError). Errors are one line on stderr, never a traceback.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from . import __version__
from .errors import ConvergenceError, HpgenError, ModelError


def _add_options(p):
    p.add_argument("model", help="model file (YAML, schema version 1)")
    from .schemes import BACKEND, RKMK, TAU
    p.add_argument("--tableau", help="catalog name (see `hpgen list`); default: the model's")
    p.add_argument("--tau", choices=TAU.names, help=TAU.help("default: the model's"))
    p.add_argument("--rkmk", choices=RKMK.names, help=RKMK.help("default: the model's"))
    p.add_argument("--backend", choices=BACKEND.names, default="c",
                   help=BACKEND.help("default: c"))
    p.add_argument("--cache-dir", help="build cache directory (default ~/.cache/hpgen)")


def _parser():
    ap = argparse.ArgumentParser(prog="hpgen", description=__doc__.splitlines()[0])
    ap.add_argument("--version", action="version", version=f"hpgen {__version__}")
    sub = ap.add_subparsers(dest="command", required=True)
    c = sub.add_parser("compile", help="generate (and build) the integrator module of a model")
    _add_options(c)
    c.add_argument("-o", "--out", default="generated", help="output directory (default generated/)")
    r = sub.add_parser("run", help="simulate the model's scene and save the recorded samples")
    _add_options(r)
    r.add_argument("--out", help="output .npz file (default <model name>.npz)")
    r.add_argument("--h", type=float, help="override scene.h")
    r.add_argument("--steps", type=int, help="override scene.steps")
    r.add_argument("--chunk", type=int, default=1_000_000,
                   help="steps per C call; memory holds one chunk's records (default 10^6)")
    r.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    sub.add_parser("list", help="groups, tableaus and chart maps")
    k = sub.add_parser("check", help="observed order, energy, momentum map, group and "
                       "symplecticity defects of an integrator on the model's scene",
                       epilog="exit status 3 when a structure check fails")
    _add_options(k)
    k.add_argument("--scheme", choices=("hpgen", "rkmk-rk4"), default="hpgen",
                   help="the compiled scheme (default) or the non-variational RKMK-RK4")
    k.add_argument("--h", type=float, help="override scene.h")
    k.add_argument("--steps", type=int, help="override scene.steps")
    k.add_argument("--order-horizon", type=float,
                   help="time span of the order runs (default min(1, steps h))")
    k.add_argument("--states", type=int, default=4,
                   help="states along the run where the symplecticity defect is computed")
    k.add_argument("--json", help="also write the figures to this JSON file")
    from .bench.cli import add_parser as _add_bench_parser
    _add_bench_parser(sub)
    from .ensemble.cli import add_parser as _add_sweep_parser
    _add_sweep_parser(sub, _add_options)
    return ap


def _options(args, out=None):
    from .api import CompileOptions
    return CompileOptions(tableau=args.tableau, tau=args.tau, rkmk=args.rkmk,
                          backend=args.backend, out=out, cache_dir=args.cache_dir)


def cmd_compile(args) -> int:
    from .api import build_module
    t0 = time.perf_counter()
    path = build_module(args.model, _options(args, out=args.out))
    print(f"{path} ({args.backend} backend, {time.perf_counter() - t0:.2f} s)")
    return 0


def cmd_run(args) -> int:
    from .api import build_module
    from .runtime import load
    from .runtime.recorder import record_to_npz
    from .model import load_model_text
    from .api import read_model_text

    text = read_model_text(args.model)
    model = load_model_text(text, filename=args.model)
    if model.scene is None:
        raise ModelError("the model has no scene section to run", file=args.model, field="scene")
    sc = model.scene
    h = sc.h if args.h is None else args.h
    steps = sc.steps if args.steps is None else args.steps
    integ = load(build_module(args.model, _options(args)), backend=args.backend)
    out = Path(args.out or f"{model.name}.npz")
    if getattr(sc, "section", None) is not None:
        return _run_sections(integ, model, sc, h, steps, out, args)
    t0 = time.perf_counter()
    try:
        path, summary = record_to_npz(integ, out, g0=sc.g0, h=h, steps=steps,
                                      xi0=sc.xi0, mu0=sc.mu0, every=sc.every, chunk=args.chunk,
                                      progress=False if args.no_progress else None)
    except ConvergenceError as e:
        saved = getattr(e, "saved", None)
        if saved is not None and saved[1]:
            raise type(e)(f"{e.reason}; the {saved[1]} samples before the failure were saved "
                          f"to {saved[0]} with partial=True", step=e.step, time=e.time,
                          residual=e.residual, iterations=e.iterations,
                          partial=e.partial) from None
        raise
    wall = time.perf_counter() - t0
    print(f"{model.name}: {steps} steps of h = {h:g} in {wall:.3f} s "
          f"({wall / max(steps, 1) * 1e6:.2f} us/step, {args.backend}); "
          f"{summary['samples']} samples -> {path}")
    if summary["energy_max_change"] is not None:
        print(f"  energy error max |E - E0| = {float(summary['energy_max_change']):.3e}")
    if summary["momentum_max_change"] is not None:
        print("  spatial momentum Ad*_{g^-1} p, max change per component: "
              + " ".join(f"{v:.2e}" for v in summary["momentum_max_change"]))
    return 0


def _run_sections(integ, model, sc, h, steps, out, args) -> int:
    """``hpgen run`` of a scene with a ``section``: only the crossings are kept (t, g, mu,
    step; see hpgen.runtime.trajectory.SectionCrossings), saved like a trajectory."""
    from .runtime.trajectory import npz_path, run_metadata, write_npz
    def save(cr, error):
        write_npz(path, {"t": cr.t, "g": cr.g, "mu": cr.mu, "step": cr.step,
                         **run_metadata(integ, h, 1, error is not None, cr.newton_iterations,
                                        error)})

    t0 = time.perf_counter()
    path = npz_path(out)
    try:
        cr = integ.sections(g0=sc.g0, h=h, steps=steps, xi0=sc.xi0, mu0=sc.mu0,
                            chunk=args.chunk)
    except ConvergenceError as e:
        cr = e.partial
        if cr is None:
            raise
        save(cr, e)
        raise type(e)(f"{e.reason}; the {len(cr)} section crossings before the failure were "
                      f"saved to {path} with partial=True", step=e.step, time=e.time,
                      residual=e.residual, iterations=e.iterations, partial=cr) from None
    wall = time.perf_counter() - t0
    save(cr, None)
    print(f"{model.name}: {steps} steps of h = {h:g} in {wall:.3f} s "
          f"({wall / max(steps, 1) * 1e6:.2f} us/step, {args.backend}); "
          f"{len(cr)} crossings of the section {sc.section.text!r} -> {path}")
    return 0


def cmd_check(args) -> int:
    """``hpgen check``: print the table (hpgen.analysis.check); exit 3 if a check fails."""
    from .analysis.check import format_report, run_check, write_json
    report = run_check(args.model, scheme=args.scheme, tableau=args.tableau, tau=args.tau,
                       rkmk=args.rkmk, h=args.h, steps=args.steps, backend=args.backend,
                       cache_dir=args.cache_dir, order_horizon=args.order_horizon,
                       n_states=args.states)
    print(format_report(report))
    if args.json:
        print(f"  figures -> {write_json(report, args.json)}")
    return 0 if report["passed"] else 3


def cmd_list(args) -> int:
    """``hpgen list``: the groups and every registered option value (hpgen.schemes)."""
    from .groups import GROUP_NAMES
    from .schemes import BACKEND, RKMK, TAU, tableaus
    from .tableaus import tableau_summary
    print("groups: " + ", ".join(GROUP_NAMES) + " and lists of them (direct products)")
    print("tau (chart maps):")
    for c in TAU.entries:
        print(f"  {c.name:15s} {c.summary}; on {c.groups_text}; steps need {c.domain}")
    print("rkmk (RKMK constraints):")
    for r in RKMK.entries:
        print(f"  {r.name:15s} {r.summary}")
    print("backends:")
    for b in BACKEND.entries:
        print(f"  {b.name:15s} {b.summary}")
    print("tableaus:")
    for t in tableaus():
        print(f"  {t.name:15s} stages {t.stages}  order {t.order}  {tableau_summary(t.name)}"
              f"{', symplectic RK' if t.is_symplectic else ''}")
    return 0


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    try:
        if args.command == "bench":
            from .bench.cli import cmd_bench
            return cmd_bench(args)
        if args.command == "sweep":
            from .ensemble.cli import cmd_sweep
            return cmd_sweep(args, _options)
        return {"compile": cmd_compile, "run": cmd_run, "list": cmd_list,
                "check": cmd_check}[args.command](args)
    except ModelError as e:
        print(f"hpgen: error: {e}", file=sys.stderr)
        return 2
    except HpgenError as e:
        print(f"hpgen: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("hpgen: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
