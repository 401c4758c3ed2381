"""hpgen: a compiler for Hamilton-Pontryagin integrators on Lie groups.

Importing hpgen is cheap and has no side effects: the compile-time stack (sympy, casadi,
jinja2) is imported only when ``hpgen.compile`` runs; ``hpgen.runtime`` needs numpy only.
"""
from __future__ import annotations

from .errors import (ArgumentError, BuildError, ConvergenceError, DomainError, HpgenError,
                     ModelError)
from .version import __version__

__all__ = ["compile", "build", "load", "sweep", "HpgenError", "ModelError", "ArgumentError",
           "BuildError", "ConvergenceError", "DomainError", "__version__"]


def compile(model, **options):
    """Compile a model file (path) into an integrator; see :func:`hpgen.api.compile`."""
    from .api import compile as _compile
    return _compile(model, **options)


def build(model, **options):
    """Compile a model file like ``compile`` and return what the compile produced (module
    directory, meta, derivation) as a CompiledModule; see :func:`hpgen.api.build`."""
    from .api import build as _build
    return _build(model, **options)


def load(path, backend=None):
    """Load a generated module directory; see :func:`hpgen.runtime.load`."""
    from .runtime import load as _load
    return _load(path, backend=backend)


def sweep(integ, **kwargs):
    """Run many members (initial states, steps) of an integrator on local threads or a Dask
    cluster; see :func:`hpgen.ensemble.sweep.sweep`."""
    from .ensemble.sweep import sweep as _sweep
    return _sweep(integ, **kwargs)
