"""The benchmark chain as hpgen runs it, in two model files of the same physics (SE3^N, ball
joints as holonomic constraints, the parameters of the default :class:`chain.ChainSpec`), and
conversions between their states and :class:`chain.ChainState`, vectorized over nodes.

Frames (``frames`` argument; xi_i = (omega_i, v_i) in the body frame, v_i the velocity of the
frame's origin):
- ``"pin"``, examples/pendulum_chain.yaml (:data:`MODEL`): body i's frame sits at the pin when
  the chain hangs straight down; link i's centre is t_i + R_i (i + 1/2) b, b = (0, 0, -length).
- ``"centre"``, examples/capsule_chain.yaml (:data:`CENTRE_MODEL`): body i's frame is the link
  frame at its centre; the translation t_i is the centre minus its place (i + 1/2) b in the
  straight chain (a world vector), so g = identity is still the straight chain.
:func:`to_hpgen` gives (g, xi) of a ChainState, :func:`from_hpgen` the ChainStates of K nodes
(g (K, 4N, 4N), xi (K, 6N)); :func:`check_parameters` says whether a loaded model is the
spec's chain or raises.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from hpgen.errors import ArgumentError, HpgenError

from .chain import ChainSpec, ChainState

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
MODEL = EXAMPLES / "pendulum_chain.yaml"
CENTRE_MODEL = EXAMPLES / "capsule_chain.yaml"
MODELS = {"pin": MODEL, "centre": CENTRE_MODEL}


def _places(spec: ChainSpec) -> np.ndarray:
    """(N, 3): (i + 1/2) b, each link's centre in the straight chain (and, in the pin frames,
    in its own frame)."""
    b = np.array([0.0, 0.0, -spec.length])
    return (np.arange(spec.n)[:, None] + 0.5) * b


def _check_frames(frames: str) -> None:
    if frames not in MODELS:
        raise ArgumentError(f"expected frames 'pin' or 'centre', got {frames!r}", field="frames")


def check_parameters(spec: ChainSpec, model, frames: str = "pin") -> None:
    """Raise HpgenError unless the loaded model's parameters are the spec's chain."""
    _check_frames(frames)
    p = dict(model.parameters)
    b = [0.0, 0.0, -spec.length]
    same = (np.isclose(p["m"], spec.mass, rtol=1e-15) and np.isclose(p["grav"], spec.g, rtol=1e-15)
            and np.allclose(p["b"], b, rtol=1e-15)
            and np.allclose(p["J"], spec.inertia, rtol=1e-12))
    if frames == "centre":
        same = same and np.allclose(p["a"], spec.a, rtol=1e-15)
    if not same:
        raise HpgenError(f"{MODELS[frames].name}'s parameters are not those of {spec}: update "
                         "one of them")


def to_hpgen(spec: ChainSpec, s: ChainState, frames: str = "pin") -> tuple[np.ndarray, np.ndarray]:
    """(g (4N, 4N), xi (6N,)) of a ChainState in the model's frames."""
    _check_frames(frames)
    n, place = spec.n, _places(spec)
    g, xi = np.eye(4 * n), np.zeros(6 * n)
    for i in range(n):
        g[4 * i:4 * i + 3, 4 * i:4 * i + 3] = s.R[i]
        xi[6 * i:6 * i + 3] = s.omega[i]
        if frames == "pin":
            g[4 * i:4 * i + 3, 4 * i + 3] = s.x[i] - s.R[i] @ place[i]
            xi[6 * i + 3:6 * i + 6] = s.R[i].T @ s.v[i] - np.cross(s.omega[i], place[i])
        else:
            g[4 * i:4 * i + 3, 4 * i + 3] = s.x[i] - place[i]
            xi[6 * i + 3:6 * i + 6] = s.R[i].T @ s.v[i]
    return g, xi


def from_hpgen(spec: ChainSpec, g: np.ndarray, xi: np.ndarray, frames: str = "pin") -> list:
    """The ChainStates of nodes g (K, 4N, 4N), xi (K, 6N) in the model's frames."""
    _check_frames(frames)
    n, place = spec.n, _places(spec)
    K = len(g)
    blocks = g.reshape(K, n, 4, n, 4)
    idx = np.arange(n)
    R = blocks[:, idx, :3, idx, :3].transpose(1, 0, 2, 3)          # (K, N, 3, 3)
    t = blocks[:, idx, :3, idx, 3].transpose(1, 0, 2)              # (K, N, 3)
    w = xi.reshape(K, n, 6)[..., :3]
    v = xi.reshape(K, n, 6)[..., 3:]
    if frames == "pin":
        x = t + np.einsum("knij,nj->kni", R, place)
        v = v + np.cross(w, np.broadcast_to(place, w.shape))
    else:
        x = t + place
    vel = np.einsum("knij,knj->kni", R, v)
    return [ChainState(R[k], x[k], w[k], vel[k]) for k in range(K)]
