"""Shared fixtures: one build cache per test session, model files written on demand."""
from __future__ import annotations

import hashlib
import subprocess
from contextlib import contextmanager
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

HEAVY_TOP = """
name: top
group: SO3
parameters: {I: [1.0, 5.0, 6.0], Mg: 1.0, chi: [0.0, 0.0, 1.0]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2) - Mg*(R[2,0]*chi[0] + R[2,1]*chi[1] + R[2,2]*chi[2])
"""

FREE_BODY = """
name: body
group: SO3
parameters: {I: [2.0, 1.0, 0.6666666666666666]}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2)
"""

# an SE3 body with a potential depending on both R and x (so the full, non-reduced step)
SE3_BODY = """
name: se3body
group: SE3
parameters: {I: [2.0, 1.0, 0.6666666666666666], M: [1.0, 1.5, 3.0], Mg: 0.5, chi: [0.0, 0.0, 1.0], k: 0.3}
lagrangian: 0.5*(I[0]*xi[0]**2 + I[1]*xi[1]**2 + I[2]*xi[2]**2 + M[0]*xi[3]**2 + M[1]*xi[4]**2 + M[2]*xi[5]**2) - Mg*(R[2,0]*chi[0] + R[2,1]*chi[1] + R[2,2]*chi[2]) - 0.5*k*(x[0]**2 + x[1]**2 + x[2]**2)
"""


@pytest.fixture(scope="session")
def cache_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("hpgen-cache")


@pytest.fixture(scope="session")
def model_file(tmp_path_factory):
    folder = tmp_path_factory.mktemp("models")

    def write(text: str) -> Path:
        path = folder / (hashlib.sha256(text.encode()).hexdigest()[:12] + ".yaml")
        path.write_text(text)
        return path
    return write


@pytest.fixture(scope="session")
def compile_model(cache_dir, model_file):
    """compile_model(text_or_path, **options) -> Integrator, sharing the session cache."""
    import hpgen

    def _compile(model, **opts):
        path = Path(model) if isinstance(model, Path) else model_file(model)
        return hpgen.compile(path, cache_dir=cache_dir, **opts)
    return _compile


def model_error(text, filename="m.yaml") -> str:
    """The ModelError message of loading the model text ``text``, checked to be one line."""
    from hpgen.errors import ModelError
    from hpgen.model import load_model_text
    with pytest.raises(ModelError) as e:
        load_model_text(text, filename)
    msg = str(e.value)
    assert "\n" not in msg
    return msg


@contextmanager
def child_process(argv, **kwargs):
    """A child process with text pipes for stdout and stderr, killed and reaped on the way out
    if it is still running (a failed assertion while waiting for it leaves no orphan)."""
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            **kwargs)
    try:
        yield proc
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
