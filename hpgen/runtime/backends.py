"""The two kernel backends behind Integrator: C (ctypes on the compiled kernels.c) and Python
(the generated kernels.py). Both expose the same small interface:

  call(name, *args) -> [outputs]   args/outputs flat float64 arrays (matrices column-major)
  step(g, p, hv, z, tol, maxit)    -> (code, g1, p1, z, iterations, residual)
  simulate(g0, p0, h, z0, steps, every, tol, maxit) -> (done, g_rec, p_rec, status)

with g_rec (K, n*n) column-major rows and p_rec (K, d), K = steps // every + 1, and status a
dict (code, step, iterations, total_iterations, residual); codes as in hpgen.runtime.newton.
Imports only the standard library and numpy.
"""
from __future__ import annotations

import ctypes
import importlib.util
import itertools

import numpy as np

from ..errors import BuildError
from . import newton
from .build import build_library

_counter = itertools.count()
_ABI = 1


def _flat(a, size: int, what: str) -> np.ndarray:
    arr = np.ascontiguousarray(a, dtype=np.float64)
    if arr.shape != (size,):
        raise ValueError(f"{what}: expected a flat array of {size} values, got shape "
                         f"{arr.shape}")
    return arr


class _Backend:
    name = ""

    def __init__(self, meta: dict):
        self.meta = meta
        self.n, self.d, self.nz = meta["n"], meta["d"], meta["nz"]
        self._sig = {k: ([s for _, s in v["inputs"]], [s for _, s in v["outputs"]])
                     for k, v in meta["kernels"].items()}

    def step(self, g, p, hv, z, tol, maxit):
        return newton.step_core(self.call, self.nz, g, p, hv, z, tol, maxit)

    def simulate(self, g0, p0, h, z0, steps, every, tol, maxit):
        return newton.simulate(self.call, self.nz, self.d, self.n * self.n, g0, p0, h, z0,
                               steps, every, tol, maxit)


class PythonBackend(_Backend):
    """Kernels from the generated kernels.py; Newton and the step loop in numpy."""
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

    def call(self, name, *args):
        return self._kernels[name](*args)


class _Status(ctypes.Structure):
    _fields_ = [("code", ctypes.c_longlong), ("step", ctypes.c_longlong),
                ("iterations", ctypes.c_longlong), ("total_iterations", ctypes.c_longlong),
                ("residual", ctypes.c_double)]

    def as_dict(self) -> dict:
        return {f: getattr(self, f) for f, _ in self._fields_}


class CBackend(_Backend):
    """Kernels, Newton, step and simulate from the compiled kernels.c (built on first use)."""
    name = "c"

    def __init__(self, module_dir, meta: dict, cc=None, cflags=None):
        super().__init__(meta)
        self.library = build_library(module_dir, cc=cc, cflags=cflags)
        try:
            lib = ctypes.CDLL(str(self.library))
        except OSError as exc:
            raise BuildError(f"cannot load {self.library.name}: {exc}") from None
        lib.hpgen_hash.restype = ctypes.c_char_p
        lib.hpgen_hash.argtypes = []
        if lib.hpgen_hash().decode() != meta["hash"]:
            raise BuildError(f"{self.library.name} was built from another kernels.c "
                             "(hash mismatch); delete it to rebuild")
        dims = (ctypes.c_longlong * 4)()
        lib.hpgen_dims(dims)
        if tuple(dims) != (_ABI, self.n, self.d, self.nz):
            raise BuildError(f"{self.library.name}: ABI/dimensions {tuple(dims)} do not "
                             "match meta.json")
        self._fns = {}
        for k, (ins, outs) in self._sig.items():
            fn = getattr(lib, f"hpgen_kernel_{k}")
            fn.argtypes = [ctypes.c_void_p] * (len(ins) + len(outs))
            fn.restype = ctypes.c_int
            self._fns[k] = fn
        P, LL, D = ctypes.c_void_p, ctypes.c_longlong, ctypes.c_double
        lib.hpgen_step.argtypes = [P, P, D, P, D, LL, P, P, ctypes.POINTER(_Status)]
        lib.hpgen_step.restype = ctypes.c_int
        lib.hpgen_simulate.argtypes = [P, P, D, P, LL, LL, D, LL, P, P,
                                       ctypes.POINTER(_Status)]
        lib.hpgen_simulate.restype = ctypes.c_longlong
        self._lib = lib

    def call(self, name, *args):
        ins, outs = self._sig[name]
        if len(args) != len(ins):
            raise TypeError(f"kernel {name} takes {len(ins)} arguments, got {len(args)}")
        a = [_flat(x, s, f"{name} input {i}") for i, (x, s) in enumerate(zip(args, ins))]
        r = [np.zeros(s) for s in outs]
        self._fns[name](*[x.ctypes.data for x in a + r])
        return r

    def step(self, g, p, hv, z, tol, maxit):
        nn, d = self.n * self.n, self.d
        g, p = _flat(g, nn, "g"), _flat(p, d, "p")
        z = np.array(_flat(z, self.nz, "z"))
        g1, p1, st = np.zeros(nn), np.zeros(d), _Status()
        code = self._lib.hpgen_step(g.ctypes.data, p.ctypes.data, float(hv[0]), z.ctypes.data,
                                    tol, maxit, g1.ctypes.data, p1.ctypes.data,
                                    ctypes.byref(st))
        if code != newton.OK:
            return code, None, None, z, st.iterations, st.residual
        return code, g1, p1, z, st.iterations, st.residual

    def simulate(self, g0, p0, h, z0, steps, every, tol, maxit):
        nn, d = self.n * self.n, self.d
        g0, p0 = _flat(g0, nn, "g0"), _flat(p0, d, "p0")
        z = np.array(_flat(z0, self.nz, "z0"))
        K = steps // every + 1
        g_rec, p_rec, st = np.zeros((K, nn)), np.zeros((K, d)), _Status()
        done = self._lib.hpgen_simulate(g0.ctypes.data, p0.ctypes.data, h, z.ctypes.data,
                                        steps, every, tol, maxit, g_rec.ctypes.data,
                                        p_rec.ctypes.data, ctypes.byref(st))
        if st.code < 0:
            raise ValueError("hpgen_simulate rejected its arguments")
        return int(done), g_rec, p_rec, st.as_dict()
