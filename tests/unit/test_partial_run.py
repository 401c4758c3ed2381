"""hpgen.runtime.partial_run.interrupts_deferred: a SIGINT that arrives while a chunk or the
output file is written is delivered after the write, as the KeyboardInterrupt the chunked
run saves on (raised inside zipfile's writer it became a ValueError and a traceback); and
Progress's totals, the run's counters among them, saved and read back."""
from __future__ import annotations

import os
import signal

import numpy as np
import pytest

from hpgen.runtime.partial_run import interrupts_deferred
from hpgen.runtime.trajectory import write_npz


def test_sigint_during_a_deferred_write_is_raised_after_it(tmp_path):
    path = tmp_path / "chunk.npz"
    with pytest.raises(KeyboardInterrupt):
        with interrupts_deferred():
            os.kill(os.getpid(), signal.SIGINT)           # pending, not raised here
            write_npz(path, {"t": np.arange(5.0)})
            written = True
    assert written
    with np.load(path) as f:
        assert f["t"].tolist() == [0.0, 1.0, 2.0, 3.0, 4.0]


def test_the_handlers_are_restored():
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    with interrupts_deferred():
        assert signal.getsignal(signal.SIGINT) is not before[0]
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before


def test_progress_counters_round_trip_and_an_older_folder_reads_zero():
    """Progress.totals keeps "totals" (chunks, k, samples, Newton iterations: what an older
    hpgen wrote and reads) and one "count_<name>" per counter; an older folder's state (no
    count_*) resumes with its Newton iterations and the other counters 0."""
    from hpgen.runtime.partial_run import Progress
    prog = Progress()
    prog.chunks, prog.k, prog.samples = 3, 30, 31
    prog.counts = {"newton_iterations": 70, "guarded": 2}
    saved = prog.totals()
    assert saved["totals"].tolist() == [3, 30, 31, 70]
    back = Progress.from_state(saved)
    assert (back.chunks, back.k, back.samples, back.counts) == (3, 30, 31, prog.counts)
    old = Progress.from_state({"totals": saved["totals"]})
    assert old.counts == {"newton_iterations": 70, "guarded": 0}
