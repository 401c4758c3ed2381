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

:func:`run` is the benchmarks' hpgen runner: the module's C loop through
``Integrator.stream`` with ``every`` (only every ``every``-th node is recorded), in chunks whose
records fit in a memory bound; the clocks time the stream's calls alone (the C loop advancing
a chunk and copying its records out, plus the stream's per-chunk Python), and the record
velocity (``Trajectory.xi``: the Legendre inverse, a Newton solve per recorded node), the
energy and the joints' gaps are computed afterwards, on the recorded nodes only, with their
own clock (``observe_seconds``), as MuJoCo's energy is evaluated outside its rollout's clock
(mujoco_peer).
"""
from __future__ import annotations

import time
from dataclasses import dataclass
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


def node_arrays(spec: ChainSpec, g: np.ndarray, xi: np.ndarray, frames: str = "pin"):
    """(R (K, N, 3, 3), x (K, N, 3), omega (K, N, 3), v (K, N, 3)) of nodes g (K, 4N, 4N),
    xi (K, 6N) in the model's frames (ChainState's conventions, stacked over the nodes)."""
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
    return R, x, w, vel


def from_hpgen(spec: ChainSpec, g: np.ndarray, xi: np.ndarray, frames: str = "pin") -> list:
    """The ChainStates of nodes g (K, 4N, 4N), xi (K, 6N) in the model's frames."""
    R, x, w, vel = node_arrays(spec, g, xi, frames)
    return [ChainState(R[k], x[k], w[k], vel[k]) for k in range(len(g))]


def node_energy(spec: ChainSpec, R, x, w, v) -> np.ndarray:
    """(K,) total energy (J, potential zero at the pin) of :func:`node_arrays`' nodes: the
    sum of chain.energy's kinetic and potential parts, vectorized over the nodes."""
    kinetic = 0.5 * spec.mass * np.sum(v * v, axis=(1, 2)) + 0.5 * np.sum(
        spec.inertia * w * w, axis=(1, 2))
    return kinetic + spec.mass * spec.g * np.sum(x[..., 2], axis=1)


def node_gaps(spec: ChainSpec, R, x, w, v) -> np.ndarray:
    """(2,) chain.constraint_residual's (position, velocity) residuals, the largest over
    :func:`node_arrays`' nodes."""
    r = R @ spec.a                                                  # (K, N, 3) top - centre
    top, bottom = x + r, x - r
    gaps = np.concatenate([top[:, :1], top[:, 1:] - bottom[:, :-1]], axis=1)
    orth = np.swapaxes(R, -1, -2) @ R - np.eye(3)
    wr = np.cross(np.einsum("knij,knj->kni", R, w), r)
    gaps_v = np.concatenate([(v + wr)[:, :1], (v + wr)[:, 1:] - (v - wr)[:, :-1]], axis=1)
    return np.array([max(np.abs(gaps).max(), np.abs(orth).max()), np.abs(gaps_v).max()])


#: bytes of records one chunk of :func:`run` may hold
RECORD_MEMORY = 64e6


@dataclass(frozen=True)
class HpgenRun:
    """A run of :func:`run`: ``times`` (s) and ``energy`` (J, potential zero at the pin) of
    the recorded nodes 0, every, 2 every, ... (and the last); the joints' largest (position,
    velocity) gaps over them; the final ChainState; Newton iterations over all steps and
    ``guarded``, the steps the wrong-root guard solved again (hpgen.runtime.counters);
    ``seconds`` the wall time and ``cpu_seconds`` the thread's CPU time of the stream's calls
    alone; ``observe_seconds`` the CPU time of the record velocity, energy and gaps on the
    recorded nodes (not in ``seconds``)."""
    times: np.ndarray
    energy: np.ndarray
    gaps: np.ndarray
    last: ChainState
    iterations: int
    steps: int
    seconds: float
    cpu_seconds: float
    observe_seconds: float
    guarded: int = 0


def chunk_steps(spec: ChainSpec, steps: int, every: int, memory: float = RECORD_MEMORY) -> int:
    """Steps per chunk of :func:`run`: a multiple of ``every`` whose records (g (4N)^2 and
    mu 6N doubles each) take at most ``memory`` bytes (at least one record), at most steps."""
    record = 8 * (16 * spec.n * spec.n + 6 * spec.n)
    return int(min(max(steps, every), every * max(1, int(memory // record))))


def run(integ, spec: ChainSpec, g0, xi0, h: float, steps: int, every: int = 10,
        newton=None, frames: str = "pin", memory: float = RECORD_MEMORY) -> HpgenRun:
    """``steps`` steps of h of the compiled chain ``integ`` from (g0, xi0), every ``every``-th
    node recorded (the last step too when ``steps % every``: a separate one-step stream is not
    taken; the final state is the last record), streamed in chunks of :func:`chunk_steps`;
    newton: NewtonOptions or None (the module's default); frames: the model's, ``"pin"`` or
    ``"centre"``. Timing: see the module docstring."""
    for name, value in (("steps", steps), ("every", every)):
        if not isinstance(value, (int, np.integer)) or value < 1:
            raise ArgumentError(f"expected a positive integer, got {value!r}", field=name)
    chunk = chunk_steps(spec, steps, every, memory)
    stream = integ.stream(g0, h, steps, xi0=xi0, every=every, chunk=chunk, newton=newton)
    times, energies, gaps = [], [], np.zeros(2)
    seconds = cpu = observe = 0.0
    iterations = guarded = 0
    last = None
    while True:
        start, start_cpu = time.perf_counter(), time.thread_time()
        part = next(stream, None)
        cpu += time.thread_time() - start_cpu
        seconds += time.perf_counter() - start
        if part is None:
            break
        start_cpu = time.thread_time()
        iterations += int(part.newton_iterations)
        guarded += int(part.guarded)
        nodes = node_arrays(spec, part.g, part.xi(), frames)
        times.append(part.t)
        energies.append(node_energy(spec, *nodes))
        gaps = np.maximum(gaps, node_gaps(spec, *nodes))
        last = ChainState(*(a[-1] for a in nodes))
        observe += time.thread_time() - start_cpu
    if last is None:
        raise HpgenError("the stream yielded no records")
    return HpgenRun(np.concatenate(times), np.concatenate(energies), gaps, last, iterations,
                    int(steps), seconds, cpu, observe, guarded)
