"""Cold compile of the pendulum chain by stage: derive, emit, write, C compiler (cc).

Each compile runs in a fresh Python process with an empty build cache (nothing cached,
nothing imported beforehand), through ``hpgen.build`` (the path ``hpgen compile`` takes);
``CompiledModule.timings`` gives the stages, the wall time of the call the total.

    PYTHONPATH=. python benchmarks/chain_compile.py --n 8 16 32 64 --tableau stormer-verlet
    PYTHONPATH=. python benchmarks/chain_compile.py --n 8 64 --tableau gauss2
    PYTHONPATH=. python benchmarks/chain_compile.py --n 32 --model examples/pendulum_chain_gravity.yaml
    PYTHONPATH=/other/tree python benchmarks/chain_compile.py ...   # another revision
      (a revision without CompiledModule.timings reports the total only)

Prints one Markdown row per N: the stages in seconds (wall), the CPU time (user + sys) of
the C compiler processes (all translation units, hpgen.codegen.cparts) and of the Python
process during the compile (derive, emit and write: "py CPU"), then the wall and
CPU time of the build the first linearize runs (hpgen.runtime.build.build_lazy_library,
after the compile; "-" for a revision without it), the sizes of kernels.c and (if the
compile wrote it) kernels.py. The machine's load changes the wall
figures: compare revisions in the same session, alternating.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MODEL = ROOT / "examples" / "pendulum_chain.yaml"

CHILD = """
import json, resource, sys, time
import hpgen
print(hpgen.__file__, file=sys.stderr)
ru0 = resource.getrusage(resource.RUSAGE_SELF)
t0 = time.perf_counter()
c = hpgen.build(sys.argv[1], parameters={"N": int(sys.argv[2])}, tableau=sys.argv[3],
                cache_dir=sys.argv[4], backend="c")
total = time.perf_counter() - t0
ru1 = resource.getrusage(resource.RUSAGE_SELF)
py_cpu = ru1.ru_utime + ru1.ru_stime - ru0.ru_utime - ru0.ru_stime
sizes = {}
for name in ("kernels.c", "kernels.py"):
    p = c.module_dir / name
    sizes[name] = p.stat().st_size if p.exists() else 0
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
cc_cpu = ru.ru_utime + ru.ru_stime
lazy = lazy_cpu = None
from hpgen.runtime import build
if hasattr(build, "build_lazy_library") and sys.argv[5] == "lazy":    # the first linearize's build (C compiler only)
    t0 = time.perf_counter()
    build.build_lazy_library(c.module_dir)
    lazy = time.perf_counter() - t0
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    lazy_cpu = ru.ru_utime + ru.ru_stime - cc_cpu
print(json.dumps({"total": total, "py_cpu": py_cpu, "cc_cpu": cc_cpu, "lazy": lazy,
                  "lazy_cpu": lazy_cpu,
                  "timings": dict(getattr(c, "timings", {}) or {}), "sizes": sizes}))
"""


def cold_compile(n: int, tableau: str, lazy: bool = True, model: Path = MODEL) -> dict:
    """The child's result; it runs in the empty cache directory (``-c`` puts the working
    directory first on sys.path) with PYTHONPATH made absolute, so PYTHONPATH alone chooses
    the hpgen it imports."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in
                                        env.get("PYTHONPATH", "").split(os.pathsep) if p)
    with tempfile.TemporaryDirectory(prefix="hpgen-cold-") as cache:
        out = subprocess.run([sys.executable, "-c", CHILD, str(Path(model).resolve()), str(n), tableau, cache,
                              "lazy" if lazy else "-"],
                             capture_output=True, text=True, env=env, cwd=cache)
    if out.returncode != 0:
        raise SystemExit(f"N = {n}: {out.stderr.strip().splitlines()[-1]}")
    return dict(json.loads(out.stdout.strip().splitlines()[-1]),
                hpgen=out.stderr.strip().splitlines()[0])


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--tableau", default="stormer-verlet")
    ap.add_argument("--no-lazy", action="store_true",
                    help="skip the lazily built library's build (its columns read -)")
    ap.add_argument("--model", default=str(MODEL), help="the model file (a chain on G^N)")
    args = ap.parse_args()
    print(f"tableau {args.tableau}, model {Path(args.model).name}")
    print("| N | derive | emit | write | cc | cold total | py CPU | cc CPU | lazy lib | lazy CPU "
          "| kernels.c | kernels.py | hpgen |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in args.n:
        r = cold_compile(n, args.tableau, lazy=not args.no_lazy, model=args.model)
        t = r["timings"]
        cells = [f"{t[k]:.1f} s" if k in t else "-" for k in ("derive", "emit", "write", "cc")]
        kb = [f"{r['sizes'][f] / 1e6:.2f} MB" if r["sizes"][f] else "-"
              for f in ("kernels.c", "kernels.py")]
        lazy = [f"{r[k]:.1f} s" if r.get(k) is not None else "-" for k in ("lazy", "lazy_cpu")]
        print(f"| {n} | " + " | ".join(cells) + f" | {r['total']:.1f} s | {r['py_cpu']:.1f} s | "
              + f"{r['cc_cpu']:.1f} s | "
              + " | ".join(lazy + kb)
              + f" | {Path(r['hpgen']).parent} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
