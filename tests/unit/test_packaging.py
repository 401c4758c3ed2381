"""Packaging: the wheel's package list covers every subpackage and ships templates/ (kept at
the top of the repository) as hpgen/templates and the C runtime (hpgen/runtime/c);
dependencies are ranges, pins live in constraints.txt. (.ci/wheel-test builds and installs the
wheel itself.)"""
from __future__ import annotations

import importlib
import re
import tomllib
from pathlib import Path

emit = importlib.import_module("hpgen.codegen.emit")

ROOT = Path(__file__).resolve().parents[2]
PROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())
SETUPTOOLS = PROJECT["tool"]["setuptools"]


def test_package_list_is_every_subpackage_plus_templates():
    found = {".".join(p.parent.relative_to(ROOT).parts)
             for p in (ROOT / "hpgen").rglob("__init__.py")}
    assert set(SETUPTOOLS["packages"]) == found | {"hpgen.templates"}


def test_templates_ship_as_package_data():
    assert SETUPTOOLS["package-dir"] == {"hpgen.templates": "templates"}
    shipped = SETUPTOOLS["package-data"]["hpgen.templates"]
    names = sorted(p.name for p in (ROOT / "templates").iterdir())
    assert names == sorted(emit.TEMPLATES.values())
    assert all(any(Path(n).match(pat) for pat in shipped) for n in names)
    assert all(any(Path(p.name).match(pat) for pat in SETUPTOOLS["package-data"]["hpgen.bench"])
               for p in (ROOT / "hpgen" / "bench").glob("*.j2"))
    assert emit.template_dir() == ROOT / "templates"      # a checkout / editable install


def test_the_c_runtime_ships_as_package_data():
    """Every file of the static C runtime (hpgen/runtime/c) matches a package-data pattern
    of hpgen.runtime, and the build finds them there."""
    from hpgen.runtime import build
    shipped = SETUPTOOLS["package-data"]["hpgen.runtime"]
    files = sorted((ROOT / "hpgen" / "runtime" / "c").iterdir())
    assert {p.suffix for p in files} == {".c", ".h"}
    assert all(any(Path("c", p.name).match(pat) for pat in shipped) for p in files)
    assert build.RUNTIME_DIR == ROOT / "hpgen" / "runtime" / "c"
    assert build.runtime_sources() == files


def test_dependencies_are_ranges_and_pins_are_constraints():
    deps = PROJECT["project"]["dependencies"]
    names = {re.match(r"[A-Za-z0-9_.-]+", d).group(0).lower() for d in deps}
    assert {"numpy", "sympy", "casadi", "jinja2", "pyyaml", "mpmath", "scipy",
            "matplotlib"} <= names
    assert not [d for d in deps if "==" in d]
    pins = dict(line.split("==") for line in (ROOT / "constraints.txt").read_text().splitlines()
                if line and not line.startswith("#"))
    assert {n.lower() for n in pins} >= names | {"pytest", "hypothesis"}
