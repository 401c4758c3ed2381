"""Hand-written reference integrators, coded directly from the equations of the paper
(Bou-Rabee & Marsden, "Hamilton-Pontryagin Integrators on Lie Groups, Part I",
section "Lie Group VPRK Integrators") and from the classical literature, in NumPy only.

Nothing here imports hpgen: these modules are the independent side of the regression tests
in ``tests/regression/test_handwritten.py``.

- ``lie``           so(3) tools (hat, ad, ad*), the maps tau (cay, exp, skew) and their
                    trivialized tangents from the paper's formulas, and a Newton solver with
                    complex-step Jacobians.
- ``euler_poincare`` Euler-Poincare integrators on SO(3), eqs. cayhpvi, exphpvi, skewprojector.
- ``heavy_top``     Lie Stormer-Verlet (eqs. sv1-sv5), forward and backward variational Euler
                    for l(R, Omega) = 1/2 Omega.I Omega - Mg chi.(R^T e3), tau = cay or exp.
- ``flat``          classical Stormer-Verlet and the 3-stage Lobatto IIIA-IIIB pair on R^n.
- ``vprk``          the general s-stage Lie group VPRK method of the paper's theorem (eqs.
                    lievprk1 - lievprk, q = 0), any tableau, for the heavy top.
- ``moser_veselov`` the Moser-Veselov discrete rigid body, and what it coincides with.
- ``rattle_split``  RATTLE around kick / exact symmetric-top flow / kick on the N-link capsule
                    chain (the reference of ``tests/regression/test_rattle_split.py``; world
                    momentum, not hpgen's body-frame p: the test converts).

Convention shared by all modules (the regression tests depend on it): hpgen's state momentum
p_k is the node momentum (discrete Legendre transform at t_k) and NOT the paper's multiplier
mu_k; see ``euler_poincare`` and ``heavy_top`` for the conversions, derived from the action sum.
"""
