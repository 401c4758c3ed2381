"""The contract between a generated module and hpgen.runtime, written once.

Standard library only and at the bottom of the import graph: the derive stage, codegen (which
renders kernels.c / kernels.py from these values), the runtime (loader, Newton in Python, the
run loops, the C backend through ctypes) and the tests read it; it imports nothing of hpgen.

What it holds:
- KERNELS: every kernel of a DiscreteStep, in order, with the size symbols of its positional
  inputs and outputs (``sizes`` gives their values). Inputs and outputs are dense float64
  column vectors, matrices flattened column-major (g.ravel(order="F")), h a 1-vector.
- the record row's layout conventions (``record_width``): meta.json "record" /
  DiscreteStep.record_layout.
- STATUS: the status codes of a step or a run with their messages (C ``HPGEN_<NAME>``).
- the Newton constants shared by the C runtime (hpgen/runtime/c) and its Python mirror
  (hpgen.runtime.newton / loop), which must stay bitwise equal: Python takes them from here,
  the C header writes them as literals (C_CONSTANTS) that the tests read back bitwise.
- ABI_VERSION (``hpgen_dims()[0]`` of a compiled kernels.c) and META_FORMAT (meta.json
  "format"): bump ABI_VERSION when an exported C signature or struct changes, META_FORMAT when
  a meta.json key is added, removed or changes meaning.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

#: version of the exported C API of kernels.c (hpgen_dims()[0]); checked when it is loaded
#: (4: hpgen_advance_batch_lanes and hpgen_lanes, the lane-wise ensembles, where emitted)
#: (5: hpgen_run holds the predictor offsets dz0..dz2 instead of zprev, zprev2)
#: (6: hpgen_run holds PREDICTOR_HISTORY offsets dz[0..5], the predictor is quintic)
#: (7: a sparse module's hpgen_run.lu holds the sparse QR of J, HPGEN_LU_SIZE doubles)
#: (8: hpgen_run holds the composition's substeps and their predictor histories;
#:  hpgen_run_set_compose)
#: (9: hpgen_linearize takes the run and steps it as simulate does, one signature for closed
#:  and open modules; the first step may take simplified Newton)
#: (10: hpgen_status counts the steps the guard solved again, "guarded")
ABI_VERSION = 10
#: version of meta.json's layout; the loader refuses any other (recompile the module)
#: (3: "group", the group's name, e.g. "SO3" or "[SO3, R3]")
#: (4: "jacobian", the Newton matrix's storage: dense, or sparse with J's CCS pattern)
#: (5: "explicit", true for a step that is one explicit update: the splitting schemes)
META_FORMAT = 5


# ---- kernels -----------------------------------------------------------------------------

@dataclass(frozen=True)
class KernelSpec:
    """One kernel: its name and the size symbols of its positional inputs and outputs.

    Size symbols: "nz" (unknowns of the step), "nn" (n*n, a group element), "d" (algebra
    dimension), "dd" (d*d), "nznz" (nz*nz), "1", "w" (the record row's width), "H" (the step
    vector: [h] for a closed model, [h, t_k, u, params] for an open one, see
    step_vector_size), "nzs" (nz*2d), "ss" (2d*2d)."""
    name: str
    inputs: tuple
    outputs: tuple
    doc: str


KERNELS = (
    KernelSpec("residual", ("nz", "nn", "d", "H"), ("nz",),
               "(z, g, p, h) -> F: stationarity conditions of the step"),
    KernelSpec("jacobian", ("nz", "nn", "d", "H"), ("nznz",),
               "(z, g, p, h) -> J = dF/dz, dense, column-major"),
    KernelSpec("residual_jacobian", ("nz", "nn", "d", "H"), ("nz", "nznz"),
               "(z, g, p, h) -> F, J in one evaluation"),
    KernelSpec("update", ("nz", "nn", "d", "H"), ("nn", "d"),
               "(z, g, p, h) -> g_{k+1}, p_{k+1}, explicit"),
    KernelSpec("guess", ("d", "nn", "d", "H"), ("nz",),
               "(xi, g, p, h) -> z0: Newton start from a velocity estimate"),
    KernelSpec("legendre", ("nn", "d"), ("d",), "(g, xi) -> mu = dl/dxi"),
    KernelSpec("hessian", ("nn", "d"), ("dd",), "(g, xi) -> d^2 l / dxi^2"),
    KernelSpec("energy", ("nn", "d"), ("1",), "(g, xi) -> <dl/dxi, xi> - l"),
    KernelSpec("momentum", ("nn", "d"), ("d",), "(g, p) -> Ad*_{g^{-1}} p (spatial)"),
    KernelSpec("defect", ("nn",), ("1",), "(g) -> distance of g from the group"),
    KernelSpec("margin", ("nz", "H"), ("1",),
               "(z, h) -> > 0 while every tau argument of the step is inside tau's domain"),
    KernelSpec("section", ("nn", "d"), ("1",),
               "(g, p) -> the scene's Poincare section s(g, mu = p) (1 without one)"),
    KernelSpec("chart_point", ("nz", "nn", "H", "1"), ("nn",),
               "(z, g, h, theta) -> g tau(theta h xi_{k+1}(z)), theta in [0, 1]"),
    KernelSpec("observe", ("nn", "d"), ("d", "1", "d", "1"),
               "(g, p) -> xi, E, m, e at a record (xi: one Newton step of dl/dxi = p from 0)"),
    KernelSpec("update_p", ("nz", "nn", "d", "H"), ("d",),
               "(z, g, p, h) -> p_{k+1} alone (update's p1)"),
    KernelSpec("velocity_step", ("nn", "d", "d"), ("d",),
               "(g, p, xi) -> xi - H^{-1}(dl/dxi(g, xi) - p): one Newton step"),
    KernelSpec("record", ("nn", "d", "d"), ("w",), "(g, p, xi) -> the scene's record row"),
    KernelSpec("step_partials", ("nz", "nn", "d", "H"), ("nzs", "nzs", "ss"),
               "(z, g, p, h) -> Fs = dF/ds, Yz = dY/dz, Ys = dY/ds: the step's "
               "partials in s = (eta, dp), g -> g tau(eta), p -> p + dp, "
               "Y = (eta_{k+1}, p_{k+1}) (hpgen.derive.linearize)"),
)
KERNEL_NAMES = tuple(k.name for k in KERNELS)
#: name -> (input size symbols, output size symbols)
SIGNATURES = {k.name: (k.inputs, k.outputs) for k in KERNELS}

#: Open models (forces, control inputs, runtime parameters or the time t): every
#: "H" input is the step vector hv = [h, t_k, u_0..u_{m-1}, params_0..params_{P-1}]
#: (t_k the start time of the step, u the control inputs held over the step, params the
#: runtime parameters, flat, in the model's order), and these kernels, which evaluate the
#: Lagrangian but take no h, take hv as one more, last input (t = t_k there).
OPEN_EXTRA = ("legendre", "hessian", "energy", "observe", "velocity_step", "record")
#: Open models: these kernels have more outputs (appended): step_partials's partials in the
#: step vector, FH = dF/dH (nz x H) and YH = dY/dH (2d x H) (hpgen.derive.linearize)
OPEN_OUTPUTS = {"step_partials": ("nzH", "sH")}


def step_vector_size(m: int, P: int, is_open: bool) -> int:
    """H: 1 for a closed module, 2 + m + P for an open one (m inputs, P runtime parameters)."""
    return 2 + m + P if is_open else 1


def signature(name: str, is_open: bool = False) -> tuple:
    """(input size symbols, output size symbols) of kernel ``name`` in a closed or open module."""
    ins, outs = SIGNATURES[name]
    return ((ins + ("H",) if is_open and name in OPEN_EXTRA else ins),
            outs + OPEN_OUTPUTS.get(name, ()) if is_open else outs)


def sizes(n: int, d: int, nz: int, w: int = 1, H: int = 1) -> dict:
    """The value of every size symbol for a module of dimensions n, d, nz, record width w and
    step vector size H."""
    return {"nz": nz, "nn": n * n, "d": d, "dd": d * d, "nznz": nz * nz, "1": 1, "w": w,
            "H": H, "nzs": 2 * d * nz, "ss": 4 * d * d, "nzH": nz * H, "sH": 2 * d * H}


# ---- the record row ----------------------------------------------------------------------

#: a record entry's name
RECORD_NAME_RE = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,63}\Z")


def record_width(layout, n: int, d: int) -> int:
    """Width w of a record row from its layout ((name, offset, shape), ...): names distinct
    identifiers (RECORD_NAME_RE), offsets contiguous from 0, shapes () (a scalar), (d,) (a
    vector) or (n, n) (a matrix, column-major in the row), at least one entry. Raises
    ValueError naming the first bad entry."""
    if not isinstance(layout, (list, tuple)) or not layout:
        raise ValueError("expected a non-empty list of (name, offset, shape)")
    offset, seen = 0, set()
    for entry in layout:
        ok = isinstance(entry, (list, tuple)) and len(entry) == 3
        if ok:
            name, off, shape = entry
            ok = (isinstance(name, str) and bool(RECORD_NAME_RE.match(name))
                  and name not in seen and isinstance(shape, (list, tuple))
                  and off == offset and tuple(shape) in ((), (d,), (n, n)))
        if not ok:
            raise ValueError(f"entry {entry!r} is not (distinct name, offset {offset}, shape "
                             f"() | ({d},) | ({n}, {n}))")
        seen.add(name)
        offset += math.prod(shape)
    return offset


# ---- status codes ------------------------------------------------------------------------

OK, NO_CONVERGENCE, NONFINITE, DOMAIN, RECORD, INVALID = 0, 1, 2, 3, 4, -1
#: (code, C name HPGEN_<name>, message), in code order; INVALID is the C API's answer to
#: arguments it rejects (never a step's outcome)
STATUS = (
    (OK, "OK", "ok"),
    (NO_CONVERGENCE, "NO_CONVERGENCE", "Newton did not converge"),
    (NONFINITE, "NONFINITE", "Newton diverged: a non-finite value (or a singular Jacobian) "
     "appeared"),
    # a start (the first step's) or a converged solution outside the chart; a Newton that
    # fails is NO_CONVERGENCE or NONFINITE wherever its iterates went
    (DOMAIN, "DOMAIN", "the converged solution left the chart map tau's domain "
     "(margin(z, h) <= 0)"),
    (RECORD, "RECORD", "a record row is not finite (or its velocity xi did not converge)"),
    (INVALID, "INVALID", "invalid argument"),
)
MESSAGES = {code: message for code, _, message in STATUS}

#: fields of the C ``hpgen_status`` (ctypes type letter: "q" long long, "d" double), in order
STATUS_FIELDS = (("code", "q"), ("step", "q"), ("iterations", "q"),
                 ("total_iterations", "q"), ("residual", "d"), ("jacobians", "q"),
                 ("guarded", "q"))
#: fields of the C ``hpgen_options``, in order (hpgen.runtime.newton.NewtonOptions)
OPTIONS_FIELDS = (("tol", "d"), ("maxit", "q"), ("simplified", "q"), ("predictor", "q"))


# ---- Newton ------------------------------------------------------------------------------

#: default tolerance: converged when |dz| <= tol (1 + |z|), inf-norms
DEFAULT_TOL = 1e-14
#: default cap on Newton iterations per step
DEFAULT_MAXIT = 50
#: round-off floor: stop when |dz| stopped decreasing while |dz| <= ROUNDOFF_FLOOR (1 + |z|)
ROUNDOFF_FLOOR = 1e-11
#: a sparse module's Newton takes a stall of its contracting iterates (theta > THETA_MAX with
#: a fresh J or one that contracted in the step) for the round-off noise of the solution while
#: |dz| <= STALL_MAX (1 + |z|) (hpgen_newton.c, hpgen_stalled). The noise grows with cond(J):
#: 5e-13 .. 5e-11 (1 + |z|) on the pendulum chain at 8 .. 64 links (pin frames)
STALL_MAX = 1e-9
#: a sparse module's simplified Newton keeps its J, from a step's third iterate on, while
#: |dz| <= KEEP_J_FLOOR (1 + |z|) (the many-body step's round-off noise in dz, 2e-12..1e-11 at
#: |z| = 13 on the 10-link chain): a rate above THETA_MAX there is the noise's. At
#: ROUNDOFF_FLOOR an aged J's slow rate passed for noise (joint velocity gaps 6.5e-11 over
#: 1e5 steps); at 1e-13 noise refreshed J at every step (hpgen_newton.c, hpgen_at_floor)
KEEP_J_FLOOR = 1e-12
#: simplified Newton: a contraction rate |dz_k| / |dz_{k-1}| above this refreshes J (or,
#: with a J fresh from this step, switches the step to full Newton). A refresh (J and its
#: inverse) costs 15-25 simplified iterations (residual + J^{-1} F) on the shipped Gauss
#: schemes: 0.2 trades iterations for refreshes (heavy top gauss3 h = 0.1: 6.6 -> 9.4
#: it/step, 0.50 -> 0.19 J/step, 16 % less time; docs/performance.md). At most
#: log(1e-15) / log(0.2) = 22 iterations from an O(1) start error, within DEFAULT_MAXIT.
THETA_MAX = 0.2
#: simplified Newton stops when its error estimate is <= SIMPLIFIED_TOL tol (1 + |z|)
SIMPLIFIED_TOL = 0.01
#: ... the estimate being te/(1 - te) |dz| with te = max(theta, THETA_FLOOR): theta from the
#: last two corrections underestimates a kept J's contraction while its slow modes are still
#: hidden under the fast ones (a close start stops before they show). Measured asymptotic
#: rates of a kept J^{-1} on the heavy top (gauss3, h = 0.08): 7e-3 one step old, 2.5e-2
#: at 4 steps, 5.5e-2 at 12 (benchmarks/newton_replay.py). Without the floor the quintic
#: predictor's Lagrange top left a coherent error that drifted e3.(R p) by 5e-12 over 8e4
#: steps (3e-14 with it, as with the quadratic predictor; docs/performance.md).
THETA_FLOOR = 0.05
#: kernels.py ITERATE (the Python backend's fused simplified iterates, hpgen.codegen.pyiterate)
#: returns this, not a status code, when the rate exceeds THETA_MAX: the caller refreshes J
REFRESH = -2
#: the velocity xi of a record row (Newton on dl/dxi = p from xi = 0, compiled into the
#: record loop): the tolerance and iteration cap of Integrator.velocity's defaults
VELOCITY_TOL = DEFAULT_TOL
VELOCITY_MAXIT = DEFAULT_MAXIT
#: largest nz whose Newton linear algebra kernels.py carries as straight-line Python
#: (bitwise the C runtime's; above it numpy/LAPACK, equal to C to round-off)
UNROLL_MAX = 12

#: a sparse Newton matrix's LU with a static pivot order (hpgen.codegen.static_lu) accepts a
#: pivot u_kk when |u_kk| > STATIC_PIVOT_TOL max_i |J_ik| (J's column k, permuted); else that J
#: is factored by the sparse QR, which needs no pivoting
STATIC_PIVOT_TOL = 1e-8

#: the predictor keeps the offsets z_j - G_j of this many past steps; the start of a step is G_k
#: plus the polynomial through the last m = min(steps done, PREDICTOR_HISTORY) offsets,
#: extrapolated one step (degree m - 1: quintic once six exist). Heavy top gauss2 h = 0.05:
#: 7.9 (ABI 5) -> 6.8 it/step, free body SV h = 0.1: 3.0 -> 2.0
#: (docs/performance.md, "Newton's start and stop").
PREDICTOR_HISTORY = 6
#: PREDICTOR_COEFFICIENTS[m - 1][i]: the weight of the offset of step k - 1 - i in the
#: extrapolation through m offsets, (-1)^i binomial(m, i + 1); summed in the order of i
#: (t = c_0 dz_0, t += c_i dz_i), in C and in Python alike
PREDICTOR_COEFFICIENTS = tuple(tuple(float((-1) ** i * math.comb(m, i + 1)) for i in range(m))
                               for m in range(1, PREDICTOR_HISTORY + 1))

#: the guard on an accepted step (hpgen_runs.c, hpgen.runtime.guard): a step predicted from
#: three or more offsets d_j = z_j - G_j whose root z has |(z - G) - d_0| > GUARD_RATIO
#: (max(|d_0 - d_1|, |d_0 - 2 d_1 + d_2|) + GUARD_FLOOR (1 + |z|)) (inf-norms) is solved
#: again from G; the threshold sits well between the ratios of normal runs and of a foreign
#: root (docs/numerics.md sec. 8, benchmarks/guard_ratio.py). GUARD_FLOOR is STALL_MAX: the
#: largest noise a solution keeps
GUARD_RATIO = 15.0
GUARD_FLOOR = STALL_MAX

#: the contract's values the C runtime defines (hpgen/runtime/c/hpgen_runtime.h: macro ->
#: value, written there as c_literal(value); tests/unit/test_abi.py reads them back)
C_CONSTANTS = {"HPGEN_ABI": ABI_VERSION, "HPGEN_ROUNDOFF_FLOOR": ROUNDOFF_FLOOR,
               "HPGEN_KEEP_J_FLOOR": KEEP_J_FLOOR, "HPGEN_STALL_MAX": STALL_MAX,
               "HPGEN_THETA_MAX": THETA_MAX, "HPGEN_SIMPLIFIED_TOL": SIMPLIFIED_TOL,
               "HPGEN_THETA_FLOOR": THETA_FLOOR, "HPGEN_VELOCITY_TOL": VELOCITY_TOL,
               "HPGEN_VELOCITY_MAXIT": VELOCITY_MAXIT, "HPGEN_PH": PREDICTOR_HISTORY,
               "HPGEN_STATIC_PIVOT_TOL": STATIC_PIVOT_TOL, "HPGEN_GUARD_RATIO": GUARD_RATIO,
               "HPGEN_GUARD_FLOOR": GUARD_FLOOR}


def c_literal(value) -> str:
    """A C literal of an int or a double that the C compiler reads back bitwise: repr of a
    float is the shortest decimal that rounds to it (C parses decimals correctly rounded)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"not a C number: {value!r}")
    if isinstance(value, int):
        return str(value)
    if not math.isfinite(value):
        raise ValueError(f"not a finite double: {value!r}")
    text = repr(value)
    if float(text) != value or ("." not in text and "e" not in text):
        raise ValueError(f"{value!r} has no exact short C literal")
    return text
