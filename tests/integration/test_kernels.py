"""Generated kernels of the shipped examples (and other option sets) against the CasADi
functions they were generated from, on random inputs; the real generated C compiled with
-Wall -Werror.

Tolerance 1e-12 relative to the output's size: C and the Python printer evaluate the same
instruction list; differences come only from the C compiler's reassociation-free
evaluation of libm calls (a few ulp per operation, amplified by at most the kernel's
depth).
"""
from __future__ import annotations

import subprocess

import numpy as np
import pytest

from conftest import EXAMPLES

CASES = [("free_rigid_body", None), ("heavy_top", None), ("underwater_vehicle", None),
         ("heavy_top", dict(tableau="stormer-verlet", tau="cay", rkmk="truncated")),
         ("free_rigid_body", dict(tableau="gauss2", tau="skew", rkmk="exact"))]


def _step(example, opts):
    from hpgen.api import CompileOptions, resolve
    from hpgen.derive import derive
    from hpgen.model import load_model
    model = load_model(EXAMPLES / f"{example}.yaml")
    tab, tau, rkmk = resolve(model, CompileOptions(**(opts or {})))
    return derive(model, tab, tau, rkmk)


def _random_inputs(kernel, step, rng):
    from reference import rotvec
    n = step.n
    args = []
    for name, size in zip(kernel.inputs, (kernel.function.size1_in(i)
                                          for i in range(kernel.function.n_in()))):
        if name == "g":
            g = np.eye(n)
            g[:3, :3] = rotvec(rng.normal(size=3))
            if n == 4:
                g[:3, 3] = rng.normal(size=3)
            args.append(g.ravel(order="F"))
        elif name == "h":
            args.append(np.array([0.05]))
        else:
            args.append(0.3 * rng.normal(size=size))
    return args


@pytest.mark.parametrize("example,opts", CASES, ids=[f"{e}-{o}" for e, o in CASES])
def test_kernels_match_casadi(compile_model, example, opts):
    step = _step(example, opts)
    rng = np.random.default_rng(7)
    backends = {b: compile_model(EXAMPLES / f"{example}.yaml", backend=b, **(opts or {}))
                for b in ("c", "python")}
    for kernel in step.kernels:
        for _ in range(3):
            args = _random_inputs(kernel, step, rng)
            out = kernel.function.call(args)
            want = [np.array(o).ravel(order="F") for o in out]
            for backend, integ in backends.items():
                got = integ.kernel(kernel.name, *args)
                for w, o in zip(want, got):
                    scale = max(1.0, np.abs(w).max())
                    assert np.abs(np.ravel(o) - w).max() <= 1e-12 * scale, (backend, kernel.name)


@pytest.mark.parametrize("example", sorted(p.stem for p in EXAMPLES.glob("*.yaml")))
def test_generated_c_compiles_with_strict_warnings(tmp_path, cache_dir, example):
    """-Wall -Werror with the flags modules are built with (-O3: gcc's maybe-uninitialized
    analysis runs at -O2 and above, so -O1 would miss those warnings). The example's module
    is generated into the session's build cache (backend python: sources only)."""
    import hpgen
    from hpgen.runtime.build import DEFAULT_CFLAGS, include_flags
    module = hpgen.build(EXAMPLES / f"{example}.yaml", backend="python", cache_dir=cache_dir,
                          out=tmp_path / "module")           # out: both backends' sources
    src = module.module_dir / "kernels.c"
    flags = [f for f in DEFAULT_CFLAGS if f not in ("-shared", "-fPIC")]
    proc = subprocess.run(["cc", *flags, "-Wall", "-Werror", "-fPIC", "-shared",
                           *include_flags(), "-o", str(tmp_path / "k.so"), str(src), "-lm"],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[:2000]
