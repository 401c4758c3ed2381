"""The ``hpgen sweep`` subcommand: parser and command (used by hpgen.cli).

    hpgen sweep model.yaml --grid sweep.yaml [--scheduler tcp://host:8786 | --workers N]
                [--out sweep.zarr] [--resume] [--chunk-size N] [--no-progress] [--u U ...]

A model with control inputs takes u from --u, else the grid file's ``u`` (constant: shared or
one per member), else the scene's u (hpgen.model.controls), shared by the members (one row
per member's step when u depends on t and the members' h differ).

Completed chunks are kept in ``<out>.parts/`` as they complete; an interrupted sweep leaves
them there and ``--resume`` continues from them. The output (.zarr, .nc or .npz) is written
at the end, atomically, and the parts are then removed. Standard library at import.
"""
from __future__ import annotations

import shutil
import sys
import time
from pathlib import Path


def add_parser(sub, add_options):
    """Add ``sweep`` to hpgen's subparsers (``add_options``: the shared compile options)."""
    s = sub.add_parser("sweep", help="many members on local threads or a Dask cluster",
                       description="run many members (initial states, steps) of the model "
                       "on local threads or a Dask cluster; save member x time arrays")
    add_options(s)
    s.add_argument("--grid", required=True, help="grid file (YAML: xi0 or mu0 per member, "
                   "optional g0, h, steps, every, record, chunk_size)")
    where = s.add_mutually_exclusive_group()
    where.add_argument("--scheduler", help="address of a Dask scheduler (tcp://host:8786); "
                       "default: local threads")
    where.add_argument("--workers", type=int, help="start a local Dask cluster of this many "
                       "worker processes")
    s.add_argument("--out", help="output file: .zarr, .nc or .npz (default <model>-sweep.npz)")
    s.add_argument("--resume", action="store_true",
                   help="continue an interrupted sweep from the chunks in <out>.parts/")
    s.add_argument("--chunk-size", type=int, help="members per chunk (one Dask task each)")
    s.add_argument("--threads", type=int, help="local threads (default: the CPU count)")
    s.add_argument("--no-progress", action="store_true", help="no progress bar")
    return s


def cmd_sweep(args, compile_options) -> int:
    """Run the sweep of ``args`` (compile_options(args): the CompileOptions)."""
    from ..api import build_module, read_model_text
    from ..errors import ModelError
    from ..model import load_model_text
    from ..runtime import load
    from .grid import read_grid
    from .parts import refuse_if_in_use
    from .result import SUFFIXES
    from .sweep import sweep

    model = load_model_text(read_model_text(args.model), filename=args.model)
    out = Path(args.out or f"{model.name}-sweep.npz")
    if out.suffix not in SUFFIXES:
        raise ModelError(f"expected a file name ending in {', '.join(SUFFIXES)}, got "
                         f"{out.name!r}", field="option out")
    parts = out.with_name(out.name + ".parts")
    refuse_if_in_use(parts)
    if parts.exists() and not args.resume:
        raise ModelError("holds the chunks of an interrupted sweep; pass --resume to continue "
                         "it, or remove it", file=str(parts))
    integ = load(build_module(args.model, compile_options(args)), backend=args.backend)
    kw = read_grid(args.grid, integ.n, integ.d)
    sc = model.scene
    for key, default in (("h", getattr(sc, "h", None)), ("steps", getattr(sc, "steps", None)),
                         ("every", getattr(sc, "every", 1)), ("g0", getattr(sc, "g0", None))):
        if key not in kw and default is not None:
            kw[key] = default
    kw.setdefault("record", list(integ.record_names))
    from ..model.controls import controls_for, member_rows
    controls = None if "u" in kw and args.u is None else \
        controls_for(model, args.u, args.u_interpolation, args.model)
    if args.chunk_size is not None:
        kw["chunk_size"] = args.chunk_size
    for key in ("h", "steps"):
        if key not in kw:
            raise ModelError(f"no {key}: give it in the grid file (the model has no scene)",
                             file=args.grid, field=key)
    if args.u is not None or "u" not in kw:            # --u, else the grid's, else the scene's
        if controls is not None:
            kw["u"] = member_rows(controls, kw["h"], kw["steps"])
    t0 = time.perf_counter()
    progress = False if args.no_progress else None
    try:
        with _client(args) as client:
            res = sweep(integ, client=client, threads=args.threads, progress=progress,
                        checkpoint=parts, **kw)
    except ModelError as e:                 # the grid's values: name the grid file
        raise e.located(file=args.grid) from None
    except KeyboardInterrupt:
        print(f"hpgen: interrupted; the completed chunks are in {parts}/, continue with "
              "--resume", file=sys.stderr)
        raise
    res.save(out)
    shutil.rmtree(parts, ignore_errors=True)
    wall = time.perf_counter() - t0
    failed = int(res.failed.sum())
    where = ("local threads" if args.scheduler is None and args.workers is None else
             f"Dask at {args.scheduler}" if args.scheduler else f"{args.workers} Dask workers")
    print(f"{model.name}: {len(res)} members x {kw['steps']} steps in {wall:.3f} s ({where}); "
          f"{failed} failed -> {out}")
    for i in res.failed.nonzero()[0][:5]:
        print(f"  member {i}: {res.error[i]}")
    guarded = res.guarded.nonzero()[0]
    if len(guarded):
        print(f"  {int(res.guarded.sum())} steps re-solved by the wrong-root guard, in "
              f"{len(guarded)} members (SweepResult.guarded)")
    return 0


class _client:
    """Context manager: a dask Client for --scheduler / --workers, else None."""

    def __init__(self, args):
        self.args, self.stack = args, []

    def __enter__(self):
        from ..errors import ModelError
        a = self.args
        if a.scheduler is None and a.workers is None:
            return None
        try:
            from distributed import Client, LocalCluster
        except ImportError:
            raise ModelError("dask.distributed is not installed; install the scale extra: "
                             "pip install 'hpgen[scale]'", field="option scheduler") from None
        if a.workers is not None:
            if a.workers < 1:
                raise ModelError(f"expected an integer >= 1, got {a.workers}",
                                 field="option workers")
            cluster = LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True,
                                   host="127.0.0.1", dashboard_address=None)
            self.stack.append(cluster)
            client = Client(cluster)
        else:
            try:
                client = Client(a.scheduler, timeout=30)
            except (OSError, ValueError, TypeError) as e:
                raise ModelError(f"cannot connect to the Dask scheduler {a.scheduler!r} "
                                 f"({str(e).splitlines()[0] if str(e) else type(e).__name__})",
                                 field="option scheduler") from None
        self.stack.append(client)
        return client

    def __exit__(self, *exc):
        while self.stack:
            self.stack.pop().close()
        return False
