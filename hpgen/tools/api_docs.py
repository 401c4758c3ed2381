"""The generated parts of docs/api.md: the signatures and summaries of the public API, the
error tree, the command-line options and the sweep grid file, taken from the code itself
(``inspect`` signatures, docstrings, hpgen.errors, the argparse parser of hpgen.cli).

    python -m hpgen.tools.api_docs            # rewrite the generated blocks of docs/api.md
    python -m hpgen.tools.api_docs --check    # exit 1 when the page differs from the code

The page is hand-written prose around blocks delimited by ``<!-- generated: NAME -->`` and
``<!-- end generated: NAME -->``; only the blocks are rewritten. A public method, error class or
CLI option added to the code appears in the page on the next run; tests/unit/test_api_docs.py
fails while the committed page differs from what this module renders.
"""
from __future__ import annotations

import argparse
import importlib
import inspect
import re
import sys
from pathlib import Path

WIDTH = 96
BEGIN = "<!-- generated: {} -->"
END = "<!-- end generated: {} -->"

#: (name on the page, where it is defined) of the documented functions and classes, in page
#: order; a class lists its dataclass fields and every public method and property it has
FUNCTIONS = (
    ("hpgen.compile", "hpgen.api.compile"),
    ("hpgen.build", "hpgen.api.build"),
    ("hpgen.load", "hpgen.runtime.load"),
    ("hpgen.sweep", "hpgen.ensemble.sweep.sweep"),
    ("hpgen.model.builder.ModelBuilder", "hpgen.model.builder.ModelBuilder"),
    ("hpgen.model.load_model", "hpgen.model.loader.load_model"),
    ("hpgen.ocp.rest_to_rest", "hpgen.ocp.rest_to_rest"),
)
CLASSES = (
    ("Integrator", "hpgen.runtime.integrator.Integrator"),
    ("Integrator.group", "hpgen.runtime.initial.GroupElements"),
    ("hpgen.runtime.NewtonOptions", "hpgen.runtime.newton.NewtonOptions"),
    ("Trajectory", "hpgen.runtime.trajectory.Trajectory"),
    ("Records", "hpgen.runtime.records.Records"),
    ("SectionCrossings", "hpgen.runtime.trajectory.SectionCrossings"),
    ("SweepResult", "hpgen.ensemble.result.SweepResult"),
    ("hpgen.ocp.Plan", "hpgen.ocp.Plan"),
)


def resolve(dotted: str):
    """The object named by ``dotted`` (module path, then attributes); None when the module
    or attribute does not exist (a part another branch has not merged yet is left out)."""
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for attr in parts[i:]:
            obj = getattr(obj, attr, None)
            if obj is None:
                return None
        return obj
    return None


def summary(obj) -> str:
    """The first paragraph of obj's docstring, as one line."""
    doc = inspect.getdoc(obj) or ""
    return " ".join(doc.split("\n\n")[0].split())


def wrap_signature(name: str, sig: str) -> str:
    """``name(sig)`` broken after commas to at most WIDTH columns, continuation lines
    aligned after the opening parenthesis."""
    text = f"{name}{sig}"
    if len(text) <= WIDTH:
        return text
    indent = " " * (len(name) + 1)
    lines, line = [], ""
    for piece in re.split(r"(?<=,) ", text):
        if line and len(line) + 1 + len(piece) > WIDTH:
            lines.append(line)
            line = indent + piece
        else:
            line = f"{line} {piece}" if line else piece
    return "\n".join(lines + [line])


class _Text:
    """An annotation shown as its text (a string annotation without quotes)."""

    def __init__(self, text):
        self.text = text

    def __repr__(self):
        return self.text


def _signature(obj) -> str:
    """obj's signature without ``self`` / ``cls``, string annotations unquoted."""
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return "(...)"
    params = list(sig.parameters.values())
    if params and params[0].name in ("self", "cls"):
        params = params[1:]
    unquote = (lambda a: _Text(a) if isinstance(a, str) else a)     # noqa: E731
    params = [p.replace(annotation=unquote(p.annotation)) for p in params]
    return str(sig.replace(parameters=params,
                           return_annotation=unquote(sig.return_annotation)))


def _entry(name: str, obj) -> str:
    return f"```python\n{wrap_signature(name, _signature(obj))}\n```\n{summary(obj)}\n"


def _members(cls):
    """(name, kind, object) of cls's public methods and properties, alphabetical."""
    out = []
    for name in sorted(dir(cls)):
        if name.startswith("_"):
            continue
        static = inspect.getattr_static(cls, name)
        if isinstance(static, property) or type(static).__name__ == "cached_property":
            out.append((name, "property", static))
        elif isinstance(static, (staticmethod, classmethod)) or inspect.isfunction(static):
            out.append((name, "method", getattr(cls, name)))
    return out


def render_reference() -> str:
    parts = []
    for heading, dotted in FUNCTIONS:
        obj = resolve(dotted)
        if obj is not None:
            parts.append(f"### `{heading}`\n\n{_entry(heading, obj)}")
    for heading, dotted in CLASSES:
        cls = resolve(dotted)
        if cls is None:
            continue
        block = [f"### `{heading}`\n\n{summary(cls)}\n"]
        fields = [f for f in getattr(cls, "__dataclass_fields__", {}) if not f.startswith("_")]
        if fields:
            block.append("Fields: " + ", ".join(f"`{f}`" for f in fields) + ".\n")
        for name, kind, obj in _members(cls):
            if kind == "property":
                about = summary(obj)
                block.append(f"- `{heading}.{name}` (property)" + (f": {about}" if about else ""))
            else:
                block.append(_entry(f"{heading}.{name}", obj))
        parts.append("\n".join(b.rstrip("\n") + "\n" for b in block))
    return "\n".join(p.rstrip("\n") + "\n" for p in parts)


def render_errors() -> str:
    """The HpgenError tree (hpgen.errors and every module defining a subclass), one line each:
    the class, its other bases, its docstring's first sentence."""
    from .. import errors
    root = Path(errors.__file__).resolve().parent
    for path in sorted(root.rglob("*.py")):        # every module defining an error class
        if re.search(r"^class \w+\([^)]*Error\b", path.read_text(), re.M):
            rel = path.relative_to(root.parent).with_suffix("")
            resolve(".".join(rel.parts))
    lines = []

    def walk(cls, depth):
        bases = [b.__name__ for b in cls.__bases__ if not issubclass(b, errors.HpgenError)
                 and b is not Exception]
        first = re.split(r"(?<!e\.g)(?<!i\.e)\. ", summary(cls))[0].rstrip(".")
        where = "" if cls.__module__ == "hpgen.errors" else f" [{cls.__module__}]"
        label = cls.__name__ + (f" ({', '.join(bases)})" if bases else "") + where
        prefix = "" if depth == 0 else " " * (5 * (depth - 1)) + " +-- "
        lines.append(f"{prefix}{label}: {first}")
        for sub in sorted(cls.__subclasses__(), key=_definition_order):
            walk(sub, depth + 1)

    walk(errors.HpgenError, 0)
    return "```\n" + "\n".join(lines) + "\n```\n"


def _definition_order(cls):
    try:
        return (cls.__module__ != "hpgen.errors", cls.__module__,
                inspect.getsourcelines(cls)[1])
    except (OSError, TypeError):
        return (True, cls.__module__, 0)


def render_cli() -> str:
    """Every subcommand of ``hpgen`` with its arguments and their help text."""
    from ..cli import _parser
    parser = _parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    out = []
    helps = {a.dest: a.help for a in sub._choices_actions}
    for name, p in sub.choices.items():
        about = " ".join((p.description or helps.get(name) or "").split())
        out.append(f"### `hpgen {name}`\n\n{about}\n")
        rows = ["| argument | meaning |", "|---|---|"]
        for a in p._actions:
            if isinstance(a, argparse._HelpAction):
                continue
            flag = ", ".join(a.option_strings) or a.dest
            if a.option_strings and a.nargs != 0:
                flag += " " + (a.metavar or a.dest.upper())
            text = " ".join((a.help or "").split()).replace("|", "\\|")
            if a.choices and not isinstance(a.choices, dict):
                text += f" (one of: {', '.join(map(str, a.choices))})"
            rows.append(f"| `{flag}` | {text} |")
        out.append("\n".join(rows) + "\n")
    return "\n".join(out)


def render_grid() -> str:
    """The grid file of ``hpgen sweep --grid``: hpgen.ensemble.grid's module docstring."""
    mod = resolve("hpgen.ensemble.grid")
    doc = inspect.getdoc(mod) or ""
    head, _, rest = doc.partition("\n\n")
    example, _, tail = rest.partition("\n\n")
    example = "\n".join(line[4:] if line.startswith("    ") else line
                        for line in example.splitlines())
    return f"{head}\n\n```yaml\n{example}\n```\n\n{' '.join(tail.split())}\n"


SECTIONS = {"errors": render_errors, "reference": render_reference, "cli": render_cli,
            "grid": render_grid}


def update(page: str) -> str:
    """``page`` with every generated block rendered again; a block the page lacks is an
    error (the page's layout is hand-written)."""
    for name, render in SECTIONS.items():
        begin, end = BEGIN.format(name), END.format(name)
        i, j = page.find(begin), page.find(end)
        if i < 0 or j < i:
            raise SystemExit(f"api_docs: the page has no block {begin} ... {end}")
        page = page[:i + len(begin)] + "\n" + render().rstrip("\n") + "\n" + page[j:]
    return page


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m hpgen.tools.api_docs",
                                 description=__doc__.splitlines()[0])
    ap.add_argument("--page", default=str(Path(__file__).resolve().parents[2] / "docs" /
                                          "api.md"), help="the page (default: docs/api.md)")
    ap.add_argument("--check", action="store_true",
                    help="do not write; exit 1 when the page differs from the code")
    args = ap.parse_args(argv)
    path = Path(args.page)
    if not path.is_file():
        print(f"api_docs: no page {path} (run from a checkout, or give --page)", file=sys.stderr)
        return 2
    old = path.read_text()
    new = update(old)
    if args.check:
        if new != old:
            print(f"{path} differs from the code: run python -m hpgen.tools.api_docs",
                  file=sys.stderr)
            return 1
        return 0
    if new != old:
        path.write_text(new)
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
