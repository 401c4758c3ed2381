"""hpgen.sweep scaling: local threads against Dask worker processes, and the Dask overhead.

    PYTHONPATH=. python benchmarks/sweep_scaling.py [--model examples/heavy_top.yaml]
        [--members 32] [--steps 20000] [--repeats 3]

1. Throughput: the same sweep (B members x steps, energy recorded every 1000 steps) on the
   local threads (1 and 2) and on a LocalCluster of 1 and 2 worker processes (1 thread each,
   loopback, chunk_size = B / (4 workers)); best wall time of ``repeats``, speed-ups as ratios
   against the 1-thread local run of the same process.
2. Overhead: B_o members x 10 steps (the stepping costs nothing), on the local threads and on
   Dask with chunk_size 1 (one task per member) and 16: the extra wall time per task and per
   member of the Dask path against the threads path.
The workers build the module once (a warm-up sweep, not timed). The figures printed are what
this machine measured in this run; nothing is asserted.
"""
from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np

import hpgen


def best(fn, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--model", default="examples/heavy_top.yaml")
    ap.add_argument("--members", type=int, default=32)
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--overhead-members", type=int, default=256)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    from distributed import Client, LocalCluster

    integ = hpgen.compile(a.model)
    rng = np.random.default_rng(1)
    xi = np.array([0.2, 1.0, 3.0])[: integ.d]
    W = xi + 0.05 * rng.standard_normal((a.members, integ.d))
    Wo = xi + 0.05 * rng.standard_normal((a.overhead_members, integ.d))
    g0 = np.eye(integ.n)
    kw = dict(g0=g0, xi0=W, h=0.05, steps=a.steps, every=1000, record=["energy"],
              progress=False)
    ko = dict(g0=g0, xi0=Wo, h=0.05, steps=10, every=10, record=["energy"], progress=False)

    rows = []
    t1 = best(lambda: hpgen.sweep(integ, threads=1, **kw), a.repeats)
    rows.append(("local threads", 1, t1))
    rows.append(("local threads", 2, best(lambda: hpgen.sweep(integ, threads=2, **kw),
                                         a.repeats)))
    ref = hpgen.sweep(integ, threads=2, **kw)
    to_local = best(lambda: hpgen.sweep(integ, threads=1, **ko), a.repeats)
    over = {}
    with tempfile.TemporaryDirectory() as cache:
        os.environ["XDG_CACHE_HOME"] = cache          # the workers' own (empty) cache
        for workers in (1, 2):
            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                              host="127.0.0.1", dashboard_address=None) as cl, \
                    Client(cl) as c:
                t0 = time.perf_counter()
                hpgen.sweep(integ, client=c, **{**kw, "xi0": W[:workers], "steps": 10})
                build = time.perf_counter() - t0
                size = max(1, a.members // (4 * workers))
                t = best(lambda: hpgen.sweep(integ, client=c, chunk_size=size, **kw),
                         a.repeats)
                res = hpgen.sweep(integ, client=c, chunk_size=size, **kw)
                assert np.array_equal(res["energy"], ref["energy"])   # bitwise, as tested
                rows.append((f"dask processes (chunk {size}, first sweep {build:.1f} s)",
                             workers, t))
                if workers == 1:
                    for cs in (1, 16):
                        over[cs] = best(lambda: hpgen.sweep(integ, client=c, chunk_size=cs,
                                                            **ko), a.repeats)

    per_step = t1 / (a.members * a.steps)
    print(f"# hpgen sweep scaling: {integ.meta['module']}, {a.members} members x {a.steps} "
          f"steps, {os.cpu_count()} CPUs\n")
    print("| path | workers | wall (s) | speed-up vs 1 local thread |")
    print("|---|---|---|---|")
    for name, w, t in rows:
        print(f"| {name} | {w} | {t:.3f} | {t1 / t:.2f} |")
    print(f"\none step: {per_step * 1e6:.2f} us (local, 1 thread)")
    B = a.overhead_members
    print(f"\n# Dask overhead: {B} members x 10 steps, 1 worker process\n")
    print("| path | wall (s) | extra per task (ms) | extra per member (ms) |")
    print("|---|---|---|---|")
    print(f"| local threads (1) | {to_local:.3f} | - | - |")
    for cs, t in over.items():
        tasks = -(-B // cs)
        print(f"| dask, chunk_size {cs} ({tasks} tasks) | {t:.3f} | "
              f"{(t - to_local) / tasks * 1e3:.2f} | {(t - to_local) / B * 1e3:.3f} |")
    # extra = fixed (scatter of the module, submit, gather) + tasks x per task, from 2 points
    n1, n16 = B, -(-B // 16)
    per_task = ((over[1] - to_local) - (over[16] - to_local)) / (n1 - n16)
    fixed = (over[16] - to_local) - n16 * per_task
    print(f"\nfit: Dask extra = {fixed * 1e3:.0f} ms per sweep + {per_task * 1e3:.2f} ms per "
          "task (client, scheduler and worker on the same cores)")


if __name__ == "__main__":
    main()
