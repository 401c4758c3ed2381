"""Runtime (stage 5): load a generated module and integrate with it.

Imports only the standard library and numpy (never casadi, sympy, jinja2 or the compile-time
hpgen stages), so a generated module runs where only numpy is installed.

  load(path, backend=None) -> Integrator       backend "c" (compiled once) or "python"
  Integrator.simulate(g0, h, steps, xi0=/mu0=, every=1) -> Trajectory
  Integrator.record(g0, h, steps, xi0=/mu0=, every=1) -> Records   (the scene's record list)
  ... newton=NewtonOptions(tol=, maxit=, simplified=, predictor=)  Newton settings of any run
  build_library(module_dir, cc=None, cflags=None) -> Path of the compiled kernels

Layout: ``integrator.Integrator`` is the front; every run goes through the run engine
(``engine.Engine``: run starts, the one start -> advance -> restart loop, ensembles) with an
output saying what is kept (``states``: Trajectory, ``records``: Records, ``sections``:
SectionCrossings and the stroboscopic section); ``first_step`` makes the first step's
Newton start, ``state_maps`` the Legendre transform and observables, ``prologue`` simulate's
fast path on C; the kernels, Newton and loops run in a backend (``backends`` Python,
``cbackend`` / ``cbatch`` C through ctypes).
"""
from .build import DEFAULT_CFLAGS, build_library
from .integrator import Integrator
from .loader import load, read_meta
from .newton import NewtonOptions
from .records import Records
from .trajectory import Trajectory

__all__ = ["load", "read_meta", "Integrator", "NewtonOptions", "Trajectory", "Records",
           "build_library", "DEFAULT_CFLAGS"]
