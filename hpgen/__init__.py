"""hpgen: a compiler for Hamilton-Pontryagin integrators on Lie groups.

Importing hpgen is cheap and has no side effects. ``compile``, ``build``, ``load`` and
``sweep`` are the functions of hpgen.api, hpgen.runtime and hpgen.ensemble.sweep themselves
(their signatures and docstrings, for ``help`` and ``inspect``), imported on first access; the
compile-time stack (sympy, casadi, jinja2) is imported only when a compile derives a module,
and ``hpgen.runtime`` needs numpy only.
"""
from __future__ import annotations

import importlib

from .errors import (ArgumentError, BuildError, ConvergenceError, DomainError, HpgenError,
                     ModelError)
from .version import __version__

__all__ = ["compile", "build", "load", "sweep", "HpgenError", "ModelError", "ArgumentError",
           "BuildError", "ConvergenceError", "DomainError", "__version__"]

#: public name -> the module that defines it (imported on first access)
_LAZY = {"compile": "hpgen.api", "build": "hpgen.api", "load": "hpgen.runtime",
         "sweep": "hpgen.ensemble.sweep"}


def __getattr__(name):
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_LAZY))
