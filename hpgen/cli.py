"""hpgen: compile, run, sweep, check and benchmark variational integrators.

Exit status: 0 success; 2 bad input (ModelError, ArgumentError; usage errors); 1 any other
hpgen failure (BuildError; a failed step of ``hpgen run``: ConvergenceError, DomainError,
RecordError, the samples before it saved with partial=True); 3 a failed ``hpgen check``; 130 /
143 ``hpgen run`` interrupted by SIGINT / SIGTERM (the completed chunks saved with partial=True
and kept for ``--resume``). Errors are one line on stderr, never a traceback.
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path

from . import __version__
from .cli_interrupts import failed, interrupted, resume_command, sigterm_raises
from .errors import ArgumentError, ConvergenceError, HpgenError, ModelError


def _add_options(p):
    p.add_argument("model", help="model file (YAML, schema version 1)")
    from .schemes import BACKEND, RKMK, TAU
    p.add_argument("--tableau", help="catalog name or splitting scheme (see `hpgen list`); default: the model's")
    p.add_argument("--tau", choices=TAU.names, help=TAU.help("default: the model's"))
    p.add_argument("--rkmk", choices=RKMK.names, help=RKMK.help("default: the model's"))
    p.add_argument("--backend", choices=BACKEND.names, default="c",
                   help=BACKEND.help("default: c"))
    p.add_argument("--cache-dir", help="build cache directory (default $XDG_CACHE_HOME/hpgen, "
                   "else ~/.cache/hpgen)")


def _add_compose(p):
    from .tableaus.composition import COMPOSITION_NAMES
    p.add_argument("--compose", choices=COMPOSITION_NAMES,
                   help="compose the symmetric step into a higher-order step (see `hpgen "
                   "list`; the same compiled kernels); default: the model's")


def _add_u_options(p):
    """--u and --u-interpolation: the control inputs of a model with ``inputs:``, given on
    the command line (they replace the scene's u; hpgen.model.controls)."""
    p.add_argument("--u", nargs="+", metavar="U",
                   help="control inputs (replace scene.u): m numbers (a constant), m entries "
                   "each a number or a quoted expression of t (u_k = u(t_k), held over step "
                   "k), or one .npz / .csv table (one row per step, or with a time column t)")
    p.add_argument("--u-interpolation", choices=("hold", "linear"),
                   help="how a table with a time column gives u(t_k): hold (default, the "
                   "last row at or before t_k) or linear")


def _add_set(p):
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="override a parameter of the model file, e.g. --set N=8 (repeatable)")


def _parser():
    ap = argparse.ArgumentParser(prog="hpgen", description=__doc__.splitlines()[0])
    ap.add_argument("--version", action="version", version=f"hpgen {__version__}")
    sub = ap.add_subparsers(dest="command", required=True)
    c = sub.add_parser("compile", help="generate (and build) the integrator module of a model")
    _add_options(c)
    _add_compose(c)
    _add_set(c)
    c.add_argument("-o", "--out", help="directory receiving <module>/ (default: none, the "
                   "module stays in the build cache, whose path is printed)")
    r = sub.add_parser("run", help="simulate the model's scene, save its records (.npz)")
    _add_options(r)
    _add_compose(r)
    _add_set(r)
    r.add_argument("--out", help="output .npz file (default <model name>.npz)")
    r.add_argument("--h", type=float, help="override scene.h")
    r.add_argument("--steps", type=int, help="override scene.steps")
    r.add_argument("--chunk", type=int, default=1_000_000,
                   help="steps per C call; memory holds one chunk's records, each completed "
                   "chunk is kept on disk in <out>.partial/ until the run ends (default 10^6)")
    r.add_argument("--resume", action="store_true",
                   help="continue the interrupted run kept in <out>.partial/ (the final file "
                   "equals that of an uninterrupted run); without one, start a new run")
    r.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    r.add_argument("--no-plot", action="store_true",
                   help="do not write the PNGs of the run next to --out (see hpgen plot)")
    _add_u_options(r)
    sub.add_parser("list", help="groups, tableaus and chart maps")
    from .analysis.cli import add_parser as _add_check_parser
    _add_check_parser(sub, _add_options, _add_compose, _add_set, _add_u_options)
    from .bench.cli import add_parser as _add_bench_parser, add_recommend_parser
    _add_bench_parser(sub)
    add_recommend_parser(sub)
    from .ensemble.cli import add_parser as _add_sweep_parser
    _add_u_options(_add_sweep_parser(sub, _add_options))
    pl = sub.add_parser("plot", help="PNG figures of a saved run, section run or benchmark",
                        description="PNGs of what the file holds: energy error, momentum "
                        "change, group distance, records (a run), crossings (a section run), "
                        "work-precision (a bench directory)")
    pl.add_argument("file", help=".npz of hpgen run (or Trajectory/Records.save), or the "
                    "output directory of hpgen bench (or its work_precision.csv)")
    pl.add_argument("--out-dir", help="directory for the PNGs (default: next to the file)")
    return ap


def _options(args, out=None):
    from .api import CompileOptions
    return CompileOptions(tableau=args.tableau, tau=args.tau, rkmk=args.rkmk,
                          backend=args.backend, out=out, cache_dir=args.cache_dir,
                          parameters=_overrides(args), compose=getattr(args, "compose", None))


def _overrides(args):
    """The --set NAME=VALUE options as ((name, value), ...), or None."""
    from .model.overrides import parse_assignment
    pairs = dict(parse_assignment(a) for a in getattr(args, "set", None) or ())
    return tuple(pairs.items()) or None


def cmd_compile(args) -> int:
    from .api import build_compiled
    t0 = time.perf_counter()
    compiled = build_compiled(args.model, _options(args, out=args.out))
    path = compiled.module_dir
    where = "" if args.out else " (in the build cache; -o DIR writes the module there)"
    stages = ", ".join(f"{k} {v:.2f} s" for k, v in compiled.timings.items())
    print(f"{path}{where} ({args.backend} backend, {time.perf_counter() - t0:.2f} s"
          + (f": {stages})" if stages else ")"))
    print(_scheme_line(path, args))
    return 0


def _load_model(file, overrides=None):
    from .api import read_model_text
    from .model import load_model_text
    from .model.overrides import apply_overrides
    text = apply_overrides(read_model_text(file), dict(overrides or ()), file=file)
    return load_model_text(text, filename=file)


def _scheme_line(module_dir, args) -> str:
    """The scheme a compile used (meta.json options) and where each part came from: an
    option, the model's ``integrator:`` section, or hpgen's default (the model file's YAML
    only is read: a cache hit imports no compile-time stack)."""
    import json
    from .api import read_model_text
    from .model.yamldoc import compose_document
    meta = json.loads((Path(module_dir) / "meta.json").read_text())
    o = meta["options"]
    section = compose_document(read_model_text(args.model), args.model).data.get("integrator")
    section = section if isinstance(section, dict) else {}
    parts = ("tableau", "tau", "rkmk")
    given = [f"--{k}" for k in parts if getattr(args, k) is not None]
    model = [k for k in parts if getattr(args, k) is None and k in section]
    default = [k for k in parts if getattr(args, k) is None and k not in section]
    src = ([f"{', '.join(given)} given"] if given else []) + \
        ([f"{', '.join(model)} from the model's integrator:"] if model else []) + \
        ([f"{', '.join(default)}: hpgen's default"] if default else [])
    from .schemes import is_splitting
    explicit = meta.get("explicit") is True
    if is_splitting(o["tableau"]) and explicit:  # an explicit composition: no chart, no RKMK
        return f"scheme: splitting {o['tableau']} (explicit; tau and rkmk unused)"
    if is_splitting(o["tableau"]):     # constrained: Newton on the joints' multipliers
        src.insert(0, "constrained: the joints' multipliers solved by Newton")
    compose = getattr(args, "compose", None) or section.get("compose")
    if compose is not None:
        from .tableaus.composition import check_base, get_composition
        c = get_composition(compose)
        check_base(o["tableau"], rkmk=o["rkmk"], step_uses_g=meta["step_uses_g"],
                   explicit=explicit)
        src.append(f"composed {c.name}: {c.stages} substeps, order {c.order}"
                   f"{' (--compose)' if getattr(args, 'compose', None) else ' (the model)'}")
    return (f"scheme: tableau {o['tableau']}, tau {o['tau']}, rkmk {o['rkmk']} "
            f"({'; '.join(src)})")


def cmd_run(args) -> int:
    from .api import build_module
    from .runtime import load
    from .runtime.chunked_output import record_to_npz

    model = _load_model(args.model, _overrides(args))
    if model.scene is None:
        raise ModelError("the model has no scene section to run", file=args.model, field="scene")
    sc = model.scene
    h = sc.h if args.h is None else args.h
    steps = sc.steps if args.steps is None else args.steps
    from .model.controls import controls_for
    controls = controls_for(model, args.u, args.u_interpolation, args.model)
    u = None if controls is None else controls.rows(h, steps)
    module_dir = build_module(args.model, _options(args))
    try:
        integ = load(module_dir, backend=args.backend,
                     compose=args.compose or model.integrator.compose)
    except ModelError as e:
        if e.field != "integrator.compose":
            raise
        raise ModelError(e.message, file=args.model, field=e.field) from None
    print(_scheme_line(module_dir, args))
    if sc.projection is not None:
        print(f"  {sc.projection.note}")
    out = Path(args.out or f"{model.name}.npz")
    if sc.section is not None or sc.section_every_t is not None:
        return _run_sections(integ, model, sc, h, steps, out, args, u)
    directions = None
    if "momentum" in integ.record_names:
        from .analysis.symmetry import conserved_directions
        directions = conserved_directions(model, g0=sc.g0)
    t0 = time.perf_counter()
    try:
        with sigterm_raises():
            path, summary = record_to_npz(integ, out, g0=sc.g0, h=h, steps=steps, xi0=sc.xi0,
                                          mu0=sc.mu0, every=sc.every, chunk=args.chunk,
                                          resume=args.resume, resume_hint=resume_command(args),
                                          directions=directions, u=u,
                                          progress=False if args.no_progress else None)
    except ConvergenceError as e:
        _print_counters(getattr(e, "counts", {}))        # the failed run's, as on success
        return failed(e, "samples")
    wall = time.perf_counter() - t0
    for old in summary["removed"]:
        print(f"removed {old}/: the memory maps of a run of {out} killed under an older hpgen "
              "(not resumable)")
    ran = steps - summary["resumed_at"]
    resumed = (f" (resumed at step {summary['resumed_at']})" if summary["resumed_at"] else "")
    print(f"{model.name}: {ran} steps of h = {h:g} in {wall:.3f} s "
          f"({wall / max(ran, 1) * 1e6:.2f} us/step, {args.backend}){resumed}; "
          f"{summary['samples']} samples -> {path}")
    if model.forced:                     # energy and momentum change: not conservation errors
        print(_forced_line(summary))
    elif summary["energy_max_change"] is not None:
        print(f"  energy error max |E - E0| = {float(summary['energy_max_change']):.3e}")
    if summary["momentum_max_change"] is not None and not model.forced:
        print(_momentum_line(model, summary["momentum_max_change"], directions,
                             summary["conserved_max_change"]))
    _print_counters(summary)
    _plot_run(path, args, integ)
    return 0


def _print_counters(counts):
    """A run's counters ({name: total}, hpgen.runtime.counters; a failed or interrupted
    run's too): the steps the wrong-root guard solved again (numerics.md sec. 8), if any."""
    n = counts.get("guarded", 0)
    if n:
        print(f"  {n} step{'s' if n != 1 else ''} re-solved by the wrong-root guard (its "
              "root jumped away from the predictor's offsets)")


def _plot_run(path, args, integ=None):
    """The PNGs of a finished run next to it (hpgen.plot), unless --no-plot; a plotting
    failure (matplotlib missing) is a note, the run's result stands."""
    if args.no_plot:
        return
    from .plot import plot_file
    try:
        files = plot_file(path, integrator=integ)
    except HpgenError as e:
        print(f"hpgen: note: no figures ({e})", file=sys.stderr)
        return
    print("  figures: " + ", ".join(str(f) for f in files))


def cmd_plot(args) -> int:
    """``hpgen plot FILE``: write the PNGs (hpgen.plot) and print their paths."""
    from .plot import plot_file
    for f in plot_file(args.file, out_dir=args.out_dir):
        print(f)
    return 0


def _forced_line(summary) -> str:
    """A forced model's energy figure: the energy-work balance E - W (docs/numerics.md sec.
    13) when the scene records energy and work; else what to record for it."""
    if summary.get("balance_max_change") is not None:
        return ("  energy-work balance max |(E - W) - E0| = "
                f"{float(summary['balance_max_change']):.3e} (forces: E alone is not conserved)")
    return ("  forces: energy is not conserved; record energy and work for the energy-work "
            "balance E - W")


def _momentum_line(model, change, directions, conserved_change) -> str:
    """Only the spatial momenta the model's symmetry conserves (its Lagrangian's and, if any,
    its constraints') are conservation figures (hpgen.analysis.symmetry decides them from
    the model)."""
    from .analysis.symmetry import describe
    head = "  spatial momentum J = Ad*_{g^-1} p"
    if not len(directions):
        return (f"{head}: nothing conserved (l is invariant under no left translation); "
                "no conservation figure")
    if len(directions) == len(change):
        return (f"{head}, conserved (l is left-invariant), max change per component: "
                + " ".join(f"{v:.2e}" for v in change))
    what = "the symmetry of l and the constraints" if model.constraints else "l's symmetry"
    return (f"{head}: {what} conserves only "
            + ", ".join(f"{q} (max change {v:.2e})"
                        for q, v in zip(describe(directions), conserved_change)))


def _run_sections(integ, model, sc, h, steps, out, args, u=None) -> int:
    """``hpgen run`` of a scene with a ``section``: only the crossings are kept (t, g, mu,
    step; see hpgen.runtime.trajectory.SectionCrossings), saved like a trajectory."""
    from .runtime import counters
    from .runtime.trajectory import npz_path, run_metadata, write_npz
    def save(cr, error):
        write_npz(path, {"t": cr.t, "g": cr.g, "mu": cr.mu, "step": cr.step,
                         **run_metadata(integ, h, 1, error is not None, counters.of(cr),
                                        error)})

    t0 = time.perf_counter()
    path = npz_path(out)
    try:
        with sigterm_raises():
            cr = integ.sections(g0=sc.g0, h=h, steps=steps, xi0=sc.xi0, mu0=sc.mu0,
                                chunk=args.chunk, every_t=sc.section_every_t, u=u)
    except ConvergenceError as e:
        cr = e.partial
        if cr is None:
            raise
        save(cr, e)
        e.saved = (path, len(cr))
        _print_counters(counters.of(cr))
        return failed(e, "section crossings")
    wall = time.perf_counter() - t0
    save(cr, None)
    print(f"{model.name}: {steps} steps of h = {h:g} in {wall:.3f} s "
          f"({wall / max(steps, 1) * 1e6:.2f} us/step, {args.backend}); "
          + (f"{len(cr)} crossings of the section {sc.section.text!r}" if sc.section else
             f"{len(cr)} samples of the section every_t = {sc.section_every_t:g}")
          + f" -> {path}")
    _print_counters(counters.of(cr))
    _plot_run(path, args)
    return 0


def cmd_list(args) -> int:
    """``hpgen list``: the groups and every registered option value (hpgen.schemes)."""
    from .groups import GROUP_NAMES
    from .schemes import BACKEND, RKMK, TAU, compositions, splittings, tableaus
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
    print("splitting schemes (explicit; for l = 1/2 xi.M xi - V(g) with constant M on SO3, SE3,"
          " SO2, R<n> and products; chosen as the tableau; tau and rkmk unused):")
    for s in splittings():
        print(f"  {s.name:17s} stages {s.stages:2d}  order {s.order}  {s.summary}")
    print("compositions (integrator.compose / --compose: S(gamma_s h) o ... o S(gamma_1 h) of "
          "a symmetric step: a symmetric tableau with rkmk truncated, stormer-verlet when the step "
          "reads g; the order with an order-2 step):")
    for c in compositions():
        print(f"  {c.name:17s} stages {c.stages:2d}  order {c.order}  {c.summary}")
    return 0


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else [str(a) for a in argv]
    args = _parser().parse_args(argv)
    args.argv = argv
    try:
        if args.command == "bench":
            from .bench.cli import cmd_bench
            return cmd_bench(args)
        if args.command == "recommend":
            from .bench.recommend import cmd_recommend
            return cmd_recommend(args)
        if args.command == "check":
            from .analysis.cli import cmd_check
            return cmd_check(args, _load_model, _overrides(args))
        if args.command == "sweep":
            from .ensemble.cli import cmd_sweep
            return cmd_sweep(args, _options)
        return {"compile": cmd_compile, "run": cmd_run, "list": cmd_list,
                "plot": cmd_plot}[args.command](args)
    except (ModelError, ArgumentError) as e:
        print(f"hpgen: error: {e}", file=sys.stderr)
        return 2
    except HpgenError as e:
        print(f"hpgen: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt as e:
        _print_counters(getattr(e, "counts", {}))      # an interrupted run's committed chunks'
        return interrupted(e)
    except BrokenPipeError:
        # the reader of stdout went away (hpgen list | head): stop quietly, as cat does
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141


if __name__ == "__main__":
    sys.exit(main())
