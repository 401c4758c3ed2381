"""Minimum-effort rest-to-rest slew of a rigid spacecraft on SO3 (hpgen.ocp).

    PYTHONPATH=. python examples/spacecraft_rest_to_rest.py [tableau]

The spacecraft is a free rigid body (principal inertia I) driven by body torques u = (u0, u1,
u2): the model file below (written next to the build cache; the torques enter through
``forces:``, the discrete Lagrange-d'Alembert principle, math.md sec. 9). hpgen.ocp.rest_to_rest
plans the transfer from rest at g0 to rest at gT in time T, minimizing sum_k |u_k|^2 h, with
the compiled HP step as the equality constraints of a casadi.Opti problem solved by IPOPT.

1. Principal-axis slew (about body axis 3 by theta_f): the continuous optimum is known,
   theta(t) = theta_f (3 s^2 - 2 s^3), s = t/T, torque u2(t) = I3 theta''(t) =
   I3 theta_f (6 - 12 s) / T^2, cost 12 I3^2 theta_f^2 / T^3. The table gives the discrete
   optimum's distance from it for halving h: the torque u_k against u2 at the step's midpoint
   t_k + h/2 (u_k is held over the step), the angle at the nodes, and the cost. The order
   observed is 2: Stormer-Verlet's order; with a higher-order tableau (gauss2) also 2, since
   the inputs are held constant over each step (a zero-order hold is a second-order
   approximation of a smooth control). Against the exact optimum among held inputs
   (``sampled_optimum``: the same problem without the scheme's error) the distance shrinks
   at the scheme's order: 2 for Stormer-Verlet, 4 for gauss2.
2. Three-axis slew: the planned inputs, re-simulated by ``integ.simulate(..., u=plan.u)``,
   reproduce the planned states (to 1e-9 in tests/unit/test_ocp.py).
"""
from __future__ import annotations

import sys
import tempfile
from pathlib import Path

import numpy as np

MODEL = """\
name: spacecraft_rest_to_rest
group: SO3
parameters: {I: [1.0, 2.0, 3.0]}
inputs: [u0, u1, u2]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)
forces: [u0, u1, u2]
"""
I3 = 3.0


def compile_spacecraft(tableau="stormer-verlet", **options):
    """The spacecraft's Integrator (the model file written to a temporary directory)."""
    import hpgen
    path = Path(tempfile.mkdtemp(prefix="hpgen-slew-")) / "spacecraft_rest_to_rest.yaml"
    path.write_text(MODEL)
    return hpgen.compile(path, tableau=tableau, tau="cay", rkmk="exact", **options)


def rotation(axis, angle):
    """exp(angle axis^) (Rodrigues)."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def sampled_optimum(steps, theta_f, T):
    """(torques (steps,), angles (steps+1,)) of the exact optimum among inputs held constant
    over each step (zero-order hold) of the double integrator I3 theta'' = u: minimizing
    sum u_k^2 subject to sum u_k = 0 and sum u_k (steps - k - 1/2) = I3 theta_f / h^2 gives
    u_k linear in the midpoint time, u_k = u*(t_k + h/2) / (1 - 1/steps^2) (the midpoint
    rule's sum of the continuous condition); angles from the exact hold-step map."""
    h = T / steps
    mid = (np.arange(steps) + 0.5) / steps
    u = I3 * theta_f * (6 - 12 * mid) / T ** 2 / (1 - 1 / steps ** 2)
    theta, omega = [0.0], 0.0
    for uk in u:
        theta.append(theta[-1] + h * omega + h * h * uk / (2 * I3))
        omega += h * uk / I3
    return u, np.array(theta)


def principal_axis_errors(integ, steps, theta_f=1.0, T=2.0):
    """(plan, errors) of the slew about body axis 3. errors: against the closed-form
    continuous optimum, max |u_k - u*(t_k + h/2)| (all axes), max |theta_k - theta*(t_k)|,
    |cost - cost*|; against the exact sampled (held-input) optimum (sampled_optimum),
    max |u_k - u_k^s| and max |theta_k - theta_k^s|."""
    from hpgen.ocp import rest_to_rest
    plan = rest_to_rest(integ, np.eye(3), rotation([0, 0, 1], theta_f), T, steps)
    mid = (plan.t[:-1] + plan.h / 2) / T
    torque = I3 * theta_f * (6 - 12 * mid) / T ** 2
    s = plan.t / T
    angle = np.arctan2(plan.g[:, 1, 0], plan.g[:, 0, 0])
    us, ths = sampled_optimum(steps, theta_f, T)
    off = np.abs(plan.u[:, :2]).max()
    return plan, (max(off, np.abs(plan.u[:, 2] - torque).max()),
                  np.abs(angle - theta_f * (3 * s ** 2 - 2 * s ** 3)).max(),
                  abs(plan.cost - 12 * I3 ** 2 * theta_f ** 2 / T ** 3),
                  max(off, np.abs(plan.u[:, 2] - us).max()), np.abs(angle - ths).max())


def convergence_table(integ, steps=(10, 20, 40, 80)):
    """Rows (steps, h, the five errors of principal_axis_errors, IPOPT iterations,
    IPOPT seconds)."""
    rows = []
    for N in steps:
        plan, errs = principal_axis_errors(integ, N)
        rows.append((N, plan.h, *errs, plan.iterations, plan.seconds))
    return rows


def three_axis(integ, steps=40, T=3.0):
    """(plan, re-simulated Trajectory) of a slew by 2 rad about (1, -2, 2)."""
    from hpgen.ocp import rest_to_rest
    from hpgen.runtime import NewtonOptions
    plan = rest_to_rest(integ, np.eye(3), rotation([1.0, -2.0, 2.0], 2.0), T, steps)
    traj = integ.simulate(plan.g[0], plan.h, steps, mu0=plan.mu[0], u=plan.u,
                          newton=NewtonOptions(simplified=False))
    return plan, traj


def main(argv):
    integ = compile_spacecraft(argv[0] if argv else "stormer-verlet")
    print(f"{integ.meta['module']}: principal-axis slew, theta_f = 1, T = 2")
    heads = ("|u-u*|", "|th-th*|", "|J-J*|", "|u-u^s|", "|th-th^s|")
    print(f"{'steps':>5} {'h':>6} " + " ".join(f"{x:>9} {'ord':>4}" for x in heads)
          + f" {'iter':>4} {'IPOPT s':>7}")
    prev = None
    for N, h, *rest in convergence_table(integ):
        errs, (it, sec) = rest[:5], rest[5:]
        cells = [f"{e:9.2e} {'' if prev is None else f'{np.log2(a / e):.2f}':>4}"
                 for e, a in zip(errs, prev or errs)]
        print(f"{N:5d} {h:6.4f} " + " ".join(cells) + f" {it:4d} {sec:7.3f}")
        prev = errs
    plan, traj = three_axis(integ)
    print(f"three-axis slew: {plan.iterations} IPOPT iterations, {plan.seconds:.3f} s, cost "
          f"{plan.cost:.6g}; re-simulated: max |g - g_plan| = "
          f"{np.abs(traj.g - plan.g).max():.1e}, max |mu - mu_plan| = "
          f"{np.abs(traj.mu - plan.mu).max():.1e}")


if __name__ == "__main__":
    main(sys.argv[1:])
