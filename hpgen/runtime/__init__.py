"""Runtime (stage 5): load a generated module and integrate with it.

Imports only the standard library and numpy (never casadi, sympy, jinja2 or the compile-time
hpgen stages), so a generated module runs where only numpy is installed.

  load(path, backend=None) -> Integrator       backend "c" (compiled once) or "python"
  Integrator.simulate(g0, h, steps, xi0=/mu0=, every=1) -> Trajectory
  Integrator.record(g0, h, steps, xi0=/mu0=, every=1) -> Records   (the scene's record list)
  ... newton=NewtonOptions(tol=, maxit=, simplified=, predictor=)  Newton settings of any run
  build_library(module_dir, cc=None, cflags=None) -> Path of the compiled kernels
"""
from .build import DEFAULT_CFLAGS, build_library
from .integrator import Integrator
from .loader import load, read_meta
from .newton import NewtonOptions
from .records import Records
from .trajectory import Trajectory

__all__ = ["load", "read_meta", "Integrator", "NewtonOptions", "Trajectory", "Records",
           "build_library", "DEFAULT_CFLAGS"]
