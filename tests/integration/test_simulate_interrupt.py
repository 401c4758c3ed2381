"""Ctrl-C stops a long ``simulate``: the run is advanced in slices of bounded wall time
(hpgen.runtime.states.Slices), a pending SIGINT raises KeyboardInterrupt between them, and
the exception carries ``.partial``, the Trajectory of the steps done, bitwise the start of
the uninterrupted run."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.runtime.states import Slices

ROOT = Path(__file__).resolve().parents[2]

SCRIPT = textwrap.dedent("""
    import json, sys
    import numpy as np
    import hpgen
    integ = hpgen.compile(sys.argv[1], cache_dir=sys.argv[2])
    g0, xi0, h, every = np.eye(3), np.array([0.3, 1.0, 0.2]), 0.01, 10_000
    print("ready", flush=True)
    try:
        integ.simulate(g0, h, 10**10, xi0=xi0, every=every)
        print(json.dumps({"interrupted": False}), flush=True)
    except KeyboardInterrupt as exc:
        part = exc.partial
        K = len(part.t)
        again = integ.simulate(g0, h, (K - 1) * every, xi0=xi0, every=every)
        print(json.dumps({
            "interrupted": True, "partial": bool(part.partial), "records": K,
            "same": again.g.tobytes() == part.g.tobytes()
                    and again.mu.tobytes() == part.mu.tobytes()
                    and again.t.tobytes() == part.t.tobytes()}), flush=True)
""")


def test_sigint_stops_a_long_simulate_promptly_with_the_partial_trajectory(compile_model,
                                                                           cache_dir):
    compile_model(EXAMPLES / "free_rigid_body.yaml")          # compiled: the child loads it
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    child = subprocess.Popen([sys.executable, "-c", SCRIPT,
                              str(EXAMPLES / "free_rigid_body.yaml"), str(cache_dir)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=env, cwd=ROOT)
    try:
        assert child.stdout.readline().strip() == "ready"
        time.sleep(1.0)
        assert child.poll() is None              # still running the long simulate
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert child.returncode == 0, err
    res = json.loads(out.strip().splitlines()[-1])
    assert res["interrupted"] and res["partial"]
    assert res["records"] > 1 and res["same"]


def test_slices_continue_one_run_bitwise(compile_model, monkeypatch):
    """simulate in slices of a few steps is bitwise simulate in one slice (the generic
    path on both backends; totals of Newton iterations summed over the slices)."""
    import hpgen.runtime.states as states
    integ = compile_model(EXAMPLES / "heavy_top.yaml")
    kw = dict(g0=np.eye(3), h=0.01, steps=30_000, xi0=np.array([0.3, 1.0, 0.2]), every=7)
    whole = integ.simulate(**kw)       # more than the fast path's steps: the generic path
    monkeypatch.setattr(states, "SLICE_FIRST", 5)
    monkeypatch.setattr(Slices, "advance", lambda self, run, span: states.States.advance(
        self, run, (min(span[0], 13),)))
    sliced = integ.simulate(**kw)
    for name in ("t", "g", "mu"):
        assert getattr(whole, name).tobytes() == getattr(sliced, name).tobytes(), name
    assert whole.newton_iterations == sliced.newton_iterations


@pytest.mark.parametrize("steps", [0, 1, 255, 256, 257])
def test_short_generic_runs_keep_their_length(compile_model, steps):
    integ = compile_model(EXAMPLES / "free_rigid_body.yaml")
    traj = integ.simulate(np.eye(3).tolist(), 0.01, steps, xi0=[0.3, 1.0, 0.2],
                          t0=0.5)                     # (lists: the generic path)
    assert len(traj.t) == steps + 1 and traj.t[0] == 0.5 and not traj.partial
    assert np.isfinite(traj.mu).all()
