"""Analysis of integrators and reference solutions (docstring only; import the modules).

Modules: ``check`` (the ``hpgen check`` report: observed order against a DOP853 reference,
energy, momentum map, group defect, symplecticity defect of the one-step map),
``symplectic`` (the canonical form of T*G in left trivialization and the step's Jacobian by
implicit differentiation), ``rkmk`` (the continuous equations and an explicit,
non-variational RKMK-RK4 for comparison), ``exact`` (the free rigid body in Jacobi elliptic
functions).
"""
