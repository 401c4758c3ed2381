"""docs/api.md matches the code: its generated blocks are what hpgen.tools.api_docs renders now
(signatures, docstring summaries, the error tree, the CLI options, the sweep grid file), every
public function, method, error class and CLI option is on the page, and ``hpgen.compile`` is the
real function for help() and inspect."""
from __future__ import annotations

import argparse
import inspect
import pydoc
import re
import subprocess
import sys
from pathlib import Path

import pytest

import hpgen
from hpgen.tools import api_docs

REPO = Path(hpgen.__file__).resolve().parents[1]
PAGE = REPO / "docs" / "api.md"


def test_committed_page_is_the_generated_page():
    page = PAGE.read_text()
    assert api_docs.update(page) == page, \
        "docs/api.md differs from the code: run `python -m hpgen.tools.api_docs` (make docs)"


def test_check_mode_detects_drift(tmp_path):
    stale = tmp_path / "api.md"
    stale.write_text(PAGE.read_text().replace("hpgen.compile(model, *, tableau=None",
                                              "hpgen.compile(model, *, tableau=1"))
    assert api_docs.main(["--page", str(stale), "--check"]) == 1
    assert api_docs.main(["--page", str(stale)]) == 0
    assert api_docs.main(["--page", str(stale), "--check"]) == 0
    assert stale.read_text() == PAGE.read_text()


def _public_methods(cls):
    return [n for n in dir(cls) if not n.startswith("_") and callable(getattr(cls, n))
            and not isinstance(inspect.getattr_static(cls, n), property)]


def test_every_public_name_is_on_the_page():
    page = PAGE.read_text()
    from hpgen.runtime import Integrator, Records, Trajectory
    from hpgen.runtime.initial import GroupElements
    for name in hpgen.__all__:
        obj = getattr(hpgen, name)
        if callable(obj) and not isinstance(obj, type):
            sig = str(inspect.signature(obj)).replace("'", "")
            assert f"hpgen.{name}" in page and sig.split(",")[0] in page, name
    for cls, shown in ((Integrator, "Integrator"), (Trajectory, "Trajectory"),
                       (Records, "Records"), (GroupElements, "Integrator.group")):
        for name in _public_methods(cls):
            assert f"{shown}.{name}(" in page, f"{shown}.{name}"
    # the run methods are listed with their inputs
    for method, args in (("step", ("u=None", "params=None", "t=")),
                         ("simulate", ("u=None", "params=None", "t0="))):
        entry = page.split(f"Integrator.{method}(")[1].split("```")[0]
        assert all(a in entry for a in args), (method, entry)


def test_every_error_class_is_in_the_tree():
    page = PAGE.read_text()
    tree = page.split("<!-- generated: errors -->")[1].split("<!-- end generated")[0]

    def walk(cls):
        yield cls
        for sub in cls.__subclasses__():
            yield from walk(sub)
    import hpgen.cache  # noqa: F401  (defines CacheUnwritable)
    for cls in walk(hpgen.HpgenError):
        assert cls.__name__ in tree, cls
    assert "ArgumentError (ValueError)" in tree and "ModelError (ValueError)" in tree
    intro = " ".join(page.split("## Compile")[0].split())
    assert "h > 0" not in page and "h < 0 runs backwards" in intro
    assert "non-finite argument of a run (g0, xi0, u, params, h, steps, ...) raises " \
           "`ArgumentError`" in intro


def test_every_cli_option_is_on_the_page():
    from hpgen.cli import _parser
    cli = PAGE.read_text().split("<!-- generated: cli -->")[1]
    sub = next(a for a in _parser()._actions if isinstance(a, argparse._SubParsersAction))
    for name, p in sub.choices.items():
        section = cli.split(f"### `hpgen {name}`")[1].split("### `hpgen ")[0]
        for a in p._actions:
            for flag in a.option_strings:
                if flag not in ("-h", "--help"):
                    assert flag in section, (name, flag)
    assert "$XDG_CACHE_HOME/hpgen" in cli


def test_grid_file_format_is_on_the_page():
    from hpgen.ensemble.grid import KEYS
    grid = PAGE.read_text().split("<!-- generated: grid -->")[1]
    for key in KEYS:
        assert re.search(rf"\b{key}\b", grid), key


def test_compile_is_the_real_function_for_help_and_inspect():
    from hpgen import api
    assert hpgen.compile is api.compile and hpgen.build is api.build
    params = inspect.signature(hpgen.compile).parameters
    assert list(params)[:4] == ["model", "tableau", "tau", "rkmk"]
    assert params["tableau"].kind is inspect.Parameter.KEYWORD_ONLY
    text = pydoc.render_doc(hpgen.compile, renderer=pydoc.plaintext)
    assert "cache_dir=None" in text and "Parameters" in text and "ModelError" in text
    assert len(text.splitlines()) > 30


def test_import_hpgen_stays_cheap():
    code = ("import sys, hpgen; print(sorted(m for m in ('numpy', 'hpgen.api', 'hpgen.runtime',"
            " 'sympy', 'casadi', 'yaml') if m in sys.modules)); "
            "from hpgen import compile, sweep; print(compile.__module__, sweep.__module__)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={"PYTHONPATH": str(REPO), "PATH": "/usr/bin:/bin"}, check=True)
    assert out.stdout.split("\n")[:2] == ["[]", "hpgen.api hpgen.ensemble.sweep"]


def test_unknown_attribute_is_an_attribute_error():
    with pytest.raises(AttributeError):
        hpgen.no_such_name  # noqa: B018
