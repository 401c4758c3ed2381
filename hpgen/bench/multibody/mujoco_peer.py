"""MuJoCo as a peer on the chain: the MJCF of :mod:`chain`'s N-link chain, and runs through
MuJoCo's own C rollout loop (``mujoco.rollout.rollout``: the steps and the recording run in
C; Python only hands over chunks of steps).

Model: nested bodies link0 ... link(N-1); body i's frame sits at its top joint point (body 0
at the world origin, body i at (0, 0, -length) in its parent's frame) with a ball joint there,
and its inertia is given explicitly (``<inertial>``: mass, centre (0, 0, -length/2),
``diaginertia`` = :func:`chain.capsule_inertia`), so that MuJoCo uses exactly the inertia of
the reference and of Pinocchio; the capsule geom is for viewing only (no contact: the contact
flag is off and contype = conaffinity = 0). No damping, armature or friction loss. MuJoCo's
body frame then has the orientation of :mod:`chain`'s link frame, and qpos / qvel follow the
convention of :func:`chain.from_joint`.

Energy: the model enables MuJoCo's energy computation (``<flag energy="enable"/>``):
after ``mj_forward`` on a state, ``data.energy`` holds its potential (gravity, zero at
z = 0) and kinetic (qvel' M qvel / 2) energy, which :func:`run` records on every
``sample``-th state of the rollout. (Inside ``mj_step`` the kinetic part is not re-evaluated
at the step's start state: it is left over from the previous evaluation, the last RK4
stage or the previous Euler step, so energy sensors or ``data.energy`` read during a
rollout lag; a fresh ``mj_forward`` on the recorded state does not.)

Integrators (MJCF ``integrator``): ``RK4``, ``Euler`` (semi-implicit Euler, MuJoCo's
default), ``implicitfast``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from hpgen.errors import ArgumentError

from . import require
from .chain import ChainSpec

INTEGRATORS = ("RK4", "Euler", "implicitfast")
CHUNK = 2000     # steps per rollout call (bounds the state array's memory)


def mjcf(spec: ChainSpec, dt: float, integrator: str = "RK4") -> str:
    """The MJCF text of the N-link chain (see the module docstring)."""
    if integrator not in INTEGRATORS:
        raise ArgumentError(f"expected one of {', '.join(INTEGRATORS)}, got {integrator!r}",
                            field="integrator")
    if not (np.isfinite(dt) and dt > 0):
        raise ArgumentError(f"expected a positive time step, got {dt!r}", field="dt")
    dt, g, mass = float(dt), float(spec.g), float(spec.mass)
    L, r = float(spec.length), float(spec.radius)
    inertia = " ".join(repr(float(v)) for v in spec.inertia)
    lines = [f'<mujoco model="chain{spec.n}">',
             (f'  <option timestep="{dt!r}" integrator="{integrator}" '
             f'gravity="0 0 {-g!r}">'),
             '    <flag contact="disable" energy="enable"/>',
             '  </option>',
             '  <worldbody>']
    indent = "    "
    for i in range(spec.n):
        pos = "0 0 0" if i == 0 else f"0 0 {-L!r}"
        lines += [f'{indent}<body name="link{i}" pos="{pos}">',
                  f'{indent}  <joint name="ball{i}" type="ball" pos="0 0 0"/>',
                  (f'{indent}  <inertial pos="0 0 {-L / 2!r}" mass="{mass!r}" '
                  f'diaginertia="{inertia}"/>'),
                  (f'{indent}  <geom type="capsule" fromto="0 0 0 0 0 {-L!r}" size="{r!r}" '
                  'contype="0" conaffinity="0"/>')]
        indent += "  "
    for i in range(spec.n):
        indent = indent[:-2]
        lines.append(f"{indent}</body>")
    lines += ['  </worldbody>', '</mujoco>']
    return "\n".join(lines) + "\n"


def model(spec: ChainSpec, dt: float, integrator: str = "RK4"):
    """The compiled MjModel of :func:`mjcf`."""
    mujoco = require("mujoco")
    return mujoco.MjModel.from_xml_string(mjcf(spec, dt, integrator))


@dataclass(frozen=True)
class MujocoRun:
    """A rollout: the final joint state, the energy (kinetic + potential, J; MuJoCo's own
    computation) of the states 0, sample, 2 sample, ... and of the final state at ``times``,
    the wall time of the rollout calls alone (s; ``cpu_seconds`` the thread's CPU time of the
    same calls: the rollout of one run steps in the calling thread), ``observe_seconds`` the
    CPU time of the energy evaluations (mj_setState + mj_forward per sampled state; not in
    ``seconds``). ``stable`` is False when MuJoCo reset the simulation (its reaction to
    non-finite or huge accelerations: the rollout's clock restarts) or an energy is not
    finite."""
    qpos: np.ndarray
    qvel: np.ndarray
    times: np.ndarray
    energy: np.ndarray
    seconds: float
    steps: int
    stable: bool
    cpu_seconds: float = float("nan")
    observe_seconds: float = 0.0


def run(spec: ChainSpec, qpos, qvel, dt: float, steps: int, integrator: str = "RK4",
        sample: int = 10, chunk: int = CHUNK) -> MujocoRun:
    """Step the chain ``steps`` times from (qpos, qvel) at t = 0 through MuJoCo's C rollout,
    ``chunk`` steps per call (rounded to a multiple of ``sample``)."""
    import time

    mujoco = require("mujoco")
    from mujoco import rollout

    for name, value in (("steps", steps), ("sample", sample), ("chunk", chunk)):
        if not isinstance(value, (int, np.integer)) or value < 1:
            raise ArgumentError(f"expected a positive integer, got {value!r}", field=name)
    chunk = max(sample, chunk // sample * sample)
    m = model(spec, dt, integrator)
    d = mujoco.MjData(m)
    full = mujoco.mjtState.mjSTATE_FULLPHYSICS.value
    state = np.empty(mujoco.mj_stateSize(m, full))

    def energy_of(row):
        mujoco.mj_setState(m, d, row, full)
        mujoco.mj_forward(m, d)
        return d.energy[0] + d.energy[1]

    d.qpos[:], d.qvel[:] = np.asarray(qpos, dtype=float), np.asarray(qvel, dtype=float)
    mujoco.mj_getState(m, d, state, full)
    marks, energy = [0], [energy_of(state)]
    done, seconds, cpu, observe, reset = 0, 0.0, 0.0, 0.0, False
    while done < steps:
        k = min(chunk, steps - done)
        start, start_cpu = time.perf_counter(), time.thread_time()
        states, _ = rollout.rollout(m, d, state[None], nstep=k)
        cpu += time.thread_time() - start_cpu
        seconds += time.perf_counter() - start
        start_cpu = time.thread_time()
        for j in range(sample - 1, k, sample):         # row j: the state after step done+j+1
            marks.append(done + j + 1)
            energy.append(energy_of(states[0, j]))
        observe += time.thread_time() - start_cpu
        state = states[0, -1].copy()
        done += k
        reset = reset or abs(state[0] - done * dt) > 1e-9 * (1.0 + done * dt)
    if marks[-1] != steps:
        marks.append(steps)
        energy.append(energy_of(state))
    mujoco.mj_setState(m, d, state, full)
    energy_arr = np.asarray(energy)
    return MujocoRun(d.qpos.copy(), d.qvel.copy(), dt * np.asarray(marks), energy_arr,
                     seconds, int(steps), not reset and bool(np.isfinite(energy_arr).all()),
                     cpu, observe)
