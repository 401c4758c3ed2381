"""The run loop of the C runtime's hpgen/runtime/c/hpgen_runs.c in Python (hpgen_run_step,
hpgen_advance, hpgen_advance_record, hpgen_advance_sections): the same order of operations
on lists of Python floats with the module's raw kernels, so that the Python backend's runs
are those of the C backend (bitwise for nz <= UNROLL_MAX, see hpgen.runtime.newton). One
step is newton.step_lists; the record row of advance_record is hpgen.runtime.record_row's.
numpy and the standard library only.
"""
from __future__ import annotations

import numpy as np

from ..abi import (GUARD_RATIO, NONFINITE, OK, PREDICTOR_COEFFICIENTS, PREDICTOR_HISTORY,
                   RECORD, STATUS_FIELDS)
from .guard import guard_ratio, guard_resolve
from .newton import (Kernels, NewtonMemory, NewtonOptions, _floats, _isfinite, all_finite,
                     step_lists)


#: the offsets z - G each substep of a composed step keeps for its predictor (HPGEN_CH in
#: hpgen_runtime.h)
COMPOSE_HISTORY = 6


class Run:
    """A run in progress (the C backend's ``hpgen_run``): state (g_k, p_k) flat, the last
    solution z, the predictor's offsets dz = [dz_{k-1}, dz_{k-2}, ...] (newest first,
    have_prev = len(dz) <= PREDICTOR_HISTORY of them; see _run_step), the Newton memory and
    the steps done k;
    vectors are lists of Python floats."""

    def __init__(self, g0, p0, z0, inputs=None):
        self.g, self.p, self.z = _floats(g0), _floats(p0), _floats(z0)
        self.inputs = inputs     # an open module's StepInputs (hpgen.runtime.inputs) or None
        self.dz = []
        self.have_prev = 0
        self.memory = NewtonMemory()
        self.k = 0
        self.s = None            # section(g_k, p_k) once evaluated (advance_sections)
        self.g_stale = False     # g is g_0, not g_k (advance_record without g)
        # a composed step (_composed_step): the substep fractions (() for the plain step),
        # substep i's offsets z - G at the previous steps cdz[i] (newest first; the first
        # c_have <= COMPOSE_HISTORY valid)
        self.compose = ()
        self.cdz = []
        self.c_have = 0

    def to_arrays(self) -> dict:
        """Every field as float64 / int64 arrays (a checkpoint: from_arrays of them continues
        bitwise as this run would). The kept J^{-1} is a tuple of floats (printed solver) or
        an (nz, nz) array (numpy solver); its dimension tells which."""
        lu = self.memory.lu
        flags = [self.k, self.have_prev, int(self.g_stale), -1 if lu is None else np.ndim(lu),
                 int(self.s is not None)]
        nz, ch = len(self.z), COMPOSE_HISTORY
        cdz = np.zeros((len(self.cdz), ch, nz))
        for i, rows in enumerate(self.cdz):
            cdz[i, :len(rows[:ch])] = rows[:ch]
        comp = {"compose": np.array(self.compose, dtype=np.float64),
                "c_have": np.array([self.c_have], dtype=np.int64), "cdz": cdz
                } if self.compose else {}
        return {**comp,
                "g": np.array(self.g, dtype=np.float64), "p": np.array(self.p, dtype=np.float64),
                "z": np.array(self.z, dtype=np.float64),
                "dz": np.array(self.dz, dtype=np.float64).reshape(len(self.dz), len(self.z)),
                "s": np.array([self.s or 0.0], dtype=np.float64),
                "lu": np.array([] if lu is None else lu, dtype=np.float64),
                "flags": np.array(flags, dtype=np.int64)}

    @classmethod
    def from_arrays(cls, a: dict) -> "Run":
        """The run to_arrays saved (Python floats again: bitwise the same values)."""
        k, have_prev, g_stale, lu_dim, has_s = (int(v) for v in a["flags"])
        run = cls(a["g"].tolist(), a["p"].tolist(), a["z"].tolist())
        run.dz = a["dz"].tolist()
        if "compose" in a:
            run.compose, run.cdz = tuple(a["compose"].tolist()), a["cdz"].tolist()
            run.c_have = int(a["c_have"][0])
        run.s = float(a["s"][0]) if has_s else None
        run.k, run.have_prev, run.g_stale = k, have_prev, bool(g_stale)
        lu = a["lu"]
        run.memory.lu = None if lu_dim < 0 else (np.array(lu) if lu_dim == 2
                                                 else tuple(lu.tolist()))
        return run


def new_status() -> dict:
    """A status as the C ``hpgen_status`` after hpgen_status_init (fields: abi.STATUS_FIELDS,
    all zero: code OK)."""
    return {name: (0.0 if kind == "d" else 0) for name, kind in STATUS_FIELDS}


def predictor_base(kern: Kernels, g, p, hv, open_module: bool) -> list:
    """G(g, p) = guess(velocity_step(g, p, 0), g, p, hv) like ``hpgen_predictor_base`` in C:
    the guess kernel at one Newton step of the Legendre transform from xi = 0 (an open
    module's velocity_step also takes hv)."""
    extra = (hv,) if open_module else ()
    xi = kern.velocity_step(g, p, [0.0] * len(p), *extra)[0]
    return kern.guess(xi, g, p, hv)[0]


def _predictors():
    """predict's six cases, each one comprehension over the entries with the coefficients
    bound to names (a loop over the offsets per entry, or indexing the coefficient tuples,
    would cost microseconds per step on the Python backend)."""
    assert len(PREDICTOR_COEFFICIENTS) == 6, "PREDICTOR_HISTORY changed: write its case here"
    (a,), (b0, b1), (c0, c1, c2), (d0, d1, d2, d3), (e0, e1, e2, e3, e4), \
        (f0, f1, f2, f3, f4, f5) = PREDICTOR_COEFFICIENTS

    def m1(G, d):
        return [g + a * x for g, x in zip(G, d[0])]

    def m2(G, d):
        return [g + (b0 * x + b1 * y) for g, x, y in zip(G, d[0], d[1])]

    def m3(G, d):
        return [g + ((c0 * x + c1 * y) + c2 * u) for g, x, y, u in zip(G, d[0], d[1], d[2])]

    def m4(G, d):
        return [g + (((d0 * x + d1 * y) + d2 * u) + d3 * v)
                for g, x, y, u, v in zip(G, d[0], d[1], d[2], d[3])]

    def m5(G, d):
        return [g + ((((e0 * x + e1 * y) + e2 * u) + e3 * v) + e4 * w)
                for g, x, y, u, v, w in zip(G, d[0], d[1], d[2], d[3], d[4])]

    def m6(G, d):
        return [g + (((((f0 * x + f1 * y) + f2 * u) + f3 * v) + f4 * w) + f5 * r)
                for g, x, y, u, v, w, r in zip(G, d[0], d[1], d[2], d[3], d[4], d[5])]
    return m1, m2, m3, m4, m5, m6


_PREDICTORS = _predictors()


def predict(G, dz) -> list:
    """G + the polynomial through the m = len(dz) offsets dz (newest first, 1 <= m <=
    PREDICTOR_HISTORY) extrapolated one step, entry by entry: t = c_0 dz_0, t += c_i dz_i
    with c = PREDICTOR_COEFFICIENTS[m - 1], then G + t (hpgen_runs.c's hpgen_predict, the
    same operations)."""
    return _PREDICTORS[len(dz) - 1](G, dz)


def explicit_step(kern: Kernels, run: Run, hv, st, with_g=True):
    """One explicit step of ``run`` (a splitting scheme, meta "explicit") like
    ``hpgen_explicit_step`` in C: z = p_k, (g1, p1) = update(z, g_k, p_k, hv) once (with_g
    False: update_p, g kept); no Newton: iterations 0, residual 0.0, no Jacobian; NONFINITE
    when the update is not finite (the run keeps its state). Returns the status code."""
    run.z = run.p
    if with_g:
        g1, p1 = kern.update(run.z, run.g, run.p, hv)
        bad = not (all_finite(g1) and all_finite(p1))
    else:
        g1, p1 = run.g, kern.update_p(run.z, run.g, run.p, hv)[0]
        bad = not all_finite(p1)
    st["iterations"], st["residual"] = 0, 0.0
    if bad:
        st.update(code=NONFINITE, step=run.k)
        return NONFINITE
    run.g, run.p = g1, p1
    run.k += 1
    return OK


def _run_step(kern: Kernels, run: Run, hv, opts: NewtonOptions, full: NewtonOptions, st,
              with_g=True):
    """One step of ``run`` like ``hpgen_run_step`` in C: predictor, step, run moved on success
    (with_g False: p only, g kept); st's counters updated (iterations, residual,
    total_iterations, jacobians; code and step on failure). Returns the status code.

    Predictor (hpgen_runs.c, hpgen_run_step): z_j = G_j + dz_j with G_j = predictor_base at
    step j's start; the start is G_k plus the polynomial through the last m offsets dz
    extrapolated one step (predict). Guard: a step predicted from three or more offsets whose
    root's offset jumps away from them (guard_ratio > GUARD_RATIO) is solved again from G
    (hpgen.runtime.guard: steps 0, 1, 2 are not), counted in st["guarded"]."""
    if run.inputs is not None:           # an open module: hv = [h, t_k, u_k, params]
        hv = run.inputs.hv(hv[0], run.k)
    if kern.explicit:
        return explicit_step(kern, run, hv, st, with_g)
    G = predictor_base(kern, run.g, run.p, hv, run.inputs is not None)
    dz = run.dz
    zs = predict(G, dz) if opts.predictor and dz else run.z
    first = run.k == 0
    # the first step (from the guess kernel: its start is checked) takes opts' Newton too,
    # except with a sparse J (full Newton there, as in C); where simplified Newton fails,
    # full Newton from the same start
    o1 = full if first and kern.sparse else opts
    code, g1, p1, z1, it, r, jacs = step_lists(kern, run.g, run.p, hv, zs, o1, run.memory,
                                               first, with_g)
    st["total_iterations"] += it
    st["jacobians"] += jacs
    if code != OK and first and o1.simplified:
        code, g1, p1, z1, it, r, jacs = step_lists(kern, run.g, run.p, hv, zs, full,
                                                   run.memory, True, with_g)
        st["total_iterations"] += it
        st["jacobians"] += jacs
    zs = z1
    if code != OK and opts.predictor and run.have_prev >= 1:
        # the extrapolated start failed (Newton diverged, or reached a root outside the
        # chart): retry from the plain warm start z_k before reporting anything
        code, g1, p1, zs, it, r, jacs = step_lists(kern, run.g, run.p, hv, run.z, opts,
                                                   run.memory, False, with_g)
        st["total_iterations"] += it
        st["jacobians"] += jacs
    if code == OK and opts.predictor and run.have_prev >= 3 and \
            guard_ratio(zs, G, dz) > GUARD_RATIO:
        g1, p1, zs, it, r = guard_resolve(kern, run, hv, full, G, (g1, p1, zs, it, r), st,
                                          with_g)
    st["iterations"], st["residual"] = it, r
    if code != OK:
        st.update(code=code, step=run.k)
        return code
    run.dz = [[a - b for a, b in zip(zs, G)]] + dz[:PREDICTOR_HISTORY - 1]
    run.have_prev = len(run.dz)
    run.z = zs
    run.g, run.p = g1, p1
    run.k += 1
    return OK


def _composed_step(kern: Kernels, run: Run, hv, opts: NewtonOptions, full: NewtonOptions, st,
                   with_g=True, after=None):
    """One step of ``run`` like ``hpgen_run_cstep`` in C: _run_step, or for a composed run
    (run.compose = (gamma_1, .., gamma_s)) the substeps _run_step with h_i = gamma_i h at the
    same k, each started from its own predictor (G at the first step), J^{-1} kept across
    substeps as across steps, an open model's substep at time t0 + (k + gamma_1 + ... +
    gamma_{i-1}) h; st["iterations"] summed over the substeps; on failure the run is back
    at its state before the step. Substep i's predictor extrapolates its own offsets at the
    last c_have steps. after(i, hv) (None in the runs; hpgen.runtime.linearize's
    per-substep derivative): called after each substep i that converged with the step vector
    it took; a code other than OK fails the step with that code. Returns the status code."""
    gam = run.compose
    if not gam:
        code = _run_step(kern, run, hv, opts, full, st, with_g)
        if code == OK and after is not None:
            hv1 = hv if run.inputs is None else run.inputs.hv(hv[0], run.k - 1)
            if (code := after(0, hv1)) != OK:
                st.update(code=code, step=run.k - 1)
        return code
    if not run.cdz:
        run.cdz = [[] for _ in gam]
    h, k = hv[0], run.k
    g0, p0, z0 = run.g, run.p, run.z
    inputs = run.inputs
    t0 = inputs.t0 if inputs is not None else 0.0
    c, it, zero = 0.0, 0, [0.0] * len(run.z)
    for i, gi in enumerate(gam):
        hs = gi * h
        run.k = k
        run.dz = run.cdz[i][:run.c_have] if run.c_have else [zero]
        run.have_prev = len(run.dz)
        if inputs is not None:
            inputs.t0 = t0 + (k + c) * h - k * hs
        try:
            code = _run_step(kern, run, [hs], opts, full, st, with_g)
            if code == OK and after is not None:
                if (code := after(i, [hs] if inputs is None else inputs.hv(hs, k))) != OK:
                    st.update(code=code, step=k)
        finally:
            if inputs is not None:
                inputs.t0 = t0
        it += st["iterations"]
        if code != OK:
            run.g, run.p, run.z, run.k = g0, p0, z0, k
            return code
        run.cdz[i] = run.dz[:COMPOSE_HISTORY]
        c += gi
    run.c_have = min(run.c_have + 1, COMPOSE_HISTORY)
    st["iterations"] = it
    return OK


def _loop_start(run: Run, h, opts: NewtonOptions, what: str, with_g: bool):
    """(hv, a new status, the full-Newton options of the first step) for a run loop; a loop
    that needs g refuses a run advanced without it (g_stale, like the C loops)."""
    if with_g and run.g_stale:
        raise ValueError(f"{what}: this run was advanced without its group element "
                         "(advance_record): start a new run")
    return [float(h)], new_status(), NewtonOptions(opts.tol, opts.maxit, False, opts.predictor)


def advance(kern: Kernels, run: Run, h, steps, every, opts: NewtonOptions):
    """Advance ``run`` by ``steps`` steps like ``hpgen_advance`` in C.

    Returns (steps done, records [(g flat, p)] (lists) of the global steps k % every == 0
    reached, status dict with code, step, iterations, total_iterations, residual, jacobians).
    """
    hv, st, full = _loop_start(run, h, opts, "advance", with_g=True)
    recs: list[tuple] = []
    for n in range(steps):
        if _composed_step(kern, run, hv, opts, full, st) != OK:
            return n, recs, st
        if run.k % every == 0:
            recs.append((run.g, run.p))
    st["step"] = run.k
    return steps, recs, st


def advance_record(kern: Kernels, row_of, run: Run, h, steps, every, opts: NewtonOptions,
                   skip_g):
    """Advance ``run`` like ``hpgen_advance_record`` in C: ``row_of(g, p, k, h) -> (code, row)`` at
    the global steps k % every == 0; skip_g: update_p only (run.g stays g_0, g_stale).
    Returns (steps done, rows (lists), status dict); a failed row stops the run after its
    step with code RECORD (the row is kept)."""
    hv, st, full = _loop_start(run, h, opts, "advance_record", with_g=False)
    rows: list = []
    if skip_g:
        run.g_stale = True
    for n in range(steps):
        if _composed_step(kern, run, hv, opts, full, st, not skip_g) != OK:
            return n, rows, st
        if run.k % every == 0:
            code, row = row_of(run.g, run.p, run.k, h)
            rows.append(row)
            if code != OK:
                st.update(code=RECORD, step=run.k)
                return n + 1, rows, st
    st["step"] = run.k
    return steps, rows, st


def advance_sections(kern: Kernels, section, chart_point, run: Run, h, steps, cap,
                     opts: NewtonOptions):
    """Advance ``run`` by up to ``steps`` steps recording the upward crossings of
    section(g, p) = 0, like ``hpgen_advance_sections`` in C (same formulas, same order of
    operations). section(g, p) -> [[s]], chart_point(z, g, hv, [theta]) -> [g_theta] (raw
    kernels). Returns (steps done, records [(k, t, g flat, p)], status dict)."""
    hv, st, full = _loop_start(run, h, opts, "advance_sections", with_g=True)
    recs: list[tuple] = []
    if run.s is None:
        run.s = section(run.g, run.p)[0][0]
    n = 0
    while n < steps and len(recs) < cap:
        s0, k, g0, p0 = run.s, run.k, run.g, run.p
        if _composed_step(kern, run, hv, opts, full, st) != OK:
            return n, recs, st
        n += 1
        s1 = section(run.g, run.p)[0][0]
        if not _isfinite(s1):
            st.update(code=NONFINITE, step=run.k)
            return n, recs, st
        run.s = s1
        if s0 < 0.0 and s1 >= 0.0:
            theta = s0 / (s0 - s1)
            p_c = [(1.0 - theta) * a + theta * b for a, b in zip(p0, run.p)]
            hv_k = hv if run.inputs is None else run.inputs.hv(hv[0], k)   # step k's
            if run.compose:     # hpgen_composed_section_point: one plain step S(theta h)
                hv_t = [theta * hv[0]] + hv_k[1:]
                G = predictor_base(kern, g0, p0, hv_t, run.inputs is not None)
                code, g_c, *_ = step_lists(kern, g0, p0, hv_t, G, full, NewtonMemory())
                if code != OK:
                    st.update(code=code, step=run.k)
                    return n, recs, st
            else:
                g_c = chart_point(run.z, g0, hv_k, [theta])[0]
            recs.append((k, (float(k) + theta) * float(h), g_c, p_c))
    st["step"] = run.k
    return n, recs, st
