"""Control inputs u written as data: the scene's ``u:`` and the CLI's ``--u``.

A model with ``inputs: [u0, ..., u_{m-1}]`` takes u held over each step: step k (from
t_k = t0 + k h to t_{k+1}) uses the row u_k (hpgen.runtime.inputs; docs/numerics.md sec. 9,
F_i = f(G_i, Xi_i, t_k + c_i h, u_k)). Three ways to say u, each giving those rows:

- a constant: ``u: [0.5, 0.5, 0.5, 0.5]`` (m numbers; u_k the same for every step);
- expressions of the time t: ``u: ["0.5 + 0.1*sin(t)", 0.5, 0.5, 0.5]`` (m entries, each a
  number or a quoted expression in t and the model's fixed parameters, parsed like the force
  expressions by hpgen's whitelist parser, never evaluated as Python); u_k = u(t_k), the
  value at the step's start (a sample-and-hold, as a digital controller applies it: first
  order in h for a smooth u(t); write the t-dependence into ``forces:`` for the scheme's
  order);
- a table: ``u: {table: thrust.csv}`` or ``{table: thrust.npz, interpolation: linear}`` (a
  path relative to the model file; on the CLI relative to the working directory):
  * without a time column, row k is step k's input (one row per step; rows past the run's
    steps are not used, fewer rows are refused);
  * with a time column (strictly increasing times), u_k is the table's value at t_k:
    ``hold`` (default) the last row at or before t_k (a staircase; after the last time the
    last row stays), ``linear`` the linear interpolation between the rows around t_k
    (t_k must lie within the table's times). Times before the first row are refused.
  File formats: ``.npz`` with an array ``u`` (rows, m) (or (rows,) for m = 1) and optionally
  ``t`` (rows,); ``.csv`` with a header row naming the columns (the model's input names, in
  any order, and optionally ``t``) or without one: m columns (one row per step) or m + 1
  (the first one the time).

Every problem is a ModelError naming the file (the model file, or the table) and the field
(``scene.u``, ``scene.u[2]``, ``option u``, ``row 17`` of a table). numpy and sympy only.
"""
from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ModelError

INTERPOLATIONS = ("hold", "linear")
TABLE_SUFFIXES = (".npz", ".csv")
TABLE_KEYS = ("table", "interpolation")
#: the tolerance (relative to |h|) within which a step time counts as a table time
TIME_TOL = 1e-9


@dataclass(frozen=True, eq=False)
class ControlSpec:
    """u as written. kind: "constant" (``values``: m floats), "expressions" (``texts`` as
    written, ``exprs`` sympy scalars in the time symbol or numbers), "table" (``table``
    (rows, m) floats, ``times`` (rows,) or None for one row per step, ``interpolation``).
    ``names``: the model's input names; ``where``: (file, field) for messages."""
    kind: str
    names: tuple
    where: tuple = (None, "scene.u")
    values: tuple = ()
    texts: tuple = ()
    exprs: tuple = ()
    table: Any = None
    times: Any = None
    interpolation: str = "hold"
    #: the table's path (for messages), "" for the other kinds
    source: str = ""

    @property
    def m(self) -> int:
        return len(self.names)

    def _error(self, message: str, field: str | None = None) -> ModelError:
        head = f"table {self.source}: " if self.source else ""
        return ModelError(head + message, file=self.where[0], field=field or self.where[1])

    def rows(self, h: float, steps: int, t0: float = 0.0) -> np.ndarray:
        """u for a run of ``steps`` steps of size h from t0: (m,) when constant, else
        (steps, m) (row k held over step k); a run of 0 steps gets the row of t0, (m,)."""
        if self.kind == "constant":
            return np.array(self.values, dtype=np.float64)
        n = max(int(steps), 1)
        if self.kind == "table" and self.times is None:
            if len(self.table) < n:
                raise self._error(f"the table has {len(self.table)} rows, and the run needs "
                                  f"one per step ({n}; give a time column to sample it in t)")
            out = np.array(self.table[:n], dtype=np.float64)
        else:
            t = t0 + np.arange(n) * float(h)
            out = self._of_time(t, h)
        return out[0] if steps == 0 else out

    def _of_time(self, t, h) -> np.ndarray:
        if self.kind == "expressions":
            cols = []
            for j, e in enumerate(self.exprs):
                v = np.broadcast_to(np.asarray(evaluate(e, t), dtype=np.float64), t.shape)
                bad = np.flatnonzero(~np.isfinite(v))
                if len(bad):
                    k = int(bad[0])
                    raise self._error(f"u({self.names[j]}) = {self.texts[j]} is not finite at "
                                      f"step {k} (t = {t[k]:.17g})",
                                      field=f"{self.where[1]}[{j}]")
                cols.append(v)
            return np.stack(cols, axis=1)
        T, U, tol = self.times, self.table, TIME_TOL * abs(float(h))
        first = int(np.argmin(t))
        if t[first] < T[0] - tol:
            raise self._error(f"the table starts at t = {T[0]:.17g}, after the time "
                              f"{t[first]:.17g} of step {first}")
        if self.interpolation == "hold":
            idx = np.searchsorted(T, t + tol, side="right") - 1
            return np.array(U[np.clip(idx, 0, len(T) - 1)], dtype=np.float64)
        last = int(np.argmax(t))
        if t[last] > T[-1] + tol:
            raise self._error(f"the table ends at t = {T[-1]:.17g}, before the time "
                              f"{t[last]:.17g} of step {last} (linear interpolation does not "
                              "extrapolate)")
        tc = np.clip(t, T[0], T[-1])
        return np.stack([np.interp(tc, T, U[:, j]) for j in range(U.shape[1])], axis=1)


# ---- parsing -----------------------------------------------------------------------------
def parse_controls(raw, names, parameters, group, *, file=None, field="scene.u",
                   base=None, line=None) -> ControlSpec:
    """The ControlSpec of ``raw`` (the YAML value of ``u:`` or the CLI's --u tokens) for the
    inputs ``names``. parameters: the fixed parameters' exact values (runtime parameters as
    sympy symbols, which u may not use); base: the directory a table path is relative to."""
    names = tuple(names)
    m = len(names)

    def error(msg, sub=""):
        return ModelError(msg, file=file, field=field + sub, line=line)
    if not m:
        raise error("this model has no control inputs (inputs:), so it takes no u")
    if isinstance(raw, dict):
        unknown = [k for k in raw if k not in TABLE_KEYS]
        if unknown or "table" not in raw:
            raise error(f"expected {{table: FILE.npz | FILE.csv, interpolation: hold | "
                        f"linear}}, got keys {', '.join(map(str, raw)) or 'none'}")
        interp = raw.get("interpolation", "hold")
        if interp not in INTERPOLATIONS:
            raise error(f"expected one of {', '.join(INTERPOLATIONS)}, got {interp!r}",
                        ".interpolation")
        if not isinstance(raw["table"], str) or not raw["table"].strip():
            raise error("expected the path of a .npz or .csv file", ".table")
        path = Path(raw["table"])
        if base is not None and not path.is_absolute():
            path = Path(base) / path
        try:
            table, times = read_table(path, names)
        except ModelError as e:           # the table's own location, inside the message
            where = ":".join(str(p) for p in (e.file, e.field) if p)
            raise error(f"{where}: {e.message}", ".table") from None
        if times is None and interp != "hold":
            raise error("interpolation needs a table with a time column t", ".interpolation")
        return ControlSpec("table", names, (file, field), table=table, times=times,
                           interpolation=interp, source=str(path))
    if not isinstance(raw, list) or len(raw) != m:
        raise error(f"expected {m} entries (one per input: {', '.join(names)}), each a number "
                    "or an expression of t, or {table: FILE}, got "
                    + (f"{len(raw)} entries" if isinstance(raw, list) else type(raw).__name__))
    if all(type(v) in (int, float) for v in raw):
        vals = tuple(float(v) for v in raw)
        for j, v in enumerate(vals):
            if not math.isfinite(v):
                raise error(f"input {names[j]} is not finite ({v})", f"[{j}]")
        return ControlSpec("constant", names, (file, field), values=vals)
    texts, exprs = [], []
    for j, v in enumerate(raw):
        if type(v) in (int, float):
            if not math.isfinite(v):
                raise error(f"input {names[j]} is not finite ({v})", f"[{j}]")
            texts.append(repr(float(v)))
            exprs.append(float(v))
        elif isinstance(v, str) and v.strip():
            texts.append(v)
            exprs.append(_expression(v, parameters, group, file, f"{field}[{j}]", line))
        else:
            raise error(f"expected a number or an expression of t for input {names[j]}, got "
                        f"{type(v).__name__}", f"[{j}]")
    return ControlSpec("expressions", names, (file, field), texts=tuple(texts),
                       exprs=tuple(exprs))


def _expression(text, parameters, group, file, field, line):
    """One input's expression: the force grammar with t and the fixed parameters only."""
    from .expr import _parse_scalar
    from .symbols import TIME_SYMBOL
    try:
        expr, ev, _ = _parse_scalar(text, group, parameters, (), None, field,
                                    "an input expression", extra={"t": TIME_SYMBOL})
    except ModelError as e:
        raise e.located(file, field, line) from None
    extra = sorted(str(s) for s in expr.free_symbols if s != TIME_SYMBOL)
    if extra:
        raise ModelError(f"an input may depend on t and the fixed parameters only, and "
                         f"{text!r} uses {extra[0].replace('param:', '')} (no state, no runtime "
                         "parameter: u is computed before the run)", file=file, field=field,
                         line=line)
    return expr


def parse_cli_controls(tokens, names, parameters, group, interpolation=None) -> ControlSpec:
    """``--u`` on the command line: one token naming a .npz / .csv table, or m tokens, each
    a number or an expression of t (quote it for the shell)."""
    tokens = list(tokens)
    if len(tokens) == 1 and Path(tokens[0]).suffix.lower() in TABLE_SUFFIXES:
        raw = {"table": tokens[0]}
        if interpolation is not None:
            raw["interpolation"] = interpolation
        return parse_controls(raw, names, parameters, group, field="option u")
    if interpolation is not None:
        raise ModelError("--u-interpolation applies to a table with a time column",
                         field="option u-interpolation")
    raw = []
    for tok in tokens:
        try:
            raw.append(float(tok))
        except ValueError:              # an expression of t
            raw.append(tok)
    return parse_controls(raw, names, parameters, group, field="option u")


def controls_for(model, tokens=None, interpolation=None, file=None):
    """The ControlSpec of a command-line run: ``tokens`` (--u), else the scene's u; None
    for a model without inputs. A model with inputs and no u: ModelError naming scene.u."""
    if tokens is not None:
        exact = {k: v for k, v in model.parameters}
        return parse_cli_controls(tokens, model.inputs, exact, model.group, interpolation)
    if interpolation is not None:
        raise ModelError("--u-interpolation goes with --u FILE", field="option u-interpolation")
    spec = None if model.scene is None else model.scene.u
    if spec is None and model.inputs:
        raise ModelError(f"the model has control inputs ({', '.join(model.inputs)}); give them "
                         "as scene.u in the model file or with --u", file=None if file is None
                         else str(file), field="scene.u")
    return spec


def member_rows(spec, h, steps):
    """u for a sweep of members with steps h (a number, or one per member): shared rows,
    or (B, steps, m) when u depends on the time and the members' h differ."""
    hs = np.atleast_1d(np.asarray(h, dtype=np.float64))
    shared = spec.kind == "constant" or (spec.kind == "table" and spec.times is None)
    if len(hs) == 1 or shared or len(set(hs.tolist())) == 1:
        return spec.rows(float(hs[0]), steps)
    return np.stack([np.atleast_2d(spec.rows(float(x), steps)) for x in hs])


# ---- tables ------------------------------------------------------------------------------
def read_table(path: Path, names) -> tuple:
    """(table (rows, m), times (rows,) or None) of a .npz or .csv file (module docstring)."""
    m = len(names)
    suffix = path.suffix.lower()
    if suffix not in TABLE_SUFFIXES:
        raise ModelError(f"expected a .npz or .csv table, got {path.name!r}", file=str(path))
    if not path.is_file():
        raise ModelError("no such file", file=str(path))
    if suffix == ".npz":
        table, times = _read_npz(path, m)
    else:
        table, times = _read_csv(path, names)
    if not len(table):
        raise ModelError("the table has no rows", file=str(path))
    bad = np.argwhere(~np.isfinite(table))
    if len(bad):
        r, j = (int(i) for i in bad[0])
        raise ModelError(f"input {names[j]} is not finite ({table[r, j]})", file=str(path),
                         field=f"row {r}")
    if times is not None:
        if not np.isfinite(times).all():
            raise ModelError(f"the time t is not finite ({times[~np.isfinite(times)][0]})",
                             file=str(path), field=f"row {int(np.argmin(np.isfinite(times)))}")
        back = np.flatnonzero(np.diff(times) <= 0)
        if len(back):
            raise ModelError(f"the times must increase strictly; t = {times[back[0] + 1]:.17g} "
                             f"follows t = {times[back[0]]:.17g}", file=str(path),
                             field=f"row {int(back[0]) + 1}")
    table.setflags(write=False)
    return table, times


def _read_npz(path, m):
    try:
        with np.load(path, allow_pickle=False) as z:
            if "u" not in z.files:
                raise ModelError(f"expected an array named u (rows, {m}), found "
                                 f"{', '.join(z.files) or 'none'}", file=str(path))
            u, t = z["u"], (z["t"] if "t" in z.files else None)
    except ModelError:
        raise
    except (OSError, ValueError, EOFError) as e:
        raise ModelError(f"cannot read the table ({str(e).splitlines()[0][:100]})",
                         file=str(path)) from None
    if u.dtype.kind not in "fiu":
        raise ModelError(f"expected real numbers, got dtype {u.dtype}", file=str(path),
                         field="u")
    if m == 1 and u.ndim == 1:
        u = u[:, None]
    if u.ndim != 2 or u.shape[1] != m:
        raise ModelError(f"expected shape (rows, {m}), got {u.shape}", file=str(path),
                         field="u")
    if t is not None and (t.dtype.kind not in "fiu" or t.shape != (len(u),)):
        raise ModelError(f"expected {len(u)} real numbers (one time per row), got dtype "
                         f"{t.dtype}, shape {t.shape}", file=str(path), field="t")
    return (np.array(u, dtype=np.float64),
            None if t is None else np.array(t, dtype=np.float64))


def _read_csv(path, names):
    m = len(names)
    try:
        with open(path, newline="") as fh:
            rows = [r for r in csv.reader(fh) if r and any(c.strip() for c in r)]
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise ModelError(f"cannot read the table ({e})", file=str(path)) from None
    if not rows:
        raise ModelError("the table has no rows", file=str(path))
    header = None
    if any(not _is_number(c) for c in rows[0]):
        header, rows = [c.strip() for c in rows[0]], rows[1:]
        cols = list(names) + (["t"] if "t" in header else [])
        if sorted(header) != sorted(cols) or len(set(header)) != len(header):
            raise ModelError(f"expected the columns {', '.join(names)} (and optionally t), "
                             f"got {', '.join(header)}", file=str(path), field="row 0")
    width = len(header) if header else len(rows[0])
    if header is None and width not in (m, m + 1):
        raise ModelError(f"expected {m} columns (one per input: {', '.join(names)}) or "
                         f"{m + 1} (t first), got {width}", file=str(path), field="row 0")
    data = np.empty((len(rows), width))
    for i, r in enumerate(rows):
        if len(r) != width:
            raise ModelError(f"expected {width} columns, got {len(r)}", file=str(path),
                             field=f"row {i + (1 if header else 0)}")
        for j, c in enumerate(r):
            if not _is_number(c):
                raise ModelError(f"expected a number, got {c.strip()[:40]!r}", file=str(path),
                                 field=f"row {i + (1 if header else 0)}")
            data[i, j] = float(c)
    if header:
        order = [header.index(nm) for nm in names]
        return data[:, order], (data[:, header.index("t")] if "t" in header else None)
    return (data, None) if width == m else (data[:, 1:], data[:, 0])


def _is_number(text) -> bool:
    try:
        float(text.strip())
    except ValueError:
        return False
    return True


# ---- evaluation --------------------------------------------------------------------------
def evaluate(expr, t):
    """A parsed input expression (sympy, in the time symbol) at the times ``t`` (an array),
    by a walk over its tree with numpy (no code generation, nothing evaluated as text)."""
    import sympy as sp
    if isinstance(expr, float):
        return np.full(np.shape(t), expr)
    funcs = {sp.sin: np.sin, sp.cos: np.cos, sp.tan: np.tan, sp.exp: np.exp,
             sp.log: np.log}

    def walk(e):
        if e.is_Symbol:
            return t
        if e.is_Number or e.is_NumberSymbol:
            return float(e)
        if e.is_Add:
            out = walk(e.args[0])
            for a in e.args[1:]:
                out = out + walk(a)
            return out
        if e.is_Mul:
            out = walk(e.args[0])
            for a in e.args[1:]:
                out = out * walk(a)
            return out
        if e.is_Pow:
            return np.power(walk(e.args[0]), walk(e.args[1]))
        if e.func in funcs:
            return funcs[e.func](walk(e.args[0]))
        raise ModelError(f"cannot evaluate {str(e)[:40]} in an input", field="u")
    with np.errstate(all="ignore"):
        return walk(expr)
