"""The import graph of hpgen.bench (drawn from the code, imports inside functions included)
has no circle: a module's shared pieces live where every user can import them."""
from __future__ import annotations

import ast
from pathlib import Path

import hpgen.bench

BENCH = Path(hpgen.bench.__file__).parent


def _graph():
    graph = {}
    for path in BENCH.glob("*.py"):
        deps = set()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
                deps.add(node.module.split(".")[0])
            elif isinstance(node, ast.ImportFrom) and node.module and \
                    node.module.startswith("hpgen.bench."):
                deps.add(node.module.split(".")[2])
        graph[path.stem] = deps & {p.stem for p in BENCH.glob("*.py")}
    return graph


def _cycle(graph):
    state = {}

    def visit(m, stack):
        state[m] = "open"
        for d in sorted(graph.get(m, ())):
            if state.get(d) == "open":
                return stack + [m, d]
            if d not in state:
                found = visit(d, stack + [m])
                if found:
                    return found
        state[m] = "done"
        return None

    for m in sorted(graph):
        if m not in state:
            found = visit(m, [])
            if found:
                return found
    return None


def test_bench_imports_have_no_circle():
    graph = _graph()
    assert "measure" in graph["rigid"] and "measure" in graph["peers"]   # the shared piece
    assert _cycle(graph) is None, " -> ".join(_cycle(graph))


def test_the_cycle_finder_finds_a_circle():
    assert _cycle({"a": {"b"}, "b": {"a"}}) is not None
