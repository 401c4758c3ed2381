"""A run that records ``work`` cannot be resumed (issue 16): the work is accumulated from the
run's start by a rule that needs the first nodes (hpgen.runtime.work), so a resumed run is
refused with one line that says why and what to do, and the interrupted run's completed
chunks are left as they were (nothing half-written, nothing removed)."""
from __future__ import annotations

import pytest

from conftest import EXAMPLES
from hpgen.errors import ModelError
from hpgen.runtime.partial_run import PartialFolder
from hpgen.runtime.chunked_output import partial_dir, record_to_npz


def test_a_work_run_interrupted_after_two_chunks_is_refused_on_resume(compile_model, tmp_path,
                                                                    monkeypatch):
    integ = compile_model(EXAMPLES / "driven_pendulum.yaml")
    assert "work" in integ.record_names
    out = tmp_path / "run.npz"
    kw = dict(g0=[[1.0, 0.0], [0.0, 1.0]], h=0.1, steps=400, xi0=[0.0], chunk=100)
    commit, calls = PartialFolder.commit, []

    def interrupted_commit(self, prog, rec, snapshot):
        commit(self, prog, rec, snapshot)
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt

    monkeypatch.setattr(PartialFolder, "commit", interrupted_commit)
    with pytest.raises(KeyboardInterrupt):
        record_to_npz(integ, out, **kw)
    monkeypatch.setattr(PartialFolder, "commit", commit)
    parts = partial_dir(out)
    chunks = sorted(p.name for p in parts.glob("chunk_*.npz"))
    assert len(chunks) == 2

    with pytest.raises(ModelError, match="records work cannot be resumed") as err:
        record_to_npz(integ, out, resume=True, **kw)
    msg = str(err.value)
    assert "\n" not in msg and str(parts) in msg and "delete the folder and run it again" in msg
    assert sorted(p.name for p in parts.glob("chunk_*.npz")) == chunks

    # what the message asks for works: a fresh run (the folder removed) completes
    import shutil
    shutil.rmtree(parts)
    path, summary = record_to_npz(integ, out, **kw)
    assert summary["steps"] == 400 and summary["resumed_at"] == 0 and path.exists()
