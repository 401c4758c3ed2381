"""simulate's fast path: the common call on the C backend without the generic prologue's
per-call Python (Integrator.simulate).

What the generic path (hpgen.runtime.states.simulate: Engine.prepare, the engine's run loop,
states.trajectory) does
per call, done here with what can be kept across calls kept:
- a Plan per (h, steps, every, newton) holds the checked h, steps, every, the resolved Newton
  options (and their C struct), the record count K, the record times and the memory check;
  kept in a dict of at most PLANS_MAX plans (cleared when full). Keyed by value for h, steps
  and every (of types float / int only, so 1 == 1.0 == True never alias) and by identity for
  ``newton`` (the plan holds the object, so its id is not reused; NewtonOptions is frozen).
  Nothing a plan holds depends on anything else: the module, its options and the machine's
  memory do not change while it is loaded.
- per thread, one staging block [xi | hv | lv | z | e | m] and record rows whose row 0 is the
  start (g, mu), their addresses made once, a run buffer and a status: the start is direct
  kernel calls in place (defect, legendre, guess, and margin for a closed module), the run
  one hpgen_run_init (and hpgen_run_set_inputs) and one hpgen_advance writing the records
  after row 0; the Trajectory copies them out;
- an explicit step (a splitting scheme) starts from z = mu0: no velocity, guess nor margin;
- a mu0 start's velocity (StateMaps.velocity_flat: Newton with numpy's solve, ~30 us) is kept for
  the last (g0, mu0, lv) by their bytes (a function of those bytes alone).
An open module's u, params and t0 are checked by the generic step_inputs at every call (u is
the caller's array: it may have changed in place).

The same kernels on the same doubles in the same order as the generic path: the results are
bitwise those of the generic path. Whatever is not the common case -- another type or shape
of g0 / xi0 / mu0 / h / steps / every / t0, a non-finite entry, g0 off the group, any
argument error, a closed module's start outside the chart (the first step by continuation)
or first step failing (the retry), a run of more than STEPS_MAX steps -- is left to the
generic path (``simulate`` returns None before anything is returned or raised), which raises
the same errors as before. numpy, ctypes and the standard library only.
"""
from __future__ import annotations

import ctypes
import math
import threading

import numpy as np

from .. import abi
from ..errors import HpgenError
from . import counters
from .args import _fits, _int, _step_size
from .cstructs import _Options, _Status, _addr
from .engine import DEFECT_MAX
from .inputs import step_inputs
from .states import trajectory
from .trajectory import Trajectory

#: plans kept per Integrator (the dict is cleared when it holds more)
PLANS_MAX = 32
#: a plan keeps its record times, and a thread's record rows hold, up to this many records
#: (longer runs make theirs per call)
ROWS_MAX = 4096
ROWS_MIN = 64
#: the fast path runs at most this many steps (in one C call, which an interrupt cannot
#: stop); longer runs take the generic path, which advances them in slices
#: (hpgen.runtime.engine.Sliced)
STEPS_MAX = 20_000
_FLOATS, _INTS = (float, np.float64), (int, np.int64)
_F64 = np.dtype(np.float64)


class Plan:
    """The checked, per-call-independent part of a simulate call (see the module docstring)."""
    __slots__ = ("h", "steps", "every", "newton", "opts", "copts", "copts_addr", "K", "t")

    def __init__(self, engine, h, steps, every, newton):
        self.h = _step_size(h)
        self.steps, self.every = _int(steps, "steps", 0), _int(every, "every", 1)
        self.newton, self.opts = newton, engine.options(newton)
        self.copts = _Options.of(self.opts)
        self.copts_addr = ctypes.addressof(self.copts)
        self.K = self.steps // self.every + 1
        _fits(self.K, engine.n * engine.n + engine.d, "simulate")
        # the times of the records for t0 = 0, in an immutable buffer: views of it handed to
        # Trajectories can never be made writeable
        self.t = np.frombuffer(self.times().tobytes()) if self.K <= ROWS_MAX else None

    def times(self) -> np.ndarray:
        """t_k = k every h of records k = 0..K-1 (hpgen.runtime.states.records)."""
        return np.arange(0, self.K * self.every, self.every) * self.h


class _NoPlan:
    """Prologue.last before the first plan (matches no call)."""
    h = steps = every = newton = math.nan


_NO_PLAN = _NoPlan()


class _Thread:
    """One thread's staging: a block [xi | hv | lv | z | e | m] (hv the step vector, lv the
    open module's argument of l, StateMaps.lv) and the record rows G (cap, n*n),
    P (cap, d) whose row 0 is the start (g flat, mu): the kernels read and write them in
    place, hpgen_advance writes the records from row 1 (runs of more than ROWS_MAX records get
    rows of their own); their addresses made once per size; a run buffer and a status."""

    def __init__(self, n, d, nz, H, run_size):
        self.n, self.d = n, d
        sizes = {"xi": d, "hv": H, "lv": H, "z": nz, "e": 1, "m": 1}
        self.block = np.zeros(sum(sizes.values()))
        base, off = _addr(self.block), 0
        self.views, self.ptr = {}, {}
        for name, s in sizes.items():
            self.views[name] = self.block[off:off + s]
            self.ptr[name] = base + 8 * off
            off += s
        self.cap = 0
        self.rows(ROWS_MIN)
        self.run = ctypes.create_string_buffer(run_size)
        self.run_addr = ctypes.addressof(self.run)
        self.status = _Status()
        self.status_addr = ctypes.addressof(self.status)

    def rows(self, K):
        """Make the record rows hold K records (K <= ROWS_MAX); their row 0 is not kept."""
        if K <= self.cap:
            return
        n, d = self.n, self.d
        self.cap = max(K, 2 * self.cap)
        self.G, self.P = np.zeros((self.cap, n * n)), np.zeros((self.cap, d))
        v, p = self.views, self.ptr
        v["g"], v["mu"] = self.G[0], self.P[0]
        p["g"], p["mu"] = _addr(self.G), _addr(self.P)
        #: g as the (n, n) matrix whose column-major entries are the flat g
        self.gT = v["g"].reshape(n, n).T


class Prologue:
    """simulate's fast path for the run engine (hpgen.runtime.engine) of a module on the C
    backend."""

    def __init__(self, engine):
        b = engine.backend
        self.defect_max = DEFECT_MAX
        self.engine, self.lib = engine, b.lib
        self.n, self.d, self.nz = engine.n, engine.d, engine.nz
        self.open = engine.open
        #: an explicit step (meta "explicit"): the start needs no velocity, guess nor margin
        self.explicit = engine.meta.get("explicit") is True
        self.H = 1 if self.open is None else self.open["H"]
        #: the zeros of an open module's lv standing for the inputs (l takes no u)
        self.lv_u = [0.0] * (0 if self.open is None else len(self.open["inputs"]))
        self.run_size = b.run_size
        # the start's kernels and hpgen_run_init through a PyDLL handle of the same library:
        # calls of well under a microsecond that keep the GIL (a CDLL call releases and takes
        # it back, 0.2-0.4 us each on a loaded machine); hpgen_advance releases it
        py = ctypes.PyDLL(str(b.library), handle=b.lib._handle)     # (no second dlopen)
        self.fns = {}
        for k in ("defect", "legendre", "guess", "margin"):
            fn = getattr(py, f"hpgen_kernel_{k}")
            kf = b.kernel_function(k)
            fn.argtypes, fn.restype = kf.argtypes, kf.restype
            self.fns[k] = fn
        self.run_init = py.hpgen_run_init
        self.run_init.argtypes = [ctypes.c_void_p] * 4
        self.run_init.restype = None
        self.plans = {}
        self.last = _NO_PLAN
        self.velocity_last = None        # (bytes of g flat, mu0 and lv; xi0)
        self._tls = threading.local()

    def _thread(self) -> _Thread:
        try:
            return self._tls.s
        except AttributeError:
            s = self._tls.s = _Thread(self.n, self.d, self.nz, self.H, self.run_size)
            return s

    def plan(self, h, steps, every, newton):
        """The Plan of these arguments, None when the generic path must check them (another
        type, or a check fails: it raises the error)."""
        if type(h) not in _FLOATS or type(steps) not in _INTS or type(every) not in _INTS:
            return None
        p = self.last                       # the last call's (a repeated call's)
        if p.h == h and p.steps == steps and p.every == every and p.newton is newton:
            return p
        key = (float(h), int(steps), int(every), id(newton))
        p = self.plans.get(key)
        if p is not None and p.newton is newton:
            self.last = p
            return p
        try:
            p = Plan(self.engine, h, steps, every, newton)
        except HpgenError:
            return None
        if len(self.plans) >= PLANS_MAX:
            self.plans.clear()
        self.plans[key] = self.last = p
        return p

    def simulate(self, g0, h, steps, xi0, mu0, every, newton, t0, u=None, params=None):
        """The Trajectory of Integrator.simulate(g0, h, steps, xi0, mu0, every, newton=newton,
        t0=t0, u=u, params=params), None when the generic path must run it; raises a step's
        failure as the generic path does (a closed module's after the first step only: the
        first step's retry is the generic path's)."""
        plan = self.plan(h, steps, every, newton)
        if plan is None or plan.steps > STEPS_MAX or (xi0 is None) == (mu0 is None):
            return None
        if type(t0) is float or type(t0) is int:
            t0 = float(t0)
            if not math.isfinite(t0):
                return None
        else:
            return None
        inputs = None
        if self.open is None:
            if u is not None or params is not None:     # the generic path checks them
                return None
        else:
            try:
                inputs = step_inputs(self.open, plan.steps, u, params, t0)
            except HpgenError:
                return None
        n, d, nn = self.n, self.d, self.n * self.n
        g = np.asarray(g0)
        v = np.asarray(xi0 if mu0 is None else mu0)
        if g.dtype is not _F64 or v.dtype is not _F64 or g.shape != (n, n) or \
                v.shape != (d,):
            return None
        K = plan.K
        s = self._thread()
        if s.cap < K <= ROWS_MAX:
            s.rows(K)
        views, ptr, fns = s.views, s.ptr, self.fns
        s.gT[...] = g
        v_in = views["xi"] if mu0 is None else views["mu"]
        v_in[...] = v
        total = sum(s.G[0].tolist()) + sum(v_in.tolist())
        if not total - total == 0.0:        # a non-finite entry (or the sum overflowed)
            return None
        fns["defect"](ptr["g"], ptr["e"])
        if not views["e"][0] <= self.defect_max:
            return None
        if inputs is None:
            views["hv"][0] = plan.h
            lv = ()
        else:
            views["hv"][...] = inputs.hv(plan.h, 0)
            views["lv"][...] = [0.0, inputs.t0] + self.lv_u + inputs.params
            lv = (ptr["lv"],)
        z = ptr["z"]
        if mu0 is None:
            fns["legendre"](ptr["g"], ptr["xi"], *lv, ptr["mu"])
        if self.explicit:                   # no Newton start: z = mu0 (FirstStep.start)
            z = ptr["mu"]
        elif mu0 is not None and not self._velocity(s, inputs is not None):
            return None
        if not self.explicit:
            fns["guess"](ptr["xi"], ptr["g"], ptr["mu"], ptr["hv"], z)
            if inputs is None:
                fns["margin"](z, ptr["hv"], ptr["m"])
                if not views["m"][0] > 0.0:             # the first step by continuation
                    return None
        if K <= ROWS_MAX:
            G, P, ga, pa = s.G, s.P, ptr["g"], ptr["mu"]
        else:
            G, P = np.empty((K, nn)), np.empty((K, d))
            G[0], P[0] = views["g"], views["mu"]
            ga, pa = _addr(G), _addr(P)
        self.run_init(s.run_addr, ptr["g"], ptr["mu"], z)
        # (an open run points into its input rows and parameters: kept alive over the call)
        keep = None if inputs is None else self.engine.backend.set_inputs(s.run_addr, inputs)
        done = self.lib.hpgen_advance(s.run_addr, plan.h, plan.steps, plan.every,
                                      plan.copts_addr, ga + 8 * nn, pa + 8 * d, s.status_addr)
        del keep
        st = s.status
        if st.code != abi.OK:
            if st.code < 0 or (st.step == 0 and inputs is None):   # C refused; the retry
                return None
            traj = trajectory(self.engine, done, G, P, st.as_dict(), plan.h, plan.every,
                              inputs, t0)
            raise traj.error
        # (copies: the rows are this thread's scratch; g row-major per record)
        gk = np.array(G[:K].reshape(K, n, n).transpose(0, 2, 1), order="C")
        mu = P[:K].copy() if K <= ROWS_MAX else P
        t = plan.times() if plan.t is None else plan.t.view() if not t0 else plan.t
        return Trajectory.made(t=t0 + t if t0 else t, g=gk, mu=mu, h=plan.h,
                               every=plan.every, jacobians=int(st.jacobians),
                               **counters.of_status(st), integrator=self.engine.owner,
                               inputs=inputs)

    def _velocity(self, s, is_open) -> bool:
        """xi0 from (g, mu) (and lv for an open module) of the staging block into it
        (StateMaps.velocity_flat, kept for the last of those by their bytes); False when it
        fails (the generic path raises)."""
        lv = (s.views["lv"].copy(),) if is_open else ()
        key = s.G[0].tobytes() + s.P[0].tobytes() + (lv[0].tobytes() if lv else b"")
        last = self.velocity_last
        if last is not None and last[0] == key:
            s.views["xi"][...] = last[1]
            return True
        try:
            xi = self.engine.maps.velocity_flat(s.views["g"].copy(), s.views["mu"].copy(),
                                                lv=lv)
        except HpgenError:
            return False
        self.velocity_last = (key, xi)
        s.views["xi"][...] = xi
        return True
