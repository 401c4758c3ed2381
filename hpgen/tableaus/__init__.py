"""Butcher tableaus for the VPRK / Hamilton-Pontryagin integrators (stage 3).

``ButcherTableau(name, A, b, order)`` validates itself (square A, nonzero weights b_j since the
discrete Hamilton-Pontryagin principle divides by them, sum(b) = 1); ``ButcherTableau.from_user``
computes the classical order (rooted-tree order conditions up to order 6). The catalog:
TABLEAU_NAMES, ``get_tableau(name)``, ``tableau_summary(name)``,
``resolve_tableau(name_or_tableau)``.
"""
from .catalog import (MAX_CHECKED_ORDER, TABLEAU_NAMES, ButcherTableau, compute_order,
                      get_tableau, resolve_tableau, rooted_trees, tableau_summary)

__all__ = ["ButcherTableau", "TABLEAU_NAMES", "get_tableau", "resolve_tableau", "compute_order",
           "rooted_trees", "MAX_CHECKED_ORDER", "tableau_summary"]
