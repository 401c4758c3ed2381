"""Lie group catalog (stage 2): matrix forms, hat/vee, Ad, ad and the chart maps tau."""
from .base import TAU_KINDS, FactorLayout, LieGroup
from .catalog import GROUP_NAMES, group_from_spec

__all__ = ["TAU_KINDS", "FactorLayout", "LieGroup", "GROUP_NAMES", "group_from_spec"]
