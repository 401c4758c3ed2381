"""The benchmark chain as hpgen runs it: examples/pendulum_chain.yaml (SE3^N, ball joints as
holonomic constraints) with :mod:`chain`'s conventions, and conversions between its states
and :class:`chain.ChainState`, vectorized over nodes.

The example's frames: body i's frame sits at the pin when the chain hangs straight down
(link i's centre is x_i + R_i (i + 1/2) b with b = (0, 0, -length)), xi_i = (omega_i, v_i) in
the body frame, v_i the velocity of that frame's origin. :func:`to_hpgen` gives (g, xi) of a
ChainState, :func:`from_hpgen` the ChainStates of K nodes (g (K, 4N, 4N), xi (K, 6N)).
The example's parameters (mass 1, b = (0, 0, -0.5), gravity 9.81, the capsule inertia J) are
those of the default :class:`chain.ChainSpec`; :func:`check_parameters` says so or raises.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from hpgen.errors import HpgenError

from .chain import ChainSpec, ChainState

MODEL = Path(__file__).resolve().parents[3] / "examples" / "pendulum_chain.yaml"


def _offsets(spec: ChainSpec) -> np.ndarray:
    """(N, 3): each link's centre in its frame, (i + 1/2) b."""
    b = np.array([0.0, 0.0, -spec.length])
    return (np.arange(spec.n)[:, None] + 0.5) * b


def check_parameters(spec: ChainSpec, model) -> None:
    """Raise HpgenError unless the loaded example's parameters are the spec's chain."""
    p = dict(model.parameters)
    same = (np.isclose(p["m"], spec.mass, rtol=1e-15) and np.isclose(p["grav"], spec.g, rtol=1e-15)
            and np.allclose(p["b"], [0.0, 0.0, -spec.length], rtol=1e-15)
            and np.allclose(p["J"], spec.inertia, rtol=1e-12))
    if not same:
        raise HpgenError(f"{MODEL.name}'s parameters are not those of {spec}: update one of them")


def to_hpgen(spec: ChainSpec, s: ChainState) -> tuple[np.ndarray, np.ndarray]:
    """(g (4N, 4N), xi (6N,)) of a ChainState in the example's frames."""
    n, off = spec.n, _offsets(spec)
    g, xi = np.eye(4 * n), np.zeros(6 * n)
    for i in range(n):
        g[4 * i:4 * i + 3, 4 * i:4 * i + 3] = s.R[i]
        g[4 * i:4 * i + 3, 4 * i + 3] = s.x[i] - s.R[i] @ off[i]
        xi[6 * i:6 * i + 3] = s.omega[i]
        xi[6 * i + 3:6 * i + 6] = s.R[i].T @ s.v[i] - np.cross(s.omega[i], off[i])
    return g, xi


def from_hpgen(spec: ChainSpec, g: np.ndarray, xi: np.ndarray) -> list:
    """The ChainStates of nodes g (K, 4N, 4N), xi (K, 6N)."""
    n, off = spec.n, _offsets(spec)
    K = len(g)
    blocks = g.reshape(K, n, 4, n, 4)
    idx = np.arange(n)
    R = blocks[:, idx, :3, idx, :3].transpose(1, 0, 2, 3)          # (K, N, 3, 3)
    t = blocks[:, idx, :3, idx, 3].transpose(1, 0, 2)              # (K, N, 3)
    w = xi.reshape(K, n, 6)[..., :3]
    v = xi.reshape(K, n, 6)[..., 3:]
    x = t + np.einsum("knij,nj->kni", R, off)
    vel = np.einsum("knij,knj->kni", R, v + np.cross(w, np.broadcast_to(off, w.shape)))
    return [ChainState(R[k], x[k], w[k], vel[k]) for k in range(K)]
