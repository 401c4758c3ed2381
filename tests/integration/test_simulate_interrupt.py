"""Ctrl-C stops a long ``simulate`` or ``record``: the run is advanced in slices of bounded
wall time (hpgen.runtime.engine.Sliced), a pending SIGINT raises KeyboardInterrupt between
them, and the exception carries ``.partial``, the Trajectory (Records) of the steps done,
bitwise the start of the uninterrupted run."""
from __future__ import annotations

import json
import os
import signal
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from conftest import EXAMPLES, child_process
ROOT = Path(__file__).resolve().parents[2]

SCRIPT = textwrap.dedent("""
    import json, sys
    import numpy as np
    import hpgen
    integ = hpgen.compile(sys.argv[1], cache_dir=sys.argv[2])
    run = getattr(integ, sys.argv[3])          # simulate or record
    g0, xi0, h, every = np.eye(3), np.array([0.3, 1.0, 0.2]), 0.01, 10_000

    def arrays(r):
        return ([r.t, r.g, r.mu] if sys.argv[3] == "simulate" else
                [r.t, *(r[name] for name in r.names)])

    print("ready", flush=True)
    try:
        run(g0, h, 10**10, xi0=xi0, every=every)
        print(json.dumps({"interrupted": False}), flush=True)
    except KeyboardInterrupt as exc:
        part = exc.partial
        K = len(part.t)
        again = run(g0, h, (K - 1) * every, xi0=xi0, every=every)
        print(json.dumps({
            "interrupted": True, "partial": bool(part.partial), "records": K,
            "same": all(a.tobytes() == b.tobytes()
                        for a, b in zip(arrays(again), arrays(part)))}), flush=True)
""")


@pytest.mark.parametrize("method", ["simulate", "record"])
def test_sigint_stops_a_long_run_promptly_with_the_partial_result(compile_model, cache_dir,
                                                                  method):
    compile_model(EXAMPLES / "free_rigid_body.yaml")          # compiled: the child loads it
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    with child_process([sys.executable, "-c", SCRIPT, str(EXAMPLES / "free_rigid_body.yaml"),
                        str(cache_dir), method], env=env, cwd=ROOT) as child:
        assert child.stdout.readline().strip() == "ready"
        time.sleep(1.0)
        assert child.poll() is None              # still running the long run
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    assert child.returncode == 0, err
    res = json.loads(out.strip().splitlines()[-1])
    assert res["interrupted"] and res["partial"]
    assert res["records"] > 1 and res["same"]


@pytest.mark.parametrize("model", ["heavy_top", "driven_pendulum"])
def test_slices_continue_one_run_bitwise(compile_model, monkeypatch, model):
    """simulate and record in slices of one step are bitwise simulate and record in the
    default slices (Newton totals summed over the slices; a forced model's work
    accumulated across them)."""
    import hpgen.runtime.engine as engine
    import hpgen.runtime.records as records
    import hpgen.runtime.states as states
    integ = compile_model(EXAMPLES / f"{model}.yaml")
    n, d = integ.n, integ.d
    kw = dict(g0=np.eye(n).tolist(), h=0.01, steps=3000,       # lists: the generic path
              xi0=[0.3, 1.0, 0.2][:d], every=7)
    whole, rec = integ.simulate(**kw), integ.record(**kw)
    monkeypatch.setattr(states, "SLICE_FIRST", 5)
    monkeypatch.setattr(records, "SLICE_FIRST", 5)
    monkeypatch.setattr(engine, "SLICE_SECONDS", 0.0)       # slices of one step from the 2nd
    sliced, rec1 = integ.simulate(**kw), integ.record(**kw)
    for name in ("t", "g", "mu"):
        assert getattr(whole, name).tobytes() == getattr(sliced, name).tobytes(), name
    assert whole.newton_iterations == sliced.newton_iterations
    assert rec.names == rec1.names and rec.t.tobytes() == rec1.t.tobytes()
    for name in rec.names:
        assert rec[name].tobytes() == rec1[name].tobytes(), name
    assert rec.newton_iterations == rec1.newton_iterations == whole.newton_iterations
    assert len(rec.t) == 3000 // 7 + 1


@pytest.mark.parametrize("steps", [0, 1, 255, 256, 257])
def test_short_generic_runs_keep_their_length(compile_model, steps):
    integ = compile_model(EXAMPLES / "free_rigid_body.yaml")
    traj = integ.simulate(np.eye(3).tolist(), 0.01, steps, xi0=[0.3, 1.0, 0.2],
                          t0=0.5)                     # (lists: the generic path)
    assert len(traj.t) == steps + 1 and traj.t[0] == 0.5 and not traj.partial
    assert np.isfinite(traj.mu).all()
