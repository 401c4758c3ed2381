"""The N-link chain's F and J and the static LU of this checkout against another's (same-run
A/B), with the results compared: J's nonzeros (relative to the largest) and the LU's factors.

    PYTHONPATH=. python benchmarks/chain_jacobian_lu.py --base /tmp/base-worktree [--n 8 64]

Each N: examples/pendulum_chain.yaml (--model to change) compiled by this checkout and by the
one at --base (a git worktree of another commit; its own cache key), 50 steps of h = 1e-3 from
the benchmark's start (hpgen.bench.multibody.chain) give (g, p), z the predictor there. A C
harness that includes a module's kernels.c times hpgen_k_residual, the fused F and J
(residual_jacobian_nz) and hpgen_slu_factor (CPU clock, best of 5 rounds, us per call); the
three builds (this module, this module with -DHPGEN_SLU_LOOP: the runtime's loop instead of
the generated factorization, the base module) run alternately, twice.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import hpgen
from hpgen.bench.multibody import hpgen_chain
from hpgen.runtime.build import DEFAULT_CFLAGS, include_flags

sys.path.insert(0, str(Path(__file__).resolve().parent))
from chain_step_parts import write_state  # noqa: E402

HARNESS = r"""
#define _POSIX_C_SOURCE 199309L
#include <time.h>
#include "kernels.c"
static double now(void) { struct timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
#define TIME(label, reps, stmt) do { double best = 1e30; int rr, q; for (rr = 0; rr < 5; ++rr) { double t0 = now(); for (q = 0; q < (reps); ++q) { stmt; } double t1 = (now() - t0) / (reps); if (t1 < best) best = t1; } printf("%-22s %9.2f us\n", label, best * 1e6); } while (0)
int main(int argc, char** argv) {
    static double g[HPGEN_NN], p[HPGEN_D], z[HPGEN_NZ], F[HPGEN_NZ], A[HPGEN_LU_SIZE], A2[HPGEN_LU_SIZE];
    double hv[1] = {1e-3};
    int fail = 0;
    FILE* f = fopen(argv[1], "rb");
    if (!f || fread(g, 8, HPGEN_NN, f) != HPGEN_NN || fread(p, 8, HPGEN_D, f) != HPGEN_D) return 1;
    fclose(f);
    hpgen_predictor_base(g, p, hv, z);
    TIME("residual", 2000, hpgen_k_residual(z, g, p, hv, F));
    TIME("residual_jacobian_nz", 300, hpgen_k_residual_jacobian_nz(z, g, p, hv, F, A + HPGEN_J_OFFSET));
    memcpy(A2, A, sizeof A);
    TIME("slu_factor", 1000, fail = hpgen_slu_factor(A2 + HPGEN_J_OFFSET, A2));
    f = fopen(argv[2], "wb");
    fwrite(A + HPGEN_J_OFFSET, 8, HPGEN_SP_NJ, f);
    fwrite(A2, 8, HPGEN_SP_NLU, f);
    fclose(f);
    return fail;
}
"""

MODULE_DIR = ("import hpgen, sys; from pathlib import Path; "
              "i = hpgen.compile(sys.argv[1], parameters={'N': int(sys.argv[2])}); "
              "print(Path(i.engine.backend.lib._name).parent)")


def module_dir(root: Path | None, model: str, n: int) -> Path:
    """The compiled module's directory, by this checkout (root None) or the one at root."""
    env = dict(os.environ)
    if root is not None:
        env["PYTHONPATH"] = str(root)
    out = subprocess.run([sys.executable, "-c", MODULE_DIR, model, str(n)], env=env,
                         cwd=root, check=True, capture_output=True, text=True).stdout
    return Path(out.strip().splitlines()[-1])


def build(module: Path, src: Path, exe: Path, extra=()) -> None:
    flags = [f for f in DEFAULT_CFLAGS if f != "-shared"]
    subprocess.run([os.environ.get("CC", "cc"), *flags, *include_flags(), "-I", str(module),
                    *extra, str(src), "-o", str(exe), "-lm"], check=True)


def run(n: int, model: str, base: Path, work: Path) -> None:
    _, state = write_state(model, n, work)
    src = work / "harness.c"
    src.write_text(HARNESS)
    this, other = module_dir(None, model, n), module_dir(base, model, n)
    builds = {"this": (this, ()), "this, LU loop": (this, ("-DHPGEN_SLU_LOOP",)),
              "base": (other, ())}
    for k, (mod, extra) in enumerate(builds.values()):
        build(mod, src, work / f"h{n}-{k}", extra)
    out = {}
    for rnd in range(2):
        for k, label in enumerate(builds):
            res = subprocess.run([str(work / f"h{n}-{k}"), str(state), str(work / f"o{n}-{k}")],
                                 capture_output=True, text=True)
            print(f"-- N = {n}, {label}, round {rnd + 1} (pivot failed: {res.returncode})")
            sys.stdout.write(res.stdout)
            out[label] = np.fromfile(work / f"o{n}-{k}")
    nj = len(json.loads((this / "meta.json").read_text())["jacobian"]["row"])
    dj = np.max(np.abs(out["this"][:nj] - out["base"][:nj])) / np.max(np.abs(out["base"][:nj]))
    print(f"N = {n}: max |J - J_base| / max |J_base| = {dj:.2e}")
    lu_gen, lu_loop = out["this"], out["this, LU loop"]
    same = np.array_equal(lu_gen.view(np.uint64), lu_loop.view(np.uint64))
    print(f"N = {n}: generated LU bitwise equal to the loop's: {same}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 64])
    ap.add_argument("--base", type=Path, required=True, help="worktree of the other commit")
    ap.add_argument("--model", default=hpgen_chain.MODEL)
    a = ap.parse_args()
    print(f"hpgen from {hpgen.__file__}; base {a.base}")
    with tempfile.TemporaryDirectory() as tmp:
        for n in a.n:
            run(n, a.model, a.base.resolve(), Path(tmp))
            sys.stdout.flush()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
