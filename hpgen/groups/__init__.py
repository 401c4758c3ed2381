"""Lie group catalog (stage 2): matrix forms, hat/vee, Ad, ad and the chart maps tau.

The catalog (base, catalog, maps, series) is CasADi code, loaded on first use of a name below;
``hpgen.groups.elements`` (numpy only: initial elements, quaternions, rotation vectors) is
imported by the runtime without the compile-time stack.
"""
from __future__ import annotations

import importlib

__all__ = ["TAU_KINDS", "FactorLayout", "LieGroup", "GROUP_NAMES", "group_from_spec"]
_LAZY = {"TAU_KINDS": "base", "FactorLayout": "base", "LieGroup": "base",
         "GROUP_NAMES": "catalog", "group_from_spec": "catalog"}


def __getattr__(name):
    if name in _LAZY:
        return getattr(importlib.import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
