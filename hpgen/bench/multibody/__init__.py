"""The N-link 3-D pendulum chain (capsules, ball joints, the first link pinned to the world)
as a benchmark scene outside hpgen: its state convention and energy (chain), an independent
reference solution (reference: reduced Newton-Euler equations, SciPy DOP853), and the peers
a multibody user would run instead, MuJoCo (mujoco_peer) and Pinocchio (pinocchio_peer);
hpgen's own runs of it (hpgen_chain: the model files' states, the streamed runner) and the
comparison of runners at equal cost (equal_cost).

The peers need the optional extra ``pip install 'hpgen[peers]'``; they import mujoco /
pinocchio only when called (:func:`require` raises a one-line HpgenError without them).
Importing this package loads numpy only.
"""
from __future__ import annotations

import importlib

from hpgen.errors import HpgenError

__all__ = ["require"]


def require(module: str):
    """Import an optional peer library (``mujoco`` or ``pinocchio``) or raise HpgenError."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise HpgenError(f"{module} is not installed ({exc}); the multibody peers need the "
                         "optional extra: pip install 'hpgen[peers]'") from None
