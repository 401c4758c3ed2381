"""The ensembles' worker threads (hpgen.runtime.workers): every slice run once, on at most
the threads asked for, errors re-raised, one pool kept across calls and made again in a
forked child."""
import threading
import time

import pytest

from hpgen.runtime import workers


def _record(slices, threads):
    seen, names = [], set()

    def run(s):
        time.sleep(0.002)
        seen.append(s)
        names.add(threading.current_thread().name)

    workers.run_slices(slices, threads, run)
    return seen, names


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_every_slice_once_on_at_most_threads(threads):
    slices = [(i, i + 1) for i in range(13)]
    seen, names = _record(slices, 3 if threads == 1 else threads)
    assert sorted(seen) == slices
    workers._pool(5)                              # a larger pool: a call still uses its own count
    seen, names = _record(slices, threads)
    assert sorted(seen) == slices and len(names) <= threads
    if threads == 1:
        assert names == {threading.current_thread().name}


def test_pool_kept_and_remade_after_fork(monkeypatch):
    _record([(0, 1), (1, 2)], 2)
    pool = workers._pool(2)
    assert workers._pool(2) is pool and workers._pool(1) is pool
    monkeypatch.setitem(workers._POOL, "pid", -1)             # as a forked child sees it
    assert workers._pool(2) is not pool


def test_error_reraised_and_no_further_slices():
    started = []

    def run(s):
        started.append(s)
        if s == 0:
            raise ValueError("slice 0")
        time.sleep(0.01)

    with pytest.raises(ValueError, match="slice 0"):
        workers.run_slices(list(range(200)), 2, run)
    time.sleep(0.05)
    assert len(started) < 200


@pytest.mark.parametrize("threads", [1, 2])
def test_batch_start_refuses_too_many_substeps(compile_model, monkeypatch, threads):
    """A composed step of more substeps than the library takes (HPGEN_CS_MAX = 9) is refused
    by the batch start, on one thread and from a worker thread."""
    from pathlib import Path

    import numpy as np

    body = compile_model(Path(__file__).resolve().parents[2] / "examples"
                         / "free_rigid_body.yaml")
    cb = body.engine.backend
    monkeypatch.setattr(cb, "compose", (0.1,) * 10)
    with pytest.raises(ValueError, match="10 substeps"):
        cb.simulate_batch(np.broadcast_to(np.eye(3).ravel(), (20, 9)), np.ones((20, 3)), 0.1,
                          np.ones((20, 3)), 5, 1, body.engine.options(None), threads)
