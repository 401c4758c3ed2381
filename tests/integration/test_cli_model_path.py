"""A model path that is not a regular file (issue 17): a symlink to /dev/zero or /dev/urandom,
a FIFO, a directory. Refused before anything is read (the FIFO never blocks), with one
ModelError line (CLI exit 2), and never more than the 2 MB limit + 1 bytes read."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest

import hpgen
from hpgen.api import read_model_text
from hpgen.model import load_model
from hpgen.model.yamldoc import MAX_FILE_BYTES

TIMEOUT = 60      # a FIFO that blocks would hang: the subprocess timeout turns that into a fail


def _special(tmp_path, kind):
    path = tmp_path / f"model_{kind}.yaml"
    if kind in ("zero", "urandom"):
        path.symlink_to(f"/dev/{kind}")
    elif kind == "fifo":
        os.mkfifo(path)
    else:
        path.mkdir()
    return path


KINDS = ("zero", "urandom", "fifo", "directory")
WHAT = {"zero": "character device", "urandom": "character device", "fifo": "FIFO",
        "directory": "directory"}


@pytest.mark.parametrize("kind", KINDS)
def test_cli_refuses_a_model_path_that_is_not_a_regular_file(tmp_path, kind):
    path = _special(tmp_path, kind)
    for command in ("compile", "run"):
        out = subprocess.run([sys.executable, "-m", "hpgen", command, str(path), "--cache-dir",
                              str(tmp_path / "cache"), "--out", str(tmp_path / "out")],
                             capture_output=True, text=True, timeout=TIMEOUT)
        assert out.returncode == 2, (command, out.stderr[-2000:])
        lines = out.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("hpgen: error: "), out.stderr[-2000:]
        assert str(path) in lines[0] and "regular file" in lines[0] and WHAT[kind] in lines[0]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("kind", KINDS)
def test_api_refuses_a_model_path_that_is_not_a_regular_file(tmp_path, kind):
    # in a child process so that a FIFO which blocks fails by timeout instead of hanging
    path = _special(tmp_path, kind)
    code = ("import sys, hpgen\n"
            "from hpgen.api import read_model_text\nfrom hpgen.model import load_model\n"
            "for f in (read_model_text, load_model, hpgen.compile):\n"
            "    try:\n        f(sys.argv[1])\n    except hpgen.ModelError as e:\n"
            "        print(type(e).__name__, e)\n    else:\n        print('accepted')\n")
    out = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True,
                         timeout=TIMEOUT)
    assert out.returncode == 0, out.stderr[-2000:]
    lines = out.stdout.strip().splitlines()
    assert len(lines) == 3 and all(ln.startswith("ModelError ") and "regular file" in ln
                                   for ln in lines), out.stdout


def test_a_file_over_the_limit_is_refused_and_read_no_further(tmp_path, monkeypatch):
    path = tmp_path / "big.yaml"
    path.write_bytes(b"#" * (MAX_FILE_BYTES + 1))
    for f in (read_model_text, load_model):
        with pytest.raises(hpgen.ModelError, match="too large"):
            f(path)
    # a file that is small when stat'ed and grows while read (the size check alone would pass):
    # os.read is asked for at most the limit + 1 bytes in total
    path.write_bytes(b"")
    asked, real_read = [], os.read

    def growing_read(fd, n):
        asked.append(n)
        return b"#" * n
    monkeypatch.setattr(os, "read", growing_read)
    with pytest.raises(hpgen.ModelError, match="too large"):
        read_model_text(path)
    monkeypatch.setattr(os, "read", real_read)
    assert sum(asked) == MAX_FILE_BYTES + 1
