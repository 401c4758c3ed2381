"""The members of a sweep: their initial states and step sizes, checked once, and their chunks.

A sweep has B members, member i starting at (g0[i], xi0[i] or mu0[i]) with step h[i]; every
member runs the same ``steps`` steps and keeps a sample every ``every`` steps (K = steps //
every + 1 samples, sample 0 the initial state). ``g0`` and ``h`` given once are shared by all
members. Member order is the input order everywhere (chunks are contiguous slices).
numpy and the standard library only.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import ModelError
from ..runtime.args import _int, _step_size

#: error text of a params= sweep on a model without runtime parameters
NO_RUNTIME_PARAMETERS = "params sweeps need runtime_parameters in the model"


@dataclass(frozen=True, eq=False)
class Members:
    """Checked member inputs: g0 (B, n, n), init (B, d) (``kind`` "xi0" or "mu0"), h (B,),
    params {runtime parameter name: (B, *shape) values, member i's in row i} ({} without),
    u the control inputs (None without; shared: (m,) or (steps, m); ``u_per_member``: (B, m)
    or (B, steps, m), member i's in row i)."""
    g0: np.ndarray
    init: np.ndarray
    kind: str
    h: np.ndarray
    params: dict = field(default_factory=dict)
    u: np.ndarray | None = None
    u_per_member: bool = False
    steps: int = 0

    def __len__(self) -> int:
        return len(self.init)

    def slice(self, lo: int, hi: int) -> "Members":
        return Members(self.g0[lo:hi], self.init[lo:hi], self.kind, self.h[lo:hi],
                       {k: v[lo:hi] for k, v in self.params.items()},
                       self.u[lo:hi] if self.u_per_member else self.u, self.u_per_member,
                       self.steps)

    def take(self, idx) -> dict:
        """The runs' keyword arguments of members ``idx``: the initial states and, with
        runtime parameters, params with a leading member axis (simulate_batch's sweep)."""
        kw = {self.kind: self.init[idx]}
        if self.params:
            kw["params"] = {k: v[idx] for k, v in self.params.items()}
        if self.u is not None and self.u_per_member:
            u = self.u[idx]
            if u.ndim == 2 and len(u) == self.steps:      # (b, m) would read as (steps, m)
                u = np.repeat(u[:, None, :], self.steps, axis=1)
            kw["u"] = u
        elif self.u is not None:
            kw["u"] = self.u
        return kw


def members(integ, g0, xi0, mu0, h, params=None, u=None, steps=None) -> Members:
    """Members from the sweep arguments (shapes, finiteness and h != 0 checked here; the
    group defect and the Legendre transform are checked per member when it starts).
    u: shared (m,) or (steps, m), or per member (B, m) or (B, steps, m) (a (B, m) u with
    B == steps is the shared (steps, m)). ModelError naming the argument."""
    if (xi0 is None) == (mu0 is None):
        raise ModelError("give exactly one of xi0 (velocities) and mu0 (momenta), each (B, d)",
                         field="xi0" if xi0 is not None else "mu0")
    kind = "xi0" if xi0 is not None else "mu0"
    init = _finite(xi0 if xi0 is not None else mu0, kind)
    if init.ndim != 2 or init.shape[1] != integ.d or len(init) == 0:
        raise ModelError(f"expected an array of shape (B, {integ.d}) with B >= 1, got shape "
                         f"{init.shape}", field=kind)
    B, n = len(init), integ.n
    G = _finite(g0, "g0")
    if G.shape == (n, n):
        G = np.broadcast_to(G, (B, n, n))
    if G.shape != (B, n, n):
        raise ModelError(f"expected g0 of shape ({n}, {n}) or ({B}, {n}, {n}), got {G.shape}",
                         field="g0")
    H = np.asarray(h, dtype=object)
    if H.ndim == 0:
        H = np.full(B, _step_size(h, "h"))
    elif H.shape == (B,):
        H = np.array([_step_size(x, f"h[{i}]") for i, x in enumerate(H.tolist())])
    else:
        raise ModelError(f"expected a number or {B} numbers (one per member), got shape "
                         f"{H.shape}", field="h")
    U, per_member = _inputs(integ, u, B, steps)
    return Members(np.ascontiguousarray(G), init, kind, H, _params(integ, params, B), U,
                   per_member, int(steps or 0))


def _inputs(integ, u, B, steps):
    """(u as float64, per member?) of a sweep's ``u`` (see members)."""
    names = list((integ.open or {}).get("inputs") or ())
    if u is None:
        return None, False
    if not names:
        raise ModelError("this model has no control inputs (inputs:), so it takes no u",
                         field="u")
    m = len(names)
    a = _finite(u, "u")
    shared = [(m,)] + ([(steps, m)] if steps else [])
    if a.shape in shared:
        return a, False
    if a.shape == (B, m) or (steps and a.shape == (B, steps, m)):
        return a, True
    raise ModelError(f"expected u of shape ({m},) or (steps, {m}) shared, or ({B}, {m}) or "
                     f"({B}, steps, {m}) one per member (inputs {', '.join(names)}), got "
                     f"{a.shape}", field="u")


def _params(integ, params, B) -> dict:
    """{name: (B, *shape) float64} of a params sweep, each value one entry per member (names
    and values are checked again by the runs: hpgen.runtime.inputs)."""
    if params is None:
        return {}
    spec = dict((name, tuple(shape)) for name, shape in
                ((integ.open or {}).get("runtime_parameters") or ()))
    if not spec:
        raise ModelError(NO_RUNTIME_PARAMETERS, field="params")
    if not isinstance(params, dict):
        raise ModelError("expected a mapping {runtime parameter name: one value per member}",
                         field="params")
    out = {}
    for name, v in params.items():
        if name not in spec:
            raise ModelError(f"unknown runtime parameter {name!r}; expected one of "
                             f"{', '.join(spec)}", field="params")
        a = _finite(v, f"params.{name}")
        if a.shape != (B,) + spec[name]:
            raise ModelError(f"expected shape {(B,) + spec[name]} (one value per member), "
                             f"got {a.shape}", field=f"params.{name}")
        out[name] = a
    return out


def _finite(x, field) -> np.ndarray:
    from ..runtime.args import _non_numeric
    try:
        bad = _non_numeric(x, np.asarray(x))
        a = np.array(x, dtype=np.float64) if bad is None else None
    except (TypeError, ValueError):
        raise ModelError(f"expected an array of numbers, got {type(x).__name__}",
                         field=field) from None
    if a is None:
        raise ModelError(f"expected real numbers, got {bad}", field=field)
    if not np.isfinite(a).all():
        raise ModelError("has non-finite entries", field=field)
    return a


def run_length(steps, every) -> tuple[int, int, int]:
    """(steps, every, K samples) checked."""
    steps, every = _int(steps, "steps", 0), _int(every, "every", 1)
    return steps, every, steps // every + 1


def chunk_bounds(B: int, chunk_size) -> list[tuple[int, int]]:
    """Contiguous member slices [lo, hi) of at most ``chunk_size`` members."""
    size = _int(chunk_size, "chunk_size", 1)
    return [(lo, min(lo + size, B)) for lo in range(0, B, size)]


def default_chunk_size(B: int, slots: int) -> int:
    """About 4 chunks per worker thread (load balance, and a lost worker costs little),
    at least 1 member each."""
    return max(1, math.ceil(B / (4 * max(1, slots))))
