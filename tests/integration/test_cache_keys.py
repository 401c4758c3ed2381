"""The cache is keyed by what changes the code (issue 15 item 3).

- content hash: normalized model (no comments, formatting, h, steps, initial state) + options;
- derivation key: content hash + generator digest;
- C library: sha256 of kernels.c + the C runtime's sources + compiler + flags.
Compiler runs are counted with a wrapper around the real compiler, derivations by wrapping
hpgen.api.derive_module.
"""
from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import hpgen
import hpgen.api as api
from hpgen.api import CompileOptions, content_hash, module_key
from hpgen.tools import generate_examples

ROOT = Path(__file__).resolve().parents[2]
BODY = (ROOT / "examples" / "free_rigid_body.yaml").read_text()
G0 = np.eye(3)
MU0 = [0.4535961214255773, 0.0, 0.8912073600614354]

# edits that change no generated code: comments, YAML layout, run-only scene values
SAME_CODE = {
    "comment": "# a comment added by a user\n" + BODY.replace("group: SO3", "group: SO3  # SO(3)"),
    "yaml layout": BODY.replace("parameters:\n  I: [2.0, 1.0, 0.6666666666666666]",
                                "parameters: {I: [2.0, 1.0, 0.6666666666666666]}"),
    "lagrangian spacing": BODY.replace("0.5*(I[0]*xi[0]**2", "0.5 * ( I[0] * xi[0]**2"),
    "scene h, steps, every": BODY.replace("h: 0.1", "h: 0.025").replace(
        "steps: 1000", "steps: 7").replace("every: 1", "every: 3"),
    "scene initial": BODY.replace("mu: [0.4535961214255773, 0.0, 0.8912073600614354]",
                                  "xi: [0.1, 0.2, 0.3]"),
}
# edits that change the generated code (or may): each must give another content hash
OTHER_CODE = {
    "parameter": BODY.replace("I: [2.0, 1.0,", "I: [2.5, 1.0,"),
    "parameter int": BODY.replace("I: [2.0, 1.0,", "I: [2, 1.0,"),
    "lagrangian": BODY.replace("0.5*(I[0]", "0.25*(I[0]"),
    "name": BODY.replace("name: free_rigid_body", "name: body2"),
    "group": BODY.replace("group: SO3", "group: [SO3]"),
    "record entry": BODY.replace("record: [g, mu, energy, momentum]",
                                 "record: [g, mu, energy]"),
    "record expression": BODY.replace("record: [g, mu, energy, momentum]",
                                      "record: [g, {m1: \"mu[0]*2\"}]"),
    "section": BODY.replace("every: 1", "every: 1\n  section: mu[0]"),
    "no scene": BODY[:BODY.index("scene:")],
    "integrator tau": BODY.replace("tau: cay", "tau: exp"),
}


def test_content_hash_ignores_what_changes_no_code():
    opts = CompileOptions()
    base = content_hash(BODY, opts)
    for label, text in SAME_CODE.items():
        assert text != BODY and content_hash(text, opts) == base, label


def test_content_hash_follows_what_changes_code():
    opts = CompileOptions()
    hashes = {"base": content_hash(BODY, opts)}
    for label, text in OTHER_CODE.items():
        assert text != BODY, label
        hashes[label] = content_hash(text, opts)
    for label, opt in {"option tableau": CompileOptions(tableau="gauss2"),
                       "option tau": CompileOptions(tau="exp"),
                       "option rkmk": CompileOptions(rkmk="exact"),
                       "user tableau": CompileOptions(tableau={"A": [[0.5]], "b": [1.0]}),
                       "user tableau b": CompileOptions(tableau={"A": [[0.5]], "b": [1.5]})
                       }.items():
        hashes[label] = content_hash(BODY, opt)
    assert len(set(hashes.values())) == len(hashes), hashes


def test_explicit_options_equal_to_the_model_defaults_share_the_hash():
    explicit = CompileOptions(tableau="stormer-verlet", tau="cay", rkmk="truncated")
    assert content_hash(BODY, explicit) == content_hash(BODY, CompileOptions())


def test_generator_digest_is_in_the_derivation_key_only(monkeypatch):
    opts = CompileOptions()
    key, chash = module_key(BODY, opts), content_hash(BODY, opts)
    monkeypatch.setattr(api, "generator_digest", lambda: "an edited generator")
    assert module_key(BODY, opts) != key and content_hash(BODY, opts) == chash


@pytest.fixture
def counting_cc(tmp_path):
    """(cc command, number of compiler runs so far)."""
    log = tmp_path / "cc.log"
    wrapper = tmp_path / "cc-counting"
    wrapper.write_text(f'#!/bin/sh\necho run >> "{log}"\nexec cc "$@"\n')
    wrapper.chmod(wrapper.stat().st_mode | stat.S_IEXEC)
    return str(wrapper), lambda: len(log.read_text().splitlines()) if log.exists() else 0


@pytest.fixture
def counting_derive(monkeypatch):
    calls = []
    real = api.derive_module

    def counted(*args, **kw):
        calls.append(args[0])
        return real(*args, **kw)
    monkeypatch.setattr(api, "derive_module", counted)
    return calls


def _run(integ, steps=50):
    tr = integ.simulate(G0, 0.1, steps, mu0=MU0)
    return np.asarray(tr.g), np.asarray(tr.mu)


def test_scene_edit_and_comment_are_cache_hits(tmp_path, counting_cc, counting_derive):
    cc, runs = counting_cc
    cache_dir = tmp_path / "cache"
    (tmp_path / "base.yaml").write_text(BODY)
    ref = _run(hpgen.compile(tmp_path / "base.yaml", cache_dir=cache_dir, cc=cc))
    assert runs() == 1 and len(counting_derive) == 1
    for i, (label, text) in enumerate(SAME_CODE.items()):
        path = tmp_path / f"edit{i}.yaml"
        path.write_text(text)
        got = _run(hpgen.compile(path, cache_dir=cache_dir, cc=cc))
        assert runs() == 1 and len(counting_derive) == 1, label      # no derivation, no gcc
        for a, b in zip(ref, got):
            np.testing.assert_array_equal(a, b)


def test_code_edit_derives_again(tmp_path, counting_cc, counting_derive):
    cc, runs = counting_cc
    cache_dir = tmp_path / "cache"
    for i, text in enumerate((BODY, OTHER_CODE["record entry"])):
        (tmp_path / f"m{i}.yaml").write_text(text)
        hpgen.compile(tmp_path / f"m{i}.yaml", cache_dir=cache_dir, cc=cc)
    assert runs() == 2 and len(counting_derive) == 2


def _tree(folder: Path) -> dict:
    return {p.relative_to(folder).as_posix(): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file() and not p.name.endswith(".lock")}


def test_generator_edit_costs_a_derivation_never_a_compiler_run(
        tmp_path, monkeypatch, counting_cc, counting_derive):
    cc, runs = counting_cc
    cache_dir, out1, out2 = tmp_path / "cache", tmp_path / "out1", tmp_path / "out2"
    (tmp_path / "m.yaml").write_text(BODY)
    hpgen.compile(tmp_path / "m.yaml", cache_dir=cache_dir, cc=cc, out=out1)
    assert runs() == 1 and len(counting_derive) == 1
    monkeypatch.setattr(api, "generator_digest", lambda: "a comment added to the generator")
    integ = hpgen.compile(tmp_path / "m.yaml", cache_dir=cache_dir, cc=cc, out=out2)
    assert len(counting_derive) == 2 and runs() == 1          # derived again, not compiled
    assert _tree(out1) == _tree(out2)                          # same sources, same library
    entries = [p for p in cache_dir.iterdir() if p.is_dir() and p.name != "lib"]
    assert len(entries) == 2
    libs = [sorted(e.glob("_kernels_*.so")) for e in entries]
    assert [len(x) for x in libs] == [1, 1] and libs[0][0].name == libs[1][0].name
    assert libs[0][0].read_bytes() == libs[1][0].read_bytes()
    assert integ.step(G0, [0.1, 0.2, 0.3], 0.1)[0].shape == (3, 3)


def test_generator_edit_leaves_generated_unchanged(monkeypatch):
    """The committed golden modules do not depend on the generator digest: regenerated
    with another digest, every file has the same bytes."""
    monkeypatch.setattr(api, "generator_digest", lambda: "a comment added to the generator")
    for path in generate_examples.golden_examples():
        name, files = generate_examples.example_sources(path)
        for fname, text in files.items():
            committed = (generate_examples.GENERATED / name / fname).read_text()
            assert committed == text, (name, fname)


CLI_HIT = """
import subprocess, sys
for mod in ("casadi", "sympy", "jinja2"):
    sys.modules[mod] = None
from hpgen.cli import main
sys.exit(main(["compile", sys.argv[1], "--cache-dir", sys.argv[2], "-o", sys.argv[3]]))
"""


def test_cli_compile_of_a_scene_edit_is_a_hit_without_compile_stack(tmp_path):
    """From the command line too: a changed h is served from the cache (no sympy, casadi,
    jinja2 imported), and the -o copy carries the edited model file. (The first compile
    copies out too, so that the entry holds both backends' sources, as -o needs.)"""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    (tmp_path / "m.yaml").write_text(BODY)
    hpgen.compile(tmp_path / "m.yaml", cache_dir=tmp_path / "cache", out=tmp_path / "first")
    edited = SAME_CODE["scene h, steps, every"]
    (tmp_path / "m.yaml").write_text(edited)
    out = subprocess.run([sys.executable, "-c", CLI_HIT, str(tmp_path / "m.yaml"),
                          str(tmp_path / "cache"), str(tmp_path / "out")],
                         capture_output=True, text=True, timeout=120, env=env)
    assert out.returncode == 0, out.stderr
    (module,) = (tmp_path / "out").iterdir()
    assert (module / "model.yaml").read_text() == edited
