"""hpgen bench on forced models: the peers integrate the continuous forced Euler-Poincare
equations (+ f in mu', math.md sec. 9; forces of the state, of t and of constant inputs u,
the default runtime parameters), hpgen holds the same u over every step; the errors of both
against the DOP853 reference fall at the methods' orders, which they could not if the two
sides integrated different equations. Timings are never asserted on."""
from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import EXAMPLES

#: a forced top with a time-dependent torque, a control input and a runtime parameter
FORCED = """\
name: forced_top_u
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, c: 0.1, a: 0.4}
runtime_parameters: [Mg]
inputs: [u0]
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*R[2, 2]
forces: ["-c*xi[0] + a*cos(2*t) + u0", "-c*xi[1] - u0", "-c*xi[2] + a*R[2, 0]*sin(t)"]
scene:
  h: 0.05
  steps: 20
  initial: {g: {rotvec: [0.3, 0.2, 0.0]}, xi: [0.2, 1.0, 3.0]}
  u: [0.3]
"""
HS = [0.1, 0.05, 0.025]
RK4_HS = [0.05, 0.025, 0.0125]


def _rates(points):
    e = np.array([p.error for p in points])
    return np.log2(e[:-1] / e[1:])


def _bench(path, cache_dir, **kw):
    from hpgen.bench import run_bench
    return run_bench(path, T=1.0, schemes=[("gauss2", "cay", "exact")], h=HS, rk4_h=RK4_HS,
                     rtol=[1e-10], peers=["DOP853", "RK4-numpy", "RK4-C", "RATTLE"],
                     reference="dop853", min_time=0, min_repeats=1, samples=10,
                     cache_dir=cache_dir, write=False, log=lambda s: None, **kw)


@pytest.mark.parametrize("model", ["damped_top", "forced_top_u"])
def test_forced_peers_and_hpgen_agree_to_the_order(model, cache_dir, model_file):
    path = EXAMPLES / "damped_top.yaml" if model == "damped_top" else model_file(FORCED)
    res = _bench(path, cache_dir)
    hp = res.family("hpgen gauss2/cay/exact")
    assert len(hp) == 3 and all(p.ok for p in hp)
    assert np.all(np.abs(_rates(hp) - 4) < 0.3), [p.error for p in hp]      # gauss2: 4
    rk = res.family("RK4-C")
    assert np.all(np.abs(_rates(rk) - 4) < 0.3), [p.error for p in rk]      # RK4: 4
    for c, py in zip(rk, res.family("RK4-numpy")):          # same f(t, y), same arithmetic
        assert np.abs(c.y_end - py.y_end).max() <= 1e-13
    (dop,) = res.family("DOP853")
    assert dop.error < 1e-8
    for p in res.points:                 # the energy is not conserved: no drift figure
        assert math.isnan(p.energy_drift) and math.isfinite(p.group_defect)
    assert max(p.group_defect for p in hp) < 1e-13          # hpgen stays on the group
    assert not res.family("RATTLE") and any("RATTLE skipped" in n for n in res.notes)
    assert any("energy is not conserved" in n for n in res.notes)


def test_u_enters_every_side(cache_dir, model_file):
    """Another u moves the peers' f and hpgen's steps alike: the errors against the
    reference of that u stay at the order (above), and the end states move."""
    from hpgen.bench.crk4 import CRK4
    from hpgen.bench.problem import Problem
    path = model_file(FORCED)
    a, b = Problem(path, T=1.0), Problem(path, T=1.0, u=[-0.5])
    assert a.u.tolist() == [0.3] and b.u.tolist() == [-0.5]
    fa, fb = CRK4(a, cache_dir), CRK4(b, cache_dir)
    assert np.abs(fa.f(a.y0, 0.3) - fb.f(a.y0, 0.3)).max() > 0.1
    assert np.abs(fa.f(a.y0, 0.0) - fa.f(a.y0, 0.3)).max() > 1e-3      # f depends on t
    res = _bench(path, cache_dir, u=[-0.5])
    assert np.all(np.abs(_rates(res.family("hpgen gauss2/cay/exact")) - 4) < 0.3)


@pytest.mark.parametrize("kw, parts", [
    (dict(u=[1.0, 2.0]), ["option u", "shape (1,)"]),
    (dict(u=["1"]), ["option u", "strings"]),
])
def test_bad_u(cache_dir, model_file, kw, parts):
    from hpgen.errors import ModelError
    with pytest.raises(ModelError) as e:
        _bench(model_file(FORCED), cache_dir, **kw)
    for p in parts:
        assert p in str(e.value)


def test_a_time_varying_scene_u_is_refused(model_file, cache_dir):
    from hpgen.bench.problem import Problem
    from hpgen.errors import ModelError
    with pytest.raises(ModelError, match="constant u"):
        Problem(model_file(FORCED.replace("u: [0.3]", 'u: ["0.3*t"]')))


def test_cli_bad_u_is_one_line_exit_2(model_file, tmp_path, capsys):
    from hpgen.cli import main
    code = main(["bench", model_file(FORCED), "--u", "1", "2", "--out", tmp_path / "b"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "option u" in err and "shape (1,)" in err
    assert not (tmp_path / "b").exists()
