"""Explicit splitting schemes compiled from the Lagrangian's structure.

``coefficients``: the catalog of composition coefficients (SplittingScheme, get_splitting,
SPLITTING_NAMES); ``structure``: recognition of l = 1/2 xi.M xi - V(g) (recognise);
``flows``: the step as a composition of exact sub-flows (splitting_step, CasADi).
A splitting scheme is chosen where a tableau is (``integrator: {tableau: split6-kahan-li}``,
``--tableau``); derive builds its step in the VPRK step's contract (hpgen.abi).
"""
from .coefficients import SPLITTING_NAMES, SplittingScheme, get_splitting, is_splitting

__all__ = ["SPLITTING_NAMES", "SplittingScheme", "get_splitting", "is_splitting",
           "splitting_step"]


def splitting_step(*args, **kw):
    """hpgen.splitting.flows.splitting_step (imports casadi)."""
    from .flows import splitting_step as f
    return f(*args, **kw)
