"""The Makefile's set-up (``make -n``, nothing run): `make install`, `make demo` and
`make test` install into the active virtual environment, else into the project's .venv
(created first), never into the bare python3 unless asked (VENV= or PYTHON=)."""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.skipif(shutil.which("make") is None, reason="needs make")


def dry_run(target, *args, virtual_env=None):
    env = {k: v for k, v in os.environ.items() if k not in ("VIRTUAL_ENV", "PYTHON", "VENV")}
    if virtual_env:
        env["VIRTUAL_ENV"] = virtual_env
    out = subprocess.run(["make", "-n", "-C", str(REPO), target, *args], capture_output=True,
                         text=True, env=env, check=True).stdout
    return [line for line in out.splitlines() if not line.startswith("make")]


@pytest.mark.parametrize("target", ["install", "demo", "test"])
def test_default_is_the_project_venv(target):
    lines = dry_run(target)
    pip = [line for line in lines if "pip install" in line]
    assert pip and all(line.startswith(".venv/bin/python -m pip") for line in pip), lines
    if not (REPO / ".venv" / "bin" / "python").exists():
        assert lines[0] == "python3 -m venv .venv"
    assert not any(line.startswith("python3 -m pip") for line in lines)


def test_active_venv_is_used_as_is():
    lines = dry_run("test", virtual_env="/somewhere/env")
    assert "python3 -m venv .venv" not in lines
    assert lines[0].startswith("python3 -m pip install") and lines[-1].startswith("python3 -m pytest")


def test_ci_may_ask_for_the_bare_interpreter():
    assert dry_run("test", "VENV=")[0].startswith("python3 -m pip install")
    lines = dry_run("test", "PYTHON=/opt/py/bin/python3")
    assert lines[0].startswith("/opt/py/bin/python3 -m pip install") and len(lines) == 2


def test_wheel_test_and_docs():
    assert dry_run("wheel-test") == ["PYTHON=python3 sh .ci/wheel-test"]
    assert dry_run("docs")[-1] == ".venv/bin/python -m hpgen.tools.api_docs"
