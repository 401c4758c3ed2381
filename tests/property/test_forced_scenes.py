"""The forced scenes of issue 16 (examples/spacecraft_slew, underwater_vehicle_drag,
driven_pendulum, damped_top): what each shows, with the figures measured when written (C
backend; bounds 10x the measurement unless stated)."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.analysis.rkmk import ContinuousEquations
from hpgen.errors import ModelError
from hpgen.model import load_model
from hpgen.runtime import NewtonOptions
from hpgen.runtime.work import WorkSum

FULL = NewtonOptions(simplified=False)


def _scene(compile_model, name):
    path = EXAMPLES / f"{name}.yaml"
    model = load_model(path)
    sc = model.scene
    init = {"xi0": sc.xi0} if sc.xi0 is not None else {"mu0": sc.mu0}
    return model, compile_model(path), np.array(sc.g0), sc, init


def test_spacecraft_slew_converges_and_balances_spatial_momentum(compile_model):
    """The PD law brings R to the target (cos of the attitude error 1 - 5e-12 and |Omega|
    2e-6 by t = 50; bounds 1e-9 and 1e-4), and the spatial momentum changes by the applied
    spatial impulse: R_k p_k - R_0 p_0 against int_0^t R f dt (the node quadrature of
    hpgen.runtime.work on R_k f_k): measured 3.7e-9, 2.3e-10 at h = 0.05, 0.025 (ratio 15.8:
    order 4, the scheme's), bound 10x."""
    model, integ, g0, sc, init = _scene(compile_model, "spacecraft_slew")
    rec = integ.record(g0, sc.h, sc.steps, every=sc.every, **init)
    assert rec["cos_error"][-1] > 1 - 1e-9
    assert np.abs(rec["mu"][-1]).max() < 1e-4
    errs = []
    for h in (0.05, 0.025):
        steps = int(round(10 / h))
        tr = integ.simulate(g0, h, steps, newton=FULL, **init)
        xi = tr.xi()
        cont = ContinuousEquations(model)
        f = np.array([cont.applied(g, x, t=t)
                      for g, x, t in zip(tr.g, xi, tr.t)])
        spatial = np.einsum("kij,kj->ki", tr.g, f)
        impulse = np.stack([WorkSum(h).add(spatial[:, i]) for i in range(3)], axis=1)
        m = tr.momentum()
        errs.append(np.abs(m - m[0] - impulse).max())
    print(f"spatial momentum balance: {errs}")
    assert errs[0] < 3.7e-8 and errs[1] < 2.3e-9 and errs[0] / errs[1] > 12


def test_underwater_vehicle_reaches_terminal_velocity_and_matches_dop853(compile_model):
    """v -> (0, 0, v*), Omega -> 0, k v* + q v*^2 = T: |xi(100) - (0, 0, 0, 0, 0, v*)|
    measured 1.3e-7 (bound 1e-6); against DOP853 (rtol 1e-12) on the continuous forced
    equations over t in [0, 10]: mu error 1.7e-6 at h = 0.05 (bound 10x), and halving h
    divides it by 2^4 (Gauss 2: order 4, ratio > 12)."""
    model, integ, g0, sc, init = _scene(compile_model, "underwater_vehicle_drag")
    k, q, T = 0.2, 0.3, 1.0                       # the file's parameters
    v_star = (np.sqrt(k * k + 4 * q * T) - k) / (2 * q)
    tr = integ.simulate(g0, sc.h, 2000, every=2000, **init)
    xi_end = tr.xi()[-1]
    print(f"terminal: {np.abs(xi_end - [0, 0, 0, 0, 0, v_star]).max():.2e}")
    assert np.abs(xi_end - [0, 0, 0, 0, 0, v_star]).max() < 1e-6
    errs = []
    for h, every in ((0.05, 10), (0.025, 20)):
        tr = integ.simulate(g0, h, 20 * every, every=every, newton=FULL, **init)
        g_ref, mu_ref = ContinuousEquations(model).reference(g0, tr.mu[0], tr.t, rtol=1e-12)
        errs.append(np.abs(tr.mu - mu_ref).max())
    print(f"vs DOP853: mu {errs}")
    assert errs[0] < 1.7e-5 and errs[0] / errs[1] > 12


def test_driven_pendulum_stroboscopic_section(compile_model, tmp_path):
    """section: {every_t: T}: the samples are the node states at t = j T (bitwise simulate
    every T/h steps), C and Python alike; the chaotic attractor's samples spread over more
    than one turn of the angle's velocity range; a period that is not a whole number of
    steps is refused."""
    model, integ, g0, sc, init = _scene(compile_model, "driven_pendulum")
    T = sc.section_every_t
    N = int(round(T / sc.h))
    cr = integ.sections(g0, sc.h, 100 * N, every_t=T, **init)
    tr = integ.simulate(g0, sc.h, 100 * N, every=N, **init)
    assert len(cr) == 101 and np.array_equal(cr.mu, tr.mu) and np.array_equal(cr.g, tr.g)
    assert np.array_equal(cr.t, tr.t) and np.array_equal(cr.step, N * np.arange(101))
    assert np.abs(cr.t - T * np.arange(101)).max() <= 1e-12 * cr.t[-1]
    py = compile_model(EXAMPLES / "driven_pendulum.yaml", backend="python")
    assert np.array_equal(py.sections(g0, sc.h, 5 * N, every_t=T, **init).mu, cr.mu[:6])
    assert np.ptp(cr.mu[20:, 0]) > 1.0
    with pytest.raises(ModelError, match="every_t"):
        integ.sections(g0, sc.h, 10, every_t=1.05 * sc.h, **init)
    bad = tmp_path / "bad.yaml"
    bad.write_text((EXAMPLES / "driven_pendulum.yaml").read_text()
                   .replace("every_t: 9.42477796076938", "every_t: 9.5"))
    with pytest.raises(ModelError, match=r"scene.section.every_t: every_t / h"):
        load_model(bad)


def test_damped_top_energy_decays_as_the_work_says(compile_model):
    """E falls from 30.5 to 6.3 over t = 100 and E - W stays within 6.5e-6 of E0 (bound
    10x); the recorded power is -c |Omega|^2 at the records (to round-off); with c = 0
    (runtime parameter) work and power vanish and E is conserved as in heavy_top."""
    model, integ, g0, sc, init = _scene(compile_model, "damped_top")
    rec = integ.record(g0, sc.h, sc.steps, every=sc.every, **init)
    E, W = rec["energy"], rec["work"]
    assert E[-1] < 0.25 * E[0]
    assert np.abs((E - W) - E[0]).max() < 6.5e-5
    tr = integ.simulate(g0, sc.h, sc.steps, every=sc.every, **init)
    xi = tr.xi()
    assert np.abs(rec["power"] + 0.05 * np.einsum("ki,ki->k", xi, xi)).max() < 1e-13
    free = integ.record(g0, sc.h, sc.steps, every=sc.every, params={"c": 0.0}, **init)
    assert not np.any(free["work"]) and not np.any(free["power"])
    assert np.abs(free["energy"] - free["energy"][0]).max() < 1e-6 * abs(free["energy"][0])
