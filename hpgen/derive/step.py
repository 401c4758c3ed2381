"""The IR produced by the derive stage: one step of the discrete HP action sum, as CasADi
functions with a fixed calling convention, ready for code generation.

The kernels, their order and the sizes of their positional inputs and outputs are the
generated-module contract, hpgen.abi.KERNELS (inputs and outputs dense column vectors of
doubles, matrices flattened column-major, h a 1-vector); ``Kernel.inputs/outputs`` name the
arguments (e.g. ("z", "g", "p", "h")). The record row's layout is described in
hpgen.derive.record_kernel and checked by hpgen.abi.record_width.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from ..abi import KERNEL_NAMES

__all__ = ["KERNEL_NAMES", "Kernel", "DiscreteStep"]



@dataclass(frozen=True)
class Kernel:
    name: str                   # one of KERNEL_NAMES
    function: Any               # casadi.Function over SX, dense inputs/outputs as above
    inputs: tuple[str, ...]     # argument names, e.g. ("z", "g", "p", "h")
    outputs: tuple[str, ...]


@dataclass(frozen=True)
class OpenSpec:
    """What an open model's step vector hv = [h, t_k, u, params] holds (hpgen.abi).

    inputs: the control inputs' names (m); runtime_parameters: ((name, shape), ...) in order,
    their entries flat row-major in params (P); defaults: the P default values (the model
    file's); forced: some force is not identically zero; time_dependent: l or f uses t."""
    inputs: tuple
    runtime_parameters: tuple
    defaults: tuple
    forced: bool
    time_dependent: bool

    @property
    def m(self) -> int:
        return len(self.inputs)

    @property
    def P(self) -> int:
        return len(self.defaults)

    @property
    def H(self) -> int:
        return 2 + self.m + self.P


@dataclass(frozen=True)
class DiscreteStep:
    """One step (g_k, p_k) -> (g_{k+1}, p_{k+1}) of a Lie group VPRK method.

    unknowns: ((label, start, stop), ...) the blocks of z, e.g. ("Xi1", 0, 3).
    reduced: True for the Euler-Poincare step of a left-invariant Lagrangian (no g in F).
    """
    model_name: str
    group_name: str
    n: int
    d: int
    nz: int
    tableau_name: str
    tableau_order: int
    tau: str
    rkmk: str
    reduced: bool
    unknowns: tuple
    kernels: tuple               # tuple[Kernel, ...], in KERNEL_NAMES order
    section: str | None = None   # the scene's Poincare section text (None: kernel section = 1)
    legendre_quadratic: bool = False   # d2l/dxi2 free of xi: observe's xi is exact
    record_layout: tuple = ()    # ((name, offset, shape), ...): see hpgen.derive.record_kernel
    step_uses_g: bool = True     # residual or update_p depend on g
    record_uses_g: bool = True   # the record row depends on g
    record_uses_xi: bool = True  # the record row depends on xi (velocity_step needed)
    open_spec: OpenSpec | None = None  # an open model's step vector, else None (closed)
    explicit: bool = False       # (g1, p1) = update(z = p, g, p, h) needs no Newton (a splitting)

    @property
    def record_width(self) -> int:
        """w: the record row's length."""
        return sum(math.prod(shape) for _, _, shape in self.record_layout)

    def kernel(self, name: str) -> Kernel:
        for k in self.kernels:
            if k.name == name:
                return k
        raise KeyError(name)
