"""The N-link chain's step by parts: the C runtime's static functions of a compiled module
(residual, F and J, the sparse LU, the solves, update, predictor) timed one by one, then
whole runs with full and simplified Newton, in a C program that includes the module's
kernels.c (static functions are not exported, so ctypes cannot call them).

    PYTHONPATH=. python benchmarks/chain_step_parts.py [--n 8 64] [--frames pin|centre]
        [--tableau split2] [--model FILE --u 0.15 --param grav=5]   (N >= 3: a sparse J)

Each N: examples/pendulum_chain.yaml (``--frames centre``: examples/capsule_chain.yaml)
compiled (C, sparse J; ``--tableau``: the model's scheme else, e.g. ``split2``, whose
unknowns are the joints' multipliers only), 50 steps of h = 1e-3 from the
benchmark's start (hpgen.bench.multibody.chain) give the state; the harness (built with the
runtime's flags) then advances 20 more steps and times each part at that state, best of 5
rounds, us per call. ``--model``: another chain model file in the frames' layout; an open one
(forces, inputs, runtime parameters, t) runs with the inputs ``--u`` held and the runtime
parameters ``--param`` (their defaults else), its parts timed at t = 0.05. Read the parts against each other: the machine's load moves them all.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import hpgen
from hpgen.bench.multibody import chain, hpgen_chain
from hpgen.runtime.build import DEFAULT_CFLAGS, include_flags

HARNESS = r"""
#define _POSIX_C_SOURCE 199309L
#include <time.h>
#include "kernels.c"
static double now(void) { struct timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
#define TIME(label, reps, stmt) do { double best = 1e30; int rr, q; for (rr = 0; rr < 5; ++rr) { double t0 = now(); for (q = 0; q < (reps); ++q) { stmt; } double t1 = (now() - t0) / (reps); if (t1 < best) best = t1; } printf("%-28s %9.2f us\n", label, best * 1e6); } while (0)
static hpgen_run R;
int main(int argc, char** argv) {
    static double g[HPGEN_NN], p[HPGEN_D], z[HPGEN_NZ], F[HPGEN_NZ], A[HPGEN_LU_SIZE], A2[HPGEN_LU_SIZE], b[HPGEN_NZ];
    static double g1[HPGEN_NN], p1[HPGEN_D], G[HPGEN_NZ], m[1];
    static double grec[HPGEN_NN * 2], prec[HPGEN_D * 2];
    int piv[HPGEN_NZ];
#if HPGEN_OPEN
    static double hv[HPGEN_H];      /* [h, t, u, params]: from the state file */
#else
    double hv[1] = {1e-3};
#endif
    hpgen_options o = {1e-14, 50, 0, 1}, os_ = {1e-14, 50, 1, 1};
    hpgen_status st;
    FILE* f = fopen(argv[1], "rb");
    long long steps = 2000, n;
    if (!f || fread(g, 8, HPGEN_NN, f) != HPGEN_NN || fread(p, 8, HPGEN_D, f) != HPGEN_D) return 1;
#if HPGEN_OPEN
    if (fread(hv, 8, HPGEN_H, f) != HPGEN_H) return 1;
#endif
    fclose(f);
    hpgen_predictor_base(g, p, hv, z);
    hpgen_run_init(&R, g, p, z);
#if HPGEN_OPEN
    hpgen_run_set_inputs(&R, hv[1], hv + 2, 1, hv + 2 + HPGEN_M);
#endif
    hpgen_advance(&R, 1e-3, 20, 1000, &o, grec, prec, &st);
    memcpy(g, R.g, sizeof g); memcpy(p, R.p, sizeof p); memcpy(z, R.z, sizeof z);
    printf("N=%d nz=%d NJ=%d NLU=%d\n", HPGEN_N / 4, HPGEN_NZ, HPGEN_SP_NJ, HPGEN_SP_NLU);
    TIME("residual", 2000, hpgen_k_residual(z, g, p, hv, F));
    TIME("residual_jacobian_nz", 300, hpgen_k_residual_jacobian_nz(z, g, p, hv, F, A + HPGEN_J_OFFSET));
    memcpy(A2, A, sizeof A);
    TIME("slu_factor", 2000, hpgen_slu_factor(A2 + HPGEN_J_OFFSET, A2));
    TIME("lu_factor_solve", 2000, (memcpy(b, F, sizeof b), hpgen_lu_factor_solve(A2, piv, b, 1)));
    TIME("lu_apply", 5000, (memcpy(b, F, sizeof b), hpgen_lu_apply(A2, piv, b)));
    TIME("update", 2000, hpgen_k_update(z, g, p, hv, g1, p1));
#ifdef HPGEN_UPDATE_NZ_VARIANT
    TIME("update_nz", 2000, hpgen_k_update_nz(z, g, p, hv, g1, p1));
#endif
    TIME("update_p", 2000, hpgen_k_update_p(z, g, p, hv, p1));
    TIME("predictor_base", 2000, hpgen_predictor_base(g, p, hv, G));
    TIME("margin", 5000, hpgen_k_margin(z, hv, m));
    for (n = 0; n < 2; ++n) {
        double t0 = now();
        hpgen_advance(&R, 1e-3, steps, steps, &o, grec, prec, &st);
        printf("advance full      %9.2f us/step it %.2f J %.2f\n", (now() - t0) / steps * 1e6, (double)st.total_iterations / steps, (double)st.jacobians / steps);
        t0 = now();
        hpgen_advance(&R, 1e-3, steps, steps, &os_, grec, prec, &st);
        printf("advance simplified%9.2f us/step it %.2f J %.2f\n", (now() - t0) / steps * 1e6, (double)st.total_iterations / steps, (double)st.jacobians / steps);
    }
    if (argc > 2) { FILE* fo = fopen(argv[2], "wb"); fwrite(R.g, 8, HPGEN_NN, fo); fwrite(R.p, 8, HPGEN_D, fo); fwrite(R.z, 8, HPGEN_NZ, fo); fclose(fo); }
    return 0;
}
"""


def write_state(model, n: int, work: Path, frames: str = "pin", tableau=None, u=(),
                params=None):
    """The model compiled at N = n, and the path of the state (g column-major, mu; float64;
    an open model's step vector [h, t, u, params] after them) after 50 steps of h = 1e-3
    from the benchmark's start, written into ``work``."""
    integ = hpgen.compile(model, parameters={"N": n}, tableau=tableau)
    spec = chain.ChainSpec(n)
    qpos, qvel = chain.initial_joint_state(spec)
    g0, xi0 = hpgen_chain.to_hpgen(spec, chain.from_joint(spec, qpos, qvel), frames)
    lay = integ.meta.get("open")
    kw = {} if lay is None else {"u": list(u) or None, "params": params or None}
    tr = integ.simulate(g0, 1e-3, 50, xi0=xi0, every=50, **kw)
    state = work / f"state{n}.bin"
    hv = [] if lay is None else [1e-3, 0.05, *u, *[
        (params or {}).get(name, d) for (name, _), d in zip(lay["runtime_parameters"],
                                                            lay["defaults"])]]
    np.concatenate([np.asarray(tr.g[-1]).ravel(order="F"), np.asarray(tr.mu[-1]),
                    np.asarray(hv, dtype=float)]).tofile(state)
    return integ, state


def run(n: int, work: Path, frames: str = "pin", tableau=None, model=None, u=(),
        params=None) -> str:
    integ, state = write_state(model or hpgen_chain.MODELS[frames], n, work, frames, tableau,
                               u, params)
    module = Path(integ.engine.backend.lib._name).parent
    src, exe = work / "parts.c", work / f"parts{n}"
    src.write_text(HARNESS)
    flags = [f for f in DEFAULT_CFLAGS if f != "-shared"]
    out = []
    for chord in (1, 0):
        subprocess.run([os.environ.get("CC", "cc"), *flags, *include_flags(), "-I", str(module),
                        f"-DHPGEN_SPARSE_CHORD={chord}", str(src), "-o", f"{exe}-{chord}",
                        "-lm"], check=True)
    for rnd in range(2):                # the two builds interleaved
        for chord in (1, 0):
            text = subprocess.run([f"{exe}-{chord}", str(state)], check=True,
                                  capture_output=True, text=True).stdout
            label = "chord (J once a step)" if chord else "J at every iterate"
            out.append(f"-- {label}, round {rnd + 1}\n" + text)
    return "".join(out)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 64])
    ap.add_argument("--frames", choices=sorted(hpgen_chain.MODELS), default="pin")
    ap.add_argument("--tableau", default=None, help="default: the model file's")
    ap.add_argument("--model", default=None, help="default: the frames' chain example")
    ap.add_argument("--u", type=float, nargs="*", default=[], help="an open model's inputs")
    ap.add_argument("--param", nargs="*", default=[], metavar="NAME=VALUE",
                    help="an open model's runtime parameters (default: their defaults)")
    a = ap.parse_args()
    params = {k: float(v) for k, v in (q.split("=", 1) for q in a.param)}
    print(f"hpgen from {hpgen.__file__}")
    with tempfile.TemporaryDirectory() as tmp:
        for n in a.n:
            sys.stdout.write(run(n, Path(tmp), a.frames, a.tableau, a.model, a.u, params))
            sys.stdout.flush()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
