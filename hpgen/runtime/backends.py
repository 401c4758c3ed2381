"""The kernel backends behind Integrator: Python (the generated kernels.py, here) and C
(ctypes on the compiled kernels.c, hpgen.runtime.cbackend). Both expose the same small
interface:

  call(name, *args) -> [outputs]   args/outputs flat float64 arrays (matrices column-major)
  step(g, p, hv, z, opts)          -> (code, g1, p1, z, iterations, residual)
  start(g0, p0, z0) -> run;  advance(run, h, steps, every, opts) -> (done, g_rec, p_rec, status)
  state(run) -> (g, p, z, k);  simulate(g0, p0, h, z0, steps, every, opts) (start + advance)
  observe(g_rec, p_rec); advance_sections(run, h, steps, cap, opts)
  record(g, p) -> (code, row);  advance_record(run, h, steps, every, opts) -> (done, rows, status)

opts is a newton.NewtonOptions as Engine.options resolves it (simplified a bool); g_rec
(K, n*n) column-major rows and p_rec (K, d) hold the records of the global steps
k % every == 0 reached (simulate prepends step 0), status a dict with the fields of the C
hpgen_status (hpgen.abi.STATUS_FIELDS: code, step, iterations, total_iterations, residual,
jacobians); codes hpgen.abi.STATUS. Advancing a run in chunks gives bitwise the same states
as in one call.
Imports only the standard library and numpy.
"""
from __future__ import annotations

import importlib.util
import itertools

import numpy as np

from . import loop, newton
from .record_row import record_row

_counter = itertools.count()


def _flat(a, size: int, what: str) -> np.ndarray:
    arr = np.ascontiguousarray(a, dtype=np.float64)
    if arr.shape != (size,):
        raise ValueError(f"{what}: expected a flat array of {size} values, got shape "
                         f"{arr.shape}")
    return arr


class _Backend:
    """Common driver: simulate = start a run, record step 0, advance."""
    name = ""

    def __init__(self, meta: dict):
        self.meta = meta
        self.n, self.d, self.nz = meta["n"], meta["d"], meta["nz"]
        #: the record row's width and whether advance_record skips g (see hpgen/runtime/c/hpgen_runs.c)
        self.record_width = sum(int(np.prod(shape)) for _, _, shape in meta["record"])
        self.skip_g = not (meta["step_uses_g"] or meta["record_uses_g"])
        self._sig = {k: ([s for _, s in v["inputs"]], [s for _, s in v["outputs"]])
                     for k, v in meta["kernels"].items()}
        #: the substep fractions of a composed step (hpgen.tableaus.composition), () for the
        #: plain step; every run this backend starts takes them
        self.compose: tuple = ()

    def records_in(self, k0: int, steps: int, every: int) -> int:
        """Number of global steps k in (k0, k0 + steps] with k % every == 0."""
        return (k0 + steps) // every - k0 // every

    def simulate(self, g0, p0, h, z0, steps, every, opts, inputs=None):
        run = self.start(g0, p0, z0) if inputs is None else self.start(g0, p0, z0, inputs)
        done, g_rec, p_rec, st = self.advance(run, h, steps, every, opts)
        nn = self.n * self.n
        g_all = np.concatenate([np.asarray(g0, dtype=np.float64).reshape(1, nn), g_rec])
        p_all = np.concatenate([np.asarray(p0, dtype=np.float64).reshape(1, self.d), p_rec])
        return done, g_all, p_all, st

class PythonBackend(_Backend):
    """Kernels from the generated kernels.py; Newton and the step loop in Python
    (hpgen.runtime.newton) on lists of floats with the module's raw kernels (RAW)."""
    name = "python"

    def __init__(self, module_dir, meta: dict):
        super().__init__(meta)
        path = module_dir / "kernels.py"
        unique = f"_hpgen_kernels_{meta['module']}_{meta['hash'][:16]}_{next(_counter)}"
        spec = importlib.util.spec_from_file_location(unique, path)
        if spec is None or spec.loader is None:
            raise ImportError(f"cannot load {path}")
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        if (mod.N, mod.D, mod.NZ) != (self.n, self.d, self.nz):
            raise ImportError(f"{path} does not match meta.json (n, d, nz)")
        self._kernels = {k: mod.KERNELS[k] for k in self._sig}
        raw = getattr(mod, "RAW", None)
        if raw is None:   # a kernels.py from before RAW: lists through the public kernels
            raw = {k: (lambda f: lambda *a: [o.tolist() for o in f(*a)])(f)
                   for k, f in self._kernels.items()}
        self._raw = {k: raw[k] for k in self._sig}
        self._newton = newton.Kernels.from_raw(self.nz, self._raw, getattr(mod, "LINEAR", None),
                                               getattr(mod, "ITERATE", None),
                                               getattr(mod, "ITERATE_FULL", None),
                                               meta.get("jacobian"))
        self._newton.explicit = meta.get("explicit") is True

    def call(self, name, *args):
        return self._kernels[name](*args)

    def steps_done(self, run) -> int:
        return run.k

    def snapshot(self, run) -> dict:
        """A run's whole state as arrays (a checkpoint; restore continues it bitwise)."""
        return run.to_arrays()

    def restore(self, state: dict, inputs=None):
        """The run a snapshot holds (an open module's run gets its StepInputs again)."""
        run = loop.Run.from_arrays(state)
        run.inputs = inputs
        return run

    def _lists(self, g, p, z):
        nn, d = self.n * self.n, self.d
        return (_flat(g, nn, "g").tolist(), _flat(p, d, "p").tolist(),
                _flat(z, self.nz, "z").tolist())

    def step(self, g, p, hv, z, opts):
        g, p, z = self._lists(g, p, z)
        hv = np.asarray(hv, dtype=np.float64).reshape(-1).tolist()
        code, g1, p1, z, it, r, _ = newton._arrays(newton.step_lists(
            self._newton, g, p, hv, z, opts, newton.NewtonMemory()))
        return code, g1, p1, z, it, r

    def start(self, g0, p0, z0, inputs=None):
        run = loop.Run(*self._lists(g0, p0, z0), inputs)
        run.compose = self.compose
        return run

    def run_step(self, run, h, opts, st, after=None):
        """One step of ``run`` as ``advance`` takes it (loop._composed_step; full Newton at
        step 0), with after(i, hv) called after each substep (hpgen.runtime.linearize)."""
        hv, _, full = loop._loop_start(run, h, opts, "linearize", with_g=True)
        return loop._composed_step(self._newton, run, hv, opts, full, st, True, after)

    def advance(self, run, h, steps, every, opts):
        """(steps done, g_rec (K, nn), p_rec (K, d), status); K records of this call."""
        done, recs, st = loop.advance(self._newton, run, h, steps, every, opts)
        K = len(recs)
        g_rec = np.array([g for g, _ in recs], dtype=np.float64).reshape(K, self.n * self.n)
        p_rec = np.array([p for _, p in recs], dtype=np.float64).reshape(K, self.d)
        return done, g_rec, p_rec, st

    def state(self, run):
        """(g flat, p, z, k) of a run."""
        return (np.array(run.g, dtype=np.float64), np.array(run.p, dtype=np.float64),
                np.array(run.z, dtype=np.float64), run.k)

    def observe(self, g_rec, p_rec):
        """(records done, xi (K, d), E (K,), m (K, d), e (K,)) of K records (g column-major
        flat rows), like hpgen_observe: stops at the first non-finite xi or E."""
        K, d, f = len(p_rec), self.d, self._raw["observe"]
        xi, E, m, e = np.zeros((K, d)), np.zeros(K), np.zeros((K, d)), np.zeros(K)
        for k, (g, p) in enumerate(zip(g_rec.tolist(), p_rec.tolist())):
            a, b, c, q = f(g, p)
            xi[k], E[k], m[k], e[k] = a, b[0], c, q[0]
            if not (np.isfinite(xi[k]).all() and np.isfinite(E[k])):
                return k, xi, E, m, e
        return K, xi, E, m, e

    def advance_sections(self, run, h, steps, cap, opts):
        """(steps done, k_rec (K,), t_rec (K,), g_rec (K, nn), p_rec (K, d), status)."""
        done, recs, st = loop.advance_sections(self._newton, self._raw["section"],
                                                 self._raw["chart_point"], run, h, steps, cap,
                                                 opts)
        return _section_arrays(done, recs, st, self.n * self.n, self.d)

    def _row_of(self, inputs=None):
        """row_of(g, p, k, h) -> (code, row) of the record after global step k (an open
        module's kernels get the run's step vector at that time, StepInputs.at_record)."""
        m = self.meta
        raw = self._raw
        rec, vel, w = raw["record"], raw["velocity_step"], self.record_width
        uses_xi, quad = m["record_uses_xi"], m["legendre_quadratic"]
        stall = self._newton.sparse
        if inputs is None:
            return lambda g, p, k=0, h=0.0: record_row(rec, vel, w, g, p, uses_xi, quad,
                                                            stall)

        def row_of(g, p, k=0, h=0.0):
            hv = inputs.at_record(h, k)
            return record_row(lambda *a: rec(*a, hv), lambda *a: vel(*a, hv), w, g, p,
                                   uses_xi, quad, stall)
        return row_of

    def record(self, g, p, inputs=None):
        """(code, row (W,)): the scene's record row at (g flat, p), like hpgen_record (an
        open module: at the start time of ``inputs``)."""
        code, row = self._row_of(inputs)(_flat(g, self.n * self.n, "g").tolist(),
                                         _flat(p, self.d, "p").tolist())
        return code, np.array(row, dtype=np.float64)

    def advance_record(self, run, h, steps, every, opts):
        """(steps done, rows (K, W), status): the record rows of this call (hpgen_advance_record;
        without g when meta skip_g)."""
        done, rows, st = loop.advance_record(self._newton, self._row_of(run.inputs), run, h, steps,
                                               every, opts, self.skip_g)
        return done, np.array(rows, dtype=np.float64).reshape(len(rows), self.record_width), st


def _section_arrays(done, recs, st, nn, d):
    K = len(recs)
    return (done, np.array([r[0] for r in recs], dtype=np.int64),
            np.array([r[1] for r in recs], dtype=np.float64),
            np.array([r[2] for r in recs], dtype=np.float64).reshape(K, nn),
            np.array([r[3] for r in recs], dtype=np.float64).reshape(K, d), st)
