"""Regenerate generated/<module>/ for every shipped example, with its default options.

Writes sources only (kernels.c, kernels.py, __init__.py, meta.json, model.yaml), no built
library, so the committed tree is the same bytes on every machine. ``make generate`` runs
this; tests/regression/test_generated.py fails when the committed files are stale.
"""
from __future__ import annotations

import sys
from pathlib import Path

from ..api import CompileOptions, content_hash, generate_files
from ..cache import write_tree

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
GENERATED = ROOT / "generated"


def example_sources(path: Path) -> tuple[str, dict[str, str]]:
    """(module name, files) of one example, with its model's default options; the model
    file is referred to by its path relative to the repository (deterministic headers)."""
    text = path.read_text()
    opts = CompileOptions()
    files = generate_files(f"examples/{path.name}", text, opts, content_hash(text, opts))
    import json
    return json.loads(files["meta.json"])["module"], files


def main(argv=None) -> int:
    out = Path(argv[0]) if argv else GENERATED
    names = []
    for path in sorted(EXAMPLES.glob("*.yaml")):
        name, files = example_sources(path)
        write_tree(out / name, files, manifest=False)
        names.append(name)
        print(f"{out / name}")
    stale = [p for p in out.iterdir() if p.is_dir() and p.name not in names] if out.exists() else []
    for p in stale:
        print(f"note: {p} is not produced by any example (remove it if obsolete)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
