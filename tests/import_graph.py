"""The imports of the package's modules, read with :mod:`ast` (nothing is imported): what
each module imports where, and the graph of imports between the package's own modules that
the import contracts (tests/test_import_contracts.py) are checked on.

Every import counts, at module level or inside a function, except those in an
``if TYPE_CHECKING:`` block, which run only under a type checker: they are kept, marked, for
the contracts that forbid even those.  Importing ``a.b.c`` also runs ``a/__init__`` and
``a/b/__init__``, so the graph has those edges too -- but not to the importing module's own
packages, which have always run before it does.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path

#: A module docstring that says the module does without Textual ("no Textual here", "(no
#: Textual)", "without Textual", "No Textual or Rich here").
TEXTUAL_FREE_MARK = re.compile(
    r"\b(?:[Nn]o Textual(?: or Rich)?(?: here)?[).,:;]|[Ww]ithout Textual\b)")


@dataclass(frozen=True)
class Import:
    """One import statement's module: ``import module`` or ``from module import names``."""

    line: int
    module: str  # absolute
    names: tuple[str, ...] = ()
    type_checking: bool = False
    deferred: bool = False  # in a function: runs when the function does, not at import

    def mentions(self, prefix: str) -> bool:
        """Does it import ``prefix`` or a module under it (``from a import b`` imports ``a.b``
        when that is a module)?"""
        return any(name == prefix or name.startswith(prefix + ".")
                   for name in (self.module, *(f"{self.module}.{n}" for n in self.names)))


@dataclass(frozen=True)
class Module:
    name: str
    is_package: bool
    docstring: str
    imports: tuple[Import, ...]

    @property
    def path(self) -> str:
        return self.name.replace(".", "/") + ("/__init__.py" if self.is_package else ".py")

    @property
    def textual_free_by_docstring(self) -> bool:
        return TEXTUAL_FREE_MARK.search(self.docstring) is not None


def read_package(folder: Path) -> dict[str, str]:
    """Every module's source under ``folder`` (a package), by dotted name."""
    sources = {}
    for path in sorted(folder.rglob("*.py")):
        parts = path.relative_to(folder.parent).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        sources[".".join(parts)] = path.read_text(encoding="utf-8")
    return sources


def parse_modules(sources: dict[str, str]) -> dict[str, Module]:
    """The modules of ``sources`` (dotted name -> source); a name with modules under it is a
    package."""
    modules = {}
    for name, source in sources.items():
        is_package = any(other.startswith(name + ".") for other in sources)
        tree = ast.parse(source)
        modules[name] = Module(name, is_package, ast.get_docstring(tree) or "",
                               tuple(_imports(tree, name, is_package)))
    return modules


def _is_type_checking(test: ast.expr) -> bool:
    return ((isinstance(test, ast.Name) and test.id == "TYPE_CHECKING")
            or (isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"))


def _imports(tree: ast.Module, name: str, is_package: bool) -> Iterator[Import]:
    """Every import in ``tree`` (module ``name``), in functions and classes too."""
    here = name.split(".") if is_package else name.split(".")[:-1]

    def visit(node: ast.AST, type_checking: bool, deferred: bool) -> Iterator[Import]:
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield Import(node.lineno, alias.name, (), type_checking, deferred)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = here[:len(here) - node.level + 1]
                module = ".".join([*base, *([node.module] if node.module else [])])
            else:
                module = node.module or ""
            names = tuple(a.name for a in node.names if a.name != "*")
            yield Import(node.lineno, module, names, type_checking, deferred)
        elif isinstance(node, ast.If) and _is_type_checking(node.test):
            for child in node.body:
                yield from visit(child, True, deferred)
            for child in node.orelse:
                yield from visit(child, type_checking, deferred)
        else:
            in_function = isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
            for inner in ast.iter_child_nodes(node):
                yield from visit(inner, type_checking, deferred or in_function)

    yield from visit(tree, False, False)


def _ancestors(name: str) -> list[str]:
    parts = name.split(".")
    return [".".join(parts[:i]) for i in range(1, len(parts))]


def targets(module: Module, imp: Import, known: Iterable[str]) -> set[str]:
    """The package's modules that ``imp`` runs, from ``module``: the ones it names and their
    packages, less ``module``'s own packages (and ``module`` itself)."""
    known = set(known)
    named = {n for n in (imp.module, *(f"{imp.module}.{n}" for n in imp.names)) if n in known}
    own = {module.name, *_ancestors(module.name)}
    implied = {a for n in named for a in _ancestors(n) if a in known}
    return (named | implied) - own if named else set()


def runtime_graph(modules: dict[str, Module]) -> dict[str, set[str]]:
    """Module -> the package's modules its imports run (``if TYPE_CHECKING:`` ones aside)."""
    return {name: set().union(*(targets(m, imp, modules) for imp in m.imports
                                if not imp.type_checking))
            for name, m in modules.items()}


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """One cycle per strongly connected part of ``graph`` that has one: ``[a, b, ..., a]``."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    parts: list[list[str]] = []

    def connect(v: str) -> None:  # Tarjan's algorithm
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            part = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                part.append(w)
                if w == v:
                    break
            if len(part) > 1 or v in graph.get(v, ()):
                parts.append(sorted(part))

    for v in sorted(graph):
        if v not in index:
            connect(v)
    return sorted(_cycle_in(graph, part) for part in parts)


def _cycle_in(graph: dict[str, set[str]], part: list[str]) -> list[str]:
    """The shortest cycle through ``part``'s first module, within ``part``."""
    start, inside = part[0], set(part)
    came_from: dict[str, str] = {}
    frontier = [start]
    while frontier:
        nxt = []
        for v in frontier:
            for w in sorted(graph[v] & inside):
                if w == start:
                    path = [v]
                    while path[-1] != start:
                        path.append(came_from[path[-1]])
                    return [start, *reversed(path[:-1]), start] if v != start else [start, start]
                if w not in came_from:
                    came_from[w] = v
                    nxt.append(w)
        frontier = nxt
    raise AssertionError(f"no cycle in {part}")


def reach(graph: dict[str, set[str]], start: str) -> dict[str, list[str]]:
    """Every module ``start``'s imports run, with the chain of imports that runs it."""
    chains = {start: [start]}
    frontier = [start]
    while frontier:
        nxt = []
        for v in frontier:
            for w in sorted(graph.get(v, ())):
                if w not in chains:
                    chains[w] = [*chains[v], w]
                    nxt.append(w)
        frontier = nxt
    return chains
