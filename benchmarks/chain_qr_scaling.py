"""How the sparse Newton linear algebra of the N-link pendulum chain grows with N, up to 64
links: the C runtime's factorization (casadi_qr) and solve (casadi_qr_solve) alone, on the
chain's Jacobian pattern, against LAPACK's dense LU (numpy) of the same matrix.

    PYTHONPATH=. python benchmarks/chain_qr_scaling.py [--n 8 16 32 64] [--base 5]

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
Columns: nonzeros of J, of V + R; flops of one QR (4 |v_r| per R_rc above the diagonal);
the fill and flops of the LU with a static order it was chosen over (static_lu_flops);
us per factorization (QR) and per solve with the kept factors (simplified Newton's
iterate); LAPACK dense LU + solve of the nz x nz matrix for comparison; the ratios to the
smallest N.
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

from hpgen.api import CompileOptions, derive_module, read_model_text
from hpgen.model.overrides import apply_overrides

MODEL = str(Path(__file__).resolve().parent.parent / "examples" / "pendulum_chain.yaml")
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


def static_lu_flops(M: np.ndarray) -> tuple[int, int]:
    """(flops, nnz(L + U)) of the peer the QR was chosen over: an LU without run-time
    pivoting on an order fixed at compile time, Markowitz's (the pivot of least
    (|L col| |U row|), ties by index) on the structure with fill, where a variable with a
    structurally zero diagonal (a multiplier) is a pivot only once all its neighbours are
    eliminated (the Schur complement on it is then the full -C A^-1 B). Flops: 2 |L col|
    |U row| + |L col| per pivot."""
    n = M.shape[0]
    rows = [set(np.flatnonzero(M[i]).tolist()) for i in range(n)]
    cols = [set(np.flatnonzero(M[:, j]).tolist()) for j in range(n)]
    waits = {k: (rows[k] | cols[k]) - {k} for k in range(n) if not M[k, k]}
    alive, flops, nnz = set(range(n)), 0, 0
    while alive:
        ready = [k for k in alive if k in rows[k] and not (waits.get(k, set()) & alive)]
        k = min(ready, key=lambda v: ((len(rows[v]) - 1) * (len(cols[v]) - 1), v))
        L, U = cols[k] - {k}, rows[k] - {k}
        flops += 2 * len(L) * len(U) + len(L)
        nnz += len(L) + len(U) + 1
        for i in L:
            rows[i] |= U
            rows[i].discard(k)
        for j in U:
            cols[j] |= L
            cols[j].discard(k)
        alive.discard(k)
    return flops, nnz


def qr_library(tmp: Path) -> ctypes.CDLL:
    """casadi_qr and casadi_qr_solve as CasADi's code generator writes them (a Linsol "qr"),
    compiled with -O3; symbols bench_qr, bench_qr_solve."""
    sp = ca.Sparsity.banded(4, 1)
    A, b = ca.MX.sym("A", sp), ca.MX.sym("b", 4)
    cg = ca.CodeGenerator("qrbench", {"with_header": False, "prefix": "bench",
                                      "casadi_int": "long long int"})
    cg.add(ca.Function("aux", [A, b], [ca.solve(A, b, "qr")]))
    src = tmp / "qrbench.c"
    src.write_text(cg.dump())
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


def measure(lib, M: np.ndarray, rng) -> dict:
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
    solve_args = (ptr(x), ctypes.c_longlong(1), ctypes.c_longlong(0), ptr(sv), ptr(V), ptr(sr),
                  ptr(R), ptr(beta), ptr(pri), ptr(pcc), ptr(w))
    lib.bench_qr(*qr_args)
    dense = np.zeros((nz, nz))
    dense[np.asarray(sp.row()), np.asarray(sp.get_col())] = vals
    b0 = x.copy()
    lib.bench_qr_solve(*solve_args)
    err = np.abs(dense @ x - b0).max() / np.abs(b0).max()
    reps = max(20, int(2e5 / nz))
    t_qr = best_of(lambda: lib.bench_qr(*qr_args), reps)
    t_solve = best_of(lambda: lib.bench_qr_solve(*solve_args), reps)
    t_lapack = best_of(lambda: np.linalg.solve(dense, b0), max(3, reps // 50))
    vcol, rci, rr = np.diff(spv.colind()), spr.colind(), spr.row()
    flops = int(sum(4 * vcol[rr[k]] for c in range(nz) for k in range(rci[c], rci[c + 1])
                    if rr[k] < c))
    lu_flops, lu_nnz = static_lu_flops(M)
    return {"nz": nz, "nnz_j": sp.nnz(), "nnz_vr": spv.nnz() + spr.nnz(), "flops": flops,
            "lu_flops": lu_flops, "lu_nnz": lu_nnz,
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
        print("| N | nz | nnz J | nnz V+R | QR flops | static LU: nnz L+U, flops | QR us | "
              "solve us | LAPACK LU+solve us | QR / QR(N0) | solve / solve(N0) | |J x - b|/|b| |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
        first = None
        for n in a.n:
            r = measure(lib, extrapolated_pattern(base, a.base, n), rng)
            first = first or r
            print(f"| {n} | {r['nz']} | {r['nnz_j']} | {r['nnz_vr']} | {r['flops']} | "
                  f"{r['lu_nnz']}, {r['lu_flops']} | {r['qr_us']:.1f} | {r['solve_us']:.2f} | {r['lapack_us']:.0f} | "
                  f"{r['qr_us'] / first['qr_us']:.2f} | {r['solve_us'] / first['solve_us']:.2f} "
                  f"| {r['residual']:.1e} |", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
