"""Step times of this tree's C modules against an older commit's, in one process.

    python benchmarks/runtime_ab.py --base /path/to/older/checkout [--rounds 20] [--split]

For a change to the C runtime (hpgen/runtime/c) or the kernels.c template: the older commit
(``--base``, a checkout or git worktree of it) generates its modules (``python -m hpgen
compile -o``, run with that checkout first on the path), this tree generates its own, both
are built by this tree's hpgen.runtime.build (same compiler, the portable DEFAULT_CFLAGS) and
timed through their exported C API (hpgen.abi; ctypes), which does not depend on the Python
run engine: the two must have the same hpgen.abi.ABI_VERSION (checked).

Cases: the heavy top (examples/heavy_top.yaml, R0 = exp((0.3, 0.2, 0)^), Omega0 = (0.2, 1,
3)) with Lie Stormer-Verlet (cay, truncated, h = 0.01, full Newton), Gauss 2 and Gauss 3
(cay, exact, h = 0.05, simplified Newton), each run continued by ``hpgen_advance`` calls of
`steps` steps; and the free rigid body's lane-wise ensemble (256 bodies, random unit
momenta, h = 0.1, full Newton) continued by ``hpgen_advance_batch_lanes`` calls, one thread.
Every round times each library in shuffled order (the best of --repeats calls); printed per
case: ns per (body-)step of each side (the median over rounds) and the ratio new / old of
each round, its minimum and median. Both sides must reach bitwise the same states (checked:
the same code in another layout computes the same doubles).

``--split`` adds a column: this tree's kernels.c compiled as two translation units, the
runtime apart from the kernels (sizes still constant), linked into one library: what a
runtime compiled once and linked into every module would at best cost (the kernels called
out of line; see hpgen.runtime.build.RUNTIME_LINKING).
"""
from __future__ import annotations

import argparse
import ctypes
import json
import os
import random
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import hpgen  # noqa: E402
from hpgen import abi  # noqa: E402
from hpgen.runtime import build as cbuild  # noqa: E402

TOP, BODY = "heavy_top.yaml", "free_rigid_body.yaml"
#: (label, model, compile options, h, steps per call, simplified Newton, ensemble bodies)
CASES = (
    ("SV heavy top", TOP, {"tableau": "stormer-verlet", "tau": "cay", "rkmk": "truncated"},
     0.01, 10000, 0, 0),
    ("Gauss 2 heavy top", TOP, {"tableau": "gauss2", "tau": "cay", "rkmk": "exact"},
     0.05, 1000, 1, 0),
    ("Gauss 3 heavy top", TOP, {"tableau": "gauss3", "tau": "cay", "rkmk": "exact"},
     0.05, 1000, 1, 0),
    ("free body lanes, 256 bodies", BODY, {}, 0.1, 100, 0, 256),
)
P, LL, D = ctypes.c_void_p, ctypes.c_longlong, ctypes.c_double


class _Status(ctypes.Structure):
    _fields_ = [(n, LL if k == "q" else D) for n, k in abi.STATUS_FIELDS]


class _Options(ctypes.Structure):
    _fields_ = [(n, LL if k == "q" else D) for n, k in abi.OPTIONS_FIELDS]


def old_module(base: Path, model: str, opts: dict, out: Path) -> Path:
    """The older commit's module directory for ``model`` (its hpgen compile -o)."""
    args = [sys.executable, "-m", "hpgen", "compile", str(base / "examples" / model),
            "-o", str(out)]
    for k, v in opts.items():
        args += [f"--{k}", v]
    before = set(out.iterdir()) if out.exists() else set()
    subprocess.run(args, cwd=base, env=dict(os.environ, PYTHONPATH=str(base)), check=True,
                   capture_output=True, text=True)
    return next(iter(set(out.iterdir()) - before))


def split_library(module_dir: Path, out: Path) -> Path:
    """module_dir's kernels.c built as two translation units (kernels | runtime), one .so."""
    src = (module_dir / "kernels.c").read_text()
    model = src[:src.index('#include "hpgen_runtime.h"')]
    kernels = re.sub(r"\bstatic (int hpgen_k_|void hpgen_lane_)", r"\1",
                     src.replace('#include "hpgen_runtime.c"', ""))
    protos = re.findall(r"^int hpgen_k_\w+\([^)]*\);$", kernels, re.M)
    protos += [m + ";" for m in re.findall(r"^(?:void hpgen_lane_|HPGEN_EXPORT int "
                                           r"hpgen_kernel_)\w+\([^)]*\)", kernels, re.M)]
    lanes = re.search(r"^#define HPGEN_L \d+$", src, re.M)
    runtime = (model + (lanes.group(0) if lanes else "") + '\n#include "hpgen_runtime.h"\n'
               + "\n".join(protos) + '\n#include "hpgen_runtime.c"\n')
    out.mkdir(parents=True, exist_ok=True)
    (out / "k.c").write_text(kernels)
    (out / "r.c").write_text(runtime)
    flags = [f for f in cbuild.DEFAULT_CFLAGS if f != "-shared"] + ["-fvisibility=hidden"]
    for name in ("k", "r"):
        subprocess.run(["cc", *flags, *cbuild.include_flags(), "-c", str(out / f"{name}.c"),
                        "-o", str(out / f"{name}.o")], check=True)
    lib = out / "split.so"
    subprocess.run(["cc", "-shared", "-o", str(lib), str(out / "k.o"), str(out / "r.o"),
                    *cbuild.LIBS], check=True)
    return lib


class Runs:
    """``bodies`` runs (1: a single run) of one library from the case's initial states:
    p0 = legendre(g0, xi0) (heavy top) or xi0 = velocity_step(g0, mu0, 0) (free body, l
    quadratic), z0 = guess(xi0, g0, p0, h); ``advance()`` continues them by `steps` steps."""

    def __init__(self, lib_path: Path, meta: dict, h, steps, simplified, bodies):
        lib = ctypes.CDLL(str(lib_path))
        dims = (LL * 4)()
        lib.hpgen_dims(dims)
        n, d, nz = meta["n"], meta["d"], meta["nz"]
        if tuple(dims) != (abi.ABI_VERSION, n, d, nz):
            raise SystemExit(f"{lib_path}: ABI/dimensions {tuple(dims)}, this tree has ABI "
                             f"{abi.ABI_VERSION}: the sides cannot share one driver")
        lib.hpgen_run_size.restype = LL
        size = lib.hpgen_run_size()
        self.B, self.h, self.steps, self.lib = max(bodies, 1), h, steps, lib
        self.runs = ctypes.create_string_buffer(size * self.B)
        base = ctypes.addressof(self.runs)
        rng = np.random.default_rng(0)
        hv = np.array([h])
        for b in range(self.B):
            g0 = np.eye(n).ravel(order="F")
            if bodies:
                p0 = rng.normal(size=d)
                p0 /= np.linalg.norm(p0)
                xi0 = self._call("hpgen_kernel_velocity_step", [g0, p0, np.zeros(d)], [d])[0]
            else:
                from scipy.spatial.transform import Rotation
                g0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix().ravel(order="F")
                xi0 = np.array([0.2, 1.0, 3.0])
                p0 = self._call("hpgen_kernel_legendre", [g0, xi0], [d])[0]
            z0 = self._call("hpgen_kernel_guess", [xi0, g0, p0, hv], [nz])[0]
            lib.hpgen_run_init(P(base + b * size), *(a.ctypes.data_as(P) for a in (g0, p0, z0)))
        self.opts = _Options(abi.DEFAULT_TOL, abi.DEFAULT_MAXIT, simplified, 1)
        self.st = (_Status * self.B)()
        self.g_rec, self.p_rec = np.zeros((self.B, n * n)), np.zeros((self.B, d))
        self.bodies = bodies
        self.advance()                      # the first step (scalar code) and a warm-up

    def _call(self, name, ins, outs):
        res = [np.zeros(k) for k in outs]
        fn = getattr(self.lib, name)
        fn.argtypes = [P] * (len(ins) + len(outs))
        fn(*(np.ascontiguousarray(a, dtype=float).ctypes.data_as(P) for a in ins + res))
        return res

    def advance(self):
        g, p = self.g_rec.ctypes.data_as(P), self.p_rec.ctypes.data_as(P)
        o, st = ctypes.byref(self.opts), ctypes.byref(self.st)
        if self.bodies:
            fn = self.lib.hpgen_advance_batch_lanes
            fn.argtypes, fn.restype = [P, LL, D, LL, LL, P, LL, P, P, P], LL
            failed = fn(self.runs, self.B, self.h, self.steps, self.steps, o, 1, g, p, st)
        else:
            fn = self.lib.hpgen_advance
            fn.argtypes, fn.restype = [P, D, LL, LL, P, P, P, P], LL
            failed = fn(self.runs, self.h, self.steps, self.steps, o, g, p, st) != self.steps
        if failed:
            raise SystemExit(f"a run failed: {self.st[0].code}")

    def best(self, repeats: int) -> float:
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            self.advance()
            times.append(time.perf_counter() - t0)
        return min(times)

    def state(self) -> bytes:
        return self.g_rec.tobytes() + self.p_rec.tobytes()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--base", type=Path, required=True, help="checkout of the older commit")
    ap.add_argument("--rounds", type=int, default=20)
    ap.add_argument("--repeats", type=int, default=5, help="calls per round (best taken)")
    ap.add_argument("--split", action="store_true",
                    help="also time this tree's runtime compiled apart from the kernels")
    a = ap.parse_args()
    tmp = Path(tempfile.mkdtemp(prefix="hpgen-runtime-ab-"))
    try:
        rows = []
        for label, model, opts, h, steps, simplified, bodies in CASES:
            old = old_module(a.base.resolve(), model, opts, tmp / "old")
            new = hpgen.build(ROOT / "examples" / model, **opts).module_dir
            libs = {"old": cbuild.build_library(old), "new": cbuild.build_library(new)}
            if a.split:
                libs["split"] = split_library(new, tmp / "split" / new.name)
            meta = json.loads((new / "meta.json").read_text())
            rows.append((label, {k: Runs(lib, meta, h, steps, simplified, bodies)
                                 for k, lib in libs.items()}))
        names = list(rows[0][1])
        times = {(label, k): [] for label, sides in rows for k in sides}
        for _ in range(a.rounds):
            for label, sides in rows:
                order = list(sides)
                random.shuffle(order)
                for k in order:
                    times[(label, k)].append(sides[k].best(a.repeats))
        head = " | ".join(f"{k} ns/step" for k in names)
        ratios = " | ".join(f"{k}/old min, median" for k in names if k != "old")
        print(f"\n| case | {head} | {ratios} | same states |\n|---|"
              + "---|" * (2 * len(names)))
        for label, sides in rows:
            n = sides["old"].steps * sides["old"].B
            cells = [f"{statistics.median(times[(label, k)]) / n * 1e9:.1f}" for k in names]
            for k in names[1:]:
                r = [x / y for x, y in zip(times[(label, k)], times[(label, "old")])]
                cells.append(f"{min(r):.3f}, {statistics.median(r):.3f}")
            same = len({s.state() for s in sides.values()}) == 1
            print(f"| {label} | " + " | ".join(cells) + f" | {'yes' if same else 'NO'} |")
        print(f"\n{a.rounds} rounds, best of {a.repeats} calls each, flags "
              f"{' '.join(cbuild.DEFAULT_CFLAGS)}; old = {a.base}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
