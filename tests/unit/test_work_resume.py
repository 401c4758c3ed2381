"""A run that records ``work`` is resumed like any other: each committed chunk holds the work
accumulated so far (hpgen.runtime.work.WorkSum.state) next to the run's snapshot, so a run
killed after some chunks and resumed writes bitwise the uninterrupted run's file."""
from __future__ import annotations

import numpy as np
import pytest

from conftest import EXAMPLES
from hpgen.errors import ModelError
from hpgen.runtime.partial_run import STATE, PartialFolder
from hpgen.runtime.chunked_output import partial_dir, record_to_npz
from hpgen.runtime.work import WorkSum


def _interrupt_after(monkeypatch, n):
    commit, calls = PartialFolder.commit, []

    def interrupted_commit(self, *args, **kw):
        commit(self, *args, **kw)
        calls.append(1)
        if len(calls) == n:
            raise KeyboardInterrupt

    monkeypatch.setattr(PartialFolder, "commit", interrupted_commit)
    return commit


@pytest.mark.parametrize("chunk, every", [(100, 1), (37, 3), (2, 1)])
def test_a_work_run_killed_and_resumed_is_bitwise_the_uninterrupted_run(
        compile_model, tmp_path, monkeypatch, chunk, every):
    integ = compile_model(EXAMPLES / "driven_pendulum.yaml")
    assert "work" in integ.record_names
    kw = dict(g0=[[1.0, 0.0], [0.0, 1.0]], h=0.1, steps=400, xi0=[0.0], chunk=chunk,
              every=every)
    whole, _ = record_to_npz(integ, tmp_path / "whole.npz", **kw)

    out = tmp_path / "run.npz"
    commit = _interrupt_after(monkeypatch, 2)
    with pytest.raises(KeyboardInterrupt):
        record_to_npz(integ, out, **kw)
    monkeypatch.setattr(PartialFolder, "commit", commit)
    parts = partial_dir(out)
    assert len(list(parts.glob("chunk_*.npz"))) == 2
    with np.load(parts / "chunk_000001.npz") as f:
        assert STATE + "work_s" in f.files          # the accumulated work is kept

    path, summary = record_to_npz(integ, out, resume=True, **kw)
    assert summary["resumed_at"] > 0 and summary["steps"] == 400
    with np.load(whole) as a, np.load(path) as b:
        for name in ("t", *integ.record_names):
            assert a[name].tobytes() == b[name].tobytes(), name
        assert a["work"][-1] != 0.0


def test_a_resumed_work_run_without_its_saved_work_is_refused_in_one_line(
        compile_model, tmp_path, monkeypatch):
    integ = compile_model(EXAMPLES / "driven_pendulum.yaml")
    kw = dict(g0=[[1.0, 0.0], [0.0, 1.0]], h=0.1, steps=400, xi0=[0.0], chunk=100)
    out = tmp_path / "run.npz"
    commit = _interrupt_after(monkeypatch, 2)
    with pytest.raises(KeyboardInterrupt):
        record_to_npz(integ, out, **kw)

    def without_work(self, prog, rec, snapshot, work=None):   # as a folder without it
        commit(self, prog, rec, snapshot)

    monkeypatch.setattr(PartialFolder, "commit", without_work)
    parts = partial_dir(out)
    last = parts / "chunk_000001.npz"
    with np.load(last) as f:
        kept = {k: f[k] for k in f.files if not k.startswith(STATE + "work_")}
    np.savez(last, **kept)
    with pytest.raises(ModelError, match="do not hold the work") as err:
        record_to_npz(integ, out, resume=True, **kw)
    assert "\n" not in str(err.value) and str(parts) in str(err.value)


def test_work_sum_state_continues_bitwise():
    rng = np.random.default_rng(1)
    P = rng.standard_normal(50)
    whole = WorkSum(0.01).add(P)
    for cut in (5, 7, 20):            # (the first five nodes are fed together)
        a = WorkSum(0.01)
        first = a.add(P[:cut])
        b = WorkSum.restore(0.01, a.state())
        assert np.concatenate([first, b.add(P[cut:])]).tobytes() == whole.tobytes()
