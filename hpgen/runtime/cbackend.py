"""The C backend: kernels, Newton, step and the run loops of the compiled kernels.c through
ctypes (interface: hpgen.runtime.backends). Kernel calls go through per-thread staging
buffers of fixed address (hpgen.runtime.cstructs); ensembles (simulate_batch, record_batch)
run in hpgen.runtime.cbatch. Imports only the standard library and numpy.

A family module's step library lacks step_partials and hpgen_linearize
(hpgen.codegen.csource.LAZY_KERNELS): the first call of either builds and loads the lazily
built library (hpgen.runtime.build.build_lazy_library), which takes the runs this library
initialised (the same hpgen_run struct).
"""
from __future__ import annotations

import ctypes
import threading

import numpy as np

from .. import abi
from ..errors import BuildError
from .backends import _Backend, _flat
from .build import build_lazy_library, build_library
from . import cbatch
from .cstructs import _Options, _Staging, _Status, _addr

_F64 = np.dtype(np.float64)
_RUN = ("run",)      # CBackend._staging key of the run state buffers (not a kernel name)


class CBackend(_Backend):
    """Kernels, Newton, step and simulate from the compiled kernels.c (built on first use)."""
    name = "c"

    def __init__(self, module_dir, meta: dict, cc=None, cflags=None):
        super().__init__(meta)
        #: an open module (meta "open"): hpgen_step takes the step vector, runs carry their
        #: inputs (hpgen_run_set_inputs), and the record/observe functions are not built
        self.open = meta.get("open")
        self.library = build_library(module_dir, cc=cc, cflags=cflags)
        self._lazy_args = (module_dir, cc, cflags)
        self._lazy_lib: ctypes.CDLL | None = None
        self._lazy_lock = threading.Lock()
        lib = self._open(self.library)
        self._fns = {}
        for k in self._sig:
            if hasattr(lib, f"hpgen_kernel_{k}"):
                self._fns[k] = self._kernel(lib, k)
        P, LL, D = ctypes.c_void_p, ctypes.c_longlong, ctypes.c_double
        closed_only = ("hpgen_observe",)
        for name, args, res in (
                ("hpgen_step", [P, P, P if self.open else D, P, P, P, P, P], ctypes.c_int),
                ("hpgen_run_size", [], LL),
                ("hpgen_run_init", [P, P, P, P], None),
                ("hpgen_run_get", [P, P, P, P], LL),
                ("hpgen_advance", [P, D, LL, LL, P, P, P, P], LL),
                ("hpgen_advance_sections", [P, D, LL, P, LL, P, P, P, P, P, P], LL),
                ("hpgen_observe", [LL, P, P, P, P, P, P], LL),
                ("hpgen_advance_batch", [P, LL, D, LL, LL, P, LL, P, P, P], LL),
                ("hpgen_record", [P, P, P] + [P] * bool(self.open), ctypes.c_int),
                ("hpgen_advance_record", [P, D, LL, LL, P, P, P, P], LL),
                ("hpgen_advance_record_batch", [P, LL, D, LL, LL, P, LL, P, P, P], LL),
                ("hpgen_run_set_inputs", [P, D, P, LL, P], None),
                ("hpgen_run_set_compose", [P, LL, P], ctypes.c_int),
                ("hpgen_linearize", [P, LL, P, P, D, LL, LL, P, P, P, P, P], LL)):
            if (self.open and name in closed_only) or (
                    not self.open and name == "hpgen_run_set_inputs") or (
                    not hasattr(lib, name) and name == "hpgen_linearize"):
                continue
            fn = getattr(lib, name)
            fn.argtypes, fn.restype = args, res
        #: bodies per call of the lane-wise ensemble kernel (hpgen_advance_batch_lanes;
        #: hpgen.codegen.lanes), 0 when the module has none
        self.lanes = 0
        if hasattr(lib, "hpgen_advance_batch_lanes"):
            lib.hpgen_advance_batch_lanes.argtypes = [P, LL, D, LL, LL, P, LL, P, P, P]
            lib.hpgen_advance_batch_lanes.restype = LL
            self.lanes = int(lib.hpgen_lanes())
        self.run_size = int(lib.hpgen_run_size())
        self._lib = lib
        self._tls = threading.local()    # per thread: {key: _Staging} (see _staging)

    def _open(self, path) -> ctypes.CDLL:
        """The library at ``path`` loaded, checked against meta.json (hash, ABI, sizes)."""
        try:
            lib = ctypes.CDLL(str(path))
        except OSError as exc:
            raise BuildError(f"cannot load {path.name}: {exc}") from None
        lib.hpgen_hash.restype = ctypes.c_char_p
        lib.hpgen_hash.argtypes = []
        if lib.hpgen_hash().decode() != self.meta["hash"]:
            raise BuildError(f"{path.name} was built from another kernels.c "
                             "(hash mismatch); delete it to rebuild")
        dims = (ctypes.c_longlong * 4)()
        lib.hpgen_dims(dims)
        if tuple(dims) != (abi.ABI_VERSION, self.n, self.d, self.nz):
            raise BuildError(f"{path.name}: ABI/dimensions {tuple(dims)} do not "
                             "match meta.json")
        return lib

    def _kernel(self, lib: ctypes.CDLL, name: str):
        ins, outs = self._sig[name]
        fn = getattr(lib, f"hpgen_kernel_{name}")
        fn.argtypes = [ctypes.c_void_p] * (len(ins) + len(outs))
        fn.restype = ctypes.c_int
        return fn

    @property
    def lib(self) -> ctypes.CDLL:
        """The loaded step library (its C functions' argument types set)."""
        return self._lib

    @property
    def lazy_lib(self) -> ctypes.CDLL:
        """The library with hpgen_linearize and every kernel: the step library when it has
        them, else the lazily built library (built and loaded on first access)."""
        if hasattr(self._lib, "hpgen_linearize"):
            return self._lib
        with self._lazy_lock:
            if self._lazy_lib is None:
                module_dir, cc, cflags = self._lazy_args
                path = build_lazy_library(module_dir, cc=cc, cflags=cflags)
                lib = self._open(path)
                lib.hpgen_run_size.restype = ctypes.c_longlong
                lib.hpgen_run_size.argtypes = []
                if lib.hpgen_run_size() != self.run_size:
                    raise BuildError(f"{path.name}: its runs are {lib.hpgen_run_size()} "
                                     f"bytes, the step library's {self.run_size}")
                P, LL, D = ctypes.c_void_p, ctypes.c_longlong, ctypes.c_double
                lib.hpgen_linearize.argtypes = [P, LL, P, P, D, LL, LL, P, P, P, P, P]
                lib.hpgen_linearize.restype = LL
                self._lazy_lib = lib
            return self._lazy_lib

    def kernel_function(self, name):
        """The ctypes function of kernel ``name`` (hpgen_kernel_<name>; one of the lazily
        built library builds it)."""
        fn = self._fns.get(name)
        if fn is None:
            if name not in self._sig:
                raise KeyError(name)
            fn = self._fns[name] = self._kernel(self.lazy_lib, name)
        return fn

    def _staging(self, key) -> _Staging:
        """This thread's staging buffers for kernel ``key``, or for _RUN (g, p, z in and
        out: hpgen_run_init / hpgen_run_get); per thread, so that concurrent calls (threads;
        ctypes releases the GIL) never share them."""
        try:
            return self._tls.staging[key]
        except AttributeError:
            self._tls.staging = {}
        except KeyError:
            pass
        nn, d, nz = self.n * self.n, self.d, self.nz
        ins, outs = self._sig[key] if key != _RUN else ([nn, d, nz], [nn, d, nz])
        st = self._tls.staging[key] = _Staging(ins, outs)
        return st

    def _run_k(self, run) -> int:
        """The steps done k of a run (hpgen_run_get into this thread's scratch)."""
        st = self._staging(_RUN)
        return int(self._lib.hpgen_run_get(run, *st.ptrs[3:]))

    def steps_done(self, run) -> int:
        return self._run_k(run)

    def snapshot(self, run) -> dict:
        """A run's whole state (the bytes of its C ``hpgen_run``: state, Newton start and
        memory, steps done) as a uint8 array; restore continues it bitwise."""
        return {"run": np.frombuffer(run.raw, dtype=np.uint8).copy()}

    def restore(self, state: dict, inputs=None):
        """The run a snapshot of this library holds (same hash, same run_size); an open
        module's run is pointed at its StepInputs again (the snapshot's pointers are stale)."""
        raw = np.asarray(state["run"], dtype=np.uint8)
        if raw.shape != (self.run_size,):
            raise ValueError(f"a run snapshot of {raw.size} bytes; this library's runs are "
                             f"{self.run_size} bytes")
        run = ctypes.create_string_buffer(self.run_size)
        ctypes.memmove(run, raw.tobytes(), self.run_size)
        if self.open:
            run.keep = self.set_inputs(run, inputs)  # type: ignore[attr-defined]
        return run

    def call(self, name, *args):
        # arguments copied into this thread's fixed buffers of the kernel (their addresses
        # made once), outputs zeroed before and copied out after the call
        try:
            st = self._tls.staging[name]
        except (AttributeError, KeyError):
            st = self._staging(name)
        ins = st.ins
        if len(args) != len(ins):
            raise TypeError(f"kernel {name} takes {len(ins)} arguments, got {len(args)}")
        for i, (x, buf) in enumerate(zip(args, ins)):
            if type(x) is np.ndarray and x.dtype is _F64 and x.shape == buf.shape:
                buf[...] = x
            else:
                buf[...] = _flat(x, len(buf), f"{name} input {i}")
        st.out_all.fill(0.0)
        fn = self._fns.get(name)
        (fn if fn is not None else self.kernel_function(name))(*st.ptrs)
        return [o.copy() for o in st.outs]

    def step(self, g, p, hv, z, opts):
        nn, d = self.n * self.n, self.d
        g, p = _flat(g, nn, "g"), _flat(p, d, "p")
        z = np.array(_flat(z, self.nz, "z"))
        g1, p1, st, o = np.zeros(nn), np.zeros(d), _Status(), _Options.of(opts)
        if self.open:
            hv = np.array(hv, dtype=np.float64)
            harg = hv.ctypes.data
        else:
            harg = float(hv[0])
        code = self._lib.hpgen_step(g.ctypes.data, p.ctypes.data, harg, z.ctypes.data,
                                    ctypes.byref(o), g1.ctypes.data, p1.ctypes.data,
                                    ctypes.byref(st))
        if code < 0:
            raise ValueError("hpgen_step rejected its arguments")
        if code != abi.OK:
            return code, None, None, z, st.iterations, st.residual
        return code, g1, p1, z, st.iterations, st.residual

    def start(self, g0, p0, z0, inputs=None):
        """A run (a ctypes byte buffer holding a C ``hpgen_run``) at (g0, p0), start z0; an
        open module's run gets its StepInputs (the input rows and parameters are kept alive
        on the buffer, which the C run points into)."""
        nn, d = self.n * self.n, self.d
        g0, p0 = _flat(g0, nn, "g0"), _flat(p0, d, "p0")
        z0 = _flat(z0, self.nz, "z0")
        run = ctypes.create_string_buffer(self.run_size)
        self.init_run(run, g0, p0, z0)
        if self.open:
            run.keep = self.set_inputs(run, inputs)  # type: ignore[attr-defined]
        return run

    def set_inputs(self, run, inputs):
        """Point the C run ``run`` (a buffer or its address) at an open module's StepInputs;
        returns the arrays it points into (keep them alive while the run is used)."""
        if inputs is None:
            raise ValueError("an open module's run needs its inputs (t0, u, params)")
        U = np.ascontiguousarray(inputs.rows, dtype=np.float64)
        params = np.ascontiguousarray(inputs.params, dtype=np.float64)
        self._lib.hpgen_run_set_inputs(run, float(inputs.t0), U.ctypes.data, len(inputs.rows),
                                       params.ctypes.data)
        return U, params

    def init_run(self, run, g0, p0, z0):
        """hpgen_run_init from flat arrays of the right sizes (copied in: this thread's
        staging buffers)."""
        st = self._staging(_RUN)
        st.ins[0][...], st.ins[1][...], st.ins[2][...] = g0, p0, z0
        self._lib.hpgen_run_init(run, *st.ptrs[:3])
        if self.compose:
            gam = np.array(self.compose, dtype=np.float64)
            if self._lib.hpgen_run_set_compose(run, len(gam), gam.ctypes.data) != 0:
                raise ValueError(f"a composed step of {len(gam)} substeps: this library "
                                 "takes at most HPGEN_CS_MAX")

    def simulate(self, g0, p0, h, z0, steps, every, opts, inputs=None):
        """_Backend.simulate in one pair of record arrays: step 0 in row 0, hpgen_advance
        writing from row 1 (a new run is at k = 0: no state query)."""
        nn, d = self.n * self.n, self.d
        run = self.start(g0, p0, z0, inputs)
        K = self.records_in(0, steps, every) + 1
        g_all, p_all = np.zeros((K, nn)), np.zeros((K, d))
        g_all[0], p_all[0] = g0, p0
        st, o = _Status(), _Options.of(opts)
        done = self._lib.hpgen_advance(run, float(h), steps, every, ctypes.byref(o),
                                       _addr(g_all) + 8 * nn, _addr(p_all) + 8 * d,
                                       ctypes.byref(st))
        if st.code < 0:
            raise ValueError("hpgen_advance rejected its arguments")
        K = self.records_in(0, done, every) + 1
        return int(done), g_all[:K], p_all[:K], st.as_dict()

    def simulate_batch(self, g0s, p0s, h, z0s, steps, every, opts, threads, inputs=None,
                       bar=None, lanes=True):
        """B independent runs keeping their states (hpgen.runtime.cbatch.simulate_batch)."""
        return cbatch.simulate_batch(self, g0s, p0s, h, z0s, steps, every, opts, threads,
                                     inputs, bar, lanes)

    def record_batch(self, g0s, p0s, h, z0s, steps, every, opts, threads, bar=None,
                     inputs=None):
        """B independent runs keeping record rows (hpgen.runtime.cbatch.record_batch)."""
        return cbatch.record_batch(self, g0s, p0s, h, z0s, steps, every, opts, threads, bar,
                                   inputs)

    def state(self, run):
        """(g flat, p, z, k) of a run."""
        st = self._staging(_RUN)
        k = self._lib.hpgen_run_get(run, *st.ptrs[3:])
        g, p, z = (o.copy() for o in st.outs)
        return g, p, z, int(k)

    def advance(self, run, h, steps, every, opts):
        """(steps done, g_rec (K, nn), p_rec (K, d), status); K records of this call."""
        nn, d = self.n * self.n, self.d
        K = self.records_in(self._run_k(run), steps, every)
        g_rec, p_rec, st, o = np.zeros((K, nn)), np.zeros((K, d)), _Status(), _Options.of(opts)
        done = self._lib.hpgen_advance(run, float(h), steps, every, ctypes.byref(o),
                                       _addr(g_rec), _addr(p_rec), ctypes.byref(st))
        if st.code < 0:
            raise ValueError("hpgen_advance rejected its arguments")
        K = self.records_in(self._run_k(run) - done, done, every)
        return int(done), g_rec[:K], p_rec[:K], st.as_dict()

    def observe(self, g_rec, p_rec):
        """(records done, xi (K, d), E (K,), m (K, d), e (K,)) of K records (g column-major
        flat rows), one C call (hpgen_observe)."""
        K, d = len(p_rec), self.d
        g_rec = np.ascontiguousarray(g_rec, dtype=np.float64).reshape(K, self.n * self.n)
        p_rec = np.ascontiguousarray(p_rec, dtype=np.float64).reshape(K, d)
        xi, E, m, e = np.zeros((K, d)), np.zeros(K), np.zeros((K, d)), np.zeros(K)
        done = self._lib.hpgen_observe(K, g_rec.ctypes.data, p_rec.ctypes.data, xi.ctypes.data,
                                       E.ctypes.data, m.ctypes.data, e.ctypes.data)
        return int(done), xi, E, m, e

    def advance_sections(self, run, h, steps, cap, opts):
        """(steps done, k_rec (K,), t_rec (K,), g_rec (K, nn), p_rec (K, d), status): the
        section crossings of this call, at most cap."""
        nn, d = self.n * self.n, self.d
        k_rec, t_rec = np.zeros(cap, dtype=np.int64), np.zeros(cap)
        g_rec, p_rec = np.zeros((cap, nn)), np.zeros((cap, d))
        n_rec, st, o = ctypes.c_longlong(0), _Status(), _Options.of(opts)
        done = self._lib.hpgen_advance_sections(
            run, float(h), steps, ctypes.byref(o), cap, t_rec.ctypes.data, g_rec.ctypes.data,
            p_rec.ctypes.data, k_rec.ctypes.data, ctypes.byref(n_rec), ctypes.byref(st))
        if st.code < 0:
            raise ValueError("hpgen_advance_sections rejected its arguments")
        K = n_rec.value
        return int(done), k_rec[:K], t_rec[:K], g_rec[:K], p_rec[:K], st.as_dict()

    def record(self, g, p, inputs=None):
        """(code, row (W,)): the scene's record row at (g flat, p) (hpgen_record; an open
        module's at the start time of ``inputs``)."""
        g, p = _flat(g, self.n * self.n, "g"), _flat(p, self.d, "p")
        row = np.zeros(self.record_width)
        extra = ()
        if self.open:
            hv = np.array(inputs.at_record(0.0, 0), dtype=np.float64)
            extra = (hv.ctypes.data,)
        code = self._lib.hpgen_record(g.ctypes.data, p.ctypes.data, row.ctypes.data, *extra)
        return int(code), row

    def advance_record(self, run, h, steps, every, opts):
        """(steps done, rows (K, W), status): the record rows of this call, one C call
        (hpgen_advance_record; g not reconstructed when skip_g)."""
        K = self.records_in(self._run_k(run), steps, every)
        rows, st, o = np.zeros((K, self.record_width)), _Status(), _Options.of(opts)
        n_rec = ctypes.c_longlong(0)
        done = self._lib.hpgen_advance_record(run, float(h), steps, every, ctypes.byref(o),
                                              rows.ctypes.data, ctypes.byref(n_rec),
                                              ctypes.byref(st))
        if st.code < 0:
            raise ValueError("hpgen_advance_record rejected its arguments")
        return int(done), rows[:n_rec.value], st.as_dict()

    def linearize(self, run, gf, p, h, cols, opts):
        """hpgen_linearize: ``run`` (this backend's start at record 0) stepped along the
        records gf (K+1, n*n), p (K+1, d) as the run steps (hpgen.runtime.linearize); cols
        the step vector's columns of B (a slice; empty for a closed module):
        (A (K, 2d, 2d), B (K, 2d, nc), dev (K,), status dict, steps done)."""
        K, s, nc = len(gf) - 1, 2 * self.d, cols.stop - cols.start
        gf, p = np.array(gf, dtype=_F64, order="C"), np.array(p, dtype=_F64, order="C")
        A, B, dev = np.zeros((K, s, s)), np.zeros((K, nc, s)), np.zeros(K)
        st = _Status()
        done = int(self.lazy_lib.hpgen_linearize(run, K, _addr(gf), _addr(p), float(h),
                                             cols.start if self.open else 0, nc,
                                             ctypes.byref(_Options.of(opts)), _addr(A),
                                             _addr(B), _addr(dev), ctypes.byref(st)))
        if st.code < 0:
            raise ValueError("hpgen_linearize rejected its arguments")
        # C's column-major 2d x 2d blocks are row-major transposes
        return (A.transpose(0, 2, 1).copy(), B.transpose(0, 2, 1).copy(), dev, st.as_dict(),
                done)
