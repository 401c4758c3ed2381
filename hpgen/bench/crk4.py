"""The classical RK4 peer (and the implicit midpoint rule) emitted as C by hpgen, so that RK4 and hpgen run in one language.

CasADi's C generator writes f (the Problem's vector field, a dense casadi.Function
(t, y) -> y'); ``rk4.c.j2`` (next to this file, rendered with Jinja2 StrictUndefined) adds the
RK4 loop and a plain ``hpgen_bench_f(t, y, ydot)`` entry. The library is built by ``hpgen.runtime.build`` (flags
DEFAULT_CFLAGS = -std=c99 -O3 -fPIC -shared, -lm, race-free) in a cache entry keyed by the
sha256 of the C source, and loaded with ctypes. The template lives in hpgen/bench, not in
templates/: every templates/*.j2 is hashed into hpgen's generator digest, so a file there
would change the content hash of every generated module.

Arrays across the boundary: y is the contiguous float64 state (see hpgen.bench.problem).
"""
from __future__ import annotations

import ctypes
import hashlib
import json
import time
from pathlib import Path

import numpy as np

from .. import __version__

TEMPLATE = "rk4.c.j2"


def render(problem) -> str:
    """The C source: CasADi's code of problem.f plus the RK4 loop of the template."""
    import casadi as ca
    import jinja2
    f = problem.f
    cg = ca.CodeGenerator("hpgen_bench", {"with_header": False})
    cg.add(f)
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(Path(__file__).parent)),
                             undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
                             autoescape=False)
    return env.get_template(TEMPLATE).render(
        model=problem.model.name, version=__version__, ny=problem.ny, fname=f.name(),
        casadi_source=cg.dump(), sz_arg=max(1, f.sz_arg()), sz_res=max(1, f.sz_res()),
        sz_iw=max(1, f.sz_iw()), sz_w=max(1, f.sz_w()),
        so3=problem.model.group.name == "SO3")


def build(source: str, cache_dir=None, cc=None, prefix="bench-rk4") -> Path:
    """Compile ``source`` (cached by its sha256, in the cache entry ``<prefix>-<sha256[:24]>``);
    returns the shared library's path."""
    from .. import cache
    from ..runtime.build import build_library
    cache_dir = Path(cache_dir) if cache_dir else cache.default_cache_dir()
    key = hashlib.sha256(source.encode()).hexdigest()
    entry = cache_dir / f"{prefix}-{key[:24]}"
    if not cache.is_valid(entry):
        with cache.locked(cache_dir, f"{prefix}-{key[:24]}"):
            if not cache.is_valid(entry):
                cache.write_tree(entry, {"kernels.c": source,
                                         "meta.json": json.dumps({"hash": key})})
    return build_library(entry, cc=cc)


class CRK4:
    """Loaded C RK4 of a Problem. ``f(y)`` and ``rhs(t, y)`` evaluate the C vector field
    (for the Python peers); ``run(y0, h, steps, every)`` integrates. ``setup_s``: render +
    build + load seconds."""

    def __init__(self, problem, cache_dir=None, cc=None):
        t0 = time.perf_counter()
        self.ny = problem.ny
        self.source = render(problem)
        self.path = build(self.source, cache_dir, cc)
        lib = self.lib = ctypes.CDLL(str(self.path))
        lib.hpgen_bench_f.argtypes = [ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p]
        lib.hpgen_bench_f.restype = ctypes.c_int
        lib.hpgen_bench_rk4.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_long,
                                        ctypes.c_long, ctypes.c_void_p]
        lib.hpgen_bench_rk4.restype = ctypes.c_long
        lib.hpgen_bench_midpoint.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_long,
                                             ctypes.c_long, ctypes.c_void_p, ctypes.c_void_p]
        lib.hpgen_bench_midpoint.restype = ctypes.c_long
        self.has_lie_midpoint = problem.model.group.name == "SO3"
        if self.has_lie_midpoint:
            lib.hpgen_bench_lie_midpoint.argtypes = lib.hpgen_bench_midpoint.argtypes
            lib.hpgen_bench_lie_midpoint.restype = ctypes.c_long
        self._f = lib.hpgen_bench_f
        self.setup_s = time.perf_counter() - t0

    def f(self, y, t=0.0):
        """f(t, y) for a float64 vector y (contiguous copy made if needed); t matters for a
        forced or time-dependent model only."""
        y = np.ascontiguousarray(y, dtype=np.float64)
        out = np.empty(self.ny)
        self._f(float(t), y.ctypes.data, out.ctypes.data)
        return out

    def rhs(self, t, y):
        """SciPy's signature."""
        return self.f(y, t)

    def run(self, y0, h, steps, every=None):
        """(records (K, ny) or None, last state, steps done). Records y0 and every
        ``every``-th state when ``every`` is given."""
        y = np.array(y0, dtype=np.float64)
        rec = None
        if every:
            rec = np.empty((steps // every + 1, self.ny))
        done = self.lib.hpgen_bench_rk4(y.ctypes.data, float(h), int(steps), int(every or 1),
                                        None if rec is None else rec.ctypes.data)
        if rec is not None:
            rec = rec[:done // (every or 1) + 1]
        return rec, y, int(done)

    def midpoint(self, y0, h, steps, every=None, lie=False):
        """The implicit midpoint rule on the same f (rk4.c.j2), or with lie=True (SO3 only)
        the Lie (RKMK, exp chart) midpoint rule: (records or None, last state, steps done,
        f evaluations of the fixed-point iterations)."""
        fn = self.lib.hpgen_bench_lie_midpoint if lie else self.lib.hpgen_bench_midpoint
        y = np.array(y0, dtype=np.float64)
        rec = np.empty((steps // every + 1, self.ny)) if every else None
        its = ctypes.c_long(0)
        done = fn(y.ctypes.data, float(h), int(steps), int(every or 1),
                  None if rec is None else rec.ctypes.data, ctypes.byref(its))
        if rec is not None:
            rec = rec[:done // (every or 1) + 1]
        return rec, y, int(done), int(its.value)
