"""The explicit splitting schemes (hpgen.splitting.flows.open_splitting_step) on an open
model: a heavy top with a time-dependent potential, a runtime parameter, a body torque of
(t, g, u) and a control input, against DOP853 at rtol 1e-12 on the continuous forced
equations (hpgen.analysis.rkmk.ContinuousEquations, derived from the model file, not from
the splitting code).

- order 2.0 +- 0.1 (split2) and 4.0 +- 0.2 (split4-suzuki) of the error at T = 1 (h = 0.05,
  0.025, 0.0125; the kicks at their own times t_k + c h, u held over the step);
- C and Python give the same nodes to round-off;
- a force that depends on xi is refused in one line naming the entry.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from hpgen.analysis.rkmk import ContinuousEquations
from hpgen.errors import ModelError
from hpgen.model import load_model_text

TOP = """name: forced_top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, A: 0.5, om: 2.0}
runtime_parameters: [Mg]
inputs: [u]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*(1 + 0.3*sin(t))*R[2,2]
forces: ["A*cos(om*t) + u", "0.3*R[2,0]", "0"]
"""
U, MG, T = 0.1, 1.5, 1.0
G0 = Rotation.from_rotvec([0.3, 0.2, 0.0]).as_matrix()
MU0 = np.array([1.0, 5.0, 6.0]) * np.array([0.2, 1.0, 3.0])


def _errors(integ, hs):
    eq = ContinuousEquations(load_model_text(TOP), u=np.array([U]), params=np.array([MG]))
    gT, muT = (a[-1] for a in eq.reference(G0, MU0, [T]))
    errs = []
    for h in hs:
        tr = integ.simulate(G0, h, round(T / h), mu0=MU0, every=round(T / h), u=[U],
                            params={"Mg": MG})
        errs.append(max(np.abs(tr.g[-1] - gT).max(), np.abs(tr.mu[-1] - muT).max()))
    return errs, np.log2(np.array(errs[:-1]) / np.array(errs[1:]))


@pytest.mark.parametrize("tableau,order,tol", [("split2", 2.0, 0.1),
                                               ("split4-suzuki", 4.0, 0.2)])
def test_forced_order(compile_model, tableau, order, tol):
    integ = compile_model(TOP, tableau=tableau)
    assert integ.meta.get("explicit") is True
    errs, orders = _errors(integ, (0.05, 0.025, 0.0125))
    print(tableau, "errors", errs, "orders", orders)
    assert np.all(np.abs(orders - order) <= tol), (errs, orders)


def test_backends_agree(compile_model):
    runs = [compile_model(TOP, tableau="split2", backend=b).simulate(
        G0, 0.05, 40, mu0=MU0, every=10, u=[U], params={"Mg": MG}) for b in ("c", "python")]
    assert np.abs(runs[0].g - runs[1].g).max() <= 1e-14
    assert np.abs(runs[0].mu - runs[1].mu).max() <= 1e-13


def test_velocity_dependent_force_refused(compile_model):
    with pytest.raises(ModelError) as e:
        compile_model(TOP.replace('"0.3*R[2,0]"', '"-0.2*xi[1]"'), tableau="split2",
                      backend="python")
    msg = str(e.value)
    assert "forces[1] (-0.2*xi[1]) depends on the velocity" in msg
    assert "integrator.tableau" in msg and "\n" not in msg
