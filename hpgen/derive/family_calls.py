"""The options of the functions a family model's step calls (per body, per joint, per
potential): CasADi call nodes composed over MX (hpgen.derive.family_kernels) and, for the
Python backend, over their SX expansion (hpgen.codegen.pycallees).

``never_inline``: a call node where the function is used, printed once as a callee.
``jac_penalty`` 0: CasADi differentiates a call through the callee's own Jacobian function,
derived once, instead of one directional derivative per seed.
``der_options`` ``never_inline``: the derivative functions CasADi builds of a callee (its
Jacobian, forward and reverse sweeps) are never_inline too, so that an SX expansion of a
kernel over MX (the step's partial derivatives) keeps them as calls instead of inlining one
copy per use.
"""
from __future__ import annotations

CALL = {"never_inline": True, "jac_penalty": 0, "der_options": {"never_inline": True}}
