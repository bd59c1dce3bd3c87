"""No import circles inside ``python/burmester`` (issue 25).

The graph is built from the source (``ast``), not by importing: an edge
``a -> b`` for each import that runs when ``a`` is first imported (at module
level, outside ``if TYPE_CHECKING:``; imports inside functions run later and
do not count). ``import burmester`` and ``from burmester import Name`` (a
name, not a submodule) are edges to the package's ``__init__``; importing a
submodule is an edge to that submodule. The parent package that Python
initializes first is no edge (every submodule would have one).

Run as a script to print the graph and its circles.
"""

from __future__ import annotations

import ast
from pathlib import Path
from typing import Dict, Iterator, List, Set

PACKAGE = Path(__file__).resolve().parents[2] / "python" / "burmester"


def _modules() -> Dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


def _top_level(body: List[ast.stmt]) -> Iterator[ast.stmt]:
    """The statements that run on import: into ``try``/``if`` blocks, but not
    ``if TYPE_CHECKING:`` nor function or class bodies."""
    for node in body:
        if isinstance(node, ast.If):
            test = node.test
            name = test.id if isinstance(test, ast.Name) else getattr(test, "attr", None)
            if name != "TYPE_CHECKING":
                yield from _top_level(node.body)
            yield from _top_level(node.orelse)
        elif isinstance(node, ast.Try):
            for block in [node.body, node.orelse, node.finalbody] + [h.body for h in node.handlers]:
                yield from _top_level(block)
        else:
            yield node


def import_graph() -> Dict[str, Set[str]]:
    """Each module of the package and the modules of the package it imports on import."""
    modules = _modules()
    graph: Dict[str, Set[str]] = {m: set() for m in modules}
    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in _top_level(ast.parse(path.read_text(encoding="utf-8")).body):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    base = ".".join(package.split(".")[: len(package.split(".")) - node.level + 1] + ([base] if base else []))
                targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names]
            else:
                continue
            graph[name].update(t for t in targets if t in modules and t != name)
    return graph


def circles(graph: Dict[str, Set[str]]) -> List[List[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: Dict[str, int] = {}
    low: Dict[str, int] = {}
    stack: List[str] = []
    on: Set[str] = set()
    found: List[List[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_import_circles() -> None:
    graph = import_graph()
    # The graph is the package's: every module, and the edges it must have.
    assert {"burmester", "burmester.taskfile", "burmester.units", "burmester.cli.base"} <= set(graph)
    assert "burmester.atlas" in graph["burmester"]
    assert "burmester.units" in graph["burmester.taskfile"]
    assert circles(graph) == []


def test_a_circle_is_found() -> None:
    # The search itself, on a graph with a known circle (a -> b -> c -> a) and a tail.
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set()}
    assert circles(graph) == [["a", "b", "c"]]


if __name__ == "__main__":
    g = import_graph()
    for m in sorted(g):
        print(f"{m} -> {', '.join(sorted(g[m])) or '(none)'}")
    print("circles:", circles(g) or "none")
