"""No import circles inside ``python/burmester``, the core crate or the
binding (issue 25).

The graph is built from the source (``ast``), not by importing: an edge
``a -> b`` for each import that runs when ``a`` is first imported (at module
level, outside ``if TYPE_CHECKING:``; imports inside functions run later and
do not count). ``import burmester`` and ``from burmester import Name`` (a
name, not a submodule) are edges to the package's ``__init__``; importing a
submodule is an edge to that submodule. The parent package that Python
initializes first is no edge (every submodule would have one).

For the Rust crates (:func:`rust_module_graph`) an edge ``a -> b`` is a
path ``crate::b::...`` (or ``super::...`` resolved from ``a``, or a macro's
``$crate::b::...``) anywhere in ``a``'s code outside comments, to the
longest module ``b`` it names; a module's own submodules and its parents
are no edge.

Run as a script to print the graphs and their circles.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path
from typing import Dict, Iterator, List, Set

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = ROOT / "python" / "burmester"
CORE = ROOT / "crates" / "burmester" / "src"
BINDING = ROOT / "crates" / "burmester-py" / "src"


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


def _rust_modules(src: Path) -> Dict[str, Path]:
    """Each module of a crate by its path (``design::map``; the crate root ``""``)."""
    out = {}
    for path in src.rglob("*.rs"):
        parts = list(path.relative_to(src).with_suffix("").parts)
        if parts[-1] in ("mod", "lib"):
            parts.pop()
        out["::".join(parts)] = path
    return out


_RUST_PATH = re.compile(r"\b(crate|super)((?:::[a-z_0-9]+)+)")


def rust_module_graph(src: Path) -> Dict[str, Set[str]]:
    """Each module of a crate and the modules of the crate it names."""
    modules = _rust_modules(src)
    graph: Dict[str, Set[str]] = {m: set() for m in modules if m}
    for name in graph:
        code = "\n".join(line.split("//")[0] for line in modules[name].read_text(encoding="utf-8").splitlines())
        for root, rest in _RUST_PATH.findall(code):
            # `super` from a file module `a::b` is `a`; from `a::b` as `a/b/mod.rs`, also `a`.
            base = [] if root == "crate" else name.split("::")[:-1]
            path = base + rest.strip(":").split("::")
            for k in range(len(path), 0, -1):
                target = "::".join(path[:k])
                if target in graph:
                    inside = target == name or target.startswith(name + "::") or name.startswith(target + "::")
                    if not inside:
                        graph[name].add(target)
                    break
    return graph


def test_no_module_circles_in_the_rust_crates() -> None:
    core = rust_module_graph(CORE)
    binding = rust_module_graph(BINDING)
    # The graphs are the crates': every module, and edges they must have.
    assert {"geom", "linkage", "synthesis", "design::map", "design::options"} <= set(core)
    assert "geom" in core["linkage::fourbar"] and "design::options" in core["design::map"]
    assert {"classes", "options", "design", "slider_map", "display", "map_state"} <= set(binding)
    assert "design" in binding["slider_map"] and "display" in binding["slider"]
    assert "map_state" in binding["design"] and "classes" in binding["design"]
    assert circles(core) == []
    assert circles(binding) == []
    # The layers of the core, one way: geom <- linkage <- synthesis <- design.
    layer = {"geom": 0, "linkage": 1, "synthesis": 2, "design": 3}
    for m, deps in core.items():
        for d in deps:
            a, b = layer.get(m.split("::")[0]), layer.get(d.split("::")[0])
            assert a is None or b is None or b <= a, f"{m} -> {d} goes up the layers"


def test_a_circle_is_found() -> None:
    # The search itself, on a graph with a known circle (a -> b -> c -> a) and a tail.
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set()}
    assert circles(graph) == [["a", "b", "c"]]


if __name__ == "__main__":
    g = import_graph()
    for m in sorted(g):
        print(f"{m} -> {', '.join(sorted(g[m])) or '(none)'}")
    print("circles:", circles(g) or "none")
    for src in (CORE, BINDING):
        rg = rust_module_graph(src)
        print(f"{src}: circles:", circles(rg) or "none")
