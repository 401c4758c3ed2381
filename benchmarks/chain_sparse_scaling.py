"""How the sparse Newton linear algebra of the N-link pendulum chain grows with N, up to 64
links: the C runtime's factorizations and solves alone (the static LU and CasADi's sparse QR
it falls back to), on the chain's Jacobian pattern, against LAPACK's dense LU (numpy).

    PYTHONPATH=. python benchmarks/chain_sparse_scaling.py [--n 8 16 32 64] [--base 5]

The step's derivation (and the model loader's group size limit) do not reach 64 links yet, so
the pattern is the chain's block pattern extrapolated: the pattern of J for --base links is
derived (examples/pendulum_chain.yaml, unknowns Xi (6 per link), lambda (3 per joint), nu (3
per joint)), and the pattern for N links copies each block (link/joint i, link/joint j) from
the base's first, an interior or the last block row with the same offset j - i. The script
checks the extrapolation against real derivations for N = base + 1 and base + 2 (equal
patterns) before timing. The values are random (a Householder QR's cost does not depend on
them). The QR's symbolic analysis is the one the compiler emits (casadi.Sparsity.qr_sparse
with AMD), its C the one CasADi's code generator writes into kernels.c, compiled here with
the runtime's flags (-O3) and called through ctypes (best of 5 timings of ``reps`` calls).
The static LU (the runtime's first choice) likewise: hpgen_slu_factor / hpgen_slu_solve
taken from hpgen_linalg.c with the compile-time analysis (hpgen.codegen.static_lu).
Columns: nonzeros of J; for the LU and the QR the nonzeros of the factors (L + U, V + R),
flops of one factorization (LU: static_lu.flops; QR: 4 |v_r| per R_rc above the diagonal),
us per factorization and per solve with the kept factors (simplified Newton's iterate);
LAPACK's dense LU + solve of the nz x nz matrix for comparison; the factorizations' time
ratios to the smallest N; the largest relative residual of the solves.
"""
from __future__ import annotations

import argparse
import ctypes
import subprocess
import tempfile
import time
from pathlib import Path

import casadi as ca
import numpy as np

from hpgen.abi import STATIC_PIVOT_TOL
from hpgen.api import CompileOptions, derive_module, read_model_text
from hpgen.codegen.static_lu import flops as lu_flops
from hpgen.codegen.static_lu import static_lu
from hpgen.model.overrides import apply_overrides

ROOT = Path(__file__).resolve().parent.parent
MODEL = str(ROOT / "examples" / "pendulum_chain.yaml")
RUNTIME_LINALG = ROOT / "hpgen" / "runtime" / "c" / "hpgen_linalg.c"
SIZES = {"x": 6, "l": 3, "n": 3}       # unknowns per link (Xi) and per joint (lambda, nu)


def derived_pattern(n: int) -> np.ndarray:
    text = apply_overrides(read_model_text(MODEL), {"N": n}, file=MODEL)
    step = derive_module(MODEL, text, CompileOptions(jacobian="sparse")).step
    sp = step.kernel("jacobian").function.sparsity_out(0)
    M = np.zeros((step.nz, step.nz), dtype=bool)
    M[np.asarray(sp.row()), np.asarray(sp.get_col())] = True
    return M


def offsets(n: int) -> dict:
    """Start of block (kind, i) in z: Xi (6n), lambda (3n), nu (3n)."""
    out, at = {}, 0
    for kind in "xln":
        for i in range(n):
            out[kind, i] = at
            at += SIZES[kind]
    return out


def extrapolated_pattern(base: np.ndarray, nb: int, n: int) -> np.ndarray:
    """The pattern for n links from the base pattern for nb links (see the docstring)."""
    ob, on = offsets(nb), offsets(n)
    nz = sum(SIZES.values()) * n
    M = np.zeros((nz, nz), dtype=bool)
    mid = nb // 2

    def rep(i):
        return 0 if i == 0 else (nb - 1 if i == n - 1 else mid)
    for a in "xln":
        for b in "xln":
            for i in range(n):
                for j in range(max(0, i - 2), min(n, i + 3)):
                    ib = rep(i)
                    jb = ib + (j - i)
                    if not 0 <= jb < nb:
                        continue
                    sub = base[ob[a, ib]:ob[a, ib] + SIZES[a], ob[b, jb]:ob[b, jb] + SIZES[b]]
                    M[on[a, i]:on[a, i] + SIZES[a], on[b, j]:on[b, j] + SIZES[b]] = sub
    return M


def lu_library(tmp: Path, M: np.ndarray, tag: str):
    """(StaticLU, library with bench_lu_factor(J, X), bench_lu_solve(X, b)): the runtime's
    hpgen_slu_factor / hpgen_slu_solve (taken from hpgen_linalg.c) on the compile-time
    analysis of pattern M (hpgen.codegen.static_lu), built like a module (-O3)."""
    n = M.shape[0]
    c_idx, r_idx = np.nonzero(M.T)
    colind = np.searchsorted(c_idx, np.arange(n + 1)).tolist()
    lu = static_lu(n, colind, r_idx.tolist())
    code = RUNTIME_LINALG.read_text()
    code = code[code.index("static int hpgen_slu_factor("):]
    code = code[:code.index("#endif")]
    arrays = "".join(f"static const int hpgen_slu_{name}[] = {{{', '.join(map(str, v))}}};\n"
                     for name, v in (("perm", lu.perm), ("colptr", lu.colptr), ("row", lu.row),
                                     ("diag", lu.diag), ("jmap", lu.jmap)))
    src = tmp / f"lu{tag}.c"
    src.write_text(f"""#include <math.h>
#include <string.h>
#define HPGEN_NZ {n}
#define HPGEN_SP_NJ {len(lu.jmap)}
#define HPGEN_SP_NLU {lu.nnz}
#define HPGEN_STATIC_PIVOT_TOL {STATIC_PIVOT_TOL!r}
{arrays}{code}
int bench_lu_factor(const double* J, double* X) {{ return hpgen_slu_factor(J, X); }}
void bench_lu_solve(const double* X, const double* b0, double* b) {{
    memcpy(b, b0, sizeof(double) * HPGEN_NZ);
    hpgen_slu_solve(X, b);
}}
""")
    lib = tmp / f"lu{tag}.so"
    subprocess.run(["cc", "-std=c99", "-O3", "-fPIC", "-shared", "-o", str(lib), str(src),
                    "-lm"], check=True)
    return lu, ctypes.CDLL(str(lib))


def qr_library(tmp: Path) -> ctypes.CDLL:
    """casadi_qr and casadi_qr_solve as CasADi's code generator writes them (a Linsol "qr"),
    compiled with -O3; symbols bench_qr, bench_qr_solve."""
    sp = ca.Sparsity.banded(4, 1)
    A, b = ca.MX.sym("A", sp), ca.MX.sym("b", 4)
    cg = ca.CodeGenerator("qrbench", {"with_header": False, "prefix": "bench",
                                      "casadi_int": "long long int"})
    cg.add(ca.Function("aux", [A, b], [ca.solve(A, b, "qr")]))
    src = tmp / "qrbench.c"
    src.write_text(cg.dump() + """
#include <string.h>
/* x = J^{-1} b0 with the kept factors (a solve from the same right-hand side every time) */
void bench_qr_solve_from(long long n, const double* b0, double* x, const long long* sv,
                         const double* v, const long long* sr, const double* r,
                         const double* beta, const long long* prinv, const long long* pc,
                         double* w) {
    memcpy(x, b0, sizeof(double) * n);
    casadi_qr_solve(x, 1, 0, sv, v, sr, r, beta, prinv, pc, w);
}
""")
    lib = tmp / "qrbench.so"
    subprocess.run(["cc", "-std=c99", "-O3", "-fPIC", "-shared", "-o", str(lib), str(src), "-lm"],
                   check=True)
    return ctypes.CDLL(str(lib))


def best_of(f, reps, repeats=5) -> float:
    best = np.inf
    for _ in range(repeats):
        t = time.perf_counter()
        for _ in range(reps):
            f()
        best = min(best, (time.perf_counter() - t) / reps)
    return best


def measure(lib, M: np.ndarray, rng, tmp: Path, tag: str) -> dict:
    nz = M.shape[0]
    c_idx, r_idx = np.nonzero(M.T)
    sp = ca.Sparsity.triplet(nz, nz, r_idx.tolist(), c_idx.tolist())
    spv, spr, prinv, pc = sp.qr_sparse(True)
    i64 = lambda v: np.ascontiguousarray(np.asarray(v, dtype=np.int64))  # noqa: E731
    sj, sv, sr, pri, pcc = (i64(s) for s in (sp.compress(), spv.compress(), spr.compress(),
                                              prinv, pc))
    vals = rng.standard_normal(sp.nnz()) + 4.0 * (np.asarray(sp.row()) == np.asarray(
        sp.get_col()))
    V, R, beta = np.zeros(spv.nnz()), np.zeros(spr.nnz()), np.zeros(nz)
    w, x = np.zeros(spv.size1()), rng.standard_normal(nz)
    P = ctypes.c_void_p
    ptr = lambda a: a.ctypes.data_as(P)  # noqa: E731
    qr_args = (ptr(sj), ptr(vals), ptr(w), ptr(sv), ptr(V), ptr(sr), ptr(R), ptr(beta),
               ptr(pri), ptr(pcc))
    b0 = x.copy()
    solve_args = (ctypes.c_longlong(nz), ptr(b0), ptr(x), ptr(sv), ptr(V), ptr(sr), ptr(R),
                  ptr(beta), ptr(pri), ptr(pcc), ptr(w))
    lib.bench_qr(*qr_args)
    dense = np.zeros((nz, nz))
    dense[np.asarray(sp.row()), np.asarray(sp.get_col())] = vals
    lib.bench_qr_solve_from(*solve_args)
    err = np.abs(dense @ x - b0).max() / np.abs(b0).max()
    reps = max(20, int(2e5 / nz))
    t_qr = best_of(lambda: lib.bench_qr(*qr_args), reps)
    t_solve = best_of(lambda: lib.bench_qr_solve_from(*solve_args), reps)
    t_lapack = best_of(lambda: np.linalg.solve(dense, b0), max(3, reps // 50))
    vcol, rci, rr = np.diff(spv.colind()), spr.colind(), spr.row()
    flops = int(sum(4 * vcol[rr[k]] for c in range(nz) for k in range(rci[c], rci[c + 1])
                    if rr[k] < c))
    lu, lulib = lu_library(tmp, M, tag)
    jnz = np.ascontiguousarray(vals)             # J's nonzeros, CCS order, as the kernels'
    X, bl = np.zeros(lu.nnz), b0.copy()
    lu_args = (ptr(jnz), ptr(X))
    assert lulib.bench_lu_factor(*lu_args) == 0
    lus_args = (ptr(X), ptr(b0), ptr(bl))
    lulib.bench_lu_solve(*lus_args)
    err = max(err, np.abs(dense @ bl - b0).max() / np.abs(b0).max())
    t_lu = best_of(lambda: lulib.bench_lu_factor(*lu_args), reps)
    t_lus = best_of(lambda: lulib.bench_lu_solve(*lus_args), reps)
    return {"nz": nz, "nnz_j": sp.nnz(), "nnz_vr": spv.nnz() + spr.nnz(), "flops": flops,
            "lu_flops": lu_flops(lu), "lu_nnz": lu.nnz, "lu_us": t_lu * 1e6,
            "lu_solve_us": t_lus * 1e6,
            "qr_us": t_qr * 1e6, "solve_us": t_solve * 1e6, "lapack_us": t_lapack * 1e6,
            "residual": err}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, nargs="+", default=[8, 16, 32, 64])
    ap.add_argument("--base", type=int, default=5)
    a = ap.parse_args()
    base = derived_pattern(a.base)
    for n in (a.base + 1, a.base + 2):
        same = np.array_equal(extrapolated_pattern(base, a.base, n), derived_pattern(n))
        print(f"extrapolated pattern for N = {n} equals the derived one: {same}")
        if not same:
            return 1
    rng = np.random.default_rng(0)
    with tempfile.TemporaryDirectory() as tmp:
        lib = qr_library(Path(tmp))
        print("| N | nz | nnz J | LU: nnz L+U | flops | factor us | solve us | QR: nnz V+R | "
              "flops | factor us | solve us | LAPACK LU+solve us | LU factor / N0 | "
              "QR factor / N0 | max |J x - b|/|b| |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        first = None
        for n in a.n:
            r = measure(lib, extrapolated_pattern(base, a.base, n), rng, Path(tmp), str(n))
            first = first or r
            print(f"| {n} | {r['nz']} | {r['nnz_j']} | {r['lu_nnz']} | {r['lu_flops']} | "
                  f"{r['lu_us']:.1f} | {r['lu_solve_us']:.2f} | {r['nnz_vr']} | {r['flops']} | "
                  f"{r['qr_us']:.1f} | {r['solve_us']:.2f} | {r['lapack_us']:.0f} | "
                  f"{r['lu_us'] / first['lu_us']:.2f} | {r['qr_us'] / first['qr_us']:.2f} | "
                  f"{r['residual']:.1e} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
