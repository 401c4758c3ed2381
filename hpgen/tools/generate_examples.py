"""Regenerate the golden modules in generated/ and build the other shipped examples into the
build cache, each with its model's default options.

generated/ holds the sources (kernels.c, kernels.py, __init__.py, meta.json, model.yaml; no
built library, so the committed tree is the same bytes on every machine) of the GOLDEN
examples only: a closed model with the reduced Stormer-Verlet step (free rigid body, SO3) and
an open one with time-dependent forcing and a runtime parameter (driven pendulum, Gauss 2 on
SO2). Both are small enough to read, cover the C and the Python kernels, and are checked
current by tests/regression/test_generated.py. The other examples are generated on demand:
``make generate`` compiles them into the build cache (``--cache-dir``, default hpgen's), and
``--all DIR`` writes every example's sources under DIR.

    python -m hpgen.tools.generate_examples [--out DIR] [--cache-dir DIR | --no-cache]
    python -m hpgen.tools.generate_examples --all DIR
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from ..api import CompileOptions, build, content_hash, generate_files
from ..cache import write_tree

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
GENERATED = ROOT / "generated"
#: the examples whose generated sources are committed under generated/ (file stems)
GOLDEN = ("driven_pendulum", "free_rigid_body")


def examples() -> list[Path]:
    """Every shipped example model file, sorted."""
    return sorted(EXAMPLES.glob("*.yaml"))


def golden_examples() -> list[Path]:
    """The model files of the golden modules."""
    return [EXAMPLES / f"{stem}.yaml" for stem in GOLDEN]


def example_sources(path: Path) -> tuple[str, dict[str, str]]:
    """(module name, files) of one example, with its model's default options; the model
    file is referred to by its path relative to the repository (deterministic headers)."""
    text = path.read_text()
    opts = CompileOptions()
    files = generate_files(f"examples/{path.name}", text, opts, content_hash(text, opts))
    return json.loads(files["meta.json"])["module"], files


def write_sources(paths: list[Path], out: Path) -> list[str]:
    """Write the sources of each example to ``out/<module>/``; the module names."""
    names = []
    for path in paths:
        name, files = example_sources(path)
        write_tree(out / name, files, manifest=False)
        names.append(name)
        print(out / name)
    return names


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m hpgen.tools.generate_examples",
                                 description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=GENERATED,
                    help="directory of the golden modules (default: generated/)")
    ap.add_argument("--cache-dir", type=Path, default=None,
                    help="build cache receiving the other examples (default: hpgen's)")
    ap.add_argument("--no-cache", action="store_true",
                    help="write the golden modules only")
    ap.add_argument("--all", type=Path, metavar="DIR",
                    help="write the sources of every example under DIR instead")
    args = ap.parse_args(argv)
    if args.all is not None:
        write_sources(examples(), args.all)
        return 0
    names = write_sources(golden_examples(), args.out)
    for p in sorted(args.out.iterdir()):
        if p.is_dir() and p.name not in names:
            print(f"note: {p} is not a golden module (remove it if obsolete)")
    if not args.no_cache:
        for path in examples():
            if path not in golden_examples():
                module = build(path, cache_dir=args.cache_dir)
                print(f"{module.meta['module']} (build cache): {module.module_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
