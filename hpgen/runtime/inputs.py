"""The step vector of an open module (forces, control inputs, runtime parameters or the time t):
checking the user's ``u``, ``params`` and ``t0`` and building
hv = [h, t_k, u_k, params] for step k (hpgen.abi.step_vector_size; meta.json "open").

Conventions: t_k = t0 + k h (computed from k, never accumulated); u is (m,) (held for every
step) or (steps, m) (row k held over step k; an ensemble also takes one u per run, see
batch_inputs); params is a dict {runtime parameter name: value}
of overrides of the model file's defaults (a number, or an array of the parameter's shape).
Every problem is a one-line ArgumentError (a ValueError) naming the argument, raised before any
step runs. numpy and the standard library only.
"""
from __future__ import annotations

import math
import numbers

import numpy as np

from ..errors import ArgumentError
from .args import _array


class StepInputs:
    """What an open module's steps take besides (g, p, h): t0, the input rows U (one row
    when constant) and the flat runtime parameters. ``hv(h, k)`` is step k's step vector
    (a list of floats)."""
    __slots__ = ("t0", "rows", "params", "constant")

    def __init__(self, t0: float, rows: list, params: list):
        self.t0, self.rows, self.params = t0, rows, params
        self.constant = len(rows) == 1

    def hv(self, h: float, k: int) -> list:
        row = self.rows[0] if self.constant else self.rows[k]
        return [h, self.t0 + k * h, *row, *self.params]

    def at_record(self, h: float, k: int) -> list:
        """The step vector a record row after global step k is evaluated with: the time
        t0 + k h, the input of the step that ends there (step k - 1; step 0's at k = 0, the
        C loop's run step vector) and the parameters."""
        row = self.rows[0] if self.constant else self.rows[max(k - 1, 0)]
        return [h, self.t0 + k * h, *row, *self.params]


def check_t0(t0) -> float:
    if isinstance(t0, bool) or not isinstance(t0, numbers.Real) or not math.isfinite(t0):
        raise ArgumentError(f"expected a finite start time, got {t0!r}", field="t0")
    return float(t0)


def check_params(open_meta, params) -> list:
    """The flat runtime parameters: the defaults with ``params``'s overrides."""
    spec = [] if open_meta is None else open_meta["runtime_parameters"]
    if params is None or (isinstance(params, dict) and not params):
        return [] if open_meta is None else [float(v) for v in open_meta["defaults"]]
    if not isinstance(params, dict):
        raise ArgumentError(f"expected a dict {{runtime parameter name: value}}, got "
                         f"{type(params).__name__}", field="params")
    names = [name for name, _ in spec]
    if not names:
        raise ArgumentError("this model has no runtime parameters (declare them in the model "
                         "file's runtime_parameters to change them without recompiling)",
                         field="params")
    for key in params:
        if key not in names:
            raise ArgumentError(f"unknown runtime parameter {key!r}; expected one of "
                             f"{', '.join(names)}", field="params")
    flat, off = [float(v) for v in open_meta["defaults"]], 0
    for name, shape in spec:
        size = math.prod(shape)
        if name in params:
            what = "a number" if not shape else "an array"
            flat[off:off + size] = _array(params[name], tuple(shape), f"params[{name!r}]",
                                          what).ravel().tolist()
        off += size
    return flat


def check_u(open_meta, u, steps: int | None) -> list:
    """The input rows: [row] for a constant u (m,), steps rows for u (steps, m); ``steps``
    None: one step (``Integrator.step``), which takes u of shape (m,) only."""
    m = 0 if open_meta is None else len(open_meta["inputs"])
    if m == 0:
        if u is not None:
            raise ArgumentError("this model has no control inputs (declare them in the model "
                             "file's inputs)", field="u")
        return [[]]
    names = ", ".join(open_meta["inputs"])
    shapes = f"({m},)" if steps is None else f"({m},) or (steps, {m})"
    if u is None:
        raise ArgumentError(f"u is required: the model has {m} control input(s) ({names}); pass "
                         f"an array of shape {shapes}", field="u")
    try:
        ndim = np.ndim(u)
    except ValueError:                      # ragged: _array reports it
        ndim = 2
    if ndim > 1 and steps == 0:
        raise ArgumentError(f"u with one row per step needs steps >= 1 (a run of 0 steps still "
                            f"records its start, which takes a constant u of shape ({m},))",
                            field="u")
    shape: tuple[int, ...]
    if steps is None or ndim <= 1:
        shape, what = (m,), f"the inputs ({names}: shape ({m},)" + \
            (")" if steps is None else f" constant or ({steps}, {m}) one row per step)")
    else:
        shape = (steps, m)
        what = f"the inputs ({names}: ({m},) constant or ({steps}, {m}) one row per step)"
    a = _array(u, shape, "u", what, finite=False)
    bad = np.argwhere(~np.isfinite(a))
    if len(bad):
        where = tuple(int(i) for i in bad[0])
        step = "" if a.ndim == 1 else f"step {where[0]}, "
        raise ArgumentError(f"{step}input {open_meta['inputs'][where[-1]]} is not finite "
                            f"(u[{', '.join(map(str, where))}] = {a[where]})", field="u")
    return [a.tolist()] if a.ndim == 1 else a.tolist()


def _per_run_u(open_meta, u, B: int, steps: int) -> bool:
    """True when ``u`` holds one entry per run: (B, steps, m), or (B, m) unless B == steps
    (then (steps, m), one row per step shared by every run, as before)."""
    m = 0 if open_meta is None else len(open_meta["inputs"])
    try:
        shape = np.shape(u)
    except ValueError:                       # ragged: step_inputs reports it
        return False
    return m > 0 and (shape == (B, steps, m) or (shape == (B, m) and B != steps))


def batch_inputs(open_meta, B: int, steps: int, u=None, params=None, t0=0.0) -> list | None:
    """B StepInputs for an ensemble (None for a closed module): t0 shared; u shared ((m,) or
    (steps, m)) or one per run ((B, m) constant per run, (B, steps, m) one row per step;
    (B, m) with B == steps is read as the shared (steps, m)); each value of ``params``
    either of the parameter's shape (shared) or with a leading axis of length B (run b
    takes entry b: a sweep without recompiling)."""
    per_run_u = _per_run_u(open_meta, u, B, steps)
    if open_meta is None or (not isinstance(params, dict) and not per_run_u):
        one = step_inputs(open_meta, steps, u, params, t0)
        return None if one is None else [one] * B
    shapes = {name: tuple(shape) for name, shape in open_meta["runtime_parameters"]}
    per_run = set()
    for key, v in (params.items() if isinstance(params, dict) else ()):
        try:
            if key in shapes and np.shape(v) == (B,) + shapes[key]:
                per_run.add(key)
        except ValueError:                   # ragged: step_inputs reports it
            pass
    runs = []
    for b in range(B):
        p = params if not isinstance(params, dict) else \
            {k: (np.asarray(v, dtype=np.float64)[b] if k in per_run else v)
             for k, v in params.items()}
        try:
            runs.append(step_inputs(open_meta, steps, u[b] if per_run_u else u, p, t0))
        except ArgumentError as e:
            if not per_run_u or e.field != "u":
                raise
            raise ArgumentError(f"run {b}: {e.message}", field="u") from None
    return runs


def step_inputs(open_meta, steps: int | None, u=None, params=None,
                t0=0.0) -> StepInputs | None:
    """The checked StepInputs of a run of ``steps`` steps (None: one step, u of shape (m,)),
    or None for a closed module (which takes no u and no params)."""
    t0 = check_t0(t0)
    flat = check_params(open_meta, params)
    rows = check_u(open_meta, u, steps)
    if open_meta is None:
        return None
    return StepInputs(t0, rows, flat)
