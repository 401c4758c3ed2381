"""hpgen.files: atomic outputs get a plain open()'s permissions, and a failed write leaves
the target as it was (no partial file, no temporary left behind)."""
import os
import stat

import pytest

from hpgen.files import atomic_output, write_file


def _mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


def test_permissions_are_those_of_open(tmp_path):
    old = os.umask(0o022)
    try:
        write_file(tmp_path / "a.txt", "x")
        with open(tmp_path / "b.txt", "w") as fh:
            fh.write("x")
    finally:
        os.umask(old)
    assert _mode(tmp_path / "a.txt") == _mode(tmp_path / "b.txt") == 0o644


def test_failed_write_keeps_the_old_file_and_leaves_no_temporary(tmp_path):
    target = tmp_path / "out.bin"
    write_file(target, b"old")
    with pytest.raises(RuntimeError):
        with atomic_output(target) as fh:
            fh.write(b"half")
            raise RuntimeError("killed mid-write")
    assert target.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.bin"]
