"""``hpgen run`` of a model that records ``work``, stopped by SIGTERM: the one line printed
offers a resume command, and that command continues the run (the accumulated work is kept
with each chunk) to bitwise the uninterrupted run's file."""
from __future__ import annotations

import shlex
import signal
import subprocess
import sys
import time

import numpy as np

from conftest import EXAMPLES, child_process
from hpgen.runtime.chunked_output import partial_dir

STEPS, CHUNK = 300_000, 2000


def _argv(out, cache, *extra):
    return [sys.executable, "-m", "hpgen", "run", str(EXAMPLES / "damped_top.yaml"),
            "--out", str(out), "--cache-dir", str(cache), "--steps", str(STEPS), "--chunk",
            str(CHUNK), "--no-plot", "--no-progress", *extra]


def test_sigterm_on_a_work_run_offers_a_resume_that_gives_the_uninterrupted_file(tmp_path):
    cache = tmp_path / "cache"
    ref = subprocess.run(_argv(tmp_path / "ref.npz", cache), capture_output=True, text=True,
                         timeout=600)
    assert ref.returncode == 0, ref.stderr[-3000:]
    out = tmp_path / "run.npz"
    with child_process(_argv(out, cache)) as proc:
        parts, t0 = partial_dir(out), time.monotonic()
        while len(list(parts.glob("chunk_*.npz"))) < 3:
            assert proc.poll() is None, f"the run ended before 3 chunks: {proc.communicate()}"
            assert time.monotonic() - t0 < 300, "no chunk committed in 300 s"
            time.sleep(0.005)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=120)
    assert proc.returncode == 143, err[-3000:]
    line, = err.strip().splitlines()
    assert "for --resume: " in line, line
    command = shlex.split(line.split("for --resume: ", 1)[1])
    assert command[:2] == ["hpgen", "run"] and "--resume" in command
    again = subprocess.run([sys.executable, "-m", "hpgen", *command[1:]], capture_output=True,
                           text=True, timeout=600)
    assert again.returncode == 0, again.stderr[-3000:]
    assert "resumed at step" in again.stdout
    with np.load(tmp_path / "ref.npz") as a, np.load(out) as b:
        assert sorted(a.files) == sorted(b.files) and "work" in a.files
        for key in a.files:
            assert np.array_equal(a[key], b[key]), key        # bitwise, metadata included
    assert not partial_dir(out).exists()
